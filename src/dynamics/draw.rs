//! The diagrams of the dynamic study as constructions through the recorder.
//!
//! 1. M_с(φ) = −M_пр (the reduced moment of the resistances, positive when it resists, the
//!    seed's Table 9) at μ_M over μ_φ, integrated graphically by chords with the pole
//!    distance H: A_с(φ) at μ_A = μ_M·μ_φ·H;
//! 2. A_д: the straight line from the origin to A_с(2π) (constant driving moment); the ray
//!    from the pole parallel to it cuts the M axis at M_д (graphical differentiation of a
//!    straight line), drawn across the M diagram;
//! 3. ΔT = A_д − A_с: the ordinates between the line and the curve, measured, laid off at μ_T;
//! 4. J_пр(φ) at μ_J;
//! 5. the energy–mass diagram ΔT(J_пр) (Wittenbauer) with the tangents at
//!    tan ψ_max,min = μ_J·ω_ср²(1 ± δ)/(2μ_T); they cut the ΔT axis at k and l, and
//!    J_м = μ_T·kl/(δ·ω_ср²); the curve through the points is drawn on its side of both
//!    tangents (they touch it, never cut it);
//! 6. Mertsalov's route (the seed's): T_I = ΔT − ω_ср²·J_пр/2, its range ΔT_I measured,
//!    J_I = ΔT_I/(δ·ω_ср²), J_м = J_I − J_const.

use super::reduce::ReducedPosition;
use super::scales::{given_draws, scale_of, HEIGHT_MM};
use super::spec::DynamicsSpec;
use super::twin::{Cycle, Solution};
use super::work::{read_up, work, WorkScales};
use super::DynamicsError;
use crate::calculus::{draw_axes, thin};
use crate::construct::{Context, Figure, Item, Recorder, Role, StepId};
use crate::geom::{hermite, DVec2};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// A textbook route to the flywheel, as read off its diagram.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RouteReading {
    /// The flywheel's moment of inertia, kg·m²: 0 when the route finds none needed.
    pub j_fw: f64,
    /// The moment of inertia as read off the diagram, kg·m² (≤ 0: the constant inertia
    /// alone gives δ, no flywheel is needed).
    pub read: f64,
    /// The energy range measured (kl, or ΔT_I), J.
    pub range: f64,
    /// The nodes where the range is taken (the tangents' points; T_I max and min).
    pub at: [usize; 2],
}

/// The diagrams as constructed and what was read off them.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsDiagrams {
    /// μ_φ, μ_M, μ_A, μ_T, μ_J.
    pub scale_phi: Scale,
    /// μ_M.
    pub scale_m: Scale,
    /// μ_A = μ_M·μ_φ·H.
    pub scale_a: Scale,
    /// μ_T.
    pub scale_t: Scale,
    /// μ_J.
    pub scale_j: Scale,
    /// μ_T of Mertsalov's T_I.
    pub scale_t1: Scale,
    /// μ_T of the energy–mass diagram.
    pub scale_tw: Scale,
    /// The pole distance H, mm.
    pub pole_h: f64,
    /// M_с, A_с and A_д (at μ_A).
    pub work: Figure,
    /// ΔT (at μ_T).
    pub energy: Figure,
    /// J_пр (at μ_J).
    pub inertia: Figure,
    /// The energy–mass diagram (at μ_T).
    pub wittenbauer_figure: Figure,
    /// Mertsalov's T_I (at μ_T).
    pub mertsalov_figure: Figure,
    /// A_с at the nodes 0 … N as read, J (an engine's A_д: the varying side's work).
    pub a_c: Vec<f64>,
    /// M_д read through the pole, N·m (an engine's M_с: the constant side's moment).
    pub m_drive: f64,
    /// ΔT at the nodes 0 … N as read, J.
    pub delta_t: Vec<f64>,
    /// J_пр at the nodes 0 … N−1 (from the velocity plans), kg·m².
    pub j: Vec<f64>,
    /// Wittenbauer's flywheel.
    pub wittenbauer: RouteReading,
    /// Mertsalov's flywheel.
    pub mertsalov: RouteReading,
}

