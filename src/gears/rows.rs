//! The checks of the gear studies as typed rows, and the notes: the seeds' errata computed
//! from the pair (never matched), undercut, pointing and the feasible shift range.

use super::generate::Generation;
use super::involute::thickness_at;
use super::mesh::Meshing;
use super::{x_for_tip, x_min_textbook, GearPair, MIN_TIP};
use crate::check::notes::gears::{Cut, GearsNote, Junction, PairIndices, WrongBase};
use crate::check::{Key, Method, Row, Symbol};
use std::f64::consts::FRAC_PI_2;

/// A row of the whole scene.
pub(super) fn row(
    symbol: Symbol,
    subject: &str,
    method: Method,
    graphical: f64,
    analytic: f64,
    scale: f64,
) -> Row {
    Row::new(
        Key::of_scene(symbol, subject),
        method,
        graphical,
        analytic,
        scale,
    )
}

/// The pair's rows by formula: each quantity by the textbook's chain (graphical column)
/// against an independent closed form (analytic column) — α_w by the bracketed inverse
/// against Newton's, a_w = m((z₁+z₂)/2 + y) against (r_b1 + r_b2)/cos α_w, r_w = r(1 + 2y/
/// (z₁+z₂)) against r_b/cos α_w, r_a = r + (h_a* + x − Δy)m against a_w − r_f(mate) − c*m,
/// s_a by the thickness formula against the involute's polar angle, ε_α by (3.20) against
/// B₁B₂/p_b.
pub fn pair_rows(p: &GearPair) -> Vec<Row> {
    let f = Method::Formula;
    let m = p.spec.module;
    let mut out = vec![
        row(
            Symbol::EngagementAngle,
            "w",
            f,
            p.alpha_w.to_degrees(),
            p.alpha_w_newton.to_degrees(),
            p.alpha_w.to_degrees(),
        ),
        row(Symbol::CentreDistance, "w", f, p.a_w, p.a_w_base, p.a_w),
    ];
    for i in 0..2 {
        let n = i + 1;
        out.push(row(
            Symbol::Radius,
            &format!("w{n}"),
            f,
            p.rw[i],
            p.rb[i] / p.alpha_w.cos(),
            p.rw[i],
        ));
    }
    for i in 0..2 {
        let n = i + 1;
        let mate_rf = p.rf[1 - i];
        out.push(row(
            Symbol::Radius,
            &format!("a{n}"),
            f,
            p.ra[i],
            p.a_w - mate_rf - p.spec.rack.c * m,
            p.ra[i],
        ));
    }
    for i in 0..2 {
        let n = i + 1;
        // The involute's polar angle at r_a from the tooth's axis, doubled, times r_a.
        let cut = super::Cutting::with_tip(m, p.spec.z[i], p.spec.x[i], p.spec.rack, p.ra[i]);
        let polar = cut.map_or(f64::NAN, |c| {
            let q = c.involute_at_radius(p.ra[i]);
            2.0 * p.ra[i] * (FRAC_PI_2 - q.y.atan2(q.x))
        });
        out.push(row(
            Symbol::ToothThickness,
            &format!("a{n}"),
            f,
            thickness_at(p.s[i], p.r[i], p.spec.rack.alpha, p.ra[i]),
            polar,
            m,
        ));
    }
    out.push(row(
        Symbol::ContactRatio,
        "alpha",
        f,
        p.eps_formula,
        p.eps,
        p.eps,
    ));
    out.extend(parameter_rows(p));
    out
}

