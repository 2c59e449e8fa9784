//! The textbook's symbols on the sheets. The domains and the reports name a quantity by its
//! [`Symbol`] and a plain subject (`F` of `in3`, `A` of `res`, `J` of `flywheel`); the
//! domains' drawings label their loads in the Russian textbooks' markup (`F_{и3}`,
//! `M_{пс}`, `J_{пр}`). Here both become the textbook symbol of the sheet's language: the
//! Russian spelling for a quantity ([`quantity`]), then every Russian subscript through the
//! table [`SUBSCRIPTS`] ([`localise`]), which every sheet's text passes on its way out.

use super::Symbol;
use crate::scale::Lang;

/// The Russian textbooks' subscripts (and superscripts) with their Ukrainian and English
/// spellings. The Ukrainian course writes its own where its textbooks do (ін — інерції, зр —
/// зрівноважувальний, зв — зведений, пк — корисного опору, о — опору, р — рушійних, л —
/// ланок), the Russian ones where the word is the same; the English course notation takes the initial of the
/// English word.
const SUBSCRIPTS: &[(&str, &str, &str)] = &[
    // инерции: the inertia force and moment, F_i, M_i.
    ("и", "ін", "i"),
    // полезного сопротивления: the useful resistance, F_r (as the resisting moment M_r).
    ("пс", "пк", "r"),
    // сопротивления (сил опору): the resisting moment and its work, M_r, A_r.
    ("с", "о", "r"),
    // движущих сил (рушійних сил): the driving moment, its work, a gas force, M_d, A_d, F_d.
    ("д", "р", "d"),
    // уравновешивающий: the balancing force and moment, and a rotor's correcting masses,
    // F_b, M_b, m_b.
    ("у", "зр", "b"),
    // приведённый: reduced to the crank, M_red, J_red.
    ("пр", "зв", "red"),
    // редуктора: the reducer's share of the reduced moment of inertia, as the dynamics'
    // data writes it: J_gr (the gear reducer; J_red is the reduced inertia itself).
    ("ред", "ред", "gr"),
    // коробки скоростей (коробки швидкостей): the gearbox's share of the reduced moment of
    // inertia, J_gb.
    ("кс", "кш", "gb"),
    // звеньев: the links' kinetic energy, T_l.
    ("зв", "л", "l"),
    // средняя: the mean angular velocity, ω_m.
    ("ср", "ср", "m"),
    // маховика: the flywheel's moment of inertia, J_fw.
    ("м", "м", "fw"),
    // ступицы (маточини): the width of the flywheel's hub, b_h.
    ("ст", "мат", "h"),
    // трения: friction, F_f, M_f and the values with friction in the pairs, R^f.
    ("тр", "тр", "f"),
    // двигателя: the motor's power, N_mot.
    ("дв", "дв", "mot"),
    // требуемое (потрібне): the ratio a required speed asks for, u^req.
    ("треб", "потр", "req"),
    // скольжения (ковзання): the force that drags a load on rollers, P_sl.
    ("ск", "ковз", "sl"),
    // ролика: a cam's roller, r_r.
    ("р", "р", "r"),
    // профиля: a cam profile's deviation, Δ_prof.
    ("проф", "проф", "prof"),
    // огибающей: a generated tooth's deviation from the exact envelope, δ_env.
    ("огиб", "обв", "env"),
    // критический: the pressure angle at which a cam's follower jams, λ_cr.
    ("кр", "кр", "cr"),
];

/// The machine's parts a constant moment of inertia may be named after (`J_{ред}`), with
/// the part's name in each language, printed beside the symbol so that the sheet explains it.
const PARTS: &[(&str, &str, &str, &str)] = &[
    ("ред", "редуктор", "редуктор", "reducer"),
    ("кс", "коробка скоростей", "коробка швидкостей", "gearbox"),
];

/// The name in `lang` of the part a constant inertia's subscript `word` names (`ред`:
/// редуктор, reducer), `None` for a name the catalogue does not know.
pub(crate) fn part(word: &str, lang: Lang) -> Option<&'static str> {
    PARTS
        .iter()
        .find(|(ru, ..)| *ru == word)
        .map(|&(_, ru, uk, en)| lang.pick(ru, uk, en))
}

