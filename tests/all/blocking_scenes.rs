//! The blocking contour through scenes: `[gears.pair] choose` builds the pair on the
//! contour's choice, which works and is drawn (the largest ε_α on 13/30 and 20/40 renders, its
//! x₁, x₂ and λ in rows); a pair whose mate's tip cuts a wheel's fillet is refused with the
//! interference named.

use crate::gears::{row, run_scene};
use crate::support::{notes, num, render_svg, report_json as report, scratch};

/// `[gears.pair] choose`: the contour chooses x₁, x₂, the pair is built on them, and the
/// scene's point is that choice; criteria it cannot meet and shifts given beside it are
/// refused on their keys.
#[test]
fn the_blocking_contour_chooses_the_shifts_a_scene_asks_for() {
    let head = "[gears]\nmodule = 10.0\n[gears.pair]\nz = [13, 21]\n";
    let dir = scratch("choose");
    for (choose, tag) in [
        ("choose = \"equal-sliding\"\nx_sum = 1.078\n", "bsl"),
        ("choose = \"largest-contact-ratio\"\n", "beps"),
        ("choose = \"greatest-sum\"\nsa_min = 0.4\n", "bsum"),
    ] {
        let path = dir.join(format!("{tag}.toml"));
        std::fs::write(&path, format!("{head}{choose}")).expect("write scene");
        let v = report(path.to_str().expect("utf-8"), None);
        for q in ["eps_alpha", "s_a1", "s_a2", "dy"] {
            let (k, c) = (
                num(row(&v, &format!("{q}_bz"), "formula"), "analytic"),
                num(row(&v, &format!("{q}_{tag}"), "formula"), "analytic"),
            );
            assert!(
                (k - c).abs() <= 1e-12 * k.abs().max(1.0),
                "{tag} {q}: {k} {c}"
            );
        }
        let notes = notes(&v);
        assert!(notes.contains("chosen on the contour by"), "{notes}");
        if tag == "bsum" {
            assert!(notes.contains("s_a ≥ 0.4m"), "{notes}");
            let sa = num(row(&v, "s_a1_bz", "formula"), "analytic");
            assert!(sa >= 0.4 * 0.010 * (1.0 - 1e-9), "{sa}");
        }
    }
    let cases: &[(&str, &[&str])] = &[
        (
            "choose = \"largest-contact-ratio\"\nx = [0.5, 0.5]\n",
            &["gears.pair.x", "not both"],
        ),
        (
            "choose = \"smallest\"\n",
            &["gears.pair.choose = smallest", "equal-sliding"],
        ),
        (
            "choose = \"equal-sliding\"\n",
            &["gears.pair.x_sum", "missing"],
        ),
        (
            "choose = \"equal-sliding\"\nx_sum = 5.0\n",
            &["gears.pair.choose", "does not cross"],
        ),
        (
            "choose = \"greatest-sum\"\nsa_min = 2.0\nx_sum = 1.0\n",
            &["gears.pair.sa_min = 2", "gears.pair.x_sum"],
        ),
    ];
    for (k, (text, expected)) in cases.iter().enumerate() {
        let (ok, code, err) = run_scene(
            &format!("bad-choose-{k}"),
            &format!("{head}{text}"),
            &["check"],
        );
        assert!(!ok && code == 2, "case {k}: {code} {err}");
        for e in *expected {
            assert!(err.contains(e), "case {k}: `{e}` not in\n{err}");
        }
    }
}

/// A pair whose mate's tip cuts a wheel's fillet (meets its flank below the junction of
/// involute and fillet) is refused with the interference named: 30/76 with x = 0, −0.7
/// (wheel 1's fillet, 0.17 mm deep at m = 10 mm), on `gears.pair.x`.
#[test]
fn a_tip_that_cuts_the_mates_fillet_is_refused() {
    let text = "[gears]\nmodule = 10.0\n[gears.pair]\nz = [30, 76]\nx = [0.0, -0.7]\n";
    let (ok, code, err) = run_scene("fillet-interference", text, &["check"]);
    assert!(!ok && code == 2, "{code} {err}");
    for e in [
        "gears.pair.x",
        "interference with the fillet of wheel 1",
        "0.1692 mm below",
    ] {
        assert!(err.contains(e), "`{e}` not in\n{err}");
    }
}

/// A choice on the contour is a pair that works and is drawn: the largest ε_α on the
/// shaper's 13/30 (it lay where the mate's tip reaches N₁: λ₁(B₁) = −1.2·10⁹, and the render
/// failed blaming `gears.scale_l`) and on 20/40 renders; its x₁, x₂ and λ have rows, each
/// within 1e6 of its scale.
#[test]
fn the_largest_contact_ratio_renders() {
    let dir = scratch("largest-eps");
    for z in ["[13, 30]", "[20, 40]"] {
        let path = dir.join(format!("z{}.toml", z.replace([',', ' ', '[', ']'], "")));
        std::fs::write(
            &path,
            format!("[gears]\nmodule = 14.0\n[gears.pair]\nz = {z}\nchoose = \"largest-contact-ratio\"\n[plates]\nwanted = [\"gears\"]\n"),
        )
        .expect("write");
        render_svg(&path, &dir.join("out"), z);
        let p = path.to_str().expect("utf-8");
        let v = report(p, None);
        for q in [
            "x_1_beps",
            "x_2_beps",
            "lambda_1_beps",
            "lambda_2_beps",
            "lambda_1_bz",
        ] {
            let r = row(&v, q, "formula");
            let (g, a) = (num(r, "graphical"), num(r, "analytic"));
            assert!(g.is_finite() && g.abs() < 100.0, "{z} {q}: {g}");
            assert!((g - a).abs() <= 1e-9 * g.abs().max(1.0), "{z} {q}: {g} {a}");
        }
        for r in v["rows"].as_array().expect("rows") {
            for f in ["graphical", "analytic"] {
                let x = r[f].as_f64().unwrap_or(0.0);
                assert!(x.abs() < 1e6, "{z}: {r}");
            }
        }
    }
}
