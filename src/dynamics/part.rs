//! The flywheel as a part drawing (seed 000 L1481: "выполняем чертёж маховика в масштабе
//! 1/4"), every dimension from its size ([`super::flywheel::size`]): at the left the axial
//! section through two spokes — the rim and the hub cut and hatched, the spokes cut
//! lengthwise left unhatched (ГОСТ 2.305), tapering from b₁ at the hub to b₂ at the rim —
//! with ⌀d₁, ⌀d₂, ⌀d₃, ⌀D on extension lines (the smallest nearest the part), b over the
//! rim and b_ст in the bore; at the right the front view: the rim, the hub and the bore, four
//! spokes tapering from a₁ at the hub to a₂ at the rim, the circles broken where the spokes
//! join them; beyond it the upper spoke's two elliptical sections (a × b, b/a = 0.4) at the
//! hub and at the rim, each on the trace of its cutting plane (a symmetric removed section
//! there is not lettered, ГОСТ 2.305), hatched, with its a and b. A disc is its section
//! with ⌀D, ⌀d₁ and its width b in the bore, and its front view. The bore takes the shaft
//! with the fit H7 and the roughness Ra 1,6 of a fit's surface (ГОСТ 2.309); the hub's
//! keyway for d₁ (ГОСТ 23360, [`Keyway`]) is cut up from the bore in the front view, with
//! its width (JS9) and d₁ + t₂, and the section runs through it.

use super::flywheel::Size;
use super::spec::FlywheelKind;
use super::{roughness, DynamicsError, Keyway};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Segment};
use crate::scale::{format_fixed, Lang, Quantity, Scale};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

/// The longest the outer diameter is drawn, mm: the part's scale is the round reduction
/// (1, 2, 2.5, 4, 5 × 10ⁿ, ГОСТ 2.302's 1:2, 1:2,5, 1:4, 1:5, 1:10 …) that draws D at most
/// this long — 1:4 for the seed's D ≈ 0.8 m, as the seed draws it.
pub const PART_MM: f64 = 230.0;
/// From the contour to the first dimension line, mm (ГОСТ 2.307: at least 10).
const FIRST_MM: f64 = 10.0;
/// Between parallel dimension lines, mm (ГОСТ 2.307: at least 7).
const STEP_MM: f64 = 8.0;
/// How far a centre line runs past the contour, mm (ГОСТ 2.303: 2…5).
const PAST_MM: f64 = 4.0;
/// Between the section and the front view, and between the front view and the spoke's
/// sections, mm.
const GAP_MM: f64 = 24.0;
/// Spacing of the hatching, mm (ГОСТ 2.306: 1…10 by the area).
const HATCH_MM: f64 = 2.0;
/// How far past the hub (a disc's bore) the roughness leader's shelf starts, mm.
const LEADER_MM: f64 = 10.0;
/// The bore's roughness (ГОСТ 2.309): the fit H7's surface (a decimal point: the sheet
/// writes its language's sign).
const BORE_ROUGHNESS: &str = "Ra 1.6";
/// The bore's fit on the shaft (ГОСТ 25347).
const BORE_FIT: &str = "H7";
/// The hub keyway width's tolerance of the normal connection (ГОСТ 23360).
const KEYWAY_FIT: &str = "JS9";
/// Points of a spoke's elliptical section.
const ELLIPSE_POINTS: u32 = 48;

