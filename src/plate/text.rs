//! Label markup and its SVG text.
//!
//! The markup of [`Label`](crate::construct::Label) texts: `_x` or `_{xy}` for a subscript,
//! `^x` or `^{xy}` for a superscript, `\x` for a literal `x`. Without braces a script
//! covers one "word": a run of digits (`b_3b_1` is b₃b₁), or a run of letters followed by
//! digits (`V_B2`, `φ_max`). Everything else is normal text.

use super::metrics::glyph;
use super::path::{num, Map};
use super::Rect;
use crate::geom::DVec2;
use std::borrow::Cow;
use std::fmt::Write as _;

/// ГОСТ 2.304 size of labels (height of capitals), mm.
pub const LABEL_HEIGHT_MM: f64 = 3.5;
/// ГОСТ 2.304 size of view captions, mm.
pub const CAPTION_HEIGHT_MM: f64 = 5.0;

/// The vertical position of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Script {
    /// On the baseline.
    Normal,
    /// Lowered, smaller (index).
    Sub,
    /// Raised, smaller (exponent, mark).
    Sup,
}

/// A piece of text in one script.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Run {
    /// The characters.
    pub text: String,
    /// Where they sit.
    pub script: Script,
}

/// Split label markup into runs; adjacent runs of the same script are merged and empty runs
/// dropped. Never fails: a marker with nothing to apply to is kept as text.
pub fn parse(markup: &str) -> Vec<Run> {
    let chars: Vec<char> = markup.chars().collect();
    let mut runs = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let script = match c {
            '_' => Script::Sub,
            '^' => Script::Sup,
            '\\' if i + 1 < chars.len() => {
                push(&mut runs, Script::Normal, &chars[i + 1..i + 2]);
                i += 2;
                continue;
            }
            _ => Script::Normal,
        };
        let (body, next) = match script {
            Script::Normal => ((i, i + 1), i + 1),
            _ => scripted(&chars, i + 1),
        };
        if body.0 == body.1 && script != Script::Normal {
            push(&mut runs, Script::Normal, &[c]);
            i = next;
            continue;
        }
        push(&mut runs, script, &chars[body.0..body.1]);
        i = next;
    }
    runs
}

/// The body of a script starting at `start` (after the marker): `(body range, next index)`.
fn scripted(chars: &[char], start: usize) -> ((usize, usize), usize) {
    match chars.get(start) {
        Some('{') => match chars[start + 1..].iter().position(|&c| c == '}') {
            Some(len) => ((start + 1, start + 1 + len), start + 2 + len),
            None => ((start + 1, chars.len()), chars.len()),
        },
        Some(c) if c.is_ascii_digit() => {
            let end = run_end(chars, start, |c| c.is_ascii_digit());
            ((start, end), end)
        }
        Some(c) if c.is_alphabetic() => {
            let letters = run_end(chars, start, char::is_alphabetic);
            let end = run_end(chars, letters, |c| c.is_ascii_digit());
            ((start, end), end)
        }
        _ => ((start, start), start),
    }
}

fn run_end(chars: &[char], start: usize, keep: impl Fn(char) -> bool) -> usize {
    chars[start..]
        .iter()
        .position(|&c| !keep(c))
        .map_or(chars.len(), |n| start + n)
}

fn push(runs: &mut Vec<Run>, script: Script, chars: &[char]) {
    if chars.is_empty() {
        return;
    }
    match runs.last_mut() {
        Some(last) if last.script == script => last.text.extend(chars),
        _ => runs.push(Run {
            text: chars.iter().collect(),
            script,
        }),
    }
}

/// The markup with the markers removed (for widths and plain-text uses).
pub fn plain(markup: &str) -> String {
    parse(markup).into_iter().map(|r| r.text).collect()
}

/// Height of capitals of DejaVu Sans, in em (1493 / 2048 units).
pub const CAP_HEIGHT_EM: f64 = 0.729;
/// Size of sub- and superscripts relative to the text.
pub const SCRIPT_SCALE: f64 = 0.7;
/// Shift of a subscript below the baseline, em of the text.
pub const SUB_SHIFT_EM: f64 = 0.3;
/// Shift of a superscript above the baseline, em of the text.
pub const SUP_SHIFT_EM: f64 = 0.4;
/// Narrowest a text is condensed (`lengthAdjust="spacingAndGlyphs"`) before it is also
/// made smaller to fit.
pub const MIN_CONDENSE: f64 = 0.7;

