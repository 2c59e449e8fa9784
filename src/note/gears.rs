//! The gears section: the pair's geometry worked formula by formula (seed 000 §4: symbols,
//! numbers, result), ε_α by formula and off the meshing picture, the specific sliding
//! (Table 6), the rack-cut wheel and the train by Willis and by the triangles.

use super::markup::{frac, inline, label, num, sym, text, Align};
use super::rows::{by_position, of_scene, quantities};
use super::worked::{deg, Printed, Worked, INV};
use super::{NoteError, Writer};
use crate::check::{Key, Method, Symbol};
use crate::gears::{inv, GearPair, Generation};
use crate::scene::PlateKind;
use crate::words::{unit_in, Meaning as M, NoteText as T, Text as S};

/// The gears section.
pub(super) fn gears(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    w.section(T::GearsSection);
    let study = w.session.gears()?;
    // What the scene has of the pair, the rack-cut wheels and the train, in a sentence each.
    let intro: Vec<&str> = [
        (study.pair.is_some(), T::GearsIntroPair),
        (!study.racks.is_empty(), T::GearsIntroRack),
        (
            study
                .train
                .as_ref()
                .is_some_and(|t| t.spec.train.second.is_none()),
            T::GearsIntroTrain,
        ),
        (
            study
                .train
                .as_ref()
                .is_some_and(|t| t.spec.train.second.is_some()),
            T::GearsIntroDifferential,
        ),
    ]
    .into_iter()
    .filter(|(has, _)| *has)
    .map(|(_, t)| w.word(t))
    .collect();
    w.doc.say(&intro.join(" "));
    // The data are the task's; the results are worked below.
    if let Some(p) = &study.pair {
        super::pair_worked::pair_geometry(w, &p.pair);
        contact_ratio(w, &p.pair, p.meshing.ab.value);
    }
    // The pair's own rows (its u₁₂ among them, not the train's).
    let [pair_rows, _] = study.rows_by_part();
    let of_pair = |r: &crate::check::Row| pair_rows.iter().any(|p| p.key == r.key);
    let caption = w.word(T::PairTable);
    of_scene(w, caption, |r| {
        r.position().is_none()
            && matches!(r.method, Method::Formula | Method::Meshing)
            && of_pair(r)
    });
    // The values at the points of the blocking contour: a table of their own.
    let blocking = study
        .blocking
        .as_ref()
        .map(|b| b.rows())
        .unwrap_or_default();
    let on_contour = |r: &crate::check::Row| blocking.iter().any(|b| b.key == r.key);
    let q = quantities(&w.report.rows, |r| {
        r.key.symbol == Symbol::SpecificSliding && !on_contour(r)
    });
    if let Some(p) = &study.pair {
        sliding_table(w, &p.pair);
    }
    let caption = w.word(T::SlidingTable);
    by_position(w, caption, &q);
    let caption = w.word(T::BlockingTable);
    of_scene(w, caption, on_contour);
    for cut in &study.racks {
        rack_form(w, &cut.generation);
    }
    let caption = w.word(T::RackTable);
    // A rack-cut wheel's x_min (formula) beside what its envelope gives.
    of_scene(w, caption, |r| {
        (r.method == Method::Envelope || r.key.symbol == Symbol::ShiftCoefficient) && !on_contour(r)
    });
    if let Some(train) = &study.train {
        super::train::train_worked(w, train);
    }
    let caption = w.word(T::TrainTable);
    of_scene(w, caption, |r| {
        (r.key.symbol == Symbol::GearRatio && !of_pair(r)) || r.method == Method::Triangles
    });
    w.figures((PlateKind::Gears, None), |_| true, |own| own.to_string());
    Ok(())
}

