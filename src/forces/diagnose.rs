//! Which part of a mechanism a failed force analysis is about: the group (or the driving link)
//! a link belongs to, and the group whose own equilibrium equations are singular at a pose (a
//! toggle or dead position). Diagnosis only: neither route's values come from here.

use super::twin::{pairs, PairKind};
use super::ForceError;
use crate::geom::{smallest_pivot, DVec2};
use crate::linkage::{Pose, Program};

/// The name of the group that link `link` belongs to, as the polygons title it (`group 2
/// (links 4, 5)`), or `the driving link`.
pub fn group_of(prog: &Program, link: usize) -> String {
    for g in prog.groups() {
        if g.links.contains(&link) {
            return format!(
                "group {} (links {}, {})",
                g.group + 1,
                g.links[0],
                g.links[1]
            );
        }
    }
    "the driving link".to_string()
}

/// The position in program order of the group of `link` (0 the driving link, then 1, 2 …
/// for the groups as they are attached): the force analysis goes from the last to the first.
pub fn order_of(prog: &Program, link: usize) -> usize {
    prog.groups()
        .position(|g| g.links.contains(&link))
        .map_or(0, |q| q + 1)
}

/// The group whose own equations (its two links' ΣF = 0 and ΣM = 0 in its three pairs'
/// unknowns) are the nearest to singular at `pose`, when they are singular to within 1e-9 of
/// their largest coefficient: the twin's system is block triangular by groups, so a singular
/// system has such a group.
pub fn singular_group(prog: &Program, pose: &Pose) -> Option<String> {
    let all = pairs(prog);
    let mut worst: Option<(f64, String)> = None;
    for (q, g) in prog.groups().enumerate() {
        let own = all.get(1 + 3 * q..4 + 3 * q)?;
        let (group, [i, j]) = (g.group, g.links);
        let centre = pose.p.get(prog.centre).copied()?;
        let mut a = [[0.0f64; 6]; 6];
        let mut put = |l: usize, c: usize, f: DVec2, x: DVec2, m: f64| {
            let r = if l == i {
                0
            } else if l == j {
                3
            } else {
                return;
            };
            a[r][c] += f.x;
            a[r + 1][c] += f.y;
            a[r + 2][c] += (x - centre).perp_dot(f) + m;
        };
        for (k, pair) in own.iter().enumerate() {
            let (cx, cy) = (2 * k, 2 * k + 1);
            match pair.kind {
                PairKind::Revolute(x) => {
                    let x = pose.p.get(x).copied()?;
                    for (c, e) in [(cx, DVec2::X), (cy, DVec2::Y)] {
                        put(pair.to, c, e, x, 0.0);
                        put(pair.from, c, -e, x, 0.0);
                    }
                }
                PairKind::Prismatic {
                    reference,
                    dir_link,
                } => {
                    let x = pose.p.get(reference).copied()?;
                    let n = pose.dir.get(dir_link).copied()?.perp();
                    put(pair.to, cx, n, x, 0.0);
                    put(pair.from, cx, -n, x, 0.0);
                    put(pair.to, cy, DVec2::ZERO, x, 1.0);
                    put(pair.from, cy, DVec2::ZERO, x, -1.0);
                }
            }
        }
        let measure = smallest_pivot(a.iter().map(|r| r.to_vec()).collect());
        if measure <= 1e-9 && worst.as_ref().is_none_or(|(w, _)| measure < *w) {
            let name = format!("group {} (links {}, {})", group + 1, i, j);
            worst = Some((measure, name));
        }
    }
    worst.map(|(_, name)| name)
}

/// The twin's [`ForceError::Singular`] at position `label`, with the group whose equations
/// are singular at `pose`.
pub(super) fn located(e: ForceError, label: &str, prog: &Program, pose: &Pose) -> ForceError {
    match e {
        ForceError::Singular => ForceError::SingularAt {
            position: label.to_string(),
            group: singular_group(prog, pose),
        },
        e => e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::{twin, Drive, ForceError};
    use crate::linkage::proptests::build;

    /// The slider-crank of `constructions/slider-crank.toml` with its rod turned square to the
    /// guide (B moved straight below A onto the guide's line): the RRP group's equations are
    /// singular, the twin refuses it and the diagnosis names group 1; at the real pose none.
    #[test]
    fn the_singular_group_is_named() {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("constructions/slider-crank.toml"),
        )
        .expect("the scene");
        let scene =
            crate::scene::parse(&text, std::path::Path::new("slider-crank.toml")).expect("parsed");
        let m = scene.mechanism.expect("a mechanism");
        let (prog, _, mut pose) = build(&m, 1.0).expect("assembled");
        assert_eq!(singular_group(&prog, &pose), None);
        let a = pose.p[prog.index("A").expect("A")];
        let b = prog.index("B").expect("B");
        let guide_y = pose.p[b].y;
        pose.p[b] = DVec2::new(a.x, guide_y);
        pose.dir[2] = (pose.p[b] - a).normalize();
        let loads = [crate::forces::Load::couple(
            2,
            crate::forces::LoadKind::Resistance,
            "M".into(),
            1.0,
        )];
        assert_eq!(
            twin::solve(&prog, &pose, &loads, &Drive::Coupling, 1.0),
            Err(ForceError::Singular)
        );
        assert_eq!(
            singular_group(&prog, &pose).as_deref(),
            Some("group 1 (links 2, 3)")
        );
        let e = ForceError::SingularAt {
            position: "3".into(),
            group: singular_group(&prog, &pose),
        };
        assert!(
            e.to_string().contains(
                "position 3: the equilibrium equations are singular in group 1 (links 2, 3)"
            ),
            "{e}"
        );
    }
}
