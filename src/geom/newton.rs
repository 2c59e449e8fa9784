//! Newton's method: kept inside a bracket, the root of a function rising through it (each
//! step taken where it lands inside the bracket, the bracket's middle where it does not, so
//! that a poor start or a flat slope never throws it out); and in the plane, where two
//! levels cross or a point of one level, the slopes by central differences; and for n
//! equations with their Jacobian, each step damped until the residual falls.

use super::{solve_system, DVec2};

/// Where [`bracketed_newton`] ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NewtonEnd<T> {
    /// At a point where the function is exactly zero, with the evaluation's extra there.
    Root(f64, T),
    /// On a Newton step that its caller judged landed on the root: the point it went to, the
    /// step, and the extra at the point it was taken from.
    Landed {
        /// Where the step went.
        to: f64,
        /// The step taken, `to` − the point it was taken from.
        step: f64,
        /// The evaluation's extra at the point it was taken from.
        from: T,
    },
    /// At the bracket's middle, when the bracket (or the step to its middle) came down to a
    /// few ulps.
    Middle(f64),
    /// At the last point tried, after the steps allowed.
    Spent(f64),
}

/// The root of `f` in the bracket `[lo, hi]`, over which it rises (negative at `lo`,
/// positive at `hi`), from `start` (clamped into it). `f(x)` gives the value, the slope and
/// an extra its caller carries to the end (a tangent it computed on the way); each point
/// tried narrows the bracket by its sign. The Newton step is taken when it lands inside the
/// bracket, and ends the search when `landed(x, step, extra)` judges it on the root; else the
/// bracket's middle is tried, and ends it when it lies within 4 ulps of the last point or the
/// bracket is 4 ulps wide. At most `steps` points.
pub fn bracketed_newton<T>(
    f: impl Fn(f64) -> (f64, f64, T),
    (lo, hi): (f64, f64),
    start: f64,
    steps: usize,
    landed: impl Fn(f64, f64, &T) -> bool,
) -> NewtonEnd<T> {
    let (mut lo, mut hi) = (lo, hi);
    let mut x = start.clamp(lo, hi);
    for _ in 0..steps {
        let (value, slope, extra) = f(x);
        if value == 0.0 {
            return NewtonEnd::Root(x, extra);
        }
        if value > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let newton = x - value / slope;
        if newton > lo && newton < hi {
            let step = newton - x;
            if landed(x, step, &extra) {
                return NewtonEnd::Landed {
                    to: newton,
                    step,
                    from: extra,
                };
            }
            x = newton;
        } else {
            let middle = 0.5 * (lo + hi);
            if (middle - x).abs() <= 4.0 * f64::EPSILON * x || hi - lo <= 4.0 * f64::EPSILON * hi {
                return NewtonEnd::Middle(middle);
            }
            x = middle;
        }
    }
    NewtonEnd::Spent(x)
}

/// Where [`plane_newton`] or [`level_newton`] ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlaneNewton {
    /// Every equation within its tolerance at this point.
    Settled(DVec2),
    /// The last point reached after the steps allowed, not within the tolerance.
    Unsettled(DVec2),
    /// The equations' slopes give no step (their Jacobian singular there).
    Flat,
    /// An equation had no value at a point tried.
    Undefined,
}

/// The slope of `f` at `p` by central differences `diff` apart, each way.
fn slope(f: &impl Fn(DVec2) -> Option<f64>, p: DVec2, diff: f64) -> Option<DVec2> {
    let (dx, dy) = (DVec2::new(diff, 0.0), DVec2::new(0.0, diff));
    Some(DVec2::new(f(p + dx)? - f(p - dx)?, f(p + dy)? - f(p - dy)?) / (2.0 * diff))
}

/// The Jacobian of the two equations `f` at `p` by central differences `diff` apart: its
/// columns, the derivatives along x and along y.
fn columns(f: &impl Fn(DVec2) -> Option<DVec2>, p: DVec2, diff: f64) -> Option<(DVec2, DVec2)> {
    let (ex, ey) = (DVec2::new(diff, 0.0), DVec2::new(0.0, diff));
    Some((
        (f(p + ex)? - f(p - ex)?) / (2.0 * diff),
        (f(p + ey)? - f(p - ey)?) / (2.0 * diff),
    ))
}

