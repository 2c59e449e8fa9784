//! Which link carries a guide — the textbook's rule, in one place for the scene's validator
//! and the compiled program: a guide belongs to the link whose body it is. A direction along
//! two points belongs to the link that holds both; a frame direction through a fixed point to
//! the frame; a frame direction through a moving point to the one moving link there. Where the
//! points leave it open (a joint of two links: the rod and the slider at B), the scene names
//! the link (`link`), as it does for a load at a joint. A frame direction stays a frame
//! direction only on a link that does not turn: carried by a turning link it is refused.

use super::error::{CarrierError, LinkageError, ModelError};
use super::indexed::PGuide;
use super::model::{Dir, Group, Mechanism};
use super::program::{group_what, Op, Program};

/// The links a guide's points leave to choose from: for a frame direction, the links at its
/// point `through` (the frame among them for a fixed point); for a direction along two
/// points, the links that hold both.
pub fn candidates(dir: &Dir, on: impl Fn(&str) -> Vec<u32>, through: &str) -> Vec<u32> {
    match dir {
        Dir::Fixed(_) => on(through),
        Dir::Along { from, to, .. } => {
            let b = on(to);
            let mut v: Vec<u32> = on(from).into_iter().filter(|l| b.contains(l)).collect();
            v.sort_unstable();
            v.dedup();
            v
        }
    }
}

/// The link that carries a guide of direction `dir` whose points lie on `links` (see
/// [`candidates`]), `named` by the scene or not; `translates` tells the links known not to
/// turn. The frame is 0.
pub fn carrier(
    links: &[u32],
    dir: &Dir,
    named: Option<u32>,
    translates: impl Fn(u32) -> bool,
) -> Result<u32, CarrierError> {
    let fixed = matches!(dir, Dir::Fixed(_));
    let frame = links.contains(&0);
    let moving: Vec<u32> = links.iter().copied().filter(|&l| l != 0).collect();
    let l = match named {
        Some(l) if links.contains(&l) => l,
        Some(l) => {
            return Err(CarrierError::NotOn {
                link: l,
                links: links.to_vec(),
            })
        }
        None if fixed && frame => 0,
        None => match moving[..] {
            [l] => l,
            [] if frame => 0,
            [] => return Err(CarrierError::Unshared),
            _ => return Err(CarrierError::Ambiguous { links: moving }),
        },
    };
    if fixed && l != 0 && !translates(l) {
        return Err(CarrierError::Turns { link: l });
    }
    Ok(l)
}

impl Group {
    /// The links of the group that translate: a link whose guide (or, for the block of an
    /// RPP, whose slide) keeps a frame direction — its angle is the guide's. Every other link
    /// of a group turns.
    pub fn translating(&self) -> Vec<u32> {
        self.links
            .into_iter()
            .zip(self.dyad.link_dirs())
            .filter(|(_, d)| matches!(d, Some(Dir::Fixed(_))))
            .map(|(link, _)| link)
            .collect()
    }
}

impl Program {
    /// Resolve the carrier of every guide of the program by [`carrier`], from the links
    /// each guide's points lie on before its group is attached and the links that translate
    /// by then; refused with the group and the guide's point where the rule cannot tell.
    pub(super) fn resolve_carriers(&mut self, m: &Mechanism) -> Result<(), LinkageError> {
        let names = self.names.clone();
        let name = |k: usize| names.get(k).cloned().unwrap_or_default();
        for i in 0..self.ops.len() {
            let Op::Dyad { group, .. } = self.ops[i] else {
                continue;
            };
            let Some(g) = m.groups.get(group) else {
                continue;
            };
            let translating: Vec<u32> = m.groups[..group]
                .iter()
                .flat_map(Group::translating)
                .collect();
            let on = |n: &str| -> Vec<u32> {
                self.index(n)
                    .map(|k| self.links_in(&self.ops[..i], k))
                    .unwrap_or_default()
                    .into_iter()
                    .map(|l| l as u32)
                    .collect()
            };
            let mut found = [None, None];
            for (slot, (pg, mg)) in found
                .iter_mut()
                .zip(self.op_guides(i).into_iter().zip(g.dyad.guides()))
            {
                let (Some(pg), Some(mg)) = (pg, mg) else {
                    continue;
                };
                let links = candidates(&mg.dir, on, &mg.through);
                let l = carrier(&links, &mg.dir, mg.link, |l| translating.contains(&l)).map_err(
                    |why| ModelError::Carrier {
                        what: group_what(group, g),
                        point: name(pg.through),
                        why,
                    },
                )?;
                *slot = Some(l as usize);
            }
            if let Op::Dyad { dyad, .. } = &mut self.ops[i] {
                for (pg, l) in dyad.guides_mut().into_iter().zip(found) {
                    if let (Some(pg), Some(l)) = (pg, l) {
                        pg.carrier = l;
                    }
                }
            }
        }
        Ok(())
    }

