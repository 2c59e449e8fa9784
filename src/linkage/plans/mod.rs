//! Velocity and acceleration plans (планы скоростей и ускорений) as drawing-board
//! constructions: from the pole, each Assur group's two vector equations are drawn as
//! direction lines through known images and intersected; further points of a link follow by
//! the similarity theorem; every value is read off the drawing (drafting model applied) and
//! turned into a physical value with the plan's μ.
//!
//! Velocity plan (pole `p`): the crank pin's velocity ⊥ to the crank in the sense of ω₁;
//! RRR: ⊥ to each link through the outer images; RRP: ⊥ to the link and ∥ to the guide through
//! the image of the guide's coincident point; RPR: ⊥ to the line from the pivot and ∥ to the
//! slide through the block's image (the coincident point `b₃`); PRP: ∥ to each guide through the
//! coincident points of the carrying links; RPP: ∥ to the slide and ∥ to the guide.
//! Acceleration plan (pole `π`): the same equations with the normal components (ends `n`) laid
//! from the known images along the links and the Coriolis components (end `k`, 2ω·v_r turned
//! 90° in the sense of ω of the carrying link) laid before the direction lines. Each kind draws
//! its own equations (`GroupKind::plan`, in its file of `kinds/`) with the builder's steps.

pub(in crate::linkage) mod builder;
pub(in crate::linkage) mod names;
pub(in crate::linkage) mod plan;

use super::built::Built;
use super::program::{Op, Program};
use crate::construct::{ConstructionError, Context, Recorder};
use crate::geom::DVec2;
use crate::scale::Scale;
pub(in crate::linkage) use builder::Builder;
use builder::{Known, Links};
pub use names::{image_label, plain};
pub use plan::{KinPlan, Measure, PlanKind, PlanReading};

/// The link a known point belongs to (the first that carried it; 0 for fixed points):
/// [`Program::owner`].
pub fn owner(prog: &Program, k: usize) -> usize {
    prog.owner(k)
}

/// A constructed position and the crank speed: what every drawing of that position starts
/// from — its plans here, its force polygons and Zhukovsky's lever in `forces` (which add
/// μ_F).
#[derive(Debug, Clone, Copy)]
pub struct PlanSetup<'a> {
    /// The compiled mechanism.
    pub prog: &'a Program,
    /// The constructed position (drawing mm).
    pub built: &'a Built,
    /// μ_l of the construction.
    pub mu_l: Scale,
    /// Crank speed ω₁, rad/s, signed counter-clockwise.
    pub w1: f64,
    /// The construction context: the plan's tolerances and the drafting model of its
    /// readings.
    pub ctx: Context,
}

/// Build a plan of `kind` at plan scale `scale`. The acceleration plan needs the velocity
/// plan of the same position (`vel`). A failure names the group (file order) and the step.
pub fn kin_plan(
    setup: &PlanSetup<'_>,
    kind: PlanKind,
    scale: Scale,
    vel: Option<&KinPlan>,
) -> Result<KinPlan, (usize, ConstructionError)> {
    let PlanSetup {
        prog,
        built: b,
        mu_l,
        w1,
        ctx,
    } = *setup;
    let title = match kind {
        PlanKind::Velocity => "velocity plan",
        PlanKind::Acceleration => "acceleration plan",
    };
    let n = prog.names.len();
    let mut bl = Builder {
        prog,
        b,
        kind,
        rec: Recorder::in_context(title, scale, &ctx),
        mu_l: mu_l.value(),
        img: vec![None; n],
        links: Links {
            pts: vec![Vec::new(); prog.link_count],
            rate: vec![None; prog.link_count],
        },
        readings: Vec::new(),
        coincident: Vec::new(),
        cond: vec![None; n],
        w1,
        known: Known {
            vel: vel.filter(|_| kind == PlanKind::Acceleration),
            mu_v: vel.map_or(1.0, |v| v.figure.scale.value()),
        },
    };
    let pole = bl.rec.pole(if kind == PlanKind::Velocity {
        "p"
    } else {
        "π"
    });
    for k in 0..prog.fixed.len() {
        bl.img[k] = Some(DVec2::ZERO);
    }
    bl.links.rate[0] = Some(0.0);
    // The class-I mechanism.
    let cl = prog.crank_link as usize;
    let r = bl.r(prog.centre, prog.pin);
    let v_pin = match kind {
        PlanKind::Velocity => r.perp() * w1,
        PlanKind::Acceleration => -r * (w1 * w1),
    };
    let pin_img = v_pin / bl.mu();
    bl.set_image(prog.pin, pin_img, &[pole]);
    bl.links.rate[cl] = Some(if kind == PlanKind::Velocity { w1 } else { 0.0 });
    bl.links.add(cl, b.p[prog.centre], DVec2::ZERO);
    bl.links.add(cl, b.p[prog.pin], pin_img);
    for op in &prog.ops {
        match *op {
            Op::Point { idx, link, .. } => {
                let at = b.p[idx];
                let name = prog.names[idx].clone();
                let x = bl.image_on(link as usize, at, &name);
                bl.set_image(idx, x, &[]);
                bl.links.add(link as usize, at, x);
            }
            // One Assur group: the image of its joint (of the slider's coincident point for
            // RPR, RPP) from its two vector equations, by its kind's own steps.
            Op::Dyad { group, links, dyad } => {
                let ij = links.map(|l| l as usize);
                let step = format!("group ({},{})", ij[0], ij[1]);
                dyad.group()
                    .plan(&mut bl, &step, ij)
                    .map_err(|e| (group, e))?;
            }
        }
    }
    // Readings: every moving point, every link rate.
    for k in prog.fixed.len()..n {
        let x = bl.image(k);
        let v = bl.read(DVec2::ZERO, x);
        let q = match kind {
            PlanKind::Velocity => format!("v_{}", plain(&prog.names[k])),
            PlanKind::Acceleration => format!("a_{}", plain(&prog.names[k])),
        };
        let cond = bl.cond[k];
        bl.reading(q, Measure::Point(k), v, cond);
    }
    for l in 1..prog.link_count {
        if let Some(w) = bl.links.rate[l] {
            let q = match kind {
                PlanKind::Velocity => format!("omega_{l}"),
                PlanKind::Acceleration => format!("eps_{l}"),
            };
            bl.reading(q, Measure::Rate(l), w, None);
        }
    }
    let rate = bl.links.rate.iter().map(|r| r.unwrap_or(0.0)).collect();
    let images = bl.img.iter().map(|i| i.unwrap_or(DVec2::ZERO)).collect();
    Ok(KinPlan {
        kind,
        figure: bl.rec.finish(),
        images,
        coincident: bl.coincident,
        rate,
        readings: bl.readings,
    })
}
