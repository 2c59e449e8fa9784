//! The analytic method of the note (seed 000 §1.7): for a slotted link turning about a fixed
//! pivot under the crank's pin, the closed vector loop, its projections on the axes, the
//! formulas of the positions, velocities and accelerations, and one position worked with the
//! analytic table's numbers; then the table itself (the seed's Table 5), split in parts of
//! at most eight columns.

use super::equations::vector;
use super::markup::{frac, label, num, sym, text, Align};
use super::rows::{fmt, DIGITS};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::{is_zero, Table};
use crate::linkage::{Dyad, Mechanism};
use crate::words::{
    plain, subscripted, unit_in, KinematicsMeaning as M, KinematicsNote as K, NoteText as T,
};

/// The analytic method: the slotted link's loop worked where the mechanism has one, then
/// the analytic table.
pub(super) fn analytic(
    w: &mut Writer<'_, '_>,
    at: Option<&str>,
    omega1: f64,
) -> Result<(), NoteError> {
    w.heading(2, T::AnalyticMethod);
    w.doc.say(w.word(T::AnalyticText));
    let m = w.session.mechanism("the explanatory note")?;
    if let Some(slot) = Slot::of(m) {
        slot.formulas(w);
        if let Some(at) = at {
            slot.worked(w, at, omega1);
        }
    }
    tables(w);
    Ok(())
}

/// A slotted link j turning about the fixed pivot C, its block riding the crank's pin B
/// (the crank AB turning about A): the loop AB + CA = CB.
struct Slot {
    /// A, B, C (plain names).
    names: [String; 3],
    /// The link's number.
    j: u32,
    /// The crank's length, m.
    l1: f64,
    /// A − C, m.
    xa: f64,
    /// See `xa`.
    ya: f64,
    /// A further point of link j (`D`) and its distance from C, m, when the link has one.
    far: Option<(String, f64)>,
}

impl Slot {
    fn of(m: &Mechanism) -> Option<Self> {
        let centre = m.fixed.iter().find(|f| f.name == m.crank.centre)?;
        m.groups.iter().find_map(|g| match &g.dyad {
            Dyad::Rpr { a, c, offset } if *a == m.crank.pin && *offset == 0.0 => {
                let pivot = m.fixed.iter().find(|f| f.name == *c)?;
                let j = g.links[1];
                let far = m
                    .points
                    .iter()
                    .filter(|p| p.link == j)
                    .max_by(|a, b| a.along.abs().total_cmp(&b.along.abs()))
                    .map(|p| (plain(&p.name), p.along.hypot(p.across)));
                Some(Self {
                    names: [plain(&centre.name), plain(a), plain(c)],
                    j,
                    l1: m.crank.length,
                    xa: centre.at.x - pivot.at.x,
                    ya: centre.at.y - pivot.at.y,
                    far,
                })
            }
            _ => None,
        })
    }

    /// The symbols: `l_{1}`, `φ_{1}`, `φ_{3}`, `L_{3}`, `ω_{3}`, `ε_{3}`, `V_{B3B1}`.
    fn symbols(&self) -> [String; 6] {
        let [_, b, _] = &self.names;
        let j = self.j;
        [
            format!("φ_{{{j}}}"),
            format!("L_{{{j}}}"),
            format!("ω_{{{j}}}"),
            format!("ε_{{{j}}}"),
            format!("V_{{{b}{j}{b}1}}"),
            "l_{1}".into(),
        ]
    }

