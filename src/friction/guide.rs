//! A cam's translating follower in its guide (seed 001 lecture 15, L1705–1773; seed 002
//! L1457–1459): the cam pushes the rod at its end K along the common normal, at the pressure
//! angle λ to the axis, against the resistance Q along the axis; the guide's bearings, l and
//! l + b from K, press the rod back with the normal reactions N₁ (the nearer, against P's
//! side push) and N₂ (the farther, with it), each with its friction f·N against the motion:
//! the total reactions R₁, R₂ lean from the normal by φ = arctg f.
//!
//! The construction, to scale at μ_l: the two reactions' lines through the bearings, each
//! turned by φ, meet at Z; the rod is then held by three forces — P and Q through K, and
//! R₁ + R₂ through Z — so R₁₂ = R₁ + R₂ lies on the line KZ. The angle between the axis and
//! KZ is the jamming angle λ_кр: a P along KZ is balanced by the guide alone, whatever its
//! size (tg λ_кр = b/(f(2l + b))). The force plan at μ_F: the triangle Q + P + R₁₂ = 0, then
//! R₁₂ split along the two reactions' lines into R₁ and R₂. The twin is
//! [`crate::cam::force`]'s closed form (`translating_forces`, `translating_locking`).

use super::draw::{angle_mark, arrow, thin_line, triangle, Third};
use super::incline::MIN_CROSSING_DEG;
use super::{
    friction_angle, reading, subject, CaseReading, Drawing, DrawingKind, FollowerGuide,
    FrictionCase, FrictionError, Solved,
};
use crate::cam::force::{translating_forces, translating_locking};
use crate::check::notes::FrictionNote;
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Recorder, Role};
use crate::geom::{DVec2, Line, Segment, Side};

/// Preferred drawn size of the scheme (the guide or the reach of Z, whichever is larger), mm.
const SCHEME_MM: f64 = 100.0;
/// Half the width the rod is drawn at, mm (the model's rod is its axis).
const ROD_MM: f64 = 2.0;

/// The closed form of a follower in its guide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideTwin {
    /// φ = arctg f, rad.
    pub phi: f64,
    /// The cam's force P, N.
    pub p: f64,
    /// The bearings' normal reactions N₁, N₂, N.
    pub n: [f64; 2],
    /// The bearings' total reactions R₁, R₂ = N·√(1 + f²), N.
    pub r: [f64; 2],
    /// The jamming angle λ_кр, rad.
    pub lock: f64,
}

/// The twin, from [`crate::cam::force`]; `None` when the follower jams (λ ≥ λ_кр).
pub fn guide_twin(c: &FollowerGuide) -> Option<GuideTwin> {
    let g = &c.guide;
    let forces = translating_forces(c.load, c.angle, g)?;
    let total = g.f.hypot(1.0);
    Some(GuideTwin {
        phi: friction_angle(g.f),
        p: forces.p,
        n: [forces.r1, forces.r2],
        r: [forces.r1 * total, forces.r2 * total],
        lock: translating_locking(g),
    })
}

/// The directions of R₁ and R₂ acting on the rod: against P's side push at the nearer
/// bearing, with it at the farther, each leaning by φ against the motion (+y).
fn reaction_dirs(f: f64) -> [DVec2; 2] {
    [
        DVec2::new(-1.0, -f).normalize(),
        DVec2::new(1.0, -f).normalize(),
    ]
}

