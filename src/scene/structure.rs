//! `[mechanism]` → [`Mechanism`]: fixed points, the crank, the Assur groups in file order, the
//! link points, redundant pairs, outputs and the mobility check. A point name may be used once
//! it is known: fixed points and the crank pin at once, a group's joint once its group is
//! attached, a `[[mechanism.point]]` once its link is attached.

use super::check::{item, join, number, one_of, quoted, Checker};
use super::raw::{RawCrank, RawDir, RawGroup, RawGuide, RawMechanism, RawOutput, RawPoint};
use crate::geom::DVec2;
use crate::linkage::{
    Branch, Crank, Dir, Dyad, DyadKind, FixedPoint, Group, Guide, LinkPoint, Mechanism, Output,
    RedundantPair, Sense,
};

/// The key path of the mechanism table.
const MECH: &str = "mechanism";

/// The five kinds, Latin and Cyrillic letters accepted.
const KINDS: [DyadKind; 5] = [
    DyadKind::Rrr,
    DyadKind::Rrp,
    DyadKind::Rpr,
    DyadKind::Prp,
    DyadKind::Rpp,
];

/// A lower pair of the structure: its kind, one link and the links the other element may be.
#[derive(Debug)]
struct Pair {
    prismatic: bool,
    link: u32,
    other: Vec<u32>,
}

/// A point that may be referenced: its name, the links it lies on (0: the frame), where it
/// was defined.
#[derive(Debug)]
struct Known {
    name: String,
    links: Vec<u32>,
}

/// The state of the attachment: what is known so far.
struct Builder<'a> {
    check: &'a mut Checker,
    /// Points known so far, in order of becoming known.
    known: Vec<Known>,
    /// Moving links attached so far, with the key that attached them.
    links: Vec<(u32, String)>,
    /// The lower pairs so far.
    pairs: Vec<Pair>,
    /// The link points (validated), released when their link is attached.
    points: Vec<LinkPoint>,
    /// Every name declared anywhere, with the key that declared it.
    declared: Vec<(String, String)>,
}

/// Validate `[mechanism]`; `None` when it is missing (reported).
pub(crate) fn mechanism(check: &mut Checker, raw: Option<&RawMechanism>) -> Option<Mechanism> {
    let raw = check.required(MECH, raw, "a [mechanism] table")?;
    let mut b = Builder {
        check,
        known: Vec::new(),
        links: Vec::new(),
        pairs: Vec::new(),
        points: Vec::new(),
        declared: Vec::new(),
    };
    b.declare_all(raw);
    let fixed = b.fixed(raw);
    let crank = b.crank(raw.crank.as_ref());
    b.points = b.link_points(&raw.point);
    // The crank was attached before its points were read: release them now.
    if let Some(c) = &crank {
        b.release(c.link);
    }
    let groups = b.groups(&raw.group);
    b.unattached_points();
    let redundant = b.redundant(raw);
    let outputs = b.outputs(&raw.output);
    b.mobility(&redundant);
    Some(Mechanism {
        fixed,
        crank: crank?,
        groups,
        points: b.points,
        redundant,
        outputs,
    })
}

