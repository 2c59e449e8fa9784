//! Uniform motion on an inclined plane under a force P at β′ above the horizontal (seed 001
//! §10.4, Fig. 47–48): the scheme with the friction cone, and the force triangle
//! Q + P + R = 0 with R turned from the normal by φ against the motion; beside it the same
//! triangle without friction, whose P₀ gives the efficiency.

use super::draw::{angle_mark, arrow, cone, triangle, turned, Third, Triangle, CONE_MM};
use super::{
    friction_angle, reading, subject, CaseReading, Drawing, DrawingKind, FrictionCase,
    FrictionError, Incline, Motion, Solved,
};
use crate::check::notes::FrictionNote;
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Recorder, Role};
use crate::geom::{DVec2, Segment, Side};

/// The smallest angle, degrees, between the lines of P and R that still closes a triangle a
/// hand can draw; below it P would exceed ~29 Q and the motion is refused.
pub const MIN_CROSSING_DEG: f64 = 2.0;

/// The closed form of uniform motion on an inclined plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InclineTwin {
    /// The friction angle φ = arctg f, rad.
    pub phi: f64,
    /// The driving (up) or holding (down) force P, N: `Q·sin(α ± φ)/cos(α ± φ − β′)`;
    /// negative when the body must be pushed down (self-braking).
    pub p: f64,
    /// The total reaction |R|, N.
    pub r: f64,
    /// P without friction, `Q·sin α/cos(α − β′)`, N.
    pub p0: f64,
    /// |R| without friction, N.
    pub r0: f64,
    /// The efficiency: P₀/P up the plane; P/P₀ down it (≤ 0: self-braking); 0 on a level
    /// plane (no work is done against the load).
    pub eta: f64,
    /// Down the plane with α ≤ φ: the body stays put under any load.
    pub self_braking: bool,
}

/// The twin of an inclined plane: the explicit vector solution of Q + P + R = 0 (the
/// printed `cos(α + β + φ)` of the seed is an erratum).
pub fn incline_twin(c: &Incline) -> InclineTwin {
    let phi = friction_angle(c.f);
    let s = c.motion.sign();
    let q = c.load;
    let p = q * (c.alpha + s * phi).sin() / (c.alpha + s * phi - c.beta).cos();
    let p0 = q * c.alpha.sin() / (c.alpha - c.beta).cos();
    // R = −(Q + P) with Q = (0, −q) and P along (cos β′, sin β′).
    let reaction = |p: f64| DVec2::new(-p * c.beta.cos(), q - p * c.beta.sin()).length();
    let eta = match c.motion {
        _ if p0 == 0.0 => 0.0,
        Motion::Up => p0 / p,
        Motion::Down => p / p0,
    };
    InclineTwin {
        phi,
        p,
        r: reaction(p),
        p0,
        r0: reaction(p0),
        eta,
        self_braking: c.motion == Motion::Down && c.alpha <= phi,
    }
}

/// The directions of P and of R (acting on the body) and the plane's rise `u`.
fn directions(c: &Incline, phi: f64) -> (DVec2, DVec2, DVec2) {
    let u = DVec2::from_angle(c.alpha);
    let n = u.perp();
    let p_dir = DVec2::from_angle(c.beta);
    // Against the motion: up the plane R leans back (counter-clockwise from n).
    let r_dir = turned(n, c.motion.sign() * phi);
    (p_dir, r_dir, u)
}

/// Refuse a motion whose P and R lines (nearly) coincide in direction.
pub(super) fn feasible(case: &str, c: &Incline, phi: f64) -> Result<(), FrictionError> {
    let s = c.motion.sign();
    let lean = c.alpha + s * phi - c.beta;
    if lean.cos() < MIN_CROSSING_DEG.to_radians().sin() {
        return Err(FrictionError::Impossible {
            case: case.to_string(),
            why: format!(
                "α {} φ − β′ = {:.2}°: the force P at β′ = {:.2}° cannot move the body uniformly \
                 (the lines of P and R cross at less than {MIN_CROSSING_DEG}°)",
                if s > 0.0 { "+" } else { "−" },
                lean.to_degrees(),
                c.beta.to_degrees()
            ),
        });
    }
    Ok(())
}

