//! Typst markup written piece by piece: headings, paragraphs, formulas, tables and figures.
//! Every text the note takes from elsewhere (the scene's title, a label's markup, a number)
//! enters as a Typst string or as content built from one, so no character of it is read as
//! markup.

use crate::plate::text::{parse, Script};
use crate::scale::{format_sig_from, Lang};
use crate::words::symbols::cyrillic;

/// A Typst string literal of `text`.
pub(super) fn string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The character a Unicode subscript stands for (`₁` → `1`, `₋` → `−`), `None` for any
/// other character: the note's face has no subscript glyphs, so `ω₁` is set as `ω` with a
/// subscript `1`, in the note's own face.
fn subscript_of(c: char) -> Option<char> {
    const LETTERS: [(char, char); 13] = [
        ('ₐ', 'a'),
        ('ₑ', 'e'),
        ('ₒ', 'o'),
        ('ₓ', 'x'),
        ('ₕ', 'h'),
        ('ₖ', 'k'),
        ('ₗ', 'l'),
        ('ₘ', 'm'),
        ('ₙ', 'n'),
        ('ₚ', 'p'),
        ('ₛ', 's'),
        ('ₜ', 't'),
        ('ᵢ', 'i'),
    ];
    match c {
        '₀'..='₉' => char::from_digit(c as u32 - '₀' as u32, 10),
        '₊' => Some('+'),
        '₋' => Some('−'),
        '₌' => Some('='),
        '₍' => Some('('),
        '₎' => Some(')'),
        _ => LETTERS.iter().find(|(s, _)| *s == c).map(|&(_, l)| l),
    }
}

/// The Unicode superscript digits, 0 … 9.
const SUPERSCRIPT_DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// The character a Unicode superscript digit or sign stands for (`⁻` → `−`, `⁸` → `8`),
/// `None` for any other character (`²` and `³` of a unit are the face's own).
fn superscript_of(c: char) -> Option<char> {
    match c {
        '²' | '³' => None,
        '⁺' => Some('+'),
        '⁻' => Some('−'),
        _ => SUPERSCRIPT_DIGITS
            .iter()
            .position(|&d| d == c)
            .and_then(|k| char::from_digit(k as u32, 10)),
    }
}

/// A number as text, its exponent form (`1,44133e−8`, as [`format_sig_from`] writes past the
/// plain range) as a power of ten in Unicode superscripts (`1,44133·10⁻⁸`), which [`text`]
/// and [`label`] set as a superscript: ГОСТ 2.105 has no `e` form.
pub(super) fn power_of_ten(number: &str) -> String {
    let Some((mantissa, exponent)) = number.split_once('e') else {
        return number.to_string();
    };
    let power: String = exponent
        .chars()
        .map(|c| match c {
            '−' | '-' => '⁻',
            '+' => '⁺',
            d => d.to_digit(10).map_or(d, |k| SUPERSCRIPT_DIGITS[k as usize]),
        })
        .collect();
    format!("{mantissa}·10{power}")
}

/// `text` as content pieces: `#"…"` for its runs of plain characters, `#sub("…")` and
/// `#super("…")` for its runs of Unicode subscripts and superscripts; a space between a
/// digit and a letter (a number and its unit) non-breaking.
fn pieces(text: &str, out: &mut String) {
    let mut run = String::new();
    let mut script = Script::Normal;
    let flush = |run: &mut String, script: Script, out: &mut String| {
        if !run.is_empty() {
            let s = string(run);
            out.push_str(&match script {
                Script::Normal => format!("#{s}"),
                Script::Sub => format!("#sub({s})"),
                Script::Sup => format!("#super({s})"),
            });
            run.clear();
        }
    };
    let chars: Vec<char> = text.chars().collect();
    for (k, &c) in chars.iter().enumerate() {
        // A number and the unit after it are not parted at a line's end (`34 мм`).
        let c = match (k.checked_sub(1).map(|j| chars[j]), chars.get(k + 1)) {
            (Some(a), Some(b)) if c == ' ' && a.is_ascii_digit() && b.is_alphabetic() => '\u{a0}',
            _ => c,
        };
        let (ch, kind) = match (subscript_of(c), superscript_of(c)) {
            (Some(d), _) => (d, Script::Sub),
            (_, Some(d)) => (d, Script::Sup),
            _ => (c, Script::Normal),
        };
        if kind != script {
            flush(&mut run, script, out);
            script = kind;
        }
        run.push(ch);
    }
    flush(&mut run, script, out);
}

