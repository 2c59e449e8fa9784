//! Intersections as outcome enums: never NaN, always the crossing angle.
//!
//! A shallow crossing is an ill-conditioned construction (a small error in a radius moves the
//! point a long way), so every proper intersection reports the acute angle between the two
//! curves at the point; the report shows it next to the value.

use super::primitives::{Circle, Line};
use super::tolerance::Tolerances;
use glam::DVec2;

/// Outcome of intersecting two circles (two compass arcs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CircleCircle {
    /// The circles do not meet: too far apart, or one inside the other.
    Disjoint {
        /// Distance between the centres.
        center_distance: f64,
        /// r₁ + r₂.
        radius_sum: f64,
        /// |r₁ − r₂|.
        radius_diff: f64,
    },
    /// The circles touch (within `coincident`): a single point, crossing angle 0.
    Tangent {
        /// The point of contact.
        point: DVec2,
    },
    /// Two points, named by side of the directed line from the first centre to the second.
    Two {
        /// The solution left of c₁ → c₂.
        left: DVec2,
        /// The solution right of c₁ → c₂.
        right: DVec2,
        /// Acute angle between the circles at the points, radians.
        crossing_angle: f64,
    },
    /// Same centre and same radius: every point is common.
    Coincident,
}

/// Intersect two circles.
pub fn circle_circle(a: &Circle, b: &Circle, tol: &Tolerances) -> CircleCircle {
    let delta = b.center - a.center;
    let d = delta.length();
    let (ra, rb) = (a.radius, b.radius);
    let sum = ra + rb;
    let diff = (ra - rb).abs();
    let eps = tol.coincident;
    if d <= eps {
        if diff <= eps {
            return CircleCircle::Coincident;
        }
        return CircleCircle::Disjoint {
            center_distance: d,
            radius_sum: sum,
            radius_diff: diff,
        };
    }
    let u = delta / d;
    if (d - sum).abs() <= eps {
        // External contact: the point divides the centre line in the ratio of the radii.
        let t = if sum > 0.0 { ra / sum } else { 0.5 };
        return CircleCircle::Tangent {
            point: a.center + delta * t,
        };
    }
    if (d - diff).abs() <= eps {
        // Internal contact: on the centre line, on the far side of the smaller circle.
        let point = if ra >= rb {
            a.center + u * ra
        } else {
            a.center - u * ra
        };
        return CircleCircle::Tangent { point };
    }
    if d > sum || d < diff {
        return CircleCircle::Disjoint {
            center_distance: d,
            radius_sum: sum,
            radius_diff: diff,
        };
    }
    // The chord is found from the smaller circle's centre: from the larger one, its distance
    // along u is nearly the radius and the half chord √(r² − along²) would lose the digits
    // of a small circle's offset (a compass set to a fraction of a millimetre beside a long
    // arc). d² − R² is formed as (d − R)(d + R) for the same reason.
    let (base, h) = if rb < ra {
        let along = ((d - ra) * (d + ra) + rb * rb) / (2.0 * d);
        let h = (rb * rb - along * along).max(0.0).sqrt();
        (b.center - u * along, h)
    } else {
        let along = ((d - rb) * (d + rb) + ra * ra) / (2.0 * d);
        let h = (ra * ra - along * along).max(0.0).sqrt();
        (a.center + u * along, h)
    };
    let n = u.perp();
    // Angle between the radii at the point = angle between the tangents.
    let cos_g = ((ra * ra + rb * rb - d * d) / (2.0 * ra * rb)).clamp(-1.0, 1.0);
    let g = cos_g.acos();
    CircleCircle::Two {
        left: base + n * h,
        right: base - n * h,
        crossing_angle: g.min(std::f64::consts::PI - g),
    }
}

/// Outcome of intersecting a line and a circle (an arc notching a guide line).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineCircle {
    /// The line passes outside the circle.
    Disjoint {
        /// Distance from the centre to the line.
        distance: f64,
        /// The radius.
        radius: f64,
    },
    /// The line touches the circle.
    Tangent {
        /// The point of contact (foot of the perpendicular from the centre).
        point: DVec2,
    },
    /// Two points, named by their order along the line's direction.
    Two {
        /// The point farther back along the line's direction.
        backward: DVec2,
        /// The point farther forward along the line's direction.
        forward: DVec2,
        /// Acute angle between the line and the circle at the points, radians.
        crossing_angle: f64,
    },
}

/// Intersect a line with a circle.
pub fn line_circle(line: &Line, c: &Circle, tol: &Tolerances) -> LineCircle {
    let t = line.project_t(c.center);
    let foot = line.eval(t);
    let dist = line.signed_distance(c.center).abs();
    let r = c.radius;
    if (dist - r).abs() <= tol.coincident {
        return LineCircle::Tangent { point: foot };
    }
    if dist > r {
        return LineCircle::Disjoint {
            distance: dist,
            radius: r,
        };
    }
    let h = (r * r - dist * dist).max(0.0).sqrt();
    LineCircle::Two {
        backward: foot - line.direction * h,
        forward: foot + line.direction * h,
        crossing_angle: (dist / r).clamp(-1.0, 1.0).acos(),
    }
}