/// The scheme: the plane, the body, the loads, the friction cone and the reaction. Returns
/// the drawing and the friction angle as read off the cone.
pub(super) fn scheme(
    case: &FrictionCase,
    c: &Incline,
    ctx: &Context,
) -> Result<(Drawing, f64), FrictionError> {
    let u = DVec2::from_angle(c.alpha);
    let mut rec = case.schematic_recorder(ctx)?;
    // The plane reaches past the cone and the reaction on both sides.
    let half = CONE_MM + 6.0;
    let foot = -u * half;
    rec.draw(
        "the inclined plane",
        Item::Guide {
            segment: Segment::new(foot, u * half),
            hatch: Side::Right,
        },
        Role::Given,
        &[],
    );
    if c.alpha > 0.0 {
        rec.draw(
            "the horizontal",
            Item::Segment(Segment::new(foot, foot + DVec2::X * half)),
            Role::Construction,
            &[],
        );
        angle_mark(&mut rec, "α", foot, 0.5 * half, (DVec2::X, u), "α");
    }
    let phi_read = body_on_plane(&mut rec, c, DVec2::ZERO);
    Ok((
        Drawing {
            kind: DrawingKind::Scheme,
            figure: rec.finish(),
            scaled: false,
            also: Vec::new(),
        },
        phi_read,
    ))
}

/// The body on the plane at the contact `at`: the block, its velocity, Q and P, the friction
/// cone and the total reaction R with its angle φ. Returns φ as read off the cone (arctg of
/// f·N over N, both measured).
pub(super) fn body_on_plane(rec: &mut Recorder, c: &Incline, at: DVec2) -> f64 {
    let phi = friction_angle(c.f);
    let (p_dir, r_dir, u) = directions(c, phi);
    let n = u.perp();
    let g = at + n * 3.0;
    rec.draw(
        "the body",
        Item::Slider {
            at: g,
            angle: c.alpha,
        },
        Role::Given,
        &[],
    );
    let s = c.motion.sign();
    let v_from = g + n * 10.0 - u * (8.0 * s);
    let v = (v_from, v_from + u * (16.0 * s));
    arrow(rec, "the velocity", v, Role::Dimension, "v", n);
    let load = 0.6 * CONE_MM;
    arrow(
        rec,
        "the load",
        (g, g - DVec2::Y * load),
        Role::Given,
        "Q",
        DVec2::X,
    );
    // P from the body, or onto it where drawn from it it would run into the plane (a
    // horizontal P on the way down).
    let p = if (g + p_dir * load - at).dot(n) < 0.0 {
        (g - p_dir * load, g)
    } else {
        (g, g + p_dir * load)
    };
    arrow(rec, "the force", p, Role::Given, "P", -DVec2::Y);
    let (left, right, top) = cone(rec, at, n, c.f, CONE_MM);
    let (edge, side) = if s > 0.0 {
        (left, n.perp())
    } else {
        (right, -n.perp())
    };
    let r = (at, at + r_dir * (CONE_MM + 6.0));
    arrow(rec, "the total reaction R", r, Role::Result, "R", side);
    angle_mark(rec, "φ", at, 0.7 * CONE_MM, (n, r_dir), "φ");
    let across = rec.measure(top, edge).read_mm;
    let along = rec.measure(at, top).read_mm;
    across.atan2(along)
}

