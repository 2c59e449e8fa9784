//! A table's heading as ГОСТ 2.105 writes it: the heads of columns and rows begin with a
//! capital letter. One rule for the sheets' tables and the note's.

/// `text` with its first letter capital when it begins with a word: a phrase (a word, a
/// space, more: «a link's length»), three or more letters, or an abbreviation of two
/// («ед.», «пол.»), all small Latin or Cyrillic letters. A symbol (a Greek letter: `δ ср., %`,
/// `φ_{1}, °`), a plan's segment (`pd`) or a unit (`мм`) is left as it is.
pub(crate) fn heading(text: &str) -> String {
    let greek = |c: char| ('\u{370}'..='\u{3ff}').contains(&c);
    let letters = (text.chars())
        .take_while(|&c| c.is_alphabetic() && !greek(c))
        .count();
    let after = text.chars().nth(letters);
    // A phrase's second word has two letters or more: `x m` (the shift times the module)
    // is a product of symbols.
    let next = (text.chars().skip(letters + 1))
        .take_while(|&c| c.is_alphabetic() && !greek(c))
        .count();
    let phrase = letters > 0 && after == Some(' ') && next >= 2;
    let abbreviation = letters == 2 && after == Some('.');
    let small = text.chars().take(letters).all(char::is_lowercase);
    if !(small && (phrase || letters >= 3 || abbreviation)) {
        return text.to_string();
    }
    let mut chars = text.chars();
    let first = chars.next().map(char::to_uppercase);
    first.into_iter().flatten().chain(chars).collect()
}

#[cfg(test)]
mod tests {
    use super::heading;

    #[test]
    fn a_heading_begins_with_a_capital_unless_it_begins_with_a_symbol_or_a_unit() {
        for (given, written) in [
            ("величина", "Величина"),
            ("пол.", "Пол."),
            ("ед.", "Ед."),
            ("a link's length", "A link's length"),
            ("on the drawing, mm", "On the drawing, mm"),
            ("graphical", "Graphical"),
            ("δ ср., %", "δ ср., %"),
            ("φ_{1}, °", "φ_{1}, °"),
            ("x_{1}", "x_{1}"),
            ("x m", "x m"),
            ("в точке B", "В точке B"),
            ("pd", "pd"),
            ("мм", "мм"),
            ("№", "№"),
            ("Размер", "Размер"),
        ] {
            assert_eq!(heading(given), written, "{given}");
        }
    }
}
