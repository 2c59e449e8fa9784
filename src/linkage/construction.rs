//! The plan of positions as a drawing-board construction: every point of every position is
//! found by compass arcs and straightedge lines through the recorder, in drawing millimetres.

use super::built::{Built, Frames};
use super::program::{Op, PDyad, Program};
use crate::construct::{ConstructionError, Item, Recorder, Role};
use crate::geom::{rotate, Arc, DVec2};

/// A failed group construction: which group, and the diagnostic from the recorder.
#[derive(Debug, Clone, PartialEq)]
pub struct Failed {
    /// Group index.
    pub group: usize,
    /// The diagnostic.
    pub error: ConstructionError,
}

impl Program {
    /// Construct the position at crank angle `phi` (radians). `mu` is μ_l (m/mm); `prev` the
    /// previous constructed position (continuity), `tag` names the position in diagnostics.
    pub fn construct(
        &self,
        rec: &mut Recorder,
        phi: f64,
        prev: Option<&Built>,
        tag: &str,
    ) -> Result<Built, Failed> {
        let mut pos = self.crank_divided(rec, phi, tag);
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => self.step_off(rec, &mut pos, tag, (idx, link), DVec2::new(along, across)),
                Op::Dyad { group, links, dyad } => {
                    let s = format!("{tag}, group {} ({})", group + 1, dyad.kind().letters());
                    let links = links.map(|l| l as usize);
                    self.construct_group(rec, &mut pos, prev, &s, links, dyad)
                        .map_err(|error| Failed { group, error })?;
                }
            }
        }
        Ok(pos)
    }

    /// The fixed points, and the crank pin: the division of the crank circle at φ₁.
    fn crank_divided(&self, rec: &mut Recorder, phi: f64, tag: &str) -> Built {
        let mu = rec.scale().value();
        let n = self.names.len();
        let mut pos = Built {
            phi,
            p: vec![DVec2::ZERO; n],
            angle: vec![0.0; self.link_count],
            origin: vec![0usize; self.link_count],
            crossing: Vec::new(),
            step: vec![None; n],
        };
        for (k, f) in self.fixed.iter().enumerate() {
            pos.p[k] = *f / mu;
        }
        let pin = pos.p[self.centre] + DVec2::from_angle(phi) * (self.crank_length / mu);
        pos.p[self.pin] = pin;
        pos.step[self.pin] = Some(rec.draw(
            format!(
                "{tag}: crank circle divided at φ₁ = {:.4}°",
                phi.to_degrees()
            ),
            Item::Point(pin),
            Role::Result,
            &[],
        ));
        pos.angle[self.crank_link as usize] = phi;
        pos.origin[self.crank_link as usize] = self.centre;
        pos
    }

    /// A further point `idx` of a known link: its distance stepped off with dividers from
    /// the link's origin, `local` (along, across; m) in the link's frame.
    fn step_off(
        &self,
        rec: &mut Recorder,
        pos: &mut Built,
        tag: &str,
        (idx, link): (usize, u32),
        local: DVec2,
    ) {
        let mu = rec.scale().value();
        let l = link as usize;
        let o = pos.p[pos.origin[l]];
        let at = o + rotate(local / mu, pos.angle[l]);
        // Dividers: the distance is stepped off from the link's origin.
        let notch = rec.draw(
            format!(
                "{tag}: dividers from {} to {}",
                self.names[pos.origin[l]], self.names[idx]
            ),
            Item::Arc(Arc::notch(o, at, 2.5)),
            Role::Construction,
            &[],
        );
        pos.p[idx] = at;
        pos.step[idx] = Some(rec.draw(
            format!("{tag}: point {} of link {link}", self.names[idx]),
            Item::Point(at),
            Role::Result,
            &[notch],
        ));
    }

    /// One Assur group (step name `s`, links `i`, `j`): its joint by the intersection its
    /// kind calls for (RPR: its slide line), then the frames of its two links.
    fn construct_group(
        &self,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        s: &str,
        [i, j]: [usize; 2],
        dyad: PDyad,
    ) -> Result<(), ConstructionError> {
        let Frames {
            angle: [ti, tj],
            origin: [oi, oj],
            crossing: cr,
        } = dyad.group().construct(self, rec, pos, prev, (s, j))?;
        pos.angle[i] = ti;
        pos.angle[j] = tj;
        pos.origin[i] = oi;
        pos.origin[j] = oj;
        pos.crossing.push(cr);
        Ok(())
    }
}
