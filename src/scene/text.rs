//! What a scene's text may hold. Every string of a scene (a title, a name, a note, a word)
//! becomes text on a sheet, in a note's typesetting and in a PDF: no control characters, at
//! most [`MAX_TEXT_CHARS`] characters (a title block's field holds far fewer; a PDF string
//! holds at most 65 535 bytes), and no character carrying more than [`MAX_MARKS`] combining
//! marks (Unicode's stream-safe limit, UAX #15: the typesetter's cost grows with a cluster's
//! length squared).

use unicode_segmentation::UnicodeSegmentation as _;

/// The most characters a string of a scene may hold.
pub const MAX_TEXT_CHARS: usize = 1000;

/// The most combining marks (characters after the first of a cluster) one character may carry.
pub const MAX_MARKS: usize = 30;

/// Whether `c` cannot be text: a control character or a noncharacter.
pub(super) fn not_text(c: char) -> bool {
    c.is_control() || c == '\u{fffe}' || c == '\u{ffff}'
}

/// Why the string `s` cannot be a scene's text (see the module's documentation), or `None`.
pub(super) fn refused(s: &str) -> Option<String> {
    if s.chars().any(not_text) {
        return Some(
            "expected text without control characters (U+0000–U+001F, U+007F–U+009F)".into(),
        );
    }
    let n = s.chars().count();
    if n > MAX_TEXT_CHARS {
        return Some(format!("{n} characters: expected at most {MAX_TEXT_CHARS}"));
    }
    let marks = s
        .graphemes(true)
        .map(|g| g.chars().count() - 1)
        .max()
        .unwrap_or(0);
    (marks > MAX_MARKS)
        .then(|| format!("a character with {marks} combining marks: expected at most {MAX_MARKS}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_bounded_in_length_and_in_marks() {
        assert_eq!(refused("Шарнирный четырёхзвенник ω₁ й"), None);
        assert_eq!(refused(&"Я".repeat(MAX_TEXT_CHARS)), None);
        let long = refused(&"Я".repeat(32_768)).expect("too long");
        assert!(long.contains("32768 characters"), "{long}");
        let marks = refused(&format!("a{}", "\u{301}".repeat(900))).expect("marks");
        assert!(marks.contains("900 combining marks"), "{marks}");
        assert_eq!(refused(&format!("a{}", "\u{301}".repeat(MAX_MARKS))), None);
        assert!(refused("a\u{7}b").is_some_and(|m| m.contains("control")));
    }
}
