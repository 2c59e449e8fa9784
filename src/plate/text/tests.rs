//! Tests of the lettering: its markup, its measures, its fitting.

use super::*;

fn runs(markup: &str) -> Vec<(&'static str, String)> {
    parse(markup)
        .into_iter()
        .map(|r| {
            let tag = match r.script {
                Script::Normal => "n",
                Script::Sub => "sub",
                Script::Sup => "sup",
            };
            (tag, r.text)
        })
        .collect()
}

fn expect(list: &[(&'static str, &str)]) -> Vec<(&'static str, String)> {
    list.iter().map(|(t, s)| (*t, s.to_string())).collect()
}

#[test]
fn parse_subscript_covers_one_word() {
    assert_eq!(
        runs("μ_l = 0,0025"),
        expect(&[("n", "μ"), ("sub", "l"), ("n", " = 0,0025")])
    );
    assert_eq!(runs("S_3"), expect(&[("n", "S"), ("sub", "3")]));
    assert_eq!(
        runs("b_3b_1"),
        expect(&[("n", "b"), ("sub", "3"), ("n", "b"), ("sub", "1")])
    );
    assert_eq!(
        runs("V_B2 ⊥ AB"),
        expect(&[("n", "V"), ("sub", "B2"), ("n", " ⊥ AB")])
    );
}

#[test]
fn parse_braces_and_superscripts() {
    assert_eq!(runs("S_{3}"), expect(&[("n", "S"), ("sub", "3")]));
    assert_eq!(
        runs("a^{k}_{CB}"),
        expect(&[("n", "a"), ("sup", "k"), ("sub", "CB")])
    );
    assert_eq!(runs("м/с^2"), expect(&[("n", "м/с"), ("sup", "2")]));
    assert_eq!(runs("x_{ab"), expect(&[("n", "x"), ("sub", "ab")]));
}

#[test]
fn parse_keeps_stray_markers_and_escapes() {
    assert_eq!(runs("a_ b"), expect(&[("n", "a_ b")]));
    assert_eq!(runs("x^"), expect(&[("n", "x^")]));
    assert_eq!(runs(r"a\_b"), expect(&[("n", "a_b")]));
    assert_eq!(runs("8′"), expect(&[("n", "8′")]));
    assert_eq!(runs("_{}"), expect(&[("n", "_")]));
    assert!(parse("").is_empty());
    assert_eq!(plain("μ_{l} = 1"), "μl = 1");
}

/// The box of a text as resvg draws it (its pixels at 20 per mm, those over a quarter
/// inked), sheet mm.
fn rendered_box(t: &Placed) -> Rect {
    use resvg::tiny_skia::{Pixmap, Transform};
    use resvg::usvg::{Options, Tree};
    const PX: f32 = 20.0;
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 200 100" font-family="DejaVu Sans" font-style="italic">{}</svg>"#,
        t.to_xml("t")
    );
    let opt = Options {
        fontdb: super::super::font_database(),
        ..Options::default()
    };
    let tree = Tree::from_str(&svg, &opt).expect("svg");
    let mut pixmap = Pixmap::new(200 * PX as u32, 100 * PX as u32).expect("pixmap");
    resvg::render(&tree, Transform::from_scale(PX, PX), &mut pixmap.as_mut());
    let width = pixmap.width() as usize;
    let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
    for (k, p) in pixmap.pixels().iter().enumerate() {
        if p.alpha() > 64 {
            let at = DVec2::new((k % width) as f64, (k / width) as f64);
            lo = lo.min(at);
            hi = hi.max(at + 1.0);
        }
    }
    let px = f64::from(PX);
    Rect::new(lo / px, hi / px)
}

#[test]
fn measured_boxes_hold_what_is_rendered() {
    let texts = [
        ("p ≡ b_3 ≡ d", Align::Start, 0.0),
        ("s^{″}_{3}", Align::Middle, 0.0),
        ("e^{′}_5", Align::End, 0.0),
        ("План положений, μ_l = 0,004 м/мм", Align::Middle, 0.0),
        ("8′", Align::Start, -90.0),
        ("ω_{3}(φ), dω_{3}/dφ", Align::Start, 30.0),
    ];
    for (markup, align, rotate) in texts {
        let mut t = Placed::new(DVec2::new(100.0, 50.0), markup, 3.5, align);
        t.rotate = rotate;
        let (ours, drawn) = (t.bounds(), rendered_box(&t));
        // Ours holds the ink (kerning moves glyphs by hundredths of a mm) and, unless
        // turned obliquely, is no more than the line's band larger.
        assert!(
            ours.inflate(0.1).contains(&drawn),
            "{markup}: {ours:?} does not hold {drawn:?}"
        );
        let slack = ours.size() - drawn.size();
        assert!(
            rotate % 90.0 != 0.0 || slack.max_element() < 1.5,
            "{markup}: {ours:?} vs {drawn:?}"
        );
    }
}

#[test]
fn scripts_shift_and_return_to_the_baseline() {
    let t = Placed::new(DVec2::new(10.0, 20.0), "b_3b & c", 3.5, Align::Start);
    let xml = t.to_xml("t");
    assert!(
        xml.starts_with(
            r#"<text id="t" x="10" y="20" font-size="4.8" text-anchor="start">b<tspan"#
        ),
        "{xml}"
    );
    assert!(
        xml.contains(
            r#"<tspan dy="1.44" font-size="3.36">3</tspan><tspan dy="-1.44">b &amp; c</tspan>"#
        ),
        "{xml}"
    );
}

/// A centred or end-aligned text with scripts is written from its start, so that a
/// renderer anchoring each `<tspan>` on its own (cairosvg) places it where resvg does;
/// resvg still draws it centred on (ending at) its point.
#[test]
fn scripted_texts_are_written_from_their_start() {
    let at = DVec2::new(100.0, 50.0);
    for (markup, align) in [
        (
            "μ_{φ} = 0,03491 рад/мм, μ_{S′} = 0,0007 м/мм, H_2 = 40 мм",
            Align::Middle,
        ),
        ("e^{′}_5", Align::End),
    ] {
        let t = Placed::new(at, markup, 3.5, align);
        let xml = t.to_xml("t");
        assert!(xml.contains(r#"text-anchor="start""#), "{xml}");
        let advance = measure(markup, 3.5).advance;
        let x = at.x - if align == Align::Middle { 0.5 } else { 1.0 } * advance;
        assert!(xml.contains(&format!(r#" x="{}""#, num(x))), "{xml}");
        let drawn = rendered_box(&t);
        let end = if align == Align::Middle {
            (drawn.min.x + drawn.max.x) * 0.5
        } else {
            drawn.max.x
        };
        assert!((end - at.x).abs() < 0.3, "{markup}: {drawn:?}");
    }
    // Without scripts the anchor is kept (one chunk, read alike everywhere).
    let plain = Placed::new(at, "O_", 3.5, Align::Middle).to_xml("t");
    assert!(plain.contains(r#"text-anchor="middle""#), "{plain}");
}

/// The oblique f leans into a prime set after it (f′ on the friction sheet): the prime is set
/// a hair space off, clear of the f's ink, in the SVG and in the measured box alike; a prime
/// after an upright-ending letter (φ′, s′) is left as written.
#[test]
fn a_prime_keeps_off_the_oblique_f() {
    let xml = Placed::new(DVec2::ZERO, "f′ = f/sin(β/2)", 3.5, Align::Start).to_xml("t");
    assert!(xml.contains("f\u{200A}′ = f/sin"), "{xml}");
    for plain in ["φ′ = 9,826°", "s′", "d′"] {
        let xml = Placed::new(DVec2::ZERO, plain, 3.5, Align::Start).to_xml("t");
        assert!(!xml.contains('\u{200A}'), "{xml}");
    }
    let f = measure("f", 3.5);
    let prime = glyph('′');
    let em = em_for_height(3.5);
    let prime_ink = |m: &str| {
        let pen = measure(m, 3.5).advance - prime.advance * em;
        pen + prime.ink.unwrap().0 * em
    };
    // The hair space between them, and the prime's foot where the f's hook ends (the
    // prime, leaning, moves away from the f above its foot).
    let hair = glyph('\u{200A}').advance * em;
    assert!(hair > 0.09 * em, "{hair}");
    assert!((measure("f′", 3.5).advance - f.advance - prime.advance * em - hair).abs() < 1e-12);
    let foot = prime_ink("f′");
    assert!(foot > f.max.x - 0.03 * em, "{foot} against {}", f.max.x);
}