/// Approximate advance of a DejaVu Sans character, em, erring on the wide side (for fitting
/// text in cells; the classes follow the font's advance widths).
fn advance_em(c: char) -> f64 {
    match c {
        ' ' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' | 'i' | 'j' | 'l' | 'І' | 'і' | 'ї'
        | 'I' | 'J' => 0.33,
        '(' | ')' | '[' | ']' | '{' | '}' | '/' | '-' | 'r' | 't' | 'f' | '‘' | '’' | '′' => {
            0.43
        }
        'm' | 'w' | 'M' | 'W' | 'Ш' | 'Щ' | 'Ж' | 'Ю' | 'Ы' | 'ш' | 'щ' | 'ж' | 'ю' | 'ы' | '№'
        | '%' | '—' => 0.9,
        c if c.is_uppercase() => 0.74,
        _ => 0.64,
    }
}

/// Plain text as label markup: `_`, `^` and `\` kept literally (`v_B3_B1` reads as written).
pub fn literal(plain: &str) -> String {
    let mut out = String::with_capacity(plain.len());
    for ch in plain.chars() {
        if matches!(ch, '_' | '^' | '\\') {
            out.push('\\');
        }
        out.push(ch);
    }
    out
}

/// The SVG font size (em, mm) for a ГОСТ 2.304 text size (height of capitals, mm).
pub fn em_for_height(height_mm: f64) -> f64 {
    height_mm / CAP_HEIGHT_EM
}

/// Approximate width of the markup at text size `height_mm`, mm: the character classes'
/// estimate, erring on the wide side, and never under the face's own advance (a line of
/// `=`, `≥`, `>` and digits runs wider than the classes say: 0,84 em each against 0,64).
pub fn approx_width(markup: &str, height_mm: f64) -> f64 {
    classes_width(markup, height_mm).max(measure(markup, height_mm).advance)
}

/// The width the markup needs at `height_mm` to stand inside a width, mm: [`approx_width`]
/// grown as its ink runs past its advance (an oblique line's last letter leans past it, and
/// a text narrowed to a length narrows its ink alike).
pub fn fitting_width(markup: &str, height_mm: f64) -> f64 {
    let e = measure(markup, height_mm);
    // An empty text's 0/0 is no lean: `max` passes over a NaN.
    let lean = ((e.max.x - e.min.x) / e.advance).max(1.0);
    approx_width(markup, height_mm) * lean
}

/// The character classes' estimate of the markup's width at `height_mm`, mm.
fn classes_width(markup: &str, height_mm: f64) -> f64 {
    let em: f64 = parse(markup)
        .iter()
        .map(|r| {
            let k = if r.script == Script::Normal {
                1.0
            } else {
                SCRIPT_SCALE
            };
            r.text.chars().map(advance_em).sum::<f64>() * k
        })
        .sum();
    em * em_for_height(height_mm)
}

/// What a text covers, relative to the start of its baseline, mm, y down: the advance (how
/// far the pen moves, which `text-anchor` aligns) and the box of its ink, widened to the
/// advance and to the band from the baseline up to the height of capitals, so that every
/// text occupies at least its line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extent {
    /// Sum of the advances, mm.
    pub advance: f64,
    /// Top-left corner of the box.
    pub min: DVec2,
    /// Bottom-right corner of the box.
    pub max: DVec2,
}

/// The extent of the markup at text size `height_mm` (height of capitals), measured with the
/// bundled face's metrics, scripts at their size and shift as `Placed` writes them.
pub fn measure(markup: &str, height_mm: f64) -> Extent {
    let em = em_for_height(height_mm);
    let mut pen = 0.0;
    let mut min = DVec2::new(0.0, -height_mm);
    let mut max = DVec2::ZERO;
    for run in parse(markup) {
        let (size, dy) = match run.script {
            Script::Normal => (em, 0.0),
            Script::Sub => (em * SCRIPT_SCALE, SUB_SHIFT_EM * em),
            Script::Sup => (em * SCRIPT_SCALE, -SUP_SHIFT_EM * em),
        };
        for c in kerned(&run.text).chars() {
            let g = glyph(c);
            if let Some((x0, y0, x1, y1)) = g.ink {
                min = min.min(DVec2::new(pen + x0 * size, dy - y1 * size));
                max = max.max(DVec2::new(pen + x1 * size, dy - y0 * size));
            }
            pen += g.advance * size;
        }
    }
    max.x = max.x.max(pen);
    Extent {
        advance: pen,
        min,
        max,
    }
}

