//! `[[mechanism.redundant]]`, `[[mechanism.output]]` and the mobility check, which counts
//! with the linkage's own structure ([`Structure::mobility`]).

use super::check::{item, join, number};
use super::raw::{RawMechanism, RawOutput};
use super::structure::{Builder, MECH};
use crate::geom::Tolerances;
use crate::linkage::{Dir, Group, Mechanism, Output, RedundantPair, Structure};

/// The kinds of a redundant pair, as written (Latin or Cyrillic): prismatic or not.
const PAIR_KINDS: [(&str, bool); 4] = [("R", false), ("P", true), ("В", false), ("П", true)];

impl Builder<'_> {
    /// `[[mechanism.redundant]]`.
    pub(super) fn redundant(&mut self, raw: &RawMechanism) -> Vec<RedundantPair> {
        let mut out = Vec::new();
        for (i, r) in raw.redundant.iter().enumerate() {
            let base = item("mechanism.redundant", i);
            let name = self.check.name(&join(&base, "name"), r.name.as_ref());
            let kind = self
                .check
                .word(&join(&base, "kind"), r.kind.as_ref(), &PAIR_KINDS);
            let links_key = join(&base, "links");
            let links = self.check.link_pair(&links_key, r.links.as_ref(), 0);
            let links = links
                .map(|l| self.existing_links(&links_key, l))
                .unwrap_or([0, 0]);
            let reason = r.reason.clone().unwrap_or_default();
            let prismatic = kind == Some(true);
            out.push(RedundantPair {
                name,
                prismatic,
                links,
                reason,
            });
        }
        out
    }

    /// Both links exist (0 or attached).
    pub(super) fn existing_links(&mut self, key: &str, links: [u32; 2]) -> [u32; 2] {
        for l in links {
            self.existing_link(key, l, 0);
        }
        links
    }

    /// `link` is the frame (when `min` is 0) or an attached moving link; reported otherwise.
    pub(super) fn existing_link(&mut self, key: &str, link: u32, min: u32) -> bool {
        let ok = link >= min && (link == 0 || self.links.iter().any(|(l, _)| *l == link));
        if !ok {
            let attached: Vec<u32> = self.links.iter().map(|(l, _)| *l).collect();
            let frame = if min == 0 { "0 (the frame) or " } else { "" };
            let expected = format!("expected {frame}a moving link of the mechanism {attached:?}");
            self.check.push(key, Some(link.to_string()), expected);
        }
        ok
    }

    /// `[[mechanism.output]]`: at least one.
    pub(super) fn outputs(&mut self, raw: &[RawOutput], groups: &[Group]) -> Vec<Output> {
        if raw.is_empty() {
            let expected = "missing: expected at least one [[mechanism.output]] (rocker = N or slider = \"E\")";
            self.check.push("mechanism.output", None, expected);
        }
        let mut out = Vec::new();
        for (i, o) in raw.iter().enumerate() {
            if let Some(output) = self.output(&item("mechanism.output", i), o, groups) {
                out.push(output);
            }
        }
        out
    }

    /// One output: `rocker = N` or `slider = "E"` with `dir`, which must not be perpendicular
    /// to a frame guide the point slides on (its travel along `dir` would be 0).
    fn output(&mut self, base: &str, o: &RawOutput, groups: &[Group]) -> Option<Output> {
        match (o.rocker, &o.slider) {
            (Some(link), None) => {
                let key = join(base, "rocker");
                let link = self.check.link(&key, link, 1)?;
                self.existing_link(&key, link, 1)
                    .then_some(Output::Rocker { link })
            }
            (None, Some(_)) => {
                let (point, _) = self.point(&join(base, "slider"), o.slider.as_ref());
                let key = join(base, "dir");
                let dir = self.check.angle(&key, o.dir, 0.0);
                if let Some((gi, guide)) = self.frame_guide_of(&point, groups) {
                    let tol = Tolerances::for_model_size(1.0).map_or(0.0, |t| t.parallel_sin);
                    if (dir - guide).cos().abs() <= tol {
                        let expected = format!(
                            "expected the direction of travel of {point} along its guide (mechanism.group[{gi}], {}° or {}°): perpendicular to it, the output's travel is 0 at every position",
                            number(guide.to_degrees()),
                            number((guide + std::f64::consts::PI).to_degrees())
                        );
                        self.check
                            .push(&key, Some(number(o.dir.unwrap_or(0.0))), expected);
                    }
                }
                Some(Output::Slider { point, dir })
            }
            _ => {
                let expected = "expected exactly one of rocker = N or slider = \"E\"";
                self.check.push(base, None, expected);
                None
            }
        }
    }

    /// The group (index) and the direction (radians) of the frame guide that the joint
    /// `point` slides on, if it is the joint of a group with a guide fixed to the frame.
    fn frame_guide_of(&self, point: &str, groups: &[Group]) -> Option<(usize, f64)> {
        groups.iter().enumerate().find_map(|(gi, g)| {
            if g.dyad.joint() != Some(point) {
                return None;
            }
            g.dyad
                .guides()
                .into_iter()
                .flatten()
                .find_map(|gd| match gd.dir {
                    Dir::Fixed(a) if self.is_fixed(&gd.through) => Some((gi, a)),
                    _ => None,
                })
        })
    }

    /// W = 3n − 2p₅ = 1, counting a redundant pair only where it repeats no pair of the
    /// structure. Checked only when the structure itself is valid (no noise after errors).
    pub(super) fn mobility(&mut self, m: &Mechanism) {
        if !self.check.problems.is_empty() {
            return;
        }
        let st = Structure::analyse(m);
        let w = st.mobility();
        if w.w != 1 {
            let stray: Vec<String> = m
                .redundant
                .iter()
                .enumerate()
                .zip(st.pairs.iter().filter(|p| p.redundant))
                .filter(|(_, p)| !st.repeats(p))
                .map(|((i, r), _)| {
                    format!(
                        "mechanism.redundant[{i}] ({:?}, links {:?})",
                        r.name, r.links
                    )
                })
                .collect();
            let discounted = m.redundant.len() - stray.len();
            let expected = format!(
                "W = 3·{} − 2·({} − {discounted}) = {}: expected W = 1 (one driving crank); a redundant pair is discounted only where it \
                 repeats a pair of the structure, and {} repeats none",
                w.n,
                st.p5_all,
                w.w,
                stray.join(", ")
            );
            self.check.push(MECH, None, expected);
        }
    }
}
