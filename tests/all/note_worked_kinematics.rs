//! Issue 44 §1, the kinematics of the note worked as seed 000 works them, read off the
//! typeset text: θ from sin(θ/2) = l_AB/l_AC against the study's θ (the extremes' search, an
//! independent route), the drawn lengths of seed 000 (AB = 56, AC = 172, CD = 284 mm at
//! μ_l = 0,0025 m/mm), μ_φ = 2π/L, the similarity proportion, the Coriolis rule, the slotted
//! link's analytic loop worked at one position against its closed form, in ru, uk and en.

use crate::support;
use tmm::{Drafting, Lang, Session};

/// The note of `scene` in `lang`: its typeset text without white space (the typesetter's runs
/// split a formula's numbers and symbols) and the left sides of its formulas left
/// unexplained.
fn note(scene: &str, lang: Lang) -> (String, Vec<String>) {
    let path = support::root().join(format!("constructions/{scene}.toml"));
    let scene = tmm::load(&path).expect("scene");
    let session = Session::new(&scene, Drafting::EXACT);
    let note = tmm::note::compose(&session, lang).expect("note");
    let text = tmm::note::to_text(&note).expect("typeset");
    let text: String = text.split_whitespace().collect();
    (text, note.unexplained)
}

/// `x` with `decimals` decimals and the decimal sign of `lang`, its minus sign `−`.
fn dec(x: f64, decimals: usize, lang: Lang) -> String {
    let s = format!("{x:.decimals$}").replace('-', "−");
    match lang {
        Lang::En => s,
        _ => s.replace('.', ","),
    }
}

/// The part of `text` from the first `from` on, `len` characters long.
fn after<'a>(text: &'a str, from: &str, len: usize) -> &'a str {
    let at = text
        .find(from)
        .unwrap_or_else(|| panic!("«{from}» not in the note"));
    let end = text[at..]
        .char_indices()
        .nth(len)
        .map_or(text.len(), |(k, _)| at + k);
    &text[at..end]
}

#[test]
fn the_shaper_works_theta_lengths_scales_and_the_analytic_loop() {
    let path = support::root().join("constructions/shaper.toml");
    let scene = tmm::load(&path).expect("scene");
    let session = Session::new(&scene, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    let kin = session.kinematics(&sc).expect("kinematics");
    let theta = kin.plan.extremes.as_ref().expect("extremes").theta;
    // The closed form of a slotted link and the study's search agree: 140/430.
    let ratio = 140.0 / 430.0;
    assert!(((theta / 2.0).sin() - ratio).abs() < 1e-6, "θ = {theta}");
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let (text, _) = note("shaper", lang);
        // θ worked: 0,14/0,43 = 0,32558; θ = 2·arcsin 0,32558 = 38,002° (the study's θ, to
        // the digits shown); K = (180° + θ)/(180° − θ) = 1,5352.
        let worked = after(&text, "sinθ2=", 60);
        assert!(worked.contains(&dec(ratio, 5, lang)), "{lang:?}: {worked}");
        let arcsin = after(&text, "2⋅arcsin", 30);
        let deg = theta.to_degrees();
        assert!(
            arcsin.contains(&format!("{}={}°", dec(ratio, 5, lang), dec(deg, 3, lang))),
            "{lang:?}: {arcsin}"
        );
        let k = (180.0 + deg) / (180.0 - deg);
        assert!(text.contains(&dec(k, 4, lang)), "{lang:?}: K = {k}");
        // The drawn lengths (seed 000 §1.2.1): l/μ_l at μ_l = 0,0025 m/mm.
        for (seg, m, mm) in [("AB", 0.14, 56.0), ("AC", 0.43, 172.0), ("CD", 0.71, 284.0)] {
            let row = format!("{seg}{}{}", dec(m, 3, lang), dec(mm, 1, lang));
            assert!(text.contains(&row), "{lang:?}: no «{row}»");
        }
        // μ_φ = 2π/L: L the diagram's turn at μ_φ = 0,052 rad/mm.
        let base = std::f64::consts::TAU / 0.052;
        let phi = after(&text, "μφ=2", 60);
        assert!(
            phi.contains(&dec(std::f64::consts::TAU, 4, lang))
                && phi.contains(&dec(base, 2, lang))
                && phi.contains(&dec(0.052, 3, lang)),
            "{lang:?}: {phi}"
        );
        // The Coriolis component's direction in words, after its formula.
        let coriolis = after(&text, "akB3B1=2ω3VB3B1", 400);
        assert!(coriolis.contains("90°"), "{lang:?}: {coriolis}");
        // The analytic loop at position 3 (φ₁ = 139°), against the closed form.
        let phi1 = 139f64.to_radians();
        let (x, y) = (0.14 * phi1.cos(), 0.43 + 0.14 * phi1.sin());
        let phi3 = y.atan2(x);
        let l3 = y.hypot(x);
        let omega3 = -std::f64::consts::PI * 5.0 * 0.14 * (phi1 - phi3).cos() / l3;
        // The English textbooks write arctan where the Russian and Ukrainian write arctg.
        let arctan = if lang == Lang::En { "arctan" } else { "arctg" };
        assert_eq!(text.contains("arctg"), lang != Lang::En, "{lang:?}");
        assert_eq!(
            text.contains("tgα"),
            lang != Lang::En,
            "{lang:?}: tg α of the gears"
        );
        let loop3 = after(&text, &format!("φ3={arctan}0"), 400);
        for expected in [
            format!("={}°", dec(phi3.to_degrees(), 2, lang)),
            format!("={}", dec(l3, 4, lang)),
            format!("={}", dec(omega3, 3, lang)),
        ] {
            assert!(loop3.contains(&expected), "{lang:?}: {expected} in {loop3}");
        }
    }
}

#[test]
fn the_similarity_proportion_gives_the_plans_image() {
    let (text, _) = note("shaper", Lang::Ru);
    // pd = pb₃·CD/CB: CD = 284 mm; the result is the segment pd the plan reads (V_D/μ_v).
    let pd = after(&text, "pd=pb3⋅CD", 60);
    assert!(pd.contains("⋅284"), "{pd}");
    let vd = after(&text, "VD=pdμv=", 20);
    let read: String = vd["VD=pdμv=".len()..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == ',')
        .collect();
    assert!(pd.contains(&format!("={read}мм")), "{pd} / {vd}");
}
