//! Issue 45: the angle graph γ(φ) (λ(φ) for a translating follower) steps between
//! neighbouring readings no more than the law does, on every scene whose cam has the graph,
//! read exactly and at 0,5 mm.
//!
//! The graph's vertices, in order: each phase's readings off the profile drawing, then the
//! dwell after it (the level the curve is drawn at), the near dwell running on to φ = 0. For
//! every two neighbours a, b: |Δγ_read − Δγ_exact| ≤ ε_a + ε_b, each ε the bound of the error
//! its reading can have, derived from the exact pitch curve c(φ) (cam frame) and the
//! resolution the S diagram is read to:
//! - e_S = max |S_read − S| over the points: how far the S the drawing stands on is off the
//!   law (r·μ_S/2 of rounding at r mm, with the chord integration's own error; 0,25 mm on the
//!   seed's cam at 0,5 mm, 0,35 mm on cam-undercut's 12 sine intervals read exactly): every
//!   pitch point stands at most e_S off the exact curve (along the path, so across the curve
//!   at most e_S); a rocker's path turns with S, e_S/L more (L the arm);
//! - a reading through neighbours h in φ apart (h the phase's largest step, h₋ its least):
//!   the centred chord (equal steps, no break of the law) errs in direction by at most
//!   h²/6·max|c‴|/|c′| (truncation) + e_S/(h₋·|c′|) (two ends, each e_S, over 2h·|c′|); a
//!   one-sided or two-sided parabola (unequal steps, a break, a rigid-shock end) by at most
//!   h²/3·max|c‴|/|c′| + 4·e_S/(h₋·|c′|) (coefficients 3, 4, 1 over 2h);
//! - the end of a phase where the law's dS/dφ is continuous (0 there), and a dwell: the
//!   normal is the radius O₁B, e_S/|c| off at most.
//!
//! max|c‴| is taken over the phase's smooth pieces (third differences of the exact pitch
//! curve inside each, clear of the law's knots). Where the law is smooth the exact step at
//! a phase's end is 0, so the drawn curve may step there by e_S·(2/|c| + 2/L) at most
//! (0,3° on the seed's cam at 0,5 mm) — the 1,4–2,7° steps the review saw at 0,5 mm came from
//! reading the end through the exact h while the curve stood at the drawn S.

use glam::DVec2;
use std::f64::consts::FRAC_PI_2;
use tmm::cam::follower::{jay, to_cam};
use tmm::cam::motion::motion;
use tmm::cam::{Cam, Follower, Shock};
use tmm::construct::{Drafting, Figure, Item, Role};
use tmm::study::Session;

/// Every scene whose turning cam has an angle graph (a follower other than the flat face).
const GRAPHED: [&str; 5] = [
    "shaper",
    "cam-central",
    "cam-pz5",
    "cam-shock",
    "cam-undercut",
];

fn cam(name: &str, drafting: f64) -> Cam {
    let s = crate::support::scene(name);
    let session = Session::new(&s, Drafting::new(drafting).expect("a drafting"));
    let c = session.cam().unwrap_or_else(|e| panic!("{name}: {e}"));
    (*c).clone()
}

/// The angle drawn at a reading, degrees (γ for a rocker, λ else).
fn read_deg(cam: &Cam, i: usize) -> f64 {
    let a = cam.inversion.angle(i);
    if matches!(cam.spec.follower, Follower::Rocker { .. }) {
        (FRAC_PI_2 - a).to_degrees()
    } else {
        a.to_degrees()
    }
}

/// The exact pitch curve's point at φ (cam frame), on the side `after`.
fn pitch(cam: &Cam, phi: f64, after: bool) -> DVec2 {
    to_cam(cam.placement.kin(motion(&cam.spec, phi, after)).b, phi)
}

/// max|c‴| of the exact pitch curve over the smooth pieces of phase `phase` (0 or 2).
fn third(cam: &Cam, phase: usize) -> f64 {
    let st = cam.spec.starts();
    let law = if phase == 0 {
        cam.spec.rise
    } else {
        cam.spec.ret
    };
    let (a, len) = (st[phase], st[phase + 1] - st[phase]);
    let mut edges = vec![0.0];
    edges.extend(law.knots());
    edges.push(1.0);
    let d = 1e-3 * len;
    let mut m = 0.0f64;
    for w in edges.windows(2) {
        for j in 0..=200 {
            let u = w[0] + (w[1] - w[0]) * (0.02 + 0.96 * j as f64 / 200.0);
            let x = a + u * len;
            let c = |k: f64| pitch(cam, x + k * d, true);
            let c3 = (c(2.0) - c(1.0) * 3.0 + c(0.0) * 3.0 - c(-1.0)) / (d * d * d);
            m = m.max(c3.length());
        }
    }
    m
}