/// The rest of the parameters seed 000 §4.3 lists, each by its formula against another
/// route: y = (a_w − a)/m against (z₁+z₂)/2·(cos α/cos α_w − 1) at Newton's α_w; Δy = x_Σ − y
/// (or the table's) against x_Σ less that y (the table's Δy shows its rounding); u₁₂ = z₂/z₁ against r_w2/r_w1; p = πm and
/// p_b = πm cos α against 2πr/z and 2πr_b/z; per wheel r = mz/2 against r_w cos α_w/cos α,
/// r_b = r cos α against r_w cos α_w, r_f = r − (h_a* + c* − x)m against a_w − r_a(mate) −
/// c*m, s = m(π/2 + 2x tg α) against the pitch less the rack's tooth on the line xm off its
/// mean line, α_a = arccos(r_b/r_a) against arctg(√(r_a² − r_b²)/r_b), h = r_a − r_f against
/// (2h_a* + c* − Δy)m.
fn parameter_rows(p: &GearPair) -> Vec<Row> {
    use std::f64::consts::PI;
    let f = Method::Formula;
    let s = &p.spec;
    let (m, alpha, rack) = (s.module, s.rack.alpha, s.rack);
    let zsum = f64::from(s.z[0] + s.z[1]);
    let y_twin = zsum / 2.0 * (alpha.cos() / p.alpha_w_newton.cos() - 1.0);
    let dy_twin = s.x_sum() - y_twin;
    let z = |i: usize| f64::from(s.z[i]);
    let mut out = vec![
        row(Symbol::DistanceCoefficient, "", f, p.y, y_twin, 1.0),
        row(Symbol::EqualisingShift, "", f, p.dy, dy_twin, 1.0),
        row(
            Symbol::GearRatio,
            "12",
            f,
            z(1) / z(0),
            p.rw[1] / p.rw[0],
            z(1) / z(0),
        ),
        row(Symbol::Pitch, "", f, p.p, 2.0 * PI * p.r[0] / z(0), p.p),
        row(Symbol::Pitch, "b", f, p.p_b, 2.0 * PI * p.rb[0] / z(0), p.p),
    ];
    for i in 0..2 {
        let n = i + 1;
        let via_w = p.rw[i] * p.alpha_w.cos();
        let rack_tooth = PI * m / 2.0 - 2.0 * s.x[i] * m * alpha.tan();
        let reach = (p.ra[i] * p.ra[i] - p.rb[i] * p.rb[i]).max(0.0).sqrt();
        out.extend([
            row(
                Symbol::Radius,
                &n.to_string(),
                f,
                p.r[i],
                via_w / alpha.cos(),
                p.r[i],
            ),
            row(Symbol::Radius, &format!("b{n}"), f, p.rb[i], via_w, p.r[i]),
            row(
                Symbol::Radius,
                &format!("f{n}"),
                f,
                p.rf[i],
                p.a_w - p.ra[1 - i] - rack.c * m,
                p.r[i],
            ),
            row(
                Symbol::ToothThickness,
                &n.to_string(),
                f,
                p.s[i],
                p.p - rack_tooth,
                m,
            ),
            row(
                Symbol::EngagementAngle,
                &format!("a{n}"),
                f,
                p.alpha_a[i].to_degrees(),
                reach.atan2(p.rb[i]).to_degrees(),
                p.alpha_a[i].to_degrees(),
            ),
            row(
                Symbol::Length,
                &n.to_string(),
                f,
                p.ra[i] - p.rf[i],
                (2.0 * rack.ha + rack.c - p.dy) * m,
                m,
            ),
        ]);
    }
    out
}

/// The rows read off the meshing picture: a_w (O₁O₂), N₁N₂, B₁B₂, ε′ = B₁B₂/p_b; and off
/// the diagram of specific sliding beside it, λ₁, λ₂ at B₁, P, B₂ (by position).
pub fn meshing_rows(p: &GearPair, mesh: &Meshing) -> Vec<Row> {
    let me = Method::Meshing;
    let mut out = vec![
        row(
            Symbol::CentreDistance,
            "w",
            me,
            mesh.a_w.value,
            p.a_w,
            p.a_w,
        ),
        row(Symbol::ActionLength, "N1N2", me, mesh.g.value, p.g, p.g),
        row(Symbol::ActionLength, "B1B2", me, mesh.ab.value, p.ab, p.g),
        row(Symbol::ContactRatio, "alpha", me, mesh.eps, p.eps, p.eps),
    ];
    // The zero reference of λ: the larger |λ| at the ends of the active line.
    let scale = mesh
        .lambda
        .iter()
        .flat_map(|s| p.sliding(s.x))
        .filter(|v| v.is_finite())
        .fold(1.0_f64, |a, v| a.max(v.abs()));
    for s in &mesh.lambda {
        let exact = p.sliding(s.x);
        for (i, (read, exact)) in s.read.iter().zip(exact).enumerate() {
            let key = Key::at_position(Symbol::SpecificSliding, (i + 1).to_string(), &s.name);
            out.push(Row::new(key, Method::SlidingDiagram, *read, exact, scale));
        }
    }
    out
}

/// The suffix of a generated wheel's subjects: none for wheel `1`, `_name` otherwise.
fn suffix(name: &str) -> String {
    if name == "1" {
        String::new()
    } else {
        format!("_{name}")
    }
}

