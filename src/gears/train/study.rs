//! The train study of a scene's `[planetary]`: Willis's relations solved together (the
//! twin), the textbook's formula (the stages of a planetary train, Willis's formula of a
//! differential) and the velocity triangles (the construction), with their rows; the notes
//! live in `notes`.

use super::layout::ClosedMesh;
use super::{Train, TrainError};
use crate::gears::{rows, triangles};

/// What a source prints for the train (`[planetary.seed]`), checked in the notes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TrainSeed {
    /// The ratio u_in,out it prints.
    pub u: Option<f64>,
    /// The mobility W it prints.
    pub w: Option<i64>,
}

/// A printed value is reproduced within this share of the exact one (the source rounds).
const SEED_SHARE: f64 = 5e-3;

impl TrainSeed {
    /// Whether a printed value reproduces the exact one `exact`, to the share the source's
    /// rounding allows (0.5 %).
    pub fn reproduces(printed: f64, exact: f64) -> bool {
        (printed - exact).abs() <= SEED_SHARE * exact.abs()
    }
}

/// A planetary (or ordinary) train as a scene gives it (`[planetary]`).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetarySpec {
    /// The train.
    pub train: Train,
    /// The input's speed, rpm (signed), when given.
    pub n_input: Option<f64>,
    /// The required output speed, rpm (magnitude), when given.
    pub n_output: Option<f64>,
    /// The number of satellites k (neighbour condition), when given.
    pub satellites: Option<u32>,
    /// Whether a satellite's mesh that the train's one module leaves off the carrier's axis
    /// is taken at the module that closes it ([`Train::closing`]; `closing_module`).
    pub closing: bool,
    /// What the source prints for the train.
    pub seed: TrainSeed,
}

/// The train studied: Willis, the textbook's formula, the triangles.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainStudy {
    /// The spec.
    pub spec: PlanetarySpec,
    /// The train as drawn: the spec's, with the meshes [`Train::closing`] takes at another
    /// module when the spec asks for it.
    pub drawn: Train,
    /// The meshes taken at the module that closes them.
    pub closings: Vec<ClosedMesh>,
    /// ω of every shaft for ω_in = 1 (Willis).
    pub willis: Vec<f64>,
    /// u_in,out by Willis.
    pub ratio: f64,
    /// u by the textbook's formula: the stages of a planetary train ([`Train::by_stages`]),
    /// Willis's formula of a differential ([`Train::by_differential`]); `None` when the
    /// train is neither.
    pub formula: Option<f64>,
    /// The velocity triangles.
    pub triangles: triangles::Triangles,
    /// With n_input and n_output: the train whose first fixed-axis mesh has the ratio the
    /// required |u| = n_in/n_out asks for (the textbook's route before the tooth choice),
    /// studied alike.
    pub required: Option<Box<TrainStudy>>,
}

/// The input's ω the triangles are drawn for, rad/s: n_input·π/30, or 1 rad/s (per unit
/// input) when the scene gives no speed.
pub(super) fn omega_in(spec: &PlanetarySpec) -> f64 {
    spec.n_input.map_or(1.0, crate::scale::from_rpm)
}

/// Carry out the train study.
///
/// # Errors
/// A [`TrainError`].
pub fn train_study(
    spec: &PlanetarySpec,
    ctx: &crate::construct::Context,
) -> Result<TrainStudy, TrainError> {
    let t = &spec.train;
    let willis = t.willis()?;
    let ratio = t.ratio()?;
    let (drawn, closings) = if spec.closing {
        t.closing()?
    } else {
        (t.clone(), Vec::new())
    };
    // The stage the textbook solves for: the first fixed-axis mesh (a satellite's teeth are
    // bound by coaxiality). A design that cannot be laid out is left out.
    let required = match (spec.n_input, spec.n_output, t.fixed_axis_mesh()) {
        (Some(n_in), Some(n_out), Some(mesh)) if n_in != 0.0 => t
            .with_ratio(mesh, (n_in / n_out).abs())
            .and_then(|train| {
                let design = PlanetarySpec {
                    train,
                    n_output: None,
                    ..spec.clone()
                };
                train_study(&design, ctx)
            })
            .ok()
            .map(Box::new),
        _ => None,
    };
    Ok(TrainStudy {
        spec: spec.clone(),
        triangles: triangles::triangles(&drawn, omega_in(spec), ctx)?,
        drawn,
        closings,
        willis,
        ratio,
        formula: t.by_stages().or_else(|| t.by_differential()),
        required,
    })
}

impl TrainStudy {
    /// `u_<in>_<out>` by formula (the stages or the differential's formula against Willis)
    /// and by the triangles, the required one by formula; with n_input, ω of every shaft
    /// read off the plan of angular velocities but the given ones (the inputs, the fixed
    /// shaft).
    pub fn rows(&self) -> Vec<crate::check::Row> {
        use crate::check::{Method, Symbol};
        use rows::row;
        let t = &self.spec.train;
        let subject = format!("{}_{}", t.shafts[t.input], t.shafts[t.output]);
        let mut out = Vec::new();
        // The required train's triangles are not drawn (the sheet draws the scene's): it has
        // its formula's row only.
        let ratio_rows = |t: &TrainStudy, subject: &str, drawn: bool| {
            let at = |method, graphical| {
                row(
                    Symbol::GearRatio,
                    subject,
                    method,
                    graphical,
                    t.ratio,
                    t.ratio.abs(),
                )
            };
            t.formula
                .map(|s| at(Method::Formula, s))
                .into_iter()
                .chain(drawn.then(|| at(Method::Triangles, t.triangles.ratio)))
        };
        out.extend(ratio_rows(self, &subject, true));
        if let Some(r) = &self.required {
            out.extend(ratio_rows(r, &format!("{subject}_req"), false));
        }
        if self.spec.n_input.is_some() {
            let w_in = omega_in(&self.spec);
            let scale = self.willis.iter().fold(0.0_f64, |a, w| a.max(w.abs())) * w_in.abs();
            // A given ω — an input's, the fixed shaft's zero — is what the plan is drawn
            // from, not a result read off it.
            let given = |k: usize| {
                k == t.input || t.fixed == Some(k) || t.second.is_some_and(|(s, _)| s == k)
            };
            for (k, name) in t.shafts.iter().enumerate().filter(|(k, _)| !given(*k)) {
                out.push(row(
                    Symbol::AngularVelocity,
                    name,
                    Method::Triangles,
                    self.triangles.omega[k],
                    self.willis[k] * w_in,
                    scale,
                ));
            }
        }
        out
    }
}