/// Plain text as content: `[#"text"]` (its Unicode subscripts set as subscripts).
pub(super) fn text(text: &str) -> String {
    let mut out = String::from("[");
    pieces(text, &mut out);
    out.push(']');
    out
}

/// Label markup (`V_{B3B1}`, `μ_{v} = 0,05 м/(с·мм)`, `R_{0-5}`) as content, its subscripts
/// and superscripts set as such: `[#"V"#sub("B3B1")]` (and its Unicode subscripts: `ω₁`).
pub(super) fn label(markup: &str) -> String {
    let mut out = String::from("[");
    for run in parse(markup) {
        let s = string(&run.text);
        match run.script {
            Script::Normal => pieces(&run.text, &mut out),
            Script::Sub => out.push_str(&format!("#sub({s})")),
            Script::Sup => out.push_str(&format!("#super({s})")),
        }
    }
    out.push(']');
    out
}

/// A quantity's symbol in a formula: the label markup set in the text face, italic
/// (`#qs[...]`, defined by the note's template), a descriptive index written in Cyrillic
/// (`b_{ст}`, `M_{пр}`) upright (`#qu[...]`), as ГОСТ 2.105 writes word indices.
pub(super) fn sym(markup: &str) -> String {
    // The indices as the formula's own attachments: a text index inside a formula keeps its
    // digits full size.
    let mut out = String::new();
    for run in parse(markup) {
        let face = match run.script {
            Script::Normal => "qs",
            _ if run.text.chars().any(cyrillic) => "qu",
            _ => "qs",
        };
        let s = format!("#{face}[#{}]", string(&run.text));
        match run.script {
            Script::Normal if out.is_empty() => out.push_str(&s),
            Script::Normal => out.push_str(&format!(" {s}")),
            Script::Sub => out.push_str(&format!("_({s})")),
            Script::Sup => out.push_str(&format!("^({s})")),
        }
    }
    out
}

/// The least magnitude the note writes as a plain number: 0,00724 (two zeros after the
/// decimal sign at most); 0,000724 is 7,24·10⁻⁴ (ГОСТ 2.105: no run of zeros).
pub(super) const LEAST_PLAIN: i32 = -3;

/// A number in a formula, to `sig` significant digits with the language's decimal sign, set
/// upright; a negative number with its minus sign.
pub(super) fn num(x: f64, sig: usize, lang: Lang) -> String {
    let t = format_sig_from(x, sig, lang, LEAST_PLAIN);
    let (sign, abs) = match t.strip_prefix('-').or_else(|| t.strip_prefix('−')) {
        Some(abs) => ("-", abs),
        None => ("", t.as_str()),
    };
    // A value past the plain form as a power of ten (ГОСТ 2.105 has no `e` form).
    match abs.split_once('e') {
        Some((mantissa, power)) => format!(
            "{sign}{} dot 10^({})",
            string(mantissa),
            power.replace('−', "-")
        ),
        None => format!("{sign}{}", string(abs)),
    }
}

/// A unit after a number in a formula (`м/с`), upright, after a thin space.
pub(super) fn unit(u: &str) -> String {
    if u.is_empty() {
        String::new()
    } else if u == "°" {
        // An angle's degree sign stands against its number.
        string(u)
    } else {
        let u = u
            .replace("^{2}", "²")
            .replace("^2", "²")
            .replace("^{3}", "³")
            .replace("^3", "³");
        format!("thin {}", string(&u))
    }
}

/// A fraction in a formula.
pub(super) fn frac(top: &str, bottom: &str) -> String {
    format!("({top})/({bottom})")
}

/// An inline formula, a piece of a paragraph or a cell.
pub(super) fn inline(math: &str) -> String {
    format!("${math}$")
}

/// A table's header or row-head cell as ГОСТ 2.105 heads it ([`crate::words::heading`]):
/// `[#"величина"]` → `[#"Величина"]`; a formula or a symbol (`dS/dφ`, `x₁`, `pd`) as it is.
fn capitalised(cell: &str) -> String {
    match cell.strip_prefix("[#\"") {
        Some(rest) => format!("[#\"{}", crate::words::heading(rest)),
        None => cell.to_string(),
    }
}