/// Outcome of intersecting two lines (two straightedge lines of a plan).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineLine {
    /// One common point.
    Point {
        /// The point.
        point: DVec2,
        /// Its parameter on the first line.
        t_a: f64,
        /// Its parameter on the second line.
        t_b: f64,
        /// Acute angle between the lines, radians.
        crossing_angle: f64,
    },
    /// Parallel (within `parallel_sin`) and apart.
    Parallel {
        /// Distance between the lines.
        distance: f64,
    },
    /// The same line (within `parallel_sin` and `coincident`).
    Coincident,
}

/// Intersect two lines.
pub fn line_line(a: &Line, b: &Line, tol: &Tolerances) -> LineLine {
    let det = a.direction.perp_dot(b.direction);
    if det.abs() <= tol.parallel_sin {
        let distance = a.signed_distance(b.point).abs();
        if distance <= tol.coincident {
            return LineLine::Coincident;
        }
        return LineLine::Parallel { distance };
    }
    let w = b.point - a.point;
    let t_a = w.perp_dot(b.direction) / det;
    let t_b = w.perp_dot(a.direction) / det;
    let s = det.abs().min(1.0).asin();
    LineLine::Point {
        point: a.eval(t_a),
        t_a,
        t_b,
        crossing_angle: s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Side;

    fn tol() -> Tolerances {
        Tolerances::for_model_size(100.0).unwrap()
    }
    fn c(x: f64, y: f64, r: f64) -> Circle {
        Circle::new(DVec2::new(x, y), r).unwrap()
    }

    #[test]
    fn circle_circle_two_points_named_by_side() {
        let a = c(0.0, 0.0, 5.0);
        let b = c(8.0, 0.0, 5.0);
        match circle_circle(&a, &b, &tol()) {
            CircleCircle::Two {
                left,
                right,
                crossing_angle,
            } => {
                assert!((left - DVec2::new(4.0, 3.0)).length() < 1e-12, "{left}");
                assert!((right - DVec2::new(4.0, -3.0)).length() < 1e-12, "{right}");
                let line = Line::through(a.center, b.center).unwrap();
                assert_eq!(Side::of(left, &line, 1e-9), Some(Side::Left));
                // Radii 5, 5 and centre distance 8: cos γ = (25 + 25 − 64)/50.
                let g = (-14.0f64 / 50.0).acos();
                assert!((crossing_angle - (std::f64::consts::PI - g)).abs() < 1e-12);
            }
            other => panic!("wanted two points, got {other:?}"),
        }
    }

    #[test]
    fn circle_circle_tangent_returns_single_point() {
        let out = circle_circle(&c(0.0, 0.0, 3.0), &c(5.0, 0.0, 2.0), &tol());
        assert_eq!(
            out,
            CircleCircle::Tangent {
                point: DVec2::new(3.0, 0.0)
            }
        );
        // Nearly tangent, inside the tolerance.
        let out = circle_circle(&c(0.0, 0.0, 3.0), &c(5.0 + 1e-12, 0.0, 2.0), &tol());
        assert!(matches!(out, CircleCircle::Tangent { .. }));
        // Internal contact.
        let out = circle_circle(&c(0.0, 0.0, 5.0), &c(2.0, 0.0, 3.0), &tol());
        assert_eq!(
            out,
            CircleCircle::Tangent {
                point: DVec2::new(5.0, 0.0)
            }
        );
    }

    #[test]
    fn circle_circle_near_tangent_outside_tolerance_has_small_crossing_angle() {
        match circle_circle(&c(0.0, 0.0, 3.0), &c(5.0 - 1e-6, 0.0, 2.0), &tol()) {
            CircleCircle::Two {
                left,
                right,
                crossing_angle,
            } => {
                assert!(crossing_angle < 1e-2 && crossing_angle > 0.0);
                assert!(left.is_finite() && right.is_finite());
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn circle_circle_disjoint_and_coincident() {
        let out = circle_circle(&c(0.0, 0.0, 1.0), &c(5.0, 0.0, 1.0), &tol());
        assert!(
            matches!(out, CircleCircle::Disjoint { center_distance, .. } if center_distance == 5.0)
        );
        let out = circle_circle(&c(0.0, 0.0, 5.0), &c(1.0, 0.0, 1.0), &tol());
        assert!(matches!(out, CircleCircle::Disjoint { .. }));
        assert_eq!(
            circle_circle(&c(1.0, 1.0, 2.0), &c(1.0, 1.0, 2.0), &tol()),
            CircleCircle::Coincident
        );
        // Concentric, different radii.
        assert!(matches!(
            circle_circle(&c(1.0, 1.0, 2.0), &c(1.0, 1.0, 3.0), &tol()),
            CircleCircle::Disjoint { .. }
        ));
    }

    #[test]
    fn circle_circle_zero_radius_is_a_point() {
        // A zero-length link: the point circle lies on the other circle → tangent.
        let out = circle_circle(&c(0.0, 0.0, 0.0), &c(3.0, 0.0, 3.0), &tol());
        assert_eq!(out, CircleCircle::Tangent { point: DVec2::ZERO });
    }

    #[test]
    fn line_circle_cases() {
        let line = Line::new(DVec2::new(-10.0, 3.0), DVec2::X).unwrap();
        match line_circle(&line, &c(0.0, 0.0, 5.0), &tol()) {
            LineCircle::Two {
                backward,
                forward,
                crossing_angle,
            } => {
                assert!((backward - DVec2::new(-4.0, 3.0)).length() < 1e-12);
                assert!((forward - DVec2::new(4.0, 3.0)).length() < 1e-12);
                assert!((crossing_angle - (0.6f64).acos()).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            line_circle(&line, &c(0.0, 0.0, 3.0), &tol()),
            LineCircle::Tangent {
                point: DVec2::new(0.0, 3.0)
            }
        );
        assert!(matches!(
            line_circle(&line, &c(0.0, 0.0, 2.0), &tol()),
            LineCircle::Disjoint { .. }
        ));
    }

    #[test]
    fn line_line_cases() {
        let a = Line::new(DVec2::ZERO, DVec2::X).unwrap();
        let b = Line::new(DVec2::new(2.0, -1.0), DVec2::Y).unwrap();
        match line_line(&a, &b, &tol()) {
            LineLine::Point {
                point,
                t_a,
                t_b,
                crossing_angle,
            } => {
                assert_eq!(point, DVec2::new(2.0, 0.0));
                assert_eq!((t_a, t_b), (2.0, 1.0));
                assert!((crossing_angle - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
            }
            other => panic!("{other:?}"),
        }
        let p = Line::new(DVec2::new(0.0, 1.0), DVec2::X).unwrap();
        assert_eq!(
            line_line(&a, &p, &tol()),
            LineLine::Parallel { distance: 1.0 }
        );
        let q = Line::new(DVec2::new(5.0, 0.0), -DVec2::X).unwrap();
        assert_eq!(line_line(&a, &q, &tol()), LineLine::Coincident);
        // Nearly parallel (sin ≈ 1e-9 < parallel_sin): refused as parallel, no far-away point.
        let n = Line::new(DVec2::new(0.0, 1.0), DVec2::new(1.0, 1e-9)).unwrap();
        assert!(matches!(
            line_line(&a, &n, &tol()),
            LineLine::Parallel { .. }
        ));
        // Shallow but proper: reported with its small crossing angle.
        let s = Line::new(DVec2::new(0.0, 1.0), DVec2::new(1.0, -1e-4)).unwrap();
        match line_line(&a, &s, &tol()) {
            LineLine::Point {
                point,
                crossing_angle,
                ..
            } => {
                assert!((point.x - 1e4).abs() < 1e-6);
                assert!((crossing_angle - 1e-4).abs() < 1e-8);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn zero_length_directions_are_refused() {
        assert!(Line::new(DVec2::ZERO, DVec2::ZERO).is_none());
        assert!(Line::through(DVec2::ONE, DVec2::ONE).is_none());
        assert!(Circle::new(DVec2::ZERO, -1.0).is_none());
        assert!(Circle::new(DVec2::ZERO, f64::NAN).is_none());
    }
}

#[cfg(test)]
mod small_circle {
    use super::*;

    /// A compass set to a fraction of a millimetre beside a long arc through its centre (the
    /// foot of an offset slide line on the Thales circle): both points lie on both circles to
    /// the precision of the long arc's coordinates, not 1e-5 of the small radius.
    #[test]
    fn a_small_circle_on_a_large_one_keeps_its_digits() {
        let tol = Tolerances::for_model_size(1000.0).expect("tolerances");
        let big = Circle {
            center: DVec2::new(-3.7, 125.0),
            radius: 125.05472,
        };
        let c = big.center + DVec2::from_angle(-1.2) * big.radius;
        for r in [4.5e-4, 2e-3, 0.5] {
            let small = Circle {
                center: c,
                radius: r,
            };
            for (x, y) in [(&big, &small), (&small, &big)] {
                let CircleCircle::Two { left, right, .. } = circle_circle(x, y, &tol) else {
                    panic!("two points expected for r = {r}");
                };
                for p in [left, right] {
                    assert!(((p - c).length() - r).abs() <= 1e-12 * r.max(1e-2), "{r}");
                    assert!(((p - big.center).length() - big.radius).abs() <= 1e-12);
                }
            }
        }
    }
}
