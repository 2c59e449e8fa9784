//! `[[mechanism.group]]`: the Assur groups of the five kinds, their guides and directions,
//! validated in file order against the points known at each group.

use super::check::{item, join, one_of, quoted};
use super::raw::{RawDir, RawGroup, RawGuide};
use super::structure::Builder;
use crate::linkage::{
    candidates, carrier, Branch, CarrierError, Dir, Dyad, DyadKind, Group, Guide,
};

impl Builder<'_> {
    /// `[[mechanism.group]]` in file order.
    pub(super) fn groups(&mut self, raw: &[RawGroup]) -> Vec<Group> {
        let mut out = Vec::new();
        for (i, g) in raw.iter().enumerate() {
            if let Some(group) = self.group(&item("mechanism.group", i), g) {
                out.push(group);
            }
        }
        out
    }

    /// One group; `None` when its kind or links cannot be told (reported).
    pub(super) fn group(&mut self, base: &str, g: &RawGroup) -> Option<Group> {
        let kind = self.kind(&join(base, "kind"), g.kind.as_ref())?;
        self.refuse_foreign_keys(base, kind, g);
        let links = self
            .check
            .link_pair(&join(base, "links"), g.links.as_ref(), 1)?;
        let [i, j] = links;
        let dyad = match kind {
            DyadKind::Rrr => self.rrr(base, g, links),
            DyadKind::Rrp => self.rrp(base, g, links),
            DyadKind::Rpr => self.rpr(base, g, links),
            DyadKind::Prp => self.prp(base, g, links),
            DyadKind::Rpp => self.rpp(base, g, links),
        };
        for link in links {
            self.attach(link, join(base, "links"), format!("{links:?}"));
        }
        let group = Group {
            links: [i, j],
            dyad,
        };
        self.translating.extend(group.translating());
        Some(group)
    }

    /// `kind = "RRR"` … (case-insensitive, Cyrillic accepted).
    pub(super) fn kind(&mut self, key: &str, v: Option<&String>) -> Option<DyadKind> {
        let words: Vec<&str> = DyadKind::ALL.iter().map(|k| k.letters()).collect();
        let s = self.check.required(key, v, &one_of(&words))?;
        let upper = s.to_uppercase();
        let found = DyadKind::ALL
            .into_iter()
            .find(|k| k.letters() == upper || k.letters_ru() == upper);
        if found.is_none() {
            let ru: Vec<&str> = DyadKind::ALL.iter().map(|k| k.letters_ru()).collect();
            let expected = format!("expected {} (or {})", one_of(&words), ru.join(", "));
            self.check.push(key, Some(quoted(s)), expected);
        }
        found
    }

    /// Report the keys that belong to other kinds.
    pub(super) fn refuse_foreign_keys(&mut self, base: &str, kind: DyadKind, g: &RawGroup) {
        let allowed = kind.words().keys;
        for (key, value) in g.present() {
            if !allowed.contains(&key) {
                let expected = format!(
                    "not a key of an {} group: expected only kind, {}",
                    kind.letters(),
                    allowed.join(", ")
                );
                self.check.push(join(base, key), Some(value), expected);
            }
        }
    }

    /// The new joint of a group, known on `links` from now on.
    pub(super) fn joint(&mut self, base: &str, g: &RawGroup, links: &[u32]) -> String {
        let joint = self.check.name(&join(base, "joint"), g.joint.as_ref());
        self.know(&joint, links);
        joint
    }

    /// Kind 1, RRR.
    pub(super) fn rrr(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, _) = self.point(&join(base, "a"), g.a.as_ref());
        let la = self.check.length(&join(base, "la"), g.la);
        let (b, _) = self.point(&join(base, "b"), g.b.as_ref());
        let lb = self.check.length(&join(base, "lb"), g.lb);
        let branch = self.branch(base, g, DyadKind::Rrr);
        let joint = self.joint(base, g, &links);
        self.also_on(&a, links[0]);
        self.also_on(&b, links[1]);
        Dyad::Rrr {
            a,
            la,
            b,
            lb,
            joint,
            branch,
        }
    }

    /// Kind 2, RRP.
    pub(super) fn rrp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, _) = self.point(&join(base, "a"), g.a.as_ref());
        let la = self.check.length(&join(base, "la"), g.la);
        let guide = self.guide(&join(base, "guide"), g.guide.as_ref());
        let branch = self.branch(base, g, DyadKind::Rrp);
        let joint = self.joint(base, g, &links);
        self.also_on(&a, links[0]);
        Dyad::Rrp {
            a,
            la,
            guide,
            joint,
            branch,
        }
    }

    /// Kind 3, RPR.
    pub(super) fn rpr(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, _) = self.point(&join(base, "a"), g.a.as_ref());
        let (c, _) = self.point(&join(base, "c"), g.c.as_ref());
        let offset = self.check.distance(&join(base, "offset"), g.offset, 0.0);
        self.also_on(&a, links[0]);
        self.also_on(&c, links[1]);
        Dyad::Rpr { a, c, offset }
    }

    /// Kind 4, PRP.
    pub(super) fn prp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let guide_i = self.guide(&join(base, "guide_i"), g.guide_i.as_ref());
        let guide_j = self.guide(&join(base, "guide_j"), g.guide_j.as_ref());
        let joint = self.joint(base, g, &links);
        Dyad::Prp {
            guide_i,
            guide_j,
            joint,
        }
    }

    /// Kind 5, RPP.
    pub(super) fn rpp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, _) = self.point(&join(base, "a"), g.a.as_ref());
        let slide_key = join(base, "slide");
        let slide = self
            .check
            .required(&slide_key, g.slide.as_ref(), "a direction");
        let slide = self.dir(&slide_key, slide);
        let guide = self.guide(&join(base, "guide"), g.guide.as_ref());
        let joint = self.joint(base, g, &links[1..]);
        Dyad::Rpp {
            a,
            slide,
            guide,
            joint,
        }
    }

    /// `branch`: left/right for RRR, forward/backward for RRP.
    pub(super) fn branch(&mut self, base: &str, g: &RawGroup, kind: DyadKind) -> Branch {
        let table = match kind {
            DyadKind::Rrr => [("left", Branch::Left), ("right", Branch::Right)],
            _ => [("forward", Branch::Forward), ("backward", Branch::Backward)],
        };
        let found = self
            .check
            .word(&join(base, "branch"), g.branch.as_ref(), &table);
        found.unwrap_or(table[0].1)
    }

    /// A guide `{ through, dir, offset }`.
    pub(super) fn guide(&mut self, key: &str, raw: Option<&RawGuide>) -> Guide {
        let Some(raw) = self
            .check
            .required(key, raw, "a guide { through, dir, offset }")
        else {
            return Guide {
                through: String::new(),
                dir: Dir::Fixed(0.0),
                offset: 0.0,
                link: None,
            };
        };
        let (through, _) = self.point(&join(key, "through"), raw.through.as_ref());
        let dir_key = join(key, "dir");
        let dir = self
            .check
            .required(&dir_key, raw.dir.as_ref(), "a direction");
        let dir = self.dir(&dir_key, dir);
        let offset = self.check.distance(&join(key, "offset"), raw.offset, 0.0);
        let link = raw
            .link
            .and_then(|l| self.check.link(&join(key, "link"), l, 0));
        let guide = Guide {
            through,
            dir,
            offset,
            link,
        };
        self.carried(key, raw, &guide);
        guide
    }

    /// The guide's carrier as [`carrier`] decides it from the links its points lie on so far,
    /// refused at `link` (a link that does not hold the points, or turns under a frame
    /// direction) or, where its point joins several links and none is named, at `through`.
    fn carried(&mut self, key: &str, raw: &RawGuide, guide: &Guide) {
        let on = |n: &str| {
            self.known
                .iter()
                .find(|k| k.name == n)
                .map(|k| k.links.clone())
        };
        let points_known = match &guide.dir {
            Dir::Fixed(_) => on(&guide.through).is_some(),
            Dir::Along { from, to, .. } => on(from).is_some() && on(to).is_some(),
        };
        if !points_known || (raw.link.is_some() && guide.link.is_none()) {
            return;
        }
        let links = candidates(&guide.dir, |n| on(n).unwrap_or_default(), &guide.through);
        let translates = |l: u32| self.translating.contains(&l);
        let why = match carrier(&links, &guide.dir, guide.link, translates) {
            Ok(_) | Err(CarrierError::Unshared) => return,
            Err(why) => why,
        };
        let (at, value) = match (&why, raw.link) {
            (CarrierError::Ambiguous { .. }, _) | (_, None) => ("through", quoted(&guide.through)),
            (_, Some(l)) => ("link", l.to_string()),
        };
        self.check.push(join(key, at), Some(value), why.to_string());
    }

    /// A direction: degrees in the frame, or `{ from, to, angle }` along one link.
    pub(super) fn dir(&mut self, key: &str, raw: Option<&RawDir>) -> Dir {
        match raw {
            None => Dir::Fixed(0.0),
            Some(RawDir::Degrees(d)) => Dir::Fixed(self.check.angle(key, Some(*d), 0.0)),
            Some(RawDir::Along(a)) => {
                let (from, on_from) = self.point(&join(key, "from"), a.from.as_ref());
                let (to, on_to) = self.point(&join(key, "to"), a.to.as_ref());
                let shared = on_from.iter().any(|l| on_to.contains(l));
                if !on_from.is_empty() && !on_to.is_empty() && !shared {
                    let expected = format!("expected a point on the same link as {from:?}");
                    self.check
                        .push(join(key, "to"), Some(quoted(&to)), expected);
                }
                let angle = self.check.angle(&join(key, "angle"), a.angle, 0.0);
                Dir::Along { from, to, angle }
            }
        }
    }
}