/// The left side of the Typst math `math`: up to its first `=` outside brackets and strings.
pub(super) fn first_side(math: &str) -> &str {
    top_level_equals(math)[0]
}

/// The pieces of Typst math `math` between its `=` signs outside brackets and strings.
fn top_level_equals(math: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut quoted, mut escaped, mut from) =
        (Vec::new(), 0i32, false, false, 0);
    for (i, c) in math.char_indices() {
        match c {
            _ if escaped => escaped = false,
            '\\' if quoted => escaped = true,
            '"' => quoted = !quoted,
            '(' | '[' | '{' if !quoted => depth += 1,
            ')' | ']' | '}' if !quoted => depth -= 1,
            '=' if !quoted && depth == 0 => {
                parts.push(math[from..i].trim());
                from = i + 1;
            }
            _ => {}
        }
    }
    parts.push(math[from..].trim());
    parts
}

/// One cell of a table: content (from [`text`], [`label`] or a formula `$…$`).
pub(super) type Cell = String;

/// How a table's columns are aligned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Align {
    /// Text: left.
    Left,
    /// Numbers: centred.
    Centre,
}

/// A document's markup.
#[derive(Debug, Default)]
pub(super) struct Markup {
    out: String,
    /// The numbered sections (level-1 headings) written so far.
    sections: usize,
    /// The length of `out` when the last section's heading was written: a figure written at
    /// that length is the section's first element.
    section_opened: Option<usize>,
}

impl Markup {
    /// Raw Typst, as written.
    pub(super) fn raw(&mut self, typst: &str) {
        self.out.push_str(typst);
        self.out.push('\n');
    }

    /// A numbered heading of `level` (1 a section, 2 a subsection) with its label `<key>`.
    ///
    /// A section's displayed formulas are numbered (S.n) within it (ГОСТ 2.105), S written
    /// here: Typst counts n, and no formula's number waits for the layout to know its
    /// section, which would lay the note out once more.
    pub(super) fn heading(&mut self, level: usize, title: &str) {
        let marks = "=".repeat(level.max(1));
        self.out
            .push_str(&format!("\n{marks} #{}\n\n", string(title)));
        if level <= 1 {
            self.sections += 1;
            self.out.push_str(&format!(
                "#set math.equation(numbering: n => \"({}.\" + str(n) + \")\")\n\n",
                self.sections
            ));
            self.section_opened = Some(self.out.len());
        }
    }

    /// A paragraph of pieces: content (from [`text`], [`label`]) and inline formulas
    /// (`$…$`, from [`inline`]), a space between each two.
    pub(super) fn par(&mut self, pieces: &[String]) {
        for p in pieces {
            if !p.starts_with('$') {
                self.out.push('#');
            }
            self.out.push_str(p);
            self.out.push(' ');
        }
        self.out.push_str("\n\n");
    }

    /// A paragraph of text in label markup: its `_` and `^` scripts set as such (`M_пр`).
    pub(super) fn say(&mut self, t: &str) {
        self.par(&[label(t)]);
    }

    /// A displayed formula (Typst math, built with [`sym`], [`num`], [`unit`], [`frac`]),
    /// numbered. A chain `a = b = c …` also as two lines, `a = b` and `= c …`, which the
    /// note's `formula` shows instead when the one line would not leave room for the number
    /// (ГОСТ 2.105: a long formula broken after a sign, the sign repeated); a chain of four
    /// sides or more also a line each side, shown when the second line is still too long
    /// (a sum of substituted terms and its value).
    pub(super) fn formula(&mut self, math: &str) {
        let parts = top_level_equals(math);
        if parts.len() < 3 {
            self.out.push_str(&format!("$ {math} $\n\n"));
            return;
        }
        let first = parts[..2].join(" &= ");
        let broken = format!("{first} \\ &= {}", parts[2..].join(" = "));
        if parts.len() > 3 {
            let steps = format!("{first} \\ &= {}", parts[2..].join(" \\ &= "));
            self.forms(&[math, &broken, &steps]);
        } else {
            self.forms(&[math, &broken]);
        }
    }

