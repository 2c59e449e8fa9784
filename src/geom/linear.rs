//! Dense linear algebra for the small systems the domains solve: one forward elimination
//! with partial pivoting, and the solution and the determinant read from it; the null space
//! of a system of relations by its reduced row echelon form.

/// The smallest pivot [`solve_linear`] accepts, as a fraction of the largest coefficient:
/// below it the system is singular to rounding.
pub const SINGULAR_REL: f64 = 1e-12;

/// Forward elimination with partial pivoting on the square part of `rows` (n rows, each at
/// least n long: columns past the n-th, a right-hand side, are carried along). Afterwards
/// row c holds the pivot of column c at `rows[c][c]` and zeros are implied below the
/// diagonal. Returns whether the rows were swapped an odd number of times; `None`, leaving
/// `rows` part-eliminated, at the first column whose largest candidate pivot is not finite
/// or not above `floor` in size.
pub fn eliminate(rows: &mut [Vec<f64>], floor: f64) -> Option<bool> {
    let n = rows.len();
    let mut odd = false;
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| rows[i][c].abs().total_cmp(&rows[j][c].abs()))?;
        let pivot = rows[p][c];
        if !(pivot.abs() > floor && pivot.is_finite()) {
            return None;
        }
        if p != c {
            rows.swap(c, p);
            odd = !odd;
        }
        let (top, rest) = rows.split_at_mut(c + 1);
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
    Some(odd)
}

/// The largest coefficient of the square part of `rows` in size (NaNs passed over).
fn largest(rows: &[Vec<f64>]) -> f64 {
    let n = rows.len();
    rows.iter()
        .flat_map(|r| r[..n].iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()))
}

/// Solve the augmented system `a` (n rows of n + 1) by Gaussian elimination with partial
/// pivoting; `None` when it is singular to rounding (a pivot below [`SINGULAR_REL`] of the
/// largest coefficient) or a solution is not finite.
pub fn solve_linear(a: Vec<Vec<f64>>) -> Option<Vec<f64>> {
    solve_linear_above(a, SINGULAR_REL)
}

/// Solve `a·x = b` (a small dense system, `b` beside `a`) by [`solve_linear_above`] with the
/// pivot floor `rel`; `None` when it is singular.
pub fn solve_system(a: Vec<Vec<f64>>, b: Vec<f64>, rel: f64) -> Option<Vec<f64>> {
    let rows = a
        .into_iter()
        .zip(b)
        .map(|(mut row, b)| {
            row.push(b);
            row
        })
        .collect();
    solve_linear_above(rows, rel)
}

