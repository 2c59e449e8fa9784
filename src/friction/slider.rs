//! A slider on a plane pressed by a force P at the angle α from the normal (seed 001
//! L1205–1268, Fig. 43–45): N = P·cos α, P₁ = P·sin α along the plane, the friction force
//! F = f·N. The slider is at rest while α < φ₀ (the static limit, φ₀ = arctg f₀, F₀ ≤ N·f₀),
//! moves uniformly at α = φ and accelerates when α > φ, whatever P is: the state is the
//! force's line against the friction cone. Its weight on an inclined plane (Fig. 43) is the
//! same case with P = G and α the slope.
//!
//! The construction: the scheme with the friction cone and P; the triangle P + R₀ = ΔP with
//! R₀ along the static cone's generator (turned by φ₀ against the motion) and their resultant
//! ΔP along the plane (the side from P's start to R₀'s end): a negative ΔP is the static
//! friction's reserve P₁ − f₀·N, the slider stays; otherwise the triangle with R along the
//! sliding cone's generator (φ) measures the net force ΔP = P₁ − f·N driving it (zero:
//! uniform motion). The side is named by the quantity it reads, ΔP (issue 45), not as an
//! inertia force.
//!
//! `R_<name>` is the total reaction that acts: sliding, N/cos φ on the generator; at rest
//! −P, inside the cone (R₀ − ΔP read as the triangle's closing side), below the static
//! cone's limit N/cos φ₀ (the side R₀, stated on the sheet) by up to 1/cos φ₀.

use super::draw::{angle_mark, arrow, cone, thin_line, triangle, turned, Third, CONE_MM};
use super::{
    friction_angle, reading, subject, CaseReading, Drawing, DrawingKind, FrictionCase,
    FrictionError, Slider, Solved,
};
use crate::check::notes::friction::{FrictionNote, SliderMotion};
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Role};
use crate::geom::{DVec2, Segment, Side};

/// What the slider does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SliderState {
    /// α < φ₀: the force's line inside the cone of static friction, the slider stays.
    Rest,
    /// α = φ: on the cone's generator, uniform motion (the friction balances P₁).
    Uniform,
    /// α > φ (and past the static limit): P₁ exceeds the friction, the slider accelerates.
    Accelerating,
}

/// How near α must be to φ for the motion to count as uniform, rad.
const UNIFORM_RAD: f64 = 1e-9;

/// The closed form of a slider pressed at α.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderTwin {
    /// φ = arctg f, rad.
    pub phi: f64,
    /// φ₀ = arctg f₀, rad.
    pub phi0: f64,
    /// N = P·cos α, N.
    pub n: f64,
    /// P₁ = P·sin α, N.
    pub p1: f64,
    /// The total reaction that acts, N: sliding, on the sliding cone's generator, N/cos φ;
    /// at rest, −P (the static friction F₀ = P₁ balances P₁): √(N² + P₁²).
    pub r: f64,
    /// The static cone's limit N/cos φ₀, N: the largest reaction the plane can give before
    /// the slider moves (what R₀ of the triangle on the static generator measures).
    pub r_limit: f64,
    /// ΔP = P₁ − f·N = P(sin α − f cos α), N: the net force along the plane when it slides;
    /// at rest P₁ − f₀·N < 0, the static friction's reserve.
    pub net: f64,
    /// The state.
    pub state: SliderState,
}

/// The twin: the components of P and the state by α against φ and φ₀.
pub fn slider_twin(c: &Slider) -> SliderTwin {
    let (phi, phi0) = (friction_angle(c.f), friction_angle(c.f0));
    let (n, p1) = (c.load * c.alpha.cos(), c.load * c.alpha.sin());
    let state = if c.alpha < phi0 - UNIFORM_RAD {
        SliderState::Rest
    } else if (c.alpha - phi).abs() <= UNIFORM_RAD {
        SliderState::Uniform
    } else {
        SliderState::Accelerating
    };
    // At rest the static cone decides: the reserve P₁ − f₀·N (< 0); sliding, P₁ − f·N.
    let f_state = if state == SliderState::Rest {
        c.f0
    } else {
        c.f
    };
    let phi_state = friction_angle(f_state);
    SliderTwin {
        phi,
        phi0,
        n,
        p1,
        r: if state == SliderState::Rest {
            n.hypot(p1)
        } else {
            n / phi_state.cos()
        },
        r_limit: n / phi0.cos(),
        net: p1 - f_state * n,
        state,
    }
}