/// The flywheel of `size` as a part drawing (see the module's documentation) at its round
/// scale, then at the next coarser one: a sheet that would take a larger format for the first
/// takes the second on the smaller one (ГОСТ 2.301: the smallest format that shows the part
/// clearly). A flywheel of no size (none needed) is one empty figure.
///
/// # Errors
/// No scale can be chosen.
pub fn drawings(size: &Size, ctx: &Context) -> Result<Vec<Figure>, DynamicsError> {
    let no_scale = || DynamicsError::NoScale {
        what: "the flywheel's scale",
        value: size.d,
    };
    if !(size.d > 0.0 && size.d.is_finite()) {
        let unit = Scale::new(1.0, Quantity::Length).ok_or_else(no_scale)?;
        return Ok(vec![Recorder::in_context("flywheel", unit, ctx).finish()]);
    }
    let mu = Scale::round_for(size.d, PART_MM, Quantity::Length).ok_or_else(no_scale)?;
    let coarser = mu.coarser().ok_or_else(no_scale)?;
    Ok(vec![at_scale(size, mu, ctx), at_scale(size, coarser, ctx)])
}

/// The part drawing of `size` at `mu`.
/// The sign of the roughness of the surfaces the part drawing does not mark — as cast — drawn
/// 1:1 for the sheet's top right corner (ГОСТ 2.309).
///
/// # Errors
/// None in practice: the 1:1 scale is a valid one.
pub fn other_surfaces(ctx: &Context) -> Result<Figure, DynamicsError> {
    let unit = Scale::new(1e-3, Quantity::Length).ok_or(DynamicsError::NoScale {
        what: "the scale of the roughness sign",
        value: 1e-3,
    })?;
    let mut rec = Recorder::in_context("roughness of the other surfaces", unit, ctx);
    roughness::other_surfaces(&mut rec);
    Ok(rec.finish())
}

fn at_scale(size: &Size, mu: Scale, ctx: &Context) -> Figure {
    let key = size.dim("d_{1}").and_then(Keyway::for_shaft);
    let part = Part { size, mu, key };
    let mut rec = Recorder::in_context("flywheel", mu, ctx);
    section(&mut rec, &part);
    let (rim, hub) = part.widths();
    let outer = part.half("D");
    let centre = DVec2::new(rim.max(hub) + 2.0 * PAST_MM + GAP_MM + outer, 0.0);
    front(&mut rec, &part, centre);
    if part.rim() {
        spoke_sections(&mut rec, &part, centre);
    }
    rec.finish()
}

/// The size as drawn at μ.
struct Part<'a> {
    size: &'a Size,
    mu: Scale,
    /// The hub's keyway for the shaft of d₁ (ГОСТ 23360), when the standard has one.
    key: Option<Keyway>,
}

impl Part<'_> {
    /// Whether it is a rim with spokes.
    fn rim(&self) -> bool {
        self.size.kind == FlywheelKind::Rim
    }
    /// Half the dimension `name` as drawn, mm.
    fn half(&self, name: &str) -> f64 {
        self.mu.to_mm(self.size.dim(name).unwrap_or(0.0)) / 2.0
    }
    /// The dimension text of `name`: its value in whole millimetres (ГОСТ 2.307).
    fn text(&self, name: &str) -> String {
        format_fixed(self.size.dim(name).unwrap_or(0.0) * 1e3, 0, Lang::En)
    }
    /// The keyway `k` as drawn: half its width and the radius of its bottom (d₁/2 + t₂), mm.
    fn drawn(&self, k: Keyway) -> (f64, f64) {
        (
            self.mu.to_mm(k.b) / 2.0,
            self.half("d_{1}") + self.mu.to_mm(k.t2),
        )
    }
    /// Half the widths of the rim (the disc) and of the hub, mm.
    fn widths(&self) -> (f64, f64) {
        let b = self.half("b");
        (b, if self.rim() { self.half("b_{ст}") } else { b })
    }
}

