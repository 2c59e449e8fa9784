//! The construction protocol of a figure: every recorded step, in the recorder's order, said
//! as the lecture says it while drawing ("из точки A радиусом 56 мм проводим дугу", "через b
//! проводим прямую ⊥ BC", "откладываем pb = 2,35 м/с / μ = 47 мм") from the catalogue's
//! templates ([`StepText`]) and what the step draws: its item, its role, its label, the
//! named points it starts from, and the figure's μ. The studio's replay shows it beside the
//! drawing, step by step.

use crate::construct::{Figure, Item, Names, Role, Step};
use crate::geom::DVec2;
use crate::plate::text::plain;
use crate::scale::{format_sig, Lang, Quantity};
use crate::words::{unit_in, StepText};

/// How near a named point must be to a step's point to name it, figure mm.
const SAME_POINT_MM: f64 = 0.05;
/// A drawn length below this is nothing drawn (a solver's residue), mm.
const NOTHING_MM: f64 = 1e-6;
/// Lines whose directions' cross product (unit vectors) is below this are parallel; whose
/// dot product is below it, perpendicular.
const SQUARE: f64 = 1e-6;

/// One step of the protocol: its step's id in the figure and its sentence.
#[derive(Debug, Clone, PartialEq)]
pub struct Said {
    /// The step's id ([`Step::id`]).
    pub step: usize,
    /// The sentence, plain text.
    pub sentence: String,
}

/// The protocol of `figure` in `lang`: one sentence per step, in the recorder's order.
pub fn protocol(figure: &Figure, lang: Lang) -> Vec<Said> {
    let names = named_points(figure);
    figure
        .steps
        .iter()
        .map(|s| Said {
            step: s.id.0 as usize,
            sentence: sentence(figure, s, &names, lang),
        })
        .collect()
}

/// The points the figure names, with their names (plain text).
fn named_points(figure: &Figure) -> Vec<(DVec2, String)> {
    figure
        .steps
        .iter()
        .filter_map(|s| {
            let l = s.label.as_ref()?;
            (l.names == Names::Point).then(|| (l.anchor, plain(&l.text)))
        })
        .collect()
}

fn name_at(names: &[(DVec2, String)], p: DVec2) -> Option<&str> {
    names
        .iter()
        .find(|(q, _)| q.distance(p) < SAME_POINT_MM)
        .map(|(_, n)| n.as_str())
}

/// The name of the piece `a`–`b` by its two named ends (`BC`), when they are two points.
fn pair_name(names: &[(DVec2, String)], a: DVec2, b: DVec2) -> Option<String> {
    match (name_at(names, a), name_at(names, b)) {
        (Some(x), Some(y)) if x != y => Some(format!("{x}{y}")),
        _ => None,
    }
}

fn mm(x: f64, lang: Lang) -> String {
    format_sig(if x.abs() < NOTHING_MM { 0.0 } else { x }, 4, lang)
}

/// The sentence of step `s`.
fn sentence(figure: &Figure, s: &Step, names: &[(DVec2, String)], lang: Lang) -> String {
    let label = s.label.as_ref().map(|l| plain(&l.text)).unwrap_or_default();
    let between = |a: DVec2, b: DVec2| pair_name(names, a, b).unwrap_or_else(|| label.clone());
    let point = |p: DVec2| name_at(names, p).map_or_else(|| label.clone(), str::to_string);
    let (text, n) = match (&s.item, s.role) {
        (_, Role::Hatch) | (Item::Hatching { .. }, _) => (StepText::Hatch, label.clone()),
        (Item::Point(p), _) => (StepText::Point, point(*p)),
        (Item::Joint { at, fixed }, _) => {
            let t = if *fixed {
                StepText::FixedJoint
            } else {
                StepText::Joint
            };
            (t, point(*at))
        }
        (Item::Segment(g), Role::Axis) => (StepText::Axis, between(g.from, g.to)),
        (Item::Segment(g), Role::Given | Role::Result) => {
            let t = StepText::Link.get(lang);
            return fill(t, &between(g.from, g.to), &mm(g.from.distance(g.to), lang));
        }
        (Item::Segment(g), _) => return line(figure, s, (g.from, g.to), names, &label, lang),
        (Item::Arc(a), _) => {
            let c = point(a.center);
            let t = StepText::Arc.get(lang).replace("{c}", &c);
            return t.replace("{r}", &mm(a.radius, lang));
        }
        (Item::Circle(c), _) => {
            let t = StepText::Circle.get(lang).replace("{c}", &point(c.center));
            return fill(&t.replace("{r}", &mm(c.radius, lang)), &label, "");
        }
        (Item::Vector { from, to }, _) => {
            return lay_off(figure, (*from, *to), &between(*from, *to), lang)
        }
        (Item::Curve { points, .. }, _) => {
            let t = StepText::Curve
                .get(lang)
                .replace("{k}", &points.len().to_string());
            return fill(&t, &label, "");
        }
        // Through its pieces' ends.
        (Item::Bezier { pieces, closed, .. }, _) => {
            let ends = pieces.len() + usize::from(!*closed);
            let t = StepText::Curve.get(lang).replace("{k}", &ends.to_string());
            return fill(&t, &label, "");
        }
        (Item::Polyline { points, .. }, _) => {
            let t = StepText::Polyline
                .get(lang)
                .replace("{k}", &points.len().to_string());
            return fill(&t, &label, "");
        }
        (Item::Slider { at, .. }, _) => (StepText::Slider, point(*at)),
        (Item::Guide { segment, .. }, _) => (StepText::Guide, between(segment.from, segment.to)),
        (Item::Dimension { .. }, _) => (StepText::Dimension, label.clone()),
        (Item::Angle(_), _) => (StepText::Angle, label.clone()),
        (Item::Moment(_), _) => (StepText::Moment, label.clone()),
        (Item::Text(_), _) => (StepText::Text, label.clone()),
    };
    fill(text.get(lang), &n, "")
}