/// P acting on the slider: pressing into the plane at α from the normal, leaning along +x.
fn p_vector(c: &Slider) -> DVec2 {
    DVec2::new(c.alpha.sin(), -c.alpha.cos()) * c.load
}

/// The scheme: the plane, the slider, P at α from the normal, the friction cone and the
/// reaction that acts — on the sliding cone's generator when the triangles say the slider
/// moves, along −P inside the static cone when it stays (`rest`). Returns it with φ read off
/// the cone's base.
fn scheme(
    case: &FrictionCase,
    c: &Slider,
    rest: bool,
    ctx: &Context,
) -> Result<(Drawing, f64), FrictionError> {
    let mut rec = case.schematic_recorder(ctx)?;
    rec.draw(
        "the plane",
        Item::Guide {
            segment: Segment::new(DVec2::new(-48.0, 0.0), DVec2::new(48.0, 0.0)),
            hatch: Side::Right,
        },
        Role::Given,
        &[],
    );
    let g = DVec2::new(0.0, 3.0);
    rec.draw(
        "the slider",
        Item::Slider { at: g, angle: 0.0 },
        Role::Given,
        &[],
    );
    let p_dir = p_vector(c).normalize_or(-DVec2::Y);
    // P pressing on the slider's top left corner, clear of the cone at the contact.
    let corner = g + DVec2::new(-Item::SLIDER_HALF_MM.0, Item::SLIDER_HALF_MM.1);
    arrow(
        &mut rec,
        "the force P pressing the slider",
        (corner - p_dir * (0.6 * CONE_MM), corner),
        Role::Given,
        "P",
        DVec2::new(-1.0, 0.0),
    );
    rec.draw(
        "the normal through P's point",
        Item::Segment(Segment::new(corner, corner + DVec2::Y * 30.0)),
        Role::Construction,
        &[],
    );
    angle_mark(
        &mut rec,
        "α, P from the normal",
        corner,
        21.0,
        (DVec2::Y, -p_dir),
        "α",
    );
    let (left, _, top) = cone(&mut rec, DVec2::ZERO, DVec2::Y, c.f, CONE_MM);
    if rest && c.f0 > c.f {
        // The static cone (φ₀) the reaction stays within.
        for side in [1.0, -1.0] {
            rec.draw(
                "the static friction cone's generator at φ₀",
                Item::Segment(Segment::new(
                    DVec2::ZERO,
                    DVec2::new(-side * c.f0 * CONE_MM, CONE_MM),
                )),
                Role::Construction,
                &[],
            );
        }
        angle_mark(
            &mut rec,
            "φ₀, the static cone",
            DVec2::ZERO,
            33.0,
            (DVec2::Y, DVec2::new(c.f0, 1.0)),
            "φ_{0}",
        );
        // And the sliding cone inside it, named by its own angle.
        angle_mark(
            &mut rec,
            "φ, the sliding cone",
            DVec2::ZERO,
            24.0,
            (DVec2::Y, DVec2::new(c.f, 1.0)),
            "φ",
        );
    }
    let (note, r_dir) = if rest {
        (
            "the reaction R = −P inside the cone: the slider stays",
            -p_dir,
        )
    } else {
        (
            "the total reaction R on the cone's generator",
            turned(DVec2::Y, friction_angle(c.f)),
        )
    };
    arrow(
        &mut rec,
        note,
        (DVec2::ZERO, r_dir * (CONE_MM + 6.0)),
        Role::Result,
        "R",
        DVec2::new(-1.0, 0.0),
    );
    let across = rec.measure(top, left).read_mm;
    let along = rec.measure(DVec2::ZERO, top).read_mm;
    let drawing = Drawing {
        kind: DrawingKind::Scheme,
        figure: rec.finish(),
        scaled: false,
        also: Vec::new(),
    };
    Ok((drawing, across.atan2(along)))
}

/// What the force triangles read: the state they tell, the reaction that acts, N, ΔP (or the
/// reserve) and the crossing angle of the deciding triangle.
struct Triangles {
    drawing: Drawing,
    state: SliderState,
    r: f64,
    n: f64,
    net: f64,
    crossing_deg: f64,
}

