//! Force analysis: kinetostatics of Assur groups by force polygons, the driving link,
//! Zhukovsky's lever, friction and rotor balancing — each a construction, an analytic twin
//! and a check.

pub mod friction;
