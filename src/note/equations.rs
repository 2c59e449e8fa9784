//! The vector equations of the plans as the note writes them: each group's two equations of
//! velocities, their counterparts of accelerations (the relative term split by how the point
//! moves), the vectors with their arrows, and under each group's equations the table of what
//! is known and unknown of every vector in magnitude and direction (seed 000 §1.3.1: «у Vb1 –
//! величина и направление, у Vb3b1 – направление …»).

use super::markup::{inline, label, sym, text, Align, Cell};
use super::Writer;
use crate::linkage::{DyadKind, GroupInfo, Mechanism};
use crate::scale::Lang;
use crate::words::{plain, KinematicsNote as K, NoteText as T};

/// A point as an equation names it (`B_{3}`) and the mechanism's point it is (`B`).
type Named = (String, String);

/// The point of link `link` under the mechanism's point `name`, as the plans name it:
/// `B_{3}`.
fn on(name: &str, link: u32) -> Named {
    let plain = plain(name);
    (
        format!("{}_{{{}{link}}}", &plain[..1], &plain[1..]),
        name.to_string(),
    )
}

/// A point of one link: its own name.
fn own(name: &str) -> Named {
    (name.to_string(), name.to_string())
}

/// How the point of an equation moves relative to its reference point, which decides the
/// parts its relative acceleration splits into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Relative {
    /// Both on one turning link: normal and tangential parts.
    Turn,
    /// Sliding along a moving link: Coriolis and relative parts.
    Slide,
    /// Sliding along the frame's guide: the relative part alone.
    SlideOnFrame,
}

/// One vector equation of a velocity plan: the point, the point it is referred to (plain
/// names, `B3`, `B1`), the line its relative term lies on or across (label markup), how that
/// term moves and the link it turns or slides with.
pub(super) struct Equation {
    pub(super) point: String,
    pub(super) reference: String,
    pub(super) line: String,
    pub(super) relative: Relative,
    pub(super) link: u32,
    /// The mechanism's names of the point and of the reference point (`B`, `C`).
    pub(super) names: (String, String),
}

impl Equation {
    fn new(
        (point, reference): (&Named, &Named),
        line: String,
        relative: Relative,
        link: u32,
    ) -> Self {
        Self {
            point: plain(&point.0),
            reference: plain(&reference.0),
            line,
            relative,
            link,
            names: (point.1.clone(), reference.1.clone()),
        }
    }

    /// The relative term's subscript: `B3B1`.
    pub(super) fn pair(&self) -> String {
        format!("{}{}", self.point, self.reference)
    }

    /// The terms of the acceleration's counterpart, its relative term split into its normal
    /// and tangential parts (one turning link), its Coriolis and relative parts (a slide
    /// along a moving link) or its relative part alone (a slide along the frame).
    fn acceleration_terms(&self) -> Vec<String> {
        let sub = format!("{{{}}}", self.pair());
        let mut terms = vec![
            format!("a_{{{}}}", self.point),
            format!("a_{{{}}}", self.reference),
        ];
        match self.relative {
            Relative::Turn => terms.extend([format!("a^{{n}}_{sub}"), format!("a^{{τ}}_{sub}")]),
            Relative::Slide => terms.extend([format!("a^{{k}}_{sub}"), format!("a^{{r}}_{sub}")]),
            Relative::SlideOnFrame => terms.push(format!("a^{{r}}_{sub}")),
        }
        terms
    }

    /// `a_{B3} = a_{B1} + a^{k}_{B3B1} + a^{r}_{B3B1}` (label markup).
    #[cfg(test)]
    fn acceleration(&self) -> String {
        let t = self.acceleration_terms();
        format!("{} = {}", t[0], t[1..].join(" + "))
    }

    /// The terms of the velocity equation.
    fn velocity_terms(&self) -> Vec<String> {
        vec![
            format!("V_{{{}}}", self.point),
            format!("V_{{{}}}", self.reference),
            format!("V_{{{}}}", self.pair()),
        ]
    }
}

