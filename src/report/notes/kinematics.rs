//! The English of a kinematic study's notes ([`KinematicsNote`]).

use crate::check::notes::kinematics::{KinematicsNote, PinNearPivot};

/// The note in English.
pub(super) fn english(note: &KinematicsNote) -> String {
    match note {
        KinematicsNote::Refused(why) => why.clone(),
        KinematicsNote::NoPlan { position, why } => {
            format!("position {position}: no velocity plan: {why}")
        }
        KinematicsNote::Toggle { position, group } => format!(
            "position {position}: the analytic velocities and accelerations are not determined (group {} at its toggle): null",
            group + 1
        ),
        KinematicsNote::NearPivot(n) => near_pivot(n),
        KinematicsNote::Turning {
            position,
            accelerating,
            decelerating,
            differ,
        } => {
            let links = |l: &[String]| {
                if l.is_empty() {
                    "none".to_string()
                } else {
                    format!("links {}", l.join(", "))
                }
            };
            let twin = if differ.is_empty() {
                "the analytic twin agrees".to_string()
            } else {
                let l: Vec<String> = differ.iter().map(|l| format!("link {l}")).collect();
                format!("the analytic twin differs for {}", l.join(", "))
            };
            format!(
                "position {position}: accelerating (ω and ε in one sense) by the plans: {}; decelerating: {}; {twin}",
                links(accelerating),
                links(decelerating)
            )
        }
    }
}

/// A slotted link's pin near its pivot: the rate true but ill-conditioned.
fn near_pivot(n: &PinNearPivot) -> String {
    let (pin, pivot) = (&n.pin, &n.pivot);
    format!(
        "position {}: the pin {pin} passes {:.3e} m from the pivot {pivot} of the slotted link {} (group {}, |d{pivot}{pin}/dφ₁| = {:.4} m): the link turns at ω_{} = {:.4e} rad/s, {:.2e} times the crank's rate; the values at this position are true but ill-conditioned (a change of {:.1e} m in a length of the mechanism changes them by about 100 %)",
        n.position,
        n.distance,
        n.link,
        n.group + 1,
        n.speed,
        n.link,
        n.omega,
        n.speed / n.distance,
        n.distance
    )
}
