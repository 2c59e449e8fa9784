//! The zero sets of functions over a rectangle of the plane, traced on a square grid by
//! marching squares: every grid edge whose ends a function takes with opposite signs holds
//! one point of its zero set, bracketed along the edge to [`BRACKET_TO`] or to a value within
//! [`SETTLED`] of 0 ([`illinois`]); the points of each cell are joined so that the side where
//! the function is ≥ 0 lies on the left (a saddle cell decided by the value at its centre),
//! and the pieces linked cell to cell into polylines. Every piece of a zero set that crosses a
//! grid edge is found, whatever its shape; a closed one that fits inside one cell is not.
//!
//! A *closed* function counts as negative beyond the grid and wherever it has no value: its
//! set {f ≥ 0} is bounded by closed rings, running along the grid's edge where the set
//! reaches it. An open one gives its zero set where it has values, ending at the grid's edge.
//! Nothing here knows what the functions are.

use crate::geom::{illinois, DVec2};
use rayon::prelude::*;
use std::collections::HashMap;

/// The bracket's end along a grid edge (x per module: 10⁻¹³).
pub const BRACKET_TO: f64 = 1e-13;
/// A function's value that ends its bracket: its zero to rounding (the indices are O(1)).
pub const SETTLED: f64 = 1e-14;
/// Cell rows per task.
const BAND: usize = 8;

/// A square grid: the nodes lo + (i, j)·h, i ≤ n[0], j ≤ n[1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// The lower left node.
    pub lo: DVec2,
    /// The spacing.
    pub h: f64,
    /// The steps along each axis.
    pub n: [usize; 2],
}

impl Grid {
    /// The grid of spacing `h` from `lo` over `hi` (its last nodes at `hi`, or just beyond
    /// it when `hi − lo` is not a whole number of steps).
    pub fn over(lo: DVec2, hi: DVec2, h: f64) -> Self {
        let steps = |span: f64| ((span / h - 1e-9).ceil().max(1.0)) as usize;
        Self {
            lo,
            h,
            n: [steps(hi.x - lo.x), steps(hi.y - lo.y)],
        }
    }

    /// Node (i, j).
    pub fn node(&self, i: usize, j: usize) -> DVec2 {
        self.lo + DVec2::new(i as f64, j as f64) * self.h
    }
}

/// Functions over the plane whose zero sets are traced.
pub trait Fields: Sync {
    /// How many.
    fn count(&self) -> usize;
    /// Every function's value at every node of row `j` of `grid`: `out[i·count + k]`, NaN
    /// where it has none.
    fn row(&self, grid: &Grid, j: usize, out: &mut [f64]);
    /// Function `k`'s value at `p` (`None`: it has none there).
    fn at(&self, k: usize, p: DVec2) -> Option<f64>;
}

/// A node beyond the grid (closed functions only): outside.
const PAD: f64 = f64::NEG_INFINITY;

/// One piece of a zero set inside a cell: from the edge it enters by to the edge it leaves
/// by, the set {f ≥ 0} on its left.
#[derive(Debug, Clone, Copy)]
struct Piece {
    from: (usize, DVec2),
    to: (usize, DVec2),
}

/// Each function's zero set on `grid`: its polylines (a ring's first point repeated last),
/// {f ≥ 0} on their left. `closed[k]`: function `k` is closed (see the module's doc).
pub fn zero_sets(grid: &Grid, fields: &impl Fields, closed: &[bool]) -> Vec<Vec<Vec<DVec2>>> {
    let count = fields.count();
    // The cells with the ring of pad nodes about the grid: nodes (I, J) = (i + 1, j + 1).
    let rows = grid.n[1] + 2;
    let bands: Vec<usize> = (0..rows.div_ceil(BAND)).collect();
    let found: Vec<Vec<Vec<Piece>>> = bands
        .par_iter()
        .map(|b| band(grid, fields, closed, b * BAND, ((b + 1) * BAND).min(rows)))
        .collect();
    (0..count)
        .map(|k| {
            let pieces: Vec<Piece> = found.iter().flat_map(|f| f[k].iter().copied()).collect();
            link(&pieces)
        })
        .collect()
}

/// The extended grid's width in nodes.
fn width(grid: &Grid) -> usize {
    grid.n[0] + 3
}

/// The position of extended node (I, J) (a pad node's is never asked for).
fn position(grid: &Grid, i: usize, j: usize) -> DVec2 {
    grid.node(i.wrapping_sub(1), j.wrapping_sub(1))
}

/// The values of extended node row `j` (pads about it; a whole pad row beyond the grid).
fn node_row(grid: &Grid, fields: &impl Fields, j: usize, buf: &mut Vec<f64>) -> Vec<f64> {
    let count = fields.count();
    let w = width(grid);
    let mut out = vec![PAD; w * count];
    if j == 0 || j == grid.n[1] + 2 {
        return out;
    }
    buf.resize((grid.n[0] + 1) * count, f64::NAN);
    fields.row(grid, j - 1, buf);
    out[count..count + buf.len()].copy_from_slice(buf);
    out
}

