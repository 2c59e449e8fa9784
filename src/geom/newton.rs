//! Newton's method kept inside a bracket: the root of a function rising through a bracket,
//! each Newton step taken where it lands inside the bracket, the bracket's middle where it
//! does not, so that a poor start or a flat slope never throws it out.

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
}
