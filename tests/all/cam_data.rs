//! Issue 45, what the cam sheets say in their data and tables, checked on the plate model:
//! - a remark on the source (the seed's lost diagrams) is the note's, never the sheet's;
//! - the roller the table reports is the roller the data line takes (0,4·r₀ or 0,8·ρ_min
//!   read), and a roller the task gives is stated as given, with no row of its own;
//! - the angle graph (λ or γ) is graduated, its limit line carries its value, and its μ is
//!   named by the angle it draws;
//! - the translating cam's travel stands dimensioned on its profile and accepted against the
//!   X_min read;
//! - the rocker's centre distance a_w is dimensioned on its combined diagram, read, checked
//!   against the twin's and worked in the note.

use tmm::cam::ANGLE_LIMIT_NOTE;
use tmm::check::Symbol;
use tmm::construct::{Drafting, Item};
use tmm::plate::Plate;
use tmm::scale::{format_sig, Lang};
use tmm::scene::PlateKind;
use tmm::study::Session;

/// The cam sheets of scene `name` in `lang`, read exactly.
fn plates(name: &str, lang: Lang) -> Vec<Plate> {
    let s = crate::support::scene(name);
    let session = Session::new(&s, Drafting::EXACT);
    tmm::build(&session, PlateKind::Cam, lang).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The explanatory note of scene `name` in Russian, read to `drafting`.
fn note_of(name: &str, drafting: Drafting) -> tmm::note::Note {
    let s = crate::support::scene(name);
    tmm::note::compose(&Session::new(&s, drafting), Lang::Ru).expect("note")
}

/// Every text line, table cell and label of `plates`.
fn words(plates: &[Plate]) -> Vec<String> {
    let mut out = Vec::new();
    for p in plates {
        out.extend(p.texts.iter().flat_map(|t| t.lines.iter().cloned()));
        for t in &p.tables {
            out.push(t.title.clone());
            out.extend(t.rows.iter().flatten().cloned());
        }
        for v in &p.views {
            out.extend(v.caption.iter().cloned());
            out.extend(
                v.figure
                    .steps
                    .iter()
                    .filter_map(|s| s.label.as_ref().map(|l| l.text.clone())),
            );
        }
    }
    out
}

#[test]
fn the_sources_lost_diagrams_are_told_in_the_note_not_on_the_sheet() {
    for name in ["cam-pz4", "cam-pz5"] {
        let on_sheet = words(&plates(name, Lang::Ru));
        assert!(
            !on_sheet.iter().any(|w| w.contains("утеряны")),
            "{name}: the source's remark is on the sheet"
        );
        let note = note_of(name, Drafting::EXACT);
        assert!(
            note.source.contains("в источнике утеряны"),
            "{name}: the note does not say the source lost its diagrams"
        );
    }
}

#[test]
fn the_roller_in_the_table_is_the_roller_the_data_take() {
    // Chosen: the data's «0,4·r₀ = …, 0,8·ρ_min = … → r_р = … мм», the table's row r_р
    // graphical the same.
    let s = crate::support::scene("cam-central");
    let session = Session::new(&s, Drafting::EXACT);
    let cam = session.cam().expect("cam");
    let row = cam
        .rows()
        .into_iter()
        .find(|r| r.key.symbol == Symbol::Radius && r.key.subject == "roller")
        .expect("the roller's row");
    assert!((row.graphical - cam.roller).abs() < 1e-12, "{row:?}");
    // 0,4·r₀ under 0,8·ρ_min read (about 28 мм): the roller is 0,4·r₀.
    assert!(
        (cam.roller - 0.4 * cam.base).abs() < 1e-12,
        "r_р = {}",
        cam.roller
    );
    let stated = format!(
        "→ r_{{р}} = {} мм",
        format_sig(cam.roller * 1e3, 4, Lang::Ru)
    );
    let data = words(&plates("cam-central", Lang::Ru));
    assert!(
        data.iter().any(|w| w.ends_with(&stated)),
        "{stated}: {data:?}"
    );
    // Given: stated as given, no row of its own.
    let s = crate::support::scene("cam-undercut");
    let session = Session::new(&s, Drafting::EXACT);
    let cam = session.cam().expect("cam");
    assert!(cam
        .rows()
        .iter()
        .all(|r| !(r.key.symbol == Symbol::Radius && r.key.subject == "roller")));
    let data = words(&plates("cam-undercut", Lang::Ru));
    assert!(
        data.iter()
            .any(|w| w.starts_with("r_{р} = 15 мм (задано);")),
        "{data:?}"
    );
}

#[test]
fn the_rollers_bound_takes_the_rho_min_the_table_reads() {
    // Read to 0,5 mm the table gives ρ_min = 61 мм (60,50 drawn, the circle fitted where
    // the drawn pitch curve bends most): the rule's bound is 0,8·61 = 48,8 мм, not
    // 0,8·60,50 = 48,40 мм, and the line says the 61 is the drawing's; the flat rocker's
    // data line reads its ρ_min as its table does.
    let read = |name: &str| {
        let s = crate::support::scene(name);
        let session = Session::new(&s, Drafting::HAND);
        let plates = tmm::build(&session, PlateKind::Cam, Lang::Ru).expect("cam");
        let cell = plates[0]
            .tables
            .iter()
            .flat_map(|t| &t.rows)
            .find(|r| r.first().is_some_and(|c| c == "ρ_{min}"))
            .and_then(|r| r.get(1).cloned())
            .expect("the table's ρ_min");
        (cell, words(&plates))
    };
    let (cell, data) = read("shaper");
    assert_eq!(cell, "61");
    assert!(
        data.iter()
            .any(|w| w.contains("0,8·ρ_{min} = 0,8·61 (графически) = 48,8 мм → r_{р} = 28,4 мм")),
        "{data:?}"
    );
    // A given roller is set against the bound the rule concludes (cam-undercut: 15 mm, an
    // undercut, against r_р ≤ 8,8 mm; before, the line gave the bounds and no conclusion).
    let (_, data) = read("cam-undercut");
    assert!(
        data.iter()
            .any(|w| w.starts_with("r_{р} = 15 мм (задано); ") && w.ends_with(" → r_{р} ≤ 8,8 мм")),
        "{data:?}"
    );
    let (cell, data) = read("cam-flat-rocker");
    assert_eq!(cell, "20,3");
    assert!(
        data.iter()
            .any(|w| w.starts_with("ρ_{min} = 20,3 мм (графически)")),
        "{data:?}"
    );
}

#[test]
fn the_angle_graph_is_graduated_its_limit_valued_its_scale_named_by_its_angle() {
    for (name, symbol, limit) in [
        ("cam-central", "λ", "λ_{max} = 30°"),
        ("shaper", "γ", "γ_{min} = 60°"),
    ] {
        let plates = plates(name, Lang::Ru);
        let view = plates
            .iter()
            .flat_map(|p| &p.views)
            .find(|v| v.figure.title == format!("{symbol}(φ)"))
            .unwrap_or_else(|| panic!("{name}: no angle graph"));
        let ticks: Vec<String> = view
            .figure
            .steps
            .iter()
            .filter(|s| s.note.starts_with("tick "))
            .filter_map(|s| s.label.as_ref().map(|l| l.text.clone()))
            .collect();
        assert!(ticks.len() >= 5, "{name}: {ticks:?}");
        assert_eq!(ticks[..3], ["10", "20", "30"], "{name}");
        let lim = view
            .figure
            .steps
            .iter()
            .find(|s| s.note == ANGLE_LIMIT_NOTE)
            .and_then(|s| s.label.as_ref())
            .map(|l| l.text.as_str());
        assert_eq!(lim, Some(limit), "{name}");
        let caption = view.caption.as_deref().unwrap_or("");
        assert!(
            caption.ends_with(&format!("μ_{{{symbol}}} = 1 °/мм")),
            "{name}: {caption}"
        );
    }
}

#[test]
fn the_translating_cam_dimensions_its_travel_and_accepts_it() {
    let s = crate::support::scene("cam-sliding");
    let session = Session::new(&s, Drafting::EXACT);
    let special = session
        .special_cam()
        .expect("cam")
        .expect("a translating cam");
    let (read, _) = special.travel_min().expect("X_min");
    let accepted = format!(
        "X = 360 мм ≥ X_{{min}} = {} мм",
        format_sig(read * 1e3, 4, Lang::Ru)
    );
    assert!(read < 0.36, "X_min read {read}");
    let plates = plates("cam-sliding", Lang::Ru);
    let data = words(&plates);
    assert!(data.contains(&accepted), "{accepted}: {data:?}");
    let dimensioned = plates.iter().flat_map(|p| &p.views).any(|v| {
        v.figure.steps.iter().any(|s| {
            s.note == tmm::cam::sliding::TRAVEL_X_NOTE
                && matches!(s.item, Item::Dimension { from, to, .. }
                    if ((to - from).length() - 360.0).abs() < 1e-6)
                && s.label.as_ref().is_some_and(|l| l.text == "X = 360 мм")
        })
    });
    assert!(dimensioned, "no X = 360 мм dimension at 1:1 on the profile");
}

/// Seed 002 (4.2): where the law's d²S/dφ² is integrated at a μ_S the scene does not give,
/// μ_S = h / y_max — the S diagram's caption writes it with its numbers, the far dwell reads
/// the stroke, and the note works it; a scene's μ_S (the cusp) stays as given.
#[test]
fn the_displacement_scale_is_found_from_the_stroke() {
    for (name, stroke_mm) in [("cam-pz4", 38.0), ("cam-sliding", 30.0), ("shaper", 52.36)] {
        let s = crate::support::scene(name);
        let session = Session::new(&s, Drafting::HAND);
        let cam = match session.cam() {
            Ok(c) => c.diagrams.clone(),
            Err(_) => session
                .special_cam()
                .expect("cam")
                .expect("special")
                .diagrams
                .clone(),
        };
        let y = cam.y_max.unwrap_or_else(|| panic!("{name}: μ_S given"));
        let top = cam.s.iter().fold(0.0f64, |m, &x| m.max(x));
        assert!(
            (top * 1e3 - stroke_mm).abs() < 0.01,
            "{name}: S reaches {top}"
        );
        let mu = format_sig(cam.s_scale.value(), 4, Lang::Ru);
        let caption = format!(
            "/y_{{max}} = {}/{} = {mu}",
            format_sig(top, 4, Lang::Ru),
            format_sig(y, 4, Lang::Ru)
        );
        let sheet = words(&tmm::build(&session, PlateKind::Cam, Lang::Ru).expect("sheet"));
        assert!(
            sheet.iter().any(|w| w.contains(&caption)),
            "{name}: no «{caption}»"
        );
        let note = tmm::note::compose(&session, Lang::Ru).expect("note");
        let said = note
            .source
            .contains("наибольшая ордината диаграммы перемещений");
        assert!(said, "{name}: the note does not work μ_S out of y_max");
    }
    let cusp = crate::support::scene("cam-cusp");
    let session = Session::new(&cusp, Drafting::HAND);
    let d = &session.cam().expect("cam").diagrams;
    assert_eq!(d.y_max, None);
    assert!((d.s_scale.value() - 0.002).abs() < 1e-15);
}

/// One symbol, one quantity (the review's C4): a flat face's given margin is the admitted
/// [ρ] on the data line and the combined diagram, the profile's least radius of curvature
/// the ρ_min of the results table — never both ρ_min.
#[test]
fn a_flat_faces_admitted_radius_is_not_its_least_radius() {
    for (name, given) in [("cam-pz4", "10"), ("cam-cusp", "5")] {
        let sheet = words(&plates(name, Lang::Ru));
        let admitted = format!("[ρ] = {given} мм");
        assert!(
            sheet.iter().any(|w| w.contains(&admitted)),
            "{name}: no «{admitted}»"
        );
        let twice = format!("ρ_{{min}} = {given} мм");
        assert!(
            !sheet.iter().any(|w| w.contains(&twice)),
            "{name}: «{twice}»"
        );
        assert!(
            sheet.iter().any(|w| w.contains("ρ_{min}")),
            "{name}: no ρ_min row"
        );
    }
}

/// One notation through the sheet and the note (issue 45): the pressure angle is λ with its
/// limit λ_max on both (the note wrote ϑ).
#[test]
fn the_note_names_the_pressure_angle_as_the_sheet_does() {
    let s = crate::support::scene("cam-pz5");
    let session = Session::new(&s, Drafting::HAND);
    let sheet = words(&tmm::build(&session, PlateKind::Cam, Lang::Ru).expect("sheet"));
    assert!(sheet.iter().any(|w| w.contains("λ")), "the sheet's angle");
    let note = tmm::note::compose(&session, Lang::Ru).expect("note");
    assert!(note.source.contains("λ ≤ λ"), "the note's bound");
    assert!(!note.source.contains('ϑ'), "ϑ in the note");
}

/// Under force closure the note's angle table gives no verdict off the rise, where the angle
/// does not bind (PZ5's return reached 37° «нарушено» beside «the extreme keeps the limit»).
#[test]
fn the_note_judges_the_angle_only_where_it_binds() {
    let note = note_of("cam-pz5", Drafting::HAND);
    assert!(!note.source.contains("нарушено"), "a return point judged");
    assert!(note.source.contains("выполнено"), "no rise point judged");
}

/// Under force closure the dash is explained under the table and the extreme is the rise's
/// (the note said «на всём цикле» of an extreme taken on the rise).
#[test]
fn the_note_says_why_a_point_has_no_verdict_and_where_the_extreme_is() {
    let note = note_of("cam-pz5", Drafting::HAND);
    assert!(
        note.source.contains("Прочерк в графе допустимости"),
        "the dash unexplained"
    );
    assert!(
        note.source.contains("на фазе удаления, включая"),
        "the rise's extreme"
    );
    assert!(
        !note.source.contains("на всём цикле"),
        "the whole cycle's extreme"
    );
    // Under form closure the limit binds on the whole cycle: no dash, the cycle's extreme.
    let note = note_of("cam-central", Drafting::HAND);
    assert!(!note.source.contains("Прочерк в графе допустимости"));
}

/// The note's tables by position show a length as the sheets do, in millimetres, each
/// quantity at one precision (issue 45: PZ5's S read 0,001208 м), and the angles once, in
/// degrees, in the table of their own.
#[test]
fn the_notes_cam_tables_show_lengths_in_mm_at_one_precision() {
    let note = note_of("cam-pz5", Drafting::HAND);
    let text: String = tmm::note::to_text(&note)
        .expect("typeset")
        .split_whitespace()
        .collect();
    assert!(text.contains("S,мм(гр.)"), "S not in mm");
    assert!(!text.contains(",м(гр.)"), "a length in metres");
    // The far dwell (positions 8 and 9) at the stroke, 30 mm, at the column's two decimals,
    // both routes, then their difference 0.
    assert_eq!(text.matches("30,0030,000").count(), 2, "the far dwell's S");
    assert!(!text.contains("рад(гр.)"), "an angle in radians");
    assert_eq!(text.matches("(почертежу)").count(), 1, "the angles twice");
}

/// The analogues' scales in one unit on the sheet and in the note (issue 45: the sheet wrote
/// μ_S′ in м/мм, the note in м/(рад·мм)).
#[test]
fn the_analogues_scales_have_the_notes_units_on_the_sheet() {
    for name in ["cam-pz5", "cam-central"] {
        let on_sheet = words(&plates(name, Lang::Ru));
        for (mu, unit) in [("μ_{S′}", "м/(рад·мм)"), ("μ_{S″}", "м/(рад^2·мм)")]
        {
            let caption = on_sheet
                .iter()
                .find(|w| w.contains(mu))
                .unwrap_or_else(|| panic!("{name}: no {mu}"));
            assert!(caption.contains(unit), "{name}: «{caption}»");
        }
        let note = note_of(name, Drafting::EXACT);
        assert!(
            note.source.contains("м/(рад·мм)"),
            "{name}: the note's unit"
        );
    }
}

#[test]
fn a_flat_faces_combined_curve_is_smooth_and_its_given_centre_is_told() {
    // The flat face's S(d²S/dφ²) is a French curve through its points (a polyline spiked at
    // S″'s extremes); on cam-cusp, whose r₀ = 10 мм lies under r_min, the data say what the
    // O₁′ marked on the combined diagram is. cam-pz4 (r₀ accepted) marks no O₁′ and says none.
    for (name, under) in [("cam-cusp", true), ("cam-pz4", false)] {
        let plates = plates(name, Lang::Ru);
        let steps: Vec<_> = plates[0]
            .views
            .iter()
            .flat_map(|v| &v.figure.steps)
            .collect();
        let curve: Vec<_> = steps
            .iter()
            .filter(|s| s.note == "combined diagram S(d²S/dφ²)")
            .collect();
        assert!(!curve.is_empty(), "{name}");
        assert!(
            curve.iter().all(|s| matches!(s.item, Item::Curve { .. })),
            "{name}: {:?}",
            curve.iter().map(|s| &s.item).collect::<Vec<_>>()
        );
        let marked = steps
            .iter()
            .any(|s| s.label.as_ref().is_some_and(|l| l.text == "O_1′"));
        let told = words(&plates)
            .iter()
            .any(|w| w.contains("центр O_{1}′ в недопустимой зоне"));
        assert_eq!((marked, told), (under, under), "{name}");
    }
}

#[test]
fn the_points_table_writes_each_reading_to_its_step_and_a_rigid_shock_infinite() {
    // The table of the points read to 0,5 mm: cam-cusp's S, read off its given diagram at
    // μ_S = 0,002 м/мм, to whole millimetres (before: «0,00 / 1,00 / 3,00», a precision the
    // drawing does not give); cam-shock's uniform law has d²S/dφ² infinite at the ends of
    // its phases, as its diagram's arrows «∞» say (before: «0,00»), signed as they point: up
    // where dS/dφ jumps up (the rise's start, the return's end), down where it jumps down
    // (before: an unsigned «∞» beside arrows pointing both ways).
    let column = |name: &str, drafting: Drafting, head: &str| {
        let s = crate::support::scene(name);
        let session = Session::new(&s, drafting);
        let plates = tmm::build(&session, PlateKind::Cam, Lang::Ru).expect("cam");
        let table = plates
            .iter()
            .flat_map(|p| &p.tables)
            .find(|t| t.title.starts_with("Точки диаграмм"))
            .expect("the points table");
        let k = table.columns.iter().position(|c| c.0 == head).expect(head);
        table.rows.iter().map(|r| r[k].clone()).collect::<Vec<_>>()
    };
    let s = column("cam-cusp", Drafting::HAND, "S, мм");
    assert_eq!(s[..5], ["0", "0", "1", "3", "6"]);
    let d2s = column("cam-shock", Drafting::EXACT, "d^2S/dφ^2, мм");
    let infinite: Vec<(usize, &str)> = (0..d2s.len())
        .filter(|&k| d2s[k].ends_with('∞'))
        .map(|k| (k, d2s[k].as_str()))
        .collect();
    assert_eq!(
        infinite,
        [(0, "+∞"), (8, "−∞"), (9, "−∞"), (17, "+∞")],
        "{d2s:?}"
    );
}

#[test]
fn the_rockers_centre_distance_is_dimensioned_read_and_checked() {
    // The rocker's combined diagram finds the cam's centre O₁; the textbook reads off it r_min
    // and the centre distance a_w = O₁O₂·μ_S the profile is built on. Before, O₁O₂ was drawn
    // undimensioned and a_w was nowhere.
    let s = crate::support::scene("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let cam = session.cam().expect("cam");
    let rows = cam.rows();
    let row = (rows.iter())
        .find(|r| r.key.symbol == Symbol::CentreDistance && r.key.subject == "w")
        .expect("an a_w row");
    let exact = cam.exact_centre_distance().expect("a rocker's a_w");
    assert_eq!(row.analytic, exact);
    // The exact centre is r_min from A₀ = (0, L): a_w − L ≤ r_min ≤ a_w + L, and the drawing's
    // a_w within 0,5 % of it (r_min's own error is 0,9 %).
    let (arm, r_min) = (0.12, cam.exact_r_min());
    assert!(
        (exact - arm).abs() <= r_min && r_min <= exact + arm,
        "{exact} {r_min}"
    );
    assert!(
        (row.graphical / exact - 1.0).abs() < 5e-3,
        "{} {exact}",
        row.graphical
    );
    // The dimension O₁O₂ is the drawn centre distance at μ_S.
    let mu = cam.diagrams.s_scale.value();
    let dim = (cam.radius.figure.steps.iter())
        .find_map(|st| match st.item {
            Item::Dimension { from, to, .. } if st.note == tmm::cam::A_W_NOTE => {
                Some(from.distance(to))
            }
            _ => None,
        })
        .expect("the a_w dimension");
    assert!((dim * mu / row.graphical - 1.0).abs() < 1e-12);
    // The sheet writes it on the dimension and in its data, graphical beside exact.
    let on_sheet = words(&plates("shaper", Lang::Ru));
    let read = format_sig(row.graphical * 1e3, 4, Lang::Ru);
    let wanted = [
        format!("a_{{w}} = {read} мм"),
        format!(
            "a_{{w}} = {read} мм (графически), {} мм (точно)",
            format_sig(exact * 1e3, 4, Lang::Ru)
        ),
    ];
    for w in &wanted {
        assert!(on_sheet.contains(w), "no «{w}» on the sheet");
    }
    // The note works it beside r_min, the segment O₁O₂ named for what it is.
    let note = note_of("shaper", Drafting::EXACT).source;
    for w in [
        "межосевое расстояние",
        "отрезок от центра кулачка до центра качания коромысла",
    ] {
        assert!(note.contains(w), "the note lacks «{w}»");
    }
    // A translating follower has no centre distance to read.
    let s = crate::support::scene("cam-central");
    let central = Session::new(&s, Drafting::EXACT);
    let cam = central.cam().expect("cam");
    assert!(cam.exact_centre_distance().is_none());
    assert!(!cam
        .rows()
        .iter()
        .any(|r| r.key.symbol == Symbol::CentreDistance));
}