/// The subject a generated wheel's row `subject` has without the wheel's `name` (`a` of
/// `a0`, `min` of `min_p`, `deviation` of `deviation`): the quantity's own subscript; `None`
/// for a subject not the wheel's ([`generation_rows`] names them).
pub fn bare_subject(subject: &str, name: &str) -> Option<&'static str> {
    let own =
        |bare: &'static str, tail: &str| (subject.strip_prefix(bare) == Some(tail)).then_some(bare);
    let sfx = suffix(name);
    ["min", "deviation"]
        .into_iter()
        .find_map(|b| own(b, &sfx))
        .or_else(|| ["a", "t", "b"].into_iter().find_map(|b| own(b, name)))
}

/// The textbook's x_min = (17 − z)/17 is h_a* − z sin²α/2 rounded for h_a* = 1 and α = 20°
/// (1/17 ≈ sin²20°/2): it holds for that rack only (at α = 25° it gives −1.82 for z = 48
/// against the exact −3.29).
fn textbook_rule_holds(rack: &super::BasicRack) -> bool {
    (rack.alpha.to_degrees() - 20.0).abs() < 1e-9 && (rack.ha - 1.0).abs() < 1e-12
}

/// The rows of a rack generation of the wheel `name`: x_min exact (analytic) beside the
/// textbook's (17 − z)/17 (formula; for the rack it holds for, [`textbook_rule_holds`]), the
/// tip thickness read off the drawn tooth
/// (`s_a<name>`, envelope) and the drawn envelope's deviation from the exact one.
pub fn generation_rows(name: &str, g: &Generation) -> Vec<Row> {
    let c = &g.cutting;
    let sfx = suffix(name);
    let mut out = Vec::new();
    if textbook_rule_holds(&c.rack) {
        out.push(row(
            Symbol::ShiftCoefficient,
            &format!("min{sfx}"),
            Method::Formula,
            x_min_textbook(c.z),
            c.x_min(),
            1.0,
        ));
    }
    out.extend([
        row(
            Symbol::ToothThickness,
            &format!("a{name}"),
            Method::Envelope,
            g.sa,
            c.sa(),
            c.module,
        ),
        row(
            Symbol::EnvelopeDeviation,
            &format!("deviation{sfx}"),
            Method::Envelope,
            g.deviation,
            0.0,
            c.module,
        ),
    ]);
    // The report form's readings (PZ1 Tables 1.1/1.2) against the exact envelope: S_t and
    // e_t = πm − S_t on the pitch circle, S_b on the base circle (thinned by an undercut).
    let (st, et) = g.pitch_reading;
    if let Some(exact) = c.thickness_at_radius(c.r()) {
        out.push(row(
            Symbol::ToothThickness,
            &format!("t{name}"),
            Method::Envelope,
            st,
            exact,
            c.module,
        ));
        let space = std::f64::consts::PI * c.module - exact;
        out.push(row(
            Symbol::SpaceWidth,
            &format!("t{name}"),
            Method::Envelope,
            et,
            space,
            c.module,
        ));
    }
    if let (Some(sb), Some(exact)) = (g.sb, c.thickness_at_radius(c.rb())) {
        out.push(row(
            Symbol::ToothThickness,
            &format!("b{name}"),
            Method::Envelope,
            sb,
            exact,
            c.module,
        ));
    }
    out
}

/// The notes of a generation: undercut (drawing and criterion), pointing, x_min, the
/// feasible range of x, the junction.
pub fn generation_notes(name: &str, g: &Generation) -> Vec<GearsNote> {
    let c = &g.cutting;
    let m = c.module;
    let wheel = || name.to_string();
    let exact = c.junction().0;
    vec![
        GearsNote::Cut(Cut {
            wheel: wheel(),
            z: c.z,
            x: c.x,
            steps: g.steps,
            drawn: g.undercut,
            undercut: c.undercut(),
            depth: (-c.rack.per_module().vj - c.x) * m,
            limit: c.r() * c.rack.alpha.sin().powi(2),
        }),
        GearsNote::Shift {
            wheel: wheel(),
            x_min: c.x_min(),
            textbook: textbook_rule_holds(&c.rack).then(|| x_min_textbook(c.z)),
            pointing: x_for_tip(c.z, &c.rack, MIN_TIP),
        },
        GearsNote::Junction(Junction {
            wheel: wheel(),
            drawn: g.junction.length(),
            exact: exact.length(),
            undercut: c.undercut(),
            apart: (g.junction - exact).length() / m,
            touch: g.touch_error / m,
        }),
        GearsNote::Tip {
            wheel: wheel(),
            read: g.sa,
            module: m,
            exact: c.sa(),
            pointed: g.pointed,
        },
    ]
}

/// The centre distance of the textbook's table route: y = x_Σ − Δy with the table's Δy,
/// a_w = m(z_Σ/2 + y).
pub fn table_a_w(p: &GearPair) -> f64 {
    let zs = f64::from(p.spec.z[0] + p.spec.z[1]);
    p.spec.module * (zs / 2.0 + p.spec.x_sum() - p.dy)
}