    /// A displayed formula, numbered: `one` on one line, or `broken` (its lines laid out by
    /// the caller) where the note's `formula` measures `one` too wide to leave room for the
    /// number — a count of characters only estimates the width a sum of primed, indexed
    /// symbols takes.
    pub(super) fn formula_or(&mut self, one: &str, broken: &str) {
        self.forms(&[one, broken]);
    }

    /// The template's `formula` with its forms, the one line first: it sets the first that
    /// leaves room for the number, else the last.
    fn forms(&mut self, forms: &[&str]) {
        let forms: Vec<String> = forms.iter().map(|f| format!("$ {f} $")).collect();
        self.out
            .push_str(&format!("#formula({})\n\n", forms.join(", ")));
    }

    /// A table under its caption (ГОСТ 2.105: «Таблица N — caption» above it; on each page
    /// it continues onto, «Продолжение таблицы N» and the header repeated).
    pub(super) fn table(
        &mut self,
        caption: &str,
        align: &[Align],
        header: &[Cell],
        rows: &[Vec<Cell>],
    ) {
        let columns = header.len();
        let aligns: Vec<&str> = (0..columns)
            .map(|k| match align.get(k).copied().unwrap_or(Align::Centre) {
                Align::Left => "left",
                Align::Centre => "center",
            })
            .collect();
        let one = if columns == 1 { "," } else { "" };
        let widths = match super::columns::widths(header, rows, columns) {
            Some(w) => {
                let w: Vec<String> = w.iter().map(|w| format!("{w:.2}em")).collect();
                format!("({}{one})", w.join(", "))
            }
            None => columns.to_string(),
        };
        let mut t = format!(
            "#figure(kind: table, caption: {}, table(columns: {widths}, align: ({}{one}), table.header(table.cell(colspan: {columns}, stroke: none, inset: 0pt, align: left, continued()), ",
            text(caption),
            aligns.join(", ")
        );
        let header: Vec<String> = header.iter().map(|h| capitalised(h)).collect();
        t.push_str(&header.join(", "));
        t.push_str("),\n");
        for row in rows {
            let mut cells: Vec<String> = row.iter().take(columns).cloned().collect();
            cells.resize(columns, "[]".into());
            // A row's head capital too (ГОСТ 2.105: the heads of columns and rows).
            if let Some(head) = cells.first_mut() {
                *head = capitalised(head);
            }
            t.push_str("  ");
            t.push_str(&cells.join(", "));
            t.push_str(",\n");
        }
        t.push_str("))\n\n");
        self.out.push_str(&t);
    }

    /// A figure: the file `path` (an SVG the note carries) `width_mm` wide at most, under its
    /// caption («Рисунок N — caption» under it). A section's first element stands under its
    /// heading, which opens the page: it is not floated to the page's top, above the heading.
    pub(super) fn figure(&mut self, path: &str, width_mm: f64, caption: &str) {
        let fixed = if self.section_opened == Some(self.out.len()) {
            ", placement: none"
        } else {
            ""
        };
        self.out.push_str(&format!(
            "#figure(image({}, width: {:.1}mm){fixed}, caption: {})\n\n",
            string(path),
            width_mm,
            label(caption)
        ));
    }

