//! The angular-velocity diagram of a rocker: ω(φ₁) charted from the velocity plans and
//! differentiated by chords into ε (seed 000 §1.5).

use super::{extent, numbered, pole_and_scale, round_scale, turn_diagram, KinError, DIAGRAM_GAP};
use crate::calculus::{self, Derivative, DiagramLayout, Scales};
use crate::check::{Key, Method, Row, Symbol};
use crate::construct::{Context, Figure, Recorder};
use crate::geom::DVec2;
use crate::linkage::{KinPlan, Output, PositionPlan};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// Preferred peak ordinates of the rocker's ω diagram and its derivative, mm.
const ROCKER_MM: f64 = 30.0;
/// Abscissa of one crank turn on the rocker's ω diagram, mm.
const ROCKER_TURN_MM: f64 = 120.0;

/// The angular-velocity analogue of a rocker and its chord derivative.
#[derive(Debug, Clone, PartialEq)]
pub struct RockerDiagram {
    /// The rocker's link number.
    pub link: usize,
    /// μ_ω of the chart, (rad/s)/mm.
    pub scale: Scale,
    /// μ_φ of the abscissa.
    pub scale_phi: Scale,
    /// The chord derivative dω/dφ₁ (its scale: (rad/s)/rad per mm).
    pub derivative: Derivative,
    /// The figure: the ω chart and its derivative.
    pub figure: Figure,
    /// ε = |ω₁|·dω/dφ₁ at the numbered positions against the analytic twin.
    pub rows: Vec<Row>,
}

/// The first rocker output's link, if any.
pub fn rocker_link(outputs: &[Output]) -> Option<usize> {
    outputs.iter().find_map(|o| match o {
        Output::Rocker { link } => Some(*link as usize),
        Output::Slider { .. } => None,
    })
}

/// ω of `link` at the numbered positions, read off the velocity plans (`velocity[k]`: the
/// plan at position `k`, `None` where refused), then differentiated by chords: ε =
/// |ω₁|·dω/dθ (θ the crank's travel). The seed's ε = 12·0.32 = 3.8 rad/s² (L574) forgets the
/// factor ω₁; this does not. The abscissa at the scene's μ_φ (`phi`) when given. `None` when a
/// numbered position has no velocity plan.
pub fn rocker_diagram(
    plan: &PositionPlan,
    link: usize,
    velocity: &[Option<&KinPlan>],
    (w1, phi): (f64, Option<Scale>),
    ctx: &Context,
) -> Result<Option<RockerDiagram>, KinError> {
    let numbered = numbered(plan);
    let omega: Option<Vec<f64>> = numbered
        .iter()
        .map(|(k, _)| velocity.get(*k).copied().flatten().map(|v| v.rate[link]))
        .collect();
    let (Some(omega), true) = (omega, numbered.len() >= 3) else {
        return Ok(None);
    };
    super::full_turn(plan)?;
    let fail = |error| KinError::Diagram {
        what: format!("ω_{link}"),
        error,
    };
    let src = turn_diagram(omega.clone()).map_err(fail)?;
    let peak = super::peak(omega.iter().copied());
    let scale = round_scale(peak.max(1e-12), ROCKER_MM, Quantity::AngularVelocity)?;
    // The scene's μ_φ when it gives one (the displacement diagram's too: one μ_φ a sheet).
    let scale_phi = match phi {
        Some(s) => s,
        None => Scale::new(TAU / ROCKER_TURN_MM, Quantity::Angle).ok_or(KinError::NoScale {
            quantity: Quantity::Angle,
            value: TAU,
        })?,
    };
    let scales = Scales {
        x: scale_phi,
        y: scale,
    };
    let (h, mu) =
        pole_and_scale(None, &src, scales, ROCKER_MM, Quantity::AngularVelocity).map_err(fail)?;
    let (w_lo, _) = extent(omega.iter(), scale);
    let (d_lo, _) = super::diagrams::ordinates(&src, scales, h, mu, ctx).map_err(fail)?;
    let mut rec = Recorder::in_context("ω", mu, ctx);
    // The extremes between the numbered positions, with ω read off their own plans (nought
    // at the rocker's own extremes): the curve passes there too.
    let between = super::between(plan);
    let through = (between.iter())
        .filter_map(|&(k, travel, _)| {
            let w = velocity.get(k).copied().flatten()?.rate[link];
            Some(DVec2::new(scale_phi.to_mm(travel), scale.to_mm(w)))
        })
        .collect();
    let lay = DiagramLayout::new(DVec2::ZERO, DVec2::new(0.0, w_lo - DIAGRAM_GAP - ROCKER_MM))
        .source_through(through)
        .named("φ", &format!("ω_{{{link}}}"), &format!("dω_{{{link}}}/dφ"))
        .pole_named("P_{ω}", "H_{ω}")
        .pole_marks(
            d_lo - super::diagrams::POLE_DIMENSION_MM,
            super::diagrams::POLE_LABEL,
        );
    let derivative = calculus::Derivation::Chords
        .differentiate(&mut rec, &src, scales, h, &lay)
        .map_err(fail)?;
    // The positions' numbers on the ω diagram's φ axis, as on the S diagram's, and on its
    // derivative's (the numbers alone).
    let extremes: Vec<(f64, &String)> = (between.iter()).map(|(_, x, p)| (*x, &p.label)).collect();
    super::axis::number_phi_axis(&mut rec, (&src, &numbered), &extremes, scale_phi);
    let at = (scale_phi, lay.origin.y, derivative.node.as_slice());
    super::axis::number_derivative_axis(&mut rec, (&src, &numbered), at);
    let eps_scale = super::peak(numbered.iter().map(|(_, p)| p.pose.ddangle[link] * w1 * w1));
    let rows = numbered
        .iter()
        .enumerate()
        .map(|(idx, (_, p))| {
            Row::new(
                Key::at_position(Symbol::AngularAcceleration, link.to_string(), &p.label),
                Method::DiagramChords,
                derivative.node[idx] * w1.abs(),
                super::rate(&p.pose, p.pose.ddangle[link] * w1 * w1),
                eps_scale,
            )
        })
        .collect();
    Ok(Some(RockerDiagram {
        link,
        scale,
        scale_phi,
        derivative,
        figure: rec.finish(),
        rows,
    }))
}
