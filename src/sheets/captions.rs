//! The captions and words of the sheets in the three languages, in one catalogue.

use crate::scale::Lang;

/// A caption or word of a sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Text {
    /// Pos.
    Pos,
    /// no plan:
    NoPlan,
    /// toggle position
    TogglePosition,
    /// Acceleration plan, pos.
    AccelerationPlanAt,
    /// Velocity plans
    VelocityPlans,
    /// acceleration plans
    AccelerationPlans,
    /// Diagrams of point
    DiagramsOfPoint,
    /// Hodograph
    Hodograph,
    /// Kinematic analysis
    KinematicAnalysis,
    /// Analytic solution
    AnalyticSolution,
    /// Errors of the graphical methods
    MethodErrors,
    /// quantity
    Quantity,
    /// method
    Method,
    /// pos.
    PosShort,
    /// Plan of positions
    PlanOfMechanism,
    /// Plan of positions
    PlanOfPositions,
    /// Structural scheme
    StructuralScheme,
    /// вида
    OfKind,
    /// Structural analysis
    StructuralAnalysis,
    /// With pair
    WithPair,
    /// redundant pair
    RedundantPair,
    /// Structure formula
    StructureFormula,
    /// Extreme positions
    ExtremePositions,
    /// Working stroke: crank turns
    WorkingStroke,
    /// return —
    Return,
    /// Swing of link
    SwingOfLink,
    /// Stroke of point
    StrokeOfPoint,
    /// m
    Metre,
    /// mm
    Millimetre,
    /// No diagrams over the turn: the mechanism cannot pass φ₁ = …
    NoDiagrams,
    /// No diagrams over the turn: a link leaps near φ₁ = …
    NoDiagramsLeap,
    /// (continued): the title of a table's further part
    Continued,
    /// Lengths read off the drawing to …
    ReadTo,
    /// Lengths read off the drawing exactly
    ReadExactly,
    /// δ mean, %
    MeanError,
    /// δ max, %
    MaxError,
    /// Force analysis
    ForceAnalysis,
    /// position
    Position,
    /// Group
    Group,
    /// Force polygon of group
    ForcePolygonOfGroup,
    /// Driving link
    DrivingLink,
    /// Force polygon of the driving link
    ForcePolygonOfDriver,
    /// Zhukovsky's lever
    ZhukovskyLever,
    /// Inertia loads and reactions
    LoadsAndReactions,
    /// graphical
    Graphical,
    /// analytic
    Analytic,
    /// error, %
    ErrorPct,
    /// by the force polygon
    ByPolygon,
    /// by Zhukovsky's lever
    ByLever,
    /// difference
    Difference,
}

