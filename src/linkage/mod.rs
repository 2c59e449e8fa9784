//! Linkages: structure (mobility, Assur groups), dyads of the five kinds, positions.

mod model;

pub use model::{
    Branch, Crank, Dir, Dyad, DyadKind, FixedPoint, Group, Guide, LinkPoint, Mechanism, Output,
    RedundantPair, Sense,
};
