//! ГОСТ 2.303 line types and the roles that use them.

use super::path::PathData;
use super::text::Placed;
use crate::construct::Role;

/// A ГОСТ 2.303 line type: stroke width and dash pattern, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pen {
    /// Stroke width, mm.
    pub width: f64,
    /// Dash pattern (dash, gap, …), mm; empty for a solid line.
    pub dash: &'static [f64],
}

impl Pen {
    /// Solid main line (сплошная толстая основная), s = 0.5 mm: ГОСТ 2.303 lets s run from
    /// 0.5 to 1.4 mm by the drawing's size and complexity, and these drawings are dense (a
    /// plan's six or seven vectors meet at its pole; a slider's block carries four loads), so
    /// the thinnest keeps them from printing black.
    pub const MAIN: Pen = Pen {
        width: 0.5,
        dash: &[],
    };
    /// Solid thin line (сплошная тонкая), s/2 = 0.25 mm.
    pub const THIN: Pen = Pen {
        width: 0.25,
        dash: &[],
    };
    /// Thin dash-dot line for axes and centre lines (штрихпунктирная тонкая): 12 mm dashes,
    /// 3 mm gaps, a 1 mm dot between.
    pub const AXIS: Pen = Pen {
        width: 0.25,
        dash: &[12.0, 3.0, 1.0, 3.0],
    };
    /// Thin dashed line for invisible contours (штриховая): 4 mm strokes, 1.5 mm gaps
    /// (ГОСТ 2.303: strokes 2…8 mm, gaps 1…2 mm). No recorded role draws it; the DXF's line
    /// type table offers it to whoever finishes the sheet in a CAD program.
    pub const DASHED: Pen = Pen {
        width: 0.25,
        dash: &[4.0, 1.5],
    };
    /// The trim border of the sheet: thinnest line.
    pub const TRIM: Pen = Pen {
        width: 0.1,
        dash: &[],
    };

    /// The pen a recorded step of `role` is drawn with.
    pub fn for_role(role: Role) -> Pen {
        match role {
            Role::Given | Role::Result => Pen::MAIN,
            Role::Axis => Pen::AXIS,
            Role::Construction | Role::Dimension | Role::Hatch => Pen::THIN,
        }
    }

    /// True for the main (thick) line.
    pub fn is_main(&self) -> bool {
        self.width >= Pen::MAIN.width
    }
}

/// How a path is painted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Paint {
    /// Stroked with the pen, not filled.
    Stroke(Pen),
    /// Filled white (covering what lies under it) and stroked with the pen.
    Opaque(Pen),
    /// Filled black, not stroked (dots, arrowheads).
    Solid,
}

/// One drawn element, in sheet coordinates.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Mark {
    /// A path.
    Path(Paint, PathData),
    /// A text.
    Text(Placed),
}

impl Mark {
    /// A path mark, `None` when the path is empty.
    pub(crate) fn path(paint: Paint, d: PathData) -> Option<Mark> {
        (!d.is_empty()).then_some(Mark::Path(paint, d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roles_map_to_gost_line_types() {
        assert_eq!(Pen::for_role(Role::Given), Pen::MAIN);
        assert_eq!(Pen::for_role(Role::Result), Pen::MAIN);
        assert_eq!(Pen::for_role(Role::Construction), Pen::THIN);
        assert_eq!(Pen::for_role(Role::Axis).dash.len(), 4);
        assert!(!Pen::for_role(Role::Hatch).is_main());
    }
}
