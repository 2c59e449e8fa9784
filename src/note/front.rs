//! The note's frame and its first and last sections: the page rules and the title block's
//! data, the title page, the contents, the task, the conclusions and the references.

use super::markup::{label, string, text, Align};
use super::rows::{fmt, percent};
use super::Writer;
use crate::check::{Method, Symbol};
use crate::gears::GearsSpec;
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::sheets::captions::{quantity, unit_in, NoteText as T, Text as S};
use crate::sheets::data::mm;

/// The page rules (`template.typ`) after the title block's data.
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
        "#let meta = (title: {}, lang: {}, designation: {}, document: {}, author: {}, checked: {}, organisation: {}, changes: {}, people: {}, letter: {}, sheet: {}, sheets: {}, figure: {}, table: {}, continued: {}, where: {})",
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
    );
    w.doc.raw(&meta);
    w.doc.raw(include_str!("template.typ"));
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
        _ => w.word(crate::sheets::captions::GenreText::Checked),
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
        let g = crate::sheets::captions::GenreText::Topic;
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
        let lead = w.word(crate::sheets::captions::GenreText::Goal);
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
            w.word(crate::sheets::captions::GenreText::EngineForcesData)
        };
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

/// The conclusions: the error of every graphical method against the analytic twin (the
/// seed's §1.6, for every quantity of the project), then what the project does not
/// reproduce of the source.
pub(super) fn conclusions(w: &mut Writer<'_, '_>) {
    w.section(T::Conclusions);
    super::practicum::summary(w);
    w.doc.say(w.word(T::ConclusionsErrors));
    let summary = w.report.summary();
    let header = [
        text(w.word(S::Quantity)),
        text(w.word(S::Method)),
        text(w.word(T::Count)),
        text(w.word(S::MeanError)),
        text(w.word(S::MaxError)),
        text(w.word(T::AtPosition)),
    ];
    let lang = w.lang;
    let symbol_of = |q: &str| {
        w.report
            .rows
            .iter()
            .find(|r| r.quantity() == q)
            .map(|r| super::rows::symbol(w, r))
            .unwrap_or_else(|| q.to_string())
    };
    let rows: Vec<Vec<String>> = summary
        .entries
        .iter()
        .map(|e| {
            vec![
                label(&symbol_of(&e.quantity)),
                text(e.method.name(lang)),
                text(&e.count.to_string()),
                text(&percent(e.mean_abs_rel, lang)),
                text(&percent(e.max_abs_rel, lang)),
                text(e.worst_position.as_deref().unwrap_or("—")),
            ]
        })
        .collect();
    let caption = w.word(T::ErrorsByQuantity);
    w.doc.table(
        caption,
        &[
            Align::Left,
            Align::Left,
            Align::Centre,
            Align::Centre,
            Align::Centre,
            Align::Centre,
        ],
        &header,
        &rows,
    );
    let by_method: Vec<Vec<String>> = summary
        .mean_by_method
        .iter()
        .map(|(m, e)| vec![text(m.name(lang)), text(&percent(*e, lang))])
        .collect();
    let caption = w.word(T::ErrorsByMethod);
    w.doc.table(
        caption,
        &[Align::Left, Align::Centre],
        &[text(w.word(S::Method)), text(w.word(S::MeanError))],
        &by_method,
    );
    let r = w.session.drafting().resolution_mm();
    if r > 0.0 {
        w.doc.say(&format!(
            "{} {} {}, {}",
            w.word(T::HandReadingLead),
            crate::scale::format_sig(r, 3, w.lang),
            unit_in("mm", w.lang),
            w.word(T::HandReadingRest)
        ));
    } else {
        w.doc.say(w.word(T::ExactReading));
    }
    seed_values(w);
    sign_off(w);
}

/// A practical work's form ends with the student's and the instructor's signatures and the
/// date (seed 002: «Роботу виконав … Дата … Роботу прийняв …»).
fn sign_off(w: &mut Writer<'_, '_>) {
    if w.practicum_form().is_none() {
        return;
    }
    use crate::sheets::captions::GenreText as G;
    let t = w.session.scene().title.in_lang(w.lang);
    // A signature's or a date's line, drawn (no underscores in the text).
    let line = "#box(width: 35mm, stroke: (bottom: 0.5pt))";
    let name = |s: &str| {
        if s.is_empty() {
            line.to_string()
        } else {
            format!("#{}", text(s))
        }
    };
    w.doc.raw(&format!(
        "#v(6mm)\n#{} {} {line} #h(8mm) #{} {line}\n",
        text(w.word(G::Done)),
        name(&t.author),
        text(w.word(G::Date))
    ));
    w.doc.raw(&format!(
        "\n#{} {} {line}\n",
        text(w.word(G::Accepted)),
        name(&t.checked)
    ));
}

