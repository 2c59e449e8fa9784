//! The numeric kernel the domains share: a linear system, a bracketed root and a
//! golden-section maximum.

/// Solve the augmented system `a` (n rows of n + 1) by Gaussian elimination with partial
/// pivoting; `None` when it is singular to rounding (a pivot below 1e-12 of the largest
/// coefficient) or a solution is not finite.
pub fn solve_linear(mut a: Vec<Vec<f64>>) -> Option<Vec<f64>> {
    let n = a.len();
    let big = a
        .iter()
        .flat_map(|r| r[..n].iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    if !(big > 0.0 && big.is_finite()) {
        return None;
    }
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c].abs() <= 1e-12 * big {
            return None;
        }
        a.swap(c, p);
        let (top, rest) = a.split_at_mut(c + 1);
        let pivot = &top[c];
        for row in rest {
            let f = row[c] / pivot[c];
            if f != 0.0 {
                for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                    *x -= f * p;
                }
            }
        }
    }
    let mut x = vec![0.0; n];
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * x[k]).sum();
        x[c] = (a[c][n] - s) / a[c][c];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

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

/// The largest value of `f` on [lo, hi] by golden-section search, and where: (value, x).
/// `f` unimodal on the interval; every value evaluated is kept, so the result is never more
/// than a value `f` takes. Stops when the bracket is a few ulps of its ends wide.
pub fn golden_max(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut best = (f64::NEG_INFINITY, lo);
    let mut keep = |x: f64, v: f64| {
        if v > best.0 {
            best = (v, x);
        }
    };
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    keep(x1, f1);
    keep(x2, f2);
    for _ in 0..200 {
        if hi - lo <= 4.0 * f64::EPSILON * (lo.abs() + hi.abs()) {
            break;
        }
        if f1 >= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
            keep(x1, f1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
            keep(x2, f2);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_system_is_solved_and_a_singular_one_refused() {
        let x = solve_linear(vec![
            vec![2.0, 1.0, -1.0, 8.0],
            vec![-3.0, -1.0, 2.0, -11.0],
            vec![-2.0, 1.0, 2.0, -3.0],
        ])
        .expect("regular");
        for (v, want) in x.iter().zip([2.0, 3.0, -1.0]) {
            assert!((v - want).abs() < 1e-14, "{x:?}");
        }
        assert!(solve_linear(vec![vec![1.0, 2.0, 3.0], vec![2.0, 4.0, 6.0]]).is_none());
        assert!(solve_linear(vec![vec![0.0, 0.0, 1.0], vec![0.0, 0.0, 1.0]]).is_none());
        assert!(solve_linear(vec![vec![f64::NAN, 1.0]]).is_none());
    }
}
