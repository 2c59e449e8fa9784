//! Golden-section search for the extremum of a unimodal function.

/// Which part of the bracket a golden-section step keeps when its two inner values are
/// equal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tie {
    /// The lower part, [lo, x₂].
    Lower,
    /// The upper part, [x₁, hi].
    Upper,
}

/// How a golden-section search steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GoldenRule {
    /// The most steps it takes.
    pub steps: usize,
    /// The part kept on equal values.
    pub tie: Tie,
    /// Both inner points placed afresh at the golden division of the bracket and evaluated
    /// each step (twice the evaluations, the points exactly where the rounded bracket puts
    /// them), instead of one carried over from the step before.
    pub fresh: bool,
}

/// Where a golden-section search ended: its bracket and the two inner points x₁ < x₂ in
/// it, each with its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Golden {
    /// The bracket's lower end.
    pub lo: f64,
    /// The bracket's upper end.
    pub hi: f64,
    /// (x₁, f(x₁)) and (x₂, f(x₂)).
    pub inner: [(f64, f64); 2],
}

/// Golden-section search for a maximum of `f` on [lo, hi]: the two inner points divide the
/// bracket in the golden ratio, the part beyond the lower value is dropped (on equal values
/// the part `rule.tie` names is kept) and the inner points of the part kept evaluated (one
/// carried over, or both afresh: `rule.fresh`). Stops after `rule.steps` steps or when
/// `narrow(lo, hi)` holds after a step.
pub fn golden_section(
    lo: f64,
    hi: f64,
    rule: GoldenRule,
    narrow: impl Fn(f64, f64) -> bool,
    mut f: impl FnMut(f64) -> f64,
) -> Golden {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (lo, hi);
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..rule.steps {
        let lower = match rule.tie {
            Tie::Lower => f1 >= f2,
            Tie::Upper => f1 > f2,
        };
        if rule.fresh {
            if lower {
                hi = x2;
            } else {
                lo = x1;
            }
            (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            (f1, f2) = (f(x1), f(x2));
        } else if lower {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
        if narrow(lo, hi) {
            break;
        }
    }
    Golden {
        lo,
        hi,
        inner: [(x1, f1), (x2, f2)],
    }
}

/// The largest value of `f` on [lo, hi] by [`golden_section`], and where: (value, x).
/// `f` unimodal on the interval; every value evaluated is kept, so the result is never more
/// than a value `f` takes. Stops when the bracket is a few ulps of its ends wide.
pub fn golden_max(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let narrow = |lo: f64, hi: f64| hi - lo <= 4.0 * f64::EPSILON * (lo.abs() + hi.abs());
    let rule = GoldenRule {
        steps: if narrow(lo, hi) { 0 } else { 200 },
        tie: Tie::Lower,
        fresh: false,
    };
    let mut best = (f64::NEG_INFINITY, lo);
    golden_section(lo, hi, rule, narrow, |x| {
        let v = f(x);
        if v > best.0 {
            best = (v, x);
        }
        v
    });
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// sin on [0, 3]: the maximum 1 at π/2, to the rounding of a flat top (√ε of the
    /// abscissa).
    #[test]
    fn the_maximum_of_sin_is_found_at_a_half_pi() {
        let (v, x) = golden_max(0.0, 3.0, f64::sin);
        assert!((v - 1.0).abs() <= f64::EPSILON, "{v}");
        assert!((x - std::f64::consts::FRAC_PI_2).abs() <= 3e-8, "{x}");
    }

    /// A parabola with its top at 0.3 on [0, 1]: each step keeps the top inside and shrinks
    /// the bracket by the golden ratio (40 steps: 0.618⁴⁰ ≈ 4.3e-9); stopped by the width
    /// asked for.
    #[test]
    fn the_bracket_shrinks_by_the_golden_ratio_about_the_top() {
        let f = |x: f64| -(x - 0.3) * (x - 0.3);
        let rule = |steps, fresh| GoldenRule {
            steps,
            tie: Tie::Lower,
            fresh,
        };
        let g = golden_section(0.0, 1.0, rule(40, false), |_, _| false, f);
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        assert!((g.hi - g.lo - ratio.powi(40)).abs() <= 1e-14, "{g:?}");
        assert!(g.lo <= 0.3 && 0.3 <= g.hi, "{g:?}");
        assert!(g.lo < g.inner[0].0 && g.inner[0].0 < g.inner[1].0 && g.inner[1].0 < g.hi);
        let wide = golden_section(0.0, 1.0, rule(200, false), |lo, hi| hi - lo < 1e-6, f);
        assert!(
            wide.hi - wide.lo < 1e-6 && wide.hi - wide.lo > 0.6e-6,
            "{wide:?}"
        );
        // Both points afresh: the same bracket to rounding, the inner points at its golden
        // division exactly as computed.
        let fresh = golden_section(0.0, 1.0, rule(40, true), |_, _| false, f);
        assert!((fresh.hi - g.hi).abs() <= 1e-14 && (fresh.lo - g.lo).abs() <= 1e-14);
        let at = fresh.hi - ratio * (fresh.hi - fresh.lo);
        assert_eq!(fresh.inner[0].0, at);
    }

    /// A constant: every step ties, so the bracket runs to the end `tie` names.
    #[test]
    fn ties_keep_the_part_named() {
        let rule = |tie| GoldenRule {
            steps: 30,
            tie,
            fresh: false,
        };
        let low = golden_section(0.0, 1.0, rule(Tie::Lower), |_, _| false, |_| 1.0);
        let high = golden_section(0.0, 1.0, rule(Tie::Upper), |_, _| false, |_| 1.0);
        assert_eq!(low.lo, 0.0);
        assert!(low.hi < 1e-5, "{low:?}");
        assert_eq!(high.hi, 1.0);
        assert!(high.lo > 1.0 - 1e-5, "{high:?}");
    }
}