    /// The loop, its projections and the formulas in symbols.
    fn formulas(&self, w: &mut Writer<'_, '_>) {
        let [a, b, c] = &self.names;
        let [phi, big_l, omega, eps, vr, l1] = self.symbols();
        let s = |x: &str| sym(x);
        w.doc.par(&[text(w.word(K::LoopIntro))]);
        w.formula(&format!(
            "{} + {} = {}",
            vector(&format!("l_{{{a}{b}}}")),
            vector(&format!("l_{{{c}{a}}}")),
            vector(&format!("l_{{{c}{b}}}"))
        ));
        w.explain(&[(&format!("l_{{{c}{b}}}"), w.word(M::SlotLength), "m")]);
        w.doc.par(&[text(w.word(K::Projections))]);
        let (xa, ya) = (s(&format!("x_{{{a}}}")), s(&format!("y_{{{a}}}")));
        w.formula(&format!(
            "{} cos {} = {xa} + {} cos {}",
            s(&big_l),
            s(&phi),
            s(&l1),
            s("φ_{1}")
        ));
        w.explain(&[
            (&big_l, w.word(M::SlotLength), "m"),
            (&phi, w.word(M::SlotAngle), "deg"),
            (&format!("x_{{{a}}}"), w.word(M::PivotX), "m"),
            (&l1, w.word(M::CrankLength), "m"),
            ("φ_{1}", w.word(M::CrankAngle), "deg"),
        ]);
        w.formula(&format!(
            "{} sin {} = {ya} + {} sin {}",
            s(&big_l),
            s(&phi),
            s(&l1),
            s("φ_{1}")
        ));
        w.explain(&[(&format!("y_{{{a}}}"), w.word(M::PivotY), "m")]);
        w.doc.par(&[text(w.word(K::PositionFormulas))]);
        w.formula(&format!(
            "{} = op(\"arctg\") {}",
            s(&phi),
            frac(
                &format!("{ya} + {} sin {}", s(&l1), s("φ_{1}")),
                &format!("{xa} + {} cos {}", s(&l1), s("φ_{1}"))
            )
        ));
        w.formula(&format!(
            "{} = {}",
            s(&big_l),
            frac(
                &format!("{ya} + {} sin {}", s(&l1), s("φ_{1}")),
                &format!("sin {}", s(&phi))
            )
        ));
        w.doc.par(&[text(w.word(K::VelocityFormulas))]);
        let d13 = format!("({} - {})", s("φ_{1}"), s(&phi));
        w.formula(&format!(
            "{} = {}",
            s(&omega),
            frac(&format!("{} {} cos{d13}", s("ω_{1}"), s(&l1)), &s(&big_l))
        ));
        w.explain(&[(&omega, w.word(M::SlotSpeed), "rad/s")]);
        w.formula(&format!("{} = -{} {} sin{d13}", s(&vr), s("ω_{1}"), s(&l1)));
        w.explain(&[(&vr, w.word(M::SlideSpeed), "m/s")]);
        w.doc.par(&[text(w.word(K::AccelerationFormulas))]);
        w.formula(&format!(
            "{} = {}",
            s(&eps),
            frac(
                &format!(
                    "-{}^2 {} sin{d13} - 2{} {}",
                    s("ω_{1}"),
                    s(&l1),
                    s(&vr),
                    s(&omega)
                ),
                &s(&big_l)
            )
        ));
        w.explain(&[(&eps, w.word(M::SlotAcceleration), "rad/s^2")]);
        if let Some((d, _)) = &self.far {
            let (v, acc, l) = (
                format!("V_{{{d}}}"),
                format!("a_{{{d}}}"),
                format!("l_{{{c}{d}}}"),
            );
            w.formula(&format!("{} = |{}| {}", s(&v), s(&omega), s(&l)));
            let what = format!("{} {d}", w.word(M::PointVelocity));
            w.explain(&[(&v, &what, "m/s"), (&l, w.word(M::PointDistance), "m")]);
            w.formula(&format!(
                "{} = {} sqrt({}^2 + {}^4)",
                s(&acc),
                s(&l),
                s(&eps),
                s(&omega)
            ));
            let what = format!("{} {d}", w.word(M::PointAcceleration));
            w.explain(&[(&acc, &what, "m/s^2")]);
        }
    }