/// The point of the plane where both equations `f` (its x and y) are zero, by Newton's steps
/// from `from`, the Jacobian by central differences `diff` apart: settled once both are
/// within `to`; flat where the Jacobian's determinant is no more than `flat` times its
/// columns' lengths' product (or not a number). At most `steps` steps.
pub fn plane_newton(
    f: impl Fn(DVec2) -> Option<DVec2>,
    from: DVec2,
    (diff, to): (f64, f64),
    steps: usize,
    flat: f64,
) -> PlaneNewton {
    let mut p = from;
    for _ in 0..steps {
        let Some(v) = f(p) else {
            return PlaneNewton::Undefined;
        };
        if v.abs().max_element() <= to {
            return PlaneNewton::Settled(p);
        }
        let Some((dx, dy)) = columns(&f, p, diff) else {
            return PlaneNewton::Undefined;
        };
        // [dx dy] · step = −v.
        let det = dx.x * dy.y - dy.x * dx.y;
        let scale = dx.length() * dy.length();
        if det.abs().partial_cmp(&(flat * scale)) != Some(std::cmp::Ordering::Greater) {
            return PlaneNewton::Flat;
        }
        p += DVec2::new(
            (-v.x * dy.y + v.y * dy.x) / det,
            (-v.y * dx.x + v.x * dx.y) / det,
        );
    }
    PlaneNewton::Unsettled(p)
}

/// A point of the plane where the equation `f` is zero, by Newton's steps from `from`, the
/// slope by central differences `diff` apart: along `along` (a line through `from`), or down
/// the slope itself (the nearest point of the level, to first order), settled once within
/// `to`; flat where the slope along the line is zero. At most `steps` steps.
pub fn level_newton(
    f: impl Fn(DVec2) -> Option<f64>,
    from: DVec2,
    along: Option<DVec2>,
    (diff, to): (f64, f64),
    steps: usize,
) -> PlaneNewton {
    let mut p = from;
    for _ in 0..steps {
        let Some(v) = f(p) else {
            return PlaneNewton::Undefined;
        };
        if v.abs() <= to {
            return PlaneNewton::Settled(p);
        }
        let Some(g) = slope(&f, p, diff) else {
            return PlaneNewton::Undefined;
        };
        p += match along {
            Some(dir) => {
                let rate = g.dot(dir);
                if rate == 0.0 {
                    return PlaneNewton::Flat;
                }
                -dir * (v / rate)
            }
            None => -g * (v / g.length_squared()),
        };
    }
    PlaneNewton::Unsettled(p)
}

