//! A solved position ([`Pose`]), why a group cannot be assembled ([`Unassembled`]), a
//! slotted link's pin near its pivot ([`NearPivot`]), and the state one solve reads and
//! writes ([`State`]): what the twin's run and each kind's closed form share.

use super::jet::{heading, sub, unit, AngleJet, Jet, LineJet};
use crate::geom::DVec2;
use crate::linkage::indexed::{PDir, PGuide};

/// A solved position with its velocity and acceleration analogues.
///
/// It mirrors the construction's [`Built`](crate::linkage::Built) field for field on purpose (φ₁, the
/// points, the links' frames, the crossings): the twin and the drawing answer the same
/// questions so that every reading can be set against its analytic value.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Pose {
    /// Crank angle φ₁, radians.
    pub phi: f64,
    /// Point positions by program index, m.
    pub p: Vec<DVec2>,
    /// dp/dφ₁, m/rad.
    pub dp: Vec<DVec2>,
    /// d²p/dφ₁², m/rad².
    pub ddp: Vec<DVec2>,
    /// dθ/dφ₁ by link number.
    pub dangle: Vec<f64>,
    /// d²θ/dφ₁² by link number.
    pub ddangle: Vec<f64>,
    /// The unit vector (cos θ, sin θ) of each link's frame angle, by link number.
    pub dir: Vec<DVec2>,
    /// Link frame origin (point index) by link number.
    pub origin: Vec<usize>,
    /// Per group: the sine of the acute crossing angle of its construction (small =
    /// ill-conditioned; 0 at a tangency).
    pub crossing_sin: Vec<f64>,
    /// A dyad at its toggle (folded) position: the position exists but its analogues are not
    /// determined; `dp`, `ddp` and the angle rates downstream of it are not meaningful.
    pub toggle: Option<Unassembled>,
    /// Slotted links whose pin passes close to their pivot here: true, ill-conditioned rates.
    pub near_pivot: Vec<NearPivot>,
}

/// |dCB/dφ₁| / |CB| above which a slotted link's pin counts as passing close to its pivot:
/// the link turns over a thousand times faster than the crank.
pub const NEAR_PIVOT_RATIO: f64 = 1e3;

/// A slotted link (RPR without offset) whose pin `a` passes close to its pivot `c`: the slot
/// turns at about |w′|/|w| times the crank's rate (w = a − c), a true value that a change of
/// |w| in a length of the mechanism changes by ~100 %.
#[derive(Debug, Clone, PartialEq)]
pub struct NearPivot {
    /// Group index (file order).
    pub group: usize,
    /// The slotted link's number.
    pub link: usize,
    /// The pin's point index.
    pub pin: usize,
    /// The pivot's point index.
    pub pivot: usize,
    /// |w|: the pin's distance from the pivot, m.
    pub distance: f64,
    /// |w′| = |d(a − c)/dφ₁|, m/rad.
    pub speed: f64,
}

impl Pose {
    /// The frame angle of link `l`, radians in (−π, π], from its unit vector.
    pub fn angle(&self, l: usize) -> f64 {
        let e = self.dir[l];
        e.y.atan2(e.x)
    }
}

/// Why a dyad cannot be assembled at this crank angle (or, in [`Pose::toggle`], why its
/// analogues are not determined).
#[derive(Debug, Clone, PartialEq)]
pub struct Unassembled {
    /// Group index (file order).
    pub group: usize,
    /// What fails, with the numbers (m).
    pub detail: String,
}

/// Mutable state of one solve, borrowed from a [`Pose`]: what a kind's solve reads its
/// known points and links from and writes its joint and links to.
pub(in crate::linkage) struct State<'a> {
    /// The position being solved.
    pub(in crate::linkage) pose: &'a mut Pose,
    /// The program's frame directions with their unit vectors.
    pub(super) fixed_dirs: &'a [(f64, DVec2)],
    /// Continuity: `pose` holds the previous position, and each two-solution dyad takes the
    /// solution nearest to its previous joint.
    pub(in crate::linkage) continuity: bool,
    /// The group being solved (file order).
    pub(in crate::linkage) group: usize,
}

impl State<'_> {
    /// Point `k` with its rates.
    #[inline]
    pub(in crate::linkage) fn jet(&self, k: usize) -> Jet {
        Jet {
            p: self.pose.p[k],
            d: self.pose.dp[k],
            dd: self.pose.ddp[k],
        }
    }
    /// Set point `k` with its rates.
    #[inline]
    pub(in crate::linkage) fn set(&mut self, k: usize, j: Jet) {
        self.pose.p[k] = j.p;
        self.pose.dp[k] = j.d;
        self.pose.ddp[k] = j.dd;
    }
    /// Link `l`'s frame angle with its rates.
    #[inline]
    pub(in crate::linkage) fn link(&self, l: usize) -> AngleJet {
        AngleJet {
            d: self.pose.dangle[l],
            dd: self.pose.ddangle[l],
            e: self.pose.dir[l],
        }
    }
    /// Set link `l`'s frame angle with its rates, and its frame origin.
    #[inline]
    pub(in crate::linkage) fn set_link(&mut self, l: usize, t: AngleJet, origin: usize) {
        self.pose.dangle[l] = t.d;
        self.pose.ddangle[l] = t.dd;
        self.pose.dir[l] = t.e;
        self.pose.origin[l] = origin;
    }
    /// A direction of the program with its rates.
    #[inline]
    pub(in crate::linkage) fn dir(&self, d: &PDir) -> AngleJet {
        match *d {
            PDir::Fixed(a) => match self
                .fixed_dirs
                .iter()
                .find(|f| f.0.to_bits() == a.to_bits())
            {
                Some(&(_, e)) => AngleJet { d: 0.0, dd: 0.0, e },
                None => AngleJet::at(a, 0.0, 0.0),
            },
            PDir::Along { from, to, angle } => {
                heading(sub(self.jet(to), self.jet(from))).turned(angle)
            }
        }
    }
    /// A guide of the program with its rates.
    #[inline]
    pub(in crate::linkage) fn guide(&self, g: &PGuide) -> LineJet {
        let t = self.dir(&g.dir);
        let e = unit(t);
        let n = Jet {
            p: e.p.perp(),
            d: e.d.perp(),
            dd: e.dd.perp(),
        };
        let through = self.jet(g.through);
        let o = g.offset;
        LineJet {
            g: Jet {
                p: through.p + n.p * o,
                d: through.d + n.d * o,
                dd: through.dd + n.dd * o,
            },
            e,
            t,
        }
    }
    /// Record the group being solved at its toggle (unless one was met before), with what
    /// fails.
    pub(in crate::linkage) fn toggle(&mut self, detail: String) {
        let group = self.group;
        self.pose
            .toggle
            .get_or_insert(Unassembled { group, detail });
    }
    /// Why the group being solved cannot be assembled: `detail`, with the numbers.
    pub(in crate::linkage) fn fail(&self, detail: String) -> Unassembled {
        Unassembled {
            group: self.group,
            detail,
        }
    }
}
