//! The balancing study of the session (`[balancing]`).

use super::*;

/// The balancing's part of the report.
pub(super) const PART: Part = |session, rep| session.report_balancing(rep);
use crate::balancing::{self, BalancingSpec};
use crate::construct::fit::{finest_fitting, fit_room};
use crate::construct::{Context, Figure};
use crate::geom::DVec2;
use crate::scale::Scale;

/// The room of the rotor's drawings (end view, side view) on its sheet, mm.
const ROTOR_ROOM: DVec2 = DVec2::new(ROTOR_W, ROTOR_H);
const ROTOR_W: f64 = 250.0;
const ROTOR_H: f64 = 180.0;
/// The room of each polygon (of static moments, of moments) on the rotor's sheet, mm.
const POLYGON_ROOM: DVec2 = DVec2::new(POLYGON_SIDE, POLYGON_SIDE);
const POLYGON_SIDE: f64 = 210.0;

/// The rotor balanced with each scale the scene leaves free (μ_l, μ_mρ, μ_mρz) made finer
/// along the round series, from the textbook's choice, while its drawings still fit their
/// room on the sheet ([`ROTOR_ROOM`], [`POLYGON_ROOM`]): a rotor of a few masses is drawn
/// as large as its sheet holds. The balancing keeps the scene's choices in its `spec`.
fn larger(spec: &BalancingSpec, ctx: &Context) -> Result<Balancing, StudyError> {
    let mut b = balancing::balance(spec, ctx)?;
    // Each scale: whether it is free, its value with its drawings and their room, its setter.
    type Get = fn(&Balancing) -> (Option<Scale>, Vec<&Figure>, DVec2);
    type Set = fn(&mut BalancingSpec, Scale);
    let free: [(bool, Get, Set); 3] = [
        (
            spec.scale_l.is_none(),
            |b| (Some(b.scale_l), b.rotor.iter().collect(), ROTOR_ROOM),
            |s, mu| s.scale_l = Some(mu),
        ),
        (
            spec.scale_mr.is_none(),
            |b| (Some(b.scale_mr), vec![&b.statics], POLYGON_ROOM),
            |s, mu| s.scale_mr = Some(mu),
        ),
        (
            spec.scale_mrz.is_none(),
            |b| (b.scale_mrz, b.moments.iter().collect(), POLYGON_ROOM),
            |s, mu| s.scale_mrz = Some(mu),
        ),
    ];
    let mut chosen = spec.clone();
    for (is_free, get, set) in free {
        let Some(mu) = get(&b).0.filter(|_| is_free) else {
            continue;
        };
        let build = |next| {
            let mut trial = chosen.clone();
            set(&mut trial, next);
            balancing::balance(&trial, ctx).ok()
        };
        b = finest_fitting(mu, b, build, |t| {
            let (_, figures, room) = get(t);
            fit_room(figures, room)
        });
        if let Some(now) = get(&b).0.filter(|&now| now != mu) {
            set(&mut chosen, now);
        }
    }
    b.spec = spec.clone();
    Ok(b)
}

/// The scene's rotor balanced.
struct Balanced;
impl Cache for Balanced {
    type Key = ();
    type Value = Cached<Balancing>;
}

impl<'s> Session<'s> {
    /// The balancing of the scene's rotor (`[balancing]`), constructed once.
    pub fn balancing(&self) -> Cached<Balancing> {
        self.caches.get::<Balanced>((), || {
            let spec = self
                .scene
                .balancing
                .as_ref()
                .ok_or(StudyError::NoBalancing("the balancing of a rotor"))?;
            let b = larger(spec, &self.ctx()?)?;
            self.logged("polygon of static moments", "", b.scale_mr);
            Ok(Arc::new(b))
        })
    }

    fn report_balancing(&self, rep: &mut Report) -> Result<(), StudyError> {
        let b = self.balancing()?;
        rep.rows.extend(b.rows());
        rep.notes
            .extend(b.notes().into_iter().map(ReportNote::from));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;

    fn balanced(name: &str, edit: impl Fn(&mut BalancingSpec)) -> Balancing {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("constructions")
            .join(format!("{name}.toml"));
        let mut scene = crate::scene::load(&path).expect("scene");
        if let Some(spec) = scene.balancing.as_mut() {
            edit(spec);
        }
        let b = Session::new(&scene, Drafting::EXACT)
            .balancing()
            .expect("balanced");
        (*b).clone()
    }

    /// Each free scale is the finest round one whose drawings fit their room: one step finer
    /// they would not; the scene's choices are what the balancing's spec keeps.
    #[test]
    fn a_free_scale_draws_the_rotor_as_large_as_its_room_holds() {
        for name in ["rotor-static", "rotor-dynamic"] {
            let b = balanced(name, |_| {});
            assert!(
                b.spec.scale_l.is_none() && b.spec.scale_mr.is_none(),
                "{name}"
            );
            assert!(fit_room(&b.rotor, ROTOR_ROOM) && fit_room([&b.statics], POLYGON_ROOM));
            let ctx = Context::for_model_size(1.0, Drafting::EXACT).expect("context");
            let mut spec = b.spec.clone();
            spec.scale_l = b.scale_l.finer();
            let over = balancing::balance(&spec, &ctx).expect("finer μ_l");
            assert!(
                !fit_room(&over.rotor, ROTOR_ROOM),
                "{name}: μ_l could be finer"
            );
            let mut spec = b.spec.clone();
            spec.scale_mr = b.scale_mr.finer();
            let over = balancing::balance(&spec, &ctx).expect("finer μ_mρ");
            assert!(
                !fit_room([&over.statics], POLYGON_ROOM),
                "{name}: μ_mρ could be finer"
            );
        }
        // Larger than before: the static rotor's disc was drawn at μ_l = 0,004 m/mm.
        assert!(balanced("rotor-static", |_| {}).scale_l.value() < 0.004);
        // A scale the scene gives stands.
        let given = Scale::new(0.01, crate::scale::Quantity::Length).expect("μ_l");
        let b = balanced("rotor-static", |s| s.scale_l = Some(given));
        assert_eq!(b.scale_l, given);
    }
}
