//! What the symbols of the note's kinematics mean, for the «где» under a formula (ГОСТ
//! 2.105); a meaning ending in «точки» or «звена» is followed by the point's or link's name.

use super::catalogue;

catalogue! {
    /// The meaning of a symbol of the kinematics' formulas.
    KinematicsMeaning {
        LengthScale => ("масштаб длин", "масштаб довжин", "the length scale"),
        CrankLength => ("длина кривошипа", "довжина кривошипа", "the crank's length"),
        CrankDrawn => ("отрезок, изображающий кривошип на чертеже", "відрізок, що зображує кривошип на кресленні", "the crank's segment on the drawing"),
        CentreDistance => ("расстояние между неподвижными центрами", "відстань між нерухомими центрами", "the distance between the fixed centres"),
        LinkLength => ("длина звена", "довжина ланки", "a link's length"),
        Offset => ("расстояние от точки до направляющей", "відстань від точки до напрямної", "the guide's distance from the point"),
        PointDistance => ("расстояние точки звена от его шарнира", "відстань точки ланки від її шарніра", "a point's distance from a joint of its link"),
        Overlap => ("угол перекрытия (между положениями кривошипа в крайних положениях механизма)", "кут перекриття (між положеннями кривошипа в крайніх положеннях механізму)", "the angle between the crank's positions at the mechanism's extremes"),
        TimeRatio => ("коэффициент изменения средней скорости хода", "коефіцієнт зміни середньої швидкості ходу", "the time ratio of the strokes"),
        CrankSpeed => ("угловая скорость кривошипа", "кутова швидкість кривошипа", "the crank's angular velocity"),
        PointVelocity => ("скорость точки", "швидкість точки", "the velocity of point"),
        RelativeVelocity => ("относительно точки", "відносно точки", "relative to point"),
        PointAcceleration => ("ускорение точки", "прискорення точки", "the acceleration of point"),
        RelativeAcceleration => ("относительно точки", "відносно точки", "relative to point"),
        VelocityScale => ("масштаб плана скоростей", "масштаб плану швидкостей", "the velocity plan's scale"),
        AccelerationScale => ("масштаб плана ускорений", "масштаб плану прискорень", "the acceleration plan's scale"),
        VelocitySegment => ("отрезок плана скоростей, изображающий скорость точки", "відрізок плану швидкостей, що зображує швидкість точки", "the velocity plan's segment of the velocity of point"),
        AccelerationSegment => ("отрезок плана ускорений, изображающий ускорение точки", "відрізок плану прискорень, що зображує прискорення точки", "the acceleration plan's segment of the acceleration of point"),
        DrawnSegment => ("отрезок звена на плане положений", "відрізок ланки на плані положень", "the link's segment on the position diagram"),
        AngularVelocity => ("угловая скорость звена", "кутова швидкість ланки", "the angular velocity of link"),
        AngularAcceleration => ("угловое ускорение звена", "кутове прискорення ланки", "the angular acceleration of link"),
        LengthAt => ("расстояние в данном положении от точки", "відстань у даному положенні від точки", "the distance at this position from point"),
        ToPoint => ("до точки", "до точки", "to point"),
        Tangential => ("касательное ускорение в относительном вращательном движении", "дотичне прискорення у відносному обертальному русі", "the tangential acceleration of the relative rotation"),
        Normal => ("нормальное ускорение в относительном вращательном движении", "нормальне прискорення у відносному обертальному русі", "the normal acceleration of the relative rotation"),
        Coriolis => ("кориолисово ускорение", "коріолісове прискорення", "the Coriolis acceleration"),
        PhiScale => ("масштаб угла поворота кривошипа", "масштаб кута повороту кривошипа", "the crank angle's scale"),
        DiagramBase => ("длина оси абсцисс диаграммы (один оборот кривошипа)", "довжина осі абсцис діаграми (один оберт кривошипа)", "the diagram's abscissa for one turn of the crank"),
        DisplacementScale => ("масштаб диаграммы перемещений", "масштаб діаграми переміщень", "the displacement diagram's scale"),
        FirstScale => ("масштаб диаграммы аналога скорости", "масштаб діаграми аналога швидкості", "the scale of the velocity analogue's diagram"),
        SecondScale => ("масштаб диаграммы аналога ускорения", "масштаб діаграми аналога прискорення", "the scale of the acceleration analogue's diagram"),
        PoleFirst => ("полюсное расстояние при построении диаграммы аналога скорости", "полюсна відстань при побудові діаграми аналога швидкості", "the pole distance of the velocity analogue's construction"),
        PoleSecond => ("полюсное расстояние при построении диаграммы аналога ускорения", "полюсна відстань при побудові діаграми аналога прискорення", "the pole distance of the acceleration analogue's construction"),
        PointDisplacement => ("перемещение точки", "переміщення точки", "the displacement of point"),
        OffDiagram => ("по диаграмме", "за діаграмою", "off the diagram"),
        Ordinate => ("ордината диаграммы в данном положении", "ордината діаграми в даному положенні", "the diagram's ordinate at this position"),
        SlotLength => ("расстояние от центра вращения кулисы до камня", "відстань від центра обертання куліси до каменя", "the block's distance from the slotted link's pivot"),
        SlotAngle => ("угол поворота кулисы", "кут повороту куліси", "the slotted link's angle"),
        PivotX => ("абсцисса центра вращения кривошипа", "абсциса центра обертання кривошипа", "the abscissa of the crank's centre"),
        PivotY => ("ордината центра вращения кривошипа", "ордината центра обертання кривошипа", "the ordinate of the crank's centre"),
        CrankAngle => ("угол поворота кривошипа", "кут повороту кривошипа", "the crank's angle"),
        SlotSpeed => ("угловая скорость кулисы", "кутова швидкість куліси", "the slotted link's angular velocity"),
        SlideSpeed => ("скорость камня относительно кулисы", "швидкість каменя відносно куліси", "the block's velocity along the slot"),
        SlotAcceleration => ("угловое ускорение кулисы", "кутове прискорення куліси", "the slotted link's angular acceleration"),
    }
}