/// Whether `c` is a Cyrillic letter (a Russian or Ukrainian descriptive index).
pub(crate) fn cyrillic(c: char) -> bool {
    ('\u{0400}'..='\u{04FF}').contains(&c)
}

/// A subscript or superscript's text in `lang`: its leading Russian word by [`SUBSCRIPTS`],
/// the rest (a link number, a plane) kept.
pub(crate) fn script(text: &str, lang: Lang) -> String {
    let head = text.find(|c: char| !cyrillic(c)).unwrap_or(text.len());
    let (word, rest) = text.split_at(head);
    // An abbreviation with its dots (`д.в.`, the far dwell: дальнего выстоя, дальнього
    // вистою) is a word of its own, not the subscript `д` of the driving forces.
    if rest.starts_with('.') {
        return text.to_string();
    }
    match SUBSCRIPTS.iter().find(|(ru, ..)| *ru == word) {
        Some(&(ru, uk, en)) => format!("{}{rest}", lang.pick(ru, uk, en)),
        None => text.to_string(),
    }
}

/// Label markup with every braced subscript and superscript (`_{и3}`, `^{тр}`) in `lang`.
pub(crate) fn localise(markup: &str, lang: Lang) -> String {
    if lang == Lang::Ru || !markup.chars().any(cyrillic) {
        return markup.to_string();
    }
    let mut out = String::with_capacity(markup.len());
    let mut rest = markup;
    while let Some(k) = rest.find(['_', '^']) {
        let (before, at) = rest.split_at(k);
        out.push_str(before);
        let body = &at[1..];
        match (body.strip_prefix('{'), body.find('}')) {
            (Some(inner), Some(end)) => {
                out.push_str(&at[..1]);
                out.push('{');
                out.push_str(&script(&inner[..end - 1], lang));
                out.push('}');
                rest = &body[end + 1..];
            }
            _ => {
                out.push_str(&at[..1]);
                rest = body;
            }
        }
    }
    out.push_str(rest);
    out
}

/// A row's quantity in the textbook's notation in `lang`: `V_{B3B1}`, `ω_{3}`, `R_{1-2}`,
/// `F_{и3}` (en `F_{i3}`), `M_{у}` (en `M_{b}`), `A_{с}`, `J_{м}`, `ε_{α}`, `R_{1-2}^{тр}`.
pub(crate) fn quantity(symbol: Symbol, subject: &str, lang: Lang) -> String {
    localise(&russian(symbol, subject), lang)
}

/// A plain column name (`V_B3B1`, `φ_1`) as label markup: everything after the first `_` is
/// the subscript (`V_{B3B1}`); a name in markup already or without a subscript is kept.
pub(crate) fn subscripted(name: &str) -> String {
    match name.split_once('_') {
        Some((base, sub)) if !sub.is_empty() && !sub.starts_with('{') => {
            format!("{base}_{{{sub}}}")
        }
        _ => name.to_string(),
    }
}

/// A plain name with its trailing digits as the label's subscript, the inverse of [`plain`]:
/// `ps3` → `ps_{3}`, `B1` → `B_{1}`; a name without a head of letters (a position's number
/// `12`, `8′`) or without trailing digits is kept.
pub(crate) fn indexed(name: &str) -> String {
    let head = name.trim_end_matches(|c: char| c.is_ascii_digit());
    match &name[head.len()..] {
        digits
            if !digits.is_empty() && !head.is_empty() && head.chars().all(char::is_alphabetic) =>
        {
            format!("{head}_{{{digits}}}")
        }
        _ => name.to_string(),
    }
}

/// A point's name without its markup (`S_3` → `S3`).
pub(crate) fn plain(name: &str) -> String {
    name.replace(['_', '{', '}'], "")
}

