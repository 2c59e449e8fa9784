//! The note's scripts in the notation of its language: every subscript and superscript the
//! markup set in the Russian textbooks' notation, written in the note's.

use crate::scale::Lang;

/// The trigonometric functions of the note's formulas in the notation of `lang`: the
/// markup writes the Russian and Ukrainian textbooks' `tg` and `arctg`; English writes `tan`
/// and `arctan`.
pub(super) fn localise_functions(source: String, lang: Lang) -> String {
    match lang {
        Lang::En => source
            .replace("op(\"arctg\")", "arctan")
            .replace("op(\"tg\")", "tan"),
        Lang::Ru | Lang::Uk => source,
    }
}

/// The note's Typst source with every subscript and superscript a label or a symbol set
/// (`#sub("и3")`, `#super("тр")`, `_(#qs[#"и3"])`) in the textbook notation of `lang` (`F_{и3}` is `F_{i3}` in English), as
/// every sheet's text is ([`crate::words::symbols`]).
pub(super) fn localise_scripts(source: &str, lang: Lang) -> String {
    const OPENS: [&str; 6] = [
        "#sub(\"",
        "#super(\"",
        "_(#qs[#\"",
        "^(#qs[#\"",
        "_(#qu[#\"",
        "^(#qu[#\"",
    ];
    let mut out = String::with_capacity(source.len());
    // Where each opening next occurs, searched again only once the text passes it: a note
    // holds thousands of scripts, and searching the rest for every opening at each one
    // cost some 50 ms of the shaper's note.
    let mut next = OPENS.map(|open| source.find(open));
    let mut at = 0;
    loop {
        for (k, open) in OPENS.iter().enumerate() {
            if next[k].is_some_and(|i| i < at) {
                next[k] = source[at..].find(open).map(|i| i + at);
            }
        }
        let first = (0..OPENS.len())
            .filter_map(|k| next[k].map(|i| (i, k)))
            .min();
        let Some((open, k)) = first else { break };
        let body = open + OPENS[k].len();
        let Some(len) = source[body..].find('"') else {
            break;
        };
        out.push_str(&source[at..body]);
        out.push_str(&crate::words::symbols::script(
            &source[body..body + len],
            lang,
        ));
        at = body + len;
    }
    out.push_str(&source[at..]);
    out
}

#[cfg(test)]
mod tests {
    use super::super::markup::{label, sym};
    use super::*;

    #[test]
    fn scripts_take_the_notation_of_the_language() {
        let src = label("F_{и3} + M_{пс}^{тр} + R_{0-5}");
        assert_eq!(
            localise_scripts(&src, Lang::En),
            r##"[#"F"#sub("i3")#" + M"#sub("r")#super("f")#" + R"#sub("0-5")]"##
        );
        assert_eq!(localise_scripts(&src, Lang::Ru), src);
        assert_eq!(
            localise_scripts(&sym("M_{пс}^{тр}"), Lang::En),
            r##"#qs[#"M"]_(#qu[#"r"])^(#qu[#"f"])"##
        );
    }
}