/// The root of n equations by Newton's steps from `start`: `residual` gives their values g
/// and Jacobian J at a point, each step solves J·d = −g (any pivot that is not zero taken)
/// and is halved until the residual's largest entry falls by at least 1e-4 of the share of
/// the step taken (Armijo) or comes within the tolerance `to(x)`; settled once it is within
/// it. With the point, the steps it took; `None` when a Jacobian is singular, a step is
/// halved below 1/1024 or `steps` pass.
pub fn damped_newton(
    residual: impl Fn(&[f64]) -> (Vec<f64>, Vec<Vec<f64>>),
    start: &[f64],
    to: impl Fn(&[f64]) -> f64,
    steps: usize,
) -> Option<(Vec<f64>, usize)> {
    let norm = |g: &[f64]| g.iter().fold(0.0f64, |a, g| a.max(g.abs()));
    let mut x = start.to_vec();
    let (mut g, mut jac) = residual(&x);
    for step in 0..steps {
        let tol = to(&x);
        if norm(&g) <= tol {
            return Some((x, step));
        }
        let rhs: Vec<f64> = g.iter().map(|g| -g).collect();
        let d = solve_system(jac, rhs, 0.0)?;
        let g0 = norm(&g);
        let mut lambda = 1.0;
        loop {
            let trial: Vec<f64> = x.iter().zip(&d).map(|(x, d)| x + lambda * d).collect();
            let (gt, jt) = residual(&trial);
            if norm(&gt) < (1.0 - 1e-4 * lambda) * g0 || norm(&gt) <= tol {
                (x, g, jac) = (trial, gt, jt);
                break;
            }
            lambda /= 2.0;
            if lambda < 1.0 / 1024.0 {
                return None;
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where a search ended on the root: an exact zero, or a landed step's end.
    fn root<T: std::fmt::Debug>(end: NewtonEnd<T>) -> f64 {
        match end {
            NewtonEnd::Root(x, _) | NewtonEnd::Landed { to: x, .. } => x,
            _ => panic!("{end:?}"),
        }
    }

    /// The cube root of 2 as the root of x³ − 2 on [0, 2]: Newton's steps from a start far
    /// off end on it (a step under 1e-15 of x judged landed, or an exact zero).
    #[test]
    fn newton_in_a_bracket_lands_on_the_root() {
        let f = |x: f64| (x * x * x - 2.0, 3.0 * x * x, ());
        let end = bracketed_newton(f, (0.0, 2.0), 2.0, 100, |x, step, _| {
            step.abs() <= 1e-15 * x
        });
        let to = root(end);
        assert!((to - 2f64.cbrt()).abs() <= 4.0 * f64::EPSILON, "{to}");
    }

    /// From the flat start x = 0 (slope 0: the step leaves the bracket) the middle is taken,
    /// and the search still ends on the root; an exact zero ends it there.
    #[test]
    fn a_step_out_of_the_bracket_takes_its_middle() {
        let f = |x: f64| (x * x * x - 2.0, 3.0 * x * x, x);
        let end = bracketed_newton(f, (0.0, 2.0), 0.0, 100, |x, step, _| {
            step.abs() <= 1e-15 * x
        });
        let to = root(end);
        assert!((to - 2f64.cbrt()).abs() <= 4.0 * f64::EPSILON, "{to}");
        let exact = bracketed_newton(
            |x| (x - 1.0, 1.0, ()),
            (0.0, 2.0),
            1.0,
            100,
            |_, _, _| false,
        );
        assert_eq!(exact, NewtonEnd::Root(1.0, ()));
        // A function that never lands halves its bracket down to a few ulps.
        let step = |x: f64| (if x < 1.0 { -1.0 } else { 1.0 }, 1e-300, ());
        let NewtonEnd::Middle(m) = bracketed_newton(step, (0.0, 2.0), 0.5, 200, |_, _, _| false)
        else {
            panic!("no middle");
        };
        assert!((m - 1.0).abs() <= 1e-15, "{m}");
    }

    /// The circle x² + y² = 4 and the line y = x cross at (√2, √2): reached from (1, 0,5);
    /// two equal equations are flat; an equation without a value is undefined.
    #[test]
    fn newton_in_the_plane_finds_where_two_levels_cross() {
        let f = |p: DVec2| Some(DVec2::new(p.length_squared() - 4.0, p.y - p.x));
        let end = plane_newton(f, DVec2::new(1.0, 0.5), (1e-7, 1e-12), 30, 1e-9);
        let PlaneNewton::Settled(p) = end else {
            panic!("{end:?}");
        };
        assert!(p.distance(DVec2::splat(2f64.sqrt())) < 1e-12, "{p}");
        let same = |p: DVec2| Some(DVec2::splat(p.x + p.y - 1.0));
        let end = plane_newton(same, DVec2::ZERO, (1e-7, 1e-12), 30, 1e-9);
        assert_eq!(end, PlaneNewton::Flat);
        let none = |_: DVec2| None::<DVec2>;
        let end = plane_newton(none, DVec2::ZERO, (1e-7, 1e-12), 30, 1e-9);
        assert_eq!(end, PlaneNewton::Undefined);
    }

    /// The circle x² + y² = 4 reached along the line through (1, 1) at 45° — (√2, √2) —
    /// and down its slope from (3, 0) — (2, 0); along a line the level runs parallel to, flat.
    #[test]
    fn newton_on_one_level_goes_along_a_line_or_down_the_slope() {
        let f = |p: DVec2| Some(p.length_squared() - 4.0);
        let d = Some(DVec2::ONE);
        let end = level_newton(f, DVec2::ONE, d, (1e-7, 1e-12), 30);
        let PlaneNewton::Settled(p) = end else {
            panic!("{end:?}");
        };
        assert!(p.distance(DVec2::splat(2f64.sqrt())) < 1e-12, "{p}");
        let end = level_newton(f, DVec2::new(3.0, 0.0), None, (1e-7, 1e-12), 30);
        let PlaneNewton::Settled(p) = end else {
            panic!("{end:?}");
        };
        assert!(p.distance(DVec2::new(2.0, 0.0)) < 1e-12, "{p}");
        let line = |p: DVec2| Some(p.y - 1.0);
        let end = level_newton(line, DVec2::ZERO, Some(DVec2::X), (1e-7, 1e-12), 30);
        assert_eq!(end, PlaneNewton::Flat);
    }

    /// x² + y² = 4 and x·y = 1 from (2, 0,3): the root (1,9319, 0,5176) to 1e-14, in a few
    /// steps; x² + 1 = 0 has none (its step halves away).
    #[test]
    fn damped_newton_solves_a_small_system_or_says_it_cannot() {
        let r = |v: &[f64]| {
            let (x, y) = (v[0], v[1]);
            (
                vec![x * x + y * y - 4.0, x * y - 1.0],
                vec![vec![2.0 * x, 2.0 * y], vec![y, x]],
            )
        };
        let (p, steps) = damped_newton(r, &[2.0, 0.3], |_| 1e-14, 60).expect("a root");
        let exact = [(2.0 + 3f64.sqrt()).sqrt(), (2.0 - 3f64.sqrt()).sqrt()];
        assert!(
            (p[0] - exact[0]).abs() < 1e-13 && (p[1] - exact[1]).abs() < 1e-13,
            "{p:?}"
        );
        assert!(steps < 10, "{steps}");
        let none = |v: &[f64]| (vec![v[0] * v[0] + 1.0], vec![vec![2.0 * v[0]]]);
        assert_eq!(damped_newton(none, &[1.0], |_| 1e-14, 60), None);
    }
}
