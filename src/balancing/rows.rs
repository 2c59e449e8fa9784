//! The check of a balancing: the corrections read off the polygons against their analytic
//! twin, the inertia forces of the rotor before and after balancing, and the notes with the
//! inertia force of every mass (worked example W4 of seed 001).

use super::{
    main_moment, main_vector, residual_moment, residual_vector, Balancing, Correction, Corrective,
    Mass,
};
use crate::check::notes::balancing::{BalancingNote, Inertia};
use crate::check::{Key, Method, Row, Symbol};
use crate::geom::wrap_pi;
use crate::scale::G;
use std::f64::consts::PI;

/// A row of the whole scene, by the polygon method.
fn row(symbol: Symbol, subject: &str, graphical: f64, analytic: f64, scale: f64) -> Row {
    Row::new(
        Key::of_scene(symbol, subject),
        Method::Polygon,
        graphical,
        analytic,
        scale,
    )
}

impl Balancing {
    /// The step (SI) of the row `r`'s graphical value when lengths are read to
    /// `resolution_mm` on the drawing: a force of inertia (before balancing, or the residual
    /// after it) off the polygon of static moments, `resolution_mm` × μ_mρ × ω²; a moment off
    /// the polygon of moments, × μ_mρz × ω². `None` for the other rows (each its own reading
    /// already) or when lengths are read exactly.
    pub fn reading_step(&self, r: &Row, resolution_mm: f64) -> Option<f64> {
        let w = self.spec.omega?;
        let mu = match r.key.symbol {
            Symbol::Force => self.scale_mr,
            Symbol::Moment => self.scale_mrz?,
            _ => return None,
        };
        mu.reading_step(resolution_mm).map(|s| s * w * w)
    }

    /// Σ |mᵢρᵢ|, kg·m: the scale of the static moments (their zero reference).
    fn static_scale(&self) -> f64 {
        self.spec.masses.iter().map(|m| m.mass * m.radius).sum()
    }

    /// The plane I of a dynamic balancing (the moment centre), m.
    fn moment_centre(&self) -> Option<f64> {
        match self.spec.correction {
            Correction::Static { .. } => None,
            Correction::Dynamic { planes, .. } => Some(planes[0]),
        }
    }

    /// The graphical and analytic correction of each plane, in the order I, II (or у).
    fn pairs(&self) -> Vec<(&Corrective, &Corrective)> {
        self.analytic
            .iter()
            .filter_map(|a| {
                self.graphical
                    .iter()
                    .find(|g| g.plane == a.plane)
                    .map(|g| (g, a))
            })
            .collect()
    }

    /// Every value read off the polygons against its analytic twin: m·ρ·z of plane II
    /// (dynamic), then per plane m_уρ_у, m_у and the angle of ρ_у; with ω, the main vector
    /// (and main moment about plane I) of the inertia forces before (`F_in`, `M_in`) and after
    /// (`F_res`, `M_res`, zero analytically) balancing.
    pub fn rows(&self) -> Vec<Row> {
        let mut out = Vec::new();
        let scale = self.static_scale();
        let masses = &self.spec.masses;
        if let (Some(c), Some(z0)) = (&self.moment_closing, self.moment_centre()) {
            let arm_scale: f64 = masses
                .iter()
                .map(|m| m.mass * m.radius * (m.z - z0).abs())
                .sum();
            let analytic = main_moment(masses, z0).length();
            out.push(row(
                Symbol::UnbalanceMoment,
                "II",
                c.measured.value,
                analytic,
                arm_scale,
            ));
        }
        let pairs = self.pairs();
        for (g, a) in &pairs {
            let s = a.plane.subject();
            let (gu, au) = (g.unbalance.length(), a.unbalance.length());
            out.push(row(Symbol::StaticMoment, s, gu, au, scale));
            out.push(row(Symbol::Mass, s, g.mass(), a.mass(), scale / a.radius));
        }
        for (g, a) in &pairs {
            if let (Some(ga), Some(aa)) = (g.angle(), a.angle()) {
                // The graphical direction on the analytic one's branch.
                let ga = aa + wrap_pi(ga - aa);
                out.push(row(Symbol::Angle, a.plane.subject(), ga, aa, PI));
            }
        }
        if let Some(w) = self.spec.omega {
            let w2 = w * w;
            let (graphical, analytic): (Vec<_>, Vec<_>) =
                pairs.iter().map(|(g, a)| (**g, **a)).unzip();
            let f_scale = w2 * scale;
            let before = w2 * main_vector(masses).length();
            out.push(row(
                Symbol::Force,
                "in",
                w2 * self.unbalance_read,
                before,
                f_scale,
            ));
            let res = |c: &[Corrective]| w2 * residual_vector(masses, c).length();
            out.push(row(
                Symbol::Force,
                "res",
                res(&graphical),
                res(&analytic),
                f_scale,
            ));
            if let (Some(c), Some(z0)) = (&self.moment_closing, self.moment_centre()) {
                let before = w2 * main_moment(masses, z0).length();
                let m_scale = before.max(f_scale * self.span());
                out.push(row(
                    Symbol::Moment,
                    "in",
                    w2 * c.measured.value,
                    before,
                    m_scale,
                ));
                let res = |c: &[Corrective]| w2 * residual_moment(masses, c, z0).length();
                out.push(row(
                    Symbol::Moment,
                    "res",
                    res(&graphical),
                    res(&analytic),
                    m_scale,
                ));
            }
        }
        out
    }