/// A vertex of the graph: φ, the angle drawn and exact (degrees), its error bound (degrees).
#[derive(Debug)]
struct Vertex {
    phi: f64,
    read: f64,
    exact: f64,
    eps: f64,
}

/// The graph's vertices in order (see the module's documentation), read off `graph`'s curve
/// at the dwells.
fn vertices(cam: &Cam, graph: &Figure) -> Vec<Vertex> {
    let curve = graph
        .steps
        .iter()
        .find_map(|s| match &s.item {
            Item::Polyline { points, .. } if s.role == Role::Result => Some(points.clone()),
            _ => None,
        })
        .expect("the angle curve");
    let spec = &cam.spec;
    let st = spec.starts();
    let e_s = cam
        .points
        .iter()
        .zip(&cam.diagrams.s)
        .map(|(p, s)| (s - motion(spec, p.phi, p.after).s).abs())
        .fold(0.0, f64::max);
    let turn = match spec.follower {
        Follower::Rocker { arm, .. } => e_s / arm,
        _ => 0.0,
    };
    let mut out = Vec::new();
    for phase in [0usize, 2] {
        let law = if phase == 0 { spec.rise } else { spec.ret };
        let idx: Vec<usize> = (0..cam.points.len())
            .filter(|&i| cam.points[i].phase == phase)
            .collect();
        let steps: Vec<f64> = idx
            .windows(2)
            .map(|w| cam.points[w[1]].phi - cam.points[w[0]].phi)
            .collect();
        let h = steps.iter().copied().fold(0.0, f64::max);
        let h_least = steps.iter().copied().fold(f64::INFINITY, f64::min);
        let m3 = third(cam, phase);
        let len = st[phase + 1] - st[phase];
        for (j, &i) in idx.iter().enumerate() {
            let p = &cam.points[i];
            let k = cam.placement.kin(motion(spec, p.phi, p.after));
            let speed = (k.b1 - jay(k.b)).length();
            let radius = to_cam(k.b, p.phi).length();
            let end = j == 0 || j + 1 == idx.len();
            let on_break = law
                .breaks()
                .iter()
                .any(|b| (st[phase] + b * len - p.phi).abs() < 1e-9);
            let centred = !end && !on_break && (steps[j - 1] - steps[j]).abs() < 1e-9 * h;
            let eps = if end && law.shock() != Shock::Rigid {
                e_s / radius + turn
            } else {
                let (km, kr) = if centred {
                    (1.0 / 6.0, 1.0)
                } else {
                    (1.0 / 3.0, 4.0)
                };
                (km * h * h * m3 + kr * e_s / h_least) / speed + turn
            };
            out.push(Vertex {
                phi: p.phi,
                read: read_deg(cam, i),
                exact: cam.angle_at(p.phi, p.after).to_degrees(),
                eps: eps.to_degrees(),
            });
        }
        // The dwell after the phase: the curve's last vertex at its start.
        let x = cam.diagrams.phi.to_mm(st[phase + 1]);
        let level = curve
            .iter()
            .rev()
            .find(|q| (q.x - x).abs() < 1e-6)
            .expect("the dwell's level");
        let mid = 0.5 * (st[phase + 1] + st[phase + 2]);
        out.push(Vertex {
            phi: st[phase + 1],
            read: level.y,
            exact: cam.angle_at(mid, true).to_degrees(),
            eps: (e_s / pitch(cam, mid, true).length() + turn).to_degrees(),
        });
    }
    out
}

/// Every two neighbouring vertices (the near dwell to the first reading too) within the
/// bound; the largest share of its bound a step uses.
fn steps_within_the_law(vs: &[Vertex]) -> Result<f64, String> {
    let mut worst = 0.0f64;
    for k in 0..vs.len() {
        let (a, b) = (&vs[k], &vs[(k + 1) % vs.len()]);
        let excess = ((b.read - a.read) - (b.exact - a.exact)).abs();
        let bound = a.eps + b.eps;
        if excess > bound + 1e-9 {
            return Err(format!(
                "γ(φ) steps {:.3}° from φ = {:.1}° to {:.1}° where the law steps {:.3}°: {excess:.3}° \
                 more than the readings' bound {bound:.3}°",
                b.read - a.read,
                a.phi.to_degrees(),
                b.phi.to_degrees(),
                b.exact - a.exact
            ));
        }
        worst = worst.max(excess / bound.max(1e-12));
    }
    Ok(worst)
}

#[test]
fn the_angle_graph_steps_no_more_than_the_law_allows() {
    for name in GRAPHED {
        for drafting in [0.0, 0.5] {
            let c = cam(name, drafting);
            let g = c.angle_graph.as_ref().expect("an angle graph");
            let vs = vertices(&c, g);
            match steps_within_the_law(&vs) {
                Ok(w) => {
                    eprintln!("{name} at {drafting} mm: the largest step uses {w:.2} of its bound")
                }
                Err(e) => panic!("{name} at {drafting} mm: {e}"),
            }
        }
    }
}