/// What a source prints for the pair (`[gears.seed]`), SI: each claim is checked against the
/// pair and flagged where it is not reproduced. A scene without it gets no erratum note.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairSeed {
    /// The contact ratio ε_α as printed.
    pub eps_alpha: Option<f64>,
    /// The working pressure angle α_w as printed, rad.
    pub alpha_w: Option<f64>,
    /// cos α_w as printed.
    pub cos_alpha_w: Option<f64>,
    /// The centre distance a_w as printed, m.
    pub a_w: Option<f64>,
    /// The pitch p as printed, m.
    pub pitch: Option<f64>,
}

/// The notes of a pair: ε_α ≥ 1.1, the radial clearances, the table route (α_w read in
/// the inv table; with the table's Δy, y and a_w), and the source's printed values (`seed`)
/// checked against this pair — an α_w off the table's own reading, an ε_α from the base
/// radius r·cos α_w (seed 000: 1.22), a cos α_w misread with the a_w it gives (seed 002 PZ3:
/// 0.8836, 180.79 mm), a pitch that is not πm.
pub fn pair_notes(p: &GearPair, seed: Option<&PairSeed>) -> Vec<GearsNote> {
    let m = p.spec.module;
    let seed = seed.copied().unwrap_or_default();
    let mut out = vec![GearsNote::Pair(PairIndices {
        z: p.spec.z,
        x: p.spec.x,
        alpha_w: p.alpha_w,
        a_w: p.a_w,
        y: p.y,
        dy: p.dy,
        eps: p.eps,
        clearance: p.clearance,
        nominal: p.spec.rack.c * m,
    })];
    // The table route: inv α_w written to six decimals and read in the inv table.
    if let Some(table) = super::involute::alpha_by_table(p.inv_w) {
        // A printed α_w more than half a second off the table's reading is not reproduced.
        let printed = seed
            .alpha_w
            .filter(|a| (a - table).abs() > (0.5 / 3600.0_f64).to_radians());
        out.push(GearsNote::InvTable {
            inv: p.inv_w,
            table,
            exact: p.alpha_w,
            printed,
        });
    }
    if p.spec.dy_table.is_some() {
        out.push(GearsNote::Tables {
            dy: p.dy,
            y: p.spec.x_sum() - p.dy,
            a_w: table_a_w(p),
            exact: p.a_w,
            y_exact: p.y,
        });
    }
    out.extend(seed_notes(p, &seed));
    out
}

/// The erratum notes of the printed values that this pair does not reproduce.
fn seed_notes(p: &GearPair, seed: &PairSeed) -> Vec<GearsNote> {
    let mut out = Vec::new();
    // The base radius r·cos α_w and the base pitch πm·cos α_w (seed 000 §4).
    let wrong_pb = p.p * p.alpha_w.cos();
    let from_wrong_base = p.ab / wrong_pb;
    if let Some(e) = seed.eps_alpha.filter(|e| (e - p.eps).abs() > 0.005) {
        out.push(if (e - from_wrong_base).abs() < 0.01 {
            GearsNote::EpsFromWrongBase(WrongBase {
                printed: e,
                radii: [p.r[0] * p.alpha_w.cos(), p.r[1] * p.alpha_w.cos()],
                pitch: wrong_pb,
                eps_from: from_wrong_base,
                p_b: p.p_b,
                eps: p.eps,
            })
        } else {
            GearsNote::EpsNotReproduced {
                printed: e,
                eps: p.eps,
            }
        });
    }
    // A misread cos α_w and the centre distance a·cos α / cos α_w it gives (seed 002 PZ3).
    if let Some(c) = seed
        .cos_alpha_w
        .filter(|c| (c - p.alpha_w.cos()).abs() > 5e-5)
    {
        out.push(GearsNote::CosMisread {
            read: c,
            a_w_read: p.a * p.spec.rack.alpha.cos() / c,
            printed: seed.a_w,
            cos: p.alpha_w.cos(),
            a_w: p.a_w,
        });
    } else if let Some(a) = seed.a_w.filter(|a| (a - p.a_w).abs() > 5e-6) {
        out.push(GearsNote::AwNotReproduced {
            printed: a,
            a_w: p.a_w,
        });
    }
    if let Some(t) = seed.pitch.filter(|t| (t - p.p).abs() > 5e-6) {
        out.push(GearsNote::Pitch {
            printed: t,
            pitch: p.p,
        });
    }
    out
}