/// The two vector equations of a group's velocity plan.
pub(super) fn velocity_equations(g: &GroupInfo, lang: Lang) -> Vec<Equation> {
    let [p0, p1, p2] = &g.pairs;
    let [i, j] = g.links;
    let along = |link: u32| format!("{} {link}", T::AlongGuideOf.get(lang));
    let slide = |link: u32| match link {
        0 => Relative::SlideOnFrame,
        _ => Relative::Slide,
    };
    let turn = Relative::Turn;
    match g.kind {
        DyadKind::Rrr => {
            let (a, joint, b) = (own(&p0.name), own(&p1.name), own(&p2.name));
            vec![
                Equation::new((&joint, &a), format!("{}{}", a.0, joint.0), turn, i),
                Equation::new((&joint, &b), format!("{}{}", b.0, joint.0), turn, j),
            ]
        }
        DyadKind::Rrp => {
            let (a, joint) = (own(&p0.name), own(&p1.name));
            let g1 = p2.links[1];
            let guide = on(&p1.name, g1);
            vec![
                Equation::new((&joint, &a), format!("{}{}", a.0, joint.0), turn, i),
                Equation::new((&joint, &guide), along(g1), slide(g1), g1),
            ]
        }
        DyadKind::Rpr => {
            let (a, c) = (&p0.name, own(&p2.name));
            let (aj, ao) = (on(a, j), on(a, p0.links[0]));
            vec![
                Equation::new((&aj, &ao), format!("{}{a}", c.0), slide(j), j),
                Equation::new((&aj, &c), format!("{}{a}", c.0), turn, j),
            ]
        }
        DyadKind::Prp => {
            let joint = own(&p1.name);
            let (l0, l2) = (p0.links[0], p2.links[1]);
            let (gi, gj) = (on(&p1.name, l0), on(&p1.name, l2));
            vec![
                Equation::new((&joint, &gi), along(l0), slide(l0), l0),
                Equation::new((&joint, &gj), along(l2), slide(l2), l2),
            ]
        }
        DyadKind::Rpp => {
            let a = &p0.name;
            let l2 = p2.links[1];
            let (aj, ao) = (on(a, j), on(a, p0.links[0]));
            let g0 = on(a, l2);
            vec![
                Equation::new((&aj, &ao), along(j), slide(j), j),
                Equation::new((&aj, &g0), along(l2), slide(l2), l2),
            ]
        }
    }
}

/// A vector of an equation in formula markup, the arrow over its letter: `V_{B3}` →
/// `arrow(V)_(B3)`.
pub(super) fn vector(markup: &str) -> String {
    let s = sym(markup);
    match s.find(['_', '^']) {
        Some(at) => format!("arrow({}){}", &s[..at], &s[at..]),
        None => format!("arrow({s})"),
    }
}

/// An equation of label markup `a = b + c` in formula markup with the vectors' arrows.
fn vector_equation(terms: &[String]) -> String {
    let v: Vec<String> = terms.iter().map(|t| vector(t)).collect();
    format!("{} = {}", v[0], v[1..].join(" + "))
}

/// Which plan.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// Velocities.
    Velocity,
    /// Accelerations.
    Acceleration,
}

/// What the mechanism tells of a reference point before its group is drawn.
enum Reference {
    /// The crank's pin: its vector from ω₁ and l_AB.
    Crank,
    /// A point of the frame: zero.
    Fixed,
    /// Found on the plan of an earlier group.
    Found,
}

fn reference(m: &Mechanism, name: &str) -> Reference {
    let pin = plain(&m.crank.pin);
    if name == pin || name == format!("{pin}{}", m.crank.link) {
        Reference::Crank
    } else if m.fixed.iter().any(|f| plain(&f.name) == name) || name.ends_with('0') {
        Reference::Fixed
    } else {
        Reference::Found
    }
}

/// A product of symbols (label markup) as a cell's formula: `ω₁ l_AB`.
fn product(factors: &[&str]) -> Cell {
    let math: Vec<String> = factors.iter().map(|f| sym(f)).collect();
    inline(&math.join(" "))
}

