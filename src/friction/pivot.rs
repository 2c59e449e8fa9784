//! A cam's rocker in its pivot (seed 001 lecture 16, L1774–1797): the cam pushes the roller
//! A at the arm's end L along the common normal, at the pressure angle λ to A's velocity,
//! against the moment of resistance M_с; the pivot O₂ is a journal of diameter d whose
//! reaction, carrying the whole of P (R = −P), is tangent to the friction circle
//! ρ = (d/2)·sin φ (lecture 11) on the side that opposes the rocker's rotation.
//!
//! The construction, to scale at μ_l: the rocker O₂A, P's line through A, the friction
//! circle and R's line parallel to P tangent to it; P and R make a couple of arm
//! h = L·cos λ − ρ (the dimension between the two lines) that balances M_с: P = M_с/h. The
//! rocker jams when P's line itself touches the friction circle: the tangent from A to the
//! friction circle (its point T on the circle over O₂A, Thales) makes λ_кр with A's velocity,
//! cos λ_кр = ρ/L. The twin is [`crate::cam::force`]'s (`rocker_force`, `rocker_locking`).

use super::draw::{angle_mark, arrow, thin_line, turned};
use super::guide::jams;
use super::incline::MIN_CROSSING_DEG;
use super::{
    friction_angle, reading, subject, CaseReading, Drawing, DrawingKind, FrictionCase,
    FrictionError, RockerPivot, Solved,
};
use crate::cam::force::{rocker_force, rocker_locking, rocker_locking_lecture};
use crate::check::notes::FrictionNote;
use crate::check::Symbol;
use crate::construct::{Compass, ConstructionError, Context, Item, Pick, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Line, Segment};
use std::f64::consts::PI;

/// Preferred drawn length of the arm, mm.
const ARM_MM: f64 = 130.0;

/// The closed form of a rocker in its pivot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PivotTwin {
    /// The friction circle's radius ρ = (d/2)·sin φ, m.
    pub rho: f64,
    /// The arm of the couple P, R: h = L·cos λ − ρ, m.
    pub h: f64,
    /// The cam's force P = M_с/h, N.
    pub p: f64,
    /// The jamming angle, cos λ_кр = ρ/L, rad.
    pub lock: f64,
    /// The lecture's jamming angle with M_тр = P^n·f·d/2, tg λ_кр = 2L/(f·d), rad.
    pub lock_lecture: f64,
}

/// The twin, from [`crate::cam::force`]; `None` when the rocker jams (λ ≥ λ_кр).
pub fn pivot_twin(c: &RockerPivot) -> Option<PivotTwin> {
    let v = &c.pivot;
    let p = rocker_force(c.moment, c.angle, v)?;
    Some(PivotTwin {
        rho: v.rho(),
        h: v.arm * c.angle.cos() - v.rho(),
        p,
        lock: rocker_locking(v),
        lock_lecture: rocker_locking_lecture(v),
    })
}

/// What the scheme reads: the friction circle's radius ρ and the couple's arm h, m, and
/// λ_кр, rad.
struct Read {
    rho: f64,
    h: f64,
    lock: f64,
}

