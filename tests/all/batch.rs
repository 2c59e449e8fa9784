//! `tmm batch` (issue 22 §1): every variant of a class drawn from a template and a variant
//! grid, the answer key, impossible rows listed while the others are written, and a bad grid
//! refused whole with its line, column and key.

use crate::support::{report_json, rows_of, scratch, tmm};
use std::path::{Path, PathBuf};

/// The folders written under `out`, sorted.
fn folders(out: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(out)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .filter(|e| e.path().is_dir())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

/// The answer key's rows: header first, each split into its fields (no field holds a comma
/// but the diagnoses, which come last).
fn answer_key(out: &Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(out.join("answer-key.csv"))
        .expect("answer-key.csv")
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// `tmm batch TEMPLATE GRID` into a scratch folder, SVG only; it must succeed.
fn batch(name: &str, template: &str, grid: &str) -> PathBuf {
    let out = scratch(name);
    let o = run(template, grid, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

/// `tmm batch TEMPLATE GRID --out OUT --format svg`.
fn run(template: &str, grid: &str, out: &Path) -> std::process::Output {
    tmm(&[
        "batch",
        template,
        grid,
        "--out",
        out.to_str().unwrap(),
        "--format",
        "svg",
    ])
}

#[test]
fn the_shaper_grid_gives_thirty_variants_and_their_answer_key() {
    let out = batch(
        "batch-shaper",
        "constructions/shaper.toml",
        "constructions/variants/shaper.csv",
    );
    let names = folders(&out);
    assert_eq!(names.len(), 30, "{names:?}");
    for name in &names {
        // The project's eight sheets; a variant whose force plans or diagrams need more room
        // at the template's scales continues them on a sheet of their own (forces-3, …).
        let sheets: Vec<String> = std::fs::read_dir(out.join(name))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        // The kinematic analysis continues on kinematics-2 only when one A1 does not hold it
        // (the sheets are filled before a further one is begun).
        for sheet in [
            "kinematics",
            "forces",
            "forces-2",
            "cam",
            "gears",
            "dynamics",
            "flywheel",
        ] {
            assert!(
                sheets.contains(&format!("{sheet}.svg")),
                "{name}: {sheets:?}"
            );
        }
        assert!(
            sheets.contains(&"task.pdf".to_string()),
            "{name}: the task sheet"
        );
        assert!(sheets.len() <= 11, "{name}: {sheets:?}");
    }
    // The task sheet: one page, its title block naming the variant.
    let task = std::fs::read(out.join("07/task.pdf")).expect("task.pdf");
    assert!(String::from_utf8_lossy(&task).contains("/Count 1"));
    let key = answer_key(&out);
    assert_eq!(key.len(), 31);
    assert_eq!(key[0][0], "variant");
    assert!(key[0][1].starts_with("v_E@3 (m/s)"), "{:?}", key[0]);
    assert!(key[1..].iter().all(|r| r.last().unwrap() == "ok"));
    // The variants differ where the grid makes them differ (the ram's speed at position 3)
    // and agree where it does not (the gear pair).
    let column = |name: &str| key[0].iter().position(|h| h.starts_with(name)).unwrap();
    let (v, eps) = (column("v_E@3"), column("eps_alpha"));
    let distinct: std::collections::BTreeSet<&str> =
        key[1..].iter().map(|r| r[v].as_str()).collect();
    assert!(distinct.len() >= 25, "{distinct:?}");
    assert!(key[1..].iter().all(|r| r[eps] == key[1][eps]));
    // And as a sheet to print: one page of the drawing set's format.
    let pdf = std::fs::read(out.join("answer-key.pdf")).expect("answer-key.pdf");
    assert!(pdf.starts_with(b"%PDF-"));
    let text = String::from_utf8_lossy(&pdf);
    assert!(text.contains("/Count 1"), "one page");
}

#[test]
fn the_answer_key_holds_each_variants_own_report() {
    let out = batch(
        "batch-four-bar",
        "constructions/four-bar.toml",
        "constructions/variants/four-bar.csv",
    );
    assert_eq!(folders(&out).len(), 30);
    let key = answer_key(&out);
    // Variant 07 written by hand from the template (its row of the grid put in by text),
    // and its report asked for on its own.
    let grid = std::fs::read_to_string("constructions/variants/four-bar.csv").unwrap();
    let row: Vec<&str> = grid
        .lines()
        .find(|l| l.starts_with("07,"))
        .unwrap()
        .split(',')
        .collect();
    let template = std::fs::read_to_string("constructions/four-bar.toml").unwrap();
    let text = template
        .replace("length = 80.0", &format!("length = {}", row[1]))
        .replace("at = [280.0, 0.0]", &format!("at = [{}, 0.0]", row[2]))
        .replace("la = 250.0", &format!("la = {}", row[3]))
        .replace("lb = 180.0", &format!("lb = {}", row[4]))
        .replace("along = 125.0", &format!("along = {}", row[5]))
        .replace("omega = 10.0", &format!("omega = {}", row[6]));
    assert_ne!(text, template);
    let scene = scratch("batch-07").join("v07.toml");
    std::fs::write(&scene, text).unwrap();
    let report = report_json(scene.to_str().unwrap(), None);
    let ours = key.iter().find(|r| r[0] == "07").expect("variant 07");
    for (k, name) in key[0].iter().enumerate().skip(1) {
        let Some(item) = name.strip_suffix(')').and_then(|n| n.split_once(" (")) else {
            continue;
        };
        let (quantity, position) = item.0.split_once('@').unwrap();
        let row = rows_of(&report, quantity)
            .into_iter()
            .find(|r| r["position"] == position)
            .unwrap_or_else(|| panic!("{quantity}@{position}"));
        let exact = row["analytic"].as_f64().unwrap();
        let printed: f64 = ours[k].parse().unwrap();
        assert!(
            (printed - exact).abs() <= 1e-5 * exact.abs(),
            "{name}: {printed} against {exact}"
        );
    }
}

#[test]
fn a_grid_with_impossible_rows_lists_them_and_writes_the_others() {
    let dir = scratch("batch-impossible");
    let grid = dir.join("grid.csv");
    // a: a good row; b: the crank longer than the frame's other links allow (it cannot turn
    // through a full revolution); c: a negative length (refused as a scene); d: a rocker that
    // cannot reach the coupler; e: another good row.
    std::fs::write(
        &grid,
        "variant,mechanism.crank.length,mechanism.group[0].la,mechanism.group[0].lb\n\
         a,80,250,180\n\
         b,200,250,180\n\
         c,-80,250,180\n\
         d,80,250,10\n\
         e,70,240,180\n",
    )
    .unwrap();
    let out = dir.join("out");
    let o = run("constructions/four-bar.toml", grid.to_str().unwrap(), &out);
    assert_eq!(o.status.code(), Some(1), "some variants failed");
    let err = String::from_utf8_lossy(&o.stderr);
    for name in ["b", "c", "d"] {
        assert!(err.contains(&format!("variant {name}:")), "{name}: {err}");
    }
    assert!(err.contains("3 of 5 variants"), "{err}");
    assert!(
        err.contains("mechanism.crank.length"),
        "c names its key: {err}"
    );
    assert_eq!(folders(&out), ["a", "e"]);
    for name in ["a", "e"] {
        assert!(
            out.join(name).join("task.pdf").exists(),
            "{name}: its task sheet"
        );
    }
    let key = answer_key(&out);
    assert_eq!(key.len(), 6);
    for r in &key[1..] {
        let ok = r.last().unwrap() == "ok";
        assert_eq!(ok, r[0] == "a" || r[0] == "e", "{r:?}");
    }
}

#[test]
fn a_bad_grid_is_refused_whole_with_its_line_column_and_key() {
    let dir = scratch("batch-bad");
    for (csv, says) in [
        (
            "variant,mechanism.crank.length,mechanism.crank.omega\n1,80,10\n2,80\n",
            "line 3, column 3 (mechanism.crank.omega): 2 fields",
        ),
        (
            "variant,mechanism.crank.lenght\n1,80\n",
            "line 1, column 2 (mechanism.crank.lenght): the template has no `lenght`",
        ),
        (
            "variant,mechanism.crank.length\n1,80\n2,eighty\n",
            "line 3, column 2 (mechanism.crank.length): \"eighty\": expected a number",
        ),
    ] {
        let grid = dir.join("grid.csv");
        std::fs::write(&grid, csv).unwrap();
        let out = dir.join("out");
        let o = run("constructions/four-bar.toml", grid.to_str().unwrap(), &out);
        assert_eq!(o.status.code(), Some(2), "{csv}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(says), "{err}");
        assert!(!out.exists(), "nothing written");
    }
}

#[test]
fn an_answer_key_naming_a_row_the_report_lacks_is_refused() {
    let dir = scratch("batch-key");
    let template = std::fs::read_to_string("constructions/four-bar.toml").unwrap();
    let scene = dir.join("t.toml");
    std::fs::write(&scene, template.replace("\"eps_3@3\"", "\"eps_9@3\"")).unwrap();
    let grid = dir.join("grid.csv");
    std::fs::write(&grid, "variant,mechanism.crank.length\n1,80\n").unwrap();
    let out = dir.join("out");
    let o = tmm(&[
        "batch",
        scene.to_str().unwrap(),
        grid.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("answer_key.values[4] = \"eps_9@3\"") && err.contains("no such row"),
        "{err}"
    );
    assert!(!out.exists());
}

/// Issue 45: the task sheet a batch hands out draws the mechanism whole — its Assur groups
/// are the student's to find — and carries every datum the project's sheets need: the
/// shaper's gears (the pair's z and x, the train's wheels), the cam's phases and the
/// machine's ω_ср and δ, with the scene's own values.
#[test]
fn the_task_sheet_gives_the_scheme_whole_and_every_datum() {
    use tmm::scale::Lang;
    let scene =
        tmm::load(&crate::support::root().join("constructions/shaper.toml")).expect("scene");
    let session = tmm::Session::new(&scene, tmm::Drafting::EXACT);
    let sheets = tmm::sheets::task_sheet(&session, "07", Lang::Ru).expect("task sheet");
    assert_eq!(sheets.len(), 1);
    let p = &sheets[0];
    let mut texts: Vec<String> = p.views.iter().filter_map(|v| v.caption.clone()).collect();
    for v in &p.views {
        texts.extend(
            v.figure
                .steps
                .iter()
                .filter_map(|s| s.label.as_ref().map(|l| l.text.clone())),
        );
    }
    texts.extend(p.texts.iter().flat_map(|t| t.lines.iter().cloned()));
    let all = texts.join("\n");
    // The scheme whole: its caption, no group of the decomposition.
    assert!(all.contains("Кинематическая схема"), "{all}");
    assert!(!all.contains("II(2,3)") && !all.contains("I(0,1)"), "{all}");
    // The gears' tables by part, with the scene's numbers.
    let titles: Vec<&str> = p.tables.iter().map(|t| t.title.as_str()).collect();
    assert!(titles.contains(&"Зубчатая пара"), "{titles:?}");
    assert!(titles.contains(&"Планетарный редуктор"), "{titles:?}");
    let pair = p
        .tables
        .iter()
        .find(|t| t.title == "Зубчатая пара")
        .expect("pair");
    let value = |s: &str| {
        pair.rows
            .iter()
            .find(|r| r[0] == s)
            .map(|r| r[1].clone())
            .unwrap_or_default()
    };
    assert_eq!(
        (value("z_{1}"), value("x_{1}"), value("x_{2}")),
        ("13".into(), "0,8".into(), "0,471".into())
    );
    // The cam's phases and the machine's ω_ср, δ.
    assert!(all.contains("φ_{у} = 113,6°"), "{all}");
    assert!(all.contains("ω_{ср} = 15,7"), "{all}");
    assert!(all.contains("δ = 0,06667"), "{all}");
}
