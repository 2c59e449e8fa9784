//! `[mechanism]` → [`Mechanism`]: fixed points, the crank, the Assur groups in file order
//! (`groups.rs`), the link points, redundant pairs, outputs and the mobility check
//! (`outputs.rs`). A point name may be used once
//! it is known: fixed points and the crank pin at once, a group's joint once its group is
//! attached, a `[[mechanism.point]]` once its link is attached.

use super::check::{item, join, number, quoted, Checker};
use super::raw::{RawCrank, RawMechanism, RawPoint};
use crate::geom::DVec2;
use crate::linkage::{Crank, FixedPoint, LinkPoint, Mechanism, Sense};

/// The fastest crank a scene may give, rad/s.
const MAX_OMEGA: f64 = 1e4;

/// The key path of the mechanism table.
pub(super) const MECH: &str = "mechanism";

/// A point that may be referenced: its name, the links it lies on (0: the frame), where it
/// was defined.
#[derive(Debug)]
pub(super) struct Known {
    pub(super) name: String,
    pub(super) links: Vec<u32>,
}

/// The state of the attachment: what is known so far.
pub(super) struct Builder<'a> {
    pub(super) check: &'a mut Checker,
    /// Points known so far, in order of becoming known.
    pub(super) known: Vec<Known>,
    /// Moving links attached so far, with the key that attached them.
    pub(super) links: Vec<(u32, String)>,
    /// The link points (validated), released when their link is attached.
    pub(super) points: Vec<LinkPoint>,
    /// Every name declared anywhere, with the key that declared it.
    pub(super) declared: Vec<(String, String)>,
    /// The links attached so far that translate ([`crate::linkage::Group::translating`]).
    pub(super) translating: Vec<u32>,
}

/// Validate `[mechanism]`; `None` when it is missing (reported).
pub(crate) fn mechanism(check: &mut Checker, raw: Option<&RawMechanism>) -> Option<Mechanism> {
    let raw = check.required(MECH, raw, "a [mechanism] table")?;
    let mut b = Builder {
        check,
        known: Vec::new(),
        links: Vec::new(),
        points: Vec::new(),
        declared: Vec::new(),
        translating: Vec::new(),
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
    let outputs = b.outputs(&raw.output, &groups);
    let m = Mechanism {
        fixed,
        crank: crank?,
        groups,
        points: std::mem::take(&mut b.points),
        redundant,
        outputs,
        driving: false,
    };
    b.mobility(&m);
    Some(m)
}

impl Builder<'_> {
    /// Record every declared name and report duplicates.
    pub(super) fn declare_all(&mut self, raw: &RawMechanism) {
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
    pub(super) fn fixed(&mut self, raw: &RawMechanism) -> Vec<FixedPoint> {
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
    pub(super) fn coordinates(&mut self, key: &str, v: Option<&Vec<f64>>) -> DVec2 {
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
    pub(super) fn crank(&mut self, raw: Option<&RawCrank>) -> Option<Crank> {
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
        let sense = self
            .check
            .word(
                &join(base, "sense"),
                raw.sense.as_ref(),
                &[("cw", Sense::Clockwise), ("ccw", Sense::CounterClockwise)],
            )
            .unwrap_or(Sense::CounterClockwise);
        self.attach(link, join(base, "link"), link.to_string());
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

    /// Whether `name` is a fixed point (held by the frame, whatever links pivot there).
    pub(super) fn is_fixed(&self, name: &str) -> bool {
        self.known
            .iter()
            .any(|k| k.name == name && k.links.contains(&0))
    }

    /// `omega` (rad/s) or `n` (rpm), exactly one of them.
    pub(super) fn omega(&mut self, base: &str, raw: &RawCrank) -> f64 {
        const WANT: &str = "0 < ω ≤ 1e4 rad/s";
        let max_n = crate::scale::to_rpm(MAX_OMEGA);
        match (raw.omega, raw.n) {
            (Some(w), None) => self
                .check
                .in_range(&join(base, "omega"), w, MAX_OMEGA, WANT),
            (None, Some(n)) => {
                let key = join(base, "n");
                let n = self.check.in_range(&key, n, max_n, "0 < n ≤ 95 493 rpm");
                crate::scale::from_rpm(n)
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
    pub(super) fn link_points(&mut self, raw: &[RawPoint]) -> Vec<LinkPoint> {
        let mut out = Vec::new();
        for (i, p) in raw.iter().enumerate() {
            let base = item("mechanism.point", i);
            let name = self.check.name(&join(&base, "name"), p.name.as_ref());
            let link_key = join(&base, "link");
            let link = self
                .check
                .required(&link_key, p.link, "a link number 1 … 99");
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
    pub(super) fn unattached_points(&mut self) {
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
    pub(super) fn attach(&mut self, link: u32, key: String, value: String) {
        if let Some((_, first)) = self.links.iter().find(|(l, _)| *l == link) {
            let expected = format!("expected a new link number; link {link} is already {first}");
            self.check.push(key, Some(value), expected);
            return;
        }
        self.links.push((link, key));
        self.release(link);
    }

    /// Make the points of `link` known.
    pub(super) fn release(&mut self, link: u32) {
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
    pub(super) fn know(&mut self, name: &str, links: &[u32]) {
        if !name.is_empty() && !self.known.iter().any(|k| k.name == name) {
            self.known.push(Known {
                name: name.to_string(),
                links: links.to_vec(),
            });
        }
    }

    /// A known point is also on `link` (an outer pair of a group: the group's link turns
    /// about it), so a later direction may run from it along that link.
    pub(super) fn also_on(&mut self, name: &str, link: u32) {
        if let Some(k) = self.known.iter_mut().find(|k| k.name == name) {
            if !k.links.contains(&link) {
                k.links.push(link);
            }
        }
    }

    /// The names known so far, for messages.
    pub(super) fn known_names(&self) -> String {
        let names: Vec<&str> = self.known.iter().map(|k| k.name.as_str()).collect();
        format!("known here: {}", names.join(", "))
    }

    /// A reference to a known point: its name and links (empty when unknown; reported).
    pub(super) fn point(&mut self, key: &str, v: Option<&String>) -> (String, Vec<u32>) {
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
}
