//! A diagram's breaks: nodes where its curve has a corner (a change point, where the mechanism
//! passes from one branch to the other) or a jump. The draughtsman draws the curve as a piece
//! on each side and differentiates each piece on its own: the derivative has two values at
//! the break, one read off each piece, and a smooth curve across it would smear the corner
//! over the neighbouring intervals.

use super::read::read;
use super::{CalculusError, Diagram};

/// A node where a diagram's curve breaks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Break {
    /// The node: 0 < node < N on an open diagram, any node of a periodic one.
    pub node: usize,
    /// The ordinate the piece ending at the node reaches there: the node's own at a corner,
    /// another at a jump (the node's ordinate is the next piece's start).
    pub left: f64,
}

impl Diagram {
    /// The diagram with corners at `nodes` (the curve continuous, its slope not).
    ///
    /// # Errors
    /// [`CalculusError::BadBreak`] for a node out of range or given twice.
    pub fn with_corners(self, nodes: &[usize]) -> Result<Self, CalculusError> {
        let breaks = nodes
            .iter()
            .map(|&node| Break {
                node,
                left: self.at(node),
            })
            .collect();
        self.with_breaks(breaks)
    }

    /// The diagram with `breaks` (in any order).
    ///
    /// # Errors
    /// [`CalculusError::BadBreak`] for a node out of range or given twice,
    /// [`CalculusError::NonFinite`] for a left ordinate.
    pub fn with_breaks(mut self, mut breaks: Vec<Break>) -> Result<Self, CalculusError> {
        breaks.sort_by_key(|b| b.node);
        self.breaks = breaks;
        self.validate()?;
        Ok(self)
    }

    /// Breaks inside the diagram, once each, with finite left ordinates.
    pub(super) fn validate_breaks(&self) -> Result<(), CalculusError> {
        let n = self.intervals();
        let inside = |k: usize| if self.periodic { k < n } else { k > 0 && k < n };
        for (i, b) in self.breaks.iter().enumerate() {
            if !inside(b.node) || (i > 0 && self.breaks[i - 1].node >= b.node) {
                return Err(CalculusError::BadBreak { node: b.node });
            }
            if !b.left.is_finite() {
                return Err(CalculusError::NonFinite {
                    what: "ordinate left of a break",
                    index: b.node,
                    value: b.left,
                });
            }
        }
        Ok(())
    }

    /// The break at node `k` (node N of a periodic diagram is node 0).
    pub fn break_at(&self, k: usize) -> Option<&Break> {
        self.break_index(k).map(|i| &self.breaks[i])
    }

    /// The index in [`Diagram::breaks`] of the break at node `k` (node N of a periodic
    /// diagram is node 0).
    pub(super) fn break_index(&self, k: usize) -> Option<usize> {
        let n = self.intervals();
        let k = if self.periodic && n > 0 { k % n } else { k };
        self.breaks.iter().position(|b| b.node == k)
    }

    /// The ordinate at node `k` as the piece ending there reaches it: [`Diagram::at`] but at a
    /// jump.
    pub fn before(&self, k: usize) -> f64 {
        self.break_at(k).map_or_else(|| self.at(k), |b| b.left)
    }

    /// The smooth pieces as node ranges (a, b), a < b: from break to break; on a periodic
    /// diagram the last runs past node N to the first break (b > N), on an open one the
    /// first starts at node 0 and the last ends at node N. One piece, (0, N), without breaks.
    pub(super) fn pieces(&self) -> Vec<(usize, usize)> {
        let n = self.intervals();
        let nodes: Vec<usize> = self.breaks.iter().map(|b| b.node).collect();
        match (self.periodic, nodes.first()) {
            (true, Some(&first)) => {
                let mut ends = nodes.clone();
                ends.push(first + n);
                nodes
                    .iter()
                    .copied()
                    .zip(ends.into_iter().skip(1))
                    .collect()
            }
            _ => spans(n, &nodes),
        }
    }

    /// The spans the drawing shows as one curve each: the pieces cut at node 0 ≡ N too.
    pub(super) fn spans(&self) -> Vec<(usize, usize)> {
        let nodes: Vec<usize> = self.breaks.iter().map(|b| b.node).collect();
        spans(self.intervals(), &nodes)
    }
}

/// The ranges between consecutive nodes of 0, `inner` (ascending) and `n`.
fn spans(n: usize, inner: &[usize]) -> Vec<(usize, usize)> {
    let mut cuts = vec![0];
    cuts.extend(inner.iter().copied().filter(|&k| k > 0 && k < n));
    cuts.push(n);
    cuts.windows(2).map(|w| (w[0], w[1])).collect()
}

/// A derivative's node ordinates read off the smooth curve through its mid-interval
/// ordinates `mids` (one per interval of `src`), piece by piece: `right[k]` the value at
/// node k (0 ≤ k ≤ N) of the piece starting or running through it, and at every break of
/// `src` the value the piece ending there reaches.
pub(super) struct NodeReads {
    /// The value at every node, N included (a periodic diagram's N is its node 0).
    pub right: Vec<f64>,
    /// The value left of every break of the source, in its order.
    pub left: Vec<f64>,
}

impl NodeReads {
    /// Read `src`'s nodes off the cubics through the four nearest midpoints of each piece.
    pub(super) fn of(src: &Diagram, mids: &[f64]) -> Self {
        let n = mids.len();
        if src.breaks.is_empty() {
            let right = (0..=n)
                .map(|k| read(mids, 0.5, src.periodic, k as f64))
                .collect();
            return Self {
                right,
                left: Vec::new(),
            };
        }
        let mut right = vec![0.0; n + 1];
        let mut left = vec![0.0; src.breaks.len()];
        for (a, b) in src.pieces() {
            let piece: Vec<f64> = (a..b).map(|k| mids[k % n]).collect();
            for k in a..=b {
                let v = read(&piece, 0.5, false, (k - a) as f64);
                match src.break_index(k) {
                    Some(i) if k == b => left[i] = v,
                    _ if src.periodic => right[k % n] = v,
                    _ => right[k] = v,
                }
            }
        }
        if src.periodic {
            right[n] = right[0];
        }
        Self { right, left }
    }

    /// The value the piece ending at node `k` (0 < k ≤ N) reaches there, when `k` is a break.
    pub(super) fn left_at(&self, src: &Diagram, k: usize) -> Option<f64> {
        let i = src.break_index(k)?;
        (k > 0).then(|| self.left[i])
    }
}
