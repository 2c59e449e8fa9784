//! The DXF's layers and line types: one layer per role of the recorder and two for the
//! sheet's texts and its frame; the ГОСТ 2.303 line types in the LTYPE table, each with the
//! pen the SVG draws it with ([`Pen`]).

use crate::construct::Role;
use crate::plate::style::Pen;
use crate::scale::Lang;
use acadrust::tables::{Layer, LineType, LineTypeElement};
use acadrust::types::LineWeight;

/// A layer of the DXF: what a student hides or recolours as one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DxfLayer {
    /// The recorded steps of one role (and, for [`Role::Dimension`], their texts).
    Role(Role),
    /// Labels (with their leaders), captions, text blocks and tables.
    Text,
    /// The trim border, the frame, the title block and the designation box.
    Frame,
}

impl DxfLayer {
    /// Every layer, in the order of the LAYER table.
    pub const ALL: [DxfLayer; 8] = [
        DxfLayer::Role(Role::Given),
        DxfLayer::Role(Role::Construction),
        DxfLayer::Role(Role::Result),
        DxfLayer::Role(Role::Axis),
        DxfLayer::Role(Role::Dimension),
        DxfLayer::Role(Role::Hatch),
        DxfLayer::Text,
        DxfLayer::Frame,
    ];

    /// Its name in the sheet's language (the names a student reads in the CAD program's
    /// layer list, as the title block's captions are in that language).
    pub fn name(self, lang: Lang) -> &'static str {
        use crate::words::DxfText as W;
        match self {
            DxfLayer::Role(Role::Given) => W::LayerGiven,
            DxfLayer::Role(Role::Construction) => W::LayerConstruction,
            DxfLayer::Role(Role::Result) => W::LayerResults,
            DxfLayer::Role(Role::Axis) => W::LayerAxes,
            DxfLayer::Role(Role::Dimension) => W::LayerDimensions,
            DxfLayer::Role(Role::Hatch) => W::LayerHatching,
            DxfLayer::Text => W::LayerText,
            DxfLayer::Frame => W::LayerFrame,
        }
        .get(lang)
    }

    /// The pen most of its lines are drawn with: the layer's line type and weight, which its
    /// entities drawn with that pen take `BYLAYER`.
    pub fn pen(self) -> Pen {
        match self {
            DxfLayer::Role(role) => Pen::for_role(role),
            DxfLayer::Text => Pen::THIN,
            DxfLayer::Frame => Pen::MAIN,
        }
    }

    /// The LAYER table's entry.
    pub(super) fn table_entry(self, lang: Lang) -> Layer {
        let pen = self.pen();
        let mut layer = Layer::new(self.name(lang));
        layer.line_type = LineKind::of(pen).name().to_string();
        layer.line_weight = line_weight(pen.width);
        layer
    }
}

/// A ГОСТ 2.303 line type as an entry of the LTYPE table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum LineKind {
    /// Сплошная толстая основная.
    Main,
    /// Сплошная тонкая.
    Thin,
    /// Штриховая.
    Dashed,
    /// Штрихпунктирная тонкая.
    DashDot,
    /// Сплошная волнистая: written as a continuous line (a CAD line type cannot wave); no
    /// recorded step draws it.
    Wavy,
}

impl LineKind {
    /// Every line type, in the order of the LTYPE table.
    pub(super) const ALL: [LineKind; 5] = [
        LineKind::Main,
        LineKind::Thin,
        LineKind::Dashed,
        LineKind::DashDot,
        LineKind::Wavy,
    ];

    /// The line type a pen draws: by its dash pattern, a solid one by its width.
    pub(super) fn of(pen: Pen) -> LineKind {
        if pen.dash == Pen::AXIS.dash {
            LineKind::DashDot
        } else if !pen.dash.is_empty() {
            LineKind::Dashed
        } else if pen.is_main() {
            LineKind::Main
        } else {
            LineKind::Thin
        }
    }

    /// The pen whose pattern the entry carries.
    fn pen(self) -> Pen {
        match self {
            LineKind::Main => Pen::MAIN,
            LineKind::Thin | LineKind::Wavy => Pen::THIN,
            LineKind::Dashed => Pen::DASHED,
            LineKind::DashDot => Pen::AXIS,
        }
    }

    /// Its name in the table: ASCII, so that every CAD program's line type list takes it.
    pub(super) fn name(self) -> &'static str {
        match self {
            LineKind::Main => "GOST_MAIN",
            LineKind::Thin => "GOST_THIN",
            LineKind::Dashed => "GOST_DASHED",
            LineKind::DashDot => "GOST_DASHDOT_THIN",
            LineKind::Wavy => "GOST_WAVY",
        }
    }

    /// Its description in the sheet's language: the ГОСТ 2.303 name (ru, uk, en).
    fn description(self, lang: Lang) -> &'static str {
        use crate::words::DxfText as W;
        match self {
            LineKind::Main => W::LineMain,
            LineKind::Thin => W::LineThin,
            LineKind::Dashed => W::LineDashed,
            LineKind::DashDot => W::LineDashDot,
            LineKind::Wavy => W::LineWavy,
        }
        .get(lang)
    }

    /// The LTYPE table's entry: the pen's dash pattern (dash, gap, …) as dashes and spaces.
    pub(super) fn table_entry(self, lang: Lang) -> LineType {
        let pen = self.pen();
        let mut lt = LineType::new(self.name());
        lt.description = self.description(lang).to_string();
        for (k, &len) in pen.dash.iter().enumerate() {
            lt.add_element(if k % 2 == 0 {
                LineTypeElement::dash(len)
            } else {
                LineTypeElement::space(len)
            });
        }
        lt.pattern_length = pen.dash.iter().sum();
        lt
    }
}

/// The line weights a DXF may hold, 1/100 mm (DXF reference, group code 370): AutoCAD and
/// strict readers reject any other value.
const LINE_WEIGHTS: [i16; 24] = [
    0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200,
    211,
];

/// The line weight nearest a pen's width, mm (the lighter of two as near).
pub(super) fn line_weight(width_mm: f64) -> LineWeight {
    let hundredths = width_mm * 100.0;
    let nearest = LINE_WEIGHTS
        .iter()
        .copied()
        .min_by(|a, b| {
            let (da, db) = (
                (f64::from(*a) - hundredths).abs(),
                (f64::from(*b) - hundredths).abs(),
            );
            da.total_cmp(&db)
        })
        .unwrap_or(0);
    LineWeight::Value(nearest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pens_map_to_gost_line_types_and_standard_weights() {
        let kinds = [Pen::MAIN, Pen::THIN, Pen::AXIS, Pen::DASHED].map(LineKind::of);
        let want = [
            LineKind::Main,
            LineKind::Thin,
            LineKind::DashDot,
            LineKind::Dashed,
        ];
        assert_eq!(kinds, want);
        let weights = [Pen::MAIN, Pen::THIN, Pen::TRIM].map(|p| line_weight(p.width));
        assert_eq!(weights, [50, 25, 9].map(LineWeight::Value));
        let dash_dot = LineKind::DashDot.table_entry(Lang::Ru);
        let lengths: Vec<f64> = dash_dot.elements.iter().map(|e| e.length).collect();
        assert_eq!(lengths, [12.0, -3.0, 1.0, -3.0]);
        assert_eq!(dash_dot.pattern_length, 19.0);
        let names: std::collections::BTreeSet<&str> =
            DxfLayer::ALL.iter().map(|l| l.name(Lang::Uk)).collect();
        assert_eq!(names.len(), DxfLayer::ALL.len(), "{names:?}");
    }
}
