//! Steps 1–3 of the dynamic study's diagrams ([`super::draw`]): M_с(φ) at μ_M over μ_φ,
//! integrated by chords into A_с at μ_A = μ_M·μ_φ·H; A_д the straight line to A_с(2π), the ray
//! from the pole parallel to it reading M_д; ΔT = A_д − A_с measured between them.

use super::reduce::ReducedPosition;
use super::scales::{given_draws, scale_of, HEIGHT_MM, TURN_MM};
use super::spec::{ConstantMoment, DynamicsSpec};
use super::DynamicsError;
use crate::calculus::{integrate_chords, thin, Diagram, DiagramLayout, Sampling, Scales};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// The work diagram's scales and what they are chosen from.
pub(super) struct WorkScales {
    /// The varying side's moment at the nodes 0 … N−1: M_с = −M_пр against a constant
    /// driving moment, M_д = M_пр against a constant resisting one (an engine), N·m.
    pub mc: Vec<f64>,
    /// The step of φ between the nodes, rad.
    pub dx: f64,
    /// μ_φ.
    pub phi: Scale,
    /// μ_M.
    pub m: Scale,
    /// The pole distance H, mm.
    pub pole_h: f64,
    /// μ_A = μ_M·μ_φ·H.
    pub a: Scale,
    /// The work's estimate the scale μ_A was chosen by (when the scene gives no H), J.
    pub a_est: f64,
}

impl WorkScales {
    /// The scales of the reduction `red` at its N equally spaced positions.
    pub fn of(spec: &DynamicsSpec, red: &[ReducedPosition]) -> Result<Self, DynamicsError> {
        let n = red.len();
        let dx = TAU / n.max(1) as f64;
        let sgn = spec.constant_moment.sign();
        let mc: Vec<f64> = red.iter().map(|r| -sgn * r.m()).collect();
        let big_m = mc.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mu_phi = scale_of(spec.scale_phi, TAU, TURN_MM, Quantity::Angle, "μ_φ")?;
        given_draws(spec.scale_m, crate::scale::Key::DynamicsScaleM, big_m)?;
        let mu_m = scale_of(spec.scale_m, big_m, HEIGHT_MM, Quantity::Moment, "μ_M")?;
        let a_est: f64 = mc.iter().map(|v| v * dx).sum::<f64>().abs().max(big_m * dx);
        let (pole_h, mu_a) = match spec.pole_h {
            Some(h) => (h, mu_m.value() * mu_phi.value() * h),
            None => {
                let a = scale_of(None, a_est, 60.0, Quantity::Work, "μ_A")?;
                (a.value() / (mu_m.value() * mu_phi.value()), a.value())
            }
        };
        let mu_a = Scale::new(mu_a, Quantity::Work).ok_or(DynamicsError::NoScale {
            what: "μ_A",
            value: mu_a,
        })?;
        Ok(Self {
            mc,
            dx,
            phi: mu_phi,
            m: mu_m,
            pole_h,
            a: mu_a,
            a_est,
        })
    }
}

/// The work diagram and what was read off it.
pub(super) struct Work {
    /// M_с, A_с and A_д (at μ_A).
    pub figure: Figure,
    /// A_с at the nodes 0 … N as read, J.
    pub a_c: Vec<f64>,
    /// M_д read through the pole, N·m.
    pub m_drive: f64,
    /// ΔT at the nodes 0 … N as read, J.
    pub delta_t: Vec<f64>,
}

fn diagram_err(what: &'static str) -> impl Fn(crate::calculus::CalculusError) -> DynamicsError {
    move |error| DynamicsError::Diagram { what, error }
}

