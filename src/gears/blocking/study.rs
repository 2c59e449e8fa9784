//! The blocking contour of a scene's pair: traced, the scene's point placed, the textbook's
//! choices made, their rows (the lean formulas against the twins) and notes.

use super::trace::{twin_check, Contour};
use super::{
    twin_pair, Blocking, BlockingError, Choice, Criterion, Hard, Indices, Kind, Placement,
    CHOICE_MARGIN, SPACING,
};
use crate::check::{Key, Method, Row, Symbol};
use crate::gears::PairSpec;
use crate::geom::DVec2;
use crate::kept::Recent;
use rayon::prelude::*;

/// The studies a [`Studies`] keeps.
const KEPT: usize = 8;

/// The last [`KEPT`] studies made through it, kept by their caller (a batch's variants
/// mostly share their gears: a store the batch's sessions share traces each pair about
/// once): the pair, the criterion asked, the study.
pub struct Studies(Recent<(PairSpec, Option<Criterion>), Result<Study, BlockingError>>);

impl Default for Studies {
    fn default() -> Self {
        Self(Recent::new(KEPT))
    }
}

impl Studies {
    /// The study of the pair `spec` with `chosen` ([`Study::of`]): the one kept, else made
    /// and kept.
    ///
    /// # Errors
    /// Those of [`Study::of`].
    pub fn of(&self, spec: &PairSpec, chosen: Option<Criterion>) -> Result<Study, BlockingError> {
        let key = (*spec, chosen);
        if let Some(study) = self.0.find(|k| *k == key) {
            return study;
        }
        let study = Study::of(spec, chosen);
        self.0.keep(key, study.clone());
        study
    }
}

/// The contour of a scene's pair: traced, the scene's point placed, the textbook's choices.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// The module, m (the rows' lengths).
    pub module: f64,
    /// The traced contour (its hard limits: [`Study::HARD`]).
    pub contour: Contour,
    /// The scene's (x₁, x₂) placed.
    pub placed: Placement,
    /// The criterion the scene's (x₁, x₂) was chosen by (`None`: the scene gives it).
    pub chosen: Option<Criterion>,
    /// Each criterion's choice, or why there is none.
    pub choices: Vec<(Criterion, Result<Choice, BlockingError>)>,
    /// The largest difference of a traced point's index by the twins from its limit over
    /// the sampled points (s_a/m, ε_α, lengths/m, λ relative), and the points sampled.
    pub twin_check: (f64, usize),
}

impl Study {
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
    /// contour's lean formulas (graphical column) against [`crate::gears::Pair::new`] at that
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
    pub fn notes(&self) -> Vec<String> {
        let num = |x: f64, s| crate::scale::format_sig(x, s, crate::scale::Lang::En);
        let c = &self.contour;
        let b = &c.blocking;
        let n: usize = c.curves.iter().map(|c| c.points.len()).sum();
        let (lo, hi) = b.window;
        let mut out = vec![format!(
            "blocking contour z₁ = {}, z₂ = {}: traced on a grid of spacing {SPACING} over x₁ ∈ [{}, {}], x₂ ∈ [{}, {}] (each point bracketed along a grid edge to 1e-13 of m or its index to 1e-14 of its limit; the region's corners, where the binding limit changes, solved by Newton's steps to 1e-12): {} curves, {n} points; the admissible region {} ring(s) of {} points; at {} sampled points the twins (Pair::new, Cutting) give the limits to {:.1e}; undercut limit x_min = h_l* − z sin²α/2 with h_l* = {} (the flank's end): x_min1 = {}, x_min2 = {}",
            b.z[0],
            b.z[1],
            num(lo.x, 4),
            num(hi.x, 4),
            num(lo.y, 4),
            num(hi.y, 4),
            c.curves.len(),
            c.boundary.len(),
            c.boundary.iter().map(Vec::len).sum::<usize>(),
            self.twin_check.1,
            self.twin_check.0,
            num(b.hl, 6),
            num(b.x_min(0), 5),
            num(b.x_min(1), 5),
        )];
        let describe = |ix: &Indices| {
            let l = ix.lambda.map_or("—".to_string(), |l| {
                format!("λ₁(B₁) = {}, λ₂(B₂) = {}", num(l[0], 5), num(l[1], 5))
            });
            format!(
                "x₁ = {}, x₂ = {}: α_w = {}°, y = {}, Δy = {}, ε_α = {}, s_a1 = {}m, s_a2 = {}m, {l}",
                num(ix.x[0], 6),
                num(ix.x[1], 6),
                num(ix.alpha_w.to_degrees(), 6),
                num(ix.y, 5),
                num(ix.dy, 5),
                num(ix.eps, 5),
                num(ix.sa[0], 4),
                num(ix.sa[1], 4),
            )
        };
        let outside: Vec<String> = self
            .placed
            .sides
            .iter()
            .filter(|s| s.inside == Some(false))
            .map(|s| level_name(s.kind, s.limit))
            .collect();
        out.push(format!(
            "blocking contour: the scene's point{} {}; {} (s_a ≥ 0.25m, ε_α ≥ 1, no undercut, no interference){}",
            self.chosen.map_or(String::new(), |c| format!(
                ", chosen on the contour by {} (`choose`),",
                criterion_name(c)
            )),
            describe(&self.placed.indices),
            if self.placed.admissible {
                "inside"
            } else {
                "outside"
            },
            if outside.is_empty() {
                String::new()
            } else {
                format!("; on the wrong side of {}", outside.join(", "))
            }
        ));
        out.push(format!(
            "blocking contour: each choice searches the whole region and keeps {CHOICE_MARGIN} inside every hard limit (s_a ≥ (s_a,min + {CHOICE_MARGIN})m, ε_α ≥ {}, x_i ≥ x_min,i + {CHOICE_MARGIN}, N_iB_i ≥ ρ_l,i + {CHOICE_MARGIN}m): on a limit itself the supremum can be a pair that does not work (the largest ε_α of 13/30 lies where the mate's tip reaches N₁, λ₁(B₁) = −∞)",
            num(Self::HARD.eps_min + CHOICE_MARGIN, 3),
        ));
        for (c, r) in &self.choices {
            out.push(match r {
                Ok(ch) => {
                    let inset = Blocking::choice_hard(*c, Self::HARD).inset;
                    let on: Vec<String> = ch
                        .on
                        .iter()
                        .map(|(k, l)| inset_name(*k, *l, inset))
                        .collect();
                    format!(
                        "blocking contour: {}: {}; on {}",
                        criterion_name(*c),
                        describe(&ch.indices),
                        if on.is_empty() {
                            "no limit (an inner maximum)".to_string()
                        } else {
                            on.join(", ")
                        }
                    )
                }
                Err(e) => format!("blocking contour: {}: none ({e})", criterion_name(*c)),
            });
        }
        out
    }
}

