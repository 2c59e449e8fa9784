//! The flywheel's size from its moment of inertia (the seed's 000 §5, L1454–1480): the
//! diameter D = (J/(K_j·ρ))^(1/5), the mass m = K_m·ρ·D³ and the main dimensions as
//! fractions of D — a rim with spokes and a hub, or a disc of width 0.2·D with its bore. The part
//! drawing is [`super::part`]'s.

use super::spec::{FlywheelKind, FlywheelSpec};

/// The flywheel's size.
#[derive(Debug, Clone, PartialEq)]
pub struct Size {
    /// Its kind.
    pub kind: FlywheelKind,
    /// Its moment of inertia, kg·m².
    pub j: f64,
    /// Outer diameter D, m.
    pub d: f64,
    /// Mass, kg.
    pub mass: f64,
    /// The main dimensions (name in label markup, m), in drawing order.
    pub dims: Vec<(&'static str, f64)>,
}

impl Size {
    /// The dimension named `name`, m.
    pub fn dim(&self, name: &str) -> Option<f64> {
        self.dims.iter().find(|d| d.0 == name).map(|d| d.1)
    }
}

impl Size {
    /// The rim's peripheral speed at the crank's mean angular velocity `w` (rad/s):
    /// v = ω·D/2, m/s.
    pub fn rim_speed(&self, w: f64) -> f64 {
        w.abs() * self.d / 2.0
    }
}

/// The densest grey cast iron, kg/m³: a lighter flywheel is cast iron, a denser one steel.
const CAST_IRON_RHO: f64 = 7600.0;

impl FlywheelSpec {
    /// Whether the flywheel is grey cast iron (ρ up to [`CAST_IRON_RHO`]), else steel.
    pub fn cast_iron(&self) -> bool {
        self.rho <= CAST_IRON_RHO
    }

    /// The rim speed its material allows, m/s: grey cast iron 25 m/s (seed 000 L1452 takes
    /// СЧ12 for a rim below 25 m/s), steel 40 m/s (the course handbooks' limit of a
    /// steel rim).
    pub fn rim_speed_limit(&self) -> f64 {
        if self.cast_iron() {
            25.0
        } else {
            40.0
        }
    }
}

/// The main dimensions of a rim with spokes and a hub (seed 000 L1471–1480), in the order
/// each is found: (name in label markup, factor, the dimension it is a fraction of). The
/// spokes' section is an ellipse b/a = 0.4 (the seed's "b1 = 1.1b", "b2 = 0.352b" are
/// garbled; its values follow b/a = 0.4).
const RIM: [(&str, f64, &str); 9] = [
    ("d_{1}", 0.2, "D"),
    ("d_{2}", 0.3, "D"),
    ("d_{3}", 0.8, "D"),
    ("b", 0.125, "D"),
    ("b_{ст}", 1.05, "b"),
    ("a_{1}", 1.1, "b"),
    ("a_{2}", 0.88, "b"),
    ("b_{1}", 0.4, "a_{1}"),
    ("b_{2}", 0.4, "a_{2}"),
];

/// The main dimensions of a disc: the bore and the width.
const DISC: [(&str, f64, &str); 2] = [
    ("d_{1}", FlywheelSpec::DISC_BORE, "D"),
    ("b", FlywheelSpec::DISC_WIDTH, "D"),
];

impl Size {
    /// How the dimension `name` follows from the others: (factor, the dimension it is a
    /// fraction of), `d_{1}` = 0.2·D; `None` for D itself and for a name the kind lacks.
    pub fn rule(&self, name: &str) -> Option<(f64, &'static str)> {
        rules(self.kind)
            .iter()
            .find(|r| r.0 == name)
            .map(|r| (r.1, r.2))
    }
}

/// The proportions of a flywheel of `kind`.
fn rules(kind: FlywheelKind) -> &'static [(&'static str, f64, &'static str)] {
    match kind {
        FlywheelKind::Rim => &RIM,
        FlywheelKind::Disc => &DISC,
    }
}

/// The size of a flywheel of inertia `j` (kg·m², ≥ 0).
pub fn size(spec: &FlywheelSpec, j: f64) -> Size {
    of_diameter(spec, (j.max(0.0) / (spec.k_j * spec.rho)).powf(0.2), j)
}

/// The flywheel made for an inertia `j` (kg·m², ≥ 0): its outer diameter rounded up to a
/// whole [`diameter_step`], as a designer takes it, and its inertia K_j·ρ·D⁵ at that
/// diameter, below `j` by a rounding residue at most.
pub fn made(spec: &FlywheelSpec, j: f64) -> Size {
    let exact = size(spec, j).d;
    let step = diameter_step(exact);
    // A diameter a rounding residue over a whole step is that step.
    let d = ((exact / step) * (1.0 - 1e-12)).ceil() * step;
    of_diameter(spec, d, spec.k_j * spec.rho * d.powi(5))
}

/// The step an outer diameter `d` (m) is rounded up to, m: whole 10 mm, whole mm below
/// 100 mm.
pub fn diameter_step(d: f64) -> f64 {
    if d < 0.1 {
        0.001
    } else {
        0.01
    }
}

/// A flywheel of outer diameter `d` (m) and inertia `j` (kg·m²).
fn of_diameter(spec: &FlywheelSpec, d: f64, j: f64) -> Size {
    let mass = spec.k_m * spec.rho * d.powi(3);
    let mut dims = vec![("D", d)];
    for &(name, factor, of) in rules(spec.kind) {
        let base = dims.iter().find(|x| x.0 == of).map_or(0.0, |x| x.1);
        dims.push((name, factor * base));
    }
    Size {
        kind: spec.kind,
        j,
        d,
        mass,
        dims,
    }
}