    /// The axial span of the masses and the planes, m (the arm scale of the moments).
    fn span(&self) -> f64 {
        let zs = self
            .spec
            .masses
            .iter()
            .map(|m| m.z)
            .chain(match self.spec.correction {
                Correction::Static { .. } => [0.0, 0.0],
                Correction::Dynamic { planes, .. } => planes,
            });
        let (lo, hi) = zs.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), z| {
            (l.min(z), h.max(z))
        });
        (hi - lo).max(0.0)
    }

    /// The notes of the report: the inertia force of every mass and its ratio to the mass's
    /// weight (with ω), and a plane that needs no correction.
    pub fn notes(&self) -> Vec<BalancingNote> {
        let mut out = Vec::new();
        for a in &self.analytic {
            if a.angle().is_none() {
                out.push(BalancingNote::NoCorrection {
                    plane: a.plane.subject().to_string(),
                });
            }
        }
        if let Some(w) = self.spec.omega {
            out.extend(inertia_notes(&self.spec.masses, w));
        }
        out
    }
}

/// A mass's inertia force at ω and its weight.
fn inertia(index: usize, m: &Mass, omega: f64) -> Inertia {
    Inertia {
        index,
        mass: m.mass,
        radius: m.radius,
        omega,
        force: inertia_force(m, omega),
        weight: m.mass * G,
        g: G,
    }
}

/// The inertia force of each mass at ω (`P_и = m·ω²·ρ`), its weight `G = m·g` and their
/// ratio `ω²ρ/g`, one note per mass — seed 001's worked example W4 (m = 0,1 kg, l = 0,1 m,
/// ω = 300 1/s: P_и = 900 N, P_и/G = 917) — and, when W4's ball is among the masses, the
/// erratum of its text, which calls the ratio "900 times" (true only for g = 10 m/s²).
pub fn inertia_notes(masses: &[Mass], omega: f64) -> Vec<BalancingNote> {
    let mut out: Vec<BalancingNote> = masses
        .iter()
        .enumerate()
        .map(|(i, m)| BalancingNote::Inertia(inertia(i + 1, m, omega)))
        .collect();
    // The seed's ball itself: its text's ratio is an erratum.
    let (ball, w4_omega) = W4;
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    let is_w4 = |m: &Mass| same(m.mass, ball.mass) && same(m.radius, ball.radius);
    if same(omega, w4_omega) && masses.iter().any(is_w4) {
        out.push(w4_erratum());
    }
    out
}

/// Seed 001's worked example W4: a ball of 0,1 kg at 0,1 m from the axis, ω = 300 1/s.
pub const W4: (Mass, f64) = (
    Mass {
        mass: 0.1,
        radius: 0.1,
        angle: 0.0,
        z: 0.0,
    },
    300.0,
);

/// The erratum of W4: its text calls the inertia force "900 times" the ball's weight, which
/// holds only for g = 10 m/s²; with g = 9,81 m/s² the ratio is ω²l/g ≈ 917.
pub fn w4_erratum() -> BalancingNote {
    let (ball, omega) = W4;
    BalancingNote::W4Erratum(inertia(1, &ball, omega))
}

/// The inertia force of a mass turning at ω, `m·ω²·ρ`, N.
pub fn inertia_force(m: &Mass, omega: f64) -> f64 {
    m.mass * omega * omega * m.radius
}
