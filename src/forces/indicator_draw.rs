//! The indicator diagram as its sheet draws it: the gas pressure p against the cycle angle θ
//! (the diagram unfolded over one turn), at μ_p over μ_θ, through the rows the scene gives
//! (linear between them, as [`Indicator::pressure_at`] reads it); at each position a force
//! sheet analyses, the ordinate of each cylinder the diagram serves, from which that sheet's
//! p and F_д = p·πd²/4 are taken.

use super::indicator::Indicator;
use crate::calculus::draw_axes;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// The length of the θ axis's turn, mm at most.
const TURN_MM: f64 = 150.0;
/// The tallest the peak pressure is drawn, mm at most.
const PEAK_MM: f64 = 60.0;
/// The graduation of the θ axis, degrees.
const GRADUATION_DEG: u32 = 90;
/// How far under the θ axis its graduation is written, mm.
const BELOW_MM: f64 = 1.5;
/// Half a graduation's tick across the θ axis, mm.
const TICK_MM: f64 = 1.0;

/// An ordinate read off the diagram: its label (the piston's letter and the position's
/// label in label markup, `B_{3}`) and the cycle angle θ, radians.
pub type Reading = (String, f64);

/// The indicator diagram of `ind` with its `readings` (at μ_p, the figure's scale) and its
/// μ_θ; `None` when its peak is zero (nothing to draw) or no round scale can be formed.
pub fn indicator_figure(
    ind: &Indicator,
    readings: &[Reading],
    ctx: &Context,
) -> Option<(Figure, Scale)> {
    let peak = ind.pressure.iter().map(|r| r.1).fold(0.0, f64::max);
    let mu_p = Scale::round_for(peak, PEAK_MM, Quantity::Pressure)?;
    let mu_theta = Scale::round_for(TAU, TURN_MM, Quantity::Angle)?;
    let at = |theta: f64, p: f64| DVec2::new(mu_theta.to_mm(theta), mu_p.to_mm(p));
    let mut rec = Recorder::in_context("indicator diagram", mu_p, ctx);
    let turn = mu_theta.to_mm(TAU);
    draw_axes(
        &mut rec,
        DVec2::ZERO,
        (-4.0, turn + 12.0),
        (-4.0, mu_p.to_mm(peak) + 12.0),
        ("θ", "p"),
    );
    // The diagram over the whole turn: the rows, closed at 2π by the first row's pressure
    // (the diagram is periodic).
    let mut points: Vec<DVec2> = ind.pressure.iter().map(|&(t, p)| at(t, p)).collect();
    if ind.pressure.last().is_some_and(|r| r.0 < TAU) {
        points.push(at(TAU, ind.pressure_at(TAU)));
    }
    rec.draw(
        "the indicator diagram p(θ)",
        Item::Polyline {
            points,
            closed: false,
        },
        Role::Given,
        &[],
    );
    for (label, theta) in readings {
        let top = at(*theta, ind.pressure_at(*theta));
        let foot = DVec2::new(top.x, 0.0);
        let id = rec.draw(
            format!("the ordinate {label}"),
            Item::Segment(Segment::new(foot, top)),
            Role::Construction,
            &[],
        );
        rec.label_item(id, label.clone(), top, DVec2::new(0.3, 1.0));
    }
    // The θ axis graduated: a tick across it at each graduation past the origin.
    for k in (GRADUATION_DEG..=360).step_by(GRADUATION_DEG as usize) {
        let x = mu_theta.to_mm(f64::from(k).to_radians());
        let tick = Segment::new(DVec2::new(x, -TICK_MM), DVec2::new(x, TICK_MM));
        rec.draw(
            "the θ axis's tick",
            Item::Segment(tick),
            Role::Construction,
            &[],
        );
    }
    let mut figure = rec.finish();
    for k in (0..=360).step_by(GRADUATION_DEG as usize) {
        let x = mu_theta.to_mm(f64::from(k).to_radians());
        figure = figure.with_text(
            "the θ axis's graduation",
            DVec2::new(x, -BELOW_MM),
            format!("{k}°"),
            DVec2::new(0.0, -1.0),
        );
    }
    Some((figure, mu_theta))
}
