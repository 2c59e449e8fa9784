//! The data of a task as its sheets and its note print them: symbol (label markup), value
//! and unit of the mechanism (lengths, ω₁) and of the force analysis (masses, moments of
//! inertia, working resistances). One place for the note's task tables and the task sheet
//! of `tmm batch`.

use crate::forces::{Action, ForceSpec};
use crate::gears::GearsSpec;
use crate::linkage::Mechanism;
use crate::plate::Plate;
use crate::scale::Lang;
use crate::words::md_value as fmt;
use crate::words::{mm, plain, unit_in};
use crate::words::{GearText, NoteText, Text};

/// One line of data: symbol (label markup), value, unit (as `unit_in` takes it).
pub type DataRow = (String, String, String);

/// What a length of the mechanism is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Span {
    /// The crank.
    Crank,
    /// A link of a group between two of its pairs.
    Link,
    /// A further point of a link from the link's origin.
    Point,
    /// Two fixed points.
    Fixed,
    /// A slide line's distance from the point it is given through (its second name empty).
    Height,
}

/// The lengths of the mechanism as its data gives them, in the data block's order: the
/// crank, each group's links, the further points from their link's origin, the distances
/// between fixed points and the slide lines' heights: what, the two points' names, the
/// length (m).
pub(crate) fn spans(m: &Mechanism) -> Vec<(Span, String, String, f64)> {
    let mut out = Vec::new();
    let mut push = |what: Span, a: &str, b: &str, l: f64| {
        out.push((what, a.to_string(), b.to_string(), l));
    };
    push(Span::Crank, &m.crank.centre, &m.crank.pin, m.crank.length);
    for g in &m.groups {
        for (a, joint, l) in g.dyad.lengths() {
            push(Span::Link, a, joint, l);
        }
    }
    for p in &m.points {
        let Some(o) = link_origin(m, p.link) else {
            continue;
        };
        if p.across == 0.0 {
            push(Span::Point, &o, &p.name, p.along.abs());
            continue;
        }
        // A point off its link's line (C of the triangular rocker DBC): the triangle's two
        // sides from the link's origin and from the pair its frame runs to.
        let end = m
            .groups
            .iter()
            .flat_map(|g| g.links.into_iter().zip(g.dyad.lengths()))
            .find(|(link, _)| *link == p.link);
        if let Some((_, (_, x, len))) = end {
            push(Span::Point, &o, &p.name, p.along.hypot(p.across));
            push(Span::Point, x, &p.name, (p.along - len).hypot(p.across));
        }
    }
    let fixed = &m.fixed;
    for (k, a) in fixed.iter().enumerate() {
        for b in &fixed[k + 1..] {
            push(Span::Fixed, &a.name, &b.name, (a.at - b.at).length());
        }
    }
    for g in &m.groups {
        let guides = g.dyad.slide_lines();
        for (through, offset) in guides.into_iter().filter(|g| g.1 != 0.0) {
            push(Span::Height, through, "", offset.abs());
        }
    }
    out
}

/// The frame's guides given through a fixed point with no offset: the joint that slides on
/// each and the fixed points the guide's line passes through, in the scene's order (the
/// six-bar's E on x–x through O and D). The data states them: the lengths give the points,
/// and a guide through them is not seen from the lengths alone (an offset one is, by its
/// height).
pub(crate) fn guides_through(m: &Mechanism) -> Vec<(&str, Vec<&str>)> {
    use crate::linkage::Dir;
    // A fixed point on the line: within this fraction of the frame's span of it.
    const ON_LINE: f64 = 1e-9;
    let span = m
        .fixed
        .iter()
        .map(|p| p.at.length())
        .fold(m.crank.length, f64::max);
    let mut out = Vec::new();
    for g in &m.groups {
        let Some(joint) = g.dyad.joint() else {
            continue;
        };
        for guide in g.dyad.guides().into_iter().flatten() {
            let Dir::Fixed(angle) = guide.dir else {
                continue;
            };
            let Some(origin) = m.fixed.iter().find(|p| p.name == guide.through) else {
                continue;
            };
            if guide.offset != 0.0 {
                continue;
            }
            let u = crate::geom::DVec2::from_angle(angle);
            let on: Vec<&str> = m
                .fixed
                .iter()
                .filter(|p| u.perp_dot(p.at - origin.at).abs() <= ON_LINE * span)
                .map(|p| p.name.as_str())
                .collect();
            out.push((joint, on));
        }
    }
    out
}

