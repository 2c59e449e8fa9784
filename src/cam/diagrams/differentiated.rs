//! The diagrams when the scene gives S (the textbook's other route): the S diagram drawn
//! from the law and differentiated twice by the method of chords.

use super::*;

/// The given S of one phase as drawn: the law at 48 intervals and at the nodes.
fn given_s(spec: &CamSpec, phase: usize, phi: Scale, mu: Scale) -> Vec<DVec2> {
    let st = spec.starts()[phase];
    let len = if phase == 0 {
        spec.phases.rise
    } else {
        spec.phases.ret
    };
    let n = spec.divisions.max(1) as f64;
    let mut us: Vec<f64> = (0..=48).map(|k| k as f64 / 48.0).collect();
    us.extend((0..=spec.divisions).map(|k| k as f64 / n));
    us.sort_by(f64::total_cmp);
    us.dedup();
    us.into_iter()
        .map(|u| {
            let m = motion_u(spec, phase, u, u < 1.0);
            DVec2::new(phi.to_mm(st + u * len), mu.to_mm(m.s))
        })
        .collect()
}

/// The diagrams when the scene gives S: the S diagram drawn from the law, its chords between
/// the nodes of each moving phase, differentiated twice by the method of chords (H₂: S →
/// dS/dφ, H₁: dS/dφ → d²S/dφ²), the poles as for integration (the rise's left of the
/// ordinate axis, the return's past the return); the values at the points read off the
/// smooth curves; S itself read off the given diagram.
pub(super) fn differentiated(
    spec: &CamSpec,
    points: &[Point],
    phi: Scale,
    sc: [Scale; 3],
    [h1, h2]: [f64; 2],
    ctx: &Context,
) -> Result<CamDiagrams, CamError> {
    let [s_scale, ds_scale, d2s_scale] = sc;
    let (n, st) = (spec.divisions, spec.starts());
    let mut views = Views::new(sc, ctx);
    let mut ds = vec![0.0; points.len()];
    let mut d2s = vec![0.0; points.len()];
    for (idx, (phase, len)) in [(0usize, spec.phases.rise), (2, spec.phases.ret)]
        .into_iter()
        .enumerate()
    {
        views.group(idx as u32 + 1);
        let dx = len / n as f64;
        views.s.draw(
            format!("given S of phase {phase}"),
            Item::Polyline {
                points: given_s(spec, phase, phi, s_scale),
                closed: false,
            },
            Role::Given,
            &[],
        );
        let nodes: Vec<f64> = (0..=n)
            .map(|k| motion(spec, st[phase] + k as f64 * dx, k < n).s)
            .collect();
        let src = Diagram::new(st[phase], dx, nodes, false)?;
        let lie = Lie::of(spec, phi, idx);
        // The law fixes dS/dφ's tangent at the phase's ends, horizontal, where the
        // acceleration does not jump: d²S/dφ² is taken from it there. S's tangent is not
        // taken: dS/dφ's chords are drawn again, and an exact end beside the chord method's
        // biased mid-interval values (h²/24·S‴) would make d²S/dφ² converge at first order
        // next to the ends (at 96 intervals its largest error grew from 0,05 % to 1,3 %);
        // dS/dφ ends where its smooth curve does, the method's error in view.
        let shock = if phase == 0 { spec.rise } else { spec.ret }.shock();
        let v = lie
            .pass(h2, ["φ", "S", "dS/dφ"], super::POLES[1])
            .differentiate(
                (&mut views.s, &mut views.v),
                &src,
                Scales { x: phi, y: s_scale },
                false,
            )?;
        let a = lie
            .pass(h1, ["φ", "dS/dφ", "d^2S/dφ^2"], super::POLES[0])
            .differentiate(
                (&mut views.v, &mut views.a),
                &v.diagram()?,
                Scales {
                    x: phi,
                    y: ds_scale,
                },
                shock == Shock::None,
            )?;
        let base = idx * (n + 1);
        for k in 0..=n {
            if let Some(slot) = ds.get_mut(base + k) {
                *slot = v.node.get(k).copied().unwrap_or(0.0);
            }
            if let Some(slot) = d2s.get_mut(base + k) {
                *slot = a.node.get(k).copied().unwrap_or(0.0);
            }
        }
    }
    views.dwells(spec, phi, Given::S, [s_scale.to_mm(spec.stroke), 0.0]);
    // S at the points, read off the given diagram.
    let s: Vec<f64> = points
        .iter()
        .map(|p| {
            let m = motion(spec, p.phi, p.after);
            let x = phi.to_mm(p.phi);
            let read = views
                .s
                .measure(DVec2::new(x, 0.0), DVec2::new(x, s_scale.to_mm(m.s)));
            s_scale.to_physical(read.read_mm)
        })
        .collect();
    let ends = |i: usize| ds.get(i).copied().unwrap_or(0.0);
    let [d2s_view, ds_view, s_view] = views.finish((spec, points), phi, [&d2s, &ds, &s]);
    Ok(CamDiagrams {
        d2s_view,
        ds_view,
        s_view,
        s,
        ds_ends: [ends(n), ends(2 * n + 1)],
        ds,
        d2s,
        phi,
        s_scale,
        ds_scale,
        d2s_scale,
        poles: [h1, h2],
        drawn_poles: [true; 2],
        y_max: None,
    })
}
