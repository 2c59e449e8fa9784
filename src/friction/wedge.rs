//! The V-groove (wedge) slider (seed 001 §10.5, Fig. 49): the load Q splits into the two
//! flanks' normal forces, `N = Q/(2·sin(β/2))`; the friction on both flanks is the force that
//! pushes the slider, `P = 2·f·N = f·Q/sin(β/2)`: a flat slider with the reduced coefficient
//! `f′ = f/sin(β/2) = tg φ′`.

use super::draw::{angle_mark, arrow, triangle, Third};
use super::{
    friction_angle, reading, subject, Drawing, DrawingKind, FrictionCase, FrictionError, Solved,
    Wedge,
};
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Role};
use crate::geom::{DVec2, Segment, Side};

/// The closed form of a V-groove slider.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WedgeTwin {
    /// The normal force on each flank, N.
    pub n: f64,
    /// The pushing force, N.
    pub p: f64,
    /// The reduced coefficient f′ = f/sin(β/2).
    pub f_reduced: f64,
    /// The reduced friction angle φ′, rad.
    pub phi_reduced: f64,
}

/// The twin of a V-groove slider.
pub fn wedge_twin(c: &Wedge) -> WedgeTwin {
    let half = (c.groove / 2.0).sin();
    let f_reduced = c.f / half;
    WedgeTwin {
        n: c.load / (2.0 * half),
        p: c.f * c.load / half,
        f_reduced,
        phi_reduced: friction_angle(f_reduced),
    }
}

/// The unit directions up the left and right flanks from the groove's apex, and the flanks'
/// normals into the slider.
fn flanks(c: &Wedge) -> ([DVec2; 2], [DVec2; 2]) {
    let (s, k) = (c.groove / 2.0).sin_cos();
    (
        [DVec2::new(-s, k), DVec2::new(s, k)],
        [DVec2::new(k, s), DVec2::new(-k, s)],
    )
}

/// The cross-section: the groove, the slider, Q and the flanks' normal forces.
fn scheme(case: &FrictionCase, c: &Wedge, ctx: &Context) -> Result<Drawing, FrictionError> {
    let mut rec = case.schematic_recorder(ctx)?;
    let ([left, right], [n1, n2]) = flanks(c);
    for (dir, hatch, name) in [(left, Side::Left, "left"), (right, Side::Right, "right")] {
        rec.draw(
            format!("the {name} flank of the groove"),
            Item::Guide {
                segment: Segment::new(DVec2::ZERO, dir * 44.0),
                hatch,
            },
            Role::Given,
            &[],
        );
    }
    let lift = DVec2::Y * 10.0;
    let body = vec![
        left * 12.0,
        left * 36.0,
        left * 36.0 + lift,
        right * 36.0 + lift,
        right * 36.0,
        right * 12.0,
    ];
    rec.draw(
        "the slider",
        Item::Polyline {
            points: body,
            closed: true,
        },
        Role::Given,
        &[],
    );
    angle_mark(&mut rec, "β", DVec2::ZERO, 8.0, (right, left), "β");
    let top = DVec2::new(0.0, left.y * 36.0 + lift.y);
    arrow(
        &mut rec,
        "the load",
        (top + DVec2::Y * 16.0, top),
        Role::Given,
        "Q",
        DVec2::X,
    );
    for (k, at, n) in [(1, left * 24.0, n1), (2, right * 24.0, n2)] {
        let name = format!("N_{{{k}}}");
        arrow(
            &mut rec,
            &name,
            (at - n * 18.0, at),
            Role::Result,
            &name,
            n.perp(),
        );
    }
    Ok(Drawing {
        kind: DrawingKind::Scheme,
        figure: rec.finish(),
        scaled: false,
        also: Vec::new(),
    })
}

/// Construct the case and read it: the flanks' triangle Q + N₁ + N₂ = 0, then the side view
/// with P = f·(N₁ + N₂) as read and the reduced angle φ′ read off it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Wedge,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = wedge_twin(c);
    let scheme = scheme(case, c, ctx)?;
    let largest = c.load.max(twin.n).max(twin.p);
    let mut rec = case.force_recorder(largest, ctx)?;
    let mu = rec.scale();
    let (_, [n1, n2]) = flanks(c);
    let q = DVec2::new(0.0, -c.load);
    let t = triangle(
        &mut rec,
        DVec2::ZERO,
        q,
        (n1, n2),
        ["Q", "N_{1}", "N_{2}"],
        (Role::Result, Third::Closes),
    )
    .map_err(wrap)?;
    let p = c.f * (t.p + t.r);
    // The side view: Q, then P along the groove (to the right), R′ closing.
    let right = [t.a, t.b, t.c]
        .into_iter()
        .fold(f64::NEG_INFINITY, |m, p| m.max(p.x));
    let a = DVec2::new(right + 25.0, 0.0);
    let b = a + q / mu.value();
    let e = b + DVec2::X * mu.to_mm(p);
    arrow(
        &mut rec,
        "Q (side view)",
        (a, b),
        Role::Given,
        "Q",
        -DVec2::X,
    );
    arrow(
        &mut rec,
        "P = f·(N₁ + N₂)",
        (b, e),
        Role::Result,
        "P",
        -DVec2::Y,
    );
    arrow(&mut rec, "R′", (e, a), Role::Result, "R′", DVec2::X);
    angle_mark(&mut rec, "φ′", a, 16.0, (q, e - a), "φ′");
    let phi_read = rec.measure(b, e).read_mm.atan2(rec.measure(a, b).read_mm);
    let cond = Some(t.crossing_deg);
    let readings = vec![
        reading(
            "N",
            (Symbol::Force, subject("N", &case.name)),
            t.p,
            twin.n,
            cond,
        ),
        reading(
            "P",
            (Symbol::Force, subject("P", &case.name)),
            p,
            twin.p,
            cond,
        ),
        reading(
            "φ′",
            (Symbol::Angle, subject("phi", &case.name)),
            phi_read,
            twin.phi_reduced,
            cond,
        ),
    ];
    Ok(Solved {
        case: case.clone(),
        drawings: vec![
            scheme,
            Drawing {
                kind: DrawingKind::Flanks,
                figure: rec.finish(),
                scaled: true,
                also: Vec::new(),
            },
        ],
        readings,
        notes: Vec::new(),
    })
}
