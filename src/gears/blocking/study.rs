//! The blocking contour of a scene's pair: traced, the scene's point placed, the textbook's
//! choices made, their rows (the lean formulas against the twins) and notes.

use super::trace::{twin_check, Contour};
use super::{
    twin_pair, Blocking, BlockingError, Choice, Criterion, Hard, Indices, OnContour, CHOICE_MARGIN,
    SPACING,
};
use crate::check::notes::blocking::{BlockingNote, Level, PlanePoint, Traced};
use crate::check::{Key, Method, Row, Symbol};
use crate::gears::PairSpec;
use crate::geom::DVec2;
use crate::kept::Recent;
use crate::words::POINT_TAGS;
use rayon::prelude::*;

/// The studies a [`Studies`] keeps.
const KEPT: usize = 8;

/// The last [`KEPT`] studies made through it, kept by their caller (a batch's variants
/// mostly share their gears: a store the batch's sessions share traces each pair about
/// once): the pair, the criterion asked, the study.
pub struct Studies(Recent<(PairSpec, Option<Criterion>), Result<BlockingStudy, BlockingError>>);

impl Default for Studies {
    fn default() -> Self {
        Self(Recent::new(KEPT))
    }
}

impl Studies {
    /// The study of the pair `spec` with `chosen` ([`BlockingStudy::of`]): the one kept, else made
    /// and kept.
    ///
    /// # Errors
    /// Those of [`BlockingStudy::of`].
    pub fn of(
        &self,
        spec: &PairSpec,
        chosen: Option<Criterion>,
    ) -> Result<BlockingStudy, BlockingError> {
        let key = (*spec, chosen);
        if let Some(study) = self.0.find(|k| *k == key) {
            return study;
        }
        let study = BlockingStudy::of(spec, chosen);
        self.0.keep(key, study.clone());
        study
    }
}

/// The contour of a scene's pair: traced, the scene's point placed, the textbook's choices.
#[derive(Debug, Clone, PartialEq)]
pub struct BlockingStudy {
    /// The module, m (the rows' lengths).
    pub module: f64,
    /// The traced contour (its hard limits: [`BlockingStudy::HARD`]).
    pub contour: Contour,
    /// The scene's (x₁, x₂) placed.
    pub placed: OnContour,
    /// The criterion the scene's (x₁, x₂) was chosen by (`None`: the scene gives it).
    pub chosen: Option<Criterion>,
    /// Each criterion's choice, or why there is none.
    pub choices: Vec<(Criterion, Result<Choice, BlockingError>)>,
    /// The largest difference of a traced point's index by the twins from its limit over
    /// the sampled points (s_a/m, ε_α, lengths/m, λ relative), and the points sampled.
    pub twin_check: (f64, usize),
}

impl BlockingStudy {
    /// The study's hard limits: s_a ≥ 0.25m, ε_α ≥ 1 (with no undercut, no interference).
    pub const HARD: Hard = Hard {
        sa_min: 0.25,
        eps_min: 1.0,
        inset: 0.0,
    };

    /// The contour of the pair `spec` with its point placed and the choices: the largest
    /// ε_α, equal sliding on the scene's x_Σ, the greatest x_Σ with s_a ≥ 0.25m — or, of
    /// the kind the scene `chosen` its point by, that criterion as the scene put it.
    ///
    /// A study is a function of the pair and `chosen` alone: a caller that asks for it
    /// again keeps it ([`Studies`]).
    ///
    /// # Errors
    /// Those of [`Blocking::new`] and [`Blocking::place`].
    pub fn of(spec: &PairSpec, chosen: Option<Criterion>) -> Result<Self, BlockingError> {
        let b = Blocking::new(spec.z, spec.rack)?;
        let criteria = [
            Criterion::LargestContactRatio,
            Criterion::EqualSliding {
                x_sum: spec.x_sum(),
            },
            Criterion::GreatestSumWithTip {
                sa_min: Self::HARD.sa_min,
            },
        ]
        .map(|c| match chosen {
            Some(asked) if std::mem::discriminant(&asked) == std::mem::discriminant(&c) => asked,
            _ => c,
        });
        // The contour and the region of the choices side by side; a criterion of other hard
        // limits (a scene's s_a,min) traces its own.
        let shared = Blocking::choice_hard(Criterion::LargestContactRatio, Self::HARD);
        let (contour, region) = rayon::join(|| b.trace(Self::HARD), || b.region(shared));
        let placed = b.place(DVec2::new(spec.x[0], spec.x[1]), Self::HARD)?;
        let choices = criteria
            .into_par_iter()
            .map(|c| {
                let hard = Blocking::choice_hard(c, Self::HARD);
                let chosen = if hard == shared {
                    b.choose_in(c, &region)
                } else {
                    b.choose_in(c, &b.region(hard))
                };
                (c, chosen)
            })
            .collect();
        let twin_check = twin_check(&contour, spec.module, 10);
        Ok(Self {
            module: spec.module,
            contour,
            placed,
            chosen,
            choices,
            twin_check,
        })
    }

    /// The points the rows and the sheet name: the scene's and each choice's, with a tag.
    pub fn points(&self) -> Vec<(&'static str, Indices)> {
        let mut out = vec![(POINT_TAGS[0], self.placed.indices)];
        for (c, r) in &self.choices {
            if let Ok(ch) = r {
                out.push((criterion_tag(*c), ch.indices));
            }
        }
        out
    }

