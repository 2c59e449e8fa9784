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

/// The value at `t` (interval units, node j at j) of the smooth curve the draughtsman draws
/// through the nodes `samples`: on each interval the cubic Hermite whose slopes at the nodes
/// are the central differences (Catmull–Rom, so the curve turns without a corner at a node);
/// an open set's end slopes such that its end intervals' middles are those of [`read`]. At
/// the middle of every interval it is [`read`]'s cubic through the four nearest nodes (the
/// Hermite's middle is (y_k + y_{k+1})/2 + (m_k − m_{k+1})/8 = (−y_{k−1} + 9y_k + 9y_{k+1} −
/// y_{k+2})/16), so the mean ordinates read there end on the drawn curve. Too few nodes for a
/// slope: [`read`] itself.
pub(super) fn drawn(samples: &[f64], periodic: bool, t: f64) -> f64 {
    let n = samples.len();
    if n < if periodic { 3 } else { 4 } {
        return read(samples, 0.0, periodic, t);
    }
    let intervals = if periodic { n } else { n - 1 };
    let y = |j: i64| samples[j.rem_euclid(n as i64) as usize];
    let last = intervals as i64 - 1;
    let k = (t.floor() as i64).clamp(0, last);
    let central = |j: i64| 0.5 * (y(j + 1) - y(j - 1));
    let slope = |j: i64| {
        if periodic || (1..n as i64 - 1).contains(&j) {
            central(j)
        } else if j == 0 {
            8.0 * (read(samples, 0.0, false, 0.5) - 0.5 * (y(0) + y(1))) + central(1)
        } else {
            let mid = read(samples, 0.0, false, last as f64 + 0.5);
            central(j - 1) - 8.0 * (mid - 0.5 * (y(j - 1) + y(j)))
        }
    };
    let u = t - k as f64;
    let (u2, u3) = (u * u, u * u * u);
    (2.0 * u3 - 3.0 * u2 + 1.0) * y(k)
        + (u3 - 2.0 * u2 + u) * slope(k)
        + (-2.0 * u3 + 3.0 * u2) * y(k + 1)
        + (u3 - u2) * slope(k + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_drawn_curve_passes_the_nodes_and_the_cubic_s_middles() {
        let ys = [
            0.0, 119.5, 186.6, 218.1, 220.7, 195.2, 138.1, 37.9, 2.8, 2.8, -1.9, -2.8,
        ];
        for periodic in [true, false] {
            let intervals = if periodic { ys.len() } else { ys.len() - 1 };
            for k in 0..intervals {
                let node = drawn(&ys, periodic, k as f64);
                assert!((node - ys[k]).abs() < 1e-12, "node {k}: {node}");
                let t = k as f64 + 0.5;
                let (d, r) = (drawn(&ys, periodic, t), read(&ys, 0.0, periodic, t));
                assert!(
                    (d - r).abs() < 1e-9,
                    "periodic {periodic}, middle {k}: {d} ≠ {r}"
                );
            }
        }
        // No corner at a node: the slopes either side agree.
        let h = 1e-6;
        let left = (drawn(&ys, true, 3.0) - drawn(&ys, true, 3.0 - h)) / h;
        let right = (drawn(&ys, true, 3.0 + h) - drawn(&ys, true, 3.0)) / h;
        assert!((left - right).abs() < 1e-3, "{left} ≠ {right}");
    }

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
