//! The note's frame and its first and last sections: the page rules and the title block's
//! data, the title page, the contents, the task and the references.

use super::markup::{label, string, text, Align};
use super::rows::fmt;
use super::Writer;
use crate::gears::GearsSpec;
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::sheets::captions::{unit_in, NoteText as T, Text as S};
use crate::sheets::data::mm;

/// The page rules (`template.typ`) after the title block's data.
pub(super) fn preamble(w: &mut Writer<'_, '_>) {
    let t = &w.session.scene().title;
    let c = crate::plate::title_block_captions(w.lang);
    let list = |xs: &[&str]| {
        let items: Vec<String> = xs.iter().map(|x| string(x)).collect();
        format!("({},)", items.join(", "))
    };
    let designation = format!("{} {}", t.designation, w.word(T::NoteCode));
    let document = format!("{}\n{}", t.title, w.word(T::ExplanatoryNote));
    let lang = match w.lang {
        Lang::Ru => "ru",
        Lang::Uk => "uk",
        Lang::En => "en",
    };
    let meta = format!(
        "#let meta = (title: {}, lang: {}, designation: {}, document: {}, author: {}, checked: {}, organisation: {}, changes: {}, people: {}, letter: {}, sheet: {}, sheets: {}, figure: {}, table: {}, continued: {}, where: {})",
        string(&t.title),
        string(lang),
        string(designation.trim()),
        string(&document),
        string(&t.author),
        string(&t.checked),
        string(&t.organisation),
        list(&c.changes),
        list(&[c.people[0], c.people[1], "", c.people[4], c.people[5]]),
        string(c.letter),
        string(c.sheet),
        string(c.sheets),
        string(w.word(T::FigureWord)),
        string(w.word(T::TableWord)),
        string(w.word(T::TableContinued)),
        string(w.word(T::Where)),
    );
    w.doc.raw(&meta);
    w.doc.raw(include_str!("template.typ"));
}

/// The title page: the organisation, the work, the project's designation, the people.
pub(super) fn title_page(w: &mut Writer<'_, '_>) {
    let t = &w.session.scene().title;
    let line = |s: &str| format!("#{}", string(s));
    let designation = format!("{} {}", t.designation, w.word(T::NoteCode));
    let student = if t.group.is_empty() {
        t.author.clone()
    } else {
        format!("{} {}, {}", w.word(T::OfGroup), t.group, t.author)
    };
    let people = [
        (w.word(T::Student), student.as_str()),
        (w.word(T::Supervisor), t.checked.as_str()),
    ];
    let mut body = format!(
        "#page(margin: (x: 20mm, y: 20mm))[\n#set par(first-line-indent: 0mm, justify: false)\n#align(center)[#text(size: 14pt)[{}]]\n#v(55mm)\n#align(center)[#text(size: 18pt, weight: \"bold\")[{}] \\ #v(4mm) #text(size: 14pt)[{}] \\ #v(10mm) #text(size: 20pt, weight: \"bold\")[{}] \\ #v(8mm) #text(size: 14pt)[{}]]\n#v(40mm)\n#align(right)[#block(width: 90mm)[#set align(left)\n",
        line(&t.organisation),
        line(w.word(T::ExplanatoryNote)),
        line(w.word(T::ToTheCourseProject)),
        line(&t.title),
        line(designation.trim()),
    );
    for (role, name) in people {
        body.push_str(&format!("{}: {} \\\n", line(role), line(name)));
    }
    body.push_str("]]\n");
    if !t.year.is_empty() {
        body.push_str(&format!("#v(1fr)\n#align(center)[{}]\n", line(&t.year)));
    }
    body.push_str("]\n");
    w.doc.raw(&body);
}

/// The contents, on the first text page (form 2: its bottom margin clears the 40 mm block).
pub(super) fn contents(w: &mut Writer<'_, '_>) {
    w.doc.raw(&format!(
        "#page(margin: (left: 25mm, right: 10mm, top: 15mm, bottom: 50mm))[#outline(title: {}, depth: 2)]",
        text(w.word(T::Contents))
    ));
}

