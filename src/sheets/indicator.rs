//! An engine's indicator diagrams as views of a sheet: the dynamics sheet's, whose M_д they
//! give, or (with no dynamics sheet) the first force sheet's, whose F_д they give.

use super::layout::Block;
use super::BuildError;
use crate::scale::Lang;
use crate::study::Session;

/// An engine's indicator diagrams, each captioned p(θ) as the sheets' other diagrams are by
/// their formula, with μ_p and μ_θ, and with the cylinders it serves when the cylinders'
/// diagrams differ (its ordinates name them either way).
pub(super) fn views(session: &Session<'_>, lang: Lang) -> Result<Vec<Block>, BuildError> {
    let figures = session.indicator_figures()?;
    let several = figures.len() > 1;
    Ok(figures
        .into_iter()
        .map(|(pistons, figure, mu_theta)| {
            let theta = mu_theta.caption(lang).replacen("μ_{φ}", "μ_{θ}", 1);
            let mut what = "p(θ)".to_string();
            if several {
                what.push_str(&format!(" ({})", pistons.join(", ")));
            }
            let caption = format!("{what}, {}, {theta}", figure.scale.caption(lang));
            Block::view(figure, caption, None)
        })
        .collect())
}
