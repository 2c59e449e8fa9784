//! The revolute pair (seed 001 §12, Fig. 53–54): the shaft rolls up its bore until the
//! total reaction at the contact A₁ — the normal turned by φ against the slip — balances the
//! load Q. The reaction's line is then tangent to the friction circle of radius
//! `ρ = r·sin φ` (the textbook writes `ρ ≈ r·f` for small φ), and the friction moment is
//! `M_f = Q·ρ`.

use super::draw::{angle_mark, arrow, thin_line, turned};
use super::{
    friction_angle, reading, subject, Drawing, DrawingKind, FrictionCase, FrictionError, Journal,
    Solved,
};
use crate::check::notes::FrictionNote;
use crate::check::Symbol;
use crate::construct::{Compass, ConstructionError, Context, Item, Pick, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Line, Segment};
use std::f64::consts::PI;

/// Preferred drawn radius of the journal, mm.
const RADIUS_MM: f64 = 35.0;

/// The closed form of a revolute pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalTwin {
    /// The friction angle φ, rad.
    pub phi: f64,
    /// The friction circle's radius `r·sin φ`, m.
    pub rho: f64,
    /// The textbook's radius `r·f`, m.
    pub rho_textbook: f64,
    /// The friction moment `Q·r·sin φ`, N·m.
    pub moment: f64,
    /// The textbook's moment `f·Q·r`, N·m.
    pub moment_textbook: f64,
}

/// The twin of a revolute pair.
pub fn journal_twin(c: &Journal) -> JournalTwin {
    let phi = friction_angle(c.f);
    let rho = c.radius * phi.sin();
    JournalTwin {
        phi,
        rho,
        rho_textbook: c.radius * c.f,
        moment: c.load * rho,
        moment_textbook: c.f * c.load * c.radius,
    }
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Journal,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = journal_twin(c);
    let mut rec = case.scheme_recorder(c.radius, RADIUS_MM, ctx)?;
    let mu = rec.scale();
    let r = mu.to_mm(c.radius);
    let s = c.sense.signum();
    given(&mut rec, r, s);
    let a1 = contact(&mut rec, r, -s * twin.phi).map_err(wrap)?;
    reaction(&mut rec, (r, mu.to_mm(twin.rho)), a1, s);
    let arm = arm(&mut rec, a1);
    let readings = vec![
        reading(
            "ρ",
            (Symbol::Length, subject("rho", &case.name)),
            arm,
            twin.rho,
            None,
        ),
        reading(
            "M_{тр}",
            (Symbol::Moment, subject("f", &case.name)),
            c.load * arm,
            twin.moment,
            None,
        ),
    ];
    let notes = vec![FrictionNote::Journal {
        case: case.name.clone(),
        rho: twin.rho,
        textbook: twin.rho_textbook,
        moment: twin.moment_textbook,
    }];
    Ok(Solved {
        case: case.clone(),
        drawings: vec![Drawing {
            kind: DrawingKind::Scheme,
            figure: rec.finish(),
            scaled: true,
            also: Vec::new(),
        }],
        readings,
        notes,
    })
}

/// The given: the journal of radius `r` (mm) about O in its bearing, the load Q on its line
/// above it, ω in the sense `s` (+1 counter-clockwise).
fn given(rec: &mut Recorder, r: f64, s: f64) {
    let o = DVec2::ZERO;
    let centre = rec.draw(
        "the journal's centre",
        Item::Joint {
            at: o,
            fixed: false,
        },
        Role::Given,
        &[],
    );
    rec.label(centre, "O", o, DVec2::new(1.0, 1.0).normalize());
    rec.draw(
        "the journal",
        Item::Circle(Circle {
            center: o,
            radius: r,
        }),
        Role::Given,
        &[],
    );
    rec.draw(
        "the bearing",
        Item::Arc(Arc {
            center: o,
            radius: r * 1.2,
            start: PI * 1.1,
            sweep: PI * 0.8,
        }),
        Role::Given,
        &[],
    );
    arrow(
        rec,
        "the load (through O, drawn on its line above the journal)",
        (o + DVec2::Y * (r + 18.0), o + DVec2::Y * r),
        Role::Given,
        "Q",
        DVec2::X,
    );
    // ω: an arc with an arrow in the sense of rotation.
    let w = Arc {
        center: o,
        radius: r * 0.6,
        start: PI * 0.1,
        sweep: PI * 0.5 * s,
    };
    let id = rec.draw("ω", Item::Arc(w), Role::Dimension, &[]);
    let tip = w.end();
    let tangent = (tip - o).perp() * s;
    rec.draw(
        "the sense of ω",
        Item::Vector {
            from: tip - tangent.normalize_or(DVec2::X) * 3.0,
            to: tip,
        },
        Role::Dimension,
        &[],
    );
    rec.label(
        id,
        "ω",
        w.eval(0.5),
        (w.eval(0.5) - o).normalize_or(DVec2::Y),
    );
}

/// The contact A₁: the radius turned by `turn` (rad) from the load's line, on the side the
/// shaft climbs, meets the journal; the normal at A₁ drawn.
fn contact(rec: &mut Recorder, r: f64, turn: f64) -> Result<DVec2, ConstructionError> {
    let o = DVec2::ZERO;
    let toward = turned(-DVec2::Y, turn);
    let radius_line = Line {
        point: o,
        direction: toward,
    };
    let (a1, _, a1_id) = rec.meet_line_circle(
        "A₁",
        ("the radius at φ", &radius_line),
        Compass {
            name: "O",
            center: o,
            radius: r,
        },
        Pick::Forward,
    )?;
    rec.label(a1_id, "A_{1}", a1, toward);
    thin_line(rec, "the normal at A₁", o, a1);
    Ok(a1)
}

/// The friction circle (radius `rho_mm`) and the total reaction R at A₁: upward, tangent to
/// the friction circle, balancing Q; the angle φ from the normal marked.
fn reaction(rec: &mut Recorder, (r, rho_mm): (f64, f64), a1: DVec2, s: f64) {
    let o = DVec2::ZERO;
    // Unnamed: its radius is R's arm, dimensioned ρ ([`arm`]); a second ρ on the circle
    // named one quantity twice (the review's case 5).
    rec.draw(
        "the friction circle",
        Item::Circle(Circle {
            center: o,
            radius: rho_mm,
        }),
        Role::Construction,
        &[],
    );
    // R balances Q: through A₁, upward, tangent to the friction circle.
    // Drawn pushing on the contact from below; its line run on past the friction circle.
    rec.draw(
        "the line of R, tangent to the friction circle",
        Item::Segment(Segment::new(a1, DVec2::new(a1.x, o.y + 2.0 * rho_mm))),
        Role::Construction,
        &[],
    );
    arrow(
        rec,
        "the total reaction R",
        (a1 - DVec2::Y * 18.0, a1),
        Role::Result,
        "R",
        DVec2::X * -s,
    );
    angle_mark(rec, "φ", a1, r * 0.35, (o - a1, DVec2::Y), "φ");
}

/// The arm of R about O, dimensioned and measured: ρ as drawn, m.
fn arm(rec: &mut Recorder, a1: DVec2) -> f64 {
    let o = DVec2::ZERO;
    let foot = DVec2::new(a1.x, o.y);
    let dim = rec.draw(
        "the arm of R about O",
        Item::Dimension {
            from: o,
            to: foot,
            offset: 0.0,
        },
        Role::Dimension,
        &[],
    );
    rec.label(dim, "ρ", (o + foot) / 2.0, DVec2::Y);
    rec.measure(o, foot).value
}
