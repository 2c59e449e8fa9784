//! The verdict the textbook draws from an acceleration plan (seed 001 l. 686–689): a link
//! whose ε turns the same way as its ω rotates faster (accelerating), one whose ε opposes
//! ω slower (decelerating). Each route decides from its own numbers — the plans from the
//! ω and ε read off them, the twin from its closed forms — so a sense read wrongly on the
//! plan shows as a disagreement.

use crate::check::notes::KinematicsNote;
use crate::check::{At, Method, Row, Symbol};

/// How a link turns at an instant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Turning {
    /// ω and ε in the same sense.
    Accelerating,
    /// ω and ε in opposite senses.
    Decelerating,
}

/// One link's verdict at one position.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LinkVerdict {
    /// The position's label.
    pub position: String,
    /// The link's number.
    pub link: String,
    /// From the ω and ε read off the plans.
    pub graphical: Turning,
    /// From the analytic twin's ω and ε; `None` where the twin has no value (a toggle).
    pub analytic: Option<Turning>,
}

/// The share of the position's largest |ω| (|ε|) below which a link is taken as at rest
/// (turning uniformly): no verdict.
const NEGLIGIBLE: f64 = 1e-9;

/// The verdicts of every turning link at every position that has an acceleration plan, from
/// the plan rows (`omega_<link>`, `eps_<link>` by [`Method::Plan`]), in the rows' order.
/// A link at rest or turning uniformly on the plans (the crank at constant ω₁, a slider)
/// gets none.
pub fn verdicts(rows: &[Row]) -> Vec<LinkVerdict> {
    let plan = |symbol: Symbol| {
        rows.iter()
            .filter(move |r| r.method == Method::Plan && r.key.symbol == symbol)
    };
    let largest = |symbol: Symbol, at: &At, column: fn(&Row) -> f64| {
        plan(symbol)
            .filter(|r| &r.key.at == at)
            .map(|r| column(r).abs())
            .filter(|x| x.is_finite())
            .fold(0.0_f64, f64::max)
    };
    let decide = |w: f64, e: f64, w_max: f64, e_max: f64| {
        let still = !(w.abs() > NEGLIGIBLE * w_max && e.abs() > NEGLIGIBLE * e_max);
        match (still, w * e > 0.0) {
            (true, _) => None,
            (false, true) => Some(Turning::Accelerating),
            (false, false) => Some(Turning::Decelerating),
        }
    };
    let mut out = Vec::new();
    for e in plan(Symbol::AngularAcceleration) {
        let At::Position(position) = &e.key.at else {
            continue;
        };
        let Some(w) = plan(Symbol::AngularVelocity)
            .find(|w| w.key.at == e.key.at && w.key.subject == e.key.subject)
        else {
            continue;
        };
        let graphical = |r: &Row| r.graphical;
        let analytic = |r: &Row| r.analytic;
        let g = decide(
            w.graphical,
            e.graphical,
            largest(Symbol::AngularVelocity, &e.key.at, graphical),
            largest(Symbol::AngularAcceleration, &e.key.at, graphical),
        );
        let Some(g) = g else {
            continue;
        };
        let a = decide(
            w.analytic,
            e.analytic,
            largest(Symbol::AngularVelocity, &e.key.at, analytic),
            largest(Symbol::AngularAcceleration, &e.key.at, analytic),
        );
        out.push(LinkVerdict {
            position: position.clone(),
            link: e.key.subject.clone(),
            graphical: g,
            analytic: a,
        });
    }
    out
}

/// The links by the plans at each position, in order: (position, accelerating links,
/// decelerating links, the links whose twin's verdict differs).
pub fn by_position(verdicts: &[LinkVerdict]) -> Vec<(&str, [Vec<&str>; 3])> {
    let mut positions: Vec<&str> = verdicts.iter().map(|v| v.position.as_str()).collect();
    positions.dedup();
    positions
        .into_iter()
        .map(|p| {
            let links = |keep: &dyn Fn(&LinkVerdict) -> bool| -> Vec<&str> {
                verdicts
                    .iter()
                    .filter(|v| v.position == p && keep(v))
                    .map(|v| v.link.as_str())
                    .collect()
            };
            let turning = |t: Turning| move |v: &LinkVerdict| v.graphical == t;
            (
                p,
                [
                    links(&turning(Turning::Accelerating)),
                    links(&turning(Turning::Decelerating)),
                    links(&|v| v.analytic.is_some_and(|a| a != v.graphical)),
                ],
            )
        })
        .collect()
}

/// The report's notes: per position, the links accelerating and decelerating by the plans,
/// and whether the twin agrees.
pub fn verdict_notes(verdicts: &[LinkVerdict]) -> Vec<KinematicsNote> {
    let owned = |l: Vec<&str>| l.into_iter().map(str::to_string).collect();
    by_position(verdicts)
        .into_iter()
        .map(|(p, [up, down, differ])| KinematicsNote::Turning {
            position: p.to_string(),
            accelerating: owned(up),
            decelerating: owned(down),
            differ: owned(differ),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Key;

    fn row(symbol: Symbol, link: &str, graphical: f64, analytic: f64) -> Row {
        Row::new(
            Key::at_position(symbol, link, "1"),
            Method::Plan,
            graphical,
            analytic,
            1.0,
        )
    }

    /// Seed 001's W1 at φ = 30°: ω₂ clockwise with ε₂ counter-clockwise (decelerating),
    /// ω₃, ε₃ both clockwise and ω₄, ε₄ both counter-clockwise (accelerating); the crank at
    /// constant ω₁ and the slider (ω = 0) get no verdict.
    #[test]
    fn the_senses_of_omega_and_epsilon_decide() {
        use Symbol::{AngularAcceleration as E, AngularVelocity as W};
        let rows = [
            row(W, "1", -10.47, -10.47),
            row(W, "2", -2.6, -2.6),
            row(W, "3", -3.9, -3.9),
            row(W, "4", 1.56, 1.56),
            row(W, "5", 0.0, 0.0),
            row(E, "1", 0.0, 0.0),
            row(E, "2", 4.37, 4.37),
            row(E, "3", -20.8, -20.8),
            // A sense read wrongly off the plan: the twin disagrees.
            row(E, "4", -13.1, 13.1),
            row(E, "5", 0.0, 0.0),
        ];
        let v = verdicts(&rows);
        let got: Vec<(&str, Turning, Option<Turning>)> = v
            .iter()
            .map(|v| (v.link.as_str(), v.graphical, v.analytic))
            .collect();
        use Turning::{Accelerating as A, Decelerating as D};
        assert_eq!(
            got,
            [("2", D, Some(D)), ("3", A, Some(A)), ("4", D, Some(A))]
        );
        let notes = verdict_notes(&v);
        let owned = |l: &[&str]| l.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            notes,
            [KinematicsNote::Turning {
                position: "1".into(),
                accelerating: owned(&["3"]),
                decelerating: owned(&["2", "4"]),
                differ: owned(&["4"]),
            }]
        );
    }
}
