//! The cam section: the law's extremes and the least base radius worked (seed 000 §3:
//! symbols, numbers, result), the roller's choice, the diagrams and the profile, Table 7.

use super::markup::{frac, label, num, sym, text, Align};
use super::rows::{by_position, of_scene, quantities};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::cam::{Closure, Follower, Given, Law, SpecialProfile};
use crate::check::{Method, Symbol};
use crate::scene::PlateKind;
use crate::words::{CamText, CaseMeaning as M, Meaning, NoteText as T};

/// The cam: the law, the diagrams, r_min, the profile and the transmission (pressure)
/// angle, Table 7.
pub(super) fn cam(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let special = w.session.special_cam()?;
    w.section(T::CamSection);
    let (intro, scene) = match special.as_deref().map(|c| &c.profile) {
        Some(SpecialProfile::FlatRocker { .. }) => (T::CamFlatRockerIntro, T::CamSpecialScene),
        Some(SpecialProfile::Sliding { .. }) => (T::CamSlidingIntro, T::CamSpecialScene),
        None if w.session.cam()?.spec.given == Given::S => (T::CamIntroDifferentiated, T::CamScene),
        None => (T::CamIntro, T::CamScene),
    };
    w.doc.say(w.word(intro));
    let assumed = match &special {
        Some(c) => c.spec.law_assumed,
        None => w.session.cam()?.spec.law_assumed,
    };
    if assumed {
        w.doc.say(w.word(T::CamLawAssumed));
    }
    w.data_list(PlateKind::Cam, super::DataPart::Results);
    match &special {
        Some(c) => {
            super::cam_scales::scales(w, &c.diagrams, &c.spec);
            super::cam_special::worked(w, c)?;
        }
        None => {
            let cam = w.session.cam()?;
            super::cam_scales::scales(w, &cam.diagrams, &cam.spec);
            worked(w)?;
        }
    }
    // The angles by position in the table of their own when it follows (with the limit's
    // verdict), else here.
    let angles_apart = special.is_none();
    let q = quantities(&w.report.rows, |r| {
        r.position().is_some()
            && matches!(r.method, Method::Integration | Method::Inversion)
            && match r.key.symbol {
                Symbol::Displacement
                | Symbol::VelocityAnalogue
                | Symbol::AccelerationAnalogue
                | Symbol::ProfileRadius => true,
                Symbol::PressureAngle | Symbol::TransmissionAngle => !angles_apart,
                _ => false,
            }
    });
    let caption = w.word(if angles_apart {
        T::CamTableNoAngles
    } else {
        T::CamTable
    });
    by_position(w, caption, &q);
    if angles_apart {
        angle_table(w)?;
    }
    let caption = w.word(scene);
    // The dynamics integrates too (A_с, M_д): the cam's rows are its lengths.
    of_scene(w, caption, |r| {
        r.position().is_none()
            && matches!(
                r.method,
                Method::CombinedDiagram | Method::Inversion | Method::Integration
            )
            && !matches!(r.key.symbol, Symbol::Work | Symbol::Moment)
    });
    w.figures((PlateKind::Cam, None), |_| true, |own| own.to_string());
    Ok(())
}

