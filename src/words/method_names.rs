//! The graphical and analytic methods' short names, as the error tables of the sheets print
//! them (`check::Method::name`).

use super::catalogue;

catalogue! {
    /// A method's short name.
    MethodName {
        Plan => ("план", "план", "vector plan"),
        DiagramChords => ("диаграмма", "діаграма", "diagram"),
        DiagramTangents => ("диаграмма (кас.)", "діаграма (дот.)", "diagram (tangents)"),
        Integration => ("интегрирование", "інтегрування", "integration"),
        Polygon => ("план сил", "план сил", "force polygon"),
        Lever => ("рычаг Жуковского", "важіль Жуковського", "Zhukovsky's lever"),
        Inversion => ("обращение движения", "обернення руху", "inversion"),
        Envelope => ("огибающая", "обвідна", "envelope"),
        Triangles => ("треугольники скоростей", "трикутники швидкостей", "velocity triangles"),
        Wittenbauer => ("Виттенбауэр", "Віттенбауер", "Wittenbauer"),
        Mertsalov => ("Мерцалов", "Мерцалов", "Mertsalov"),
        Formula => ("формула", "формула", "formula"),
        Meshing => ("картина зацепления", "картина зачеплення", "meshing diagram"),
        SlidingDiagram => ("диаграмма λ", "діаграма λ", "λ diagram"),
        CombinedDiagram => ("совмещённая диаграмма", "суміщена діаграма", "combined diagram"),
    }
}
