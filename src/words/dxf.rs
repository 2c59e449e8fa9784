//! The words of a sheet's CAD drawing: its layers' names and its ГОСТ 2.303 line types'
//! descriptions, as a student reads them in the CAD program's lists.

use super::catalogue;

catalogue! {
    /// A layer's name or a line type's description in a DXF drawing.
    DxfText {
        LayerGiven => ("Заданное", "Задане", "Given"),
        LayerConstruction => ("Построения", "Побудови", "Construction"),
        LayerResults => ("Результаты", "Результати", "Results"),
        LayerAxes => ("Оси", "Осі", "Axes"),
        LayerDimensions => ("Размеры", "Розміри", "Dimensions"),
        LayerHatching => ("Штриховка", "Штрихування", "Hatching"),
        LayerText => ("Надписи", "Написи", "Text"),
        LayerFrame => ("Рамка", "Рамка", "Frame"),
        LineMain => ("Сплошная толстая основная, ГОСТ 2.303", "Суцільна товста основна, ГОСТ 2.303", "Solid thick main line, GOST 2.303"),
        LineThin => ("Сплошная тонкая, ГОСТ 2.303", "Суцільна тонка, ГОСТ 2.303", "Solid thin line, GOST 2.303"),
        LineDashed => ("Штриховая, ГОСТ 2.303", "Штрихова, ГОСТ 2.303", "Dashed line, GOST 2.303"),
        LineDashDot => ("Штрихпунктирная тонкая, ГОСТ 2.303", "Штрихпунктирна тонка, ГОСТ 2.303", "Thin dash-dot line, GOST 2.303"),
        LineWavy => ("Сплошная волнистая (как сплошная), ГОСТ 2.303", "Суцільна хвиляста (як суцільна), ГОСТ 2.303", "Solid wavy line (as continuous), GOST 2.303"),
    }
}
