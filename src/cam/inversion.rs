//! The profile by inversion: the follower's positions turned by −φ about the cam centre,
//! the pitch curve, the roller circles (or the face lines) and the practical profile; the
//! angle read off the drawing; the drawn pitch curve's smallest radius of curvature.

use super::follower::{flat_contact, to_cam, Kin, Placement};
use super::motion::{FollowerMotion, Point};
use super::reading::{read_leans, Drawn};
use super::{CamError, CamSpec, Follower};
use crate::construct::fit::{overflow, raised};
use crate::construct::{Context, Figure, Item, Recorder, Role, StepId};
use crate::geom::{bezier_points, french_piece, Arc, Circle, DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::{PI, TAU};
use std::ops::Range;

/// Largest radius of the profile drawing when the scene gives no μ_l, mm: at most this, and
/// coarser while the drawing (rollers, follower positions, labels' points) overflows
/// [`PROFILE_ROOM`].
const PROFILE_MM: f64 = 160.0;
/// The room of the profile on the cam sheet, mm: a third of an A1 sheet's width beside the
/// diagrams and the combined diagram, under half its height.
const PROFILE_ROOM: DVec2 = DVec2::new(240.0, 240.0);
/// A translating follower's inverted axis is drawn from this share of the way from the
/// foot of the offset out to the base circle.
const INNER: f64 = 0.6;
/// The profile by inversion.
#[derive(Debug, Clone, PartialEq)]
pub struct Inversion {
    /// The drawing at μ_l.
    pub figure: Figure,
    /// μ_l.
    pub scale: Scale,
    /// The pitch-curve points (roller centres, knife edge, or the flat face's foot), cam frame.
    pub centres: Vec<DVec2>,
    /// The practical profile's points (roller tangency, face contact), cam frame.
    pub profile: Vec<DVec2>,
    /// The practical profile's unit tangent at its points (⊥ the roller's radius to the
    /// tangency, along the face line), cam frame: the French curve touches every roller.
    pub tangents: Vec<DVec2>,
    /// The pressure angle read off the drawing at every point (the normal against the
    /// follower's path), signed by the side of the path the normal leans to
    /// ([`super::reading::read_leans`]), rad; its magnitude is [`Inversion::angle`].
    pub leans: Vec<f64>,
    /// The smallest convex radius of curvature of the drawn pitch curve (or of the flat
    /// profile r₀ + S + S″ from the drawn values), m.
    pub rho_min: f64,
}

/// The profile by inversion at μ_l: the scene's; else the round μ_l that draws the largest
/// radius at most [`PROFILE_MM`], made coarser along the round series until the drawing
/// fits [`PROFILE_ROOM`] (each try constructed and measured).
pub(crate) fn invert(
    spec: &CamSpec,
    points: &[Point],
    read: &[FollowerMotion],
    place: &Placement,
    (base, roller): (f64, f64),
    ctx: &Context,
) -> Result<Inversion, CamError> {
    let cam = Inverting {
        spec,
        points,
        read,
        place,
        base,
        roller,
        flat: matches!(spec.follower, Follower::Flat { .. }),
    };
    let at = |mu: Scale| cam.at(mu, ctx);
    if let Some(mu) = spec.scale_l {
        return at(mu);
    }
    let reach = match *place {
        Placement::Rocker { pivot, arm, .. } => pivot.length() + arm,
        Placement::Translating { .. } => base + spec.stroke + spec.offset().abs(),
    };
    let mut mu =
        Scale::round_for(reach, PROFILE_MM, Quantity::Length).ok_or(CamError::NoScale {
            what: "μ_l",
            size: reach,
        })?;
    let mut inv = at(mu)?;
    for _ in 0..4 {
        let Some((lo, hi)) = inv.figure.bounds() else {
            break;
        };
        let need = overflow(hi - lo, PROFILE_ROOM);
        match raised(mu, need) {
            Some(next) if need > 1.0 && next != mu => mu = next,
            _ => break,
        }
        inv = at(mu)?;
    }
    Ok(inv)
}

/// What the profile by inversion is drawn from: the law's points with the follower's motion
/// read at each, its placement, the base circle's and the roller's radii.
struct Inverting<'a> {
    spec: &'a CamSpec,
    points: &'a [Point],
    read: &'a [FollowerMotion],
    place: &'a Placement,
    base: f64,
    roller: f64,
    /// A flat-faced follower: no pitch curve, the face lines' contacts.
    flat: bool,
}

