//! Names and labels on the plans: plain quantity names, image letters.

use super::plan::PlanKind;

/// Name of a point without markup (`S_3` → `S3`).
pub fn plain(name: &str) -> String {
    name.chars()
        .filter(|c| !matches!(c, '_' | '{' | '}' | '′'))
        .collect::<String>()
        + if name.contains('′') { "'" } else { "" }
}

pub(super) fn lower(name: &str) -> String {
    let mut c = name.chars();
    c.next().map_or_else(String::new, |f| {
        f.to_lowercase().collect::<String>() + c.as_str()
    })
}

/// Label of an image: lower-case, primed on the acceleration plan.
pub fn image_label(name: &str, kind: PlanKind) -> String {
    match kind {
        PlanKind::Velocity => lower(name),
        PlanKind::Acceleration => format!("{}′", lower(name)),
    }
}
