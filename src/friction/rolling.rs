//! Rolling friction, worked example W3 of seed 001 (§13, Fig. 58–60): a load Q on two
//! rollers of weight G and diameter d. The normal reactions are shifted forward by the
//! coefficients of rolling friction k₁ (load/rollers) and k₂ (rollers/plane); the moments
//! about the rollers' contact with the plane give `P·d = Q·k₁ + (Q + 2G)·k₂`. Rolling is pure
//! when `k/d < f` at each contact; where it is not, the rollers slide and the force is the
//! sliding one: the cheaper of the load sliding on the rollers (`Q·f₁`, when `k₁/d ≥ f₁`) and
//! the load sliding on the plane with its rollers (`(Q + 2G)·f₂`, when `k₂/d ≥ f₂`) — rolling
//! would cost more than either. Without rollers the load slides: `P = Q·f₂`.
//!
//! The seed writes the plane's reaction as `R_n1`; it is `R_n2 = Q + 2G` (an erratum).
//!
//! The moment balance is drawn by the intercept theorem: on the lever of height d (at μ_l)
//! the arm k is laid across at a magnified μ_k, the load down the lever at μ_F; the parallel
//! through the load's end cuts off the force `L·k/d` at μ_P = μ_F·μ_k/μ_l.

use super::draw::{arrow, thin_line};
use super::incline::{incline_twin, polygon};
use super::{
    choose_scale, reading, subject, Drawing, DrawingKind, FrictionCase, FrictionError, Incline,
    Motion, Rolling, Solved,
};
use crate::check::notes::friction::{FrictionNote, RollerMotion};
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Recorder, Role};
use crate::geom::{Circle, DVec2, Line, Segment, Side};
use crate::scale::{Quantity, Scale};

/// Preferred drawn diameter of a roller in the scheme, mm.
const ROLLER_MM: f64 = 24.0;
/// Preferred drawn load of the moment balance without a μ_F given, mm.
const LOAD_MM: f64 = 60.0;
/// The loads of the moment balance are drawn at least this many levers long.
const LOAD_PAST: f64 = 1.5;
/// Preferred drawn arm k of the moment balance, mm.
const ARM_MM: f64 = 30.0;

/// The closed form of W3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingTwin {
    /// The reaction of the load on a roller's top, `R_n1 = Q`, N.
    pub r_n1: f64,
    /// The reaction of the plane, `R_n2 = Q + 2G`, N.
    pub r_n2: f64,
    /// `k₁/d`.
    pub ratio1: f64,
    /// `k₂/d`.
    pub ratio2: f64,
    /// Pure rolling at both contacts: `k₁/d < f₁` and `k₂/d < f₂`.
    pub pure: bool,
    /// The force to roll the load on its rollers, `(Q·k₁ + (Q + 2G)·k₂)/d`, N.
    pub p_rolling: f64,
    /// Where the rollers slide when rolling is not pure (the cheaper sliding contact).
    pub slide: Option<Slide>,
    /// The force to move the load on its rollers, N: `p_rolling` when rolling is pure, else
    /// the sliding force at `slide`.
    pub p: f64,
    /// The force to slide it without rollers, `Q·f₂`, N.
    pub p_sliding: f64,
}

/// Where rollers that do not roll purely slide.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slide {
    /// The load slides on the rollers' tops: `P = Q·f₁`.
    OnRollers,
    /// The load slides on the plane with its rollers: `P = (Q + 2G)·f₂`.
    OnPlane,
}

impl Slide {
    /// The sliding pair as an incline: the load pressing on it and its f.
    pub fn incline(self, c: &Rolling) -> Incline {
        let (load, f) = match self {
            Slide::OnRollers => (c.load, c.f1),
            Slide::OnPlane => (c.load + 2.0 * c.roller_weight, c.f2),
        };
        Incline {
            load,
            f,
            alpha: 0.0,
            beta: 0.0,
            motion: Motion::Up,
        }
    }
}

