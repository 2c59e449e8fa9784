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

/// The flywheel's axial half-sections (the axis horizontal) with its main dimensions, at a
/// round μ_l that draws D about 120 mm.
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
    let mut rec = Recorder::in_context("flywheel", mu, ctx);
    let d = mu.to_mm(size.d);
    let outline = |rec: &mut Recorder, note: &str, x: (f64, f64), y: (f64, f64)| {
        for sgn in [1.0, -1.0] {
            let pts = vec![
                DVec2::new(x.0, sgn * y.0),
                DVec2::new(x.1, sgn * y.0),
                DVec2::new(x.1, sgn * y.1),
                DVec2::new(x.0, sgn * y.1),
            ];
            rec.draw(
                note.to_string(),
                Item::Polyline {
                    points: pts,
                    closed: true,
                },
                Role::Given,
                &[],
            );
        }
    };
    let (b, hub_len, bore, hub) = match size.kind {
        FlywheelKind::Rim => (mm("b"), mm("b_{ст}"), mm("d_{1}"), mm("d_{2}")),
        FlywheelKind::Disc => (mm("b"), mm("b"), mm("d_{1}"), mm("d_{1}")),
    };
    match size.kind {
        FlywheelKind::Rim => {
            outline(
                &mut rec,
                "rim",
                (-b / 2.0, b / 2.0),
                (mm("d_{3}") / 2.0, d / 2.0),
            );
            outline(
                &mut rec,
                "hub",
                (-hub_len / 2.0, hub_len / 2.0),
                (bore / 2.0, hub / 2.0),
            );
            let w = mm("b_{2}");
            outline(
                &mut rec,
                "spoke",
                (-w / 2.0, w / 2.0),
                (hub / 2.0, mm("d_{3}") / 2.0),
            );
        }
        FlywheelKind::Disc => {
            outline(&mut rec, "disc", (-b / 2.0, b / 2.0), (bore / 2.0, d / 2.0));
        }
    }
    let span = hub_len.max(b) / 2.0 + 8.0;
    rec.draw(
        "axis",
        Item::Segment(Segment::new(DVec2::new(-span, 0.0), DVec2::new(span, 0.0))),
        Role::Axis,
        &[],
    );
    let mut dims: Vec<(&str, f64)> = vec![("D", d)];
    if size.kind == FlywheelKind::Rim {
        dims.push(("d_{3}", mm("d_{3}")));
        dims.push(("d_{2}", hub));
    }
    dims.push(("d_{1}", bore));
    let mut x = hub_len.max(b) / 2.0;
    for (name, len) in dims {
        x += 9.0;
        let id = rec.draw(
            format!("dimension {name}"),
            Item::Dimension {
                from: DVec2::new(x, -len / 2.0),
                to: DVec2::new(x, len / 2.0),
                offset: 0.0,
            },
            Role::Dimension,
            &[],
        );
        let value = crate::scale::format_fixed(len * mu.value() * 1e3, 0, crate::scale::Lang::En);
        rec.label(
            id,
            format!("⌀{value}"),
            DVec2::new(x, len / 4.0),
            DVec2::new(1.0, 0.0),
        );
        let _ = name;
    }
    let id = rec.draw(
        "dimension b",
        Item::Dimension {
            from: DVec2::new(-b / 2.0, d / 2.0),
            to: DVec2::new(b / 2.0, d / 2.0),
            offset: 6.0,
        },
        Role::Dimension,
        &[],
    );
    let value = crate::scale::format_fixed(b * mu.value() * 1e3, 0, crate::scale::Lang::En);
    rec.label(
        id,
        value,
        DVec2::new(0.0, d / 2.0 + 6.0),
        DVec2::new(0.0, 1.0),
    );
    Ok(rec.finish())
}