/// The source's values the project does not reproduce: the value printed, the exact one,
/// how far off, and why.
fn seed_values(w: &mut Writer<'_, '_>) {
    let lang = w.lang;
    let scene = w.session.scene();
    let mut rows: Vec<Vec<String>> = Vec::new();
    // A unit after a number in a cell, its power a superscript: `кг·м²`.
    let unit_of = |u: &str| unit_in(u, lang).replace("^2", "²");
    // The reason as content: plain text, or label markup with its scripts.
    let mut add =
        |symbol: String, printed: String, exact: String, off: Option<f64>, why: String| {
            rows.push(vec![
                label(&symbol),
                text(&printed),
                text(&exact),
                text(&off.map(|d| percent(d, lang)).unwrap_or_else(|| "—".into())),
                why,
            ]);
        };
    if let Some(f) = &scene.forces {
        for s in &f.seed {
            let row = w.report.rows.iter().find(|r| {
                r.quantity() == s.quantity
                    && r.position().as_deref() == Some(s.position.as_str())
                    && s.method.is_none_or(|m| m == r.method)
            });
            if let Some(r) = row {
                let unit = unit_in(r.unit(), lang);
                add(
                    format!(
                        "{} ({} {})",
                        quantity(r.key.symbol, &r.key.subject, lang),
                        w.word(T::PositionShort),
                        s.position
                    ),
                    format!(
                        "{} {}",
                        fmt(s.printed_value, 4, lang),
                        unit_of(s.printed_unit)
                    ),
                    format!("{} {unit}", fmt(r.analytic.abs(), 4, lang)),
                    Some((s.value - r.analytic.abs()) / r.analytic.abs()),
                    s.why
                        .as_ref()
                        .map_or_else(|| text(w.word(T::SeedNoReason)), |why| label(why.get(lang))),
                );
            }
        }
    }
    let exact_of = |sym: Symbol, subject: &str, method: Method| {
        w.report
            .rows
            .iter()
            .find(|r| r.key.symbol == sym && r.key.subject == subject && r.method == method)
            .map(|r| r.analytic)
    };
    if let Some(d) = &scene.dynamics {
        if let (Some(seed), Some(exact)) = (
            d.seed.as_ref().and_then(|s| s.flywheel),
            exact_of(Symbol::Inertia, "flywheel", Method::Wittenbauer),
        ) {
            add(
                "J_{м}".into(),
                format!("{} {}", fmt(seed, 4, lang), unit_of("kg*m^2")),
                format!("{} {}", fmt(exact, 5, lang), unit_of("kg*m^2")),
                Some((seed - exact) / exact),
                text(w.word(T::SeedFlywheel)),
            );
        }
    }
    if let Some(g) = &scene.gears {
        if let (Some(seed), Some(exact)) = (
            g.seed.as_ref().and_then(|s| s.eps_alpha),
            exact_of(Symbol::ContactRatio, "alpha", Method::Formula),
        ) {
            add(
                "ε_{α}".into(),
                fmt(seed, 3, lang),
                fmt(exact, 5, lang),
                Some((seed - exact) / exact),
                label(w.word(T::SeedContactRatio)),
            );
        }
    }
    if let Some(r) = train_seed(w) {
        add(r.symbol, r.printed, r.exact, Some(r.off), label(&r.why));
    }
    if let Some(c) = &scene.cam {
        if let (Some(seed), Some(exact)) = (
            c.quoted_r_min,
            w.report
                .rows
                .iter()
                .find(|r| r.quantity() == "r_min")
                .map(|r| r.analytic),
        ) {
            add(
                "r_{min}".into(),
                format!("{} {}", mm(seed, lang), unit_of("mm")),
                format!("{} {}", mm(exact, lang), unit_of("mm")),
                Some((seed - exact) / exact),
                label(w.word(T::SeedMinRadius)),
            );
        }
    }
    seed_table(w, &rows);
}

/// The table of the source's values the project does not reproduce (nothing without rows).
fn seed_table(w: &mut Writer<'_, '_>, rows: &[Vec<String>]) {
    if rows.is_empty() {
        return;
    }
    w.doc.say(w.word(T::SeedNotReproduced));
    let header = [
        text(w.word(S::Quantity)),
        text(w.word(T::SeedPrints)),
        text(w.word(S::Exact)),
        text(w.word(T::Deviation)),
        text(w.word(T::Why)),
    ];
    let caption = w.word(T::SeedValues);
    w.doc.table(
        caption,
        &[
            Align::Left,
            Align::Centre,
            Align::Centre,
            Align::Centre,
            Align::Left,
        ],
        &header,
        rows,
    );
}

/// A row of the table of the source's values the project does not reproduce.
struct SeedRow {
    /// The quantity in label markup.
    symbol: String,
    /// The value the source prints.
    printed: String,
    /// The exact value.
    exact: String,
    /// (printed − exact)/exact.
    off: f64,
    /// Why, in label markup.
    why: String,
}

/// The train's printed ratio when Willis's relations do not reproduce it: the printed and
/// the exact value, the share off, and why (the planetary stage's ratio with the carrier
/// stopped the printed value needs, against its teeth's).
fn train_seed(w: &Writer<'_, '_>) -> Option<SeedRow> {
    let lang = w.lang;
    let study = w.session.gears().ok()?;
    let t = study.train.as_ref()?;
    let printed = t.spec.seed.u?;
    if crate::gears::TrainSeed::reproduces(printed, t.ratio) {
        return None;
    }
    let tr = &t.spec.train;
    let why = t.seed_stage().map_or_else(String::new, |s| {
        format!(
            "{} u_{{{}{}}}^{{(H)}} = {}, {} {}",
            w.word(T::SeedTrainNeeds),
            s.a,
            s.f,
            fmt(s.needed, 4, lang),
            w.word(T::SeedTrainTeeth),
            fmt(s.teeth, 4, lang)
        )
    });
    Some(SeedRow {
        symbol: format!("u_{{{}{}}}", tr.shafts[tr.input], tr.shafts[tr.output]),
        printed: fmt(printed, 4, lang),
        exact: fmt(t.ratio, 5, lang),
        off: (printed - t.ratio) / t.ratio,
        why,
    })
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
