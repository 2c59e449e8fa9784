//! The loads of one position: weights, inertia forces −m·a_S at the centres of mass, inertia
//! moments −I_S·ε and the working resistance in its stroke, from the motion of the position
//! as one route knows it (the plans, or the analytic twin).

use super::spec::{Action, ForceSpec};
use super::ForceError;
use crate::geom::DVec2;
use crate::linkage::{Pose, Program};

/// The motion of one position, SI, by program point index and by link number.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionMotion {
    /// Positions, m.
    pub p: Vec<DVec2>,
    /// Velocities, m/s.
    pub v: Vec<DVec2>,
    /// Accelerations, m/s².
    pub a: Vec<DVec2>,
    /// Angular velocities, rad/s, counter-clockwise.
    pub omega: Vec<f64>,
    /// Angular accelerations, rad/s², counter-clockwise.
    pub eps: Vec<f64>,
}

impl PositionMotion {
    /// The analytic twin's motion at `pose` with the crank turning at `w1` (constant).
    pub fn analytic(pose: &Pose, w1: f64) -> Self {
        Self {
            p: pose.p.clone(),
            v: pose.dp.iter().map(|d| *d * w1).collect(),
            a: pose.ddp.iter().map(|d| *d * (w1 * w1)).collect(),
            omega: pose.dangle.iter().map(|d| d * w1).collect(),
            eps: pose.ddangle.iter().map(|d| d * (w1 * w1)).collect(),
        }
    }
}

/// What a load is, for its label and its row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadKind {
    /// The weight G = m·g.
    Weight,
    /// The inertia force F_и = −m·a_S.
    Inertia,
    /// The inertia moment M_и = −I_S·ε.
    InertiaMoment,
    /// A working resistance.
    Resistance,
    /// A reaction of a link already analysed.
    Reaction,
    /// Friction in a pair: a force along a guide or a couple in a journal.
    Friction,
    /// A driving force: the gas force of an indicator diagram.
    Driving,
}

/// A load on a link.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// The link it acts on.
    pub link: usize,
    /// What it is.
    pub kind: LoadKind,
    /// Its label (markup): `G_{3}`, `F_{и3}`, `M_{и3}`, `F_{пс}`, `R_{4-3}`.
    pub name: String,
    /// The force, N (zero for a couple).
    pub force: DVec2,
    /// Its point of application, by program index (a couple: unused) …
    pub at: usize,
    /// … shifted by this much, m (a guide's reaction acts off its reference point).
    pub shift: DVec2,
    /// The moment of a couple, N·m, counter-clockwise (zero for a force).
    pub moment: f64,
}

impl Load {
    /// A force `f` at point `at` on `link`.
    pub fn force(link: usize, kind: LoadKind, name: String, f: DVec2, at: usize) -> Self {
        Self {
            link,
            kind,
            name,
            force: f,
            at,
            shift: DVec2::ZERO,
            moment: 0.0,
        }
    }
    /// A couple `m` on `link`.
    pub fn couple(link: usize, kind: LoadKind, name: String, m: f64) -> Self {
        Self {
            link,
            kind,
            name,
            force: DVec2::ZERO,
            at: 0,
            shift: DVec2::ZERO,
            moment: m,
        }
    }
    /// A couple (no force).
    pub fn is_couple(&self) -> bool {
        self.force == DVec2::ZERO && self.moment != 0.0
    }
}

/// The part of the loads' scale ([`force_scale`]) below which a reaction's normal force is
/// rounding noise of its solve (exact sums hold to ~1e-15 of it): zero, with no arm.
pub const ZERO_PART: f64 = 1e-9;

/// The scale of `loads` on a mechanism whose points lie within `reach` (m) of each other:
/// their largest force, or couple over `reach`, N (zero when every load is).
pub fn force_scale(loads: &[Load], reach: f64) -> f64 {
    loads
        .iter()
        .map(|l| {
            let couple = if reach > 0.0 {
                l.moment.abs() / reach
            } else {
                0.0
            };
            l.force.length().max(couple)
        })
        .fold(0.0, f64::max)
}