/// A curve through points with its axes around them (the abscissa `extent` mm long).
fn plot(
    rec: &mut Recorder,
    pts: Vec<DVec2>,
    extent: f64,
    names: (&str, &str),
    closed: bool,
) -> StepId {
    let lo = pts.iter().fold(0.0f64, |m, p| m.min(p.y));
    let hi = pts.iter().fold(0.0f64, |m, p| m.max(p.y));
    draw_axes(
        rec,
        DVec2::ZERO,
        (-4.0, extent + 12.0),
        (lo - 6.0, hi + 12.0),
        names,
    );
    rec.draw(
        format!("curve {}", names.1),
        Item::Curve {
            points: pts,
            closed,
        },
        Role::Result,
        &[],
    )
}

/// Construct the diagrams from the reduction at the N equally spaced positions.
///
/// # Errors
/// A scale that cannot be chosen, a diagram that cannot be constructed.
pub fn diagrams(
    spec: &DynamicsSpec,
    red: &[ReducedPosition],
    w_avg: f64,
    ctx: &Context,
) -> Result<DynamicsDiagrams, DynamicsError> {
    let n = red.len();
    let sc = WorkScales::of(spec, red)?;
    let run = sc.phi.to_mm(sc.dx);
    let turn = run * n as f64;
    // 1–3: M_с, A_с by chords, A_д and M_д through the pole, ΔT.
    let done = work(spec, &sc, ctx)?;
    let delta_t = &done.delta_t;
    // The energy scale: ΔT and Mertsalov's T_I.
    let j: Vec<f64> = red.iter().map(|r| r.j).collect();
    let w2 = w_avg * w_avg;
    let t1: Vec<f64> = (0..=n).map(|i| delta_t[i] - w2 * j[i % n] / 2.0).collect();
    let big = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    given_draws(
        spec.scale_t,
        crate::scale::Key::DynamicsScaleT,
        big(delta_t),
    )?;
    let mu_t = scale_of(spec.scale_t, big(delta_t), HEIGHT_MM, Quantity::Work, "μ_T")?;
    // T_I lies far from zero (it carries −ω²J_пр/2): its own scale.
    let mu_t1 = scale_of(None, big(&t1), 80.0, Quantity::Work, "μ_T of T_I")?;
    let big_j = j.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    given_draws(spec.scale_j, crate::scale::Key::DynamicsScaleJ, big_j)?;
    let mu_j = scale_of(spec.scale_j, big_j, 80.0, Quantity::Inertia, "μ_J")?;
    // 3: the ΔT diagram; 4: J_пр(φ).
    let energy = plotted(
        ["ΔT", "ΔT"],
        mu_t,
        (0..=n).map(|i| delta_t[i]),
        (run, turn),
        ctx,
    );
    let inertia = plotted(
        ["J_пр", "J_{пр}"],
        mu_j,
        (0..=n).map(|i| j[i % n]),
        (run, turn),
        ctx,
    );
    // 5: Wittenbauer.
    // The tangents cut the ΔT axis (J = 0) below the curve by about ω_ср²·J_пр/2: the
    // energy–mass diagram's μ_T takes them in (unless the scene gives μ_T).
    let reach = (0..n)
        .map(|i| (delta_t[i] - w2 * (1.0 + spec.delta) * j[i] / 2.0).abs())
        .fold(big(delta_t), f64::max);
    let mu_tw = scale_of(spec.scale_t, reach, 180.0, Quantity::Work, "μ_T")?;
    let (wittenbauer_figure, wittenbauer) =
        wittenbauer(&delta_t[..n], &j, (mu_tw, mu_j), w_avg, spec.delta, ctx);
    // 6: Mertsalov.
    let (mertsalov_figure, mertsalov) = mertsalov(&t1, run, mu_t1, w_avg, spec, ctx);
    Ok(DynamicsDiagrams {
        scale_phi: sc.phi,
        scale_m: sc.m,
        scale_a: sc.a,
        scale_t: mu_t,
        scale_j: mu_j,
        scale_t1: mu_t1,
        scale_tw: mu_tw,
        pole_h: sc.pole_h,
        work: done.figure,
        energy,
        inertia,
        wittenbauer_figure,
        mertsalov_figure,
        a_c: done.a_c,
        m_drive: done.m_drive,
        delta_t: done.delta_t,
        j,
        wittenbauer,
        mertsalov,
    })
}