/// The scheme at μ_l: the rod K…, its two bearings, P along the cam's normal at λ, Q, the
/// reactions' lines turned by φ meeting at Z, the line KZ and λ_кр. Returns the drawing and
/// λ_кр read (arctg of Z's distance from the axis over its height, both measured).
fn scheme(
    case: &FrictionCase,
    c: &FollowerGuide,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<(Drawing, f64), FrictionError> {
    let g = &c.guide;
    let reach = g.length / (2.0 * g.f);
    let mut rec = case.scheme_recorder(reach.max(g.overhang + 1.3 * g.length), SCHEME_MM, ctx)?;
    let mu = rec.scale();
    let (l, b) = (mu.to_mm(g.overhang), mu.to_mm(g.length));
    let bearings = [DVec2::new(0.0, l), DVec2::new(0.0, l + b)];
    let top = l + 1.3 * b;
    rod(&mut rec, bearings, top);
    let k = DVec2::ZERO;
    let kid = rec.point(
        "the contact K",
        k,
        Role::Given,
        "K",
        DVec2::new(-1.0, -0.4),
        &[],
    );
    let p_dir = DVec2::new(c.angle.sin(), c.angle.cos());
    let n = rec.draw(
        "the common normal n–n at K",
        Item::Segment(Segment::new(k - p_dir * 14.0, k + p_dir * (top * 0.8))),
        Role::Axis,
        &[kid],
    );
    rec.label(n, "n", k + p_dir * (top * 0.8), p_dir.perp());
    arrow(
        &mut rec,
        "the cam's force P along the normal",
        (k - p_dir * 24.0, k),
        Role::Given,
        "P",
        -p_dir.perp(),
    );
    angle_mark(&mut rec, "λ", k, 12.0, (DVec2::Y, p_dir), "λ");
    arrow(
        &mut rec,
        "the resistance Q along the axis",
        (DVec2::new(0.0, top + 16.0), DVec2::new(0.0, top)),
        Role::Given,
        "Q",
        -DVec2::X,
    );
    let dirs = reaction_dirs(g.f);
    // Each reaction's line through its bearing, run out to the side P pushes towards.
    let lines = [0, 1].map(|i| Line {
        point: bearings[i],
        direction: dirs[i],
    });
    let (z, _, zid) = rec
        .meet_lines(
            "Z",
            ("the line of R₁", &lines[0]),
            ("the line of R₂", &lines[1]),
        )
        .map_err(wrap)?;
    rec.label(zid, "Z", z, DVec2::new(1.0, 0.2).normalize());
    for (i, name) in [(0, "R_{1}"), (1, "R_{2}")] {
        thin_line(&mut rec, &format!("the line of {name}"), bearings[i], z);
        arrow(
            &mut rec,
            &format!("the total reaction {name}"),
            (
                bearings[i] - dirs[i] * 16.0,
                bearings[i] - dirs[i] * (ROD_MM + 1.0),
            ),
            Role::Result,
            name,
            DVec2::new(0.0, if i == 0 { -1.0 } else { 1.0 }),
        );
        rec.draw(
            format!("the normal at bearing {}", i + 1),
            Item::Segment(Segment::new(
                bearings[i] + DVec2::X * ROD_MM,
                bearings[i] + DVec2::X * 36.0,
            )),
            Role::Construction,
            &[],
        );
        let toward = z - bearings[i];
        angle_mark(&mut rec, "φ", bearings[i], 30.0, (DVec2::X, toward), "φ");
    }
    thin_line(&mut rec, "the line of R₁₂ = R₁ + R₂: K and Z", k, z);
    angle_mark(&mut rec, "λ_кр", k, 26.0, (DVec2::Y, z - k), "λ_{кр}");
    // λ_кр read: Z's distance from the axis over its height.
    let level = DVec2::new(0.0, z.y);
    thin_line(&mut rec, "Z projected on the axis", z, level);
    let lock = rec
        .measure(level, z)
        .read_mm
        .atan2(rec.measure(k, level).read_mm);
    let drawing = Drawing {
        kind: DrawingKind::Scheme,
        figure: rec.finish(),
        scaled: true,
        also: Vec::new(),
    };
    Ok((drawing, lock))
}

/// The rod along the axis from K up to `top` (mm), its axis, the two bearings hatched on
/// both sides at `bearings`, and the dimensions l and b.
fn rod(rec: &mut Recorder, bearings: [DVec2; 2], top: f64) {
    rec.draw(
        "the follower's axis",
        Item::Segment(Segment::new(
            DVec2::new(0.0, -6.0),
            DVec2::new(0.0, top + 6.0),
        )),
        Role::Axis,
        &[],
    );
    for x in [-ROD_MM, ROD_MM] {
        rec.draw(
            "the follower (rod)",
            Item::Segment(Segment::new(DVec2::new(x, 0.0), DVec2::new(x, top))),
            Role::Given,
            &[],
        );
    }
    rec.draw(
        "the rod's end at K",
        Item::Segment(Segment::new(
            DVec2::new(-ROD_MM, 0.0),
            DVec2::new(ROD_MM, 0.0),
        )),
        Role::Given,
        &[],
    );
    for (i, at) in bearings.iter().enumerate() {
        for (x, hatch) in [(-ROD_MM, Side::Left), (ROD_MM, Side::Right)] {
            rec.draw(
                format!("bearing {} of the guide", i + 1),
                Item::Guide {
                    segment: Segment::new(DVec2::new(x, at.y - 5.0), DVec2::new(x, at.y + 5.0)),
                    hatch,
                },
                Role::Given,
                &[],
            );
        }
    }
    let dim = |rec: &mut Recorder, from: DVec2, to: DVec2, text: &str| {
        let id = rec.draw(
            format!("the dimension {text}"),
            Item::Dimension {
                from,
                to,
                offset: 14.0,
            },
            Role::Dimension,
            &[],
        );
        rec.label(id, text, (from + to) / 2.0 - DVec2::X * 14.0, -DVec2::X);
    };
    dim(rec, DVec2::ZERO, bearings[0], "l");
    dim(rec, bearings[0], bearings[1], "b");
}

/// The force plan at μ_F: Q + P + R₁₂ = 0 (R₁₂ along ZK), then R₁₂ split into R₁ and R₂
/// along their lines. Returns it with P, R₁, R₂ read and the crossing angle of P and R₁₂.
fn plan(
    case: &FrictionCase,
    c: &FollowerGuide,
    kz: DVec2,
    largest: f64,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<(Drawing, [f64; 3], f64), FrictionError> {
    let mut rec = case.force_recorder(largest, ctx)?;
    let p_dir = DVec2::new(c.angle.sin(), c.angle.cos());
    let t = triangle(
        &mut rec,
        DVec2::ZERO,
        DVec2::new(0.0, -c.load),
        (p_dir, -kz),
        ["Q", "P", "R_{12}"],
        (Role::Result, Third::Closes),
    )
    .map_err(wrap)?;
    let dirs = reaction_dirs(c.guide.f);
    let (d, _, _) = rec
        .meet_lines(
            "R₁₂ split",
            (
                "R₁ from R₁₂'s start",
                &Line {
                    point: t.c,
                    direction: dirs[0],
                },
            ),
            (
                "R₂ to R₁₂'s end",
                &Line {
                    point: t.a,
                    direction: dirs[1],
                },
            ),
        )
        .map_err(wrap)?;
    let centre = (t.c + d + t.a) / 3.0;
    for (name, (from, to)) in [("R_{1}", (t.c, d)), ("R_{2}", (d, t.a))] {
        let mid = from.lerp(to, 0.5);
        arrow(
            &mut rec,
            name,
            (from, to),
            Role::Result,
            name,
            (mid - centre).normalize_or(DVec2::X),
        );
    }
    let r1 = rec.measure(t.c, d).value;
    let r2 = rec.measure(d, t.a).value;
    let drawing = Drawing {
        kind: DrawingKind::Polygon,
        figure: rec.finish(),
        scaled: true,
        also: Vec::new(),
    };
    Ok((drawing, [t.p, r1, r2], t.crossing_deg))
}

/// The refusal of a `who` (the follower, the rocker) that jams: its pressure angle λ not
/// below the jamming angle λ_кр read off the scheme by [`MIN_CROSSING_DEG`] (both rad), with
/// `rule`, λ_кр's closed form and the data.
pub(super) fn jams(
    case: &FrictionCase,
    who: &str,
    (lambda, lock): (f64, f64),
    rule: String,
) -> FrictionError {
    FrictionError::Impossible {
        case: case.name.clone(),
        why: format!(
            "the {who} jams: λ = {:.2}° is not below the jamming angle λ_кр = {:.2}° ({rule}) \
             by {MIN_CROSSING_DEG}°",
            lambda.to_degrees(),
            lock.to_degrees()
        ),
    }
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &FollowerGuide,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let (scheme, lock_read) = scheme(case, c, ctx, wrap)?;
    let g = &c.guide;
    // The follower moves only while P's line passes the axis's side of Z (by the drawing).
    let rule = || {
        format!(
            "tg λ_кр = b/(f(2l + b)), b = {} m, l = {} m, f = {}",
            g.length, g.overhang, g.f
        )
    };
    if lock_read - c.angle < MIN_CROSSING_DEG.to_radians() {
        return Err(jams(case, "follower", (c.angle, lock_read), rule()));
    }
    let twin = guide_twin(c).ok_or_else(|| jams(case, "follower", (c.angle, lock_read), rule()))?;
    let kz = DVec2::new(lock_read.sin(), lock_read.cos());
    let largest = [c.load, twin.p, twin.r[0], twin.r[1]]
        .into_iter()
        .fold(0.0f64, f64::max);
    let (plan, [p, r1, r2], crossing) = plan(case, c, kz, largest, ctx, wrap)?;
    let cond = Some(crossing);
    let name = &case.name;
    let readings: Vec<CaseReading> = vec![
        reading("P", (Symbol::Force, subject("P", name)), p, twin.p, cond),
        reading(
            "R_{1}",
            (Symbol::Reaction, subject("1", name)),
            r1,
            twin.r[0],
            cond,
        ),
        reading(
            "R_{2}",
            (Symbol::Reaction, subject("2", name)),
            r2,
            twin.r[1],
            cond,
        ),
        reading(
            "λ_{кр}",
            (Symbol::Angle, subject("lock", name)),
            lock_read,
            twin.lock,
            None,
        ),
    ];
    let notes = vec![FrictionNote::Guide {
        case: name.to_string(),
        angle: c.angle,
        lock: twin.lock,
        useful: twin.p * c.angle.cos(),
        across: twin.p * c.angle.sin(),
    }];
    Ok(Solved {
        case: case.clone(),
        drawings: vec![scheme, plan],
        readings,
        notes,
    })
}
