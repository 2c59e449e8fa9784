//! The words of the linkage sheets (positions, kinematics, forces) and those every sheet
//! shares (the results tables' headings, "data").

use super::catalogue;

catalogue! {
    /// A caption or word of the linkage sheets, or one every sheet shares.
    Text {
        Pos => ("Пол.", "Пол.", "Pos."),
        NoPlan => ("план не существует:", "план не існує:", "no plan:"),
        TogglePosition => ("особое положение", "особливе положення", "toggle position"),
        AccelerationPlanAt => ("План ускорений, пол.", "План прискорень, пол.", "Acceleration plan, pos."),
        VelocityPlans => ("Планы скоростей", "Плани швидкостей", "Velocity plans"),
        AccelerationPlans => ("планы ускорений", "плани прискорень", "acceleration plans"),
        AcceleratingLinks => ("ускоренно вращаются звенья", "прискорено обертаються ланки", "accelerating (ω, ε in the same sense): links"),
        AcceleratingLink => ("ускоренно вращается звено", "прискорено обертається ланка", "accelerating (ω, ε in the same sense): link"),
        NoneAccelerating => ("ни одно звено не вращается ускоренно", "жодна ланка не обертається прискорено", "no link accelerating"),
        DeceleratingLinks => ("замедленно —", "сповільнено —", "decelerating:"),
        NoLinks => ("нет", "немає", "none"),
        DiagramsOfPoint => ("Диаграммы точки", "Діаграми точки", "Diagrams of point"),
        CornerBranchValues => ("ветвь после излома, по диаграммам и предел", "гілка після зламу, за діаграмами і границя", "the branch past the corner, by the diagrams and its limit"),
        ChordsRoughAtCorner => ("вблизи излома метод хорд даёт производные с большой погрешностью", "поблизу зламу метод хорд дає похідні з великою похибкою", "near a corner the chord method gives the derivatives with a large error"),
        // The error table's position of a diagram's worst error where S has a corner.
        AtCorner => ("излом", "злам", "corner"),
        CornerOfS => ("излом диаграммы S: каждая ветвь дифференцируется отдельно", "злам діаграми S: кожна гілка диференціюється окремо", "a corner of S: each branch is differentiated on its own"),
        Hodograph => ("Годограф", "Годограф", "Hodograph"),
        // A hodograph not drawn across a position without a velocity plan: its caption says where.
        HodographBroken => ("разрыв у пол.", "розрив біля пол.", "broken at pos."),
        KinematicAnalysis => ("Кинематический анализ", "Кінематичний аналіз", "Kinematic analysis"),
        AnalyticSolution => ("Аналитический расчёт", "Аналітичний розрахунок", "Analytic solution"),
        MethodErrors => ("Погрешность графических методов", "Похибка графічних методів", "Errors of the graphical methods"),
        Quantity => ("величина", "величина", "quantity"),
        AnswerKey => ("Ответы по вариантам", "Відповіді за варіантами", "Answer key"),
        ExactValues => ("точные значения", "точні значення", "exact values"),
        Variant => ("вариант", "варіант", "variant"),
        Remark => ("примечание", "примітка", "remark"),
        NotDrawn => ("не построен", "не побудовано", "not drawn"),
        Method => ("метод", "метод", "method"),
        PosShort => ("пол.", "пол.", "pos."),
        PlanOfMechanism => ("План положений механизма", "План положень механізму", "Position diagram of the mechanism"),
        PlanOfPositions => ("План положений", "План положень", "Position diagram"),
        StructuralScheme => ("Структурная схема", "Структурна схема", "Structural diagram"),
        GuideThrough => (
            "Направляющая ползуна {j} проходит через {list}",
            "Напрямна повзуна {j} проходить через {list}",
            "The guide of slider {j} passes through {list}"
        ),
        And => ("и", "і", "and"),
        KinematicScheme => ("Кинематическая схема", "Кінематична схема", "Kinematic diagram"),
        OfKind => ("вида", "виду", ""),
        StructuralAnalysis => ("Структурный анализ", "Структурний аналіз", "Structural analysis"),
        WithPair => ("С парой", "З парою", "With pair"),
        RedundantPair => ("избыточная пара", "надлишкова пара", "redundant pair"),
        StructureFormula => ("Формула строения", "Формула будови", "Structural formula"),
        ExtremePositions => ("Крайние положения", "Крайні положення", "Extreme positions"),
        AlsoStands => ("{v} = 0 также при {list}", "{v} = 0 також при {list}", "{v} = 0 also at {list}"),
        SameExtremeAs => (
            "крайнее положение, как {p}",
            "крайнє положення, як {p}",
            "the extreme position, as at {p}"
        ),
        NoTimeRatio => (
            "θ и K не определяются: крайнее положение достигается дважды за оборот",
            "θ і K не визначаються: крайнє положення досягається двічі за оберт",
            "θ and K are not defined: an extreme position is reached twice a turn"
        ),
        WorkingStroke => ("Рабочий ход", "Робочий хід", "Working stroke"),
        FromOuterDeadCentre => ("расширение от в.м.т.", "розширення від в.м.т.", "expansion from TDC"),
        SlowerStroke => ("медленный", "повільний", "the slower"),
        Return => ("холостой", "холостий", "return"),
        SwingOfLink => ("Угол размаха звена", "Кут розмаху ланки", "Swing of link"),
        StrokeOfPoint => ("Ход точки", "Хід точки", "Stroke of point"),
        GrashofCondition => ("Условие Грасгофа", "Умова Грасгофа", "Grashof's condition"),
        CrankExists => ("Кривошип существует", "Кривошип існує", "A crank exists"),
        NoCrank => ("Кривошипа нет", "Кривошипа немає", "No crank"),
        ChangePoint => (
            "Равенство: звенья ложатся на одну прямую (особое положение)",
            "Рівність: ланки лягають на одну пряму (особливе положення)",
            "The equality: the links fall into one line (a toggle position)"
        ),
        NoVelocityPlanThere => ("план скоростей не строится", "план швидкостей не будується", "no velocity plan there"),
        Millimetre => ("мм", "мм", "mm"),
        NoDiagrams => ("Диаграммы по углу поворота не строятся, положения построены каждое отдельно: механизм не собирается при", "Діаграми за кутом повороту не будуються, положення побудовано кожне окремо: механізм не складається при", "No diagrams over the crank turn, each position built on its own: the mechanism cannot be assembled at"),
        NoDiagramsLeap => ("Диаграммы по углу поворота не строятся: звено поворачивается скачком около положения", "Діаграми за кутом повороту не будуються: ланка повертається стрибком біля положення", "No diagrams over the crank turn: a link turns by a leap near"),
        Continued => ("(продолжение)", "(продовження)", "(continued)"),
        ReadTo => ("Длины считаны с чертежа с точностью", "Довжини зчитано з креслення з точністю", "Lengths read off the drawing to"),
        ReadExactly => ("Построения точные (чертёж без погрешности отсчёта)", "Побудови точні (креслення без похибки відліку)", "Exact constructions (no reading error)"),
        ErrPlansAndChords => ("погрешность планов — только округление, диаграмм — метод хорд", "похибка планів — лише округлення, діаграм — метод хорд", "the plans err by rounding only, the diagrams by the chord method"),
        ErrPlans => ("погрешность планов — только округление", "похибка планів — лише округлення", "the plans err by rounding only"),
        ErrDiagrams => ("погрешность диаграмм — метод хорд", "похибка діаграм — метод хорд", "the diagrams err by the chord method"),
        ErrRounding => ("погрешность — только округление", "похибка — лише округлення", "they err by rounding only"),
        MeanError => ("δ ср., %", "δ сер., %", "δ mean, %"),
        MaxError => ("δ макс., %", "δ макс., %", "δ max, %"),
        ForceAnalysis => ("Силовой анализ", "Силовий аналіз", "Force analysis"),
        ActsOnWorkingOnly => ("{f} = 0: {f} действует только на рабочем ходу", "{f} = 0: {f} діє лише на робочому ході", "{f} = 0: {f} acts on the working stroke only"),
        ActsOnReturnOnly => ("{f} = 0: {f} действует только на холостом ходу", "{f} = 0: {f} діє лише на холостому ході", "{f} = 0: {f} acts on the return stroke only"),
        Position => ("положение", "положення", "position"),
        Group => ("Группа", "Група", "Group"),
        ForcePolygonOfGroup => ("План сил группы", "План сил групи", "Force polygon of group"),
        DrivingLink => ("Ведущее звено", "Ведуча ланка", "Driving link"),
        ForcePolygonOfDriver => ("План сил ведущего звена", "План сил ведучої ланки", "Force polygon of the driving link"),
        ZhukovskyLever => ("Рычаг Жуковского", "Важіль Жуковського", "Zhukovsky's lever"),
        LoadsAndReactions => ("Силы инерции и реакции в кинематических парах", "Сили інерції та реакції в кінематичних парах", "Inertia loads and reactions in the pairs"),
        Graphical => ("графически", "графічно", "graphical"),
        Analytic => ("аналитически", "аналітично", "analytic"),
        ByPolygon => ("по плану сил", "за планом сил", "by the force polygon"),
        ByLever => ("по рычагу Жуковского", "за важелем Жуковського", "by Zhukovsky's lever"),
        Difference => ("расхождение", "розбіжність", "difference"),
        ByIndicator => ("по индикаторной диаграмме p(θ)", "за індикаторною діаграмою p(θ)", "by the indicator diagram p(θ)"),
        ShaftResistance => ("момент сопротивления на валу", "момент опору на валу", "the shaft's resisting moment"),        RelativeError => ("δ, %", "δ, %", "δ, %"),
        Case => ("случай", "випадок", "case"),
        Data => ("Исходные данные", "Вихідні дані", "Data"),
        CrankCounterClockwise => ("против часовой стрелки", "проти годинникової стрілки", "counter-clockwise"),
        CrankClockwise => ("по часовой стрелке", "за годинниковою стрілкою", "clockwise"),
        Unit => ("ед.", "од.", "unit"),
        Number => ("№", "№", "No."),
        Exact => ("точно", "точно", "exact"),
        GraphicalAndAnalytic => (
            "Графическое решение и аналитический расчёт",
            "Графічний розв’язок і аналітичний розрахунок",
            "Graphical vs. analytical"
        ),
    }
}