/// [`solve_linear`] with the pivot floor `rel` (a fraction of the largest coefficient) given:
/// 0 takes any pivot that is not zero.
pub fn solve_linear_above(mut a: Vec<Vec<f64>>, rel: f64) -> Option<Vec<f64>> {
    let n = a.len();
    let floor = if rel > 0.0 {
        let big = largest(&a);
        if !(big > 0.0 && big.is_finite()) {
            return None;
        }
        rel * big
    } else {
        0.0
    };
    eliminate(&mut a, floor)?;
    let mut x = vec![0.0; n];
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * x[k]).sum();
        x[c] = (a[c][n] - s) / a[c][c];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The determinant of the square matrix `a` by the same elimination (0 when a column has no
/// pivot that is finite and not zero).
pub fn determinant(mut a: Vec<Vec<f64>>) -> f64 {
    let Some(odd) = eliminate(&mut a, 0.0) else {
        return 0.0;
    };
    let mut det = if odd { -1.0 } else { 1.0 };
    for (c, row) in a.iter().enumerate() {
        det *= row[c];
    }
    det
}

/// A basis of the null space of the `rows` (each `n` long), by reduced row echelon form with
/// partial pivoting; a pivot below `1e-12` of the largest entry counts as zero. One vector
/// for each column without a pivot: 1 there, 0 at the other free columns.
pub fn null_space(rows: &[Vec<f64>], n: usize) -> Vec<Vec<f64>> {
    let mut a: Vec<Vec<f64>> = rows.to_vec();
    let big = a
        .iter()
        .flat_map(|r| r.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let tiny = 1e-12 * big.max(f64::MIN_POSITIVE);
    let mut pivots: Vec<usize> = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == a.len() {
            break;
        }
        let Some(p) = (r..a.len()).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())) else {
            break;
        };
        if a[p][c].abs() <= tiny {
            continue;
        }
        a.swap(r, p);
        let d = a[r][c];
        for v in &mut a[r] {
            *v /= d;
        }
        let pivot = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && row[c] != 0.0 {
                let f = row[c];
                for (x, p) in row.iter_mut().zip(&pivot) {
                    *x -= f * p;
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    (0..n)
        .filter(|c| !pivots.contains(c))
        .map(|free| {
            let mut v = vec![0.0; n];
            v[free] = 1.0;
            for (i, &c) in pivots.iter().enumerate() {
                v[c] = -a[i][free];
            }
            v
        })
        .collect()
}

/// The smallest pivot of the elimination of the square matrix `a`, relative to its largest
/// coefficient: a measure of how near singular it is (0: singular, or not finite).
pub fn smallest_pivot(mut a: Vec<Vec<f64>>) -> f64 {
    let big = largest(&a);
    if !(big > 0.0 && big.is_finite()) || eliminate(&mut a, 0.0).is_none() {
        return 0.0;
    }
    a.iter().enumerate().fold(f64::INFINITY, |least, (c, row)| {
        least.min(row[c].abs() / big)
    })
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

    /// A pivot of 1e-13 of the largest coefficient: singular to the relative floor, solved
    /// with the floor at 0 (x₂ = 1/δ, δ the rounded 1e-13).
    #[test]
    fn the_pivot_floor_decides_what_is_singular() {
        let a = vec![vec![1.0, 1.0, 2.0], vec![1.0, 1.0 + 1e-13, 3.0]];
        assert!(solve_linear(a.clone()).is_none());
        let x = solve_linear_above(a, 0.0).expect("a pivot that is not zero");
        assert!((x[0] + x[1] - 2.0).abs() < 0.05, "{x:?}");
        assert!((x[1] - 1e13).abs() < 1e-2 * 1e13, "{x:?}");
        assert_eq!(solve_linear_above(vec![], 0.0), Some(vec![]));
    }

    /// The determinant against the rule of Sarrus, a row swap's sign, a singular matrix.
    #[test]
    fn the_determinant_agrees_with_sarrus() {
        let m = [[2.0, -1.0, 0.5], [4.0, 3.0, -2.0], [-1.0, 0.25, 5.0]];
        let sarrus =
            m[0][0] * m[1][1] * m[2][2] + m[0][1] * m[1][2] * m[2][0] + m[0][2] * m[1][0] * m[2][1]
                - m[0][2] * m[1][1] * m[2][0]
                - m[0][0] * m[1][2] * m[2][1]
                - m[0][1] * m[1][0] * m[2][2];
        let rows: Vec<Vec<f64>> = m.iter().map(|r| r.to_vec()).collect();
        let d = determinant(rows.clone());
        assert!((d - sarrus).abs() < 1e-12 * sarrus.abs(), "{d} vs {sarrus}");
        let swapped = vec![rows[1].clone(), rows[0].clone(), rows[2].clone()];
        assert!((determinant(swapped) + sarrus).abs() < 1e-12 * sarrus.abs());
        assert_eq!(determinant(vec![vec![1.0, 2.0], vec![2.0, 4.0]]), 0.0);
    }

    /// x + y − z = 0 and 2x + 2y − 2z = 0 (rank 1): the null space is two vectors, each
    /// with a 1 at its free column, each a solution; a regular system has none.
    #[test]
    fn the_null_space_holds_what_the_relations_allow() {
        let rows = vec![vec![1.0, 1.0, -1.0], vec![2.0, 2.0, -2.0]];
        let basis = null_space(&rows, 3);
        assert_eq!(basis, vec![vec![-1.0, 1.0, 0.0], vec![1.0, 0.0, 1.0]]);
        for v in &basis {
            for r in &rows {
                let s: f64 = r.iter().zip(v).map(|(a, x)| a * x).sum();
                assert_eq!(s, 0.0, "{v:?}");
            }
        }
        assert!(null_space(&[vec![2.0, 1.0], vec![1.0, 3.0]], 2).is_empty());
        assert_eq!(null_space(&[], 2), vec![vec![1.0, 0.0], vec![0.0, 1.0]]);
    }

    /// diag(4, 1e-6): the smallest pivot is 1e-6/4 of the largest coefficient; a zero
    /// column gives 0.
    #[test]
    fn the_smallest_pivot_measures_the_nearness_to_singular() {
        let p = smallest_pivot(vec![vec![4.0, 0.0], vec![0.0, 1e-6]]);
        assert!((p - 0.25e-6).abs() < 1e-20, "{p}");
        assert_eq!(smallest_pivot(vec![vec![1.0, 0.0], vec![2.0, 0.0]]), 0.0);
        assert_eq!(smallest_pivot(vec![vec![0.0]]), 0.0);
    }
}
