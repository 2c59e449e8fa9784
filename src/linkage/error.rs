//! What goes wrong in a linkage: its model ([`ModelError`]), a guide's carrier
//! ([`CarrierError`]), a task on it ([`LinkageError`]).

use std::fmt;
use thiserror::Error;

/// Why the link that carries a guide cannot be told.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CarrierError {
    /// The named link does not hold the guide's points.
    NotOn {
        /// The named link.
        link: u32,
        /// The links that hold them.
        links: Vec<u32>,
    },
    /// The guide's point joins several links: which one carries the guide is the scene's to
    /// say.
    Ambiguous {
        /// The moving links there.
        links: Vec<u32>,
    },
    /// The direction's two points lie on no common link.
    Unshared,
    /// A frame direction on a link that turns.
    Turns {
        /// The link.
        link: u32,
    },
}

impl fmt::Display for CarrierError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let list = |ls: &[u32]| {
            ls.iter()
                .map(|l| {
                    if *l == 0 {
                        "0 (the frame)".into()
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<String>>()
                .join(" and ")
        };
        match self {
            CarrierError::NotOn { link, links } if links.is_empty() => {
                write!(f, "link {link} does not hold the guide's points")
            }
            CarrierError::NotOn { link, links } => write!(
                f,
                "link {link} does not hold the guide's points, which lie on link {}",
                list(links)
            ),
            CarrierError::Ambiguous { links } => write!(
                f,
                "the guide runs through the joint of links {}: name the link whose body carries it with `link`",
                list(links)
            ),
            CarrierError::Unshared => write!(f, "the direction's two points lie on no common link"),
            CarrierError::Turns { link } => write!(
                f,
                "link {link} turns, so a guide at a fixed angle cannot be carried by it: give the \
                 direction along the link ({{ from, to }}) or name a link that translates"
            ),
        }
    }
}

impl std::error::Error for CarrierError {}

/// What is inconsistent in a mechanism model (the scene validator reports these with their
/// keys first; a model built in code meets them here).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// A point name is used twice.
    #[error("point `{0}` is defined twice")]
    DuplicatePoint(String),
    /// A point is referenced before it is known.
    #[error("{what}: point `{name}` is not known at this stage")]
    UnknownPoint {
        /// What refers to it.
        what: String,
        /// The name.
        name: String,
    },
    /// The crank's centre is not a fixed point.
    #[error("crank centre `{0}` must be a fixed point")]
    CentreNotFixed(String),
    /// A group names the frame or a link already attached.
    #[error("{what}: link {link} is the frame or already used")]
    LinkReused {
        /// The group.
        what: String,
        /// The link.
        link: u32,
    },
    /// An RPP group's slide turns with a link that moves along its guide.
    #[error("{what}: the slide through `{point}` turns with link {link}, which moves along the guide: give the slide the guide's kind of direction (both fixed, or both along the same two points)")]
    SlideAcrossGuide {
        /// The group.
        what: String,
        /// The slide's point.
        point: String,
        /// The link it turns with.
        link: u32,
    },
    /// The link that carries a guide cannot be told, or cannot carry it.
    #[error("{what}: the guide through `{point}`: {why}")]
    Carrier {
        /// The group.
        what: String,
        /// The guide's point.
        point: String,
        /// Why.
        why: CarrierError,
    },
    /// A link point on a link no group defines.
    #[error("point `{name}` is on link {link}, which no group defines")]
    PointOnUnknownLink {
        /// The point.
        name: String,
        /// Its link.
        link: u32,
    },
    /// An output rocker that is not a link of the mechanism.
    #[error("output rocker {0}: no such link")]
    NoSuchRocker(u32),
    /// An output slider that is not a point of the mechanism.
    #[error("output slider `{0}`: no such point")]
    NoSuchSlider(String),
    /// No output is given.
    #[error("no output is given")]
    NoOutput,
    /// The tolerances of a drawing cannot be formed.
    #[error("tolerances: {0}")]
    Tolerances(#[from] crate::geom::InvalidTolerance),
}

/// Why a linkage task cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LinkageError {
    /// The model itself is inconsistent (unknown names, reused links).
    #[error("mechanism: {0}")]
    Model(#[from] ModelError),
    /// A group cannot be assembled at a position.
    #[error(
        "position {position} (φ₁ = {phi_deg:.4}°): group {group} cannot be assembled: {detail}"
    )]
    CannotAssemble {
        /// The position's label.
        position: String,
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group (`2 (RRR, links 2, 3)`).
        group: String,
        /// What fails, with its numbers.
        detail: String,
    },
    /// The crank cannot make a full turn, so the extreme positions cannot be searched for.
    #[error("the crank cannot make a full turn: at φ₁ = {phi_deg:.4}° group {group} cannot be assembled: {detail}; give `start` as an angle to construct the positions that exist")]
    CannotTurn {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group.
        group: String,
        /// What fails.
        detail: String,
    },
    /// The output has no extreme positions (it turns fully or does not move).
    #[error("output {output}: {detail}")]
    NoExtremes {
        /// The output.
        output: String,
        /// Explanation.
        detail: String,
    },
}
