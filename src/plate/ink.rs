//! Where each view puts its ink: the cells of a square grid (sheet mm) that its lines and
//! areas pass through — the plate model's own measure of two drawings lying on each other.
//! The plate rules test that no cell holds the ink of two views.

use super::items::{Outline, Shape};
use super::labels::view_outlines;
use super::Plate;
use super::Rect;
use crate::geom::{polygon_contains, DVec2};
use std::collections::BTreeSet;

/// A cell of the grid: column and row of its top-left corner in cells.
pub type Cell = (i64, i64);

/// The cells of side `cell_mm` that each view of `plate` inks, in the order of
/// [`Plate::views`]. Lines are followed along their centre line; areas (blocks, arrowheads,
/// dots) fill the cells whose centre they cover, besides their edges.
pub fn view_ink(plate: &Plate, cell_mm: f64) -> Vec<BTreeSet<Cell>> {
    let cell_mm = cell_mm.max(0.05);
    plate
        .views
        .iter()
        .map(|v| {
            let mut cells = BTreeSet::new();
            for o in view_outlines(v) {
                ink_outline(&o, cell_mm, &mut cells);
            }
            cells
        })
        .collect()
}

fn cell_of(p: DVec2, cell: f64) -> Cell {
    ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64)
}

fn ink_line(a: DVec2, b: DVec2, cell: f64, out: &mut BTreeSet<Cell>) {
    // Samples a quarter of a cell apart: every cell the centre line crosses is met.
    let n = ((b - a).length() / (0.25 * cell)).ceil().min(1e6) as usize;
    for i in 0..=n {
        let t = if n == 0 { 0.0 } else { i as f64 / n as f64 };
        out.insert(cell_of(a.lerp(b, t), cell));
    }
}

fn ink_outline(o: &Outline, cell: f64, out: &mut BTreeSet<Cell>) {
    match &o.shape {
        Shape::Line(a, b) => ink_line(*a, *b, cell, out),
        Shape::Area(pts) => {
            for (i, &a) in pts.iter().enumerate() {
                ink_line(a, pts[(i + 1) % pts.len()], cell, out);
            }
            let Some(bounds) = Rect::around(pts.iter().copied()) else {
                return;
            };
            let (c0, c1) = (cell_of(bounds.min, cell), cell_of(bounds.max, cell));
            for x in c0.0..=c1.0 {
                for y in c0.1..=c1.1 {
                    let centre = DVec2::new(x as f64 + 0.5, y as f64 + 0.5) * cell;
                    if polygon_contains(pts, centre) {
                        out.insert((x, y));
                    }
                }
            }
        }
    }
}
