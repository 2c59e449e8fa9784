//! The friction cases of the session (`[friction]`).

use super::*;

/// The friction cases' part of the report.
pub(super) const PART: Part = |session, rep| session.report_friction(rep);
use crate::construct::fit::{finest_fitting, fit_room};
use crate::construct::Figure;
use crate::friction::{self, DrawingKind, FrictionCase, FrictionError};
use crate::geom::DVec2;
use crate::scale::Quantity;

/// The room of each force triangle of a case on the friction sheet, mm.
const FORCES_ROOM: DVec2 = DVec2::new(FORCES_SIDE, FORCES_SIDE);
const FORCES_SIDE: f64 = 160.0;
/// The room of each scheme drawn to scale (the screw's unrolled thread, the journal, the
/// rollers) on the friction sheet, mm: as large as its force triangle's.
const SCHEME_ROOM: DVec2 = FORCES_ROOM;

/// The drawings of `s` whose μ is a real scale of `quantity` (its force triangles at μ_F, its
/// schemes at μ_l).
fn scaled(s: &Solved, quantity: Quantity) -> Vec<Figure> {
    s.drawings
        .iter()
        .filter(|d| d.scaled && d.figure.scale.quantity == quantity)
        .filter(|d| quantity != Quantity::Length || d.kind == DrawingKind::Scheme)
        .map(|d| d.figure.clone())
        .collect()
}

/// The case solved with each scale the scene leaves free — μ_F of its force triangles, μ_l
/// of its schemes drawn to scale — made finer along the round series from the textbook's
/// choice (the largest force about 60 mm; the scheme about 60 mm) while every drawing of
/// that scale, constructed and measured, still fits its room ([`FORCES_ROOM`],
/// [`SCHEME_ROOM`]): the drawings as large as the sheet holds them. The case keeps the
/// scene's choices.
fn larger(case: &FrictionCase, ctx: &crate::construct::Context) -> Result<Solved, FrictionError> {
    let mut solved = friction::solve(case, ctx)?;
    // Each scale: whether it is free, its quantity and room, its setter.
    type Set = fn(&mut FrictionCase, Scale);
    let free: [(bool, Quantity, DVec2, Set); 2] = [
        (
            case.scale_f.is_none(),
            Quantity::Force,
            FORCES_ROOM,
            |c, mu| c.scale_f = Some(mu),
        ),
        (
            case.scale_l.is_none(),
            Quantity::Length,
            SCHEME_ROOM,
            |c, mu| c.scale_l = Some(mu),
        ),
    ];
    let mut chosen = case.clone();
    for (is_free, quantity, room, set) in free {
        let Some(mu) = scaled(&solved, quantity).first().map(|f| f.scale) else {
            continue;
        };
        if !is_free {
            continue;
        }
        let build = |next| {
            let mut trial = chosen.clone();
            set(&mut trial, next);
            friction::solve(&trial, ctx).ok()
        };
        solved = finest_fitting(mu, solved, build, |t| fit_room(&scaled(t, quantity), room));
        if let Some(now) = scaled(&solved, quantity).first().map(|f| f.scale) {
            set(&mut chosen, now);
        }
    }
    solved.case = case.clone();
    Ok(solved)
}

/// The friction cases solved.
struct Cases;
impl Cache for Cases {
    type Key = ();
    type Value = Cached<Vec<Solved>>;
}

impl<'s> Session<'s> {
    /// Every `[[friction.case]]` of the scene constructed and read (empty without a
    /// `[friction]` section).
    pub fn friction(&self) -> Cached<Vec<Solved>> {
        self.caches.get::<Cases>((), || {
            let ctx = self.ctx()?;
            let solved = self
                .scene
                .friction
                .iter()
                .map(|c| larger(c, &ctx))
                .collect::<Result<Vec<_>, _>>()?;
            for s in &solved {
                for d in &s.drawings {
                    self.logged("friction", &s.case.name, d.figure.scale);
                }
            }
            Ok(Arc::new(solved))
        })
    }

