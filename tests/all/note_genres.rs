//! Issue 44 §3: each scene's note in its own genre. A practical work (seed 002) is reported on
//! its form — «Отчёт о практической работе № N», its topic, goal and sign-off — not as a
//! course project; a lecture case (seed 001) is worked in text with the numbers its report
//! checks; the title page speaks the note's language with the scene's own texts; the sources
//! follow the genre; the V-engine's note names no machine tool; and no formula of these
//! notes is left without its «где».

use tmm::{Drafting, Lang, Session};

/// The scene `constructions/<stem>.toml`.
fn scene(stem: &str) -> tmm::Scene {
    let path = crate::support::root().join(format!("constructions/{stem}.toml"));
    tmm::load(&path).expect("scene")
}

/// The note of `stem` in `lang`, read exactly: its source's defect list and its typeset
/// text, pages split, white space single.
fn note(stem: &str, lang: Lang) -> (Vec<String>, Vec<String>) {
    let scene = scene(stem);
    let session = Session::new(&scene, Drafting::EXACT);
    let note = tmm::note::compose(&session, lang).expect("note");
    let text = tmm::note::to_text(&note).expect("typeset");
    let pages = text
        .split(tmm::note::PAGE_BREAK)
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    (pages, note.unexplained)
}

/// The analytic value of the report's row `quantity` of `stem` (the exact drafting).
fn analytic(stem: &str, quantity: &str) -> f64 {
    let scene = scene(stem);
    let report = Session::new(&scene, Drafting::EXACT)
        .report()
        .expect("report");
    report
        .rows
        .iter()
        .find(|r| r.quantity() == quantity)
        .unwrap_or_else(|| panic!("{stem}: no row {quantity}"))
        .analytic
}

/// A number as the note's formulas print it: 5 significant digits, the decimal comma.
fn printed(x: f64) -> String {
    tmm::scale::format_sig(x, 5, Lang::Ru)
}

/// The practicum scenes and the number of seed 002's work each is.
const PRACTICUM: [(&str, u32); 7] = [
    ("gears-pz1", 1),
    ("gears-pz2", 2),
    ("gears-pz2-ex1", 2),
    ("gears-pz2-ex2", 2),
    ("gears-pz3", 3),
    ("cam-pz4", 4),
    ("cam-pz5", 5),
];

#[test]
fn a_practicum_is_reported_on_its_form_not_as_a_course_project() {
    let topics = [
        "Образование профиля зуба колеса методом обкатки",
        "Кинематический анализ планетарного механизма",
        "Расчёт геометрических параметров зубчатого зацепления",
        "Синтез кулачкового механизма с плоским толкателем",
        "Синтез кулачкового механизма с роликовым толкателем",
    ];
    for (stem, n) in PRACTICUM {
        let (ru, _) = note(stem, Lang::Ru);
        let all = ru.join(" ");
        let title = &ru[0];
        assert!(
            title.contains(&format!("Отчёт о практической работе № {n}")),
            "{stem}: {title}"
        );
        assert!(title.contains(topics[n as usize - 1]), "{stem}: {title}");
        for absent in ["курсовому проекту", "Пояснительная записка", " ПЗ "]
        {
            assert!(
                !all.contains(absent),
                "{stem}: «{absent}» in a practicum's report"
            );
        }
        for form in [
            "Цель работы и исходные данные",
            "Цель работы:",
            "Работу выполнил",
            "Работу принял",
        ] {
            assert!(all.contains(form), "{stem}: no «{form}»");
        }
        let (uk, _) = note(stem, Lang::Uk);
        assert!(
            uk[0].contains(&format!("Звіт про практичну роботу № {n}")),
            "{stem}: {}",
            uk[0]
        );
        assert!(uk.join(" ").contains("Мета роботи:"), "{stem}");
    }
    // The form's own headings: PZ1's comparison, PZ2's mobility and ratio.
    let (pz1, _) = note("gears-pz1", Lang::Ru);
    assert!(pz1
        .join(" ")
        .contains("Итоги сравнения параметров нулевого и положительного колёс"));
    let (pz2, _) = note("gears-pz2", Lang::Ru);
    assert!(pz2
        .join(" ")
        .contains("Степень подвижности и передаточное отношение механизма"));
}