/// The scheme at μ_l: the rocker O₂A turning counter-clockwise, its pivot's journal, M_с,
/// P at A along the cam's normal; R = −P through the journal's contact C, turned from the
/// normal there by φ (so tangent to the friction circle, whose radius ρ is read off it);
/// the arm h between the lines of P and R, and the tangent from A to the friction circle
/// (λ_кр).
fn scheme(
    case: &FrictionCase,
    c: &RockerPivot,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<(Drawing, Read), FrictionError> {
    let v = &c.pivot;
    let mut rec = case.scheme_recorder(v.arm, ARM_MM, ctx)?;
    let mu = rec.scale();
    let (arm, r) = (mu.to_mm(v.arm), mu.to_mm(v.diameter / 2.0));
    let (o2, a) = (DVec2::ZERO, DVec2::new(arm, 0.0));
    rocker(&mut rec, (o2, a), r);
    let p_dir = DVec2::new(-c.angle.sin(), c.angle.cos());
    // P's line through A and its foot from O₂ (towards the cam's side of O₂).
    let foot_p = a + p_dir * (o2 - a).dot(p_dir);
    let n = rec.draw(
        "the common normal n–n at A: the line of P",
        Item::Segment(Segment::new(a - p_dir * 30.0, foot_p + p_dir * 12.0)),
        Role::Axis,
        &[],
    );
    rec.label(n, "n", foot_p + p_dir * 12.0, p_dir);
    arrow(
        &mut rec,
        "the cam's force P",
        (a - p_dir * 24.0, a),
        Role::Given,
        "P",
        DVec2::X,
    );
    angle_mark(&mut rec, "λ", a, 14.0, (DVec2::Y, p_dir), "λ");
    let (foot_r, rho_mm) = reaction(&mut rec, r, p_dir, friction_angle(v.f)).map_err(wrap)?;
    let dim = rec.draw(
        "the arm h of the couple P, R",
        Item::Dimension {
            from: foot_r,
            to: foot_p,
            offset: 0.0,
        },
        Role::Dimension,
        &[],
    );
    rec.label(dim, "h", (foot_r + foot_p) / 2.0, p_dir);
    let h = rec.measure(foot_r, foot_p).value;
    let rho = rec.measure(o2, foot_r).value;
    // The tangent from A: T on the friction circle and on the circle over O₂A.
    let (t, _, _) = rec
        .meet_circles(
            "T, the tangent's point",
            Compass {
                name: "O₂ (ρ)",
                center: o2,
                radius: rho_mm,
            },
            Compass {
                name: "the middle of O₂A",
                center: a / 2.0,
                radius: arm / 2.0,
            },
            Pick::Left,
        )
        .map_err(wrap)?;
    thin_line(&mut rec, "the tangent from A to the friction circle", a, t);
    angle_mark(&mut rec, "λ_кр", a, 24.0, (DVec2::Y, t - a), "λ_{кр}");
    let lock = (rec.measure(o2, t).read_mm / rec.measure(o2, a).read_mm)
        .clamp(-1.0, 1.0)
        .acos();
    let drawing = Drawing {
        kind: DrawingKind::Scheme,
        figure: rec.finish(),
        scaled: true,
        also: Vec::new(),
    };
    Ok((drawing, Read { rho, h, lock }))
}

/// The pivot's reaction R = −P (P along `p_dir`) on the journal of radius `r` (mm) about
/// O₂: the contact C where the radius turned by φ from P's direction meets the journal, the
/// normal C–O₂, R's line through C along −P (turned by φ from the normal, against the
/// rocker's counter-clockwise turning), its foot from O₂ and the friction circle through
/// that foot. Returns the foot and the friction circle's radius as drawn, mm.
fn reaction(
    rec: &mut Recorder,
    r: f64,
    p_dir: DVec2,
    phi: f64,
) -> Result<(DVec2, f64), ConstructionError> {
    let o2 = DVec2::ZERO;
    let radius = Line {
        point: o2,
        direction: turned(p_dir, -phi),
    };
    let (contact, _, id) = rec.meet_line_circle(
        "C, the journal's contact",
        ("the radius at φ from P", &radius),
        Compass {
            name: "O₂ (d/2)",
            center: o2,
            radius: r,
        },
        Pick::Forward,
    )?;
    rec.label(id, "C", contact, radius.direction);
    thin_line(rec, "the normal at C", o2, contact);
    let foot = contact - p_dir * (o2 - contact).dot(-p_dir);
    thin_line(
        rec,
        "the line of R through C, tangent to the friction circle",
        contact,
        foot - p_dir * 12.0,
    );
    arrow(
        rec,
        "the pivot's reaction R = −P",
        (contact + p_dir * 22.0, contact),
        Role::Result,
        "R",
        turned(p_dir, -PI / 2.0),
    );
    angle_mark(rec, "φ", contact, r * 0.45, (o2 - contact, -p_dir), "φ");
    let rho = (foot - o2).length();
    let fc = rec.draw(
        "the friction circle through R's foot from O₂",
        Item::Circle(Circle {
            center: o2,
            radius: rho,
        }),
        Role::Construction,
        &[],
    );
    // Its radius drawn down to the left, clear of the lines of P and R.
    let down = DVec2::new(-0.8, -0.6);
    let arm = rec.draw(
        "the friction circle's radius ρ",
        Item::Segment(Segment::new(o2, o2 + down * rho)),
        Role::Construction,
        &[fc],
    );
    rec.label(arm, "ρ", o2 + down * rho, down);
    Ok((foot, rho))
}

/// The rocker O₂A (mm) with the pivot's journal of radius `r` (mm), the labels, A's
/// velocity and the moment of resistance M_с against the rotation about O₂ (drawn outside
/// the journal).
fn rocker(rec: &mut Recorder, (o2, a): (DVec2, DVec2), r: f64) {
    let pivot = rec.draw(
        "the pivot O₂",
        Item::Joint {
            at: o2,
            fixed: true,
        },
        Role::Given,
        &[],
    );
    rec.label(pivot, "O_{2}", o2, DVec2::new(-1.0, 0.6).normalize());
    rec.draw(
        "the pivot's journal, d",
        Item::Circle(Circle {
            center: o2,
            radius: r,
        }),
        Role::Given,
        &[],
    );
    rec.draw(
        "the rocker O₂A",
        Item::Segment(Segment::new(o2, a)),
        Role::Given,
        &[],
    );
    let end = rec.draw(
        "the roller's centre A",
        Item::Joint {
            at: a,
            fixed: false,
        },
        Role::Given,
        &[],
    );
    rec.label(end, "A", a, DVec2::new(0.6, -1.0).normalize());
    arrow(
        rec,
        "A's velocity, across the rocker",
        (a + DVec2::new(6.0, 0.0), a + DVec2::new(6.0, 16.0)),
        Role::Dimension,
        "V_{A}",
        DVec2::X,
    );
    // M_с against the rotation (clockwise), outside the journal on its left.
    let m = Arc {
        center: o2,
        radius: r + 8.0,
        start: PI * 1.2,
        sweep: -PI * 0.35,
    };
    let id = rec.draw("M_с", Item::Arc(m), Role::Dimension, &[]);
    let tip = m.end();
    let tangent = -(tip - o2).perp().normalize_or(DVec2::X);
    rec.draw(
        "the sense of M_с",
        Item::Vector {
            from: tip - tangent * 3.0,
            to: tip,
        },
        Role::Dimension,
        &[],
    );
    rec.label(
        id,
        "M_{с}",
        m.eval(0.5),
        (m.eval(0.5) - o2).normalize_or(DVec2::Y),
    );
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &RockerPivot,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let (scheme, read) = scheme(case, c, ctx, wrap)?;
    let v = &c.pivot;
    let rule = || {
        format!(
            "cos λ_кр = ρ/L, ρ = (d/2)·sin φ, d = {} m, L = {} m, f = {}",
            v.diameter, v.arm, v.f
        )
    };
    if read.lock - c.angle < MIN_CROSSING_DEG.to_radians() || read.h <= 0.0 {
        return Err(jams(case, "rocker", (c.angle, read.lock), rule()));
    }
    let twin = pivot_twin(c).ok_or_else(|| jams(case, "rocker", (c.angle, read.lock), rule()))?;
    let name = &case.name;
    let readings: Vec<CaseReading> = vec![
        reading(
            "ρ",
            (Symbol::Length, subject("rho", name)),
            read.rho,
            twin.rho,
            None,
        ),
        reading(
            "h",
            (Symbol::Length, subject("", name)),
            read.h,
            twin.h,
            None,
        ),
        reading(
            "P",
            (Symbol::Force, subject("P", name)),
            c.moment / read.h,
            twin.p,
            None,
        ),
        reading(
            "λ_{кр}",
            (Symbol::Angle, subject("lock", name)),
            read.lock,
            twin.lock,
            None,
        ),
    ];
    let notes = vec![FrictionNote::Pivot {
        case: name.to_string(),
        angle: c.angle,
        lock: twin.lock,
        rho: twin.rho,
        lecture: twin.lock_lecture,
    }];
    Ok(Solved {
        case: case.clone(),
        drawings: vec![scheme],
        readings,
        notes,
    })
}
