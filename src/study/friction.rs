//! The friction cases of the session (`[friction]`).

use super::*;

/// The friction cases' part of the report.
pub(super) const PART: Part = Part {
    has: |scene| !scene.friction.is_empty(),
    add: |session, rep| session.report_friction(rep),
};
use crate::construct::fit::{finest_fitting, fit_room};
use crate::forces::friction::{self, FrictionCase, FrictionError};
use crate::geom::DVec2;
use crate::scale::Quantity;

/// The room of each force triangle of a case on the friction sheet, mm.
const FORCES_ROOM: DVec2 = DVec2::new(FORCES_SIDE, FORCES_SIDE);
const FORCES_SIDE: f64 = 160.0;

/// The case solved with its μ_F, when the scene leaves it free, made finer along the round
/// series from the textbook's choice (the largest force about 60 mm) while every force
/// drawing of the case, constructed and measured, still fits [`FORCES_ROOM`]: the triangles
/// as large as the sheet holds them beside the schemes. The case keeps the scene's choice.
fn larger(case: &FrictionCase, ctx: &crate::construct::Context) -> Result<Solved, FrictionError> {
    let solved = friction::solve(case, ctx)?;
    if case.scale_f.is_some() {
        return Ok(solved);
    }
    let forces = |s: &Solved| -> Vec<crate::construct::Figure> {
        s.drawings
            .iter()
            .filter(|d| d.scaled && d.figure.scale.quantity == Quantity::Force)
            .map(|d| d.figure.clone())
            .collect()
    };
    let Some(mu) = forces(&solved).first().map(|f| f.scale) else {
        return Ok(solved);
    };
    let build = |next| {
        let trial = FrictionCase {
            scale_f: Some(next),
            ..case.clone()
        };
        friction::solve(&trial, ctx).ok()
    };
    let mut solved = finest_fitting(mu, solved, build, |t| fit_room(&forces(t), FORCES_ROOM));
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
            rep.notes.extend(s.notes.iter().cloned());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;
    use crate::scale::Scale;

    /// A free μ_F is the finest round one whose force drawings fit their room (one step finer
    /// one would not); the case keeps the scene's choice; a given μ_F stands.
    #[test]
    fn a_free_force_scale_draws_the_triangles_as_large_as_their_room_holds() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/friction.toml");
        let scene = crate::scene::load(&path).expect("scene");
        let ctx = crate::construct::Context::for_model_size(1.0, Drafting::EXACT).expect("ctx");
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
}