/// The diagonal of the box around `points` (m): the reach of [`force_scale`].
pub fn reach(points: &[DVec2]) -> f64 {
    let Some(first) = points.first() else {
        return 0.0;
    };
    let (lo, hi) = points
        .iter()
        .fold((*first, *first), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    (hi - lo).length()
}

/// The arm `-k / n` (m) of a prismatic pair's reaction whose normal force is `n` (N) and
/// whose moment about the pair's reference point must be `k` (N·m): `None` when `n` is zero
/// to the loads' scale `scale` (N, [`ZERO_PART`]) — a reaction that vanishes has no arm,
/// rather than rounding noise over rounding noise.
pub fn arm(n: f64, k: f64, scale: f64) -> Option<f64> {
    (n.abs() > ZERO_PART * scale).then(|| -k / n)
}

/// Which stroke a position is on: `Some(true)` on the working stroke, `Some(false)` on the
/// return, `None` at an extreme or without extremes.
pub type Phase = Option<bool>;

/// The loads of one position from `motion`: for every link with a mass its weight and its
/// inertia force at the centre of mass, for every link with a moment of inertia its inertia
/// moment, and every resistance acting on the position's stroke. Zero loads are left out.
pub fn loads(
    spec: &ForceSpec,
    prog: &Program,
    motion: &PositionMotion,
    phase: Phase,
) -> Result<Vec<Load>, ForceError> {
    let mut out = Vec::new();
    for lm in &spec.links {
        let l = lm.link as usize;
        let s = point_on(prog, &lm.centre, l)?;
        let sub = l.to_string();
        if lm.mass > 0.0 {
            let g = spec.weight(lm.mass);
            out.push(Load::force(
                l,
                LoadKind::Weight,
                format!("G_{{{sub}}}"),
                g,
                s,
            ));
            let f = -motion.a[s] * lm.mass;
            if f != DVec2::ZERO {
                let name = format!("F_{{и{sub}}}");
                out.push(Load::force(l, LoadKind::Inertia, name, f, s));
            }
        }
        let m = -lm.inertia * motion.eps.get(l).copied().unwrap_or(0.0);
        if m != 0.0 {
            let name = format!("M_{{и{sub}}}");
            out.push(Load::couple(l, LoadKind::InertiaMoment, name, m));
        }
    }
    for r in spec.acting(phase) {
        let name = r.action.symbol().to_string();
        match &r.action {
            Action::Force {
                point,
                link,
                magnitude,
                dir,
            } => {
                let k = prog.index(point).ok_or_else(|| ForceError::NoPoint {
                    key: "resistance.point",
                    name: point.clone(),
                })?;
                let l = carrier(prog, k, *link).map_err(|e| e.at(point))?;
                let e = match dir {
                    Some(a) => Some(DVec2::from_angle(*a)),
                    None => (-motion.v[k]).try_normalize(),
                };
                if let Some(e) = e {
                    out.push(Load::force(
                        l,
                        LoadKind::Resistance,
                        name,
                        e * *magnitude,
                        k,
                    ));
                }
            }
            Action::Moment { link, magnitude } => {
                let l = *link as usize;
                let w = motion.omega.get(l).copied().unwrap_or(0.0);
                if w != 0.0 {
                    let m = -w.signum() * magnitude;
                    out.push(Load::couple(l, LoadKind::Resistance, name, m));
                }
            }
        }
    }
    for ind in &spec.indicators {
        out.extend(ind.load(prog, motion)?);
    }
    Ok(out)
}

/// The point `name`, which must lie on link `l`.
fn point_on(prog: &Program, name: &str, l: usize) -> Result<usize, ForceError> {
    let k = prog.index(name).ok_or_else(|| ForceError::NoPoint {
        key: "link.centre",
        name: name.to_string(),
    })?;
    if prog.links_of(k).contains(&l) {
        Ok(k)
    } else {
        Err(ForceError::NotOnLink {
            name: name.to_string(),
            link: l,
        })
    }
}

/// Why no link carries a load at a point.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Uncarried {
    /// The point is on the frame only: a load there does nothing to the mechanism.
    Frame,
    /// The scene's `link` does not carry the point, which lies on `links`.
    NotOn {
        /// The link the scene names.
        link: u32,
        /// The links the point lies on.
        links: Vec<usize>,
    },
    /// A joint of two links neither of which is a slider, or of two sliders: the scene must
    /// say which one the load acts on.
    Ambiguous {
        /// The moving links at the joint.
        links: Vec<usize>,
    },
}

impl Uncarried {
    /// The force analysis' error for a load at point `name`.
    pub fn at(self, name: &str) -> ForceError {
        ForceError::Uncarried {
            name: name.to_string(),
            why: self,
        }
    }
}

impl std::fmt::Display for Uncarried {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let list = |ls: &[usize]| {
            ls.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(" and ")
        };
        match self {
            Uncarried::Frame => write!(f, "the point is on the frame, which carries no load"),
            Uncarried::NotOn { link, links } => write!(
                f,
                "link {link} does not carry the point, which lies on link {}",
                list(links)
            ),
            Uncarried::Ambiguous { links } => write!(
                f,
                "the point is the joint of links {}: name the link the load acts on with `link`",
                list(links)
            ),
        }
    }
}

/// The link that carries a load applied at point `k`. The scene's `link`, when it names one,
/// must lie on the point. Otherwise: the one moving link the point lies on; at a joint of a
/// slider (a block pinned there, a slider on a guide) and a link that does not slide, the
/// slider — the textbooks load the ram, the piston, the block, not the rod; any other joint
/// (two bars, two sliders) must be named in the scene.
pub fn carrier(prog: &Program, k: usize, named: Option<u32>) -> Result<usize, Uncarried> {
    let on = prog.links_of(k);
    let moving: Vec<usize> = on.iter().copied().filter(|&l| l != 0).collect();
    if let Some(l) = named {
        return if moving.contains(&(l as usize)) {
            Ok(l as usize)
        } else {
            Err(Uncarried::NotOn { link: l, links: on })
        };
    }
    match moving[..] {
        [] => return Err(Uncarried::Frame),
        [l] => return Ok(l),
        _ => {}
    }
    let sliders: Vec<usize> = moving
        .iter()
        .copied()
        .filter(|&l| is_slider(prog, l))
        .collect();
    match sliders[..] {
        [l] => Ok(l),
        _ => Err(Uncarried::Ambiguous { links: moving }),
    }
}

/// Link `l` is a slider: the block of an RRP, RPR or RPP group, either link of a PRP group,
/// the translating link of an RPP group (not a slotted link the block slides in).
fn is_slider(prog: &Program, l: usize) -> bool {
    prog.groups().any(|g| g.sliders().contains(&Some(l)))
}
