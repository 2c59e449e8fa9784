//! Cyrillic written in Latin letters, for the English sheets and note: a designation the
//! scene gives in Cyrillic (ТММ.КП.000) read TMM.KP.000 (ГОСТ 7.79–2000, system B, the
//! letters a designation uses; Ukrainian's own letters too): a capital before small letters
//! as a capital and small ones (Ш → Sh), else as capitals (ЩИТ → SHHIT).

/// `text` with every Cyrillic letter written in Latin letters (a capital as capitals), every
/// other character kept.
pub fn latin(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let chars: Vec<char> = text.chars().collect();
    for (k, &c) in chars.iter().enumerate() {
        let lower = c.to_lowercase().next().unwrap_or(c);
        let Some(l) = letter(lower) else {
            out.push(c);
            continue;
        };
        if c == lower {
            out.push_str(l);
        } else if chars.get(k + 1).is_some_and(|n| n.is_lowercase()) {
            // A capital before small letters: the first Latin letter capital (Ш → Sh).
            let mut it = l.chars();
            out.extend(it.next().map(|f| f.to_ascii_uppercase()));
            out.extend(it);
        } else {
            out.push_str(&l.to_uppercase());
        }
    }
    out
}

/// The Latin letters of one lower-case Cyrillic letter; `None` for any other character.
fn letter(c: char) -> Option<&'static str> {
    Some(match c {
        'а' => "a",
        'б' => "b",
        'в' => "v",
        'г' => "g",
        'ґ' => "g",
        'д' => "d",
        'е' => "e",
        'є' => "ye",
        'ё' => "yo",
        'ж' => "zh",
        'з' => "z",
        'и' => "i",
        'і' => "i",
        'ї' => "yi",
        'й' => "j",
        'к' => "k",
        'л' => "l",
        'м' => "m",
        'н' => "n",
        'о' => "o",
        'п' => "p",
        'р' => "r",
        'с' => "s",
        'т' => "t",
        'у' => "u",
        'ф' => "f",
        'х' => "x",
        'ц' => "cz",
        'ч' => "ch",
        'ш' => "sh",
        'щ' => "shh",
        'ъ' | 'ь' => "",
        'ы' => "y",
        'э' => "e",
        'ю' => "yu",
        'я' => "ya",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::latin;

    #[test]
    fn a_designation_reads_in_latin_letters() {
        assert_eq!(latin("ТММ.КП.000.08"), "TMM.KP.000.08");
        assert_eq!(latin("ТММ.КА.004"), "TMM.KA.004");
        assert_eq!(latin("КПІ.ТММ.Л18"), "KPI.TMM.L18");
        assert_eq!(latin("Шифр-12"), "Shifr-12");
        assert_eq!(latin("ЩИТ"), "SHHIT");
        assert_eq!(latin("TMM.01"), "TMM.01");
    }
}