/// The twin of W3.
pub fn rolling_twin(c: &Rolling) -> RollingTwin {
    let r_n2 = c.load + 2.0 * c.roller_weight;
    let ratio1 = c.k1 / c.diameter;
    let ratio2 = c.k2 / c.diameter;
    let p_rolling = (c.load * c.k1 + r_n2 * c.k2) / c.diameter;
    let pure = ratio1 < c.f1 && ratio2 < c.f2;
    // Not pure: some contact's rolling costs more than its sliding; the load moves the
    // cheaper way (either sliding force is then at most the rolling one).
    let (on_rollers, on_plane) = (c.load * c.f1, r_n2 * c.f2);
    let slide = (!pure).then_some(if on_rollers <= on_plane {
        Slide::OnRollers
    } else {
        Slide::OnPlane
    });
    RollingTwin {
        r_n1: c.load,
        r_n2,
        ratio1,
        ratio2,
        pure,
        p_rolling,
        slide,
        p: match slide {
            None => p_rolling,
            Some(Slide::OnRollers) => on_rollers,
            Some(Slide::OnPlane) => on_plane,
        },
        p_sliding: c.load * c.f2,
    }
}

/// The scheme at μ_l: the plane, two rollers, the load on them, the loads and the normal
/// reactions of the right roller shifted by k (the shifts exaggerated: they are labelled,
/// not drawn to scale).
fn scheme(case: &FrictionCase, c: &Rolling, ctx: &Context) -> Result<Drawing, FrictionError> {
    let mut rec = case.scheme_recorder(c.diameter, ROLLER_MM, ctx)?;
    let mu = rec.scale();
    let d = mu.to_mm(c.diameter);
    let half = 1.9 * d;
    rec.draw(
        "the plane",
        Item::Guide {
            segment: Segment::new(DVec2::new(-half - 8.0, 0.0), DVec2::new(half + 8.0, 0.0)),
            hatch: Side::Right,
        },
        Role::Given,
        &[],
    );
    let centres = [DVec2::new(-d, d / 2.0), DVec2::new(d, d / 2.0)];
    for (k, &at) in centres.iter().enumerate() {
        rec.draw(
            format!("roller {}", k + 1),
            Item::Circle(Circle {
                center: at,
                radius: d / 2.0,
            }),
            Role::Given,
            &[],
        );
        let g = format!("G, roller {}", k + 1);
        arrow(
            &mut rec,
            &g,
            (at, at - DVec2::Y * (d * 0.35)),
            Role::Given,
            "G",
            -DVec2::X,
        );
    }
    let slab = d * 0.35;
    rec.draw(
        "the load",
        Item::Polyline {
            points: vec![
                DVec2::new(-half, d),
                DVec2::new(half, d),
                DVec2::new(half, d + slab),
                DVec2::new(-half, d + slab),
            ],
            closed: true,
        },
        Role::Given,
        &[],
    );
    let top = DVec2::new(0.0, d + slab);
    arrow(
        &mut rec,
        "the load Q",
        (top + DVec2::Y * 16.0, top),
        Role::Given,
        "Q",
        DVec2::X,
    );
    let mid = DVec2::new(-half, d + slab / 2.0);
    arrow(
        &mut rec,
        "the force P",
        (mid - DVec2::X * 18.0, mid),
        Role::Given,
        "P",
        DVec2::Y,
    );
    // The right roller's reactions, the shifts exaggerated to 3 mm.
    let shift = 3.0;
    let c2 = centres[1];
    let n1_at = DVec2::new(c2.x - shift, d);
    arrow(
        &mut rec,
        "R_n1",
        (n1_at + DVec2::Y * 12.0, n1_at),
        Role::Result,
        "R_{n1}",
        -DVec2::X,
    );
    let n2_at = DVec2::new(c2.x + shift, 0.0);
    arrow(
        &mut rec,
        "R_n2",
        (n2_at - DVec2::Y * 12.0, n2_at),
        Role::Result,
        "R_{n2}",
        DVec2::X,
    );
    for (from, to, name, toward) in [
        (DVec2::new(c2.x, d), n1_at, "k_{1}", DVec2::new(1.0, -1.0)),
        (DVec2::new(c2.x, 0.0), n2_at, "k_{2}", DVec2::new(1.0, -1.0)),
    ] {
        let id = rec.draw(
            format!("the shift {name} (not to scale)"),
            Item::Segment(Segment::new(from, to)),
            Role::Dimension,
            &[],
        );
        rec.label(id, name, (from + to) / 2.0, toward.normalize());
    }
    let v_at = DVec2::new(half - 14.0, d + slab + 5.0);
    arrow(
        &mut rec,
        "v",
        (v_at, v_at + DVec2::X * 12.0),
        Role::Dimension,
        "v",
        DVec2::Y,
    );
    Ok(Drawing {
        kind: DrawingKind::Scheme,
        figure: rec.finish(),
        scaled: true,
        also: Vec::new(),
    })
}

