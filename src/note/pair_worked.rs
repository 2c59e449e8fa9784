//! The pair's geometry in the note as seed 000 §4 works it, formula by formula (symbols,
//! numbers, result): the operating engagement, then each wheel's radii and tooth.

use super::markup::{frac, num, sym};
use super::worked::{deg, Printed, Worked, INV};
use super::Writer;
use crate::check::{Key, Method, Symbol};
use crate::gears::{inv, GearPair};
use crate::scale::Lang;
use crate::words::{Meaning as M, NoteText as T};

/// How the worked formulas write their numbers: five significant digits, lengths in mm.
struct Nums {
    lang: Lang,
    /// The module in mm.
    m: String,
}

impl Nums {
    fn of_pair(p: &GearPair, lang: Lang) -> Self {
        let mut f = Self {
            lang,
            m: String::new(),
        };
        f.m = f.n(p.spec.module * 1e3);
        f
    }

    /// A number.
    fn n(&self, x: f64) -> String {
        num(x, 5, self.lang)
    }

    /// The tangent of an angle (rad) in degrees.
    fn tg(&self, a: f64) -> String {
        format!("op(\"tg\") {}", deg(a, self.lang))
    }

    /// A meaning of wheel `k`.
    fn of(&self, m: M, k: usize) -> String {
        format!("{} {k}", m.get(self.lang))
    }
}

/// The pair's geometry: α_w from the involute function, y, Δy, a_w, then each wheel's r,
/// r_b, r_w, r_f, r_a, h, s, α_a and s_a, the pitches; lengths in mm.
pub(super) fn pair_geometry(w: &mut Writer<'_, '_>, p: &GearPair) {
    let f = Nums::of_pair(p, w.lang);
    w.doc.say(w.word(T::PairWorked));
    operating(w, p, &f);
    for i in 0..2 {
        wheel_radii(w, p, i, &f);
        wheel_tooth(w, p, i, &f);
    }
    let (lang, m, rack) = (w.lang, &f.m, p.spec.rack);
    w.worked(
        Worked::new(
            sym("p"),
            "π m",
            format!("π dot {m}"),
            Printed::mm(p.p, 5, f.lang),
        )
        .gives_by(Key::of_scene(Symbol::Pitch, ""), Method::Formula),
    );
    w.explain(&[("p", M::Pitch.get(lang), "mm")]);
    w.worked(
        Worked::new(
            sym("p_{b}"),
            "p cos α",
            format!("{} dot cos {}", f.n(p.p * 1e3), deg(rack.alpha, lang)),
            Printed::mm(p.p_b, 5, f.lang),
        )
        .gives_by(Key::of_scene(Symbol::Pitch, "b"), Method::Formula),
    );
    w.explain(&[("p_{b}", M::BasePitch.get(lang), "mm")]);
}