/// The follower's inverted positions as drawn, in the cam frame.
#[derive(Default)]
struct Turned {
    /// The pitch points.
    centres: Vec<DVec2>,
    /// The practical profile's points.
    profile: Vec<DVec2>,
    /// The practical profile's tangents.
    tangents: Vec<DVec2>,
    /// The follower's kinematics at each.
    kins: Vec<Kin>,
}

impl Inversion {
    /// The pressure angle read at point `i` (0 past the points), rad: the magnitude of its
    /// lean; a rocker's transmission angle is its complement ([`super::Cam::angle_read`]).
    pub fn angle(&self, i: usize) -> f64 {
        self.leans.get(i).map_or(0.0, |a| a.abs())
    }
}

impl Inverting<'_> {
    /// The profile by inversion at `mu`.
    fn at(&self, mu: Scale, ctx: &Context) -> Result<Inversion, CamError> {
        let mut rec = Recorder::in_context("inversion", mu, ctx);
        let o = cam_centre(&mut rec);
        rotation(&mut rec, o, mu.to_mm(self.base));
        self.circles(&mut rec, o, mu);
        let mut turned = Turned::default();
        for (i, p) in self.points.iter().enumerate() {
            rec.set_group(i as u32 + 1);
            self.position(&mut rec, o, mu, (i, p), &mut turned);
        }
        rec.set_group(0);
        self.base_radius(&mut rec, mu, &turned.centres);
        self.profiles(&mut rec, o, mu, &turned);
        // The angle read off the drawing ([`super::reading`]).
        let paths: Vec<DVec2> = self
            .points
            .iter()
            .zip(&turned.kins)
            .map(|(p, k)| to_cam(k.path, p.phi))
            .collect();
        let drawn = Drawn {
            spec: self.spec,
            points: self.points,
            centres: &turned.centres,
        };
        let leans = read_leans(&drawn, &paths);
        let rho_min = if self.flat {
            self.read
                .iter()
                .map(|m| self.base + m.s + m.d2s)
                .fold(f64::INFINITY, f64::min)
        } else {
            drawn_rho_min(self.points, &turned.centres, &turned.tangents)
        };
        Ok(Inversion {
            figure: rec.finish(),
            scale: mu,
            centres: turned.centres,
            profile: turned.profile,
            tangents: turned.tangents,
            leans,
            rho_min,
        })
    }

    /// The base circle, and a translating follower's offset circle (a roller's or a knife
    /// edge's, offset).
    fn circles(&self, rec: &mut Recorder, o: StepId, mu: Scale) {
        rec.draw(
            "base circle r_0",
            Item::Circle(Circle {
                center: DVec2::ZERO,
                radius: mu.to_mm(self.base),
            }),
            Role::Construction,
            &[o],
        );
        // The rocker's pivot O₂ turns back about O₁ on its circle, where its positions are
        // numbered (the textbook's O₂⁰ … O₂ⁿ).
        if let Placement::Rocker { pivot, .. } = *self.place {
            rec.draw(
                "circle of the pivot O_2 turned back",
                Item::Circle(Circle {
                    center: DVec2::ZERO,
                    radius: mu.to_mm(pivot.length()),
                }),
                Role::Construction,
                &[o],
            );
        }
        if let Placement::Translating { offset, .. } = *self.place {
            if offset != 0.0 && !self.flat {
                rec.draw(
                    "offset circle e",
                    Item::Circle(Circle {
                        center: DVec2::ZERO,
                        radius: mu.to_mm(offset.abs()),
                    }),
                    Role::Construction,
                    &[o],
                );
            }
        }
    }

    /// The base circle's radius r₀ dimensioned from O₁ where the followers leave the most
    /// room: the whole degree farthest from every turned pitch point (in the near dwell's
    /// gap, where no follower is drawn), clear of the support under O₁ and of the rotation's
    /// arrow ([`rotation`]) beside it.
    fn base_radius(&self, rec: &mut Recorder, mu: Scale, centres: &[DVec2]) {
        // The angle from b to a in [−π, π): a and b in [−π, π], so a − b + π is at most a
        // turn out, and taking the turn off is exact there (what `rem_euclid` gives).
        let apart = |a: f64, b: f64| {
            let x = a - b + PI;
            let x = if x < 0.0 {
                x + TAU
            } else if x >= TAU {
                x - TAU
            } else {
                x
            };
            x - PI
        };
        let clear = |a: f64| !(R0_KEPT_OFF.0..R0_KEPT_OFF.1).contains(&a);
        let headings: Vec<f64> = centres.iter().map(|c| c.y.atan2(c.x)).collect();
        let room = |a: f64| {
            headings
                .iter()
                .map(|&h| apart(h, a).abs())
                .fold(PI, f64::min)
        };
        let Some((a, _)) = (-180..180)
            .map(|d| f64::from(d).to_radians())
            .filter(|&a| clear(a))
            .map(|a| (a, room(a)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
        else {
            return;
        };
        let dir = DVec2::from_angle(a);
        let end = dir * mu.to_mm(self.base);
        let id = rec.draw(
            "base circle's radius r_0",
            Item::Vector {
                from: DVec2::ZERO,
                to: end,
            },
            Role::Dimension,
            &[],
        );
        rec.label(id, "r_0", end * 0.6, dir.perp());
    }

    /// The follower at point `i` turned back by its φ: the compass arc to its ray, the
    /// follower, the roller, the pitch point (the phases' ends labelled).
    fn position(
        &self,
        rec: &mut Recorder,
        o: StepId,
        mu: Scale,
        (i, p): (usize, &Point),
        turned: &mut Turned,
    ) {
        let mm = |p: DVec2| p / mu.value();
        let (base, roller, flat) = (self.base, self.roller, self.flat);
        let m = self.read.get(i).copied().unwrap_or(FollowerMotion {
            s: 0.0,
            ds: 0.0,
            d2s: 0.0,
        });
        let kin = self.place.kin(m);
        let c = to_cam(kin.b, p.phi);
        // The compass arc about O₁ through B_i (radius O₁B_i), notched where it meets ray i.
        rec.draw(
            format!("arc about O_1 from B_{i} to ray {i}"),
            Item::Arc(Arc::notch(DVec2::ZERO, mm(c), 4.0)),
            Role::Construction,
            &[o],
        );
        // The follower in its inverted position.
        let fol = match *self.place {
            Placement::Rocker { pivot, .. } => Segment::new(mm(to_cam(pivot, p.phi)), mm(c)),
            // The follower's axis from inside the base circle out to the pitch point: the
            // axes would meet in a blot at the centre (tangent to the circle e, about it).
            Placement::Translating { offset, s0 } if !flat => {
                Segment::new(mm(to_cam(DVec2::new(offset, INNER * s0), p.phi)), mm(c))
            }
            Placement::Translating { .. } => {
                let dir = to_cam(DVec2::X, p.phi);
                let half = mu.to_mm(self.spec.stroke.max(m.ds.abs()) * 0.6 + 0.002);
                let foot = mm(to_cam(DVec2::new(0.0, base + m.s), p.phi));
                Segment::new(foot - dir * half, foot + dir * half)
            }
        };
        rec.draw(
            format!("follower at position {i}"),
            Item::Segment(fol),
            Role::Construction,
            &[o],
        );
        let t = if flat {
            let (q, _) = flat_contact(base, m);
            to_cam(q, p.phi)
        } else {
            if roller > 0.0 {
                rec.draw(
                    format!("roller at {i}"),
                    Item::Circle(Circle {
                        center: mm(c),
                        radius: mu.to_mm(roller),
                    }),
                    Role::Construction,
                    &[],
                );
            }
            to_cam(kin.roller_point(roller), p.phi)
        };
        let pid = rec.point(
            format!("pitch point {i}"),
            mm(c),
            Role::Construction,
            "",
            DVec2::ZERO,
            &[],
        );
        // A rocker's every position is numbered at its pivot O₂ⁱ, on the pivot's circle; a
        // translating follower's phases' ends at their pitch points (the textbook's 0, n,
        // n + 1, 2n + 1 when no point is added on a break of the law).
        if let Placement::Rocker { pivot, .. } = *self.place {
            let at = mm(to_cam(pivot, p.phi));
            let id = rec.draw(
                format!("pivot O_2 at position {i}"),
                Item::Point(at),
                Role::Construction,
                &[],
            );
            rec.label_point(id, p.label.clone(), at, at.normalize_or_zero());
        } else if p.k == 0 || p.last {
            rec.label(pid, p.label.clone(), mm(c), mm(c).normalize_or_zero());
        }
        turned.centres.push(c);
        turned.profile.push(t);
        turned.tangents.push(if flat {
            to_cam(DVec2::X, p.phi)
        } else {
            to_cam(kin.normal().perp(), p.phi)
        });
        turned.kins.push(kin);
    }

    /// The pitch (theoretical) profile through the pitch points, unless flat, and the
    /// practical profile: each the French curve along each moving phase (the two share
    /// their tangents: the roller's envelope runs parallel to the pitch curve), the dwells'
    /// arcs.
    fn profiles(&self, rec: &mut Recorder, o: StepId, mu: Scale, turned: &Turned) {
        let closed = |pts: &[DVec2]| -> Item {
            let (start, pieces) = closed_profile(self.points, pts, &turned.tangents);
            let mm = |p: DVec2| p / mu.value();
            Item::Bezier {
                start: mm(start),
                pieces: pieces.iter().map(|p| p.map(mm)).collect(),
                closed: true,
            }
        };
        if !self.flat {
            rec.draw(
                "pitch (theoretical) profile",
                closed(&turned.centres),
                Role::Construction,
                &[o],
            );
        }
        rec.draw(
            if self.flat {
                "practical profile: envelope of the face lines"
            } else {
                "practical profile: envelope of the rollers"
            },
            closed(&turned.profile),
            Role::Result,
            &[o],
        );
    }
}

/// The directions from O₁ (rad, in the frame before a clockwise cam is mirrored) the base
/// circle's radius keeps off: the support drawn under O₁ and its hatching (straight down
/// ± 60°) and the rotation's arrow beside it ([`rotation`], −69° … −17°, with its label).
const R0_KEPT_OFF: (f64, f64) = (-150.0 * PI / 180.0, -10.0 * PI / 180.0);

/// The cam's sense of rotation: an arrowed arc about O₁ of radius 0.3·r₀ (`r0_mm` the base
/// radius drawn; counter-clockwise here, the mirror image of a clockwise cam turns it round).
pub(super) fn rotation(rec: &mut Recorder, o: StepId, r0_mm: f64) {
    let turn = Arc {
        center: DVec2::ZERO,
        radius: 0.3 * r0_mm,
        start: -1.2,
        sweep: 0.9,
    };
    let w = rec.draw("the cam's rotation ω_1", Item::Arc(turn), Role::Given, &[o]);
    let end = turn.end();
    let along = DVec2::from_angle(turn.start + turn.sweep).perp();
    rec.draw(
        "the cam's rotation ω_1: the arrow",
        Item::Vector {
            from: end - along * 0.1,
            to: end,
        },
        Role::Given,
        &[w],
    );
    rec.label(
        w,
        "ω_1",
        turn.eval(0.5),
        DVec2::from_angle(turn.start + 0.5 * turn.sweep),
    );
}

/// The closed profile through `pts` (one per point of the law, cam frame) as cubic Bézier
/// pieces from its first point: each moving phase the French curve between its points,
/// touching their `tangents` (the curve itself, not points on it), and each dwell the arc
/// about O₁ it is.
pub(super) fn closed_profile(
    points: &[Point],
    pts: &[DVec2],
    tangents: &[DVec2],
) -> (DVec2, Vec<[DVec2; 3]>) {
    let [rise, ret] = moving_phases(points);
    let (n, m) = (rise.end, ret.end);
    let phase = |range: Range<usize>| {
        range.map(|i| french_piece(pts[i], tangents[i], pts[i + 1], tangents[i + 1]))
    };
    let mut out: Vec<[DVec2; 3]> = phase(rise).collect();
    out.extend(dwell(pts[n], pts[n + 1]));
    out.extend(phase(ret));
    out.extend(dwell(pts[m], pts[0]));
    (pts[0], out)
}

/// The French-curve pieces of the moving phases, each by the index of the point it starts
/// at: the rise's up to its last point, the return's from the point after it to the last
/// (the dwells between are arcs).
fn moving_phases(points: &[Point]) -> [Range<usize>; 2] {
    let n = points.iter().position(|p| p.last).unwrap_or(0);
    let m = points.len().saturating_sub(1);
    [0..n, n + 1..m]
}

/// The dwell from `from` to `to`: the arc about O₁, swept clockwise in the cam frame (the
/// short way is right for < 180°), as cubic pieces of at most [`DWELL_PIECE`] each (the
/// control points 4/3·tan(δ/4)·r along the tangents: within 4e-7·r of the arc).
fn dwell(from: DVec2, to: DVec2) -> Vec<[DVec2; 3]> {
    let r = from.length();
    let a = Arc::between(DVec2::ZERO, r, from, to);
    let sweep = if a.sweep > 0.0 {
        a.sweep - TAU
    } else {
        a.sweep
    };
    let k = (sweep.abs() / DWELL_PIECE).ceil().max(1.0);
    let delta = sweep / k;
    let arm = 4.0 / 3.0 * (delta / 4.0).tan() * r;
    (0..k as usize)
        .map(|j| {
            let e0 = DVec2::from_angle(a.start + delta * j as f64);
            let e1 = DVec2::from_angle(a.start + delta * (j + 1) as f64);
            [
                e0 * r + e0.perp() * arm,
                e1 * r - e1.perp() * arm,
                if j + 1 == k as usize { to } else { e1 * r },
            ]
        })
        .collect()
}

/// Equal steps of a French-curve piece's parameter between the points [`drawn_rho_min`]
/// fits its circles through.
const RHO_STEPS: usize = 4;

/// The largest angle of a dwell's cubic piece, radians (30°).
const DWELL_PIECE: f64 = std::f64::consts::PI / 6.0;

/// The cam's centre O₁ at the origin, fixed and labelled: the first step of every profile.
pub(super) fn cam_centre(rec: &mut Recorder) -> StepId {
    let o = rec.draw(
        "cam centre O_1",
        Item::Joint {
            at: DVec2::ZERO,
            fixed: true,
        },
        Role::Given,
        &[],
    );
    rec.label(o, "O_1", DVec2::ZERO, DVec2::new(-0.7, -0.7));
    o
}

/// The smallest radius of the circles a draughtsman fits where the drawn pitch curve turns
/// like the cam (convex): through three neighbouring points of the curve as
/// [`closed_profile`] draws it (each moving phase's French curve through the pitch points
/// `c`, touching their `tangents`), [`RHO_STEPS`] to a piece, straight or concave triples
/// skipped; the dwell arcs' radii too. (Before, through three neighbouring pitch points:
/// a circle over two pieces, which misses the bend between them, seed 000's cam by +12 %.)
pub(super) fn drawn_rho_min(points: &[Point], c: &[DVec2], tangents: &[DVec2]) -> f64 {
    let mut best = f64::INFINITY;
    for phase in moving_phases(points).into_iter().filter(|p| !p.is_empty()) {
        let start = c[phase.start];
        let pieces: Vec<[DVec2; 3]> = phase
            .map(|i| french_piece(c[i], tangents[i], c[i + 1], tangents[i + 1]))
            .collect();
        for w in bezier_points(start, &pieces, RHO_STEPS).windows(3) {
            let (a, b, d) = (w[0], w[1], w[2]);
            let cross = (b - a).perp_dot(d - b);
            // Clockwise turning is convex (the cam frame's curve runs clockwise).
            if cross < 0.0 {
                best = best.min(a.distance(b) * b.distance(d) * d.distance(a) / (2.0 * -cross));
            }
        }
    }
    for p in [
        c.first(),
        points
            .iter()
            .position(|p| p.phase == 2)
            .and_then(|j| c.get(j)),
    ]
    .into_iter()
    .flatten()
    {
        best = best.min(p.length());
    }
    best
}