/// Symbol (label markup), value and unit of the mechanism's data.
pub fn mechanism(m: &Mechanism, lang: Lang) -> Vec<DataRow> {
    let mut rows: Vec<DataRow> = spans(m)
        .into_iter()
        .map(|(what, a, b, l)| {
            let symbol = match what {
                Span::Height => format!("h_{{{}}}", plain(&a)),
                _ => format!("l_{{{}{}}}", plain(&a), plain(&b)),
            };
            (symbol, mm(l, lang), "mm".to_string())
        })
        .collect();
    rows.extend(slant_guides(m).into_iter().map(|(joint, deg)| {
        let symbol = format!("β_{{{}}}", plain(joint));
        (symbol, fmt(deg, 5, lang), "deg".to_string())
    }));
    rows.push(("ω_{1}".into(), fmt(m.crank.omega, 5, lang), "rad/s".into()));
    rows
}

/// The frame guides set neither along nor across the horizontal (an engine's cylinder
/// axes): the joint that slides on each and the guide's angle to the horizontal, degrees
/// in [0, 180). The scheme shows a horizontal or vertical guide for what it is; a slanted
/// one needs its angle.
fn slant_guides(m: &Mechanism) -> Vec<(&str, f64)> {
    use crate::linkage::Dir;
    m.groups
        .iter()
        .filter_map(|g| Some((g.dyad.joint()?, g.dyad.guides())))
        .flat_map(|(joint, guides)| guides.into_iter().flatten().map(move |g| (joint, g)))
        .filter_map(|(joint, g)| match g.dir {
            Dir::Fixed(a) => Some((joint, a.to_degrees().rem_euclid(180.0))),
            Dir::Along { .. } => None,
        })
        .filter(|(_, deg)| {
            let off = deg.rem_euclid(90.0);
            off.min(90.0 - off) > 1e-9
        })
        .collect()
}

/// Symbol, value and unit of the links' masses and moments of inertia, of the working
/// resistances and of an engine's cylinders.
pub fn forces(f: &ForceSpec, lang: Lang) -> Vec<DataRow> {
    force_units(f, lang).concat()
}

/// [`forces`] by what each row belongs to: a link (its mass and moment of inertia), a
/// resistance, a cylinder (its bore, its indicator diagram's peak and the crank angle its
/// cycle starts at; the diagram itself is the scene's table) — a sheet writes each together.
pub(crate) fn force_units(f: &ForceSpec, lang: Lang) -> Vec<Vec<DataRow>> {
    let mut units = Vec::new();
    for l in &f.links {
        let mut unit = Vec::new();
        if l.mass > 0.0 {
            unit.push((
                format!("m_{{{}}}", l.link),
                fmt(l.mass, 5, lang),
                "kg".into(),
            ));
        }
        if l.inertia > 0.0 {
            let centre = plain(&l.centre);
            unit.push((
                format!("J_{{{centre}}}"),
                fmt(l.inertia, 5, lang),
                "kg*m^2".into(),
            ));
        }
        units.push(unit);
    }
    for r in &f.resistances {
        let (magnitude, unit) = match &r.action {
            Action::Force { magnitude, .. } => (magnitude, "N"),
            Action::Moment { magnitude, .. } => (magnitude, "N*m"),
        };
        let symbol = r.action.symbol().into();
        units.push(vec![(symbol, fmt(*magnitude, 5, lang), unit.into())]);
    }
    for c in &f.indicators {
        let piston = plain(&c.point);
        let peak = c.pressure.iter().map(|&(_, p)| p).fold(0.0, f64::max);
        units.push(vec![
            (format!("d_{{{piston}}}"), mm(c.bore, lang), "mm".into()),
            (
                format!("p_{{max {piston}}}"),
                fmt(peak * 1e-6, 5, lang),
                "MPa".into(),
            ),
            (
                format!("φ_{{0 {piston}}}"),
                fmt(c.offset.to_degrees(), 5, lang),
                "deg".into(),
            ),
        ]);
    }
    units.retain(|u| !u.is_empty());
    units
}

/// A data row as a sheet's text writes it: `m_{2} = 10 кг`, an angle `φ_{0 B} = 45°`.
pub(crate) fn written((symbol, value, unit): &DataRow, lang: Lang) -> String {
    match unit_in(unit, lang).as_str() {
        "°" => format!("{symbol} = {value}°"),
        u => format!("{symbol} = {value} {u}"),
    }
}