catalogue! {
    /// The standard reasons for a redundant pair, which a scene names by key
    /// (`reason = "second_guide"`, [`REDUNDANT_REASONS`]).
    RedundantReason {
        SecondGuide => (
            "вторая направляющая ползуна, разгружающая его от изгиба",
            "друга напрямна повзуна, що розвантажує його від згину",
            "a second guide of the slider, relieving it of bending"
        ),
        SecondBearing => (
            "вторая опора вала, разгружающая его от изгиба",
            "друга опора вала, що розвантажує його від згину",
            "a second bearing of the shaft, relieving it of bending"
        ),
    }
}

/// The keys a scene names a standard reason by.
pub(crate) const REDUNDANT_REASONS: [(&str, RedundantReason); 2] = [
    ("second_guide", RedundantReason::SecondGuide),
    ("second_bearing", RedundantReason::SecondBearing),
];

/// A redundant pair's `reason` in `lang`: the catalogue's phrase for a standard key, any
/// other text printed as written.
pub(crate) fn redundant_reason(reason: &str, lang: crate::scale::Lang) -> &str {
    REDUNDANT_REASONS
        .iter()
        .find(|(key, _)| *key == reason)
        .map_or(reason, |(_, r)| r.get(lang))
}

/// A group's pair letters as the sheets of `lang` write them, from its Latin (`RRP`) and
/// Russian (`ВВП`: вращательная, поступательная) letters: `RRP` in English, `ВВП` in
/// Russian, `ООП` (обертальна, поступальна) in Ukrainian.
pub(crate) fn pair_letters(latin: &str, russian: &str, lang: crate::scale::Lang) -> String {
    match lang {
        crate::scale::Lang::En => latin.to_string(),
        crate::scale::Lang::Ru => russian.to_string(),
        crate::scale::Lang::Uk => russian.replace('В', "О"),
    }
}

