//! The cam sheet of a flat-faced rocker or a translating cam: the diagrams with their
//! integration (as every cam's), the profile by inversion (the face lines in the inverted
//! positions and their envelope; the translating cam's follower positions along it, the
//! rollers and both profiles), the data, the table of the points and the results against
//! the closed forms.

use super::cam::{diagram_block, law_lines, legend, mu, one_sheet, points_tables, results_table};
use super::layout::{keyed, Block};
use super::BuildError;
use super::{cam_marks, digits};
use crate::cam::sliding::TRAVEL_X_NOTE;
use crate::cam::{Follower, Special, SpecialProfile, TRAVEL_NOTE};
use crate::check::{Finding, Row};
use crate::plate::{Plate, Sheet, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_sig, Key, Lang};
use crate::study::{Session, StudyError};
use crate::words::{unit_in, CamText, Text};

/// Text height of the data lines, mm.
const TEXT_MM: f64 = 3.5;

/// Build the sheet of the session's flat-faced rocker or translating cam.
pub(super) fn build(
    session: &Session<'_>,
    cam: &Special,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let study = |e| BuildError::Study(StudyError::Cam(e));
    let rows = cam.rows().map_err(study)?;
    let exact = cam.angles_exact().map_err(study)?;
    let caption = match cam.profile {
        SpecialProfile::FlatRocker { .. } => CamText::FlatRockerProfile,
        SpecialProfile::Sliding { .. } => CamText::SlidingProfile,
    };
    let mut blocks = vec![diagram_block(&cam.diagrams, &cam.spec, lang)];
    if let SpecialProfile::Sliding { travel, .. } = &cam.profile {
        let s = cam.diagrams.s_scale;
        let text = cam_marks::valued("X_{min}/2π", travel.read, lang);
        blocks.push(Block::view(
            cam_marks::relabelled(&travel.figure, TRAVEL_NOTE, &text),
            format!(
                "{}, {}",
                CamText::TravelCombined.get(lang),
                mu("S", s, lang)
            ),
            keyed(Key::CamScaleS, s),
        ));
    }
    let profile = match &cam.profile {
        SpecialProfile::Sliding { frame, .. } => cam_marks::relabelled(
            cam.figure(),
            TRAVEL_X_NOTE,
            &cam_marks::valued("X", frame.travel, lang),
        ),
        SpecialProfile::FlatRocker { .. } => cam.figure().clone(),
    };
    blocks.push(Block::view(
        profile,
        format!("{}, {}", caption.get(lang), cam.scale.caption(lang)),
        keyed(Key::CamScaleL, cam.scale),
    ));
    let drawings = blocks.len();
    let read_mm = session.drafting().resolution_mm();
    let mut lines = data_lines(cam, read_mm, lang).map_err(study)?;
    lines.push(String::new());
    lines.extend(legend(last_column(&cam.profile).1, lang));
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Diagrams,
        lang,
    ));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    blocks.extend(
        points_table(cam, &exact, lang)
            .into_iter()
            .map(Block::Table),
    );
    let step = |r: &Row| cam.reading_step(r, read_mm);
    blocks.push(Block::Table(results_table(&rows, &step, lang)));
    let title = super::title_block(
        session.scene(),
        CamText::Title.get(lang),
        Some(cam.scale),
        lang,
    );
    let sheet = Sheet {
        size: SheetSize::A1,
        landscape: true,
    };
    one_sheet(sheet, blocks, drawings, &title, lang)
}