/// Symbol, value and unit of the gear pair, the wheels cut by the rack and the train's
/// wheels, each part under its name.
pub fn gears(g: &GearsSpec, lang: Lang) -> Vec<DataRow> {
    let mut rows = Vec::new();
    let one = |s: &str, x: f64| (s.to_string(), fmt(x, 5, lang), String::new());
    let part = |t: NoteText| (t.get(lang).to_string(), String::new(), String::new());
    if let Some(p) = &g.pair {
        rows.push(part(NoteText::PairPart));
        rows.push(("m".into(), mm(p.module, lang), "mm".into()));
        for i in 0..2 {
            rows.push(one(&format!("z_{{{}}}", i + 1), f64::from(p.z[i])));
            rows.push(one(&format!("x_{{{}}}", i + 1), p.x[i]));
        }
        rows.push((
            "α".into(),
            fmt(p.rack.alpha.to_degrees(), 4, lang),
            "deg".into(),
        ));
        rows.push(one("h^{*}_{a}", p.rack.ha));
        rows.push(one("c^{*}", p.rack.c));
    }
    for r in &g.racks {
        rows.push(part(NoteText::RackCutPart));
        rows.push(("m".into(), mm(r.cutting.module, lang), "mm".into()));
        // Under the wheel's own heading: z and x, not the scene's name of it (z₀, x_p).
        rows.push(one("z", f64::from(r.cutting.z)));
        rows.push(one("x", r.cutting.x));
    }
    if let Some(t) = &g.planetary {
        rows.push(part(if t.train.second.is_some() {
            NoteText::DifferentialPart
        } else {
            NoteText::TrainPart
        }));
        rows.push(("m".into(), mm(t.train.module, lang), "mm".into()));
        for wheel in &t.train.wheels {
            rows.push(one(&format!("z_{{{}}}", wheel.name), wheel.z));
        }
        if let Some(k) = t.satellites {
            rows.push(one("k", f64::from(k)));
        }
        let tr = &t.train;
        // The inputs' speeds (a differential's two), the required output speed.
        let second = tr.second.map(|(k, w)| (k, t.n_input.map(|n| n * w)));
        let speeds = [(tr.input, t.n_input)]
            .into_iter()
            .chain(second)
            .chain([(tr.output, t.n_output)]);
        for (shaft, n) in speeds {
            if let Some(n) = n {
                let s = format!("n_{{{}}}", tr.shafts[shaft]);
                rows.push((s, fmt(n, 5, lang), "rpm".into()));
            }
        }
    }
    rows
}

/// The point a link's frame starts at (its outer pivot), for the distances of its points.
fn link_origin(m: &Mechanism, link: u32) -> Option<String> {
    if link == m.crank.link {
        return Some(m.crank.centre.clone());
    }
    m.groups.iter().find_map(|g| {
        let k = g.links.iter().position(|l| *l == link)?;
        g.dyad.origins()[k].map(str::to_string)
    })
}

/// The part of a sheet's data block: the task's data, or the results the sheet adds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataPart {
    /// The lines before the block's first blank line.
    Inputs,
    /// The lines after it.
    Results,
}

/// The lines of the data blocks (headed «Исходные данные», «… и результаты») of `plates`,
/// as the sheets print them (label markup), without their heading and the drafting remark:
/// each block's `part`, the data before its first blank line or the results after it; a
/// line that several sheets print, once.
pub fn data_block<'p>(
    plates: impl IntoIterator<Item = &'p Plate>,
    part: DataPart,
    lang: Lang,
) -> Vec<String> {
    let heads = [Text::Data.get(lang), GearText::DataAndResults.get(lang)];
    let remarks = [Text::ReadExactly.get(lang), Text::ReadTo.get(lang)];
    let mut out: Vec<String> = Vec::new();
    for block in plates.into_iter().flat_map(|p| &p.texts) {
        let Some((head, lines)) = block.lines.split_first() else {
            continue;
        };
        if !heads.contains(&head.as_str()) {
            continue;
        }
        let blank = lines
            .iter()
            .position(|l| l.trim().is_empty())
            .unwrap_or(lines.len());
        let (inputs, results) = lines.split_at(blank);
        let lines = match part {
            DataPart::Inputs => inputs,
            DataPart::Results => results,
        };
        for line in lines {
            let remark = remarks.iter().any(|r| line.starts_with(r));
            if !line.trim().is_empty() && !remark && !out.contains(line) {
                out.push(line.clone());
            }
        }
    }
    out
}