/// Horizontal alignment of a text at its position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Align {
    /// The text starts at the position.
    Start,
    /// The text is centred on the position.
    Middle,
    /// The text ends at the position.
    End,
}

/// A text placed on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Placed {
    /// Baseline point, sheet mm.
    pub at: DVec2,
    /// The markup.
    pub markup: String,
    /// ГОСТ size (height of capitals), mm.
    pub height: f64,
    /// Horizontal alignment.
    pub align: Align,
    /// Rotation about `at`, degrees clockwise on the sheet.
    pub rotate: f64,
    /// Exact width to condense the text to (`textLength`), mm.
    pub length: Option<f64>,
}

impl Placed {
    /// A text with its baseline at `at`.
    pub(crate) fn new(at: DVec2, markup: &str, height: f64, align: Align) -> Self {
        Self {
            at,
            markup: markup.into(),
            height,
            align,
            rotate: 0.0,
            length: None,
        }
    }

    /// Fit the text into `width`: condensed down to [`MIN_CONDENSE`], then made smaller.
    /// The height is reduced about the vertical centre of the capitals.
    pub(crate) fn fit(self, width: f64) -> Self {
        let natural = fitting_width(&self.markup, self.height);
        if !(natural > width && width > 0.0) {
            return self;
        }
        self.narrowed(width / natural)
    }

    /// The text drawn `ratio` (< 1) of its natural width: condensed down to
    /// [`MIN_CONDENSE`], then made smaller about the vertical centre of the capitals (lines
    /// narrowed by one ratio keep one height and one condensing).
    pub(crate) fn narrowed(mut self, ratio: f64) -> Self {
        let natural = approx_width(&self.markup, self.height);
        let k = ratio / ratio.max(MIN_CONDENSE);
        self.at.y -= self.height * (1.0 - k) * 0.5;
        self.height *= k;
        self.length = Some(natural * ratio);
        self
    }
    /// The box the text covers on the sheet ([`measure`] aligned, condensed to `length`
    /// and rotated as written); the axis-aligned box of the rotated box when rotated.
    pub(crate) fn bounds(&self) -> Rect {
        let turned = self.corners();
        let lo = turned.iter().fold(DVec2::INFINITY, |m, p| m.min(*p));
        let hi = turned.iter().fold(DVec2::NEG_INFINITY, |m, p| m.max(*p));
        Rect::new(lo, hi)
    }

    /// The box the text covers in its own frame (x along the baseline, y down, the baseline
    /// point at the origin), before [`Placed::rotate`] turns it.
    pub(crate) fn own_box(&self) -> Rect {
        let e = measure(&self.markup, self.height);
        let k = match self.length {
            Some(len) if e.advance > 0.0 => len / e.advance,
            _ => 1.0,
        };
        let shift = match self.align {
            Align::Start => 0.0,
            Align::Middle => -0.5 * e.advance * k,
            Align::End => -e.advance * k,
        };
        let (x0, x1) = (e.min.x * k + shift, e.max.x * k + shift);
        Rect::new(DVec2::new(x0, e.min.y), DVec2::new(x1, e.max.y))
    }

    /// The corners of the box the text covers on the sheet, turned as written.
    pub(crate) fn corners(&self) -> [DVec2; 4] {
        let b = self.own_box();
        let corners = [
            b.min,
            DVec2::new(b.max.x, b.min.y),
            b.max,
            DVec2::new(b.min.x, b.max.y),
        ];
        let turn = DVec2::from_angle(self.rotate.to_radians());
        corners.map(|c| self.at + turn.rotate(c))
    }

    /// A point of the sheet in the text's own frame ([`Placed::own_box`]).
    pub(crate) fn to_own(&self, p: DVec2) -> DVec2 {
        let back = DVec2::from_angle(-self.rotate.to_radians());
        back.rotate(p - self.at)
    }

