//! The rigid shocks on the diagrams: where a law's velocity jumps against a dwell (the
//! uniform law), d²S/dφ² is infinite there — an arrow "∞" up or down — and dS/dφ closes its
//! rectangle with a vertical.

use super::drawn_points;
use crate::cam::law::Shock;
use crate::cam::motion::motion;
use crate::cam::CamSpec;
use crate::construct::{Item, Recorder, Role, StepId};
use crate::geom::{DVec2, Segment};
use crate::scale::Scale;

/// Length of the arrows "∞" of a rigid shock on the d²S/dφ² diagram, mm.
const SHOCK_MM: f64 = 15.0;

/// The jumps of dS/dφ where a phase meets a dwell (a rigid shock: the uniform law starts and
/// ends at h/Φ against the dwell's nought), each a vertical of the curve `id` between the
/// abscissa and its end there, as the textbook closes the rectangle of that law.
pub(super) fn velocity_jumps(rec: &mut Recorder, id: StepId) {
    let ends = match drawn_points(rec, id) {
        [first, .., last] => [*first, *last],
        _ => return,
    };
    let coincident = rec.tolerances().coincident;
    for (end, name) in ends.into_iter().zip(["start", "end"]) {
        if end.y.abs() > coincident {
            rec.draw(
                format!("jump of dS/dφ at the phase's {name}: a rigid shock"),
                Item::Segment(Segment::new(DVec2::new(end.x, 0.0), end)),
                Role::Result,
                &[id],
            );
        }
    }
}

/// The arrows "∞" of a rigid shock on the d²S/dφ² diagram: at each end of a phase whose law
/// jumps in velocity, up where dS/dφ jumps up, down where it jumps down.
pub(super) fn shock_arrows(rec: &mut Recorder, spec: &CamSpec, phase: usize, phi: Scale) {
    let st = spec.starts();
    for (at, start) in [(st[phase], true), (st[phase + 1], false)] {
        let Some(up) = spec.shock_up(phase, start) else {
            return;
        };
        let x = phi.to_mm(at);
        let tip = DVec2::new(x, if up { SHOCK_MM } else { -SHOCK_MM });
        let id = rec.draw(
            "rigid shock: d²S/dφ² infinite",
            Item::Vector {
                from: DVec2::new(x, 0.0),
                to: tip,
            },
            Role::Given,
            &[],
        );
        // Beside the tip, clear of the ordinate axis the first arrow runs along.
        let toward = DVec2::new(1.0, if up { 1.0 } else { -1.0 });
        rec.label(id, "∞", tip, toward);
    }
}

impl CamSpec {
    /// At the `start` (else the end) of `phase` (0 the rise, 2 the return) of a law with
    /// rigid shocks, whether d²S/dφ² is +∞ there (dS/dφ jumps up against the dwell's
    /// nought) or −∞; `None` for a law without them.
    pub fn shock_up(&self, phase: usize, start: bool) -> Option<bool> {
        let law = if phase == 0 { self.rise } else { self.ret };
        if law.shock() != Shock::Rigid {
            return None;
        }
        let st = self.starts();
        let v = if start {
            motion(self, st[phase], true).ds
        } else {
            -motion(self, st[phase + 1], false).ds
        };
        Some(v > 0.0)
    }
}