/// The force triangles with and without friction, at μ_F.
pub(super) fn polygon(
    case: &FrictionCase,
    c: &Incline,
    twin: &InclineTwin,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<(Drawing, Triangle, Option<Triangle>), FrictionError> {
    let largest = [c.load, twin.p, twin.r, twin.p0, twin.r0]
        .into_iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let mut rec = case.force_recorder(largest, ctx)?;
    let (p_dir, r_dir, u) = directions(c, twin.phi);
    let q = DVec2::new(0.0, -c.load);
    let with = triangle(
        &mut rec,
        DVec2::ZERO,
        q,
        (p_dir, r_dir),
        ["Q", "P", "R"],
        (Role::Result, Third::Closes),
    )
    .map_err(wrap)?;
    // Without friction (η): on a level plane nothing is lifted, no triangle.
    let without = if c.alpha > 0.0 {
        let right = [with.a, with.b, with.c]
            .into_iter()
            .fold(f64::NEG_INFINITY, |m, p| m.max(p.x));
        let at = DVec2::new(right + 25.0, 0.0);
        let t = triangle(
            &mut rec,
            at,
            q,
            (p_dir, u.perp()),
            ["Q", "P_{0}", "R_{0}"],
            (Role::Result, Third::Closes),
        )
        .map_err(wrap)?;
        Some(t)
    } else {
        None
    };
    Ok((
        Drawing {
            kind: DrawingKind::Polygon,
            figure: rec.finish(),
            scaled: true,
            also: Vec::new(),
        },
        with,
        without,
    ))
}

/// The efficiency read off the two triangles (the twin's rule).
pub(super) fn eta_read(motion: Motion, p: f64, p0: Option<f64>) -> f64 {
    match (motion, p0) {
        (_, None | Some(0.0)) => 0.0,
        (Motion::Up, Some(p0)) => p0 / p,
        (Motion::Down, Some(p0)) => p / p0,
    }
}

/// The readings of an incline-like case (shared with the screw, whose P is tangential).
pub(super) fn readings(
    name: &str,
    twin: &InclineTwin,
    with: &Triangle,
    eta: f64,
) -> Vec<CaseReading> {
    let cond = Some(with.crossing_deg);
    vec![
        reading(
            "P",
            (Symbol::Force, subject("P", name)),
            with.p,
            twin.p,
            cond,
        ),
        reading(
            "R",
            (Symbol::Reaction, subject("", name)),
            with.r,
            twin.r,
            cond,
        ),
        reading("η", (Symbol::Ratio, subject("", name)), eta, twin.eta, cond),
    ]
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Incline,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = incline_twin(c);
    feasible(&case.name, c, twin.phi)?;
    let (scheme, phi_read) = scheme(case, c, ctx)?;
    let (poly, with, without) = polygon(case, c, &twin, ctx, wrap)?;
    let eta = eta_read(c.motion, with.p, without.map(|t| t.p));
    let mut out = vec![reading(
        "φ",
        (Symbol::Angle, subject("phi", &case.name)),
        phi_read,
        twin.phi,
        None,
    )];
    out.extend(readings(&case.name, &twin, &with, eta));
    let mut notes = vec![FrictionNote::InclineErratum {
        case: case.name.clone(),
        up: c.motion == Motion::Up,
    }];
    if twin.self_braking {
        notes.push(FrictionNote::SelfBraking {
            case: case.name.clone(),
            alpha: c.alpha,
            phi: twin.phi,
        });
    }
    Ok(Solved {
        case: case.clone(),
        drawings: vec![scheme, poly],
        readings: out,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::{case, ctx, incline};
    use super::super::{solve, CaseKind, DrawingKind, Motion};
    use crate::geom::DVec2;

    /// Issue 45: on the inclined plane's scheme P stands on the body's side of the plane, drawn
    /// from the body or onto it: a horizontal P on the way down (case 2), or P at 10° over the
    /// horizontal on the way up (case 1), drawn from the body ran into the plane's hatching.
    #[test]
    fn the_inclines_force_stays_off_the_plane() {
        for (beta, motion) in [
            (0.0, Motion::Down),
            (-10.0, Motion::Up),
            (10.0, Motion::Up),
            (30.0, Motion::Up),
            (10.0, Motion::Down),
        ] {
            let c = incline(20.0, beta, 0.15, motion);
            let n = DVec2::from_angle(c.alpha).perp();
            let s = solve(&case("incline", CaseKind::Incline(c)), &ctx(0.0))
                .unwrap_or_else(|e| panic!("{e}"));
            let scheme = (s.drawings.iter())
                .find(|d| d.kind == DrawingKind::Scheme)
                .expect("the scheme");
            let p = (scheme.figure.steps.iter())
                .find_map(|st| match st.item {
                    crate::construct::Item::Vector { from, to } if st.note == "the force" => {
                        Some((from, to))
                    }
                    _ => None,
                })
                .expect("P");
            for end in [p.0, p.1] {
                assert!(
                    end.dot(n) > 0.0,
                    "β′ = {beta}°, {motion:?}: P's end {end} on the plane's far side"
                );
            }
        }
    }
}
