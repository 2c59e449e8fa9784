//! The flywheel's size from its moment of inertia (the seed's 000 §5, L1454–1480): the
//! diameter D = (J/(K_j·ρ))^(1/5), the mass m = K_m·ρ·D³ and the main dimensions as
//! fractions of D — a rim with spokes and a hub, or a solid disc of width 0.2·D.

use super::spec::{FlywheelKind, FlywheelSpec};
use super::DynamicsError;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};

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

/// The size of a flywheel of inertia `j` (kg·m², ≥ 0).
pub fn size(spec: &FlywheelSpec, j: f64) -> Size {
    let d = (j.max(0.0) / (spec.k_j * spec.rho)).powf(0.2);
    let mass = spec.k_m * spec.rho * d.powi(3);
    let dims = match spec.kind {
        FlywheelKind::Rim => {
            let b = 0.125 * d;
            let (a1, a2) = (1.1 * b, 0.88 * b);
            vec![
                ("D", d),
                ("d_{1}", 0.2 * d),
                ("d_{2}", 0.3 * d),
                ("d_{3}", 0.8 * d),
                ("b", b),
                ("b_{ст}", 1.05 * b),
                ("a_{1}", a1),
                ("a_{2}", a2),
                ("b_{1}", 0.4 * a1),
                ("b_{2}", 0.4 * a2),
            ]
        }
        FlywheelKind::Disc => vec![
            ("D", d),
            ("d_{1}", 0.2 * d),
            ("b", FlywheelSpec::DISC_WIDTH * d),
        ],
    };
    Size {
        kind: spec.kind,
        j,
        d,
        mass,
        dims,
    }
}

