//! The grid's zero sets on functions whose zero sets are known, and the region's corners.

use super::plane::{inside_rings, zero_sets, Fields, Grid};
use super::*;
use std::f64::consts::PI;

/// Closed-form functions of the plane.
struct Known(Vec<Box<dyn Fn(DVec2) -> f64 + Sync>>);

impl Fields for Known {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn row(&self, grid: &Grid, j: usize, out: &mut [f64]) {
        let c = self.count();
        for i in 0..=grid.n[0] {
            for k in 0..c {
                out[i * c + k] = self.0[k](grid.node(i, j));
            }
        }
    }
    fn at(&self, k: usize, p: DVec2) -> Option<f64> {
        Some(self.0[k](p))
    }
}

/// Twice the signed area of a ring (> 0 counter-clockwise).
fn area2(ring: &[DVec2]) -> f64 {
    ring.windows(2).map(|s| s[0].perp_dot(s[1])).sum()
}

/// A disc inside the grid is one ring, counter-clockwise about it, on the circle to 1e-12;
/// two discs apart are two rings; a disc cut by the grid's edge (a closed function) is
/// closed along the edge; a line (open) runs corner to corner.
#[test]
fn known_zero_sets() {
    let c = DVec2::new(0.3, 0.2);
    let known = Known(vec![
        Box::new(move |p| 1.0 - (p - c).length()),
        Box::new(|p| {
            (0.5 - (p - DVec2::new(-1.2, 0.0)).length())
                .max(0.5 - (p - DVec2::new(1.2, 0.0)).length())
        }),
        Box::new(|p| 1.0 - p.length()),
        Box::new(|p| p.x - p.y),
    ]);
    let grid = Grid::over(DVec2::splat(-2.0), DVec2::splat(2.0), 0.05);
    let sets = zero_sets(&grid, &known, &[true, true, true, false]);
    assert_eq!(sets[0].len(), 1);
    let ring = &sets[0][0];
    assert_eq!(ring.first(), ring.last());
    assert!(ring.len() > 100);
    for p in ring {
        assert!(((*p - c).length() - 1.0).abs() < 1e-12, "{p}");
    }
    assert!(
        (area2(ring) / 2.0 - PI).abs() < 2e-3,
        "{}",
        area2(ring) / 2.0
    );
    assert!(inside_rings(&sets[0], c) && !inside_rings(&sets[0], DVec2::splat(1.5)));
    assert_eq!(sets[1].len(), 2);
    // The quarter disc on the grid [0, 1.5]²: its edges along the grid's.
    let corner = Grid::over(DVec2::ZERO, DVec2::splat(1.5), 0.05);
    let quarter = zero_sets(&corner, &known, &[true, true, true, false]);
    assert_eq!(quarter[2].len(), 1);
    let q = &quarter[2][0];
    assert!(
        (area2(q) / 2.0 - PI / 4.0).abs() < 1e-3,
        "{}",
        area2(q) / 2.0
    );
    assert!(q.contains(&DVec2::ZERO));
    assert!(inside_rings(&quarter[2], DVec2::splat(0.3)));
    assert!(!inside_rings(&quarter[2], DVec2::splat(0.9)));
    // The line x = y, open: one polyline with the side x ≥ y on its left, so it runs down.
    assert_eq!(sets[3].len(), 1);
    let l = &sets[3][0];
    assert!(l.iter().all(|p| (p.x - p.y).abs() < 1e-12));
    assert!(
        l[0].x > l[l.len() - 1].x,
        "{:?} → {:?}",
        l[0],
        l[l.len() - 1]
    );
}

/// PZ3's pair: every point of the region's boundary lies on a hard limit or the window's
/// edge, with its margin ≥ 0 to 1e-12; the boundary turns at its corners exactly (two limits
/// met there to 1e-12): x_min1 with interference 2, with s_a1 = 0.25m's run, and so on.
#[test]
fn the_regions_corners_are_on_two_limits() {
    let b = Blocking::new([13, 21], BasicRack::GOST_13755).expect("a pair");
    let c = b.trace(BlockingStudy::HARD);
    assert_eq!(c.boundary.len(), 1);
    let (lo, hi) = b.window;
    let mut corners = 0;
    for p in &c.boundary[0] {
        let ix = b.indices(*p).expect("indices");
        let off: Vec<f64> = b
            .hard_levels(BlockingStudy::HARD)
            .iter()
            .map(|(k, l)| ix.of(*k).expect("an index") - l)
            .collect();
        let least = off.iter().copied().fold(f64::INFINITY, f64::min);
        assert!(least >= -1e-12, "{p}: {least}");
        let edge = p.x == lo.x || p.y == lo.y || p.x == hi.x || p.y == hi.y;
        assert!(edge || least <= 1e-9, "{p}: off every limit by {least}");
        if off.iter().filter(|v| v.abs() <= 1e-11).count() >= 2 {
            corners += 1;
        }
    }
    assert!(corners >= 4, "{corners} corners");
}