/// The triangle P + R₀ = ΔP with R₀ along the static cone's generator (φ₀): a negative ΔP
/// is the static friction's reserve, the slider stays, and the reaction that acts is
/// R₀ − ΔP = −P, the side from P's end to its start read; otherwise (or at the limit) the
/// triangle along the sliding cone's generator (φ) gives R and the net force ΔP.
fn triangles(
    case: &FrictionCase,
    c: &Slider,
    largest: f64,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Triangles, FrictionError> {
    let (phi, phi0) = (friction_angle(c.f), friction_angle(c.f0));
    let mut rec = case.force_recorder(largest, ctx)?;
    // The net force is zero to the drawing's resolution (a rounding residue when exact).
    let eps = rec.scale().value() * ctx.drafting.resolution_mm().max(1e-9);
    let closed = |rec: &mut crate::construct::Recorder, phi: f64, at: DVec2, names| {
        triangle(
            rec,
            at,
            p_vector(c),
            (turned(DVec2::Y, phi), DVec2::X),
            names,
            (Role::Result, Third::Resultant),
        )
    };
    let mut t = closed(&mut rec, phi0, DVec2::ZERO, ["P", "R_{0}", "ΔP"]).map_err(wrap)?;
    let mut state = SliderState::Rest;
    // At rest the reaction that acts closes P: R₀ less the reserve ΔP, b → a.
    let mut r = rec.measure(t.b, t.a).value;
    if t.r >= -eps {
        if c.f0 > c.f {
            let right = [t.a, t.b, t.c]
                .into_iter()
                .fold(f64::NEG_INFINITY, |m, p| m.max(p.x));
            t = closed(
                &mut rec,
                phi,
                DVec2::new(right + 20.0, 0.0),
                ["P", "R", "ΔP"],
            )
            .map_err(wrap)?;
        }
        state = if t.r.abs() <= eps {
            SliderState::Uniform
        } else {
            SliderState::Accelerating
        };
        r = t.p;
    }
    // N: R's component along the normal, projected across.
    let foot = DVec2::new(t.b.x, t.c.y);
    thin_line(&mut rec, "R's component along the normal: N", t.b, foot);
    let n = rec.measure(t.b, foot).value;
    Ok(Triangles {
        drawing: Drawing {
            kind: DrawingKind::Polygon,
            figure: rec.finish(),
            scaled: true,
            also: Vec::new(),
        },
        state,
        r,
        n,
        net: t.r,
        crossing_deg: t.crossing_deg,
    })
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Slider,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = slider_twin(c);
    let largest = [c.load, twin.r, twin.r_limit, twin.net.abs()]
        .into_iter()
        .fold(0.0_f64, f64::max);
    let t = triangles(case, c, largest, ctx, wrap)?;
    let state = t.state;
    let (scheme, phi_read) = scheme(case, c, state == SliderState::Rest, ctx)?;
    let cond = Some(t.crossing_deg);
    let name = &case.name;
    let readings: Vec<CaseReading> = vec![
        reading(
            "φ",
            (Symbol::Angle, subject("phi", name)),
            phi_read,
            twin.phi,
            None,
        ),
        reading(
            "R",
            (Symbol::Reaction, subject("", name)),
            t.r,
            twin.r,
            cond,
        ),
        reading("N", (Symbol::Force, subject("N", name)), t.n, twin.n, cond),
        reading(
            "ΔP",
            (Symbol::Force, subject("dP", name)),
            t.net,
            twin.net,
            cond,
        ),
    ];
    let motion = |s: SliderState| match s {
        SliderState::Rest => SliderMotion::Rest,
        SliderState::Uniform => SliderMotion::Uniform,
        SliderState::Accelerating => SliderMotion::Accelerating,
    };
    let notes = vec![FrictionNote::Slider {
        case: name.to_string(),
        alpha: c.alpha,
        phi: twin.phi,
        phi0: twin.phi0,
        by_angles: motion(twin.state),
        by_triangle: motion(state),
        net: t.net,
    }];
    Ok(Solved {
        case: case.clone(),
        drawings: vec![scheme, t.drawing],
        readings,
        notes,
    })
}
