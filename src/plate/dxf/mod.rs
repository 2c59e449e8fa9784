//! The DXF writer: a plate as one AutoCAD DXF drawing (AC1021, R2007) at 1:1 in millimetres,
//! for a student who finishes the sheet in KOMPAS-3D or AutoCAD (issue 48, `docs/dxf.md`).
//!
//! Written from the plate model the SVG writer reads — the same marks of the frame, the
//! title block, every step of every view, every label placed by [`layout`](super::layout)
//! with its leader, the captions, the text blocks and the tables — in the SVG's order, each
//! on its [`DxfLayer`]. Sheet millimetres (y down) become the DXF's (y up) by a flip about the
//! sheet's height. A stroked path is one entity per subpath (LINE, CIRCLE, ARC or
//! LWPOLYLINE), a filled one (dots, arrowheads) one solid HATCH, a hatched region (a part's
//! section, a zone: [`crate::construct::Item::Hatching`]) one HATCH of the ГОСТ 2.306 lines,
//! user-defined at its angle and spacing, on its outline. A path the SVG fills white (a pair's
//! circle, a slider's block) is a WIPEOUT under each closed subpath and then its strokes: the
//! pairs come after the links (`hinges_last`), so, drawn in order, they cover the links' ends
//! as on the sheet. A text is one TEXT per run ([`text`]). The bytes are the same on every run:
//! the crate writes no clock and numbers handles in the order entities are added.

mod layers;
mod shapes;
mod text;

pub use layers::DxfLayer;
pub use shapes::CURVE_TOLERANCE_MM;

use super::items::step_marks;
use super::labels::{layout, text_block_lines};
use super::path::Map;
use super::sheet::{frame_marks, title_block_marks};
use super::style::{Mark, Paint, Pen};
use super::table::table_marks;
use super::{Plate, PlateError};
use crate::construct::Role;
use crate::geom::DVec2;
use acadrust::entities::EntityType;
use acadrust::tables::TextStyle;
use acadrust::types::{DxfVersion, LineWeight, Vector2, Vector3};
use acadrust::{CadDocument, DxfWriter};
use layers::{line_weight, LineKind};

/// The sheet's y-down millimetres as the DXF's y-up ones: a flip about the sheet's height.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Flip {
    height: f64,
}

impl Flip {
    fn pt(&self, p: DVec2) -> DVec2 {
        DVec2::new(p.x, self.height - p.y)
    }
}

/// The plate as DXF bytes (see the module documentation).
///
/// # Errors
/// [`PlateError::Dxf`] when the crate refuses the drawing (a table entry or an entity it
/// cannot write).
pub fn to_dxf(plate: &Plate) -> Result<Vec<u8>, PlateError> {
    let refused = |e: acadrust::DxfError| PlateError::Dxf(e.to_string());
    let mut doc = document(plate).map_err(refused)?;
    let flip = Flip {
        height: plate.sheet.height_mm(),
    };
    for (layer, piece) in marks(plate) {
        let (drawn, pen) = match piece {
            Piece::Mark(mark) => {
                let pen = match mark {
                    Mark::Path(Paint::Stroke(pen) | Paint::Opaque(pen), _) => Some(pen),
                    Mark::Path(Paint::Solid, _) | Mark::Text(_) => None,
                };
                (entities(&mark, &flip), pen)
            }
            Piece::Hatching(h) => (vec![shapes::hatching_entity(&h, &flip)], None),
        };
        for mut entity in drawn {
            dress(&mut entity, layer, pen, plate);
            doc.add_entity(entity).map_err(refused)?;
        }
    }
    DxfWriter::new(&doc).write_to_vec().map_err(refused)
}

/// The drawing's header and tables: millimetres, line weights shown, the ГОСТ line types,
/// the text style and the layers.
fn document(plate: &Plate) -> Result<CadDocument, acadrust::DxfError> {
    let mut doc = CadDocument::with_version(DxfVersion::AC1021);
    let h = &mut doc.header;
    // At R2007 the text is UTF-8 whatever the code page says; readers that look at it find
    // the Cyrillic one.
    h.code_page = "ANSI_1251".into();
    // Millimetres, metric.
    h.insertion_units = 4;
    h.measurement = 1;
    h.lineweight_display = true;
    let (w, ht) = (plate.sheet.width_mm(), plate.sheet.height_mm());
    h.model_space_extents_min = Vector3::new(0.0, 0.0, 0.0);
    h.model_space_extents_max = Vector3::new(w, ht, 0.0);
    h.model_space_limits_min = Vector2::new(0.0, 0.0);
    h.model_space_limits_max = Vector2::new(w, ht);
    h.current_text_style_name = text::STYLE.into();
    for kind in LineKind::ALL {
        doc.line_types.add(kind.table_entry(plate.lang))?;
    }
    let mut style = TextStyle::with_truetype(text::STYLE, super::FONT_FAMILY);
    style.font_file = FONT_FILE.into();
    doc.text_styles.add(style)?;
    for layer in DxfLayer::ALL {
        doc.layers.add(layer.table_entry(plate.lang))?;
    }
    Ok(doc)
}