/// The axial section: the cut material, the spokes lengthwise, the axis and the dimensions.
fn section(rec: &mut Recorder, p: &Part<'_>) {
    let (rim, hub_w) = p.widths();
    let (outer, bore) = (p.half("D"), p.half("d_{1}"));
    // The section runs through the keyway: above the axis the hub's material starts at the
    // keyway's bottom, and the bore's edge beyond shows across the hub.
    let upper = p.key.map_or(bore, |k| {
        let edge = Segment::new(DVec2::new(-hub_w, bore), DVec2::new(hub_w, bore));
        rec.draw(
            "the bore beyond the keyway",
            Item::Segment(edge),
            Role::Given,
            &[],
        );
        p.drawn(k).1
    });
    if p.rim() {
        let (inner, hub) = (p.half("d_{3}"), p.half("d_{2}"));
        cut(rec, "rim", rim, [(inner, outer); 2]);
        cut(rec, "hub", hub_w, [(upper, hub), (bore, hub)]);
        // The spokes cut lengthwise: not hatched, b₁ at the hub to b₂ at the rim.
        let (w1, w2) = (p.half("b_{1}"), p.half("b_{2}"));
        for sgn in [1.0, -1.0] {
            for side in [1.0, -1.0] {
                let s = Segment::new(
                    DVec2::new(side * w1, sgn * hub),
                    DVec2::new(side * w2, sgn * inner),
                );
                rec.draw("spoke", Item::Segment(s), Role::Given, &[]);
            }
        }
    } else {
        cut(rec, "disc", rim, [(upper, outer), (bore, outer)]);
    }
    let widest = rim.max(hub_w);
    let reach = widest + PAST_MM;
    let axis = Segment::new(DVec2::new(-reach, 0.0), DVec2::new(reach, 0.0));
    rec.draw("axis", Item::Segment(axis), Role::Axis, &[]);
    // The diameters at the left, each on extension lines from its edge, the smallest nearest.
    let mut diameters = vec![("d_{1}", hub_w)];
    if p.rim() {
        diameters.extend([("d_{2}", hub_w), ("d_{3}", rim)]);
    }
    diameters.push(("D", rim));
    for (k, (name, edge)) in diameters.into_iter().enumerate() {
        let at = widest + FIRST_MM + STEP_MM * k as f64;
        let half = p.half(name);
        // The bore takes the shaft with the hub's fit (ГОСТ 25347: H7).
        let fit = if name == "d_{1}" { BORE_FIT } else { "" };
        rec.dimension(
            format!("dimension {name}"),
            (DVec2::new(-edge, -half), DVec2::new(-edge, half), at - edge),
            format!("⌀{}{fit}", p.text(name)),
        );
    }
    // The width in the bore of the lower half (clear of the spokes and of the rim's sides):
    // the hub's b_ст of a rim with spokes, whose rim's b goes over it; a disc's b.
    let in_bore = if p.rim() { "b_{ст}" } else { "b" };
    rec.dimension(
        format!("dimension {in_bore}"),
        (
            DVec2::new(-hub_w, -bore),
            DVec2::new(hub_w, -bore),
            bore * 0.3,
        ),
        p.text(in_bore),
    );
    if p.rim() {
        rec.dimension(
            "dimension b",
            (DVec2::new(-rim, outer), DVec2::new(rim, outer), FIRST_MM),
            p.text("b"),
        );
    }
}

/// Cut material `note` of half width `half` between the radii `r` (mm) above and below the
/// axis: each half an outline hatched.
fn cut(rec: &mut Recorder, note: &str, half: f64, r: [(f64, f64); 2]) {
    for (sgn, r) in [1.0, -1.0].into_iter().zip(r) {
        let outline = [
            DVec2::new(-half, sgn * r.0),
            DVec2::new(half, sgn * r.0),
            DVec2::new(half, sgn * r.1),
            DVec2::new(-half, sgn * r.1),
        ];
        hatched(rec, note, &outline);
    }
}