/// The tags of the points of [`Study::points`] in row subjects: the scene's point and each
/// criterion's ([`criterion_tag`]).
pub const POINT_TAGS: [&str; 4] = ["bz", "beps", "bsl", "bsum"];

/// The short label of a point of [`Study::points`] on the drawing (the sheet's lines give
/// its x₁, x₂ and indices under the same name): K the scene's point, ε_{α max}, λ (equal
/// sliding), x_{Σ max}.
pub fn point_label(tag: &str) -> &'static str {
    match tag {
        "bz" => "K",
        "beps" => "ε_{α max}",
        "bsl" => "λ_1 = λ_2",
        _ => "x_{Σ max}",
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

/// A criterion in words (the notes).
fn criterion_name(c: Criterion) -> String {
    match c {
        Criterion::LargestContactRatio => "the largest ε_α".into(),
        Criterion::EqualSliding { x_sum } => format!(
            "equal sliding λ₁(B₁) = λ₂(B₂) on x₁ + x₂ = {}",
            crate::scale::format_sig(x_sum, 6, crate::scale::Lang::En)
        ),
        Criterion::GreatestSumWithTip { sa_min } => format!(
            "the greatest x₁ + x₂ with s_a ≥ {}m",
            crate::scale::format_sig(sa_min, 3, crate::scale::Lang::En)
        ),
    }
}

/// A level in words (the notes).
pub(super) fn level_name(kind: Kind, limit: f64) -> String {
    inset_name(kind, limit, 0.0)
}

/// [`level_name`] of a limit taken `inset` inside.
fn inset_name(kind: Kind, limit: f64, inset: f64) -> String {
    let num = |x: f64| crate::scale::format_sig(x, 4, crate::scale::Lang::En);
    let (l, by) = (num(limit), num(inset));
    match kind {
        Kind::Undercut(i) if inset == 0.0 => format!("x{0} ≥ x_min{0} = {l}", i + 1),
        Kind::Undercut(i) => format!("x{0} ≥ x_min{0} + {by} = {l}", i + 1),
        Kind::Tip(i) => format!("s_a{} ≥ {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α ≥ {l}"),
        Kind::Interference(i) if inset == 0.0 => {
            format!("no interference with the fillet of wheel {}", i + 1)
        }
        Kind::Interference(i) => format!("N{0}B{0} ≥ ρ_l{0} + {by}m", i + 1),
        Kind::EqualSliding => "λ₁ = λ₂".into(),
    }
}