    /// The markup written.
    pub(super) fn finish(self) -> String {
        self.out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_number_keeps_its_unit_on_its_line() {
        assert_eq!(label("r0 = 34 мм"), "[#\"r0 = 34\u{a0}мм\"]");
        assert_eq!(label("0 ≡ 4 и 5"), "[#\"0 ≡ 4\u{a0}и 5\"]");
        assert_eq!(label("a = 5"), "[#\"a = 5\"]");
    }

    #[test]
    fn formulas_are_numbered_by_the_section_they_follow() {
        let mut m = Markup::default();
        m.heading(1, "A");
        m.heading(2, "a");
        m.heading(1, "B");
        let s = m.finish();
        let rule = |k: usize| format!("numbering: n => \"({k}.\" + str(n)");
        assert_eq!(s.matches("#set math.equation").count(), 2, "{s}");
        assert!(s.contains(&rule(1)) && s.contains(&rule(2)), "{s}");
        assert!(s.find(&rule(2)) > s.find("= #\"B\""), "{s}");
    }

    #[test]
    fn a_chain_of_equalities_may_break_after_its_first_sign_or_each() {
        let mut m = Markup::default();
        m.formula("a = b");
        m.formula("a = b + c = 2");
        // Four sides: also a line each, for a sum of substituted terms too long for one.
        m.formula("a = b + c = 1 + 1 = 2");
        assert_eq!(
            m.finish(),
            "$ a = b $\n\n#formula($ a = b + c = 2 $, $ a &= b + c \\ &= 2 $)\n\n\
             #formula($ a = b + c = 1 + 1 = 2 $, $ a &= b + c \\ &= 1 + 1 = 2 $, \
             $ a &= b + c \\ &= 1 + 1 \\ &= 2 $)\n\n"
        );
    }

    #[test]
    fn a_sum_laid_out_by_the_caller_is_the_other_form() {
        let mut m = Markup::default();
        m.formula_or("a + b = 0", "& a \\ & + b = 0");
        assert_eq!(
            m.finish(),
            "#formula($ a + b = 0 $, $ & a \\ & + b = 0 $)\n\n"
        );
    }

    #[test]
    fn a_chain_splits_at_its_own_equals_signs_only() {
        assert_eq!(
            top_level_equals(r#"a = f(x = 1) = "b = c" = #qs[#"="] = 2"#),
            ["a", "f(x = 1)", r#""b = c""#, r#"#qs[#"="]"#, "2"]
        );
        assert_eq!(top_level_equals("a + b"), ["a + b"]);
    }

    #[test]
    fn unicode_subscripts_are_set_as_subscripts_in_the_notes_face() {
        assert_eq!(text("ω₁ = const"), r##"[#"ω"#sub("1")#" = const"]"##);
        assert_eq!(text("1,44·10⁻⁸ м²"), r##"[#"1,44·10"#super("−8")#" м²"]"##);
        assert_eq!(
            label("R₄₋₃ и M_{пр}"),
            r##"[#"R"#sub("4−3")#" и M"#sub("пр")]"##
        );
        assert_eq!(sym("b_{ст}"), r##"#qs[#"b"]_(#qu[#"ст"])"##);
        assert_eq!(
            crate::note::scripts::localise_scripts(&sym("M_{пр}"), Lang::En),
            r##"#qs[#"M"]_(#qu[#"red"])"##
        );
    }

    #[test]
    fn a_header_starts_with_a_capital_letter() {
        assert_eq!(capitalised(r#"[#"величина"]"#), r#"[#"Величина"]"#);
        assert_eq!(capitalised(r#"[#"ед."]"#), r#"[#"Ед."]"#);
        // A symbol of one letter, a formula: as they are.
        assert_eq!(capitalised(r##"[#"x"#sub("1")]"##), r##"[#"x"#sub("1")]"##);
        assert_eq!(capitalised("$a$"), "$a$");
        assert_eq!(capitalised(r#"[#"dS/dφ, м"]"#), r#"[#"dS/dφ, м"]"#);
        assert_eq!(capitalised(r#"[#"pd, мм"]"#), r#"[#"pd, мм"]"#);
        assert_eq!(capitalised(r#"[#"луч, мм"]"#), r#"[#"Луч, мм"]"#);
    }

    #[test]
    fn strings_escape_quotes_and_backslashes() {
        assert_eq!(string(r#"a "b" \c"#), r#""a \"b\" \\c""#);
    }

    #[test]
    fn a_unit_sets_its_powers_as_superscripts() {
        assert_eq!(unit("м/с^2"), r#"thin "м/с²""#);
        assert_eq!(unit("кг·м^{2}"), r#"thin "кг·м²""#);
    }

    #[test]
    fn a_label_keeps_its_scripts() {
        assert_eq!(label("V_{B3B1}"), r##"[#"V"#sub("B3B1")]"##);
        assert_eq!(label("R_{1-2}^{тр}"), r##"[#"R"#sub("1-2")#super("тр")]"##);
    }

    #[test]
    fn numbers_in_formulas_carry_the_decimal_sign_and_minus() {
        assert_eq!(num(2.19911, 4, Lang::Ru), r#""2,199""#);
        assert_eq!(num(-0.5456, 3, Lang::En), r#"-"0.546""#);
        assert_eq!(num(2.01e-14, 3, Lang::Ru), r#""2,01" dot 10^(-14)"#);
    }
}