/// The Russian textbooks' spelling of a quantity.
fn russian(symbol: Symbol, subject: &str) -> String {
    // A value of the analysis with friction in the pairs: R_{1-2}^{тр}.
    if let Some(base) = subject.strip_suffix("_f") {
        return format!("{}^{{тр}}", russian(symbol, base));
    }
    // The ratio a required speed asks for: u_{18}^{треб}.
    if let Some(base) = subject.strip_suffix("_req") {
        return format!("{}^{{треб}}", russian(symbol, base));
    }
    // A value at a point of the blocking contour: its own symbol, the point named after it
    // as the contour's drawing names it: ε_{α} (K), x_{1} (ε_{α max}).
    if let Some((own, tag)) = blocking_point(subject) {
        let point = super::point_label(tag);
        return format!("{} ({point})", russian(symbol, own));
    }
    // A translating cam's shortest travel: X_{min}.
    if (symbol, subject) == (Symbol::Length, "travel_min") {
        return "X_{min}".into();
    }
    // The flywheel's outer diameter: D_{м}.
    if (symbol, subject) == (Symbol::Length, "flywheel") {
        return "D_{м}".into();
    }
    let letter = letter(symbol);
    // A reaction names two links, written apart as the textbooks do: R_{1-2}; so does the
    // arm of a reaction on a guide, as its drawing dimensions it: h_{0-5}.
    let two_links = subject
        .split_once('_')
        .is_some_and(|(a, b)| [a, b].iter().all(|x| x.parse::<u32>().is_ok()));
    let sep = if symbol == Symbol::Reaction || (symbol == Symbol::Length && two_links) {
        "-"
    } else {
        ""
    };
    let subject = match (symbol, subject) {
        (_, "") if symbol == Symbol::ProfileDeviation => "проф".to_string(),
        (_, "") => return letter.to_string(),
        (Symbol::Force | Symbol::Moment | Symbol::Length, "bal") => "у".into(),
        (Symbol::Force | Symbol::Moment, s) if s.starts_with("in") => format!("и{}", &s[2..]),
        (Symbol::Work | Symbol::Moment, "res") => "с".into(),
        (Symbol::Work | Symbol::Moment, "drive") => "д".into(),
        (Symbol::Inertia | Symbol::Moment, "red") => "пр".into(),
        (Symbol::Inertia | Symbol::Mass, "flywheel") => "м".into(),
        (Symbol::ContactRatio, "alpha") => "α".into(),
        (Symbol::Radius, "roller") => "р".into(),
        // A generated wheel's values name the wheel after the quantity's own subscript:
        // x_{min,p}, s_{a,p}, δ_{огиб,p} (the wheel `1` has none: x_{min}, s_{a1}).
        (Symbol::EnvelopeDeviation, s) => wheel("огиб", s.strip_prefix("deviation")),
        (Symbol::ShiftCoefficient, s) if s.starts_with("min") => {
            wheel("min", s.strip_prefix("min"))
        }
        // The circle's letter first (a: tip, t: pitch, b: base), then the wheel's name.
        (Symbol::ToothThickness | Symbol::SpaceWidth, s)
            if s.len() > 1 && s.is_char_boundary(1) && !s[1..].starts_with(char::is_numeric) =>
        {
            wheel(&s[..1], Some(&format!("_{}", &s[1..])))
        }
        (_, s) => s.replace('_', sep),
    };
    format!("{letter}_{{{subject}}}")
}

/// The subject of a value at a point of the blocking contour (`alpha_beps`, `1_bsl`, `bz`)
/// split into the quantity's own subject and the point's tag
/// ([`POINT_TAGS`](super::POINT_TAGS)).
fn blocking_point(subject: &str) -> Option<(&str, &str)> {
    let (own, tag) = subject.rsplit_once('_').unwrap_or(("", subject));
    super::POINT_TAGS.contains(&tag).then_some((own, tag))
}

/// A quantity's own subscript `own` and the wheel it belongs to (`rest` is `_name` or
/// empty).
fn wheel(own: &str, rest: Option<&str>) -> String {
    match rest.and_then(|r| r.strip_prefix('_')) {
        Some(w) => format!("{own},{w}"),
        None => own.to_string(),
    }
}