/// The file of the sheet's font, italic as the SVG writes it ([`FONT_FAMILY`](super::FONT_FAMILY)).
const FONT_FILE: &str = "DejaVuSans-Oblique.ttf";

/// One thing the plate draws, as the DXF writes it.
enum Piece {
    /// A mark: its entities ([`entities`]).
    Mark(Mark),
    /// A hatching ([`crate::construct::Item::Hatching`]): one patterned HATCH, not its strokes.
    Hatching(shapes::Hatching),
}

/// Every mark of the plate with its layer, in the order the SVG writes them; a hatching as
/// its region (the SVG strokes it).
fn marks(plate: &Plate) -> Vec<(DxfLayer, Piece)> {
    let laid = layout(plate);
    let frame = frame_marks(&plate.sheet, &plate.title_block)
        .into_iter()
        .chain(title_block_marks(
            &plate.sheet,
            &plate.title_block,
            plate.lang,
        ));
    let mut out: Vec<(DxfLayer, Piece)> =
        frame.map(|m| (DxfLayer::Frame, Piece::Mark(m))).collect();
    for (k, view) in plate.views.iter().enumerate() {
        let map = Map::figure(view.origin);
        for step in super::items::hinges_last(&view.figure.steps) {
            let layer = DxfLayer::Role(step.role);
            if let Some(h) = shapes::Hatching::of(&step.item, map) {
                out.push((layer, Piece::Hatching(h)));
                continue;
            }
            out.extend(
                step_marks(step, map)
                    .into_iter()
                    .map(|m| (layer, Piece::Mark(m))),
            );
        }
        for l in laid.labels.iter().filter(|l| l.view == k) {
            let layer = label_layer(view, &l.steps);
            let leader = l.leader.iter().flat_map(|leader| leader.marks());
            out.extend(leader.map(|m| (layer, Piece::Mark(m))));
            out.push((layer, Piece::Mark(Mark::Text(l.placed.clone()))));
        }
        if let Some(caption) = &laid.views[k].caption_text {
            out.push((DxfLayer::Text, Piece::Mark(Mark::Text(caption.clone()))));
        }
    }
    let texts = plate.texts.iter().flat_map(text_block_lines);
    out.extend(texts.map(|t| (DxfLayer::Text, Piece::Mark(Mark::Text(t)))));
    let tables = plate.tables.iter().flat_map(table_marks);
    out.extend(tables.map(|m| (DxfLayer::Text, Piece::Mark(m))));
    out
}

/// The layer of a label: a dimension's text goes with its dimension, any other label on the
/// text layer.
fn label_layer(view: &super::View, steps: &[crate::construct::StepId]) -> DxfLayer {
    let of_dimension = |id: &crate::construct::StepId| {
        view.figure
            .steps
            .iter()
            .any(|s| s.id == *id && s.role == Role::Dimension)
    };
    if !steps.is_empty() && steps.iter().all(of_dimension) {
        DxfLayer::Role(Role::Dimension)
    } else {
        DxfLayer::Text
    }
}

/// The entities of one mark.
fn entities(mark: &Mark, flip: &Flip) -> Vec<EntityType> {
    match mark {
        Mark::Path(paint, d) => {
            let drawn = shapes::subpaths(d.segs(), flip);
            match paint {
                Paint::Solid if !drawn.is_empty() => vec![shapes::fill_entity(drawn)],
                Paint::Solid => Vec::new(),
                Paint::Stroke(_) => drawn.into_iter().map(shapes::stroke_entity).collect(),
                // Each subpath masked white, then stroked.
                Paint::Opaque(_) => drawn
                    .into_iter()
                    .flat_map(|d| {
                        let mask = shapes::wipeout_entity(&d);
                        mask.into_iter().chain([shapes::stroke_entity(d)])
                    })
                    .collect(),
            }
        }
        Mark::Text(t) => text::entities(t, flip)
            .into_iter()
            .map(EntityType::Text)
            .collect(),
    }
}

/// Put `entity` on `layer`, drawn with `pen`: `BYLAYER` where the pen is the layer's, else
/// the pen's own line type and weight.
fn dress(entity: &mut EntityType, layer: DxfLayer, pen: Option<Pen>, plate: &Plate) {
    let common = entity.common_mut();
    common.layer = layer.name(plate.lang).to_string();
    match pen.filter(|p| *p != layer.pen()) {
        Some(pen) => {
            common.linetype = LineKind::of(pen).name().to_string();
            common.line_weight = line_weight(pen.width);
        }
        None => {
            common.linetype = "ByLayer".to_string();
            common.line_weight = LineWeight::ByLayer;
        }
    }
}