    fn report_friction(&self, rep: &mut Report) -> Result<(), StudyError> {
        for s in self.friction()?.iter() {
            rep.rows.extend(s.rows());
            rep.notes
                .extend(s.notes.iter().cloned().map(ReportNote::from));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;
    use crate::scale::Scale;

    /// The scene `constructions/friction.toml` and a context reading every length exactly.
    fn friction_scene() -> (crate::scene::Scene, crate::construct::Context) {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/friction.toml");
        let scene = crate::scene::load(&path).expect("scene");
        let ctx = crate::construct::Context::for_model_size(1.0, Drafting::EXACT).expect("ctx");
        (scene, ctx)
    }

    /// A free μ_F is the finest round one whose force drawings fit their room (one step finer
    /// one would not); the case keeps the scene's choice; a given μ_F stands.
    #[test]
    fn a_free_force_scale_draws_the_triangles_as_large_as_their_room_holds() {
        let (scene, ctx) = friction_scene();
        let force = |s: &Solved| -> Vec<(DVec2, Scale)> {
            s.drawings
                .iter()
                .filter(|d| d.scaled && d.figure.scale.quantity == Quantity::Force)
                .filter_map(|d| d.figure.bounds().map(|(lo, hi)| (hi - lo, d.figure.scale)))
                .collect()
        };
        let mut grown = 0;
        for case in &scene.friction {
            let s = larger(case, &ctx).expect("solved");
            assert!(s.case.scale_f.is_none(), "{}", case.name);
            let Some(&(_, mu)) = force(&s).first() else {
                continue;
            };
            assert!(force(&s)
                .iter()
                .all(|(size, _)| size.cmple(FORCES_ROOM).all()));
            let finer = Scale::round_at_least(mu.value() * 0.999, 1.0, mu.quantity).expect("μ");
            let at = friction::solve(
                &FrictionCase {
                    scale_f: Some(finer),
                    ..case.clone()
                },
                &ctx,
            )
            .expect("finer");
            assert!(
                force(&at)
                    .iter()
                    .any(|(size, _)| !size.cmple(FORCES_ROOM).all()),
                "{}",
                case.name
            );
            let textbook = friction::solve(case, &ctx).expect("textbook");
            grown += usize::from(force(&textbook)[0].1.value() > mu.value());
            let given = FrictionCase {
                scale_f: Some(mu),
                ..case.clone()
            };
            assert_eq!(
                larger(&given, &ctx).expect("given").drawings.len(),
                s.drawings.len()
            );
        }
        assert!(
            grown >= 3,
            "{grown} cases drawn larger than the textbook's 60 mm"
        );
    }

    /// A free μ_l of the schemes drawn to scale (the screw's unrolled thread, the journal, the
    /// rollers) is the finest round one at which they fit their room (one step finer they
    /// would not), larger than the textbook's 60 mm; a given μ_l stands.
    #[test]
    fn a_free_scheme_scale_draws_the_schemes_as_large_as_their_room_holds() {
        let (scene, ctx) = friction_scene();
        let mut grown = Vec::new();
        for case in &scene.friction {
            let s = larger(case, &ctx).expect("solved");
            assert!(s.case.scale_l.is_none(), "{}", case.name);
            let schemes = scaled(&s, Quantity::Length);
            let Some(mu) = schemes.first().map(|f| f.scale) else {
                continue;
            };
            assert!(fit_room(&schemes, SCHEME_ROOM), "{}", case.name);
            let at = |mu: Scale| {
                let trial = FrictionCase {
                    scale_l: Some(mu),
                    ..case.clone()
                };
                friction::solve(&trial, &ctx).expect("solved")
            };
            let finer = mu.finer().expect("finer");
            assert!(
                !fit_room(&scaled(&at(finer), Quantity::Length), SCHEME_ROOM),
                "{}: μ_l could be {}",
                case.name,
                finer.value()
            );
            let textbook = friction::solve(case, &ctx).expect("textbook");
            let was = scaled(&textbook, Quantity::Length)[0].scale;
            grown.push((case.name.clone(), was.value(), mu.value()));
            assert_eq!(scaled(&at(mu), Quantity::Length)[0].scale, mu);
        }
        assert_eq!(grown.len(), 3, "{grown:?}");
        assert!(grown.iter().all(|(_, was, now)| now < was), "{grown:?}");
    }
}