/// The diagram `[title, ordinate]` of `values` at the nodes 0 … N at `mu` over φ (`run` mm
/// apart, `turn` the whole turn).
fn plotted(
    [title, name]: [&str; 2],
    mu: Scale,
    values: impl Iterator<Item = f64>,
    (run, turn): (f64, f64),
    ctx: &Context,
) -> Figure {
    let mut rec = Recorder::in_context(title, mu, ctx);
    let pts = values
        .enumerate()
        .map(|(i, v)| DVec2::new(run * i as f64, mu.to_mm(v)))
        .collect();
    plot(&mut rec, pts, turn, ("φ", name), false);
    rec.finish()
}

/// How far a tangent of the energy–mass diagram runs on past the point it touches, mm.
const TANGENT_PAST_MM: f64 = 12.0;
/// How far from the J axis a tangent ends at least, mm: its name clear of the axis.
const AXIS_CLEAR_MM: f64 = 5.0;

/// The energy–mass diagram of the points (J_i, ΔT_i) with its two tangents.
fn wittenbauer(
    dt: &[f64],
    j: &[f64],
    (mu_t, mu_j): (Scale, Scale),
    w_avg: f64,
    delta: f64,
    ctx: &Context,
) -> (Figure, RouteReading) {
    let mut rec = Recorder::in_context("ΔT(J_пр)", mu_t, ctx);
    let pts: Vec<DVec2> = dt
        .iter()
        .zip(j)
        .map(|(t, j)| DVec2::new(mu_j.to_mm(*j), mu_t.to_mm(*t)))
        .collect();
    let w2 = w_avg * w_avg;
    let slope = |s: f64| mu_j.value() * w2 * (1.0 + s * delta) / (2.0 * mu_t.value());
    let touch = |k: f64, upper: bool| {
        let s = slope(k);
        let key = |p: &DVec2| p.y - s * p.x;
        let mut best = 0;
        for (i, p) in pts.iter().enumerate() {
            let better = if upper {
                key(p) > key(&pts[best])
            } else {
                key(p) < key(&pts[best])
            };
            if better {
                best = i;
            }
        }
        (best, s, key(&pts[best]))
    };
    let (i1, s1, c1) = touch(1.0, true);
    let (i2, s2, c2) = touch(-1.0, false);
    // Each tangent runs on past the point it touches, and on across the J axis when it
    // would end beside it (its name would stand on the axis); the J axis runs on past both,
    // that no tangent ends on its arrowhead (the shaper's ψ_min did).
    let past = [(i1, s1, c1), (i2, s2, c2)].map(|(i, s, c)| {
        let x = pts[i].x + TANGENT_PAST_MM;
        let y = c + s * x;
        let x = if y.abs() < AXIS_CLEAR_MM && s != 0.0 {
            x.max((AXIS_CLEAR_MM * s.signum() - c) / s)
        } else {
            x
        };
        DVec2::new(x, c + s * x)
    });
    let x_hi = pts.iter().chain(&past).fold(0.0f64, |m, p| m.max(p.x));
    let y_lo = pts.iter().fold(c1.min(c2), |m, p| m.min(p.y));
    let y_hi = pts.iter().fold(0.0f64, |m, p| m.max(p.y));
    draw_axes(
        &mut rec,
        DVec2::ZERO,
        (-4.0, x_hi + 14.0),
        (y_lo - 8.0, y_hi + 12.0),
        ("J_{пр}", "ΔT"),
    );
    let curve = rec.draw(
        "energy–mass curve",
        Item::Polyline {
            points: within_tangents(&pts, [(s1, c1, i1), (s2, c2, i2)]),
            closed: true,
        },
        Role::Result,
        &[],
    );
    let mut ends = [DVec2::ZERO; 2];
    for (n, (c, past, name, toward)) in [
        (c1, past[0], "k", DVec2::new(-1.0, 0.3)),
        (c2, past[1], "l", DVec2::new(-1.0, -0.3)),
    ]
    .into_iter()
    .enumerate()
    {
        let on_axis = DVec2::new(0.0, c);
        let t = thin(
            &mut rec,
            format!("tangent ψ_{name}"),
            on_axis,
            past,
            &[curve],
        );
        let psi = if n == 0 { "ψ_{max}" } else { "ψ_{min}" };
        rec.label(t, psi, past, DVec2::new(1.0, 0.0));
        rec.point(
            format!("point {name}"),
            on_axis,
            Role::Construction,
            name,
            toward,
            &[t],
        );
        ends[n] = on_axis;
    }
    let dim = rec.draw(
        "kl",
        Item::Dimension {
            from: ends[1],
            to: ends[0],
            offset: 8.0,
        },
        Role::Dimension,
        &[],
    );
    let kl = read_up(&mut rec, ends[1], ends[0]) * mu_t.value();
    rec.label(dim, "kl", (ends[0] + ends[1]) * 0.5, DVec2::new(-1.0, 0.0));
    let read = kl / (delta * w2);
    let route = RouteReading {
        j_fw: read.max(0.0),
        read,
        range: kl,
        at: [i1, i2],
    };
    (rec.finish(), route)
}