    /// The position `at` worked with the analytic table's numbers: each formula with the
    /// inputs substituted and the table's value as its result.
    fn worked(&self, w: &mut Writer<'_, '_>, at: &str, omega1: f64) {
        let lang = w.lang;
        let Some(t) = w.report.tables.first().cloned() else {
            return;
        };
        let Some((_, row)) = t.rows.iter().find(|(p, _)| p == at) else {
            return;
        };
        let b = &self.names[1];
        let j = self.j;
        let col = |name: &str| {
            t.columns
                .iter()
                .position(|c| c.name == name)
                .and_then(|k| row.get(k).copied().flatten())
        };
        let vr_name = format!("V_{b}{j}{b}1");
        let (Some(phi1), Some(phi), Some(big_l), Some(omega), Some(eps), Some(vr)) = (
            col("φ_1"),
            col(&format!("φ_{j}")),
            col(&format!("L_{j}")),
            col(&format!("ω_{j}")),
            col(&format!("ε_{j}")),
            col(&vr_name),
        ) else {
            return;
        };
        let [phi_s, big_l_s, omega_s, eps_s, vr_s, _] = self.symbols();
        // A negative number substituted in a product or a sum stands in parentheses.
        let n = |x: f64| signed(num(x, 4, lang), x);
        let n5 = |x: f64| signed(num(x, 5, lang), x);
        let deg = |x: f64| format!("{}°", num(x, 5, lang));
        w.doc.say(&format!("{} {at}:", w.word(K::AnalyticWorked)));
        let (xa, ya, l1) = (self.xa, self.ya, self.l1);
        w.worked(Worked::new(
            sym(&phi_s),
            "",
            format!(
                "op(\"arctg\") {}",
                frac(
                    &format!("{} + {} dot sin {}", n5(ya), n5(l1), deg(phi1)),
                    &format!("{} + {} dot cos {}", n5(xa), n5(l1), deg(phi1))
                )
            ),
            Printed::degrees(phi, lang),
        ));
        w.worked(Worked::new(
            sym(&big_l_s),
            "",
            frac(
                &format!("{} + {} dot sin {}", n5(ya), n5(l1), deg(phi1)),
                &format!("sin {}", deg(phi)),
            ),
            Printed::si(big_l, 4, "m", lang),
        ));
        let d13 = format!("({} - {})", deg(phi1), deg(phi));
        w.worked(Worked::new(
            sym(&omega_s),
            "",
            frac(
                &format!("{} dot {} dot cos{d13}", n5(omega1), n5(l1)),
                &n(big_l),
            ),
            Printed::si(omega, 4, "rad/s", lang),
        ));
        w.worked(Worked::new(
            sym(&vr_s),
            "",
            format!("-{} dot {} dot sin{d13}", n5(omega1), n5(l1)),
            Printed::si(vr, 4, "m/s", lang),
        ));
        w.worked(Worked::new(
            sym(&eps_s),
            "",
            frac(
                &format!(
                    "-{}^2 dot {} dot sin{d13} - 2 dot {} dot {}",
                    n5(omega1.abs()),
                    n5(l1),
                    n(vr),
                    n(omega)
                ),
                &n(big_l),
            ),
            Printed::si(eps, 4, "rad/s^2", lang),
        ));
        if let Some((d, l)) = &self.far {
            if let (Some(v), Some(acc)) = (col(&format!("V_{d}")), col(&format!("a_{d}"))) {
                w.worked(Worked::new(
                    sym(&format!("V_{{{d}}}")),
                    "",
                    format!("{} dot {}", num(omega.abs(), 4, lang), n5(*l)),
                    Printed::si(v, 4, "m/s", lang),
                ));
                w.worked(Worked::new(
                    sym(&format!("a_{{{d}}}")),
                    "",
                    format!("{} dot sqrt({}^2 + {}^4)", n5(*l), n(eps), n(omega)),
                    Printed::si(acc, 4, "m/s^2", lang),
                ));
            }
        }
    }
}

/// A number of formula markup `shown` (the value `x`) as it stands substituted after a sign
/// or in a product: in parentheses when negative.
fn signed(shown: String, x: f64) -> String {
    if x < 0.0 {
        format!("({shown})")
    } else {
        shown
    }
}

/// The analytic table (the seed's Table 5), its columns in parts of at most eight.
fn tables(w: &mut Writer<'_, '_>) {
    let lang = w.lang;
    for t in w.report.tables.clone() {
        let header: Vec<String> = std::iter::once(text(w.word(T::PositionShort)))
            .chain(t.columns.iter().map(|c| {
                let name = subscripted(&c.name);
                let u = unit_in(&c.unit, lang);
                label(&if u.is_empty() {
                    name
                } else {
                    format!("{name}, {u}")
                })
            }))
            .collect();
        let rows = cells(&t, lang);
        let align = vec![Align::Centre; header.len()];
        let caption = w.word(T::AnalyticTable);
        let cols = header.len() - 1;
        let halves = cols.div_ceil(8);
        for h in 0..halves {
            let range = (1 + h * cols / halves)..(1 + (h + 1) * cols / halves);
            let pick = |row: &Vec<String>| -> Vec<String> {
                std::iter::once(row[0].clone())
                    .chain(row[range.clone()].iter().cloned())
                    .collect()
            };
            let cap = if halves > 1 {
                format!("{caption} ({} {}/{halves})", w.word(T::Part), h + 1)
            } else {
                caption.to_string()
            };
            let body: Vec<Vec<String>> = rows.iter().map(pick).collect();
            w.doc
                .table(&cap, &align[..1 + range.len()], &pick(&header), &body);
        }
    }
}

/// The analytic table's cells: each column's largest value is its scale, a residue against
/// it written 0.
fn cells(t: &Table, lang: crate::scale::Lang) -> Vec<Vec<String>> {
    let scales: Vec<f64> = (0..t.columns.len())
        .map(|c| {
            t.rows
                .iter()
                .filter_map(|(_, vals)| vals.get(c).copied().flatten())
                .fold(0.0, |m: f64, x| m.max(x.abs()))
        })
        .collect();
    t.rows
        .iter()
        .map(|(p, vals)| {
            std::iter::once(text(p))
                .chain(vals.iter().zip(&scales).map(|(v, &scale)| {
                    let shown = |x: f64| if is_zero(x, scale) { 0.0 } else { x };
                    text(&v.map(|x| fmt(shown(x), DIGITS, lang)).unwrap_or_default())
                }))
                .collect()
        })
        .collect()
}