#[test]
fn a_step_at_a_smooth_dwell_breaks_the_rule() {
    // The seed's cam at 0,5 mm with the review's 1,6° step put back at the end of the rise.
    let c = cam("shaper", 0.5);
    let g = c.angle_graph.as_ref().expect("an angle graph");
    let mut vs = vertices(&c, g);
    assert!(steps_within_the_law(&vs).is_ok());
    let end = c
        .points
        .iter()
        .position(|p| p.last)
        .expect("the rise's end");
    vs[end].read += 1.6;
    assert!(steps_within_the_law(&vs).is_err());
}

/// A profile whose r₀ the project accepts from its own r_min (no base radius in the scene)
/// keeps the angle read off it within the limit at every point that binds (under force
/// closure the rise's), read exactly and at 0,5 mm: when the reading at the r₀ first accepted
/// breaks it, r₀ goes up a millimetre at a time, and the cam keeps that first r₀, the point
/// and the angle read there. cam-shock at 0,5 mm: the rise starts with a velocity jump, where
/// the one-sided reading and the S read to 0,5 mm put λ at 30,18° on the profile at 33 mm,
/// over λ_max = 30° (29,22° exact); at 34 mm it reads under.
#[test]
fn an_accepted_base_radius_keeps_the_angle_read_off_its_profile() {
    for name in GRAPHED {
        for drafting in [0.0, 0.5] {
            let cam = cam(name, drafting);
            let spec = &cam.spec;
            if spec.base_radius.is_some() {
                continue;
            }
            let rocker = matches!(spec.follower, Follower::Rocker { .. });
            let binds =
                |i: usize| spec.closure == tmm::cam::Closure::Geometric || cam.points[i].phase == 0;
            for i in (0..cam.points.len()).filter(|&i| binds(i)) {
                let (read, limit) = (read_deg(&cam, i), spec.angle_limit().to_degrees());
                let kept = if rocker {
                    read >= limit - 1e-7
                } else {
                    read <= limit + 1e-7
                };
                assert!(
                    kept,
                    "{name} at {drafting} mm: point {i} reads {read:.3}° against {limit}°"
                );
            }
            match (name, drafting) {
                ("cam-shock", d) if d > 0.0 => {
                    let r = cam.raised.expect("cam-shock's r₀ taken up");
                    assert!((r.base - 0.033).abs() < 1e-12, "{r:?}");
                    assert_eq!(r.at, 0);
                    assert!((r.angle.to_degrees() - 30.18).abs() < 0.005, "{r:?}");
                    assert!((cam.base - 0.034).abs() < 1e-12, "{}", cam.base);
                }
                _ => assert!(
                    cam.raised.is_none(),
                    "{name} at {drafting} mm: {:?}",
                    cam.raised
                ),
            }
        }
    }
}

/// An offset follower's pressure angle changes side where S′ passes e (cam-pz5: e = 3 mm on
/// the favourable side, the normal leaning one way at the rise's start and the other at its
/// first point): the graph of its magnitude touches nought between the two readings, as the
/// exact λ does, instead of running from 8,6° up through the readings (issue 45's review).
/// The centric cam's graph keeps off nought inside its rise.
#[test]
fn an_offset_followers_angle_graph_touches_nought_where_the_angle_changes_side() {
    let read_at = |g: &Figure, i: usize| {
        g.steps
            .iter()
            .find_map(|s| match s.item {
                Item::Point(p) if s.note == format!("read at point {i}") => Some(p),
                _ => None,
            })
            .expect("a marked reading")
    };
    let lowest_between = |g: &Figure, a: DVec2, b: DVec2| {
        g.steps
            .iter()
            .filter_map(|s| match &s.item {
                Item::Polyline { points, .. } if s.role == Role::Result => Some(points),
                _ => None,
            })
            .flatten()
            .filter(|q| q.x > a.x && q.x < b.x)
            .fold(f64::INFINITY, |m, q| m.min(q.y))
    };
    for drafting in [0.0, 0.5] {
        let c = cam("cam-pz5", drafting);
        let g = c.angle_graph.as_ref().expect("an angle graph");
        let leans = &c.inversion.leans;
        assert!(leans[0] * leans[1] < 0.0, "{:?}", &leans[..2]);
        let (a, b) = (read_at(g, 0), read_at(g, 1));
        assert!(a.y > 5.0 && b.y > 5.0, "{a} {b}");
        let low = lowest_between(g, a, b);
        assert!(
            low.abs() < 0.05,
            "at {drafting} mm: the curve keeps {low} mm over nought"
        );
        let centric = cam("cam-central", drafting);
        let g = centric.angle_graph.as_ref().expect("an angle graph");
        let (a, b) = (read_at(g, 2), read_at(g, 4));
        assert!(lowest_between(g, a, b) > 5.0);
    }
}
