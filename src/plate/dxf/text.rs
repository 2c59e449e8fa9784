//! A placed text as DXF TEXT entities: one TEXT per run of its markup, a sub- or superscript
//! written as its own smaller TEXT lowered or raised as the SVG's `<tspan>` is — plain
//! characters every CAD font has, no Unicode subscript digits, no MTEXT codes an importer
//! may not read. A text of one plain run keeps its alignment (centred, right) so that a CAD
//! font of other widths still centres it on its point.

use super::Flip;
use crate::geom::DVec2;
use crate::plate::text::{
    em_for_height, kerned, literal, measure, parse, Align, Placed, Script, SCRIPT_SCALE,
    SUB_SHIFT_EM, SUP_SHIFT_EM,
};
use acadrust::entities::{Text, TextHorizontalAlignment, TextVerticalAlignment};
use acadrust::types::Vector3;
use std::f64::consts::TAU;

/// The name of the text style every TEXT is written in.
pub(super) const STYLE: &str = "TMM";

/// One TEXT of a run: its baseline point (sheet mm), the characters, its height (of
/// capitals, mm) and its alignment at the point.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct RunText {
    /// Baseline point, sheet mm (y down).
    pub at: DVec2,
    /// The characters.
    pub text: String,
    /// Height of capitals, mm.
    pub height: f64,
    /// Alignment at `at`.
    pub align: Align,
}

/// The runs of `t` as written, each at its place on the sheet.
pub(super) fn runs(t: &Placed) -> Vec<RunText> {
    let runs = parse(&t.markup);
    let total = measure(&t.markup, t.height).advance;
    let condense = width_factor(t);
    if let [run] = runs.as_slice() {
        if run.script == Script::Normal {
            return vec![RunText {
                at: t.at,
                text: kerned(&run.text).into_owned(),
                height: t.height,
                align: t.align,
            }];
        }
    }
    let back = match t.align {
        Align::Start => 0.0,
        Align::Middle => 0.5,
        Align::End => 1.0,
    };
    let em = em_for_height(t.height);
    let turn = DVec2::from_angle(t.rotate.to_radians());
    let mut pen = -back * total;
    let mut out = Vec::with_capacity(runs.len());
    for run in runs {
        let (height, down) = match run.script {
            Script::Normal => (t.height, 0.0),
            Script::Sub => (t.height * SCRIPT_SCALE, SUB_SHIFT_EM * em),
            Script::Sup => (t.height * SCRIPT_SCALE, -SUP_SHIFT_EM * em),
        };
        let own = DVec2::new(pen * condense, down);
        out.push(RunText {
            at: t.at + turn.rotate(own),
            text: kerned(&run.text).into_owned(),
            height,
            align: Align::Start,
        });
        pen += measure(&literal(&run.text), height).advance;
    }
    out
}

/// How much `t` is condensed to its `length` (1 when it is not).
fn width_factor(t: &Placed) -> f64 {
    let natural = measure(&t.markup, t.height).advance;
    match t.length {
        Some(len) if natural > 0.0 && len > 0.0 => len / natural,
        _ => 1.0,
    }
}

/// The TEXT entities of `t`.
pub(super) fn entities(t: &Placed, flip: &Flip) -> Vec<Text> {
    let rotation = (-t.rotate.to_radians()).rem_euclid(TAU);
    let factor = width_factor(t);
    runs(t)
        .into_iter()
        .map(|r| {
            let at = flip.pt(r.at);
            let point = Vector3::new(at.x, at.y, 0.0);
            let mut e = Text::with_value(r.text, point)
                .with_height(r.height)
                .with_rotation(rotation);
            e.width_factor = factor;
            e.style = STYLE.to_string();
            e.vertical_alignment = TextVerticalAlignment::Baseline;
            e.horizontal_alignment = match r.align {
                Align::Start => TextHorizontalAlignment::Left,
                Align::Middle => TextHorizontalAlignment::Center,
                Align::End => TextHorizontalAlignment::Right,
            };
            if r.align != Align::Start {
                e.alignment_point = Some(point);
            }
            e
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scripts_are_their_own_smaller_runs_lowered_and_raised() {
        let t = Placed::new(DVec2::new(10.0, 20.0), "ω_2 = a^2", 3.5, Align::Start);
        let r = runs(&t);
        let texts: Vec<&str> = r.iter().map(|r| r.text.as_str()).collect();
        assert_eq!(texts, ["ω", "2", " = a", "2"]);
        let em = em_for_height(3.5);
        assert_eq!(r[0].at, DVec2::new(10.0, 20.0));
        assert!((r[1].at.y - (20.0 + SUB_SHIFT_EM * em)).abs() < 1e-12);
        assert!((r[3].at.y - (20.0 - SUP_SHIFT_EM * em)).abs() < 1e-12);
        assert!((r[1].height - 3.5 * SCRIPT_SCALE).abs() < 1e-12);
        // Each run starts where the one before ends, as the SVG's `<tspan>`s do.
        let first = measure("ω", 3.5).advance;
        assert!((r[1].at.x - (10.0 + first)).abs() < 1e-12);
    }

    #[test]
    fn a_plain_centred_text_keeps_its_point_and_a_scripted_one_starts_before_it() {
        let plain = Placed::new(DVec2::new(50.0, 20.0), "Звено 1, F′", 5.0, Align::Middle);
        assert_eq!(runs(&plain)[0].at, DVec2::new(50.0, 20.0));
        assert_eq!(runs(&plain)[0].align, Align::Middle);
        let scripted = Placed::new(DVec2::new(50.0, 20.0), "F_и3", 5.0, Align::Middle);
        let r = runs(&scripted);
        let half = 0.5 * measure("F_и3", 5.0).advance;
        assert!((r[0].at.x - (50.0 - half)).abs() < 1e-12);
        assert_eq!(r[1].text, "и3");
    }
}