/// The pieces of the cells of rows `j0..j1` (extended), per function.
fn band(
    grid: &Grid,
    fields: &impl Fields,
    closed: &[bool],
    j0: usize,
    j1: usize,
) -> Vec<Vec<Piece>> {
    let count = fields.count();
    let w = width(grid);
    let mut buf = Vec::new();
    let values: Vec<Vec<f64>> = (j0..=j1)
        .map(|j| node_row(grid, fields, j, &mut buf))
        .collect();
    // Each node's functions inside (≥ 0) and with a value, as bits (the 64th and beyond
    // always looked at).
    let bits = |row: &[f64], i: usize, test: fn(f64) -> bool| {
        (0..count).fold(0u64, |m, k| {
            let on = k >= 63 || test(row[i * count + k]);
            m | (u64::from(on) << k.min(63))
        })
    };
    let masks: Vec<Vec<(u64, u64)>> = values
        .iter()
        .map(|row| {
            (0..w)
                .map(|i| (bits(row, i, |v| v >= 0.0), bits(row, i, f64::is_finite)))
                .collect()
        })
        .collect();
    let shut = (0..count).fold(0u64, |m, k| {
        m | (u64::from(closed.get(k).copied().unwrap_or(false)) << k.min(63))
    });
    let mut out = vec![Vec::new(); count];
    let mut cache: HashMap<(usize, usize), Option<DVec2>> = HashMap::new();
    for j in j0..j1 {
        for i in 0..w - 1 {
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let m = corners.map(|(a, b)| masks[b - j0][a]);
            let any = m.iter().fold(0, |x, m| x | m.0);
            let all = m.iter().fold(u64::MAX, |x, m| x & m.0);
            let finite = m.iter().fold(u64::MAX, |x, m| x & m.1);
            let mut mixed = (any & !all) & (shut | finite);
            while mixed != 0 {
                let k = mixed.trailing_zeros() as usize;
                mixed &= mixed - 1;
                let ks: Vec<usize> = if k == 63 {
                    (63..count).collect()
                } else {
                    vec![k]
                };
                for k in ks {
                    let v = corners.map(|(a, b)| values[b - j0][a * count + k]);
                    let cell = Cell { i, j, corners, v };
                    let shut = closed.get(k).copied().unwrap_or(false);
                    cell.pieces(grid, fields, k, shut, &mut cache, &mut out[k]);
                }
            }
        }
    }
    out
}

/// A cell: its lower left node (extended), its corners counter-clockwise and one
/// function's values there.
struct Cell {
    i: usize,
    j: usize,
    corners: [(usize, usize); 4],
    v: [f64; 4],
}

impl Cell {
    /// The pieces of function `k`'s zero set in the cell, the crossings of its edges kept
    /// in `cache` (by edge and function).
    fn pieces(
        &self,
        grid: &Grid,
        fields: &impl Fields,
        k: usize,
        shut: bool,
        cache: &mut HashMap<(usize, usize), Option<DVec2>>,
        pieces: &mut Vec<Piece>,
    ) {
        let (i, j, v) = (self.i, self.j, self.v);
        if !shut && v.iter().any(|x| !x.is_finite()) {
            return;
        }
        // Inside: ≥ 0 (a pad or a missing value is outside).
        let ins = v.map(|v| v >= 0.0);
        if ins.iter().all(|x| *x) || ins.iter().all(|x| !*x) {
            return;
        }
        let w = width(grid);
        // The edges counter-clockwise, each with its id and its ends in the id's own order
        // (left to right, bottom to top), so that a crossing is the same from either cell.
        let edges = [
            (2 * (j * w + i), 0, 1),
            (2 * (j * w + i + 1) + 1, 1, 2),
            (2 * ((j + 1) * w + i), 3, 2),
            (2 * (j * w + i) + 1, 0, 3),
        ];
        // The crossings in counter-clockwise order: (edge, leaving the inside).
        let cross: Vec<(usize, bool)> = (0..4)
            .filter(|q| ins[*q] != ins[(q + 1) % 4])
            .map(|q| (q, ins[q]))
            .collect();
        let mut at = |q: usize| {
            let (id, a, b) = edges[q];
            let p = *cache.entry((id, k)).or_insert_with(|| {
                let (pa, pb) = (self.corners[a], self.corners[b]);
                edge_zero(grid, fields, k, shut, (pa, v[a]), (pb, v[b]))
            });
            p.map(|p| (id, p))
        };
        // Each crossing that leaves the inside joined to the one that enters it next (the
        // inside joined across the cell) or before (cut off).
        let through = cross.len() == 4 && {
            let c = position(grid, i, j) + DVec2::splat(0.5 * grid.h);
            fields.at(k, c).unwrap_or(-1.0) >= 0.0
        };
        let n = cross.len();
        for (s, (q, leaves)) in cross.iter().enumerate() {
            if !leaves {
                continue;
            }
            let t = if through {
                (s + 1) % n
            } else {
                (s + n - 1) % n
            };
            if let (Some(from), Some(to)) = (at(*q), at(cross[t].0)) {
                pieces.push(Piece { from, to });
            }
        }
    }
}