/// Pieces of each span of the drawn energy–mass curve.
const SPAN_PIECES: usize = 16;
/// Rounds of leaning the curve's tangents towards the tangent lines, and the part of a
/// tangent's lean across a line kept in each.
const LEAN_ROUNDS: usize = 400;
const LEAN_KEPT: f64 = 0.95;
/// How far the drawn curve may pass a tangent line, mm (the rounding of the arithmetic).
const TOUCH_MM: f64 = 1e-9;

/// The closed energy–mass curve through `pts` drawn as the draftsman draws it against the
/// tangents `lines` (slope s, intercept c of y = s·x + c, the point it touches; the first
/// above the curve, the second below): smooth — each span the cubic whose end tangents run
/// along the chord of the neighbouring points, as a smooth curve through points is drawn —
/// but on its side of both lines. At the point a tangent touches, the curve runs along it;
/// where a span would bulge past a line, the tangents at its ends are leaned towards the
/// line (their part across it shortened, their part along it kept) until it does not. The
/// tangents touch the curve drawn and never cut it.
fn within_tangents(pts: &[DVec2], lines: [(f64, f64, usize); 2]) -> Vec<DVec2> {
    let n = pts.len();
    if n < 3 {
        return pts.to_vec();
    }
    let at = |i: usize| pts[i % n];
    // How far p lies past line k (> 0: on the wrong side), mm of ordinate.
    let past = |k: usize, p: DVec2| {
        let (s, c, _) = lines[k];
        let side = if k == 0 { 1.0 } else { -1.0 };
        side * (p.y - s * p.x - c)
    };
    // A tangent with its part across line k kept at `keep`.
    let lean = |t: DVec2, k: usize, keep: f64| {
        let d = DVec2::new(1.0, lines[k].0).normalize_or_zero();
        let along = d * t.dot(d);
        along + (t - along) * keep
    };
    let span = |t: &[DVec2], i: usize| hermite(at(i), t[i], at(i + 1), t[(i + 1) % n], SPAN_PIECES);
    let mut t: Vec<DVec2> = (0..n).map(|i| (at(i + 1) - at(i + n - 1)) * 0.5).collect();
    for (k, &(_, _, i)) in lines.iter().enumerate() {
        if let Some(ti) = t.get_mut(i) {
            *ti = lean(*ti, k, 0.0);
        }
    }
    for round in 0..=LEAN_ROUNDS {
        let mut leaned = false;
        for i in 0..n {
            let pts = span(&t, i);
            for k in 0..2 {
                if pts.iter().any(|&p| past(k, p) > TOUCH_MM) {
                    for j in [i, (i + 1) % n] {
                        // The last round: the span within the hull of its ends.
                        t[j] = if round == LEAN_ROUNDS {
                            DVec2::ZERO
                        } else {
                            lean(t[j], k, LEAN_KEPT)
                        };
                    }
                    leaned = true;
                }
            }
        }
        if !leaned {
            break;
        }
    }
    (0..n)
        .flat_map(|i| span(&t, i).into_iter().take(SPAN_PIECES))
        .collect()
}

/// Points read along each piece of a drawn curve for its extremes.
const CURVE_SAMPLES: usize = 64;

