//! The note's frame and its first and last sections: the page rules and the title block's
//! data, the title page, the contents, the task, the conclusions and the references.

use super::markup::{label, string, text, Align};
use super::Writer;
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::words::{unit_in, NoteText as T, Text as S};

/// The note's page rules, formulas' and tables' forms and title blocks (Typst).
pub(super) const TEMPLATE: &str = include_str!("template.typ");

/// The page rules ([`TEMPLATE`]) after the title block's data.
pub(super) fn preamble(w: &mut Writer<'_, '_>) {
    let t = w.session.scene().title.in_lang(w.lang);
    let c = crate::plate::title_block_captions(w.lang);
    let list = |xs: &[&str]| {
        let items: Vec<String> = xs.iter().map(|x| string(x)).collect();
        format!("({},)", items.join(", "))
    };
    let designation = w.designation();
    let document = format!("{}\n{}", t.title, w.document_name());
    let lang = match w.lang {
        Lang::Ru => "ru",
        Lang::Uk => "uk",
        Lang::En => "en",
    };
    let meta = format!(
        "#let meta = (title: {}, lang: {}, designation: {}, document: {}, author: {}, checked: {}, organisation: {}, changes: {}, people: {}, letter: {}, sheet: {}, sheets: {}, figure: {}, table: {}, continued: {}, where: {}, is: {})",
        string(&t.title),
        string(lang),
        string(&designation),
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
        string(w.word(T::Is)),
    );
    w.doc.raw(&meta);
    w.doc.raw(TEMPLATE);
}

/// The title page in the note's language: the university and the department, the
/// document's name after its genre (a practical work's topic), the work's title and
/// designation, the student with the group and the instructor, the city and the year; a
/// line the scene leaves empty is left out.
pub(super) fn title_page(w: &mut Writer<'_, '_>) {
    let t = w.session.scene().title.in_lang(w.lang);
    let line = |s: &str| format!("#{}", string(s));
    // «Выполнил студент группы ТМ-21: …».
    let student = if t.group.is_empty() {
        w.word(T::Student).to_string()
    } else {
        // English sets the group off: «Student, group TM-21».
        let comma = if w.lang == Lang::En { "," } else { "" };
        format!(
            "{}{comma} {} {}",
            w.word(T::Student),
            w.word(T::OfGroup),
            t.group
        )
    };
    let supervisor = match w.genre() {
        crate::scene::Genre::CourseProject => w.word(T::Supervisor),
        _ => w.word(crate::words::GenreText::Checked),
    };
    let mut body = String::from(
        "#page(margin: (x: 20mm, y: 20mm))[\n#set par(first-line-indent: 0mm, justify: false)\n",
    );
    let head: Vec<String> = [&t.university, &t.organisation]
        .into_iter()
        .filter(|s| !s.is_empty())
        .map(|s| line(s))
        .collect();
    body.push_str(&format!(
        "#align(center)[#text(size: 14pt)[{}]]\n#v(50mm)\n",
        head.join(" \\ ")
    ));
    let mut centre = vec![
        format!(
            "#text(size: 18pt, weight: \"bold\")[{}]",
            line(&w.document_name())
        ),
        format!("#text(size: 14pt)[{}]", line(w.document_of())),
    ];
    if let Some((topic, _)) = w.practicum_form() {
        let g = crate::words::GenreText::Topic;
        centre.push(format!(
            "#v(6mm) #text(size: 14pt)[{} {}]",
            line(w.word(g)),
            line(topic)
        ));
    }
    centre.push(format!(
        "#v(10mm) #text(size: 20pt, weight: \"bold\")[{}]",
        line(&t.title)
    ));
    let designation = w.designation();
    if !designation.is_empty() {
        centre.push(format!("#v(8mm) #text(size: 14pt)[{}]", line(&designation)));
    }
    body.push_str(&format!(
        "#align(center)[{}]\n#v(35mm)\n",
        centre.join(" \\ ")
    ));
    body.push_str("#align(right)[#block(width: 90mm)[#set align(left)\n");
    for (role, name) in [
        (student.as_str(), t.author.as_str()),
        (supervisor, t.checked.as_str()),
    ] {
        body.push_str(&format!("{}: {} \\\n", line(role), line(name)));
    }
    body.push_str("]]\n");
    let place: Vec<&str> = [t.city.as_str(), t.year.as_str()]
        .into_iter()
        .filter(|s| !s.is_empty())
        .collect();
    if !place.is_empty() {
        body.push_str(&format!(
            "#v(1fr)\n#align(center)[{}]\n",
            line(&place.join(" "))
        ));
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
    w.section(T::Task);
    if let Some((_, goal)) = w.practicum_form() {
        let lead = w.word(crate::words::GenreText::Goal);
        w.doc.say(&format!("{lead} {goal}"));
    }
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
        // An engine's forces are its gases' pressure, a machine tool's its resistances.
        let caption = if f.indicators.is_empty() {
            w.word(T::ForcesData)
        } else {
            w.word(crate::words::GenreText::EngineForcesData)
        };
        table_of_data(w, caption, &crate::sheets::data::forces(f, w.lang));
    }
    if let Some(g) = &scene.gears {
        let caption = w.word(T::GearsData);
        table_of_data(w, caption, &crate::sheets::data::gears(g, w.lang));
    }
    // The friction's cases, each as its sheet names it.
    if !scene.friction.is_empty() {
        w.doc.say(w.word(T::FrictionTask));
        for (n, case) in scene.friction.iter().enumerate() {
            let name = crate::sheets::friction::case_name(&case.kind, w.lang);
            let case_word = w.word(crate::words::FrictionText::Case);
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
        if w.sheet_data(kind, super::DataPart::Inputs).is_empty() {
            continue;
        }
        w.doc.par(&[text(&format!("{}:", w.word(title)))]);
        w.data_list(kind, super::DataPart::Inputs);
    }
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

/// The references: the sources of the scene's genre ([`Writer::sources`]), numbered,
/// ГОСТ Р 7.0.100 records.
pub(super) fn references(w: &mut Writer<'_, '_>) {
    w.doc.raw(&format!(
        "#heading(numbering: none, {})",
        text(w.word(T::References))
    ));
    // Each record as plain text (`#[…]`: no bracket of the content block shown).
    for r in w.sources() {
        w.doc.raw(&format!("+ #{}", text(w.word(r))));
    }
}