/// The letter of a symbol as the textbooks write it.
fn letter(symbol: Symbol) -> &'static str {
    match symbol {
        Symbol::Displacement => "S",
        Symbol::Velocity => "V",
        Symbol::Acceleration => "a",
        Symbol::AngularVelocity => "ω",
        Symbol::AngularAcceleration => "ε",
        Symbol::Force => "F",
        Symbol::Reaction => "R",
        Symbol::Moment => "M",
        Symbol::Mass => "m",
        Symbol::StaticMoment => "mρ",
        Symbol::UnbalanceMoment => "mρz",
        Symbol::Length => "h",
        Symbol::Angle | Symbol::EngagementAngle => "α",
        Symbol::Ratio => "η",
        Symbol::Power => "P",
        Symbol::Inertia => "J",
        Symbol::Work => "A",
        Symbol::EnergyChange => "ΔT",
        Symbol::Irregularity | Symbol::EnvelopeDeviation => "δ",
        Symbol::CentreDistance => "a",
        Symbol::Radius => "r",
        Symbol::ToothThickness => "s",
        Symbol::SpaceWidth => "e",
        Symbol::Pitch => "p",
        Symbol::DistanceCoefficient => "y",
        Symbol::EqualisingShift => "Δy",
        Symbol::ContactRatio => "ε",
        Symbol::SpecificSliding | Symbol::PressureAngle => "λ",
        Symbol::ShiftCoefficient => "x",
        Symbol::GearRatio => "u",
        Symbol::ActionLength => "g",
        Symbol::VelocityAnalogue => "dS/dφ",
        Symbol::AccelerationAnalogue => "d^2S/dφ^2",
        Symbol::TransmissionAngle => "γ",
        Symbol::CurvatureRadius => "ρ",
        Symbol::ProfileRadius => "R",
        Symbol::ProfileDeviation => "Δ",
        Symbol::EquilibriumResidual => "ΔΣ",
        Symbol::PowerResidual => "ΔN",
    }
}

#[cfg(test)]
mod tests {
    use super::Symbol;
    use super::{localise, quantity, subscripted};
    use crate::scale::Lang;

    #[test]
    fn quantities_take_the_textbooks_symbols() {
        let ru = |s, sub| quantity(s, sub, Lang::Ru);
        assert_eq!(ru(Symbol::Velocity, "B3_B1"), "V_{B3B1}");
        assert_eq!(ru(Symbol::AngularAcceleration, "3"), "ε_{3}");
        assert_eq!(ru(Symbol::Reaction, "1_2"), "R_{1-2}");
        assert_eq!(ru(Symbol::Reaction, "1_2_f"), "R_{1-2}^{тр}");
        // The arm of the guide's reaction as its drawing dimensions it (issue 19).
        assert_eq!(ru(Symbol::Length, "0_5"), "h_{0-5}");
        assert_eq!(ru(Symbol::Length, "bal"), "h_{у}");
        assert_eq!(ru(Symbol::Length, "travel_min"), "X_{min}");
        assert_eq!(ru(Symbol::Force, "in3"), "F_{и3}");
        assert_eq!(ru(Symbol::Moment, "bal"), "M_{у}");
        assert_eq!(ru(Symbol::Work, "res"), "A_{с}");
        assert_eq!(ru(Symbol::Moment, "drive"), "M_{д}");
        assert_eq!(ru(Symbol::Inertia, "flywheel"), "J_{м}");
        assert_eq!(ru(Symbol::Length, "flywheel"), "D_{м}");
        assert_eq!(ru(Symbol::Mass, "flywheel"), "m_{м}");
        assert_eq!(ru(Symbol::ContactRatio, "alpha"), "ε_{α}");
        assert_eq!(ru(Symbol::GearRatio, "1_8_req"), "u_{18}^{треб}");
        assert_eq!(ru(Symbol::ShiftCoefficient, "min_p"), "x_{min,p}");
        assert_eq!(ru(Symbol::ToothThickness, "ap"), "s_{a,p}");
        assert_eq!(ru(Symbol::ToothThickness, "a1"), "s_{a1}");
        assert_eq!(ru(Symbol::ToothThickness, "tp"), "s_{t,p}");
        assert_eq!(ru(Symbol::ToothThickness, "b0"), "s_{b0}");
        assert_eq!(ru(Symbol::SpaceWidth, "tp"), "e_{t,p}");
        assert_eq!(ru(Symbol::EnvelopeDeviation, "deviation"), "δ_{огиб}");
        assert_eq!(ru(Symbol::Irregularity, ""), "δ");
        // The values at the points of the blocking contour, each point named.
        assert_eq!(ru(Symbol::ContactRatio, "alpha_bz"), "ε_{α} (K)");
        assert_eq!(ru(Symbol::ToothThickness, "a1_beps"), "s_{a1} (ε_{α max})");
        assert_eq!(ru(Symbol::EngagementAngle, "w_bsl"), "α_{w} (λ_1 = λ_2)");
        assert_eq!(ru(Symbol::EqualisingShift, "bsum"), "Δy (x_{Σ max})");
        assert_eq!(ru(Symbol::ShiftCoefficient, "2_beps"), "x_{2} (ε_{α max})");
        assert_eq!(ru(Symbol::SpecificSliding, "1_bz"), "λ_{1} (K)");
        let en = |s, sub| quantity(s, sub, Lang::En);
        assert_eq!(en(Symbol::Force, "in3"), "F_{i3}");
        assert_eq!(en(Symbol::Moment, "bal"), "M_{b}");
        assert_eq!(en(Symbol::Inertia, "red"), "J_{red}");
        assert_eq!(en(Symbol::Reaction, "1_2_f"), "R_{1-2}^{f}");
    }

