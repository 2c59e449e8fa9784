//! The points of a gear pair's blocking contour as the rows and the drawing name them: the
//! tag a row's subject ends in (`alpha_beps`, `1_bsl`) and the short label the contour's
//! figure writes at the point.

/// The tags of the contour's points in row subjects: the scene's point and each criterion's
/// (the largest contact ratio, equal sliding, the greatest sum of shifts with a tip limit).
pub(crate) const POINT_TAGS: [&str; 4] = ["bz", "beps", "bsl", "bsum"];

/// The short label of a point of the contour on the drawing (the sheet's lines give its x₁,
/// x₂ and indices under the same name): K the scene's point, ε_{α max}, λ (equal sliding),
/// x_{Σ max}.
pub(crate) fn point_label(tag: &str) -> &'static str {
    match tag {
        "bz" => "K",
        "beps" => "ε_{α max}",
        "bsl" => "λ_1 = λ_2",
        _ => "x_{Σ max}",
    }
}