/// The zero of function `k` on the edge from node `a` to node `b` (extended indices, each
/// with its value, of opposite sides): its inside end of the bracket; a pad node's neighbour
/// itself. `None` where an open function leaves its domain inside the edge.
fn edge_zero(
    grid: &Grid,
    fields: &impl Fields,
    k: usize,
    shut: bool,
    a: ((usize, usize), f64),
    b: ((usize, usize), f64),
) -> Option<DVec2> {
    if a.1 == PAD {
        return Some(position(grid, b.0 .0, b.0 .1));
    }
    if b.1 == PAD {
        return Some(position(grid, a.0 .0, a.0 .1));
    }
    let (pa, pb) = (
        position(grid, a.0 .0, a.0 .1),
        position(grid, b.0 .0, b.0 .1),
    );
    let d = (pb - pa) / grid.h;
    let missing = |v: f64| if v.is_finite() { v } else { -1.0 };
    // The last value's size: the bracket ends when it is within [`SETTLED`].
    let last = std::cell::Cell::new(f64::INFINITY);
    let f = |t: f64| {
        let v = fields.at(k, pa + d * t);
        let v = if shut { Some(v.unwrap_or(-1.0)) } else { v };
        last.set(v.map_or(f64::INFINITY, f64::abs));
        v
    };
    let [(lo, f_lo), (hi, f_hi)] =
        illinois(f, (0.0, missing(a.1)), (grid.h, missing(b.1)), |u, v| {
            (u - v).abs() <= BRACKET_TO || last.get() <= SETTLED
        })?;
    Some(pa + d * if f_lo.abs() <= f_hi.abs() { lo } else { hi })
}

/// The pieces linked end to start into polylines; a ring's first point repeated last.
fn link(pieces: &[Piece]) -> Vec<Vec<DVec2>> {
    let starts: HashMap<usize, usize> = pieces
        .iter()
        .enumerate()
        .map(|(s, p)| (p.from.0, s))
        .collect();
    let next: Vec<Option<usize>> = pieces
        .iter()
        .map(|p| starts.get(&p.to.0).copied())
        .collect();
    let mut has_prev = vec![false; pieces.len()];
    for n in next.iter().flatten() {
        has_prev[*n] = true;
    }
    let mut used = vec![false; pieces.len()];
    let mut out = Vec::new();
    let walk = |s0: usize, used: &mut Vec<bool>| {
        let mut pts = vec![pieces[s0].from.1];
        let mut s = s0;
        loop {
            used[s] = true;
            pts.push(pieces[s].to.1);
            match next[s] {
                Some(n) if !used[n] => s = n,
                _ => break,
            }
        }
        pts.dedup_by(|a, b| (*a - *b).length() <= 1e-15);
        pts
    };
    // The open ones from their first pieces, then the rings.
    for s in 0..pieces.len() {
        if !has_prev[s] && !used[s] {
            out.push(walk(s, &mut used));
        }
    }
    for s in 0..pieces.len() {
        if !used[s] {
            let mut ring = walk(s, &mut used);
            if ring.first() != ring.last() {
                if let Some(f) = ring.first().copied() {
                    ring.push(f);
                }
            }
            out.push(ring);
        }
    }
    out.retain(|p| p.len() >= 2);
    out
}

/// Inside the rings `rings` by the even–odd rule (a point on a ring may fall either way).
pub fn inside_rings(rings: &[Vec<DVec2>], p: DVec2) -> bool {
    let mut odd = false;
    for ring in rings {
        for s in ring.windows(2) {
            let (a, b) = (s[0], s[1]);
            if (a.y > p.y) != (b.y > p.y) {
                let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if p.x < x {
                    odd = !odd;
                }
            }
        }
    }
    odd
}

/// The distance from `p` to the nearest segment of `lines`.
pub fn distance_to(lines: &[Vec<DVec2>], p: DVec2) -> f64 {
    lines
        .iter()
        .flat_map(|l| l.windows(2))
        .map(|s| {
            let (a, b) = (s[0], s[1]);
            let d = b - a;
            let t = if d.length_squared() > 0.0 {
                ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (a + d * t - p).length()
        })
        .fold(f64::INFINITY, f64::min)
}