    #[test]
    fn a_column_name_takes_its_whole_subscript() {
        assert_eq!(subscripted("V_B3B1"), "V_{B3B1}");
        assert_eq!(subscripted("φ_1"), "φ_{1}");
        assert_eq!(subscripted("V_{S3}"), "V_{S3}");
        assert_eq!(subscripted("№"), "№");
    }

    #[test]
    fn subscripts_are_localised_and_the_rest_kept() {
        assert_eq!(localise("F_{и2} ≡ F_{пс}", Lang::En), "F_{i2} ≡ F_{r}");
        assert_eq!(
            localise("m_{уII}ρ_{уII}z_{II}", Lang::En),
            "m_{bII}ρ_{bII}z_{II}"
        );
        assert_eq!(localise("ω − ω_{ср}^2", Lang::En), "ω − ω_{m}^2");
        assert_eq!(localise("F_{и2}", Lang::Ru), "F_{и2}");
        // The dwells' abbreviations stay (uk φ_{д.в.} was written φ_{р.в.}); F_{д} does not.
        assert_eq!(
            localise("φ_{д.в.}, φ_{б.в.}, F_{д}", Lang::Uk),
            "φ_{д.в.}, φ_{б.в.}, F_{р}"
        );
        // A subscript the table does not know (a user's name) is kept.
        assert_eq!(localise("J_{кор}, b_1", Lang::En), "J_{кор}, b_1");
        assert_eq!(localise("J_{ред} + J_{кс}", Lang::En), "J_{gr} + J_{gb}");
        // The reducer's inertia and the reduced inertia are two symbols in every language.
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            assert_ne!(
                localise("J_{ред}", lang),
                quantity(Symbol::Inertia, "red", lang)
            );
        }
        // Ukrainian sheets write Ukrainian words (issue 45): коробка швидкостей, маточина,
        // ковзання, потрібне.
        assert_eq!(
            localise("J_{кс}, b_{ст}, P_{ск}, u^{треб}", Lang::Uk),
            "J_{кш}, b_{мат}, P_{ковз}, u^{потр}"
        );
        assert_eq!(super::part("кс", Lang::Uk), Some("коробка швидкостей"));
        assert_eq!(super::part("кор", Lang::En), None);
    }
}
