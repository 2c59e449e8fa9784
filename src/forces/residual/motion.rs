//! The equilibrium check's own velocities and accelerations: every moving body's motion as
//! the screw of a rigid body — the velocity V and acceleration A of its point at the origin,
//! its ω and ε — solved from the constraints of the check's own [`Picture`], linear at each
//! order once the positions are known:
//!
//! - a point held by bodies b and c: v_b(P) = v_c(P) and a_b(P) = a_c(P);
//! - body b sliding on c along a line of normal n (turning with c): ω_b = ω_c, ε_b = ε_c,
//!   n·(v_b − v_c) = 0 and n·(a_b − a_c) + 2·ω_c·n⊥·(v_b − v_c) = 0 (Coriolis);
//! - the crank turns at the scene's ω₁, with ε₁ = 0.
//!
//! It shares nothing with the plans or the analytic twin but the positions and the linear
//! solver: a guide turning with the wrong body, a Coriolis term dropped, a rate of the wrong
//! link all show as a difference.

use super::picture::Picture;
use crate::geom::{solve_linear, DVec2};

/// The motion of every moving body of a [`Picture`]: by body, V, ω, A, ε.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Screws {
    bodies: Vec<u32>,
    v: Vec<(DVec2, f64)>,
    a: Vec<(DVec2, f64)>,
}

impl Screws {
    /// The velocity of the point of body `b` at `x` (the frame's is zero).
    pub fn v(&self, b: u32, x: DVec2) -> DVec2 {
        self.slot(b)
            .map_or(DVec2::ZERO, |k| self.v[k].0 + x.perp() * self.v[k].1)
    }
    /// The acceleration of the point of body `b` at `x`.
    pub fn a(&self, b: u32, x: DVec2) -> DVec2 {
        self.slot(b).map_or(DVec2::ZERO, |k| {
            let w = self.v[k].1;
            self.a[k].0 + x.perp() * self.a[k].1 - x * (w * w)
        })
    }
    /// ω of body `b`.
    pub fn omega(&self, b: u32) -> f64 {
        self.slot(b).map_or(0.0, |k| self.v[k].1)
    }
    /// ε of body `b`.
    pub fn eps(&self, b: u32) -> f64 {
        self.slot(b).map_or(0.0, |k| self.a[k].1)
    }
    fn slot(&self, b: u32) -> Option<usize> {
        self.bodies.iter().position(|&x| x == b)
    }
}

/// One constraint row over the unknowns (V, ω of every body) with its right-hand side at
/// each order.
struct Row {
    coef: Vec<f64>,
    rhs: [f64; 2],
}

/// The motion of every body of `pic` with the points at `at` and the crank at `w1` (signed,
/// counter-clockwise positive); `None` when a point is missing or the constraints are
/// singular (a toggle).
pub(super) fn solve(pic: &Picture, at: &impl Fn(&str) -> Option<DVec2>, w1: f64) -> Option<Screws> {
    let n = 3 * pic.bodies.len();
    let col = |b: u32| pic.bodies.iter().position(|&x| x == b).map(|k| 3 * k);
    // Velocities first: the rows hold only positions.
    let mut rows = Vec::new();
    let mut crank = vec![0.0; n];
    crank[col(pic.crank.0)? + 2] = 1.0;
    rows.push(Row {
        coef: crank,
        rhs: [w1, 0.0],
    });
    for (name, first, b) in pic.pins() {
        let x = at(name)?;
        for axis in [DVec2::X, DVec2::Y] {
            let mut coef = vec![0.0; n];
            point_terms(&mut coef, col(b), axis, x, 1.0);
            point_terms(&mut coef, col(first), axis, x, -1.0);
            rows.push(Row {
                coef,
                rhs: [0.0; 2],
            });
        }
    }
    for s in &pic.slides {
        let x = at(&s.at)?;
        let normal = s.line.direction(at)?.perp();
        let mut turn = vec![0.0; n];
        add(&mut turn, col(s.slider).map(|c| c + 2), 1.0);
        add(&mut turn, col(s.on).map(|c| c + 2), -1.0);
        rows.push(Row {
            coef: turn,
            rhs: [0.0; 2],
        });
        let mut across = vec![0.0; n];
        point_terms(&mut across, col(s.slider), normal, x, 1.0);
        point_terms(&mut across, col(s.on), normal, x, -1.0);
        rows.push(Row {
            coef: across,
            rhs: [0.0; 2],
        });
    }
    if rows.len() != n {
        return None;
    }
    let v = screws(&rows, 0)?;
    let vel = Screws {
        bodies: pic.bodies.clone(),
        v: v.clone(),
        a: Vec::new(),
    };
    // Accelerations: the same rows, their right-hand sides from the velocities.
    let mut k = 1;
    for (name, first, b) in pic.pins() {
        let (wb, wf) = (vel.omega(b), vel.omega(first));
        let centripetal = at(name)? * (wb * wb - wf * wf);
        for axis in [DVec2::X, DVec2::Y] {
            rows[k].rhs[1] = centripetal.dot(axis);
            k += 1;
        }
    }
    for s in &pic.slides {
        let x = at(&s.at)?;
        let normal = s.line.direction(at)?.perp();
        let (ws, wo) = (vel.omega(s.slider), vel.omega(s.on));
        let relative = vel.v(s.slider, x) - vel.v(s.on, x);
        rows[k + 1].rhs[1] =
            normal.dot(x * (ws * ws - wo * wo)) - 2.0 * wo * normal.perp().dot(relative);
        k += 2;
    }
    let a = screws(&rows, 1)?;
    Some(Screws {
        bodies: pic.bodies.clone(),
        v,
        a,
    })
}

/// The terms of n·(V_b + ω_b·x⊥) in a row, times `sign` (nothing for the frame).
fn point_terms(coef: &mut [f64], col: Option<usize>, n: DVec2, x: DVec2, sign: f64) {
    if let Some(c) = col {
        coef[c] += sign * n.x;
        coef[c + 1] += sign * n.y;
        coef[c + 2] += sign * n.dot(x.perp());
    }
}

fn add(coef: &mut [f64], col: Option<usize>, v: f64) {
    if let Some(c) = col {
        coef[c] += v;
    }
}

/// Solve the rows at order `order` (0 velocities, 1 accelerations): (V, ω) of every body.
fn screws(rows: &[Row], order: usize) -> Option<Vec<(DVec2, f64)>> {
    let system: Vec<Vec<f64>> = rows
        .iter()
        .map(|r| {
            let mut v = r.coef.clone();
            v.push(r.rhs[order]);
            v
        })
        .collect();
    let x = solve_linear(system)?;
    Some(
        x.chunks_exact(3)
            .map(|c| (DVec2::new(c[0], c[1]), c[2]))
            .collect(),
    )
}