/// The specific sliding in the shape of seed 000's Table 6: λ₁ and λ₂ at N₁, at the ends of
/// the active line B₁ and B₂, at the pitch point P, midway between P and B₂ and at N₂
/// (the seed's points X = 0; 42,75; 66,5; 91,75; 117; g), X along N₁N₂ in mm.
fn sliding_table(w: &mut Writer<'_, '_>, p: &GearPair) {
    let lang = w.lang;
    let [b1, b2] = p.active_ends();
    let pole = p.pole();
    let points = [
        ("N_{1}", 0.0),
        ("B_{1}", b1),
        ("P", pole),
        ("", (pole + b2) / 2.0),
        ("B_{2}", b2),
        ("N_{2}", p.g),
    ];
    let value = |x: f64| {
        if x.is_finite() {
            crate::scale::format_fixed(x, 3, lang)
        } else {
            "−∞".into()
        }
    };
    let mut head = vec![text(w.word(T::PointOfLine))];
    head.extend(points.iter().map(|(name, _)| label(name)));
    let mut xs = vec![label(&format!("X, {}", unit_in("mm", lang)))];
    xs.extend(
        points
            .iter()
            .map(|(_, x)| text(&crate::scale::format_fixed(x * 1e3, 2, lang))),
    );
    let mut rows = vec![xs];
    for (i, name) in ["λ_{1}", "λ_{2}"].into_iter().enumerate() {
        let mut row = vec![label(name)];
        row.extend(points.iter().map(|(_, x)| text(&value(p.sliding(*x)[i]))));
        rows.push(row);
    }
    let mut align = vec![Align::Centre; head.len()];
    align[0] = Align::Left;
    w.doc.say(&format!("{}:", w.word(T::SlidingWorked)));
    let (z1, z2) = (sym("z_{1}"), sym("z_{2}"));
    w.formula(&format!(
        "{} = 1 - {}",
        sym("λ_{1}"),
        frac(&format!("(g - X) {z1}"), &format!("{z2} X"))
    ));
    w.explain(&[
        ("λ_{1}", &format!("{} 1", M::SlidingOfWheel.get(lang)), ""),
        ("g", M::LineOfAction.get(lang), "mm"),
        ("X", M::ContactDistance.get(lang), "mm"),
    ]);
    w.formula(&format!(
        "{} = 1 - {}",
        sym("λ_{2}"),
        frac(&format!("{z2} X"), &format!("(g - X) {z1}"))
    ));
    w.explain(&[("λ_{2}", &format!("{} 2", M::SlidingOfWheel.get(lang)), "")]);
    w.doc
        .table(w.word(T::SlidingAtPoints), &align, &head, &rows);
}

/// ε_α by the textbook's formula and as the active line read off the meshing picture over
/// the base pitch (`ab_read`, m).
fn contact_ratio(w: &mut Writer<'_, '_>, p: &GearPair, ab_read: f64) {
    let lang = w.lang;
    let n = |x: f64| num(x, 5, lang);
    let [z1, z2] = p.spec.z;
    w.doc.say(w.word(T::ContactRatioWorked));
    w.worked(
        Worked::new(
            sym("ε_{α}"),
            frac(
                &format!(
                    "{} op(\"tg\") {} + {} op(\"tg\") {} - ({} + {}) op(\"tg\") {}",
                    sym("z_{1}"),
                    sym("α_{a1}"),
                    sym("z_{2}"),
                    sym("α_{a2}"),
                    sym("z_{1}"),
                    sym("z_{2}"),
                    sym("α_{w}")
                ),
                "2 π",
            ),
            frac(
                &format!(
                    "{z1} dot op(\"tg\") {} + {z2} dot op(\"tg\") {} - {} dot op(\"tg\") {}",
                    deg(p.alpha_a[0], lang),
                    deg(p.alpha_a[1], lang),
                    z1 + z2,
                    deg(p.alpha_w, lang)
                ),
                "2 π",
            ),
            Printed::number(p.eps_formula, lang),
        )
        .gives_by(
            Key::of_scene(Symbol::ContactRatio, "alpha"),
            Method::Formula,
        ),
    );
    w.explain(&[("ε_{α}", M::ContactRatio.get(lang), "")]);
    w.doc.say(w.word(T::ContactRatioPicture));
    w.worked(
        Worked::new(
            sym("ε′_{α}"),
            frac(&sym("B_{1}B_{2}"), &sym("p_{b}")),
            frac(&n(ab_read * 1e3), &n(p.p_b * 1e3)),
            Printed::number(ab_read / p.p_b, lang),
        )
        .gives_by(
            Key::of_scene(Symbol::ContactRatio, "alpha"),
            Method::Meshing,
        ),
    );
    w.explain(&[
        ("ε′_{α}", M::ContactRatioDrawn.get(lang), ""),
        ("B_{1}B_{2}", M::ActiveLine.get(lang), "mm"),
    ]);
}