    /// A text whose capitals are vertically centred on `at`.
    pub(crate) fn centred(at: DVec2, markup: &str, height: f64, align: Align) -> Self {
        Self::new(at + DVec2::new(0.0, height * 0.5), markup, height, align)
    }

    /// The same text with its position mapped to the sheet.
    pub(crate) fn mapped(mut self, map: Map) -> Self {
        self.at = map.pt(self.at);
        self
    }

    /// The `<text>` element; scripts become `<tspan>`s with a smaller size and a `dy` shift
    /// (and the shift back), which resvg and browsers render alike. A centred or end-aligned
    /// text with scripts is written from its start ([`measure`]'s advance before `at`):
    /// `text-anchor` aligns the whole chunk in resvg but each `<tspan>` on its own in
    /// cairosvg, which would scatter the pieces of a caption over the neighbouring views.
    pub(crate) fn to_xml(&self, id: &str) -> String {
        let em = em_for_height(self.height);
        let runs = parse(&self.markup);
        let scripted = runs.iter().any(|r| r.script != Script::Normal);
        let (align, start) = match self.align {
            Align::Start => (Align::Start, self.at.x),
            a if !scripted => (a, self.at.x),
            a => {
                let advance = self
                    .length
                    .unwrap_or_else(|| measure(&self.markup, self.height).advance);
                let back = if a == Align::Middle { 0.5 } else { 1.0 };
                (Align::Start, self.at.x - back * advance)
            }
        };
        let (x, y) = (num(start), num(self.at.y));
        let (rx, ry) = (num(self.at.x), num(self.at.y));
        let anchor = match align {
            Align::Start => "start",
            Align::Middle => "middle",
            Align::End => "end",
        };
        let mut s = format!(
            r#"<text id="{id}" x="{x}" y="{y}" font-size="{}" text-anchor="{anchor}""#,
            num(em)
        );
        if self.rotate != 0.0 && self.rotate.is_finite() {
            let _ = write!(s, r#" transform="rotate({} {rx} {ry})""#, num(self.rotate));
        }
        if let Some(len) = self.length {
            let _ = write!(
                s,
                r#" textLength="{}" lengthAdjust="spacingAndGlyphs""#,
                num(len)
            );
        }
        s.push('>');
        let mut shift = 0.0;
        for run in runs {
            let (target, size) = match run.script {
                Script::Normal => (0.0, None),
                Script::Sub => (SUB_SHIFT_EM * em, Some(em * SCRIPT_SCALE)),
                Script::Sup => (-SUP_SHIFT_EM * em, Some(em * SCRIPT_SCALE)),
            };
            let dy = target - shift;
            shift = target;
            let text = kerned(&run.text);
            if dy == 0.0 && size.is_none() {
                s.push_str(&escape(&text));
                continue;
            }
            s.push_str("<tspan");
            if dy != 0.0 {
                let _ = write!(s, r#" dy="{}""#, num(dy));
            }
            if let Some(size) = size {
                let _ = write!(s, r#" font-size="{}""#, num(size));
            }
            let _ = write!(s, ">{}</tspan>", escape(&text));
        }
        s.push_str("</text>");
        s
    }
}

/// Ink past its advance, em, from which a glyph's top would touch a prime set after it.
const LEANS_PAST_EM: f64 = 0.06;

/// The characters as the face draws them: a prime (′, ″) after a glyph whose ink leans past
/// its advance (the oblique f: f′, the reduced coefficient of friction) is set a hair space
/// (U+200A) off it, so that the two never fuse. [`measure`], the SVG and the DXF see it.
pub(crate) fn kerned(text: &str) -> Cow<'_, str> {
    let leans = |c: char| {
        let g = glyph(c);
        g.ink
            .is_some_and(|(_, _, x1, _)| x1 - g.advance > LEANS_PAST_EM)
    };
    let chars: Vec<char> = text.chars().collect();
    let touching = |w: &[char]| matches!(w[1], '′' | '″') && leans(w[0]);
    if !chars.windows(2).any(touching) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 3);
    for (k, &c) in chars.iter().enumerate() {
        if k > 0 && touching(&[chars[k - 1], c]) {
            out.push('\u{200A}');
        }
        out.push(c);
    }
    Cow::Owned(out)
}

/// Escape XML special characters.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests;
