//! The checks of the gear studies as typed rows, and the notes: the seeds' errata computed
//! from the pair (never matched), undercut, pointing and the feasible shift range.

use super::generate::Generation;
use super::involute::thickness_at;
use super::mesh::Meshing;
use super::{x_for_tip, x_min_textbook, Pair, MIN_TIP};
use crate::check::{Key, Method, Row, Symbol};
use crate::scale::{format_sig, Lang};
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

/// A number for the notes.
fn num(x: f64, sig: usize) -> String {
    format_sig(x, sig, Lang::En)
}

/// The pair's rows by formula: each quantity by the textbook's chain (graphical column)
/// against an independent closed form (analytic column) — α_w by the bracketed inverse
/// against Newton's, a_w = m((z₁+z₂)/2 + y) against (r_b1 + r_b2)/cos α_w, r_w = r(1 + 2y/
/// (z₁+z₂)) against r_b/cos α_w, r_a = r + (h_a* + x − Δy)m against a_w − r_f(mate) − c*m,
/// s_a by the thickness formula against the involute's polar angle, ε_α by (3.20) against
/// B₁B₂/p_b.
pub fn pair_rows(p: &Pair) -> Vec<Row> {
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
    out
}

/// The rows read off the meshing picture: a_w (O₁O₂), N₁N₂, B₁B₂, ε′ = B₁B₂/p_b and the
/// specific sliding λ₁, λ₂ at B₁, P, B₂ (by position).
pub fn meshing_rows(p: &Pair, mesh: &Meshing) -> Vec<Row> {
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
            out.push(Row::new(key, me, *read, exact, scale));
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

/// The rows of a rack generation of the wheel `name`: x_min exact (analytic) beside the
/// textbook's (17 − z)/17 (formula), the tip thickness read off the drawn tooth
/// (`s_a<name>`, envelope) and the drawn envelope's deviation from the exact one.
pub fn generation_rows(name: &str, g: &Generation) -> Vec<Row> {
    let c = &g.cutting;
    let sfx = suffix(name);
    vec![
        row(
            Symbol::ShiftCoefficient,
            &format!("min{sfx}"),
            Method::Formula,
            x_min_textbook(c.z),
            c.x_min(),
            1.0,
        ),
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
    ]
}

/// The notes of a generation: undercut (drawing and criterion), pointing, x_min, the
/// feasible range of x, the junction.
pub fn generation_notes(name: &str, g: &Generation) -> Vec<String> {
    let c = &g.cutting;
    let m = c.module;
    let mut out = Vec::new();
    let depth = (-c.rack.per_module().vj - c.x) * m;
    let limit = c.r() * c.rack.alpha.sin().powi(2);
    out.push(format!(
        "gears: wheel {name} (z = {}, x = {}) cut by the rack in {} steps: undercut {} on the drawing ({}), {} by the criterion (the flank's end {} mm below the pitch line, the limit r·sin²α = {} mm)",
        c.z,
        num(c.x, 4),
        g.steps,
        if g.undercut { "shown" } else { "not shown" },
        if g.undercut {
            "the fillet crosses the involute"
        } else {
            "the fillet meets the involute tangentially"
        },
        if c.undercut() { "undercut" } else { "no undercut" },
        num(depth * 1e3, 5),
        num(limit * 1e3, 5),
    ));
    let range = x_for_tip(c.z, &c.rack, MIN_TIP).map_or_else(
        || "no shift gives s_a = 0.3m".to_string(),
        |x| {
            let empty = if x < c.x_min() {
                " (empty: no shift avoids both undercut and pointing)"
            } else {
                ""
            };
            format!(
                "x_min = {} … x(s_a = 0.3m) = {}{empty}",
                num(c.x_min(), 4),
                num(x, 4)
            )
        },
    );
    out.push(format!(
        "gears: wheel {name}: x_min = h_a* − z·sin²α/2 = {} (the textbook's (17 − z)/17 = {}); feasible shift: {range}",
        num(c.x_min(), 4),
        num(x_min_textbook(c.z), 4),
    ));
    let exact = c.junction().0;
    out.push(format!(
        "gears: wheel {name}: the involute meets the fillet at r = {} mm on the drawing, {} mm exactly (the involute and the trochoid intersected{}): {}·m apart; the touching points lie on the exact curves to {}·m",
        num(g.junction.length() * 1e3, 6),
        num(exact.length() * 1e3, 6),
        if c.undercut() { "" } else { ": they meet tangentially at the flank's end" },
        num((g.junction - exact).length() / m, 3),
        num(g.touch_error / m, 2),
    ));
    out.push(format!(
        "gears: wheel {name}: tip thickness s_a = {} mm = {}·m read off the drawing ({} mm exact){}",
        num(g.sa * 1e3, 5),
        num(g.sa / m, 4),
        num(c.sa() * 1e3, 5),
        if g.pointed {
            ": pointed (s_a < 0.3m)"
        } else {
            ""
        }
    ));
    out
}

/// The centre distance of the textbook's table route: y = x_Σ − Δy with the table's Δy,
/// a_w = m(z_Σ/2 + y).
pub fn table_a_w(p: &Pair) -> f64 {
    let zs = f64::from(p.spec.z[0] + p.spec.z[1]);
    p.spec.module * (zs / 2.0 + p.spec.x_sum() - p.dy)
}

/// The notes of a pair: ε_α ≥ 1.1, the radial clearances, the table route (α_w read in
/// the inv table; with the table's Δy, y and a_w), and the seeds' errata computed from this
/// pair — seed 000's base radius r·cos α_w (its ε_α = 1.22) and its α_w = 26°34′45″, and,
/// for PZ3's pair, cos 26.92° misread as 0.8836 (a_w = 180.79 mm, ε_α = 1.14) and
/// "p = 14.13 mm".
pub fn pair_notes(p: &Pair) -> Vec<String> {
    let m = p.spec.module;
    let mut out = vec![format!(
        "gears: pair z = {}/{}, x = {}/{}: α_w = {}°, a_w = {} mm, y = {}, Δy = {}, ε_α = {}{}; radial clearances {} and {} mm (c*·m = {} mm)",
        p.spec.z[0],
        p.spec.z[1],
        num(p.spec.x[0], 4),
        num(p.spec.x[1], 4),
        num(p.alpha_w.to_degrees(), 7),
        num(p.a_w * 1e3, 7),
        num(p.y, 5),
        num(p.dy, 5),
        num(p.eps, 5),
        if p.eps < 1.1 { " (below the 1.1 the course asks for)" } else { "" },
        num(p.clearance[0] * 1e3, 5),
        num(p.clearance[1] * 1e3, 5),
        num(p.spec.rack.c * m * 1e3, 4),
    )];
    // The table route: inv α_w written to six decimals and read in the inv table.
    if let Some(table) = super::involute::alpha_by_table(p.inv_w) {
        use super::involute::{dms, TABLE_DIGITS};
        out.push(format!(
            "gears: by the inv table (a row every 1′ to {TABLE_DIGITS} decimals, read linearly): inv α_w = {:.6} → α_w = {} (exact {}){}",
            p.inv_w,
            dms(table, 0),
            dms(p.alpha_w, 1),
            if p.spec.z == [13, 30] && (m - 0.014).abs() < 1e-12 {
                "; seed 000 prints 26°34′45″, 6″ off the table's own reading: not reproduced"
            } else {
                ""
            }
        ));
    }
    if p.spec.dy_table.is_some() {
        let y = p.spec.x_sum() - p.dy;
        out.push(format!(
            "gears: by the tables: Δy = {} (table), y = x_Σ − Δy = {}, a_w = m(z_Σ/2 + y) = {} mm against the exact {} mm (y = {}); the tip radii take the table's Δy",
            num(p.dy, 4),
            num(y, 5),
            num(table_a_w(p) * 1e3, 7),
            num(p.a_w * 1e3, 7),
            num(p.y, 5),
        ));
    }
    // Seed 000: r_b = r·cos α_w and the base pitch πm·cos α_w.
    let wrong_pb = p.p * p.alpha_w.cos();
    out.push(format!(
        "gears: erratum (seed 000 §4): the base radii r·cos α_w = {}/{} mm and the base pitch πm·cos α_w = {} mm give ε_α = B₁B₂/(πm·cos α_w) = {} (the seed prints 1.22 from its B₁B₂ = 48); the base pitch is πm·cos α = {} mm and ε_α = {}",
        num(p.r[0] * p.alpha_w.cos() * 1e3, 5),
        num(p.r[1] * p.alpha_w.cos() * 1e3, 5),
        num(wrong_pb * 1e3, 5),
        num(p.ab / wrong_pb, 4),
        num(p.p_b * 1e3, 5),
        num(p.eps, 5),
    ));
    if p.spec.z == [13, 21] && (m - 0.010).abs() < 1e-12 {
        let misread = 0.8836;
        let wrong_aw = p.a * p.spec.rack.alpha.cos() / misread;
        out.push(format!(
            "gears: erratum (seed 002 PZ3): cos 26.92° read as {misread} (= cos 27.92°) gives a_w = {} mm and the printed ε_α = 1.14 is not reproducible; cos α_w = {} gives a_w = {} mm and ε_α = {}; the printed \"p_t = 14.13 mm\" contradicts p = πm = {} mm",
            num(wrong_aw * 1e3, 5),
            num(p.alpha_w.cos(), 4),
            num(p.a_w * 1e3, 5),
            num(p.eps, 5),
            num(p.p * 1e3, 5),
        ));
    }
    out
}
