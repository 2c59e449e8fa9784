//! `[cam]` as the file writes it, and the key paths of its keys: what the section's
//! validation ([`super::cam`]) and its layout ([`super::cam_layout`]) read.

use super::check::join;
use serde::Deserialize;

/// The key path of the section.
pub(super) const CAM: &str = "cam";

/// `[cam]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCam {
    pub follower: Option<String>,
    pub law: Option<String>,
    pub return_law: Option<String>,
    pub ratio: Option<f64>,
    pub blend: Option<f64>,
    pub phases: Option<Vec<f64>>,
    pub stroke: Option<f64>,
    pub swing: Option<f64>,
    pub arm: Option<f64>,
    pub sense: Option<String>,
    pub offset: Option<f64>,
    pub roller: Option<f64>,
    pub gamma_min: Option<f64>,
    pub rho_min: Option<f64>,
    pub base_radius: Option<f64>,
    pub divisions: Option<i64>,
    pub poles: Option<Vec<f64>>,
    pub scale_s: Option<f64>,
    pub scale_l: Option<f64>,
    pub scale_phi: Option<f64>,
    pub law_assumed: Option<bool>,
    pub quoted_r_min: Option<f64>,
    pub closure: Option<String>,
    pub given: Option<String>,
    pub rotation: Option<String>,
    pub centres: Option<f64>,
    pub travel: Option<f64>,
}

/// `key` under `[cam]`.
pub(super) fn key(k: &str) -> String {
    join(CAM, k)
}
