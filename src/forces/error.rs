//! Why a force analysis cannot be carried out.

use super::loads;
use crate::construct::ConstructionError;
use thiserror::Error;

/// Why a force analysis cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ForceError {
    /// A point named in `[forces]` is not a point of the mechanism.
    #[error("forces.{key}: there is no point `{name}`")]
    NoPoint {
        /// The key.
        key: &'static str,
        /// The name.
        name: String,
    },
    /// A load at a point no link carries, or carries unambiguously.
    #[error("forces.resistance: the force at `{name}`: {why}")]
    Uncarried {
        /// The point.
        name: String,
        /// Why.
        why: loads::Uncarried,
    },
    /// A centre of mass that is not on its link.
    #[error("forces.link: the centre of mass `{name}` is not a point of link {link}")]
    NotOnLink {
        /// The point.
        name: String,
        /// The link.
        link: usize,
    },
    /// The equilibrium equations do not match the unknowns (a group that is not a dyad).
    #[error(
        "the mechanism is not statically determinate: {equations} equations, {unknowns} unknowns"
    )]
    NotDeterminate {
        /// 3 × moving links.
        equations: usize,
        /// 2 × pairs + 1.
        unknowns: usize,
    },
    /// The equilibrium equations are singular (a group at its toggle position).
    #[error("the equilibrium equations are singular at this position (a group at a toggle or dead position)")]
    Singular,
    /// A polygon cannot be closed.
    #[error("position {position}: {what}: {error}")]
    Polygon {
        /// The position.
        position: String,
        /// The group or the driving link.
        what: String,
        /// The construction's diagnosis.
        error: Box<ConstructionError>,
    },
    /// A position to analyse that the plan does not have.
    #[error("forces.positions: there is no position {label}; the positions are {valid}")]
    NoSuchPosition {
        /// The label asked for.
        label: String,
        /// The plan's labels, compactly.
        valid: String,
    },
    /// The equilibrium equations are singular at a position (a group at a toggle or dead
    /// position): the twin's [`ForceError::Singular`] located.
    #[error("position {position}: the equilibrium equations are singular{} (a group at a toggle or dead position)", .group.as_ref().map_or(String::new(), |g| format!(" in {g}")))]
    SingularAt {
        /// The position's label (and `with friction`).
        position: String,
        /// The group whose own equations are singular, when it can be told.
        group: Option<String>,
    },
    /// Friction in the pairs with no solution: past `f_lock` ≤ `f` the friction equations of
    /// the position have none (the reactions grow without bound there, or the solution turns
    /// back where a reaction vanishes).
    #[error("position {position}: {group} self-locks with friction in the pairs: past f = {} the friction equations have no solution ({detail}); f = {} is asked", crate::scale::format_sig(*.f_lock, 4, crate::scale::Lang::En), crate::scale::format_sig(*.f, 4, crate::scale::Lang::En))]
    SelfLocking {
        /// The position's label.
        position: String,
        /// The group that locks.
        group: String,
        /// The coefficient asked for.
        f: f64,
        /// The coefficient past which there is no solution.
        f_lock: f64,
        /// How the solution ends, and the route that found it.
        detail: String,
    },
    /// The friction equations could not be followed (not a lock).
    #[error("position {position}: the friction equations in the pairs could not be solved by {route} past f = {} (not a lock: the reactions stay bounded there)", crate::scale::format_sig(*.f, 4, crate::scale::Lang::En))]
    FrictionUnsettled {
        /// The position's label.
        position: String,
        /// The route.
        route: String,
        /// The coefficient reached.
        f: f64,
    },
    /// No round μ_F can be formed.
    #[error("no force scale μ_F can be chosen for {0} N")]
    NoScale(f64),
    /// An indicator's point that is not a piston.
    #[error(
        "forces.indicator.point: `{name}` is not the slider's joint of an RRP group (a piston)"
    )]
    NotPiston {
        /// The point.
        name: String,
    },
}