/// The front view centred at `c`: the rim, the hub and the bore; four spokes tapering from
/// a₁ at the hub to a₂ at the rim, the hub's and the rim's circles broken where they join.
fn front(rec: &mut Recorder, p: &Part<'_>, c: DVec2) {
    let (outer, bore) = (p.half("D"), p.half("d_{1}"));
    let circle = Circle {
        center: c,
        radius: outer,
    };
    rec.draw("rim", Item::Circle(circle), Role::Given, &[]);
    match p.key {
        Some(k) => keyway(rec, p, c, k),
        None => {
            let circle = Circle {
                center: c,
                radius: bore,
            };
            rec.draw("bore", Item::Circle(circle), Role::Given, &[]);
        }
    }
    let reach = outer + PAST_MM;
    for dir in [DVec2::X, DVec2::Y] {
        let line = Segment::new(c - dir * reach, c + dir * reach);
        rec.draw("centre line", Item::Segment(line), Role::Axis, &[]);
    }
    // The bore's roughness (the fit's surface), on a leader down and right between the
    // spokes (the keyway's depth is dimensioned at the left), its shelf past the hub.
    let out = DVec2::from_angle(1.75 * PI);
    let ring = if p.rim() { p.half("d_{2}") } else { bore };
    roughness::on_leader(
        rec,
        c + out * bore,
        c + out * (ring + LEADER_MM),
        false,
        BORE_ROUGHNESS,
    );
    if !p.rim() {
        return;
    }
    let (inner, hub) = (p.half("d_{3}"), p.half("d_{2}"));
    let (a1, a2) = (p.half("a_{1}"), p.half("a_{2}"));
    // The half angle a spoke's end takes on its circle.
    let at_hub = (a1 / hub).clamp(-1.0, 1.0).asin();
    let at_rim = (a2 / inner).clamp(-1.0, 1.0).asin();
    for k in 0..4 {
        let t = FRAC_PI_2 * f64::from(k);
        let u = DVec2::new(t.cos(), t.sin());
        let n = u.perp();
        for side in [1.0, -1.0] {
            let s = Segment::new(
                c + u * along(hub, a1) + n * (side * a1),
                c + u * along(inner, a2) + n * (side * a2),
            );
            rec.draw("spoke", Item::Segment(s), Role::Given, &[]);
        }
        // The circles between this spoke and the next.
        for (note, radius, half) in [("hub", hub, at_hub), ("rim", inner, at_rim)] {
            let arc = Arc {
                center: c,
                radius,
                start: t + half,
                sweep: FRAC_PI_2 - 2.0 * half,
            };
            rec.draw(note, Item::Arc(arc), Role::Given, &[]);
        }
    }
}

/// The bore of the front view centred at `c` with the keyway `k` cut up from it, and the keyway's two dimensions: its width with the hub's tolerance
/// (JS9, the normal connection) over it, and d₁ + t₂ from the bore's far side to its bottom
/// with the upper deviation, at the left.
fn keyway(rec: &mut Recorder, p: &Part<'_>, c: DVec2, k: Keyway) {
    let (bore, (w, top)) = (p.half("d_{1}"), p.drawn(k));
    let half = (w / bore).clamp(-1.0, 1.0).asin();
    let arc = Arc {
        center: c,
        radius: bore,
        start: FRAC_PI_2 + half,
        sweep: TAU - 2.0 * half,
    };
    rec.draw("bore", Item::Arc(arc), Role::Given, &[]);
    let foot = along(bore, w);
    let corners = [
        DVec2::new(-w, foot),
        DVec2::new(-w, top),
        DVec2::new(w, top),
        DVec2::new(w, foot),
    ];
    for side in corners.windows(2) {
        let s = Segment::new(c + side[0], c + side[1]);
        rec.draw("keyway", Item::Segment(s), Role::Given, &[]);
    }
    // Tenths with a decimal point: the sheet writes its language's sign.
    let mm = |x: f64| format_fixed(x * 1e3, 1, Lang::En);
    rec.dimension(
        "dimension keyway b",
        (c + DVec2::new(-w, top), c + DVec2::new(w, top), FIRST_MM),
        format!("{}{KEYWAY_FIT}", format_fixed(k.b * 1e3, 0, Lang::En)),
    );
    let d1 = p.size.dim("d_{1}").unwrap_or(0.0);
    rec.dimension(
        "dimension d_{1} + t_{2}",
        (
            c + DVec2::new(0.0, -bore),
            c + DVec2::new(0.0, top),
            bore + FIRST_MM,
        ),
        format!("{}^{{+{}}}", mm(d1 + k.t2), mm(k.depth_deviation())),
    );
}

