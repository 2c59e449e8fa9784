//! Hatching a closed outline with parallel strokes (lyon's hatcher), as a draftsman shades
//! a section or a cut-away region.

use super::{DVec2, Segment};
use lyon::algorithms::hatching::{HatchSegment, Hatcher, HatchingOptions, RegularHatchingPattern};
use lyon::math::{point, Angle};
use lyon::path::Path;

/// The strokes hatching the closed polygon `outline` (even-odd inside), `spacing` apart,
/// at `angle` radians from +x; units are the outline's. Empty for fewer than three points or
/// a spacing that is not positive and finite.
pub fn hatch(outline: &[DVec2], spacing: f64, angle: f64) -> Vec<Segment> {
    if outline.len() < 3 || !(spacing.is_finite() && spacing > 0.0) || !angle.is_finite() {
        return Vec::new();
    }
    // lyon works in f32: hatch about the outline's first point to keep the digits.
    let origin = outline[0];
    let mut builder = Path::builder();
    let at = |p: DVec2| point((p.x - origin.x) as f32, (p.y - origin.y) as f32);
    builder.begin(at(outline[0]));
    for p in &outline[1..] {
        builder.line_to(at(*p));
    }
    builder.end(true);
    let path = builder.build();
    let mut out = Vec::new();
    let options = HatchingOptions::tolerance((spacing * 1e-3) as f32)
        .with_angle(Angle::radians(angle as f32));
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
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_hatched_at_45_degrees_is_covered_at_its_spacing() {
        let square = [
            DVec2::new(10.0, 10.0),
            DVec2::new(30.0, 10.0),
            DVec2::new(30.0, 30.0),
            DVec2::new(10.0, 30.0),
        ];
        let strokes = hatch(&square, 2.0, std::f64::consts::FRAC_PI_4);
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
        assert!(hatch(&square[..2], 2.0, 0.0).is_empty());
        assert!(hatch(&square, 0.0, 0.0).is_empty());
    }
}
