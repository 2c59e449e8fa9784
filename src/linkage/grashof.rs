//! Grashof's condition of a hinged four-bar, as the structural analysis states it: the crank,
//! an RRR group on its pin and a pivot of the frame, and the frame between the two pivots
//! (the six-bar's O–A–B–D, the four-bar's O₁–A–B–O₃). A crank exists when the shortest and
//! the longest link together are no longer than the other two (l_min + l_max ≤ l′ + l″) and
//! the shortest turns about the frame or is the frame; with the equality the four links fall
//! into one line once a turn (a change point: the two circles of the group touch, and there
//! the velocity plan does not exist).

use super::model::{Dyad, Mechanism};

/// Lengths equal within this share of the four-bar's perimeter are equal (the scene's
/// 100 + 500 = 300 + 300 in metres).
const EQUAL_SHARE: f64 = 1e-9;

/// One link of a four-bar.
#[derive(Debug, Clone, PartialEq)]
pub struct Bar {
    /// The names of its two pairs' points (`O`, `A`).
    pub ends: [String; 2],
    /// Its length, m.
    pub length: f64,
    /// Its number (0: the frame).
    pub link: u32,
}

/// How l_min + l_max compares with l′ + l″.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    /// Less: the crank turns and nothing falls into line.
    Less,
    /// Equal: a change point (all four links in line once a turn).
    Equal,
    /// Greater: no link turns fully.
    Greater,
}

/// A hinged four-bar of a mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct FourBar {
    /// Its group (file order).
    pub group: usize,
    /// The crank, the coupler, the rocker and the frame, in that order.
    pub bars: [Bar; 4],
}

impl FourBar {
    /// Every hinged four-bar of `m`: each RRR group pinned to the crank's pin and to a
    /// fixed point, in the order of the groups.
    pub fn of(m: &Mechanism) -> Vec<FourBar> {
        let fixed = |name: &str| m.fixed.iter().find(|f| f.name == name).map(|f| f.at);
        let centre = fixed(&m.crank.centre);
        m.groups
            .iter()
            .enumerate()
            .filter_map(|(group, g)| {
                let Dyad::Rrr {
                    a,
                    la,
                    b,
                    lb,
                    joint,
                    ..
                } = &g.dyad
                else {
                    return None;
                };
                let frame = centre?.distance(fixed(b)?);
                (*a == m.crank.pin).then(|| {
                    let bar = |ends: [&String; 2], length: f64, link: u32| Bar {
                        ends: ends.map(Clone::clone),
                        length,
                        link,
                    };
                    FourBar {
                        group,
                        bars: [
                            bar([&m.crank.centre, a], m.crank.length, m.crank.link),
                            bar([a, joint], *la, g.links[0]),
                            bar([b, joint], *lb, g.links[1]),
                            bar([&m.crank.centre, b], frame, 0),
                        ],
                    }
                })
            })
            .collect()
    }

    /// The indices (into [`FourBar::bars`]) of the shortest and the longest link, the first
    /// of equal ones; then the other two, in the bars' order.
    pub fn ranked(&self) -> ([usize; 2], [usize; 2]) {
        let by = |better: fn(f64, f64) -> bool| {
            (1..4).fold(0, |best, i| {
                if better(self.bars[i].length, self.bars[best].length) {
                    i
                } else {
                    best
                }
            })
        };
        let shortest = by(|x, y| x < y);
        let mut longest = by(|x, y| x > y);
        if longest == shortest {
            // Four equal links: any other is the longest.
            longest = (shortest + 1) % 4;
        }
        let mut others = (0..4).filter(|i| *i != shortest && *i != longest);
        let rest = [others.next().unwrap_or(0), others.next().unwrap_or(0)];
        ([shortest, longest], rest)
    }

    /// How l_min + l_max compares with l′ + l″.
    pub fn relation(&self) -> Relation {
        let ([s, l], [p, q]) = self.ranked();
        let len = |i: usize| self.bars[i].length;
        let perimeter: f64 = self.bars.iter().map(|b| b.length).sum();
        let d = (len(s) + len(l)) - (len(p) + len(q));
        if d.abs() <= EQUAL_SHARE * perimeter {
            Relation::Equal
        } else if d < 0.0 {
            Relation::Less
        } else {
            Relation::Greater
        }
    }

    /// Whether a link turns fully about the frame: Grashof's condition holds and the
    /// shortest link is the crank, the rocker (both turn about the frame) or the frame (then
    /// both do).
    pub fn crank_exists(&self) -> bool {
        let ([shortest, _], _) = self.ranked();
        self.relation() != Relation::Greater && shortest != 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::DVec2;
    use crate::linkage::{Branch, Crank, FixedPoint, Group, Sense};

    /// The six-bar's O–A–B–D (seed 001, W1): 100 + 500 = 300 + 300 mm.
    fn six_bar(lb: f64) -> Mechanism {
        let fixed = |name: &str, x: f64| FixedPoint {
            name: name.into(),
            at: DVec2::new(x, 0.0),
        };
        Mechanism {
            fixed: vec![fixed("O", 0.0), fixed("D", -0.3)],
            crank: Crank {
                link: 1,
                centre: "O".into(),
                pin: "A".into(),
                length: 0.1,
                omega: 1.0,
                sense: Sense::Clockwise,
            },
            groups: vec![Group {
                links: [2, 3],
                dyad: Dyad::Rrr {
                    a: "A".into(),
                    la: 0.5,
                    b: "D".into(),
                    lb,
                    joint: "B".into(),
                    branch: Branch::Left,
                },
            }],
            points: Vec::new(),
            redundant: Vec::new(),
            outputs: Vec::new(),
            driving: false,
        }
    }

    #[test]
    fn the_six_bar_is_a_change_point_linkage_with_a_crank() {
        let fb = FourBar::of(&six_bar(0.3));
        assert_eq!(fb.len(), 1);
        let f = &fb[0];
        let names: Vec<String> = f.bars.iter().map(|b| b.ends.concat()).collect();
        assert_eq!(names, ["OA", "AB", "DB", "OD"]);
        assert!((f.bars[3].length - 0.3).abs() < 1e-15);
        assert_eq!(f.ranked(), ([0, 1], [2, 3]));
        assert_eq!(f.relation(), Relation::Equal);
        assert!(f.crank_exists());
        // A rocker 1 mm longer: 600 < 601, a crank without a change point; 1 mm shorter
        // leaves 600 > 599 and no crank.
        assert_eq!(FourBar::of(&six_bar(0.301))[0].relation(), Relation::Less);
        let short = &FourBar::of(&six_bar(0.299))[0];
        assert_eq!(short.relation(), Relation::Greater);
        assert!(!short.crank_exists());
    }
}
