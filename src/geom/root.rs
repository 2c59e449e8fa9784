//! Roots of a function of one variable: a bracket halved by a judgement of its midpoint
//! (bisection), and a bracket of a sign change shrunk by regula falsi (Illinois).

/// The root of `f` in [lo, hi], where f(lo) and f(hi) differ in sign (else the end nearer
/// zero): [`illinois`] until the bracket is 1e-15 of its end wide, then the end nearer zero.
pub fn bracketed_root(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (f_lo, f_hi) = (f(lo), f(hi));
    if f_lo == 0.0 || f_lo.signum() == f_hi.signum() || !(f_lo.is_finite() && f_hi.is_finite()) {
        return if f_lo.abs() <= f_hi.abs() { lo } else { hi };
    }
    let narrow = |a: f64, b: f64| (a - b).abs() <= 1e-15 * a.abs().max(b.abs());
    match illinois(|x| Some(f(x)), (lo, f_lo), (hi, f_hi), narrow) {
        Some([(a, fa), (b, fb)]) => {
            if fa.abs() <= fb.abs() {
                a
            } else {
                b
            }
        }
        None => lo,
    }
}

/// Shrink the bracket `a`, `b` (each a point and its value, the values of opposite signs by
/// `f64::signum`) about a root of `f`: regula falsi with the Illinois step (the end kept
/// twice has its value halved), so the bracket always holds the root and shrinks
/// superlinearly; a secant point outside the bracket falls back to its middle. Stops on an
/// exact zero (both ends that point), when `narrow(a, b)` holds, when a step no longer moves
/// or after 200 steps. Returns the ends in the order given, each with its value of `f`;
/// `None` when `f` has no value at a point tried.
pub fn illinois(
    f: impl Fn(f64) -> Option<f64>,
    a: (f64, f64),
    b: (f64, f64),
    narrow: impl Fn(f64, f64) -> bool,
) -> Option<[(f64, f64); 2]> {
    let ((mut lo, mut f_lo), (mut hi, mut f_hi)) = (a, b);
    // The values the secant weighs (an end kept twice has its weight halved).
    let (mut w_lo, mut w_hi) = (f_lo, f_hi);
    // Which end was kept last (−1 lo, +1 hi).
    let mut kept = 0;
    for _ in 0..200 {
        if narrow(lo, hi) {
            break;
        }
        let x = hi - w_hi * (hi - lo) / (w_hi - w_lo);
        let x = if x > lo.min(hi) && x < lo.max(hi) {
            x
        } else {
            0.5 * (lo + hi)
        };
        if x == lo || x == hi {
            break;
        }
        let fx = f(x)?;
        if fx == 0.0 {
            return Some([(x, fx), (x, fx)]);
        }
        if fx.signum() == f_lo.signum() {
            (lo, f_lo, w_lo) = (x, fx, fx);
            if kept == 1 {
                w_hi /= 2.0;
            }
            kept = 1;
        } else {
            (hi, f_hi, w_hi) = (x, fx, fx);
            if kept == -1 {
                w_lo /= 2.0;
            }
            kept = -1;
        }
    }
    Some([(lo, f_lo), (hi, f_hi)])
}

/// Where the midpoint a bisection tries lies, as its caller judges it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Midpoint {
    /// On the first end's side: it takes that end's place.
    First,
    /// On the second end's side: it takes that end's place.
    Second,
    /// On the point sought itself: the bisection ends there.
    Root,
    /// Not to be judged (no value there): the bisection ends with the bracket it has.
    Stop,
}

/// Halve the bracket between `a` and `b` (either order) about the point where `side`
/// changes its answer: each step tries the midpoint ½(a + b) and puts it in place of the end
/// `side` names. Stops after `steps` steps, when `narrow(a, b)` holds after a step, when
/// the midpoint no longer differs from an end (the bracket is at rounding), at a
/// [`Midpoint::Root`] (both ends that point) or a [`Midpoint::Stop`]; returns the ends in
/// the order given. An error of `side` ends the bisection with it.
pub fn bisect<E>(
    a: f64,
    b: f64,
    steps: usize,
    narrow: impl Fn(f64, f64) -> bool,
    mut side: impl FnMut(f64) -> Result<Midpoint, E>,
) -> Result<(f64, f64), E> {
    let (mut a, mut b) = (a, b);
    for _ in 0..steps {
        let mid = 0.5 * (a + b);
        if mid == a || mid == b {
            break;
        }
        match side(mid)? {
            Midpoint::First => a = mid,
            Midpoint::Second => b = mid,
            Midpoint::Root => return Ok((mid, mid)),
            Midpoint::Stop => break,
        }
        if narrow(a, b) {
            break;
        }
    }
    Ok((a, b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    /// √2 from x² < 2 on [1, 2]: halved to adjacent doubles about it (the midpoint stops
    /// moving well before 200 steps), in the order given.
    #[test]
    fn bisection_runs_to_the_rounding_about_the_root() {
        // The midpoint's side: `low` below √2, `high` above.
        let side = |low: Midpoint, high: Midpoint| {
            move |x: f64| Ok::<_, Infallible>(if x * x < 2.0 { low } else { high })
        };
        let below = side(Midpoint::First, Midpoint::Second);
        let Ok((a, b)) = bisect(1.0, 2.0, 200, |_, _| false, below);
        let r = 2f64.sqrt();
        assert!(a < b && a <= r && r <= b, "{a} {b}");
        assert_eq!(b, a + f64::EPSILON, "{a} {b}");
        // Either order: the ends come back as given.
        let above = side(Midpoint::Second, Midpoint::First);
        let Ok((hi, lo)) = bisect(2.0, 1.0, 200, |_, _| false, above);
        assert_eq!((lo, hi), (a, b));
    }

    /// The width asked for, the steps allowed, a root met exactly, a stop and an error.
    #[test]
    fn bisection_stops_where_it_is_told() {
        let side = |x: f64| {
            Ok::<_, ()>(if x < 0.3 {
                Midpoint::First
            } else {
                Midpoint::Second
            })
        };
        let (a, b) = bisect(0.0, 1.0, 200, |a, b| b - a <= 1e-3, side).unwrap();
        assert!(
            b - a <= 1e-3 && b - a > 0.5e-3 && a < 0.3 && 0.3 <= b,
            "{a} {b}"
        );
        assert_eq!(bisect(0.0, 1.0, 3, |_, _| false, side), Ok((0.25, 0.375)));
        let root = |x: f64| {
            Ok::<_, ()>(if x == 0.75 {
                Midpoint::Root
            } else {
                Midpoint::First
            })
        };
        assert_eq!(bisect(0.0, 1.0, 200, |_, _| false, root), Ok((0.75, 0.75)));
        let stop = |x: f64| {
            Ok::<_, ()>(if x > 0.75 {
                Midpoint::Second
            } else {
                Midpoint::Stop
            })
        };
        assert_eq!(bisect(0.0, 2.0, 200, |_, _| false, stop), Ok((0.0, 1.0)));
        let fails = |x: f64| {
            if x > 0.75 {
                Ok(Midpoint::Second)
            } else {
                Err(x)
            }
        };
        assert_eq!(bisect(0.0, 2.0, 200, |_, _| false, fails), Err(0.5));
    }
}