impl Text {
    /// The text in `lang`.
    pub fn get(self, lang: Lang) -> &'static str {
        let (ru, uk, en) = match self {
            Text::Pos => ("Пол.", "Пол.", "Pos."),
            Text::NoPlan => ("план не существует:", "план не існує:", "no plan:"),
            Text::TogglePosition => ("особое положение", "особливе положення", "toggle position"),
            Text::AccelerationPlanAt => (
                "План ускорений, пол.",
                "План прискорень, пол.",
                "Acceleration plan, pos.",
            ),
            Text::VelocityPlans => ("Планы скоростей", "Плани швидкостей", "Velocity plans"),
            Text::AccelerationPlans => {
                ("планы ускорений", "плани прискорень", "acceleration plans")
            }
            Text::DiagramsOfPoint => ("Диаграммы точки", "Діаграми точки", "Diagrams of point"),
            Text::Hodograph => ("Годограф", "Годограф", "Hodograph"),
            Text::KinematicAnalysis => (
                "Кинематический анализ",
                "Кінематичний аналіз",
                "Kinematic analysis",
            ),
            Text::AnalyticSolution => (
                "Аналитический расчёт",
                "Аналітичний розрахунок",
                "Analytic solution",
            ),
            Text::MethodErrors => (
                "Погрешность графических методов",
                "Похибка графічних методів",
                "Errors of the graphical methods",
            ),
            Text::Quantity => ("величина", "величина", "quantity"),
            Text::Method => ("метод", "метод", "method"),
            Text::PosShort => ("пол.", "пол.", "pos."),
            Text::PlanOfMechanism => (
                "План положений механизма",
                "План положень механізму",
                "Plan of positions",
            ),
            Text::PlanOfPositions => ("План положений", "План положень", "Plan of positions"),
            Text::StructuralScheme => {
                ("Структурная схема", "Структурна схема", "Structural scheme")
            }
            Text::OfKind => ("вида", "виду", ""),
            Text::StructuralAnalysis => (
                "Структурный анализ",
                "Структурний аналіз",
                "Structural analysis",
            ),
            Text::WithPair => ("С парой", "З парою", "With pair"),
            Text::RedundantPair => ("избыточная пара", "надлишкова пара", "redundant pair"),
            Text::StructureFormula => ("Формула строения", "Формула будови", "Structure formula"),
            Text::ExtremePositions => {
                ("Крайние положения", "Крайні положення", "Extreme positions")
            }
            Text::WorkingStroke => (
                "Рабочий ход: поворот кривошипа на",
                "Робочий хід: поворот кривошипа на",
                "Working stroke: crank turns",
            ),
            Text::Return => ("холостой —", "холостий —", "return —"),
            Text::SwingOfLink => ("Угол размаха звена", "Кут розмаху ланки", "Swing of link"),
            Text::StrokeOfPoint => ("Ход точки", "Хід точки", "Stroke of point"),
            Text::Metre => ("м", "м", "m"),
            Text::Millimetre => ("мм", "мм", "mm"),
            Text::NoDiagrams => (
                "Диаграммы по углу поворота не строятся: механизм не проходит положение",
                "Діаграми за кутом повороту не будуються: механізм не проходить положення",
                "No diagrams over the crank turn: the mechanism cannot pass",
            ),
            Text::NoDiagramsLeap => (
                "Диаграммы по углу поворота не строятся: звено поворачивается скачком около положения",
                "Діаграми за кутом повороту не будуються: ланка повертається стрибком біля положення",
                "No diagrams over the crank turn: a link turns by a leap near",
            ),
            Text::Continued => ("(продолжение)", "(продовження)", "(continued)"),
            Text::ReadTo => (
                "Длины считаны с чертежа с точностью",
                "Довжини зчитано з креслення з точністю",
                "Lengths read off the drawing to",
            ),
            Text::ReadExactly => (
                "Длины считаны с чертежа точно (без округления)",
                "Довжини зчитано з креслення точно (без округлення)",
                "Lengths read off the drawing exactly (no rounding)",
            ),
            Text::MeanError => ("δ ср., %", "δ сер., %", "δ mean, %"),
            Text::MaxError => ("δ max, %", "δ max, %", "δ max, %"),
            Text::ForceAnalysis => ("Силовой анализ", "Силовий аналіз", "Force analysis"),
            Text::Position => ("положение", "положення", "position"),
            Text::Group => ("Группа", "Група", "Group"),
            Text::ForcePolygonOfGroup => (
                "План сил группы",
                "План сил групи",
                "Force polygon of group",
            ),
            Text::DrivingLink => ("Ведущее звено", "Ведуча ланка", "Driving link"),
            Text::ForcePolygonOfDriver => (
                "План сил ведущего звена",
                "План сил ведучої ланки",
                "Force polygon of the driving link",
            ),
            Text::ZhukovskyLever => (
                "Рычаг Жуковского",
                "Важіль Жуковського",
                "Zhukovsky's lever",
            ),
            Text::LoadsAndReactions => (
                "Силы инерции и реакции в кинематических парах",
                "Сили інерції та реакції в кінематичних парах",
                "Inertia loads and reactions in the pairs",
            ),
            Text::Graphical => ("графически", "графічно", "graphical"),
            Text::Analytic => ("аналитически", "аналітично", "analytic"),
            Text::ErrorPct => ("погрешность, %", "похибка, %", "error, %"),
            Text::ByPolygon => ("по плану сил", "за планом сил", "by the force polygon"),
            Text::ByLever => (
                "по рычагу Жуковского",
                "за важелем Жуковського",
                "by Zhukovsky's lever",
            ),
            Text::Difference => ("расхождение", "розбіжність", "difference"),
        };
        lang.pick(ru, uk, en)
    }
}

/// A unit written in SI (`m/s^2`, `N*m`) in `lang`: `·` for the product, Cyrillic letters in
/// Russian and Ukrainian (`Н·м`, `м/с^2`).
pub(super) fn unit_in(unit: &str, lang: Lang) -> String {
    let si = unit.replace('*', "·");
    match lang {
        Lang::En => si,
        Lang::Ru | Lang::Uk => si.replace('N', "Н").replace('m', "м").replace('s', "с"),
    }
}