/// The practicum's report form of a wheel cut by the rack (seed 002 PZ1, Table 1.1 for the
/// zero wheel, 1.2 for the shifted one): each quantity by the form's formula, as read on
/// the drawing (the chords where the drawn flanks cross the pitch and base circles, turned
/// into arcs) and by the exact envelope; lengths in mm. The form's S_b is the uncut
/// involute's: an undercut thins the drawn and the exact tooth below it.
fn rack_form(w: &mut Writer<'_, '_>, g: &Generation) {
    let lang = w.lang;
    let c = &g.cutting;
    let n = |x: f64| num(x, 5, lang);
    let mm = |x: f64| inline(&n(x * 1e3));
    let none = || text("—");
    let m = c.module;
    let (alpha, z) = (c.rack.alpha, f64::from(c.z));
    let pitch = std::f64::consts::PI * m;
    let s_formula = c.s();
    let exact_st = c.thickness_at_radius(c.r());
    let (st, et) = g.pitch_reading;
    let mut rows: Vec<Vec<String>> = vec![
        vec![label("d"), inline("m z"), mm(m * z), none(), none()],
        vec![
            label("d_{b}"),
            inline(&format!("d cos {}", sym("α"))),
            mm(m * z * alpha.cos()),
            none(),
            none(),
        ],
    ];
    if c.x != 0.0 {
        // x is the shift coefficient, as in the pair's formulas; the rack's shift is x m.
        let x_min = (17.0 - z) / 17.0;
        rows.push(vec![
            label("x_{min}"),
            inline(&frac("17 - z", "17")),
            inline(&n(x_min)),
            none(),
            none(),
        ]);
        rows.push(vec![
            label("x m"),
            inline(&format!("{} dot {}", n(c.x), n(m * 1e3))),
            mm(c.x * m),
            none(),
            none(),
        ]);
    }
    let exact = |v: Option<f64>| v.map_or_else(none, mm);
    rows.push(vec![
        label("P_{t}"),
        inline("π m"),
        mm(pitch),
        mm(st + et),
        mm(pitch),
    ]);
    let st_formula = if c.x != 0.0 {
        format!(
            "{} P_(t) + 2 x m op(\"tg\") {}",
            num(0.5, 1, lang),
            sym("α")
        )
    } else {
        format!("{} P_(t)", num(0.5, 1, lang))
    };
    rows.push(vec![
        label("S_{t}"),
        inline(&st_formula),
        mm(s_formula),
        mm(st),
        exact(exact_st),
    ]);
    rows.push(vec![
        label("e_{t}"),
        inline("P_(t) - S_(t)"),
        mm(pitch - s_formula),
        mm(et),
        exact(exact_st.map(|s| pitch - s)),
    ]);
    let sb_formula = 2.0 * c.rb() * (s_formula / (2.0 * c.r()) + inv(alpha));
    let exact_sb = c.thickness_at_radius(c.rb());
    rows.push(vec![
        label("S_{b}"),
        inline(&format!(
            "2 r_(b) ({} + {} {})",
            frac("S_(t)", "2 r"),
            INV,
            sym("α")
        )),
        mm(sb_formula),
        g.sb.map_or_else(none, mm),
        exact(exact_sb),
    ]);
    let header = form_header(w);
    let form = if c.x == 0.0 {
        T::ZeroWheelForm
    } else {
        T::ShiftedWheelForm
    };
    let caption = format!(
        "{} (z = {}, x = {}): {}",
        w.word(T::WheelWord),
        c.z,
        crate::scale::format_sig(c.x, 4, lang),
        w.word(form)
    );
    let align = [
        Align::Left,
        Align::Centre,
        Align::Centre,
        Align::Centre,
        Align::Centre,
    ];
    w.doc.table(&caption, &align, &header, &rows);
    if g.undercut {
        w.doc.say(w.word(T::UndercutThins));
    } else if exact_sb.is_some_and(|s| s > sb_formula * (1.0 + 1e-4)) {
        w.doc.say(w.word(T::FilletAboveBase));
    }
}

/// The report form's header: quantity | formula | by formula | on the drawing | by the
/// envelope (the values in mm).
fn form_header(w: &Writer<'_, '_>) -> [String; 5] {
    let lang = w.lang;
    [
        text(w.word(S::Quantity)),
        text(w.word(T::FormulaColumn)),
        text(&format!(
            "{}, {}",
            w.word(T::ByFormula),
            unit_in("mm", lang)
        )),
        text(&format!(
            "{}, {}",
            w.word(T::OnTheDrawing),
            unit_in("mm", lang)
        )),
        text(&format!(
            "{}, {}",
            w.word(T::ByEnvelope),
            unit_in("mm", lang)
        )),
    ]
}