/// The seed's Table 7: the transmission angle γ (a rocker) or the pressure angle λ at every
/// point in degrees, read off the drawing and exact, each with the exact value's verdict
/// against the limit (γ ≥ γ_min, λ ≤ λ_max = 90° − γ_min); then the extreme over the whole
/// cycle, between the points too, and whether it keeps the limit.
fn angle_table(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let cam = w.session.cam()?;
    let lang = w.lang;
    let rows: Vec<&crate::check::Row> = w
        .report
        .rows
        .iter()
        .filter(|r| r.position().is_some() && r.method == Method::Inversion)
        .filter(|r| {
            matches!(
                r.key.symbol,
                Symbol::TransmissionAngle | Symbol::PressureAngle
            )
        })
        .collect();
    if rows.is_empty() {
        return Ok(());
    }
    // The sheet's angle and limit (one notation: λ, λ_max on both, was ϑ here).
    let rocker = cam.spec.shows_transmission_angle();
    let limit = cam.spec.angle_limit();
    let keeps = |a: f64| if rocker { a >= limit } else { a <= limit };
    let deg = |a: f64| crate::scale::format_fixed(a.to_degrees(), 2, lang);
    let symbol = cam.spec.angle_symbol();
    let bound = format!(
        "{symbol} {} {} = {}°",
        if rocker { "≥" } else { "≤" },
        cam.spec.angle_limit_symbol(),
        deg(limit)
    );
    // Under force closure the angle binds on the rise only (seed 002, L1477; the extreme
    // below is taken there): a point off the rise has no verdict.
    let checked = |position: &str| {
        let phase = cam
            .points
            .iter()
            .find(|p| p.label == position)
            .map(|p| p.phase);
        cam.spec.closure != Closure::Force || phase.is_none_or(|p| p == 0)
    };
    let verdict = |r: &crate::check::Row| match r.position() {
        Some(p) if !checked(&p) => "—",
        _ if keeps(r.analytic) => w.word(T::Holds),
        _ => w.word(T::Fails),
    };
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                text(&r.position().unwrap_or_default()),
                text(&deg(r.graphical)),
                text(&deg(r.analytic)),
                text(verdict(r)),
            ]
        })
        .collect();
    let header = [
        text(w.word(T::PositionShort)),
        label(&format!("{symbol}, ° ({})", w.word(T::OnDrawing))),
        label(&format!("{symbol}, ° ({})", w.word(T::ExactShort))),
        label(&bound),
    ];
    let caption = w.word(if rocker {
        T::TransmissionTable
    } else {
        T::PressureTable
    });
    w.doc.table(caption, &[Align::Centre; 4], &header, &body);
    let force = cam.spec.closure == Closure::Force;
    if rows
        .iter()
        .filter_map(|r| r.position())
        .any(|p| !checked(&p))
    {
        w.doc.say(w.word(T::ForceClosureUnchecked));
    }
    let worst = cam.worst_angle();
    let lead = match (keeps(worst), force) {
        (true, false) => T::WorstKeeps,
        (false, false) => T::WorstBreaks,
        (true, true) => T::WorstKeepsRise,
        (false, true) => T::WorstBreaksRise,
    };
    w.doc.say(&format!(
        "{} {symbol} = {}° ({} {bound}).",
        w.word(lead),
        crate::scale::format_fixed(worst.to_degrees(), 2, lang),
        w.word(T::Allowed),
    ));
    Ok(())
}

/// The law's extremes of the analogues on each phase (the textbook's closed forms, for the
/// laws that have one), the least base radius as read off the combined diagram and, for a
/// roller the scene leaves free, its choice.
fn worked(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let cam = w.session.cam()?;
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let mm = |x: f64| Printed::mm(x, 4, lang);
    let s = &cam.spec;
    let stroke = sym(s.stroke_symbol());
    let phases = [
        (s.rise, s.phases.rise, CamText::RiseIndex.get(lang)),
        (s.ret, s.phases.ret, CamText::ReturnIndex.get(lang)),
    ];
    let mut lines = Vec::new();
    for (k, (law, phase, index)) in phases.into_iter().enumerate() {
        let Some((cv, v, ca, a)) = peaks(law) else {
            continue;
        };
        let phi = sym(&format!("φ_{{{index}}}"));
        let substituted = |c: &str, power: &str| {
            frac(
                &format!("{c} dot {}", n(s.stroke * 1e3)),
                &format!("{}{power}", n(phase)),
            )
        };
        let phase_word = [M::RisePhase, M::ReturnPhase][k];
        lines.push((
            Worked::new(
                format!("({})_(max)", sym("dS/dφ")),
                frac(&format!("{v} {stroke}"), &phi),
                substituted(v, ""),
                mm(cv * s.stroke / phase),
            ),
            vec![
                ("dS/dφ", M::VelocityAnalogue, "mm"),
                (s.stroke_symbol(), M::Stroke, "mm"),
            ],
            Some((format!("φ_{{{index}}}"), phase_word)),
        ));
        lines.push((
            Worked::new(
                format!("({})_(max)", sym("d^{2}S/dφ^{2}")),
                frac(&format!("{a} {stroke}"), &format!("{phi}^2")),
                substituted(a, "^2"),
                mm(ca * s.stroke / (phase * phase)),
            ),
            vec![("d^{2}S/dφ^{2}", M::AccelerationAnalogue, "mm")],
            None,
        ));
    }
    if !lines.is_empty() {
        w.doc.say(w.word(T::CamPeaks));
        for (l, items, phase) in lines {
            w.worked(l);
            let mut words: Vec<(&str, &str, &str)> =
                items.iter().map(|(s, m, u)| (*s, w.word(*m), *u)).collect();
            if let Some((label, m)) = &phase {
                words.push((label.as_str(), w.word(*m), "rad"));
            }
            w.explain(&words);
        }
    }
    // The base radius: |O₁B₀| on the combined diagram at μ_S.
    if !matches!(s.follower, Follower::Flat { .. }) && s.base_radius.is_none() {
        radius_worked(w, &cam);
    }
    // The base radius accepted from the r_min read, as the sheet says it.
    if s.base_radius.is_none() {
        let lines = crate::sheets::cam_marks::base_lines(&cam, None, lang);
        w.doc.say(&format!("{}.", lines.join(". ")));
    }
    if cam.roller > 0.0 && s.roller.is_none() {
        let (base, rho) = (cam.base, cam.inversion.rho_min);
        w.doc.say(w.word(T::CamRollerWorked));
        let k = |x: f64| num(x, 1, lang);
        w.worked(Worked::new(
            sym("r_{р}"),
            format!(
                "min({} {}; {} {})",
                k(0.4),
                sym("r_{0}"),
                k(0.8),
                sym("ρ_{min}")
            ),
            format!(
                "min({} dot {}; {} dot {})",
                k(0.4),
                n(base * 1e3),
                k(0.8),
                n(rho * 1e3)
            ),
            Printed::mm(cam.roller, 4, lang),
        ));
        w.explain(&[
            ("r_{р}", w.word(M::RollerRadius), "mm"),
            ("r_{0}", w.word(M::InitialRadius), "mm"),
            ("ρ_{min}", w.word(M::CurvatureMin), "mm"),
        ]);
    }
    Ok(())
}