/// How far along a spoke its side of half width `half` meets the circle of radius `r`, mm.
fn along(r: f64, half: f64) -> f64 {
    (r * r - half * half).max(0.0).sqrt()
}

/// The upper spoke's sections at the hub (a₁ × b₁) and at the rim (a₂ × b₂), right of the
/// front view centred at `c`, each on the trace of its cutting plane, hatched and
/// dimensioned.
fn spoke_sections(rec: &mut Recorder, p: &Part<'_>, c: DVec2) {
    let outer = p.half("D");
    let widest = p.half("a_{1}").max(p.half("a_{2}"));
    let x = c.x + outer + PAST_MM + GAP_MM + widest;
    let ends = [
        ("hub", p.half("d_{2}"), "a_{1}", "b_{1}", -1.0),
        ("rim", p.half("d_{3}"), "a_{2}", "b_{2}", 1.0),
    ];
    for (end, r, a, b, side) in ends {
        let (ha, hb) = (p.half(a), p.half(b));
        let o = DVec2::new(x, c.y + along(r, ha));
        // The trace of the cutting plane: across the spoke, and from past the rim up to
        // the section (not over its hatching).
        for (from, to) in [
            (c.x - ha - PAST_MM, c.x + ha + PAST_MM),
            (c.x + outer + PAST_MM, x - ha - PAST_MM / 2.0),
        ] {
            let trace = Segment::new(DVec2::new(from, o.y), DVec2::new(to, o.y));
            rec.draw(
                format!("cutting plane at the {end}"),
                Item::Segment(trace),
                Role::Axis,
                &[],
            );
        }
        let outline: Vec<DVec2> = (0..ELLIPSE_POINTS)
            .map(|k| {
                let t = TAU * f64::from(k) / f64::from(ELLIPSE_POINTS);
                o + DVec2::new(ha * t.cos(), hb * t.sin())
            })
            .collect();
        hatched(rec, &format!("the spoke's section at the {end}"), &outline);
        // a across the spoke, under the section at the hub and over it at the rim; b along
        // the axis, at its right.
        rec.dimension(
            format!("dimension {a}"),
            (o - DVec2::X * ha, o + DVec2::X * ha, side * (hb + FIRST_MM)),
            p.text(a),
        );
        rec.dimension(
            format!("dimension {b}"),
            (o - DVec2::Y * hb, o + DVec2::Y * hb, -(ha + FIRST_MM)),
            p.text(b),
        );
    }
}

