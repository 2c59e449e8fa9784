//! What the symbols of the note's formulas mean, for the «где» under a formula (ГОСТ 2.105):
//! the symbols of the structural analysis and of the gears' geometry. A section with symbols
//! of its own keeps their meanings in its own catalogue beside this one.

use super::catalogue;

catalogue! {
    /// The meaning of a symbol of a formula, as the «где» under it writes it.
    Meaning {
        Mobility => ("степень подвижности механизма", "ступінь рухомості механізму", "the mechanism's mobility"),
        MovingLinks => ("число подвижных звеньев", "кількість рухомих ланок", "the number of moving links"),
        LowerPairs => ("число кинематических пар пятого класса (низших)", "кількість кінематичних пар п’ятого класу (нижчих)", "the number of fifth-class (lower) pairs"),
        HigherPairs => ("число кинематических пар четвёртого класса (высших)", "кількість кінематичних пар четвертого класу (вищих)", "the number of fourth-class (higher) pairs"),
        EngagementAngle => ("угол зацепления", "кут зачеплення", "the operating pressure angle"),
        ShiftOfWheel => ("коэффициент смещения колеса", "коефіцієнт зміщення колеса", "the shift coefficient of wheel"),
        TeethOfWheel => ("число зубьев колеса", "кількість зубців колеса", "the number of teeth of wheel"),
        ProfileAngle => ("угол профиля исходного контура", "кут профілю вихідного контуру", "the pressure angle of the basic rack"),
        TakenUpShift => ("коэффициент воспринимаемого смещения", "коефіцієнт сприйманого зміщення", "the centre-distance modification coefficient"),
        EqualisingShift => ("коэффициент уравнительного смещения", "коефіцієнт зрівняльного зміщення", "the addendum reduction coefficient"),
        CentreDistance => ("межосевое расстояние", "міжосьова відстань", "the centre distance"),
        Module => ("модуль зацепления", "модуль зачеплення", "the module"),
        PitchRadius => ("радиус делительной окружности колеса", "радіус ділильного кола колеса", "the reference radius of wheel"),
        BaseRadius => ("радиус основной окружности колеса", "радіус основного кола колеса", "the base radius of wheel"),
        RollingRadius => ("радиус начальной окружности колеса", "радіус початкового кола колеса", "the operating pitch radius of wheel"),
        RootRadius => ("радиус окружности впадин колеса", "радіус кола западин колеса", "the root radius of wheel"),
        AddendumCoefficient => ("коэффициент высоты головки зуба", "коефіцієнт висоти головки зубця", "the addendum coefficient"),
        ClearanceCoefficient => ("коэффициент радиального зазора", "коефіцієнт радіального зазору", "the bottom clearance coefficient"),
        TipRadius => ("радиус окружности вершин колеса", "радіус кола вершин колеса", "the tip radius of wheel"),
        ToothHeight => ("высота зуба колеса", "висота зубця колеса", "the tooth depth of wheel"),
        PitchThickness => ("толщина зуба по делительной окружности колеса", "товщина зубця по ділильному колу колеса", "the tooth thickness on the reference circle of wheel"),
        TipAngle => ("угол профиля на окружности вершин колеса", "кут профілю на колі вершин колеса", "the profile angle at the tip circle of wheel"),
        TipThickness => ("толщина зуба по окружности вершин колеса", "товщина зубця по колу вершин колеса", "the tooth thickness on the tip circle of wheel"),
        Pitch => ("шаг по делительной окружности", "крок по ділильному колу", "the reference pitch"),
        BasePitch => ("основной шаг", "основний крок", "the base pitch"),
        ContactRatio => ("коэффициент торцового перекрытия по формуле", "коефіцієнт торцевого перекриття за формулою", "the transverse contact ratio by the formula"),
        ContactRatioDrawn => ("коэффициент торцового перекрытия по картине зацепления", "коефіцієнт торцевого перекриття за картиною зачеплення", "the transverse contact ratio off the meshing picture"),
        SlidingOfWheel => ("удельное скольжение профиля колеса", "питоме ковзання профілю колеса", "the specific sliding of the profile of wheel"),
        ContactDistance => ("расстояние точки контакта от точки N_{1}", "відстань точки контакту від точки N_{1}", "the contact point's distance from N_{1}"),
        LineOfAction => ("длина теоретической линии зацепления N_{1}N_{2}", "довжина теоретичної лінії зачеплення N_{1}N_{2}", "the length of the theoretical line of action N_{1}N_{2}"),
        ActiveLine => ("длина активной линии зацепления на чертеже", "довжина активної лінії зачеплення на кресленні", "the length of the active line of action on the drawing"),
    }
}