/// The data (the law, the frame) and the results (ρ_min, X_min, the verdicts), each read
/// off the profile to its step at `read_mm`.
fn data_lines(
    cam: &Special,
    read_mm: f64,
    lang: Lang,
) -> Result<Vec<String>, crate::cam::CamError> {
    let s = &cam.spec;
    let mm = unit_in("mm", lang);
    let n = |x: f64| format_sig(x * 1e3, 4, lang);
    let step_mm = cam.scale.reading_step(read_mm).map(|s| s * 1e3);
    let r = |x: f64| digits::read(x * 1e3, step_mm, lang);
    let deg = |x: f64| format_sig(x.to_degrees(), 4, lang);
    let mut out = law_lines(s, s.rotation, lang);
    let rho = cam.exact_rho_min()?;
    let drawn = cam.drawn_rho_min();
    let pair = |x: f64, y: f64| {
        format!(
            "{} {mm} ({}), {} {mm} ({})",
            r(x),
            Text::Graphical.get(lang),
            n(y),
            Text::Exact.get(lang)
        )
    };
    match &cam.profile {
        SpecialProfile::FlatRocker { frame, .. } => {
            let arm = match s.follower {
                Follower::Rocker { arm, .. } => arm,
                _ => 0.0,
            };
            out.push(format!(
                "L = {} {mm}, β_{{max}} = {}°, {} = Lβ_{{max}} = {} {mm}",
                n(arm),
                deg(s.stroke / arm),
                s.stroke_symbol(),
                n(s.stroke),
            ));
            out.push(format!(
                "a = O_{{1}}O_{{2}} = {} {mm}, e = {} {mm}, r_{{0}} = {} {mm}",
                n(frame.centres),
                n(frame.face_offset),
                n(frame.base)
            ));
            out.push(String::new());
            out.push(format!("ρ_{{min}} = {}", pair(drawn, rho)));
            if rho < s.rho_min {
                out.push(format!(
                    "{} {} {mm}",
                    CamText::Concave.get(lang),
                    n(s.rho_min)
                ));
            }
        }
        SpecialProfile::Sliding { frame, .. } => {
            out.push(format!(
                "h = {} {mm}, X = {} {mm}, r_{{р}} = {} {mm}, γ_{{min}} = {}°",
                n(s.stroke),
                n(frame.travel),
                n(frame.roller),
                deg(s.gamma_min)
            ));
            out.push(String::new());
            if let Some((read, exact)) = cam.travel_min() {
                out.push(format!("X_{{min}} = {}", pair(read, exact)));
                // The verdict on the travel the task gives against the X_min the drawing read.
                if exact > frame.travel * (1.0 + 1e-9) {
                    out.push(CamText::Exceeded.get(lang).into());
                } else if read <= frame.travel {
                    out.push(format!(
                        "X = {} {mm} ≥ X_{{min}} = {} {mm}",
                        n(frame.travel),
                        r(read)
                    ));
                }
            }
            if rho.is_finite() {
                out.push(format!("ρ_{{min}} = {}", pair(drawn, rho)));
            }
            let undercut = cam.findings()?.into_iter().find_map(|f| match f {
                Finding::Undercut { rho_min, .. } => Some(rho_min),
                _ => None,
            });
            if let Some(rho_min) = undercut {
                out.push(format!(
                    "{} ρ_{{min}} = {} {mm}",
                    CamText::Undercut.get(lang),
                    n(rho_min)
                ));
            }
        }
    }
    Ok(out)
}

/// The points table's last column: its symbol, and the legend's line saying what it is.
fn last_column(profile: &SpecialProfile) -> (&'static str, CamText) {
    match profile {
        SpecialProfile::FlatRocker { .. } => ("R", CamText::RadiusVector),
        SpecialProfile::Sliding { .. } => ("ξ", CamText::TravelAt),
    }
}

/// One row per point: φ, S, dS/dφ, d²S/dφ² (read), the pressure angle read and exact, and
/// the contact's radius vector (flat-faced rocker) or the follower's place ξ on the cam.
fn points_table(cam: &Special, exact: &[f64], lang: Lang) -> Vec<TableBlock> {
    let f = |x: f64, d: usize| format_fixed(x, d, lang);
    let read = cam.angles_read();
    let d = &cam.diagrams;
    let rows = cam
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let last = match &cam.profile {
                SpecialProfile::FlatRocker { board, .. } => board.contacts[i].point.length(),
                SpecialProfile::Sliding { board, .. } => board.contacts[i].xi,
            };
            vec![
                p.label.clone(),
                f(p.phi.to_degrees(), 1),
                f(d.s[i] * 1e3, 2),
                f(d.ds[i] * 1e3, 2),
                f(d.d2s[i] * 1e3, 2),
                f(read[i].to_degrees(), 1),
                f(exact[i].to_degrees(), 1),
                f(last * 1e3, 2),
            ]
        })
        .collect();
    let mm = unit_in("mm", lang);
    let last = last_column(&cam.profile).0;
    let columns = vec![
        (Text::Number.get(lang).into(), 8.0),
        ("φ, °".into(), 14.0),
        (format!("S, {mm}"), 16.0),
        (format!("dS/dφ, {mm}"), 20.0),
        (format!("d^2S/dφ^2, {mm}"), 24.0),
        (format!("λ {}, °", CamText::Read.get(lang)), 18.0),
        (format!("λ {}, °", Text::Exact.get(lang)), 18.0),
        (format!("{last}, {mm}"), 16.0),
    ];
    points_tables(columns, rows, lang)
}