/// Steps 1–3 at the scales `sc`: M_с, A_с by chords, A_д and M_д through the pole, the
/// ordinates of ΔT.
pub(super) fn work(
    spec: &DynamicsSpec,
    sc: &WorkScales,
    ctx: &Context,
) -> Result<Work, DynamicsError> {
    let (mc, dx, mu_m, mu_a, pole_h) = (&sc.mc, sc.dx, sc.m, sc.a, sc.pole_h);
    let n = mc.len();
    let sgn = spec.constant_moment.sign();
    // The varying side: M_с = −M_пр against a constant driving moment, M_д = M_пр against a
    // constant resisting moment (an engine); the constant one is the straight line.
    let (vary, fixed) = match spec.constant_moment {
        ConstantMoment::Driving => (["M_{с}", "A_{с}"], ["A_{д}", "M_{д}"]),
        ConstantMoment::Resisting => (["M_{д}", "A_{д}"], ["A_{с}", "M_{с}"]),
    };
    let run = sc.phi.to_mm(dx);
    let turn = run * n as f64;
    let mut rec = Recorder::in_context("M_с, A_с, A_д", mu_a, ctx);
    let src = Diagram::new(0.0, dx, mc.clone(), true).map_err(diagram_err("M_с"))?;
    let m_lo = mc.iter().fold(0.0f64, |m, &v| m.min(mu_m.to_mm(v)));
    // The A diagram's top: the work's running sum (by trapezoids) at its farthest from the
    // axis, above its value at 2π where the work rises and falls back (the V engine's A_д).
    let reach = (0..n)
        .scan(0.0, |a: &mut f64, k| {
            *a += 0.5 * (mc[k] + mc[(k + 1) % n]) * dx;
            Some(a.abs())
        })
        .fold(sc.a_est, f64::max);
    let a_hi = reach / mu_a.value();
    let so = DVec2::new(0.0, a_hi + 30.0 - m_lo);
    let layout = DiagramLayout::new(so, DVec2::ZERO)
        .named("φ", vary[0], "A")
        .pole_named("P", "H");
    let scales = Scales { x: sc.phi, y: mu_m };
    let integral = integrate_chords(
        &mut rec,
        &src,
        Sampling::Nodes,
        scales,
        pole_h,
        0.0,
        &layout,
    )
    .map_err(diagram_err("A_с"))?;
    let a_c = integral.node.clone();
    let a_n = a_c.last().copied().unwrap_or(0.0);
    let end = DVec2::new(turn, mu_a.to_mm(a_n));
    let ad = rec.draw(
        "A_д: the straight line to A_с(2π)",
        Item::Segment(Segment::new(DVec2::ZERO, end)),
        Role::Result,
        &[integral.curve],
    );
    rec.label(ad, fixed[0], end, DVec2::new(0.6, 0.8));
    let q = integral.pole + end * (pole_h / turn);
    let ray = thin(&mut rec, "ray from P ∥ A_д".into(), integral.pole, q, &[ad]);
    let m_drive = read_up(&mut rec, so, q) * mu_m.value();
    let md = rec.draw(
        "M_д across the M diagram",
        Item::Segment(Segment::new(q, DVec2::new(so.x + turn, q.y))),
        Role::Result,
        &[ray],
    );
    rec.label(
        md,
        fixed[1],
        DVec2::new(so.x + turn, q.y),
        DVec2::new(1.0, 0.3),
    );
    // 3: ΔT = A_д − A_с, the ordinates between the line and the curve.
    let mut delta_t = Vec::with_capacity(n + 1);
    for (i, a) in a_c.iter().enumerate() {
        let x = run * i as f64;
        let pd = DVec2::new(x, end.y * i as f64 / n as f64);
        let pc = DVec2::new(x, mu_a.to_mm(*a));
        if pd.distance(pc) > 0.2 {
            thin(&mut rec, format!("ΔT ordinate {i}"), pc, pd, &[ad]);
        }
        delta_t.push(sgn * read_up(&mut rec, pc, pd) * mu_a.value());
    }
    // The curve named where it stands farthest from the line, on its side away from it (the
    // two meet at 2π, where the line's name stands).
    let apart = |i: usize| mu_a.to_mm(a_c[i]) - end.y * i as f64 / n as f64;
    if let Some(i) = (0..a_c.len()).max_by(|&i, &j| apart(i).abs().total_cmp(&apart(j).abs())) {
        let at = DVec2::new(run * i as f64, mu_a.to_mm(a_c[i]));
        rec.label(
            integral.curve,
            vary[1],
            at,
            DVec2::new(0.0, apart(i).signum()),
        );
    }
    Ok(Work {
        figure: rec.finish(),
        a_c,
        m_drive,
        delta_t,
    })
}

/// Signed ordinate read from `a` up to `b` (same abscissa), in the recorder's mm as read.
pub(super) fn read_up(rec: &mut Recorder, a: DVec2, b: DVec2) -> f64 {
    let m = rec.measure(a, b);
    if b.y < a.y {
        -m.read_mm
    } else {
        m.read_mm
    }
}