/// The flywheel as a part drawing (seed 000 L1447–1481), at a round μ_l that draws D about
/// 120 mm: at the left its axial section through two spokes — the rim and the hub cut and
/// hatched, the spokes cut lengthwise left unhatched (ГОСТ 2.305), tapering from b₁ at the
/// hub to b₂ at the rim — with ⌀D, ⌀d₃, ⌀d₂, ⌀d₁ on extension lines and b, b_ст; at the
/// right its front view: the rim, the hub and the bore, four spokes tapering from a₁ to a₂,
/// one with its elliptical section a × b superimposed, hatched. A disc is drawn in section
/// alone.
///
/// # Errors
/// No scale can be chosen (a flywheel of zero size).
pub fn section(size: &Size, ctx: &Context) -> Result<Figure, DynamicsError> {
    // No flywheel needed: nothing to draw.
    if !(size.d > 0.0 && size.d.is_finite()) {
        let unit = Scale::new(1.0, Quantity::Length).ok_or(DynamicsError::NoScale {
            what: "μ_l of the flywheel",
            value: size.d,
        })?;
        return Ok(Recorder::in_context("flywheel", unit, ctx).finish());
    }
    let mu = Scale::round_for(size.d, 120.0, Quantity::Length).ok_or(DynamicsError::NoScale {
        what: "μ_l of the flywheel",
        value: size.d,
    })?;
    let mm = |name: &str| mu.to_mm(size.dim(name).unwrap_or(0.0));
    let text = |name: &str| {
        let v = size.dim(name).unwrap_or(0.0) * 1e3;
        crate::scale::format_fixed(v, 0, crate::scale::Lang::En)
    };
    let mut rec = Recorder::in_context("flywheel", mu, ctx);
    let d = mu.to_mm(size.d);
    let rim = size.kind == FlywheelKind::Rim;
    let (b, hub_len, bore, hub) = if rim {
        (mm("b"), mm("b_{ст}"), mm("d_{1}"), mm("d_{2}"))
    } else {
        (mm("b"), mm("b"), mm("d_{1}"), mm("d_{1}"))
    };
    // The cut material, each half (above and below the axis) an outline hatched at 45°.
    let cut = |rec: &mut Recorder, note: &str, x: (f64, f64), y: (f64, f64)| {
        for sgn in [1.0, -1.0] {
            let pts = vec![
                DVec2::new(x.0, sgn * y.0),
                DVec2::new(x.1, sgn * y.0),
                DVec2::new(x.1, sgn * y.1),
                DVec2::new(x.0, sgn * y.1),
            ];
            hatched(rec, note, &pts);
        }
    };
    if rim {
        let inner = mm("d_{3}") / 2.0;
        cut(&mut rec, "rim", (-b / 2.0, b / 2.0), (inner, d / 2.0));
        cut(
            &mut rec,
            "hub",
            (-hub_len / 2.0, hub_len / 2.0),
            (bore / 2.0, hub / 2.0),
        );
        // The spokes cut lengthwise: not hatched, b₁ at the hub to b₂ at the rim.
        let (w1, w2) = (mm("b_{1}") / 2.0, mm("b_{2}") / 2.0);
        for sgn in [1.0, -1.0] {
            for side in [1.0, -1.0] {
                rec.draw(
                    "spoke",
                    Item::Segment(Segment::new(
                        DVec2::new(side * w1, sgn * hub / 2.0),
                        DVec2::new(side * w2, sgn * inner),
                    )),
                    Role::Given,
                    &[],
                );
            }
        }
    } else {
        cut(&mut rec, "disc", (-b / 2.0, b / 2.0), (bore / 2.0, d / 2.0));
    }
    let span = hub_len.max(b) / 2.0 + 8.0;
    rec.draw(
        "axis",
        Item::Segment(Segment::new(DVec2::new(-span, 0.0), DVec2::new(span, 0.0))),
        Role::Axis,
        &[],
    );
    // The diameters at the section's left, each on extension lines from its edge.
    let mut diameters: Vec<(&str, f64, f64)> = vec![("D", d, b / 2.0)];
    if rim {
        diameters.push(("d_{3}", mm("d_{3}"), b / 2.0));
        diameters.push(("d_{2}", hub, hub_len / 2.0));
    }
    diameters.push(("d_{1}", bore, hub_len / 2.0));
    let left = hub_len.max(b) / 2.0;
    for (k, (name, len, edge)) in diameters.into_iter().enumerate() {
        let at = left + 9.0 * (k as f64 + 1.0);
        rec.dimension(
            format!("dimension {name}"),
            (
                DVec2::new(-edge, -len / 2.0),
                DVec2::new(-edge, len / 2.0),
                at - edge,
            ),
            format!("⌀{}", text(name)),
        );
    }
    rec.dimension(
        "dimension b",
        (
            DVec2::new(-b / 2.0, d / 2.0),
            DVec2::new(b / 2.0, d / 2.0),
            6.0,
        ),
        text("b"),
    );
    if rim {
        // b_ст in the bore, clear of the spokes and of the rim's sides.
        rec.dimension(
            "dimension b_ст",
            (
                DVec2::new(-hub_len / 2.0, -bore / 2.0),
                DVec2::new(hub_len / 2.0, -bore / 2.0),
                4.0,
            ),
            text("b_{ст}"),
        );
        front(&mut rec, size, mu, span + d / 2.0 + 12.0);
    }
    Ok(rec.finish())
}