/// Mertsalov's T_I = ΔT − ω_ср²·J_пр/2 over the cycle, its range between two horizontals.
fn mertsalov(
    t1: &[f64],
    run: f64,
    mu_t: Scale,
    w_avg: f64,
    spec: &DynamicsSpec,
    ctx: &Context,
) -> (Figure, RouteReading) {
    let mut rec = Recorder::in_context("T_I", mu_t, ctx);
    let n = t1.len().saturating_sub(1);
    let pts: Vec<DVec2> = t1
        .iter()
        .enumerate()
        .map(|(i, t)| DVec2::new(run * i as f64, mu_t.to_mm(*t)))
        .collect();
    let curve = plot(&mut rec, pts.clone(), run * n as f64, ("φ", "T_{I}"), false);
    // The horizontals touch the curve as drawn: past a turning point of the points it goes
    // on to the extreme a French curve finds between them.
    let drawn = crate::geom::curve::points(&pts, false, CURVE_SAMPLES);
    let by_y = |a: &DVec2, b: &DVec2| a.y.total_cmp(&b.y);
    let top = drawn.iter().copied().max_by(by_y).unwrap_or_default();
    let bottom = drawn.iter().copied().min_by(by_y).unwrap_or_default();
    let nearest = |p: DVec2| ((p.x / run).round().max(0.0) as usize).min(n);
    let (hi, lo) = (nearest(top), nearest(bottom));
    let right = run * n as f64 + 6.0;
    // ΔT_I dimensioned right of the curve, past the φ axis's arrow (and its name under it);
    // each horizontal runs on as the dimension's extension line (2 mm past the dimension
    // line, ГОСТ 2.307), its name written at its end.
    let dim_at = 12.0;
    for (p, name) in [(top, "T_{I max}"), (bottom, "T_{I min}")] {
        let end = DVec2::new(right + dim_at + 2.0, p.y);
        let id = thin(
            &mut rec,
            format!("horizontal through {name}"),
            p,
            end,
            &[curve],
        );
        rec.label(id, name, end, DVec2::new(1.0, 0.0));
    }
    let (a, b) = (DVec2::new(right, bottom.y), DVec2::new(right, top.y));
    let dim = rec.draw(
        "ΔT_I",
        Item::Dimension {
            from: a,
            to: b,
            offset: -dim_at,
        },
        Role::Dimension,
        &[],
    );
    rec.label(dim, "ΔT_{I}", (a + b) * 0.5, DVec2::new(1.0, 0.0));
    let range = read_up(&mut rec, a, b) * mu_t.value();
    let j_i = range / (spec.delta * w_avg * w_avg);
    let read = j_i - spec.constant_inertia();
    let route = RouteReading {
        j_fw: read.max(0.0),
        read,
        range,
        at: [hi, lo],
    };
    (rec.finish(), route)
}

/// ω(φ) of the crank with the flywheel (the analytic twin), about ω_ср, with ω_max and ω_min.
///
/// # Errors
/// No scale can be chosen.
pub fn omega_figure(
    cycle: &Cycle,
    sol: &Solution,
    mu_phi: Scale,
    ctx: &Context,
) -> Result<Figure, DynamicsError> {
    let avg = sol.omega_avg();
    let swing = (sol.w_max.0 - avg)
        .abs()
        .max((avg - sol.w_min.0).abs())
        .max(1e-9 * avg.abs())
        .max(1e-12);
    let mu_w = scale_of(None, swing, 30.0, Quantity::AngularVelocity, "μ_ω")?;
    let mut rec = Recorder::in_context("ω(φ)", mu_w, ctx);
    let turn = mu_phi.to_mm(TAU);
    let pts: Vec<DVec2> = (0..=360)
        .map(|k| {
            let psi = TAU * k as f64 / 360.0;
            DVec2::new(
                mu_phi.to_mm(psi),
                mu_w.to_mm(cycle.omega(psi, sol.j_fw, sol.t0) - avg),
            )
        })
        .collect();
    plot(&mut rec, pts, turn, ("φ", "ω − ω_{ср}"), false);
    for (w, name) in [(sol.w_max.0, "ω_{max}"), (sol.w_min.0, "ω_{min}")] {
        let y = mu_w.to_mm(w - avg);
        let id = thin(
            &mut rec,
            format!("level {name}"),
            DVec2::new(0.0, y),
            DVec2::new(turn, y),
            &[],
        );
        rec.label(id, name, DVec2::new(turn, y), DVec2::new(1.0, 0.0));
    }
    Ok(rec.finish())
}