/// A closed outline of cut material, hatched at 45° (ГОСТ 2.306).
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
    // The outline is finite (the scale is), and a part's section is a few spacings across:
    // the hatcher refuses neither.
    let _ = rec.hatching("hatching", outline.to_vec(), (HATCH_MM, FRAC_PI_4), &[id]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;
    use crate::dynamics::flywheel::size;
    use crate::dynamics::FlywheelSpec;

    /// The dimension steps of `f`: (name, its text, its drawn length, mm).
    fn dimensions(f: &Figure) -> Vec<(String, String, f64)> {
        f.steps
            .iter()
            .filter_map(|s| {
                let name = s.note.strip_prefix("dimension ")?;
                let Item::Dimension { from, to, .. } = s.item else {
                    return None;
                };
                let text = s.label.as_ref()?.text.clone();
                Some((name.to_string(), text, from.distance(to)))
            })
            .collect()
    }

    /// The seed's flywheel of J = 17.1 kg·m² (000 §5: D = 785, d₁ = 157, d₂ = 235.5, d₃ = 628,
    /// b = 98.1, b_ст = 103, a₁ = 107.9, a₂ = 86.3, b₁ = 43.2, b₂ = 34.5 mm) drawn at 1:4, as
    /// the seed draws it: every dimension once, its text the value its proportion gives and
    /// its line that value at μ; the rim and the hub cut and hatched on both sides of the
    /// axis, the spokes lengthwise unhatched, four spokes in front, two sections hatched.
    #[test]
    fn the_part_drawing_dimensions_every_proportion_once_at_its_length() {
        let size = size(&FlywheelSpec::SEED_RIM, 17.1);
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("context");
        let f = drawings(&size, &ctx).expect("drawing").swap_remove(0);
        assert!((f.scale.value() - 0.004).abs() < 1e-15, "1:4");
        let seed = [
            ("D", "⌀785"),
            ("d_{1}", "⌀157H7"),
            ("d_{2}", "⌀236"),
            ("d_{3}", "⌀628"),
            ("b", "98"),
            ("b_{ст}", "103"),
            ("a_{1}", "108"),
            ("a_{2}", "86"),
            ("b_{1}", "43"),
            ("b_{2}", "35"),
        ];
        let dims = dimensions(&f);
        // And the hub's keyway for the shaft of 157 mm (ГОСТ 23360: 40 × 22, t₂ = 9,4 mm).
        assert_eq!(dims.len(), seed.len() + 2, "{dims:?}");
        let d1 = size.dim("d_{1}").expect("d₁");
        let keyway = [
            ("keyway b", "40JS9", 0.040),
            ("d_{1} + t_{2}", "166.4^{+0.3}", d1 + 0.0094),
        ];
        for (name, text, m) in keyway {
            let (_, got, drawn) = dims.iter().find(|d| d.0 == name).expect(name);
            assert_eq!(got, text, "{name}");
            assert!((drawn - m / 0.004).abs() < 1e-9, "{name}: {drawn} mm");
        }
        for (name, text) in seed {
            let (_, got, mm) = dims.iter().find(|d| d.0 == name).expect(name);
            assert_eq!(got, text, "{name}");
            let want = size.dim(name).expect(name) / 0.004;
            assert!((mm - want).abs() < 1e-9, "{name}: {mm} mm against {want}");
        }
        let count = |note: &str| f.steps.iter().filter(|s| s.note == note).count();
        assert_eq!(
            count("rim"),
            2 + 1 + 4,
            "two halves cut, D and d₃ in four arcs"
        );
        assert_eq!(count("hub"), 2 + 4);
        assert_eq!(count("spoke"), 2 * 2 + 4 * 2);
        assert_eq!(count("the spoke's section at the hub"), 1);
        assert_eq!(count("the spoke's section at the rim"), 1);
        // Hatched regions: the rim's and the hub's halves, their strokes many.
        let strokes: usize = f
            .steps
            .iter()
            .filter(|s| s.note == "hatching")
            .map(|s| s.item.hatch_strokes().len())
            .sum();
        assert!(count("hatching") >= 2 && strokes > 20, "{strokes}");
    }

    /// A disc: its section with the bore, ⌀D, ⌀d₁ and b; no spokes.
    #[test]
    fn a_disc_is_dimensioned_by_its_diameters_and_width() {
        let size = size(&FlywheelSpec::disc(7800.0), 0.5);
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("context");
        let f = drawings(&size, &ctx).expect("drawing").swap_remove(0);
        let mut names: Vec<String> = dimensions(&f).into_iter().map(|d| d.0).collect();
        names.sort();
        assert_eq!(names, ["D", "b", "d_{1}", "d_{1} + t_{2}", "keyway b"]);
        assert!(f.steps.iter().all(|s| s.note != "spoke"));
    }

    /// No flywheel, no drawing.
    #[test]
    fn no_flywheel_draws_nothing() {
        let size = size(&FlywheelSpec::SEED_RIM, 0.0);
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("context");
        assert!(drawings(&size, &ctx).expect("empty")[0].steps.is_empty());
    }
}