/// r_min read off the combined diagram, |O₁B₀|·μ_S, and a rocker's centre distance a_w,
/// |O₁O₂|·μ_S, off the same drawing.
fn radius_worked(w: &mut Writer<'_, '_>, cam: &crate::cam::Cam) {
    let (mu, lang) = (cam.diagrams.s_scale, w.lang);
    let read_off = |symbol: &str, segment: &str, x: f64| {
        Worked::new(
            sym(symbol),
            format!("{} dot {}", sym(segment), sym("μ_{S}")),
            format!(
                "{} dot {}",
                num(mu.to_mm(x), 4, lang),
                num(mu.value(), 4, lang)
            ),
            Printed::si(x, 4, "m", lang),
        )
    };
    w.doc.say(w.word(T::CamRadiusWorked));
    w.worked(read_off("r_{min}", "O_{1}B_{0}", cam.radius.graphical));
    w.explain(&[
        ("r_{min}", w.word(M::BaseRadius), "m"),
        ("O_{1}B_{0}", w.word(M::DiagramSegment), "mm"),
        ("μ_{S}", w.word(M::DisplacementScale), "m/mm"),
    ]);
    if let Some(a) = cam.radius.centre_distance {
        w.worked(read_off("a_{w}", "O_{1}O_{2}", a));
        w.explain(&[
            ("a_{w}", w.word(Meaning::CentreDistance), "m"),
            ("O_{1}O_{2}", w.word(M::CentreSegment), "mm"),
        ]);
    }
}

/// A law's extremes over a phase φ of stroke h: (dS/dφ)_max = c_v·h/φ and
/// |d²S/dφ²|_max = c_a·h/φ², with the coefficients as the formula writes them; `None` for
/// the laws without a textbook closed form (uniform: infinite acceleration; trapezoidal).
fn peaks(law: Law) -> Option<(f64, &'static str, f64, &'static str)> {
    use std::f64::consts::PI;
    match law {
        Law::ConstantAcceleration { ratio } if (ratio - 0.5).abs() < 1e-12 => {
            Some((2.0, "2", 4.0, "4"))
        }
        Law::Cosine => Some((PI / 2.0, "π/2", PI * PI / 2.0, "π^2/2")),
        Law::Sine => Some((2.0, "2", 2.0 * PI, "2π")),
        _ => None,
    }
}