/// The front view of a flywheel with spokes, centred `x` mm right of the section.
fn front(rec: &mut Recorder, size: &Size, mu: Scale, x: f64) {
    let mm = |name: &str| mu.to_mm(size.dim(name).unwrap_or(0.0));
    let c = DVec2::new(x, 0.0);
    let (outer, inner, hub, bore) = (
        mu.to_mm(size.d) / 2.0,
        mm("d_{3}") / 2.0,
        mm("d_{2}") / 2.0,
        mm("d_{1}") / 2.0,
    );
    for (note, radius) in [("rim", outer), ("rim", inner), ("hub", hub), ("bore", bore)] {
        rec.draw(
            note,
            Item::Circle(crate::geom::Circle { center: c, radius }),
            Role::Given,
            &[],
        );
    }
    let reach = outer + 5.0;
    for dir in [DVec2::X, DVec2::Y] {
        rec.draw(
            "centre line",
            Item::Segment(Segment::new(c - dir * reach, c + dir * reach)),
            Role::Axis,
            &[],
        );
    }
    // Four spokes, a₁ wide at the hub to a₂ at the rim.
    let (a1, a2) = (mm("a_{1}") / 2.0, mm("a_{2}") / 2.0);
    for dir in [DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y] {
        let n = dir.perp();
        for side in [1.0, -1.0] {
            rec.draw(
                "spoke",
                Item::Segment(Segment::new(
                    c + dir * hub + n * (side * a1),
                    c + dir * inner + n * (side * a2),
                )),
                Role::Given,
                &[],
            );
        }
    }
    // The spoke's elliptical section, superimposed on the right spoke halfway along it:
    // a across the spoke, b along it.
    let mid = c + DVec2::X * ((hub + inner) / 2.0);
    let (a, b) = (
        (mm("a_{1}") + mm("a_{2}")) / 4.0,
        (mm("b_{1}") + mm("b_{2}")) / 4.0,
    );
    let ellipse: Vec<DVec2> = (0..48)
        .map(|k| {
            let t = std::f64::consts::TAU * f64::from(k) / 48.0;
            mid + DVec2::new(b * t.cos(), a * t.sin())
        })
        .collect();
    hatched(rec, "the spoke's section", &ellipse);
}

/// A closed outline of cut material, hatched at 45° 2 mm apart (ГОСТ 2.306).
fn hatched(rec: &mut Recorder, note: &str, outline: &[DVec2]) {
    let id = rec.draw(
        note.to_string(),
        Item::Polyline {
            points: outline.to_vec(),
            closed: true,
        },
        Role::Given,
        &[],
    );
    // The outline is finite (the scale is): the hatcher refuses only non-finite ones.
    let strokes = crate::geom::hatch(outline, 2.0, std::f64::consts::FRAC_PI_4).unwrap_or_default();
    for s in strokes {
        rec.draw("hatching", Item::Segment(s), Role::Hatch, &[id]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;

    /// The seed's flywheel of J = 17.1 kg·m² (000 §5: D = 785, d₁ = 157, d₂ = 235.5, d₃ = 628,
    /// b = 98.1, b_ст = 103 mm) drawn as a part: its diameters and widths dimensioned with
    /// the values its proportions give, the rim and the hub cut and hatched on both sides of
    /// the axis, the spokes lengthwise unhatched, the front view's four spokes and the
    /// spoke's section hatched.
    #[test]
    fn the_part_drawing_dimensions_its_size_and_hatches_the_cut() {
        let size = size(&FlywheelSpec::SEED_RIM, 17.1);
        assert!((size.d - 0.7852).abs() < 5e-4, "{}", size.d);
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("context");
        let f = section(&size, &ctx).expect("drawing");
        let mut texts: Vec<String> = f
            .steps
            .iter()
            .filter(|s| s.note.starts_with("dimension "))
            .filter_map(|s| s.label.as_ref().map(|l| l.text.clone()))
            .collect();
        texts.sort();
        let mut want: Vec<String> = [
            ("D", "⌀"),
            ("d_{3}", "⌀"),
            ("d_{2}", "⌀"),
            ("d_{1}", "⌀"),
            ("b", ""),
            ("b_{ст}", ""),
        ]
        .iter()
        .map(|(n, pre)| format!("{pre}{:.0}", size.dim(n).expect("dim") * 1e3))
        .collect();
        want.sort();
        assert_eq!(texts, want);
        let count = |note: &str| f.steps.iter().filter(|s| s.note == note).count();
        // Rim and hub: a half above and below the axis each, hatched; the spoke's section.
        assert_eq!(
            count("rim"),
            2 + 2,
            "two halves in section, two circles in front"
        );
        assert_eq!(count("hub"), 2 + 1);
        assert_eq!(count("the spoke's section"), 1);
        assert!(count("hatching") > 20, "{}", count("hatching"));
        // Spokes: two tapered sides each, two in section, four in front.
        assert_eq!(count("spoke"), 2 * 2 + 4 * 2);
    }
}
