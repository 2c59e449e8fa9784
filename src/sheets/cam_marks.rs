//! What the cam's figures and data write in the sheet's language (issue 45): a construction's
//! dimension with the value it read or laid off (r_min = 69 мм, X_min/2π = 49,5 мм, ρ_min =
//! 10 мм), the phases under the displacement diagram's φ axis with their symbols and angles
//! (φ_у = 113,6°), and the line that accepts the base radius from the r_min read (Принимаем
//! r₀ = 70 мм ≥ r_min = 69 мм). The constructions record these steps with the Russian
//! textbooks' symbols; here they get the sheet's words and numbers, one place for the cam
//! sheet and the note.

use super::digits;
use crate::cam::follower::Placement;
use crate::cam::{Cam, CamSpec, PHASE_NOTES};
use crate::construct::Figure;
use crate::scale::Lang;
use crate::words::CamText;

/// The symbols of the phases in `lang`: rise, far dwell, return, near dwell.
fn phase_symbols(lang: Lang) -> [&'static str; 4] {
    [
        CamText::PhaseRise,
        CamText::PhaseFar,
        CamText::PhaseReturn,
        CamText::PhaseNear,
    ]
    .map(|t| t.get(lang))
}

/// The four phases with their angles: `φ_{у} = 113,6°, φ_{д.в.} = 14,2°, …`.
pub(super) fn phases_line(spec: &CamSpec, lang: Lang) -> String {
    let p = &spec.phases;
    phase_symbols(lang)
        .iter()
        .zip([p.rise, p.far, p.ret, p.near])
        .map(|(sym, x)| format!("{sym} = {}", digits::degrees(x, lang)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// `figure` with the label of every step noted `note` written `text`.
pub(super) fn relabelled(figure: &Figure, note: &str, text: &str) -> Figure {
    let mut out = figure.clone();
    for step in out.steps.iter_mut().filter(|s| s.note == note) {
        if let Some(label) = step.label.as_mut() {
            label.text = text.to_string();
        }
    }
    out
}

/// The angle graph's limit line with its value: `λ_{max} = 30°`, `γ_{min} = 60°`.
pub(super) fn angle_limit(spec: &CamSpec, lang: Lang) -> String {
    format!(
        "{} = {}",
        spec.angle_limit_symbol(),
        digits::degrees(spec.angle_limit(), lang)
    )
}

/// A dimension's text with its value: `r_{min} = 69 мм` for `symbol` `r_{min}` and
/// `metres` 0.069.
pub(super) fn valued(symbol: &str, metres: f64, lang: Lang) -> String {
    format!("{symbol} = {}", digits::mm(metres, lang))
}

/// r_min as read off the combined diagram to the step of `step` (m; `None`: exactly), with
/// its unit: `68,8 мм`.
pub(crate) fn r_min(cam: &Cam, step: Option<f64>, lang: Lang) -> String {
    read_mm(cam.radius.graphical, step, lang)
}

/// A length of `metres` read off a drawing to the step of `step` (m; `None`: exactly), with
/// its unit: `158,7 мм`.
pub(crate) fn read_mm(metres: f64, step: Option<f64>, lang: Lang) -> String {
    let read = digits::read(metres * 1e3, step.map(|s| s * 1e3), lang);
    format!("{read} {}", crate::words::unit_in("mm", lang))
}

/// The displacement diagram with its phases' dimensions written in `lang`.
pub(super) fn phases_marked(figure: &Figure, spec: &CamSpec, lang: Lang) -> Figure {
    let p = &spec.phases;
    let mut out = figure.clone();
    for ((note, sym), x) in PHASE_NOTES
        .iter()
        .zip(phase_symbols(lang))
        .zip([p.rise, p.far, p.ret, p.near])
    {
        out = relabelled(&out, note, &format!("{sym} = {}", digits::degrees(x, lang)));
    }
    out
}

/// The base radius the profile is built on, as the data say it: accepted from the r_min
/// read (`Принимаем r_{0} = 70 мм ≥ r_{min} = 69 мм`), after the reason when the profile's
/// check took it up (`При r_{0} = 33 мм по профилю в точке 0 λ = 30,18° > λ_{max} = 30°`),
/// or the scene's (`r_{0} = 20 мм`; under r_min, where its centre O₁′ stands: `r_{0} = 10 мм
/// (задано) < r_{min}: центр O_{1}′ в недопустимой зоне`): one sentence a line; r_min to
/// `step` ([`r_min`]).
pub(crate) fn base_lines(cam: &Cam, step: Option<f64>, lang: Lang) -> Vec<String> {
    if cam.spec.base_radius.is_some() {
        // Under the r_min read, the combined diagram marks its centre O₁′ apart from O₁.
        return vec![if cam.base < cam.radius.graphical {
            CamText::GivenUnder
                .get(lang)
                .replace("{r0}", &digits::mm(cam.base, lang))
        } else {
            format!("r_{{0}} = {}", digits::mm(cam.base, lang))
        }];
    }
    let accepted = CamText::Accepted
        .get(lang)
        .replace("{r0}", &digits::mm(cam.base, lang))
        .replace("{rmin}", &r_min(cam, step, lang));
    // The rocker's centre taken r₀ from A₀ along the direction found: the profile's a_w.
    let accepted = match cam.placement {
        Placement::Rocker { pivot, .. } => {
            format!("{accepted}, a_{{w}} = {}", digits::mm(pivot.length(), lang))
        }
        _ => accepted,
    };
    let Some(raised) = cam.raised else {
        return vec![accepted];
    };
    let spec = &cam.spec;
    let broken = format!(
        "{} = {} {} {}",
        spec.angle_symbol(),
        digits::degrees(raised.angle, lang),
        if spec.shows_transmission_angle() {
            "<"
        } else {
            ">"
        },
        angle_limit(spec, lang)
    );
    let reason = CamText::Raised
        .get(lang)
        .replace("{r0}", &digits::mm(raised.base, lang))
        .replace("{point}", &raised.at.to_string())
        .replace("{angle}", &broken);
    vec![reason, accepted]
}
