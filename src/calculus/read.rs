//! Reading a smooth curve between its drawn points: the cubic through the four nearest.

/// The stencil used to read a curve at `t`: positions (in interval units) and sample
/// indices of the (up to) four samples nearest to `t`. Sample j sits at `j + offset`;
/// a periodic set of n samples repeats with period n.
pub(super) fn stencil(n: usize, offset: f64, periodic: bool, t: f64) -> Vec<(f64, usize)> {
    if n == 0 {
        return Vec::new();
    }
    let below = (t - offset).floor();
    let below = if below.is_finite() { below as i64 } else { 0 };
    let (start, count) = if periodic {
        (below - 1, 4)
    } else if n >= 4 {
        ((below - 1).clamp(0, n as i64 - 4), 4)
    } else {
        (0, n as i64)
    };
    (start..start + count)
        .map(|j| (j as f64 + offset, j.rem_euclid(n as i64) as usize))
        .collect()
}

/// Lagrange weights of the polynomial through positions `ts`, evaluated at `t`.
pub(super) fn weights(ts: &[f64], t: f64) -> Vec<f64> {
    ts.iter()
        .enumerate()
        .map(|(i, &ti)| {
            ts.iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, &tj)| (t - tj) / (ti - tj))
                .product()
        })
        .collect()
}

/// The value at `t` of the cubic through the four samples nearest `t`.
pub(super) fn read(samples: &[f64], offset: f64, periodic: bool, t: f64) -> f64 {
    let st = stencil(samples.len(), offset, periodic, t);
    let ts: Vec<f64> = st.iter().map(|s| s.0).collect();
    weights(&ts, t)
        .iter()
        .zip(&st)
        .map(|(w, &(_, j))| w * samples.get(j).copied().unwrap_or(0.0))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_reads_cubics_exactly_and_wraps() {
        let f = |t: f64| 0.5 * t * t * t - t + 2.0;
        let s: Vec<f64> = (0..6).map(|j| f(j as f64 + 0.5)).collect();
        for t in [0.0, 0.7, 3.0, 6.0] {
            assert!((read(&s, 0.5, false, t) - f(t)).abs() < 1e-12, "t = {t}");
        }
        let st = stencil(6, 0.5, true, 0.0);
        assert_eq!(st.iter().map(|s| s.1).collect::<Vec<_>>(), vec![4, 5, 0, 1]);
        let w = weights(&[-1.5, -0.5, 0.5, 1.5], 0.0);
        assert!((w[1] - 9.0 / 16.0).abs() < 1e-15 && (w[0] + 1.0 / 16.0).abs() < 1e-15);
        assert_eq!(read(&[1.0, 3.0], 0.5, false, 0.0), 0.0);
    }
}