/// One term `L·k/d` of the moment balance by the intercept theorem on the lever AB: the arm
/// k laid across the lever at one end (`base`, +1 to the right, −1 to the left), the load L
/// laid along the lever from the other end (`apex`) and on past `base` when it is longer; the
/// line from `apex` through the arm's end, run on, cuts off on the parallel to k through the
/// load's end the force L·k/d. Every piece is drawn from the one before (the load from the
/// lever's end, the line from the arm's, the force from the load's), so the triangle and its
/// force read as one construction. Returns the force read.
fn term(
    rec: &mut Recorder,
    (base, apex): (DVec2, DVec2),
    (q_mm, k_mm): (f64, f64),
    side: f64,
    names: (&str, &str, &str),
) -> Result<f64, ConstructionError> {
    let (arm, load, force) = names;
    let kc = base + DVec2::X * (side * k_mm);
    let id = rec.draw(
        format!("the arm {arm} at μ_k"),
        Item::Segment(Segment::new(base, kc)),
        Role::Given,
        &[],
    );
    let onward = (base - apex).normalize_or(DVec2::Y);
    rec.label(id, arm, (base + kc) / 2.0, onward);
    // The load from the lever's far end, labelled on its piece past the lever (or at its
    // middle when it is shorter), on the arm's side.
    let dpt = apex + onward * q_mm;
    let lever_mm = apex.distance(base);
    let id = rec.draw(
        format!("the load {load} along the lever at μ_F"),
        Item::Vector {
            from: apex,
            to: dpt,
        },
        Role::Given,
        &[],
    );
    let on = if q_mm > lever_mm {
        base.lerp(dpt, 0.5)
    } else {
        apex.lerp(dpt, 0.5)
    };
    rec.label(id, load, on, DVec2::X * side);
    let hline = Line {
        point: dpt,
        direction: DVec2::X * side,
    };
    let through = Line {
        point: apex,
        direction: (kc - apex).normalize_or(DVec2::X),
    };
    let (e, _, _) = rec.meet_lines(
        &format!("the parallel to {arm}"),
        ("the parallel", &hline),
        ("apex–k", &through),
    )?;
    thin_line(
        rec,
        &format!("from the lever's end through the end of {arm}"),
        apex,
        e,
    );
    arrow(rec, force, (dpt, e), Role::Result, force, onward);
    Ok(rec.measure(dpt, e).value)
}

/// Construct W3 and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Rolling,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = rolling_twin(c);
    let scheme = scheme(case, c, ctx)?;
    let (balance, p_rolled) = balance(case, c, &twin, ctx, wrap)?;
    let name = &case.name;
    // Without rollers: the load slides on the plane, a level incline with f₂.
    let plane = Incline {
        load: c.load,
        f: c.f2,
        alpha: 0.0,
        beta: 0.0,
        motion: Motion::Up,
    };
    let (mut sliding, slid, _) = polygon(case, &plane, &incline_twin(&plane), ctx, wrap)?;
    sliding.kind = DrawingKind::Sliding;
    let mut drawings = vec![scheme, sliding, balance];
    // Rollers that slide: the force is the sliding one, read off that pair's polygon.
    let (p_read, p_crossing) = match twin.slide {
        None => (p_rolled, None),
        Some(at) => {
            let pair = at.incline(c);
            let (mut d, read, _) = polygon(case, &pair, &incline_twin(&pair), ctx, wrap)?;
            d.kind = DrawingKind::Sliding;
            drawings.push(d);
            (read.p, Some(read.crossing_deg))
        }
    };
    let readings = vec![
        reading(
            "P",
            (Symbol::Force, subject("P", name)),
            p_read,
            twin.p,
            p_crossing,
        ),
        reading(
            "P_{ск}",
            (Symbol::Force, subject("Pslide", name)),
            slid.p,
            twin.p_sliding,
            Some(slid.crossing_deg),
        ),
    ];
    Ok(Solved {
        case: case.clone(),
        drawings,
        readings,
        notes: notes(name, c, &twin),
    })
}

