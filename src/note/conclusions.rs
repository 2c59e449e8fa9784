//! The conclusions: the error of every graphical method against its analytic twin, and
//! every value of the source the project does not reproduce, with the exact value and the
//! reason, in sentences.

use super::markup::{label, text, Align};
use super::rows::{fmt, percent};
use super::Writer;
use crate::check::{Method, Symbol};
use crate::words::{mm, quantity, unit_in, NoteText as T, Text as S};

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
                text(e.worst_named().unwrap_or("—")),
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
    use crate::words::GenreText as G;
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
    let mut rows: Vec<SeedRow> = Vec::new();
    // A unit after a number, its power a superscript: `кг·м²`.
    let unit_of = |u: &str| unit_in(u, lang).replace("^2", "²");
    let mut add = |symbol: String, printed: String, exact: String, off: f64, why: &str| {
        rows.push(SeedRow {
            symbol,
            printed,
            exact,
            off,
            why: why.to_string(),
        });
    };
    let forces = scene.forces.iter().flat_map(|f| f.seed.iter());
    for s in scene.seed.iter().chain(forces) {
        let Some(r) = s.row(&w.report.rows) else {
            continue;
        };
        // The exact value in the unit the source prints (kgf, mm): like against like.
        let exact = r.analytic.abs() * s.printed_value.abs() / s.value;
        let symbol = quantity(r.key.symbol, &r.key.subject, lang);
        add(
            match &s.position {
                Some(p) => format!("{symbol} ({} {p})", w.word(T::PositionShort)),
                None => symbol,
            },
            // As the source prints it (164,944), its digits kept: none has more than six.
            format!(
                "{} {}",
                fmt(s.printed_value, 6, lang),
                unit_of(s.printed_unit)
            ),
            format!("{} {}", fmt(exact, 4, lang), unit_of(s.printed_unit)),
            (s.value - r.analytic.abs()) / r.analytic.abs(),
            s.why
                .as_ref()
                .map_or(w.word(T::SeedNoReason), |why| why.get(lang)),
        );
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
                (seed - exact) / exact,
                w.word(T::SeedFlywheel),
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
                (seed - exact) / exact,
                w.word(T::SeedContactRatio),
            );
        }
    }
    if let Some(r) = train_seed(w) {
        add(r.symbol, r.printed, r.exact, r.off, &r.why);
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
                (seed - exact) / exact,
                w.word(T::SeedMinRadius),
            );
        }
    }
    seed_list(w, &rows);
}

/// The source's values the project does not reproduce, as a numbered list of sentences:
/// each quantity, what the source gives, the exact value, how far off and why (nothing
/// without rows).
fn seed_list(w: &mut Writer<'_, '_>, rows: &[SeedRow]) {
    if rows.is_empty() {
        return;
    }
    w.doc.say(w.word(T::SeedNotReproduced));
    for r in rows {
        w.doc.raw(&format!(
            "+ #{}: #{} #{}, #{} #{} (#{} #{}~%) — #{}.",
            label(&r.symbol),
            text(w.word(T::SeedGives)),
            text(&r.printed),
            text(w.word(T::SeedExactValue)),
            text(&r.exact),
            text(w.word(T::SeedOffBy)),
            text(&percent(r.off, w.lang)),
            label(&r.why),
        ));
    }
    w.doc.raw("");
}

/// A value of the source the project does not reproduce, as the conclusions give it.
struct SeedRow {
    /// The quantity in label markup.
    symbol: String,
    /// The value the source prints.
    printed: String,
    /// The exact value.
    exact: String,
    /// (printed − exact)/exact.
    off: f64,
    /// Why, in label markup (`F_{и5}`).
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