/// The task: the scheme, then the data of every study the scene has, each a table of
/// symbol, value and unit.
pub(super) fn task(w: &mut Writer<'_, '_>) {
    w.heading(1, T::Task);
    let scene = w.session.scene();
    if let Some(m) = &scene.mechanism {
        let scheme = S::StructuralScheme.get(w.lang);
        w.figures(
            (PlateKind::Kinematics, None),
            |own| own.starts_with(scheme),
            |own| own.to_string(),
        );
        let rows = crate::sheets::data::mechanism(m, w.lang);
        let caption = w.word(T::MechanismData);
        table_of_data(w, caption, &rows);
    }
    if let Some(f) = &scene.forces {
        let caption = w.word(T::ForcesData);
        table_of_data(w, caption, &crate::sheets::data::forces(f, w.lang));
    }
    if let Some(g) = &scene.gears {
        let caption = w.word(T::GearsData);
        table_of_data(w, caption, &gears_data(g, w.lang));
    }
    // The friction's cases, each as its sheet names it.
    if !scene.friction.is_empty() {
        w.doc.say(w.word(T::FrictionTask));
        for (n, case) in scene.friction.iter().enumerate() {
            let name = crate::sheets::friction::case_name(&case.kind, w.lang);
            let case_word = w.word(crate::sheets::captions::FrictionText::Case);
            w.doc.raw(&format!(
                "- #{}",
                text(&format!("{case_word} {}: {name}.", n + 1))
            ));
        }
        w.doc.raw("");
    }
    // The data of the other studies as their sheets print them, inputs only.
    for (kind, title) in [
        (PlateKind::Dynamics, T::Dynamics),
        (PlateKind::Cam, T::CamSection),
        (PlateKind::Balancing, T::BalancingSection),
    ] {
        if w.sheet_data(kind, true).is_empty() {
            continue;
        }
        w.doc.par(&[text(&format!("{}:", w.word(title)))]);
        w.data_list(kind, true);
    }
}

/// Symbol, value and unit of the gear pair, the wheels cut by the rack and the train's
/// wheels, each part under its name.
fn gears_data(g: &GearsSpec, lang: Lang) -> Vec<(String, String, String)> {
    let mut rows = Vec::new();
    let one = |s: &str, x: f64| (s.to_string(), fmt(x, 5, lang), String::new());
    let part = |t: T| (t.get(lang).to_string(), String::new(), String::new());
    if let Some(p) = &g.pair {
        rows.push(part(T::PairPart));
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
        rows.push(part(T::RackCutPart));
        rows.push(("m".into(), mm(r.cutting.module, lang), "mm".into()));
        rows.push(one(&format!("z_{{{}}}", r.name), f64::from(r.cutting.z)));
        rows.push(one(&format!("x_{{{}}}", r.name), r.cutting.x));
    }
    if let Some(t) = &g.planetary {
        rows.push(part(if t.train.second.is_some() {
            T::DifferentialPart
        } else {
            T::TrainPart
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

/// A table of data: symbol, value, unit.
fn table_of_data(w: &mut Writer<'_, '_>, caption: &str, rows: &[(String, String, String)]) {
    let header = [
        text(w.word(S::Quantity)),
        text(w.word(T::Value)),
        text(w.word(S::Unit)),
    ];
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|(s, v, u)| vec![label(s), text(v), label(&unit_in(u, w.lang))])
        .collect();
    w.doc.table(
        caption,
        &[Align::Left, Align::Centre, Align::Centre],
        &header,
        &body,
    );
}

/// The references: the course texts the project follows.
pub(super) fn references(w: &mut Writer<'_, '_>) {
    w.doc.raw(&format!(
        "#heading(numbering: none, {})",
        text(w.word(T::References))
    ));
    // ГОСТ Р 7.0.100 records, numbered, each as plain text (`#[…]`: no bracket of the
    // content block shown).
    for r in [
        T::Reference1,
        T::Reference2,
        T::Reference3,
        T::Reference4,
        T::Reference5,
    ] {
        w.doc.raw(&format!("+ #{}", text(w.word(r))));
    }
}