impl Builder<'_> {
    /// Record every declared name and report duplicates.
    fn declare_all(&mut self, raw: &RawMechanism) {
        let fixed = raw
            .fixed
            .iter()
            .enumerate()
            .map(|(i, f)| ("fixed", i, "name", &f.name));
        let joints = raw
            .group
            .iter()
            .enumerate()
            .map(|(i, g)| ("group", i, "joint", &g.joint));
        let points = raw
            .point
            .iter()
            .enumerate()
            .map(|(i, p)| ("point", i, "name", &p.name));
        let mut all: Vec<(String, &Option<String>)> = fixed
            .chain(joints)
            .chain(points)
            .map(|(t, i, k, n)| (join(&item(&join(MECH, t), i), k), n))
            .collect();
        if let Some(c) = &raw.crank {
            all.insert(raw.fixed.len(), ("mechanism.crank.pin".into(), &c.pin));
        }
        for (key, name) in all {
            let Some(name) = name else { continue };
            if let Some((_, first)) = self.declared.iter().find(|(n, _)| n == name) {
                let expected = format!("expected a new point name; it is already {first}");
                self.check.push(&key, Some(quoted(name)), expected);
            } else {
                self.declared.push((name.clone(), key));
            }
        }
    }

    /// `[[mechanism.fixed]]`.
    fn fixed(&mut self, raw: &RawMechanism) -> Vec<FixedPoint> {
        let mut out = Vec::new();
        for (i, f) in raw.fixed.iter().enumerate() {
            let base = item("mechanism.fixed", i);
            let name = self.check.name(&join(&base, "name"), f.name.as_ref());
            let at = self.coordinates(&join(&base, "at"), f.at.as_ref());
            self.know(&name, &[0]);
            out.push(FixedPoint { name, at });
        }
        out
    }

    /// `at = [x, y]` in mm → m.
    fn coordinates(&mut self, key: &str, v: Option<&Vec<f64>>) -> DVec2 {
        match self.check.required(key, v, "[x, y] in mm") {
            Some(xy) if xy.len() == 2 => DVec2::new(
                self.check.coordinate(key, xy[0]),
                self.check.coordinate(key, xy[1]),
            ),
            Some(xy) => {
                let shown: Vec<String> = xy.iter().map(|v| number(*v)).collect();
                let value = format!("[{}]", shown.join(", "));
                self.check
                    .push(key, Some(value), "expected two coordinates [x, y] in mm");
                DVec2::ZERO
            }
            None => DVec2::ZERO,
        }
    }

    /// `[mechanism.crank]`.
    fn crank(&mut self, raw: Option<&RawCrank>) -> Option<Crank> {
        let base = "mechanism.crank";
        let raw = self
            .check
            .required(base, raw, "a [mechanism.crank] table")?;
        let link = self
            .check
            .link(&join(base, "link"), raw.link.unwrap_or(1), 1)
            .unwrap_or(1);
        let centre = self.check.name(&join(base, "centre"), raw.centre.as_ref());
        if !centre.is_empty() && !self.is_fixed(&centre) {
            let expected = format!("expected a fixed point ({})", self.known_names());
            self.check
                .push(join(base, "centre"), Some(quoted(&centre)), expected);
        }
        let pin = self.check.name(&join(base, "pin"), raw.pin.as_ref());
        let length = self.check.length(&join(base, "length"), raw.length);
        let omega = self.omega(base, raw);
        let sense = match self
            .check
            .word(&join(base, "sense"), raw.sense.as_ref(), &["cw", "ccw"])
        {
            Some(0) => Sense::Clockwise,
            _ => Sense::CounterClockwise,
        };
        self.attach(link, join(base, "link"), link.to_string());
        self.pairs.push(Pair {
            prismatic: false,
            link,
            other: vec![0],
        });
        self.know(&pin, &[link]);
        Some(Crank {
            link,
            centre,
            pin,
            length,
            omega,
            sense,
        })
    }

    /// Whether `name` is a fixed point.
    fn is_fixed(&self, name: &str) -> bool {
        self.known.iter().any(|k| k.name == name && k.links == [0])
    }

    /// `omega` (rad/s) or `n` (rpm), exactly one of them.
    fn omega(&mut self, base: &str, raw: &RawCrank) -> f64 {
        const WANT: &str = "ω > 0 rad/s";
        match (raw.omega, raw.n) {
            (Some(w), None) => self.check.positive(&join(base, "omega"), w, WANT),
            (None, Some(n)) => {
                let n = self.check.positive(&join(base, "n"), n, "n > 0 rpm");
                std::f64::consts::PI * n / 30.0
            }
            (Some(w), Some(n)) => {
                let value = format!("{}, n = {}", number(w), number(n));
                let expected = "expected either omega (rad/s) or n (rpm), not both";
                self.check.push(join(base, "omega"), Some(value), expected);
                0.0
            }
            (None, None) => {
                let expected = "missing: expected omega (rad/s) or n (rpm)";
                self.check.push(join(base, "omega"), None, expected);
                0.0
            }
        }
    }

    /// `[[mechanism.point]]`, validated (availability is checked as links attach).
    fn link_points(&mut self, raw: &[RawPoint]) -> Vec<LinkPoint> {
        let mut out = Vec::new();
        for (i, p) in raw.iter().enumerate() {
            let base = item("mechanism.point", i);
            let name = self.check.name(&join(&base, "name"), p.name.as_ref());
            let link_key = join(&base, "link");
            let link = self.check.required(&link_key, p.link, "a link number ≥ 1");
            let link = link
                .and_then(|l| self.check.link(&link_key, l, 1))
                .unwrap_or(0);
            let along_key = join(&base, "along");
            let along = self.check.required(&along_key, p.along, "a distance in mm");
            let along = along.map_or(0.0, |v| self.check.distance(&along_key, Some(v), 0.0));
            let across = self.check.distance(&join(&base, "across"), p.across, 0.0);
            out.push(LinkPoint {
                name,
                link,
                along,
                across,
            });
        }
        out
    }

    /// Points whose link was never attached.
    fn unattached_points(&mut self) {
        let attached: Vec<u32> = self.links.iter().map(|(l, _)| *l).collect();
        for (i, p) in self.points.iter().enumerate() {
            if p.link != 0 && !attached.contains(&p.link) {
                let key = join(&item("mechanism.point", i), "link");
                let expected = format!("expected a moving link of the mechanism ({attached:?})");
                self.check.push(key, Some(p.link.to_string()), expected);
            }
        }
    }

    /// Mark `link` attached (refusing one already used) and release its points.
    fn attach(&mut self, link: u32, key: String, value: String) {
        if let Some((_, first)) = self.links.iter().find(|(l, _)| *l == link) {
            let expected = format!("expected a new link number; link {link} is already {first}");
            self.check.push(key, Some(value), expected);
            return;
        }
        self.links.push((link, key));
        self.release(link);
    }

    /// Make the points of `link` known.
    fn release(&mut self, link: u32) {
        let released: Vec<String> = self
            .points
            .iter()
            .filter(|p| p.link == link)
            .map(|p| p.name.clone())
            .collect();
        for name in released {
            self.know(&name, &[link]);
        }
    }

    /// Make a point known on `links`.
    fn know(&mut self, name: &str, links: &[u32]) {
        if !name.is_empty() && !self.known.iter().any(|k| k.name == name) {
            self.known.push(Known {
                name: name.to_string(),
                links: links.to_vec(),
            });
        }
    }

    /// The names known so far, for messages.
    fn known_names(&self) -> String {
        let names: Vec<&str> = self.known.iter().map(|k| k.name.as_str()).collect();
        format!("known here: {}", names.join(", "))
    }

    /// A reference to a known point: its name and links (empty when unknown; reported).
    fn point(&mut self, key: &str, v: Option<&String>) -> (String, Vec<u32>) {
        let name = self.check.name(key, v);
        if name.is_empty() {
            return (name, Vec::new());
        }
        if let Some(k) = self.known.iter().find(|k| k.name == name) {
            return (name, k.links.clone());
        }
        let later = match self.declared.iter().find(|(n, _)| *n == name) {
            Some((_, at)) => format!("; it is {at}, not attached yet at this group"),
            None => String::new(),
        };
        let expected = format!(
            "expected a known point: a fixed point, the crank pin, a joint of an earlier group \
             or a point of an attached link ({}){later}",
            self.known_names()
        );
        self.check.push(key, Some(quoted(&name)), expected);
        (name, Vec::new())
    }

    /// `[[mechanism.group]]` in file order.
    fn groups(&mut self, raw: &[RawGroup]) -> Vec<Group> {
        let mut out = Vec::new();
        for (i, g) in raw.iter().enumerate() {
            if let Some(group) = self.group(&item("mechanism.group", i), g) {
                out.push(group);
            }
        }
        out
    }

    /// One group; `None` when its kind or links cannot be told (reported).
    fn group(&mut self, base: &str, g: &RawGroup) -> Option<Group> {
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
        Some(Group {
            links: [i, j],
            dyad,
        })
    }

    /// `kind = "RRR"` … (case-insensitive, Cyrillic accepted).
    fn kind(&mut self, key: &str, v: Option<&String>) -> Option<DyadKind> {
        let words: Vec<&str> = KINDS.iter().map(|k| k.letters()).collect();
        let s = self.check.required(key, v, &one_of(&words))?;
        let upper = s.to_uppercase();
        let found = KINDS
            .into_iter()
            .find(|k| k.letters() == upper || k.letters_ru() == upper);
        if found.is_none() {
            let expected = format!("expected {} (or ВВВ, ВВП, ВПВ, ПВП, ВПП)", one_of(&words));
            self.check.push(key, Some(quoted(s)), expected);
        }
        found
    }

    /// Report the keys that belong to other kinds.
    fn refuse_foreign_keys(&mut self, base: &str, kind: DyadKind, g: &RawGroup) {
        let allowed = keys_of(kind);
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

    /// Record the three pairs of a group: outer at `a`, inner, outer at `b`.
    fn pairs3(&mut self, links: [u32; 2], outer: [(bool, &[u32]); 2], inner_prismatic: bool) {
        let [i, j] = links;
        let [(pa, la), (pb, lb)] = outer;
        self.pairs.push(Pair {
            prismatic: pa,
            link: i,
            other: la.to_vec(),
        });
        self.pairs.push(Pair {
            prismatic: inner_prismatic,
            link: i,
            other: vec![j],
        });
        self.pairs.push(Pair {
            prismatic: pb,
            link: j,
            other: lb.to_vec(),
        });
    }

    /// The new joint of a group, known on `links` from now on.
    fn joint(&mut self, base: &str, g: &RawGroup, links: &[u32]) -> String {
        let joint = self.check.name(&join(base, "joint"), g.joint.as_ref());
        self.know(&joint, links);
        joint
    }

    /// Kind 1, RRR.
    fn rrr(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, on_a) = self.point(&join(base, "a"), g.a.as_ref());
        let la = self.check.length(&join(base, "la"), g.la);
        let (b, on_b) = self.point(&join(base, "b"), g.b.as_ref());
        let lb = self.check.length(&join(base, "lb"), g.lb);
        let branch = self.branch(base, g, DyadKind::Rrr);
        self.pairs3(links, [(false, &on_a), (false, &on_b)], false);
        let joint = self.joint(base, g, &links);
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
    fn rrp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, on_a) = self.point(&join(base, "a"), g.a.as_ref());
        let la = self.check.length(&join(base, "la"), g.la);
        let (guide, carrier) = self.guide(&join(base, "guide"), g.guide.as_ref());
        let branch = self.branch(base, g, DyadKind::Rrp);
        self.pairs3(links, [(false, &on_a), (true, &carrier)], false);
        let joint = self.joint(base, g, &links);
        Dyad::Rrp {
            a,
            la,
            guide,
            joint,
            branch,
        }
    }

    /// Kind 3, RPR.
    fn rpr(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, on_a) = self.point(&join(base, "a"), g.a.as_ref());
        let (c, on_c) = self.point(&join(base, "c"), g.c.as_ref());
        let offset = self.check.distance(&join(base, "offset"), g.offset, 0.0);
        self.pairs3(links, [(false, &on_a), (false, &on_c)], true);
        Dyad::Rpr { a, c, offset }
    }

    /// Kind 4, PRP.
    fn prp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (guide_i, on_i) = self.guide(&join(base, "guide_i"), g.guide_i.as_ref());
        let (guide_j, on_j) = self.guide(&join(base, "guide_j"), g.guide_j.as_ref());
        self.pairs3(links, [(true, &on_i), (true, &on_j)], false);
        let joint = self.joint(base, g, &links);
        Dyad::Prp {
            guide_i,
            guide_j,
            joint,
        }
    }

    /// Kind 5, RPP.
    fn rpp(&mut self, base: &str, g: &RawGroup, links: [u32; 2]) -> Dyad {
        let (a, on_a) = self.point(&join(base, "a"), g.a.as_ref());
        let slide_key = join(base, "slide");
        let slide = self
            .check
            .required(&slide_key, g.slide.as_ref(), "a direction");
        let slide = self.dir(&slide_key, slide);
        let (guide, carrier) = self.guide(&join(base, "guide"), g.guide.as_ref());
        self.pairs3(links, [(false, &on_a), (true, &carrier)], true);
        let joint = self.joint(base, g, &links[1..]);
        Dyad::Rpp {
            a,
            slide,
            guide,
            joint,
        }
    }

    /// `branch`: left/right for RRR, forward/backward for RRP.
    fn branch(&mut self, base: &str, g: &RawGroup, kind: DyadKind) -> Branch {
        let (words, branches) = match kind {
            DyadKind::Rrr => (["left", "right"], [Branch::Left, Branch::Right]),
            _ => (["forward", "backward"], [Branch::Forward, Branch::Backward]),
        };
        let found = self
            .check
            .word(&join(base, "branch"), g.branch.as_ref(), &words);
        found.map_or(branches[0], |k| branches[k])
    }

    /// A guide and the links of the point it passes through (its carrier).
    fn guide(&mut self, key: &str, raw: Option<&RawGuide>) -> (Guide, Vec<u32>) {
        let Some(raw) = self
            .check
            .required(key, raw, "a guide { through, dir, offset }")
        else {
            let guide = Guide {
                through: String::new(),
                dir: Dir::Fixed(0.0),
                offset: 0.0,
            };
            return (guide, Vec::new());
        };
        let (through, carrier) = self.point(&join(key, "through"), raw.through.as_ref());
        let dir_key = join(key, "dir");
        let dir = self
            .check
            .required(&dir_key, raw.dir.as_ref(), "a direction");
        let dir = self.dir(&dir_key, dir);
        let offset = self.check.distance(&join(key, "offset"), raw.offset, 0.0);
        (
            Guide {
                through,
                dir,
                offset,
            },
            carrier,
        )
    }

    /// A direction: degrees in the frame, or `{ from, to, angle }` along one link.
    fn dir(&mut self, key: &str, raw: Option<&RawDir>) -> Dir {
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

    /// `[[mechanism.redundant]]`.
    fn redundant(&mut self, raw: &RawMechanism) -> Vec<RedundantPair> {
        let mut out = Vec::new();
        for (i, r) in raw.redundant.iter().enumerate() {
            let base = item("mechanism.redundant", i);
            let name = self.check.name(&join(&base, "name"), r.name.as_ref());
            let kind =
                self.check
                    .word(&join(&base, "kind"), r.kind.as_ref(), &["R", "P", "В", "П"]);
            let links_key = join(&base, "links");
            let links = self.check.link_pair(&links_key, r.links.as_ref(), 0);
            let links = links
                .map(|l| self.existing_links(&links_key, l))
                .unwrap_or([0, 0]);
            let reason = r.reason.clone().unwrap_or_default();
            let prismatic = matches!(kind, Some(1 | 3));
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
    fn existing_links(&mut self, key: &str, links: [u32; 2]) -> [u32; 2] {
        for l in links {
            self.existing_link(key, l, 0);
        }
        links
    }

    /// `link` is the frame (when `min` is 0) or an attached moving link; reported otherwise.
    fn existing_link(&mut self, key: &str, link: u32, min: u32) -> bool {
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
    fn outputs(&mut self, raw: &[RawOutput]) -> Vec<Output> {
        if raw.is_empty() {
            let expected = "missing: expected at least one [[mechanism.output]] (rocker = N or slider = \"E\")";
            self.check.push("mechanism.output", None, expected);
        }
        let mut out = Vec::new();
        for (i, o) in raw.iter().enumerate() {
            if let Some(output) = self.output(&item("mechanism.output", i), o) {
                out.push(output);
            }
        }
        out
    }

    /// One output: `rocker = N` or `slider = "E"` with `dir`.
    fn output(&mut self, base: &str, o: &RawOutput) -> Option<Output> {
        match (o.rocker, &o.slider) {
            (Some(link), None) => {
                let key = join(base, "rocker");
                let link = self.check.link(&key, link, 1)?;
                self.existing_link(&key, link, 1)
                    .then_some(Output::Rocker { link })
            }
            (None, Some(_)) => {
                let (point, _) = self.point(&join(base, "slider"), o.slider.as_ref());
                let dir = self.check.angle(&join(base, "dir"), o.dir, 0.0);
                Some(Output::Slider { point, dir })
            }
            _ => {
                let expected = "expected exactly one of rocker = N or slider = \"E\"";
                self.check.push(base, None, expected);
                None
            }
        }
    }

    /// W = 3n − 2p₅ = 1, counting a redundant pair only where it repeats a pair of the
    /// structure. Checked only when the structure itself is valid (no noise after errors).
    fn mobility(&mut self, redundant: &[RedundantPair]) {
        if !self.check.problems.is_empty() {
            return;
        }
        let n = self.links.len() as i64;
        let p5 = (self.pairs.len() + redundant.len()) as i64;
        let repeats = |r: &RedundantPair| {
            let [x, y] = r.links;
            self.pairs.iter().any(|p| {
                p.prismatic == r.prismatic
                    && ((p.link == x && p.other.contains(&y))
                        || (p.link == y && p.other.contains(&x)))
            })
        };
        let mut stray = Vec::new();
        let mut discounted = 0;
        for (i, r) in redundant.iter().enumerate() {
            if repeats(r) {
                discounted += 1;
            } else {
                stray.push(format!(
                    "mechanism.redundant[{i}] ({:?}, links {:?})",
                    r.name, r.links
                ));
            }
        }
        let w = 3 * n - 2 * (p5 - discounted);
        if w != 1 {
            let expected = format!(
                "W = 3·{n} − 2·({p5} − {discounted}) = {w}: expected W = 1 (one driving crank); a redundant pair is discounted only where it \
                 repeats a pair of the structure, and {} repeats none",
                stray.join(", ")
            );
            self.check.push(MECH, None, expected);
        }
    }
}

/// The keys of a group of `kind`, besides `kind` itself.
fn keys_of(kind: DyadKind) -> &'static [&'static str] {
    match kind {
        DyadKind::Rrr => &["links", "a", "la", "b", "lb", "joint", "branch"],
        DyadKind::Rrp => &["links", "a", "la", "guide", "joint", "branch"],
        DyadKind::Rpr => &["links", "a", "c", "offset"],
        DyadKind::Prp => &["links", "guide_i", "guide_j", "joint"],
        DyadKind::Rpp => &["links", "a", "slide", "guide", "joint"],
    }
}