    /// The rows: at each point, ε_α, s_a1, s_a2, α_w, Δy and λ₁(B₁), λ₂(B₂) by the
    /// contour's lean formulas (graphical column) against [`crate::gears::GearPair::new`] at that
    /// point (analytic); each choice's x₁, x₂ against the twins' x of the limits it lies on
    /// ([`Choice::twin_x`]; its own where it lies on none).
    pub fn rows(&self) -> Vec<Row> {
        let f = Method::Formula;
        let m = self.module;
        let b = &self.contour.blocking;
        let row = |s: Symbol, subject: String, g: f64, a: f64, scale: f64| {
            Row::new(Key::of_scene(s, subject), f, g, a, scale)
        };
        let mut out = Vec::new();
        for (tag, ix) in self.points() {
            let Ok(p) = twin_pair(b, m, DVec2::from(ix.x)) else {
                continue;
            };
            out.push(row(
                Symbol::ContactRatio,
                format!("alpha_{tag}"),
                ix.eps,
                p.eps,
                p.eps,
            ));
            for i in 0..2 {
                out.push(row(
                    Symbol::ToothThickness,
                    format!("a{}_{tag}", i + 1),
                    ix.sa[i] * m,
                    p.sa[i],
                    m,
                ));
            }
            let aw = p.alpha_w.to_degrees();
            out.push(row(
                Symbol::EngagementAngle,
                format!("w_{tag}"),
                ix.alpha_w.to_degrees(),
                aw,
                aw,
            ));
            out.push(row(Symbol::EqualisingShift, tag.into(), ix.dy, p.dy, 1.0));
            if let Some(l) = ix.lambda {
                let ends = p.active_ends();
                let exact = [p.sliding(ends[0])[0], p.sliding(ends[1])[1]];
                let scale = exact.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
                for i in 0..2 {
                    out.push(row(
                        Symbol::SpecificSliding,
                        format!("{}_{tag}", i + 1),
                        l[i],
                        exact[i],
                        scale,
                    ));
                }
            }
        }
        for (c, r) in &self.choices {
            let Ok(ch) = r else { continue };
            let twin = ch.twin_x(b, m).map_or(ch.indices.x, <[f64; 2]>::from);
            for (i, (x, t)) in ch.indices.x.iter().zip(twin).enumerate() {
                out.push(row(
                    Symbol::ShiftCoefficient,
                    format!("{}_{}", i + 1, criterion_tag(*c)),
                    *x,
                    t,
                    1.0,
                ));
            }
        }
        out
    }

    /// The notes: the contour traced and checked, the scene's point and the choices.
    pub fn notes(&self) -> Vec<BlockingNote> {
        let c = &self.contour;
        let b = &c.blocking;
        let (lo, hi) = b.window;
        let mut out = vec![BlockingNote::Traced(Traced {
            z: b.z,
            spacing: SPACING,
            window: [[lo.x, hi.x], [lo.y, hi.y]],
            curves: c.curves.len(),
            points: c.curves.iter().map(|c| c.points.len()).sum(),
            rings: c.boundary.len(),
            ring_points: c.boundary.iter().map(Vec::len).sum(),
            sampled: self.twin_check.1,
            twin_deviation: self.twin_check.0,
            hl: b.hl,
            x_min: [b.x_min(0), b.x_min(1)],
        })];
        let outside = self
            .placed
            .sides
            .iter()
            .filter(|s| s.inside == Some(false))
            .map(|s| Level {
                kind: s.kind,
                limit: s.limit,
                inset: 0.0,
            })
            .collect();
        out.push(BlockingNote::Placed {
            chosen: self.chosen,
            point: point(&self.placed.indices),
            admissible: self.placed.admissible,
            outside,
        });
        out.push(BlockingNote::Margin {
            margin: CHOICE_MARGIN,
            eps: Self::HARD.eps_min + CHOICE_MARGIN,
        });
        for (c, r) in &self.choices {
            let result = match r {
                Ok(ch) => {
                    let inset = Blocking::choice_hard(*c, Self::HARD).inset;
                    let on = ch
                        .on
                        .iter()
                        .map(|&(kind, limit)| Level { kind, limit, inset })
                        .collect();
                    Ok((point(&ch.indices), on))
                }
                Err(e) => Err(e.to_string()),
            };
            out.push(BlockingNote::Choice {
                criterion: *c,
                result,
            });
        }
        out
    }
}

/// A point's indices as the notes state them.
fn point(ix: &Indices) -> PlanePoint {
    PlanePoint {
        x: ix.x,
        alpha_w: ix.alpha_w,
        y: ix.y,
        dy: ix.dy,
        eps: ix.eps,
        sa: ix.sa,
        lambda: ix.lambda,
    }
}

/// A criterion's tag in row subjects.
pub fn criterion_tag(c: Criterion) -> &'static str {
    match c {
        Criterion::LargestContactRatio => POINT_TAGS[1],
        Criterion::EqualSliding { .. } => POINT_TAGS[2],
        Criterion::GreatestSumWithTip { .. } => POINT_TAGS[3],
    }
}
