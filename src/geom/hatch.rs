//! Hatching a closed outline with parallel strokes (lyon's hatcher), as a draftsman shades
//! a section or a cut-away region.

use super::{DVec2, Segment};
use lyon::algorithms::hatching::{HatchSegment, Hatcher, HatchingOptions, RegularHatchingPattern};
use lyon::math::{point, Angle};
use lyon::path::Path;
use thiserror::Error;

/// The most hatch lines one outline may take (its extent across the strokes over their
/// spacing): beyond it the drawing is far larger than any sheet, and the strokes would take
/// memory without bound.
pub const MAX_HATCH_LINES: f64 = 100_000.0;

/// Why an outline cannot be hatched.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum HatchError {
    /// A coordinate, the spacing or the angle is not finite.
    #[error("a hatched outline with a coordinate, spacing or angle that is not finite")]
    NonFinite,
    /// The outline spans more hatch lines than [`MAX_HATCH_LINES`].
    #[error("a hatched outline {lines:.3e} strokes across (at most {MAX_HATCH_LINES}): the drawing is far larger than a sheet")]
    TooMany {
        /// The number of hatch lines it would take.
        lines: f64,
    },
}

/// The strokes hatching the closed polygon `outline` (even-odd inside), `spacing` apart,
/// at `angle` radians from +x; units are the outline's. Empty for fewer than three points, a
/// spacing that is not positive, or an outline less than a thousandth of the spacing across
/// the strokes (nothing to hatch; lyon's hatcher has no edge to start from).
///
/// # Errors
/// [`HatchError::NonFinite`] for a coordinate, spacing or angle that is not finite,
/// [`HatchError::TooMany`] for an outline more than [`MAX_HATCH_LINES`] spacings across.
pub fn hatch(outline: &[DVec2], spacing: f64, angle: f64) -> Result<Vec<Segment>, HatchError> {
    if !(spacing.is_finite() && angle.is_finite() && outline.iter().all(|p| p.is_finite())) {
        return Err(HatchError::NonFinite);
    }
    if outline.len() < 3 || spacing <= 0.0 {
        return Ok(Vec::new());
    }
    // lyon works in f32: hatch about the outline's first point to keep the digits.
    let origin = outline[0];
    let at = |p: DVec2| point((p.x - origin.x) as f32, (p.y - origin.y) as f32);
    // The extent across the strokes, as lyon will see it (f32, turned by −angle).
    let (sin, cos) = (angle as f32).sin_cos();
    let (lo, hi) = outline
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(l, h), p| {
            let q = at(*p);
            let v = -sin * q.x + cos * q.y;
            (l.min(v), h.max(v))
        });
    let across = f64::from(hi - lo);
    if !across.is_finite() {
        return Err(HatchError::NonFinite);
    }
    let lines = across / spacing;
    if lines > MAX_HATCH_LINES {
        return Err(HatchError::TooMany { lines });
    }
    if lines <= 1e-3 {
        return Ok(Vec::new());
    }
    let mut builder = Path::builder();
    builder.begin(at(outline[0]));
    for p in &outline[1..] {
        builder.line_to(at(*p));
    }
    builder.end(true);
    let path = builder.build();
    let mut out = Vec::new();
    // lyon turns its angle clockwise from +x (its y axis points down): strokes at `angle`
    // counterclockwise in the outline's y-up axes are its −angle.
    let options = HatchingOptions::tolerance((spacing * 1e-3) as f32)
        .with_angle(Angle::radians(-angle as f32));
    let back = |p: lyon::math::Point| DVec2::new(f64::from(p.x), f64::from(p.y)) + origin;
    Hatcher::new().hatch_path(
        path.iter(),
        &options,
        &mut RegularHatchingPattern {
            interval: spacing as f32,
            callback: &mut |s: &HatchSegment| {
                out.push(Segment::new(back(s.a.position), back(s.b.position)));
            },
        },
    );
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The square from (lo, lo) to (hi, hi), counterclockwise.
    fn square(lo: f64, hi: f64) -> [DVec2; 4] {
        [
            DVec2::new(lo, lo),
            DVec2::new(hi, lo),
            DVec2::new(hi, hi),
            DVec2::new(lo, hi),
        ]
    }

    #[test]
    fn strokes_run_at_the_angle_counted_counterclockwise_from_x() {
        let square = square(0.0, 20.0);
        for deg in [30.0f64, 45.0, 60.0, 135.0] {
            let a = deg.to_radians();
            let strokes = hatch(&square, 2.0, a).unwrap();
            assert!(!strokes.is_empty());
            for s in &strokes {
                let d = (s.to - s.from).normalize();
                assert!(d.perp_dot(DVec2::from_angle(a)).abs() < 1e-5, "{deg}°: {d}");
            }
        }
    }

    #[test]
    fn a_square_hatched_at_45_degrees_is_covered_at_its_spacing() {
        let square = square(10.0, 30.0);
        let strokes = hatch(&square, 2.0, std::f64::consts::FRAC_PI_4).unwrap();
        // Area / spacing, within one stroke's length at either end.
        let total: f64 = strokes.iter().map(Segment::length).sum();
        assert!(
            (total - 400.0 / 2.0).abs() < 2.0 * 20.0 * 2f64.sqrt(),
            "{total}"
        );
        for s in &strokes {
            for p in [s.from, s.to] {
                assert!(
                    (10.0 - 1e-3..=30.0 + 1e-3).contains(&p.x)
                        && (10.0 - 1e-3..=30.0 + 1e-3).contains(&p.y),
                    "{p}"
                );
            }
            let d = (s.to - s.from).normalize();
            assert!((d.x.abs() - d.y.abs()).abs() < 1e-5, "{d}");
        }
        assert!(hatch(&square[..2], 2.0, 0.0).unwrap().is_empty());
        assert!(hatch(&square, 0.0, 0.0).unwrap().is_empty());
    }

    #[test]
    fn tiny_huge_and_non_finite_outlines_neither_panic_nor_run_away() {
        let unit = [(10.0, 10.0), (30.0, 10.0), (30.0, 30.0), (10.0, 31.0)];
        let scaled =
            |s: f64| -> Vec<DVec2> { unit.iter().map(|(x, y)| DVec2::new(*x, *y) * s).collect() };
        // Collapsed in f32 (lyon's hatcher unwrapped `None` on no edge): nothing to hatch.
        for s in [1e-30, 1e-45, 1e-300] {
            assert_eq!(hatch(&scaled(s), 0.5, 0.7), Ok(Vec::new()), "{s}");
        }
        // A line along the strokes has no inside.
        let flat = [DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(3.0, 3.0)];
        assert_eq!(
            hatch(&flat, 0.5, std::f64::consts::FRAC_PI_4),
            Ok(Vec::new())
        );
        // 21 mm across at 0.5 mm: 42 lines, at the limit and beyond it.
        let lines = |s: f64| 21.0 * s / 0.5;
        let edge = MAX_HATCH_LINES / lines(1.0);
        assert!(hatch(&scaled(edge * 0.999), 0.5, 0.0).is_ok());
        for s in [edge * 1.001, 1e10, 1e30] {
            match hatch(&scaled(s), 0.5, 0.0) {
                Err(HatchError::TooMany { lines: n }) => {
                    assert!((n / lines(s) - 1.0).abs() < 1e-5, "{s}: {n}")
                }
                other => panic!("{s}: {other:?}"),
            }
        }
        // Beyond f32 (inf there) and non-finite input.
        for s in [1e40, 1e300] {
            assert_eq!(
                hatch(&scaled(s), 0.5, 0.0),
                Err(HatchError::NonFinite),
                "{s}"
            );
        }
        let mut nan = scaled(1.0);
        nan[2].x = f64::NAN;
        assert_eq!(hatch(&nan, 0.5, 0.0), Err(HatchError::NonFinite));
        assert_eq!(
            hatch(&scaled(1.0), f64::INFINITY, 0.0),
            Err(HatchError::NonFinite)
        );
        assert_eq!(
            hatch(&scaled(1.0), 0.5, f64::NAN),
            Err(HatchError::NonFinite)
        );
    }
}