/// The operating engagement: inv α_w, y, Δy (unless the scene's table gives it), a_w.
fn operating(w: &mut Writer<'_, '_>, p: &GearPair, f: &Nums) {
    let (lang, m) = (w.lang, &f.m);
    let spec = &p.spec;
    let rack = spec.rack;
    let [z1, z2] = spec.z;
    let zs = f64::from(z1 + z2);
    let [x1, x2] = spec.x;
    w.worked(Worked::new(
        format!("{INV} {}", sym("α_{w}")),
        format!(
            "{} + {INV} α",
            frac(
                &format!("2 ({} + {}) op(\"tg\") α", sym("x_{1}"), sym("x_{2}")),
                &format!("{} + {}", sym("z_{1}"), sym("z_{2}"))
            )
        ),
        format!(
            "{} + {}",
            frac(
                &format!("2 dot ({} + {}) dot {}", f.n(x1), f.n(x2), f.tg(rack.alpha)),
                &format!("{z1} + {z2}")
            ),
            num(inv(rack.alpha), 5, lang)
        ),
        Printed::number(p.inv_w, f.lang),
    ));
    let (x1w, x2w, z1w, z2w) = (
        f.of(M::ShiftOfWheel, 1),
        f.of(M::ShiftOfWheel, 2),
        f.of(M::TeethOfWheel, 1),
        f.of(M::TeethOfWheel, 2),
    );
    w.explain(&[
        ("α_{w}", M::EngagementAngle.get(lang), "deg"),
        ("x_{1}", &x1w, ""),
        ("x_{2}", &x2w, ""),
        ("α", M::ProfileAngle.get(lang), "deg"),
        ("z_{1}", &z1w, ""),
        ("z_{2}", &z2w, ""),
    ]);
    w.worked(
        Worked::new(sym("α_{w}"), "", "", Printed::deg(p.alpha_w, lang))
            .gives_by(Key::of_scene(Symbol::EngagementAngle, "w"), Method::Formula),
    );
    w.worked(
        Worked::new(
            sym("y"),
            format!(
                "{} ({} - 1)",
                frac(&format!("{} + {}", sym("z_{1}"), sym("z_{2}")), "2"),
                frac("cos α", &format!("cos {}", sym("α_{w}")))
            ),
            format!(
                "{} ({} - 1)",
                frac(&format!("{z1} + {z2}"), "2"),
                frac(
                    &format!("cos {}", deg(rack.alpha, lang)),
                    &format!("cos {}", deg(p.alpha_w, lang))
                )
            ),
            Printed::number(p.y, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::DistanceCoefficient, ""),
            Method::Formula,
        ),
    );
    w.explain(&[("y", M::TakenUpShift.get(lang), "")]);
    if spec.dy_table.is_none() {
        w.worked(
            Worked::new(
                sym("Δy"),
                format!("{} + {} - y", sym("x_{1}"), sym("x_{2}")),
                format!("{} + {} - {}", f.n(x1), f.n(x2), f.n(p.y)),
                Printed::number(p.dy, f.lang),
            )
            .gives_by(Key::of_scene(Symbol::EqualisingShift, ""), Method::Formula),
        );
        w.explain(&[("Δy", M::EqualisingShift.get(lang), "")]);
    } else {
        let plain = |x: f64| crate::scale::format_sig(x, 5, lang);
        w.doc.say(
            &w.word(T::TableShift)
                .replace("{dy}", &plain(p.dy))
                .replace("{exact}", &plain(spec.x_sum() - p.y)),
        );
    }
    w.worked(
        Worked::new(
            sym("a_{w}"),
            format!(
                "m ({} + y)",
                frac(&format!("{} + {}", sym("z_{1}"), sym("z_{2}")), "2")
            ),
            format!("{m} dot ({} + {})", frac(&f.n(zs), "2"), f.n(p.y)),
            Printed::mm(p.a_w, 5, f.lang),
        )
        .gives_by(Key::of_scene(Symbol::CentreDistance, "w"), Method::Formula),
    );
    w.explain(&[
        ("a_{w}", M::CentreDistance.get(lang), "mm"),
        ("m", M::Module.get(lang), "mm"),
    ]);
}

