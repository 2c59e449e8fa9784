//! What a group kind and the plan builder see of the compiled program ([`Compiled`]): its
//! point names, the frame's and the crank's points, which link carries a point, and the few
//! construction steps every kind words the same way (a compass set at a point, a guide's
//! drawn line, the step that finds a joint).
//!
//! The program holds the kinds' compiled groups, and a kind reads the program back while it
//! constructs, draws or solves itself; through this trait the kinds depend on what they read,
//! not on the program that holds them.

use super::built::{heading, other};
use super::indexed::{PDir, PGuide};
use crate::construct::{Compass, ConstructionError};
use crate::geom::{DVec2, Line};

/// The compiled program as a group kind reads it. Points are program indices, links numbers.
pub(in crate::linkage) trait Compiled {
    /// Point names by index.
    fn names(&self) -> &[String];
    /// How many points are fixed (indices `0..fixed_count()`).
    fn fixed_count(&self) -> usize;
    /// The crank centre's index.
    fn centre(&self) -> usize;
    /// The link that carries point `k` (0 the frame): its point's link, or the link a group
    /// creates it on.
    fn owner(&self, k: usize) -> usize;
    /// Whether point `k` lies on the frame or on the crank.
    fn on_frame_or_crank(&self, k: usize) -> bool;
    /// Whether point `k` is a further point of a link that no group attaches to.
    fn is_leaf_point(&self, k: usize) -> bool;
    /// Farthest `along` of link `link`'s points at μ_l = `mu`, mm.
    fn link_reach(&self, link: u32, mu: f64) -> f64;

    /// A direction at the drawn points `p`, radians.
    fn drawn_dir(&self, d: &PDir, p: &[DVec2]) -> f64 {
        match *d {
            PDir::Fixed(a) => a,
            PDir::Along { from, to, angle } => heading(p[to] - p[from]) + angle,
        }
    }

    /// A guide's line at the drawn points `p` (mm) at μ_l = `mu`.
    fn drawn_guide(&self, g: &PGuide, p: &[DVec2], mu: f64) -> Option<Line> {
        let e = DVec2::from_angle(self.drawn_dir(&g.dir, p));
        Line::new(p[g.through], e).map(|l| l.offset(g.offset / mu))
    }

    /// How a step names a guide.
    fn guide_name(&self, g: &PGuide) -> String {
        format!("guide through {}", self.names()[g.through])
    }

    /// The compass set at point `k` with `radius` (drawing mm).
    fn compass(&self, p: &[DVec2], k: usize, radius: f64) -> Compass<'_> {
        Compass {
            name: &self.names()[k],
            center: p[k],
            radius,
        }
    }

    /// The step that finds a group's `joint`.
    fn joint_step(&self, s: &str, joint: usize) -> String {
        format!("{s}: point {}", self.names()[joint])
    }

    /// A guide's line at the drawn points, or the step's failure naming it.
    fn line_or_fail(
        &self,
        g: &PGuide,
        p: &[DVec2],
        mu: f64,
        s: &str,
    ) -> Result<Line, ConstructionError> {
        self.drawn_guide(g, p, mu)
            .ok_or_else(|| other(s, &self.guide_name(g)))
    }
}