/// A template with its name and length filled in, spaces tidied where a name is missing.
fn fill(template: &str, name: &str, length: &str) -> String {
    let s = template.replace("{n}", name).replace("{l}", length);
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// A construction line: ⊥ or ∥ to a line it is derived from, through its named end; else
/// the line between its ends.
fn line(
    figure: &Figure,
    s: &Step,
    (a, b): (DVec2, DVec2),
    names: &[(DVec2, String)],
    label: &str,
    lang: Lang,
) -> String {
    let dir = (b - a).normalize_or_zero();
    for f in &s.from {
        let Some(other) = figure.steps.iter().find(|o| o.id == *f) else {
            continue;
        };
        let (p, q) = match other.item {
            Item::Segment(g) => (g.from, g.to),
            Item::Vector { from, to } => (from, to),
            _ => continue,
        };
        let d = (q - p).normalize_or_zero();
        let whose = match (name_at(names, p), name_at(names, q)) {
            (Some(x), Some(y)) => format!("{x}{y}"),
            _ => other
                .label
                .as_ref()
                .map(|l| plain(&l.text))
                .unwrap_or_default(),
        };
        let through = name_at(names, a)
            .or_else(|| name_at(names, b))
            .unwrap_or("");
        let template = if d.dot(dir).abs() < SQUARE {
            StepText::Perpendicular
        } else if d.perp_dot(dir).abs() < SQUARE {
            StepText::Parallel
        } else {
            continue;
        };
        let t = template.get(lang).replace("{p}", through);
        return fill(&t, &whose, "");
    }
    if let Some(n) = pair_name(names, a, b) {
        return fill(StepText::Line.get(lang), &n, "");
    }
    match name_at(names, a).or_else(|| name_at(names, b)) {
        Some(p) => fill(&StepText::Through.get(lang).replace("{p}", p), label, ""),
        None => fill(StepText::Line.get(lang), label, ""),
    }
}

/// A vector laid off: its drawn length and, at a figure's μ of another quantity than a
/// length, the value it stands for.
fn lay_off(figure: &Figure, (a, b): (DVec2, DVec2), label: &str, lang: Lang) -> String {
    let l = a.distance(b);
    let q = figure.scale.quantity;
    if q == Quantity::Length {
        return fill(StepText::LayOff.get(lang), label, &mm(l, lang));
    }
    let l = if l < NOTHING_MM { 0.0 } else { l };
    let value = format!(
        "{} {}",
        format_sig(figure.scale.to_physical(l), 4, lang),
        unit_in(q.si_unit(), lang)
    );
    let t = StepText::LayOffValue.get(lang).replace("{v}", &value);
    fill(&t, label, &mm(l, lang))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::{Context, Drafting, Recorder};
    use crate::geom::{Arc, Segment};
    use crate::scale::Scale;

    #[test]
    fn a_compass_step_and_a_perpendicular_are_said_as_the_lecture_says_them() {
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("context");
        let mu = Scale::new(0.01, Quantity::Velocity).expect("μ");
        let mut r = Recorder::in_context("test", mu, &ctx);
        let (b, c) = (DVec2::new(0.0, 0.0), DVec2::new(40.0, 0.0));
        let pb = r.draw("b", Item::Point(b), Role::Given, &[]);
        r.label(pb, "b", b, DVec2::Y);
        let bc = r.draw(
            "bc",
            Item::Segment(Segment { from: b, to: c }),
            Role::Given,
            &[],
        );
        let pc = r.draw("c", Item::Point(c), Role::Given, &[]);
        r.label(pc, "c", c, DVec2::Y);
        let arc = Arc {
            center: b,
            radius: 56.0,
            start: 0.0,
            sweep: 0.5,
        };
        r.draw("arc", Item::Arc(arc), Role::Construction, &[pb]);
        let up = Segment {
            from: b,
            to: DVec2::new(0.0, 30.0),
        };
        r.draw("perp", Item::Segment(up), Role::Construction, &[bc]);
        let to = DVec2::new(40.0, 43.98);
        let v = r.draw("v", Item::Vector { from: c, to }, Role::Result, &[]);
        r.label_item(v, "V_{B}", to, DVec2::Y);
        let f = r.finish();
        let said: Vec<String> = protocol(&f, Lang::Ru)
            .into_iter()
            .map(|s| s.sentence)
            .collect();
        assert_eq!(said[1], "проводим звено bc = 40 мм");
        assert_eq!(said[3], "из точки b радиусом 56 мм проводим дугу");
        assert_eq!(said[4], "через b проводим прямую ⊥ bc");
        assert_eq!(said[5], "откладываем VB = 0,4398 м/с / μ = 43,98 мм");
        assert_eq!(
            protocol(&f, Lang::Uk)[4].sentence,
            "через b проводимо пряму ⊥ bc"
        );
        let en = protocol(&f, Lang::En);
        assert_eq!(en[3].sentence, "from b draw an arc of radius 56 mm");
    }
}