/// A class-2 Assur group of `links`, of the kind numbered `number` with its pair letters in
/// `lang` (`letters`), in the words of the structural analysis:
/// «II(2,3): группа Ассура 2 класса 2 порядка вида 3 (ВПВ)».
pub(crate) fn assur_group(
    links: [u32; 2],
    (number, letters): (u32, &str),
    lang: crate::scale::Lang,
) -> String {
    let [i, j] = links;
    match lang {
        crate::scale::Lang::En => {
            format!("II({i},{j}): Assur group of class 2, order 2, type {number} ({letters})")
        }
        crate::scale::Lang::Ru => format!(
            "II({i},{j}): группа Ассура 2 класса 2 порядка {} {number} ({letters})",
            Text::OfKind.get(lang)
        ),
        crate::scale::Lang::Uk => format!(
            "II({i},{j}): група Ассура 2 класу 2 порядку {} {number} ({letters})",
            Text::OfKind.get(lang)
        ),
    }
}

/// The mechanism's class in the words of the structural analysis: «Механизм 2 класса».
pub(crate) fn mechanism_class(class: u32, lang: crate::scale::Lang) -> String {
    match lang {
        crate::scale::Lang::En => format!("The mechanism is of class {class}"),
        crate::scale::Lang::Ru => format!("Механизм {class} класса"),
        crate::scale::Lang::Uk => format!("Механізм {class} класу"),
    }
}

#[cfg(test)]
mod tests {
    use super::redundant_reason;
    use crate::scale::Lang;

    #[test]
    fn a_standard_reason_is_written_in_the_sheets_language_and_free_text_as_written() {
        assert_eq!(
            redundant_reason("second_guide", Lang::Uk),
            "друга напрямна повзуна, що розвантажує його від згину"
        );
        assert_eq!(
            redundant_reason("second_bearing", Lang::En),
            "a second bearing of the shaft, relieving it of bending"
        );
        assert_eq!(redundant_reason("своя причина", Lang::En), "своя причина");
    }

    /// The structural analysis's group and class lines in the three languages, the pair
    /// letters as each writes them (seed 000's II(2,3) of kind 3, ВПВ).
    #[test]
    fn a_group_and_the_class_read_in_each_language() {
        use super::{assur_group, mechanism_class, pair_letters};
        let line = |lang| assur_group([2, 3], (3, &pair_letters("RPR", "ВПВ", lang)), lang);
        assert_eq!(
            line(Lang::Ru),
            "II(2,3): группа Ассура 2 класса 2 порядка вида 3 (ВПВ)"
        );
        assert_eq!(
            line(Lang::Uk),
            "II(2,3): група Ассура 2 класу 2 порядку виду 3 (ОПО)"
        );
        assert_eq!(
            line(Lang::En),
            "II(2,3): Assur group of class 2, order 2, type 3 (RPR)"
        );
        assert_eq!(mechanism_class(2, Lang::Uk), "Механізм 2 класу");
        assert_eq!(mechanism_class(2, Lang::En), "The mechanism is of class 2");
    }
}