/// The magnitude and direction cells of one term of an equation.
fn known(w: &Writer<'_, '_>, m: &Mechanism, e: &Equation, term: &str, kind: Kind) -> [Cell; 2] {
    let unknown = || [text("?"), text("?")];
    let crank = super::positions::crank_length(m);
    let (centre, pin) = (plain(&m.crank.centre), plain(&m.crank.pin));
    let pair = e.pair();
    let rp = format!("{}{}", plain(&e.names.1), plain(&e.names.0));
    if term.ends_with(&format!("{{{}}}", e.point)) && !term.contains(&pair) {
        return unknown();
    }
    if term.ends_with(&format!("{{{}}}", e.reference)) {
        return match (reference(m, &e.reference), kind) {
            (Reference::Crank, Kind::Velocity) => [
                product(&["ω_{1}", &crank]),
                label(&format!("⊥ {centre}{pin}")),
            ],
            (Reference::Crank, Kind::Acceleration) => [
                product(&["ω_{1}^{2}", &crank]),
                label(&format!("∥ {pin}{centre}")),
            ],
            (Reference::Fixed, _) => [text("0"), text("—")],
            (Reference::Found, _) => [text(w.word(K::FromPlan)), text(w.word(K::FromPlan))],
        };
    }
    let j = e.link;
    let across = label(&format!("⊥ {}", e.line));
    let parallel = label(&format!("∥ {}", e.line));
    match (kind, e.relative) {
        (Kind::Velocity, Relative::Turn) => [text("?"), across],
        (Kind::Velocity, _) => [text("?"), parallel],
        (Kind::Acceleration, Relative::Turn) if term.starts_with("a^{n}") => [
            product(&[&format!("ω_{{{j}}}^{{2}}"), &format!("l_{{{rp}}}")]),
            label(&format!(
                "∥ {}, {} {}",
                e.line,
                w.word(K::Towards),
                e.reference
            )),
        ],
        (Kind::Acceleration, Relative::Slide) if term.starts_with("a^{k}") => [
            product(&["2", &format!("ω_{{{j}}}"), &format!("V_{{{pair}}}")]),
            across,
        ],
        (Kind::Acceleration, Relative::Turn) => [text("?"), across],
        (Kind::Acceleration, _) => [text("?"), parallel],
    }
}

/// Each group's two equations of `kind` with their vectors' arrows, and under them the table
/// of what is known of each vector.
pub(super) fn equations(w: &mut Writer<'_, '_>, m: &Mechanism, groups: &[GroupInfo], kind: Kind) {
    let lang = w.lang;
    for g in groups {
        let eqs = velocity_equations(g, lang);
        w.doc.par(&[text(&format!(
            "{} ({}, {}):",
            w.word(crate::words::Text::Group),
            g.links[0],
            g.links[1]
        ))]);
        let mut rows: Vec<Vec<Cell>> = Vec::new();
        let mut seen: Vec<String> = Vec::new();
        for e in &eqs {
            let terms = match kind {
                Kind::Velocity => e.velocity_terms(),
                Kind::Acceleration => e.acceleration_terms(),
            };
            w.doc.par(&[inline(&vector_equation(&terms))]);
            for t in &terms {
                if seen.contains(t) {
                    continue;
                }
                seen.push(t.clone());
                let [size, direction] = known(w, m, e, t, kind);
                rows.push(vec![inline(&vector(t)), size, direction]);
            }
        }
        let caption = format!(
            "{} ({}, {})",
            w.word(match kind {
                Kind::Velocity => K::KnownVelocities,
                Kind::Acceleration => K::KnownAccelerations,
            }),
            g.links[0],
            g.links[1]
        );
        let header = [
            text(w.word(K::Vector)),
            text(w.word(K::Magnitude)),
            text(w.word(K::Direction)),
        ];
        w.doc.table(
            &caption,
            &[Align::Centre, Align::Centre, Align::Left],
            &header,
            &rows,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linkage::Structure;

    /// The shaper's groups: a slide along the turning rocker 3 has a Coriolis part, a slide
    /// along the frame's guide the relative part alone, a turn its normal and tangential
    /// parts.
    #[test]
    fn each_relative_acceleration_splits_by_how_its_point_moves() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/shaper.toml");
        let scene = crate::scene::load(&path).expect("shaper");
        let m = scene.mechanism.as_ref().expect("mechanism");
        let s = Structure::analyse(m);
        let equations: Vec<String> = s
            .groups
            .iter()
            .flat_map(|g| velocity_equations(g, Lang::Ru))
            .map(|e| e.acceleration())
            .collect();
        assert_eq!(
            equations,
            [
                "a_{B3} = a_{B1} + a^{k}_{B3B1} + a^{r}_{B3B1}",
                "a_{B3} = a_{C} + a^{n}_{B3C} + a^{τ}_{B3C}",
                "a_{D5} = a_{D3} + a^{k}_{D5D3} + a^{r}_{D5D3}",
                "a_{D5} = a_{D0} + a^{r}_{D5D0}",
            ]
        );
        // The mechanism's points under the plans' names.
        let names: Vec<(String, String)> = s
            .groups
            .iter()
            .flat_map(|g| velocity_equations(g, Lang::Ru))
            .map(|e| e.names)
            .collect();
        assert_eq!(names[1], ("B".to_string(), "C".to_string()));
        assert_eq!(names[2], ("D".to_string(), "D".to_string()));
    }
}
