//! The balancing and friction sections of a scene that has them, and the look-up of a
//! report's row the machine sections share (the kinetostatics and the dynamics have their
//! own files).

use super::rows::of_scene;
use super::{NoteError, Writer};
use crate::check::{Method, Row, Symbol};
use crate::scene::PlateKind;
use crate::sheets::captions::NoteText as T;

/// The row of `quantity` by `method` at `position` (`None`: of the whole scene).
pub(super) fn row<'r>(
    rows: &'r [Row],
    q: &str,
    method: Method,
    position: Option<&str>,
) -> Option<&'r Row> {
    rows.iter()
        .find(|r| r.quantity() == q && r.method == method && r.position().as_deref() == position)
}

/// The balancing and friction studies of a scene that has them.
pub(super) fn others(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let scene = w.session.scene();
    if scene.balancing.is_some() {
        w.heading(1, T::BalancingSection);
        w.data_list(PlateKind::Balancing, false);
        let caption = w.word(T::BalancingTable);
        of_scene(w, caption, |r| {
            matches!(
                r.key.symbol,
                Symbol::Mass | Symbol::StaticMoment | Symbol::UnbalanceMoment | Symbol::Angle
            )
        });
        w.figures(
            (PlateKind::Balancing, None),
            |_| true,
            |own| own.to_string(),
        );
    }
    if !scene.friction.is_empty() {
        w.heading(1, T::FrictionSection);
        let caption = w.word(T::FrictionTable);
        of_scene(w, caption, |r| {
            r.position().is_none() || r.key.subject.ends_with("_f")
        });
        super::friction::followers(w);
        w.figures((PlateKind::Friction, None), |_| true, |own| own.to_string());
    }
    Ok(())
}