    /// The guides of operation `i` (none for a point).
    fn op_guides(&self, i: usize) -> [Option<PGuide>; 2] {
        match &self.ops[i] {
            Op::Dyad { dyad, .. } => dyad.guides(),
            Op::Point { .. } => [None, None],
        }
    }
}

#[cfg(test)]
impl Program {
    /// The program with guide `which` (0, 1 in the order of the dyad's guides) of group
    /// `group` carried by `link` instead: the wrong body on purpose, for the tests that show
    /// the checks see it.
    pub(crate) fn carried_by(mut self, group: usize, which: usize, link: usize) -> Self {
        for op in &mut self.ops {
            if let Op::Dyad { group: g, dyad, .. } = op {
                if *g == group {
                    if let Some(pg) = dyad.guides_mut().into_iter().nth(which).flatten() {
                        pg.carrier = link;
                    }
                }
            }
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FIXED: Dir = Dir::Fixed(0.0);

    fn along() -> Dir {
        Dir::Along {
            from: "A".into(),
            to: "B".into(),
            angle: 0.0,
        }
    }

    /// A frame direction through a fixed point is the frame's, even at a pivot; through a
    /// point of one link, that link's; through a joint, the named link's only.
    #[test]
    fn a_frame_direction_is_carried_by_the_frame_or_the_named_slider() {
        let translates = |l: u32| l == 3;
        assert_eq!(carrier(&[0, 3], &FIXED, None, translates), Ok(0));
        assert_eq!(carrier(&[3], &FIXED, None, translates), Ok(3));
        assert_eq!(
            carrier(&[2, 3], &FIXED, None, translates),
            Err(CarrierError::Ambiguous { links: vec![2, 3] })
        );
        assert_eq!(carrier(&[2, 3], &FIXED, Some(3), translates), Ok(3));
        assert_eq!(
            carrier(&[2, 3], &FIXED, Some(2), translates),
            Err(CarrierError::Turns { link: 2 })
        );
        assert_eq!(
            carrier(&[2, 3], &FIXED, Some(4), translates),
            Err(CarrierError::NotOn {
                link: 4,
                links: vec![2, 3]
            })
        );
    }

    /// A direction along two points is the link that holds both, a moving one where the frame
    /// holds them too; two such links must be named; none is refused.
    #[test]
    fn a_direction_along_two_points_is_carried_by_the_link_that_holds_both() {
        let turns = |_: u32| false;
        let on = |n: &str| match n {
            "A" => vec![0, 3],
            _ => vec![3, 5],
        };
        assert_eq!(candidates(&along(), on, "A"), vec![3]);
        assert_eq!(carrier(&[3], &along(), None, turns), Ok(3));
        assert_eq!(carrier(&[0], &along(), None, turns), Ok(0));
        assert_eq!(
            carrier(&[], &along(), None, turns),
            Err(CarrierError::Unshared)
        );
        assert_eq!(
            carrier(&[2, 3], &along(), None, turns),
            Err(CarrierError::Ambiguous { links: vec![2, 3] })
        );
        assert_eq!(carrier(&[2, 3], &along(), Some(2), turns), Ok(2));
    }
}