/// The moment balance: the lever d at μ_l, the arms k₁, k₂ at μ_k, the loads at μ_F, each
/// term cut off by the intercept theorem at μ_P = μ_F·μ_k/μ_l; gives the drawing and the
/// rolling force P₁ + P₂ as read.
fn balance(
    case: &FrictionCase,
    c: &Rolling,
    twin: &RollingTwin,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<(Drawing, f64), FrictionError> {
    let name = &case.name;
    // The loads at the case's μ_F (the textbook's about LOAD_MM without one), the lever d
    // at the round μ_l that draws it at most 1/LOAD_PAST of the smaller load: each load,
    // laid along the lever from one end, runs on past the other end by half the lever at
    // least, where it is seen and named apart from the other.
    let mu_f = choose_scale(name, case.scale_f, twin.r_n2, LOAD_MM, Quantity::Force)?;
    let mu_l = choose_scale(
        name,
        None,
        c.diameter,
        mu_f.to_mm(twin.r_n1) / LOAD_PAST,
        Quantity::Length,
    )?;
    let lever_mm = mu_l.to_mm(c.diameter);
    let mu_k = choose_scale(name, None, c.k1.max(c.k2), ARM_MM, Quantity::Length)?;
    let mu_p = mu_f.value() * mu_k.value() / mu_l.value();
    let mu_p = Scale::new(mu_p, Quantity::Force).ok_or(FrictionError::NoScale {
        case: name.clone(),
        value: mu_p,
        unit: "N",
    })?;
    let mut rec = Recorder::in_context(name, mu_p, ctx);
    let (a_pt, b_pt) = (DVec2::ZERO, DVec2::new(0.0, lever_mm));
    let lever = rec.draw(
        "the lever AB = d at μ_l",
        Item::Segment(Segment::new(a_pt, b_pt)),
        Role::Given,
        &[],
    );
    rec.label(lever, "d", a_pt.lerp(b_pt, 0.5), -DVec2::X);
    let b = rec.draw("B", Item::Point(b_pt), Role::Given, &[]);
    rec.label(b, "B", b_pt, DVec2::new(-1.0, 1.0).normalize());
    let a = rec.draw("A", Item::Point(a_pt), Role::Given, &[]);
    rec.label(a, "A", a_pt, DVec2::new(1.0, -1.0).normalize());
    // P₁ hangs from B with k₁ at A, P₂ rises from A with k₂ at B: the two triangles
    // apart, each force read off its own.
    let p1 = term(
        &mut rec,
        (a_pt, b_pt),
        (mu_f.to_mm(twin.r_n1), mu_k.to_mm(c.k1)),
        -1.0,
        ("k_{1}", "R_{n1}", "P_{1}"),
    )
    .map_err(wrap)?;
    let p2 = term(
        &mut rec,
        (b_pt, a_pt),
        (mu_f.to_mm(twin.r_n2), mu_k.to_mm(c.k2)),
        1.0,
        ("k_{2}", "R_{n2}", "P_{2}"),
    )
    .map_err(wrap)?;
    let balance = Drawing {
        kind: DrawingKind::Balance,
        figure: rec.finish(),
        scaled: true,
        also: vec![mu_f, mu_k, mu_l],
    };
    Ok((balance, p1 + p2))
}

/// The notes: k/d against f at each contact (pure rolling, or where the rollers slide), and
/// the erratum R_n2 with the gain of the rollers.
fn notes(name: &str, c: &Rolling, twin: &RollingTwin) -> Vec<FrictionNote> {
    let (p, rolling) = (twin.p, twin.p_rolling);
    vec![
        FrictionNote::Rolling {
            case: name.to_string(),
            first: (twin.ratio1, c.f1),
            second: (twin.ratio2, c.f2),
            motion: match twin.slide {
                None => RollerMotion::Rolling,
                Some(Slide::OnRollers) => RollerMotion::OnRollers { p, rolling },
                Some(Slide::OnPlane) => RollerMotion::OnPlane { p, rolling },
            },
        },
        FrictionNote::RollingErratum {
            case: name.to_string(),
            r_n2: twin.r_n2,
            gain: twin.p_sliding / twin.p,
        },
    ]
}
