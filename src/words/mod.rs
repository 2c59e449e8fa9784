//! The words and the numbers every writer shares, on the ground floor beside `scale`: the
//! captions, words and symbols of the sheets, the note, the audit and the studio in the three
//! languages, in one catalogue — the words of the linkage sheets and those every sheet shares
//! ([`Text`]), the words of each machine sheet ([`machines`]), the textbook's symbols with
//! their subscripts ([`symbols`], [`Symbol`]), the blocking contour's points
//! ([`blocking_points`]) — and the numbers of the tables as they are written ([`number`]).
//! A sheet or a note writes no word of its own; this room imports nothing but `scale`.

mod audit;
mod blocking_points;
mod dxf;
mod heading;
mod linkage;
mod machines;
mod meaning_cases;
mod meaning_kinematics;
mod meaning_machines;
mod meanings;
mod method_names;
mod note;
mod note_cases;
mod note_genres;
mod note_kinematics;
mod note_machines;
pub(crate) mod number;
mod protocol;
mod studio;
mod symbol;
pub(crate) mod symbols;
mod title_block;

pub(crate) use audit::AuditText;
pub(crate) use blocking_points::{point_label, POINT_TAGS};
pub(crate) use dxf::DxfText;
pub(crate) use heading::heading;
pub(crate) use linkage::{assur_group, mechanism_class, pair_letters, redundant_reason, Text};
pub(crate) use machines::DynamicsText;
pub(crate) use machines::{CamText, FrictionText, GearText, RotorText};
pub(crate) use meaning_cases::CaseMeaning;
pub(crate) use meaning_kinematics::KinematicsMeaning;
pub(crate) use meaning_machines::MachinesMeaning;
pub(crate) use meanings::Meaning;
pub(crate) use method_names::MethodName;
pub(crate) use note::NoteText;
pub(crate) use note_cases::CaseText;
pub(crate) use note_genres::GenreText;
pub(crate) use note_kinematics::KinematicsNote;
pub(crate) use note_machines::MachinesNote;
pub(crate) use number::{md_percent, md_value, mm};
pub(crate) use protocol::StepText;
pub(crate) use studio::{StudioText, STUDIO_KEYS};
pub use symbol::Symbol;
pub(crate) use symbols::{indexed, plain, quantity, subscripted};
pub(crate) use title_block::TitleBlockText;

/// A word of the catalogue: its text in a language.
pub(crate) trait Word: Copy {
    /// The text in `lang`.
    fn get(self, lang: Lang) -> &'static str;
}

use crate::scale::Lang;

/// Declares a catalogue enum: every variant with its text in ru, uk and en (the Russian and
/// English texts are also the variant's doc), and `get(lang)`.
macro_rules! catalogue {
    (
        $(#[$meta:meta])*
        $name:ident {
            $($variant:ident => ($ru:literal, $uk:literal, $en:literal),)*
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub(crate) enum $name {
            $(#[doc = concat!("«", $ru, "» (en: “", $en, "”)")] $variant,)*
        }

        impl $name {
            /// The text in `lang`.
            pub fn get(self, lang: crate::scale::Lang) -> &'static str {
                let (ru, uk, en) = match self {
                    $($name::$variant => ($ru, $uk, $en),)*
                };
                lang.pick(ru, uk, en)
            }
        }

        impl crate::words::Word for $name {
            fn get(self, lang: crate::scale::Lang) -> &'static str {
                $name::get(self, lang)
            }
        }
    };
}
use catalogue;

/// The units' names in Latin and in Cyrillic letters (Russian and Ukrainian write them
/// alike): the sheets write the second, `tmm audit` reads either.
pub(crate) const UNIT_WORDS: [(&str, &str); 16] = [
    ("mm", "мм"),
    ("cm", "см"),
    ("m", "м"),
    ("s", "с"),
    ("N", "Н"),
    ("kN", "кН"),
    ("kgf", "кгс"),
    ("kg", "кг"),
    ("g", "г"),
    ("rad", "рад"),
    ("J", "Дж"),
    ("kJ", "кДж"),
    ("W", "Вт"),
    ("kW", "кВт"),
    ("MPa", "МПа"),
    ("Pa", "Па"),
];

/// The unit a row of `symbol` is shown in on a sheet and in the note's tables, with the
/// factor to it from SI: a length in millimetres (a drawing's unit: `4,975 мм`, not
/// `0,004975 м`), an angle in degrees (the protractor's: `29,14°`, not `0,5086 рад`), a drawn
/// envelope's deviation from the exact one in nanometres (each wheel's, whatever its size:
/// `4,402 нм`, not `0,004402 мкм`), every other quantity in its SI unit.
pub(crate) fn shown_unit(symbol: Symbol) -> (f64, &'static str) {
    match (symbol, symbol.unit()) {
        (Symbol::EnvelopeDeviation, _) => (1e9, "nm"),
        (_, "m") => (1e3, "mm"),
        (_, "rad") => (180.0 / std::f64::consts::PI, "deg"),
        (_, u) => (1.0, u),
    }
}

/// A unit written in SI (`m/s^2`, `N*m`, `kg*m^2`, `rad/s`, `mm`) in `lang`: `·` for the
/// product, the Russian and Ukrainian unit names in Cyrillic (`Н·м`, `м/с^2`, `кг·м^2`); an
/// angle in degrees (`deg`) as `°`; a nanometre (`nm`) as `нм`; a speed in revolutions per
/// minute (`rpm`) as `об/мин`, `об/хв`, `rpm`.
pub(crate) fn unit_in(unit: &str, lang: Lang) -> String {
    match (unit, lang) {
        ("deg", _) => return "°".into(),
        ("rpm", Lang::Ru) => return "об/мин".into(),
        ("rpm", Lang::Uk) => return "об/хв".into(),
        ("nm", Lang::Ru | Lang::Uk) => return "нм".into(),
        _ => {}
    }
    let si = unit.replace('*', "·");
    if lang == Lang::En {
        return si;
    }
    let mut out = String::with_capacity(si.len());
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        let name = UNIT_WORDS.iter().find(|(latin, _)| latin == word);
        out.push_str(name.map_or(word.as_str(), |(_, cyrillic)| cyrillic));
        word.clear();
    };
    for c in si.chars() {
        if c.is_ascii_alphabetic() {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::unit_in;
    use crate::scale::Lang;

    #[test]
    fn units_are_written_in_the_sheets_language() {
        assert_eq!(unit_in("N*m", Lang::Ru), "Н·м");
        assert_eq!(unit_in("kg*m^2", Lang::Uk), "кг·м^2");
        assert_eq!(unit_in("rad/s", Lang::Ru), "рад/с");
        assert_eq!(unit_in("mm", Lang::Ru), "мм");
        assert_eq!(unit_in("kg*m^2", Lang::En), "kg·m^2");
        assert_eq!(unit_in("rpm", Lang::Ru), "об/мин");
        assert_eq!(unit_in("rpm", Lang::Uk), "об/хв");
        assert_eq!(unit_in("rpm", Lang::En), "rpm");
    }
}
