//! The studio's gallery: the shipped scenes (`constructions/*.toml`), embedded in the binary,
//! grouped by what they are — the course project, linkages, cams, gears, trains, friction,
//! balancing — as a student looks for a starting point. A request names a scene by its stem
//! only; nothing is read from disk.

use crate::scale::Lang;
use crate::scene::{self, PlateKind, Scene};
use crate::words::StudioText;
use serde::Serialize;
use std::path::Path;

/// A shipped scene: its stem and its text. A new scene of `constructions/` is one row here
/// (a test holds the list to the folder).
pub const SHIPPED: &[(&str, &str)] = &[
    ("shaper", include_str!("../../constructions/shaper.toml")),
    (
        "v-engine",
        include_str!("../../constructions/v-engine.toml"),
    ),
    (
        "four-bar",
        include_str!("../../constructions/four-bar.toml"),
    ),
    (
        "slider-crank",
        include_str!("../../constructions/slider-crank.toml"),
    ),
    ("six-bar", include_str!("../../constructions/six-bar.toml")),
    ("tangent", include_str!("../../constructions/tangent.toml")),
    (
        "cam-central",
        include_str!("../../constructions/cam-central.toml"),
    ),
    ("cam-pz4", include_str!("../../constructions/cam-pz4.toml")),
    ("cam-pz5", include_str!("../../constructions/cam-pz5.toml")),
    (
        "cam-flat-rocker",
        include_str!("../../constructions/cam-flat-rocker.toml"),
    ),
    (
        "cam-sliding",
        include_str!("../../constructions/cam-sliding.toml"),
    ),
    (
        "cam-cusp",
        include_str!("../../constructions/cam-cusp.toml"),
    ),
    (
        "cam-shock",
        include_str!("../../constructions/cam-shock.toml"),
    ),
    (
        "cam-undercut",
        include_str!("../../constructions/cam-undercut.toml"),
    ),
    (
        "gears-pz3",
        include_str!("../../constructions/gears-pz3.toml"),
    ),
    (
        "gears-pz1",
        include_str!("../../constructions/gears-pz1.toml"),
    ),
    (
        "gears-pz2",
        include_str!("../../constructions/gears-pz2.toml"),
    ),
    (
        "gears-pz2-ex1",
        include_str!("../../constructions/gears-pz2-ex1.toml"),
    ),
    (
        "gears-pz2-ex2",
        include_str!("../../constructions/gears-pz2-ex2.toml"),
    ),
    (
        "gears-differential",
        include_str!("../../constructions/gears-differential.toml"),
    ),
    (
        "friction",
        include_str!("../../constructions/friction.toml"),
    ),
    (
        "friction-follower",
        include_str!("../../constructions/friction-follower.toml"),
    ),
    (
        "rotor-static",
        include_str!("../../constructions/rotor-static.toml"),
    ),
    (
        "rotor-dynamic",
        include_str!("../../constructions/rotor-dynamic.toml"),
    ),
];

/// What a scene is, for the gallery's sections (in this order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum GalleryGroup {
    /// A scene of several studies: the whole course project.
    Project,
    /// A linkage's kinematics (and forces).
    Linkage,
    /// A cam mechanism.
    Cam,
    /// A gear pair and rack generation.
    Gears,
    /// A gear train (fixed-axis, planetary, differential).
    Train,
    /// Friction.
    Friction,
    /// Balancing of a rotor.
    Balancing,
}

impl GalleryGroup {
    /// The group of `s`: the project when it studies three kinds of sheet or more, else the
    /// kind of its first sheet.
    pub fn of(s: &Scene) -> GalleryGroup {
        let kinds = crate::sheets::drawn(s);
        if kinds.len() >= 3 {
            return GalleryGroup::Project;
        }
        match kinds.first() {
            Some(PlateKind::Cam) => GalleryGroup::Cam,
            Some(PlateKind::Gears) => {
                let train = s.gears.as_ref().is_some_and(|g| {
                    g.planetary.is_some() && g.pair.is_none() && g.racks.is_empty()
                });
                if train {
                    GalleryGroup::Train
                } else {
                    GalleryGroup::Gears
                }
            }
            Some(PlateKind::Friction) => GalleryGroup::Friction,
            Some(PlateKind::Balancing) => GalleryGroup::Balancing,
            _ => GalleryGroup::Linkage,
        }
    }

    /// The section's heading.
    pub fn heading(self, lang: Lang) -> &'static str {
        let word = match self {
            GalleryGroup::Project => StudioText::Project,
            GalleryGroup::Linkage => StudioText::Linkages,
            GalleryGroup::Cam => StudioText::Cams,
            GalleryGroup::Gears => StudioText::Gears,
            GalleryGroup::Train => StudioText::Trains,
            GalleryGroup::Friction => StudioText::Friction,
            GalleryGroup::Balancing => StudioText::Balancing,
        };
        word.get(lang)
    }
}

/// A card of the gallery.
#[derive(Debug, Clone, Serialize)]
pub struct Card {
    /// The scene's stem (`shaper`): how the page asks for its text and thumbnail.
    pub stem: &'static str,
    /// Its title in the language asked.
    pub title: String,
    /// Its section.
    pub group: GalleryGroup,
    /// The section's heading in the language asked.
    pub heading: &'static str,
}

/// The text of the shipped scene `stem`, if there is one.
pub fn text(stem: &str) -> Option<&'static str> {
    SHIPPED.iter().find(|(s, _)| *s == stem).map(|(_, t)| *t)
}

/// The shipped scene `stem`, read as `tmm` reads its file.
pub fn scene(stem: &str) -> Option<Scene> {
    let text = text(stem)?;
    scene::parse(text, &Path::new(stem).with_extension("toml")).ok()
}

/// Every shipped scene as a card, by section then in [`SHIPPED`]'s order.
pub fn cards(lang: Lang) -> Vec<Card> {
    let mut out: Vec<Card> = SHIPPED
        .iter()
        .filter_map(|(stem, _)| {
            let s = scene(stem)?;
            let group = GalleryGroup::of(&s);
            Some(Card {
                stem,
                title: s.title.in_lang(lang).title,
                group,
                heading: group.heading(lang),
            })
        })
        .collect();
    out.sort_by_key(|c| c.group);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every scene of `constructions/` is in the gallery, once, and reads as `tmm` reads it.
    #[test]
    fn the_gallery_holds_every_shipped_scene() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions");
        let mut files: Vec<String> = scene::files_in(&dir)
            .expect("constructions/")
            .iter()
            .filter_map(|p| Some(p.file_stem()?.to_string_lossy().into_owned()))
            .collect();
        let mut listed: Vec<String> = SHIPPED.iter().map(|(s, _)| s.to_string()).collect();
        files.sort();
        listed.sort();
        assert_eq!(listed, files);
        assert_eq!(cards(Lang::Ru).len(), SHIPPED.len(), "every scene reads");
        let groups: Vec<GalleryGroup> = cards(Lang::En).iter().map(|c| c.group).collect();
        assert_eq!(groups.first(), Some(&GalleryGroup::Project));
        assert!(groups.windows(2).all(|w| w[0] <= w[1]), "{groups:?}");
        assert_eq!(
            GalleryGroup::of(&scene("gears-pz2").expect("pz2")),
            GalleryGroup::Train
        );
        assert_eq!(
            GalleryGroup::of(&scene("gears-pz1").expect("pz1")),
            GalleryGroup::Gears
        );
    }
}
