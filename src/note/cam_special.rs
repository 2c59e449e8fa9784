//! The cam section's worked formulas for a flat-faced rocker (the face's start ψ₀, the
//! profile's radius of curvature) and a translating cam (the pressure angle from the law
//! laid along the travel, the shortest travel X_min, the roller against ρ_min): symbols,
//! numbers, result, every number the session's.

use super::markup::{frac, num, sym, unit};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::cam::{Special, SpecialProfile};
use crate::check::{Key, Symbol};
use crate::study::StudyError;
use crate::words::{unit_in, CaseMeaning as M, NoteText as T};
use std::f64::consts::TAU;

/// The worked formulas of `cam`.
pub(super) fn worked(w: &mut Writer<'_, '_>, cam: &Special) -> Result<(), NoteError> {
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let mm = |x: f64| format!("{}{}", num(x * 1e3, 4, lang), unit(&unit_in("mm", lang)));
    let deg = |x: f64| format!("{}°", num(x.to_degrees(), 4, lang));
    let study = |e| NoteError::Study(StudyError::Cam(e));
    let rho = cam.exact_rho_min().map_err(study)?;
    let drawn = cam.drawn_rho_min();
    match &cam.profile {
        SpecialProfile::FlatRocker { frame, .. } => {
            let ratio = (frame.base + frame.face_offset) / frame.centres;
            w.doc.say(w.word(T::CamFlatRockerStart));
            w.worked(
                Worked::new(
                    format!("sin {}", sym("ψ_{0}")),
                    frac(&format!("{} + {}", sym("r_{0}"), sym("e")), &sym("a")),
                    frac(
                        &format!("{} + {}", n(frame.base * 1e3), n(frame.face_offset * 1e3)),
                        &n(frame.centres * 1e3),
                    ),
                    Printed::plain(ratio, 4, lang),
                )
                .aside(format!(", quad {} = {}", sym("ψ_{0}"), deg(ratio.asin()))),
            );
            w.explain(&[
                ("ψ_{0}", w.word(M::RockerStart), "deg"),
                ("r_{0}", w.word(M::InitialRadius), "mm"),
                ("e", w.word(M::FaceOffset), "mm"),
                ("a", w.word(M::Centres), "mm"),
            ]);
            w.doc.say(w.word(T::CamFlatRockerCurvature));
            w.formula(&format!(
                "{} = {} + {}, quad {} = {} sin {} - {}",
                sym("ρ"),
                sym("h"),
                frac(&format!("d^2 {}", sym("h")), &format!("d {}^2", sym("α"))),
                sym("h"),
                sym("a"),
                sym("ψ"),
                sym("e")
            ));
            w.explain(&[
                ("ρ", w.word(M::Curvature), "mm"),
                ("h", w.word(M::FaceDistance), "mm"),
            ]);
            let board = format!(" quad (\"{}\" {})", w.word(T::CamOnTheBoard), mm(drawn));
            w.worked(
                Worked::new(sym("ρ_{min}"), "", "", Printed::mm(rho, 4, lang))
                    .aside(board)
                    .gives(Key::of_scene(Symbol::CurvatureRadius, "min")),
            );
            w.explain(&[("ρ_{min}", w.word(M::CurvatureMin), "mm")]);
        }
        SpecialProfile::Sliding { frame, .. } => {
            let lambda_max = cam.lambda_max();
            let Some((read, exact)) = cam.travel_min() else {
                return Ok(());
            };
            // max|dS/dφ| from X_min = 2π·max|S′|/tg λ_max.
            let v = exact * lambda_max.tan() / TAU;
            w.doc.say(w.word(T::CamSlidingAngle));
            w.formula(&format!(
                "op(\"tg\") {} = {} = {} dot {}",
                sym("λ"),
                frac(&sym("dS"), &sym("dξ")),
                sym("dS/dφ"),
                frac("2π", &sym("X"))
            ));
            w.explain(&[
                ("λ", w.word(M::PressureAngle), "deg"),
                ("ξ", w.word(M::CamTravel), "mm"),
                ("X", w.word(M::CamLength), "mm"),
            ]);
            let board = format!(" quad (\"{}\" {})", w.word(T::CamOnTheBoard), mm(read));
            w.worked(
                Worked::new(
                    sym("X_{min}"),
                    frac(
                        &format!("2π dot max|{}|", sym("dS/dφ")),
                        &format!("op(\"tg\") {}", sym("λ_{max}")),
                    ),
                    frac(
                        &format!("2π dot {}", n(v * 1e3)),
                        &format!("op(\"tg\") {}", deg(lambda_max)),
                    ),
                    Printed::mm(exact, 4, lang),
                )
                .aside(board)
                .gives(Key::of_scene(Symbol::Length, "travel_min")),
            );
            w.explain(&[
                ("X_{min}", w.word(M::CamLengthMin), "mm"),
                ("λ_{max}", w.word(M::PressureMax), "deg"),
            ]);
            if rho.is_finite() {
                w.doc.say(w.word(T::CamSlidingRoller));
                let sign = if frame.roller < rho { "<" } else { ">=" };
                w.formula(&format!(
                    "{} = {} {sign} {} = {} quad (\"{}\" {})",
                    sym("r_{р}"),
                    mm(frame.roller),
                    sym("ρ_{min}"),
                    mm(rho),
                    w.word(T::CamOnTheBoard),
                    mm(drawn)
                ));
                w.explain(&[
                    ("r_{р}", w.word(M::RollerRadius), "mm"),
                    ("ρ_{min}", w.word(M::CurvatureMin), "mm"),
                ]);
            }
        }
    }
    Ok(())
}