#[test]
fn the_friction_note_works_each_case_with_the_reports_numbers() {
    let (ru, _) = note("friction", Lang::Ru);
    let all = ru.join(" ");
    for sentence in [
        "Угол трения определяем по коэффициенту трения:",
        "из треугольника сил Q + P + R = 0 находим силу P",
        "Клинчатый ползун ведёт себя как плоский",
        "Окружная сила на среднем радиусе резьбы",
        "касается круга трения",
        "Без катков груз скользит по плоскости",
    ] {
        assert!(all.contains(sentence), "no «{sentence}»");
    }
    // The friction angle of case 1, P up the plane, the screw's moment, the journal's
    // friction moment and W3's forces, each the report's analytic value.
    // Formulas are read without their spaces (each run of the typeset text ends in one).
    let tight: String = all.chars().filter(|c| !c.is_whitespace()).collect();
    let degrees = printed(analytic("friction", "angle_phi_up").to_degrees());
    assert!(
        tight.contains(&format!("arctg0,15={degrees}°")),
        "φ = {degrees}°"
    );
    for (q, unit) in [
        ("F_P_up", "Н"),
        ("F_P_down", "Н"),
        ("M_M20", "Н·м"),
        ("M_f_journal", "Н·м"),
        ("F_P_W3", "Н"),
        ("F_Pslide_W3", "Н"),
    ] {
        let v = printed(analytic("friction", q));
        assert!(
            tight.contains(&format!("={v}{unit}")),
            "{q} = {v} {unit} not worked"
        );
    }
}

#[test]
fn the_rotor_notes_work_the_correcting_masses() {
    let (ru, _) = note("rotor-static", Lang::Ru);
    let all = ru.join(" ");
    assert!(all.contains("Условие статического уравновешивания"));
    let tight: String = all.chars().filter(|c| !c.is_whitespace()).collect();
    let m = printed(analytic("rotor-static", "m_y"));
    assert!(
        tight.contains(&format!("={m}кг")),
        "m_у = {m} кг not worked"
    );
    let (ru, _) = note("rotor-dynamic", Lang::Ru);
    let tight: String = ru.concat().chars().filter(|c| !c.is_whitespace()).collect();
    for q in ["m_I", "m_II"] {
        let m = printed(analytic("rotor-dynamic", q));
        assert!(
            tight.contains(&format!("={m}кг")),
            "{q} = {m} кг not worked"
        );
    }
}

#[test]
fn the_title_page_speaks_the_notes_language() {
    let (uk, _) = note("shaper", Lang::Uk);
    for text in [
        "Національний технічний університет",
        "Пояснювальна записка",
        "Поперечно-стругальний верстат",
        "Виконав студент групи ТМ-21: Студент",
        "Керівник: Викладач",
        "Київ 2026",
    ] {
        assert!(
            uk[0].contains(text),
            "uk title page: no «{text}» in {}",
            uk[0]
        );
    }
    assert!(!uk[0].contains("станок"), "{}", uk[0]);
    let (en, _) = note("shaper", Lang::En);
    for text in [
        "Shaping machine",
        "Explanatory note",
        "Supervisor: Instructor",
        "Kyiv 2026",
    ] {
        assert!(
            en[0].contains(text),
            "en title page: no «{text}» in {}",
            en[0]
        );
    }
    let (ru, _) = note("shaper", Lang::Ru);
    assert!(ru[0].contains("Поперечно-строгальный станок") && ru[0].contains("Киев 2026"));
}

#[test]
fn each_genre_cites_its_own_sources() {
    let references = |stem: &str| -> String {
        let (ru, _) = note(stem, Lang::Ru);
        let all = ru.join(" ");
        let at = all
            .rfind("СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ")
            .expect("references");
        all[at..].to_string()
    };
    let course = references("shaper");
    let lecture = references("friction");
    let practicum = references("gears-pz3");
    assert!(course.contains("Кореняко") && course.contains("поперечно-строгального"));
    assert!(lecture.contains("Покровский") && !lecture.contains("Кореняко"));
    assert!(practicum.contains("Михайленко") && !practicum.contains("Кореняко"));
    for r in [&course, &lecture, &practicum] {
        assert!(
            r.contains("1. ") && r.contains("2. ") && r.contains("ГОСТ 2.105–2019"),
            "{r}"
        );
    }
    assert_ne!(lecture, practicum);
}

#[test]
fn the_v_engines_note_names_no_machine_tool() {
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let (pages, _) = note("v-engine", lang);
        let all = pages.join(" ").to_lowercase();
        for word in [
            "строгальн",
            "станок",
            "станка",
            "стругальн",
            "верстат",
            "shaping",
            "shaper",
        ] {
            assert!(
                !all.contains(word),
                "{lang:?}: «{word}» in the V-engine's note"
            );
        }
    }
    let (ru, _) = note("v-engine", Lang::Ru);
    assert!(ru.join(" ").contains("Массы звеньев и силы давления газов"));
}

#[test]
fn every_formula_of_the_lecture_and_practicum_notes_is_explained() {
    let stems = [
        "friction",
        "friction-follower",
        "rotor-static",
        "rotor-dynamic",
        "cam-central",
        "cam-flat-rocker",
        "cam-sliding",
        "gears-differential",
    ];
    let mut found = Vec::new();
    // gears-pz3's pair geometry is worked by the gears section, which explains its own.
    let practicum = PRACTICUM.map(|(s, _)| s);
    for stem in stems
        .into_iter()
        .chain(practicum.into_iter().filter(|s| *s != "gears-pz3"))
    {
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let (_, unexplained) = note(stem, lang);
            if !unexplained.is_empty() {
                found.push(format!("{stem} {lang:?}: {unexplained:?}"));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}