/// Wheel `i`'s radii: r, r_b, r_w, r_f, r_a and the tooth's height h.
fn wheel_radii(w: &mut Writer<'_, '_>, p: &GearPair, i: usize, f: &Nums) {
    let (lang, m) = (w.lang, &f.m);
    let spec = &p.spec;
    let rack = spec.rack;
    let zs = f64::from(spec.z[0] + spec.z[1]);
    let k = i + 1;
    let (z, x) = (spec.z[i], spec.x[i]);
    let s = |name: &str| sym(&format!("{name}_{{{k}}}"));
    let ra = sym(&format!("r_{{a{k}}}"));
    w.doc.say(&format!("{} {k}:", w.word(T::WheelWord)));
    w.worked(
        Worked::new(
            sym(&format!("r_{{{k}}}")),
            frac(&format!("m {}", s("z")), "2"),
            frac(&format!("{m} dot {z}"), "2"),
            Printed::mm(p.r[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Radius, k.to_string()),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("r_{{{k}}}"), &f.of(M::PitchRadius, k), "mm")]);
    w.worked(
        Worked::new(
            sym(&format!("r_{{b{k}}}")),
            format!("{} cos α", s("r")),
            format!("{} dot cos {}", f.n(p.r[i] * 1e3), deg(rack.alpha, lang)),
            Printed::mm(p.rb[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Radius, format!("b{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("r_{{b{k}}}"), &f.of(M::BaseRadius, k), "mm")]);
    w.worked(
        Worked::new(
            sym(&format!("r_{{w{k}}}")),
            format!(
                "{} (1 + {})",
                s("r"),
                frac("2 y", &format!("{} + {}", sym("z_{1}"), sym("z_{2}")))
            ),
            format!(
                "{} dot (1 + {})",
                f.n(p.r[i] * 1e3),
                frac(&format!("2 dot {}", f.n(p.y)), &f.n(zs))
            ),
            Printed::mm(p.rw[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Radius, format!("w{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("r_{{w{k}}}"), &f.of(M::RollingRadius, k), "mm")]);
    w.worked(
        Worked::new(
            sym(&format!("r_{{f{k}}}")),
            format!(
                "{} - ({} + {} - {}) m",
                s("r"),
                sym("h^{*}_{a}"),
                sym("c^{*}"),
                s("x")
            ),
            format!(
                "{} - ({} + {} - {}) dot {m}",
                f.n(p.r[i] * 1e3),
                f.n(rack.ha),
                f.n(rack.c),
                f.n(x)
            ),
            Printed::mm(p.rf[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Radius, format!("f{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[
        (&format!("r_{{f{k}}}"), &f.of(M::RootRadius, k), "mm"),
        ("h^{*}_{a}", M::AddendumCoefficient.get(lang), ""),
        ("c^{*}", M::ClearanceCoefficient.get(lang), ""),
    ]);
    w.worked(
        Worked::new(
            sym(&format!("r_{{a{k}}}")),
            format!("{} + ({} + {} - Δ y) m", s("r"), sym("h^{*}_{a}"), s("x")),
            format!(
                "{} + ({} + {} - {}) dot {m}",
                f.n(p.r[i] * 1e3),
                f.n(rack.ha),
                f.n(x),
                f.n(p.dy)
            ),
            Printed::mm(p.ra[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Radius, format!("a{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("r_{{a{k}}}"), &f.of(M::TipRadius, k), "mm")]);
    w.worked(
        Worked::new(
            sym(&format!("h_{{{k}}}")),
            format!("{ra} - {}", sym(&format!("r_{{f{k}}}"))),
            format!("{} - {}", f.n(p.ra[i] * 1e3), f.n(p.rf[i] * 1e3)),
            Printed::mm(p.ra[i] - p.rf[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::Length, k.to_string()),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("h_{{{k}}}"), &f.of(M::ToothHeight, k), "mm")]);
}

/// Wheel `i`'s tooth: its thickness s on the pitch circle, the tip's pressure angle α_a and
/// thickness s_a.
fn wheel_tooth(w: &mut Writer<'_, '_>, p: &GearPair, i: usize, f: &Nums) {
    let (lang, m) = (w.lang, &f.m);
    let spec = &p.spec;
    let rack = spec.rack;
    let k = i + 1;
    let x = spec.x[i];
    let s = |name: &str| sym(&format!("{name}_{{{k}}}"));
    let ra = sym(&format!("r_{{a{k}}}"));
    let rb = sym(&format!("r_{{b{k}}}"));
    w.worked(
        Worked::new(
            sym(&format!("s_{{{k}}}")),
            format!("m (π/2 + 2{} op(\"tg\") α)", s("x")),
            format!("{m} dot (π/2 + 2 dot {} dot {})", f.n(x), f.tg(rack.alpha)),
            Printed::mm(p.s[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::ToothThickness, k.to_string()),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("s_{{{k}}}"), &f.of(M::PitchThickness, k), "mm")]);
    w.worked(
        Worked::new(
            sym(&format!("α_{{a{k}}}")),
            format!("arccos {}", frac(&rb, &ra)),
            format!("arccos {}", frac(&f.n(p.rb[i] * 1e3), &f.n(p.ra[i] * 1e3))),
            Printed::deg(p.alpha_a[i], lang),
        )
        .gives_by(
            Key::of_scene(Symbol::EngagementAngle, format!("a{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("α_{{a{k}}}"), &f.of(M::TipAngle, k), "deg")]);
    w.worked(
        Worked::new(
            sym(&format!("s_{{a{k}}}")),
            format!(
                "2 {ra} ({} + {INV} α - {INV} {})",
                frac(&s("s"), &format!("2{}", s("r"))),
                sym(&format!("α_{{a{k}}}"))
            ),
            format!(
                "2 dot {} dot ({} + {} - {})",
                f.n(p.ra[i] * 1e3),
                frac(&f.n(p.s[i] * 1e3), &format!("2 dot {}", f.n(p.r[i] * 1e3))),
                f.n(inv(rack.alpha)),
                f.n(inv(p.alpha_a[i]))
            ),
            Printed::mm(p.sa[i], 5, f.lang),
        )
        .gives_by(
            Key::of_scene(Symbol::ToothThickness, format!("a{k}")),
            Method::Formula,
        ),
    );
    w.explain(&[(&format!("s_{{a{k}}}"), &f.of(M::TipThickness, k), "mm")]);
}
