//! The construction protocol's sentences: each step of a recorded figure said as the lecture
//! says it while drawing (`{n}` a name, `{p}` a point, `{c}` a centre, `{r}`, `{l}` lengths
//! in drawing mm, `{v}` a value with its unit, `{k}` a count).

use super::catalogue;

catalogue! {
    /// A sentence of the construction protocol.
    StepText {
        Point => ("отмечаем точку {n}", "позначаємо точку {n}", "mark the point {n}"),
        FixedJoint => ("неподвижный шарнир {n}", "нерухомий шарнір {n}", "the fixed pivot {n}"),
        Joint => ("шарнир {n}", "шарнір {n}", "the joint {n}"),
        Link => ("проводим звено {n} = {l} мм", "проводимо ланку {n} = {l} мм", "draw the link {n} = {l} mm"),
        Line => ("проводим прямую {n}", "проводимо пряму {n}", "draw the line {n}"),
        Through => ("через {p} проводим прямую {n}", "через {p} проводимо пряму {n}", "through {p} draw the line {n}"),
        Perpendicular => ("через {p} проводим прямую ⊥ {n}", "через {p} проводимо пряму ⊥ {n}", "through {p} draw a line ⊥ {n}"),
        Parallel => ("через {p} проводим прямую ∥ {n}", "через {p} проводимо пряму ∥ {n}", "through {p} draw a line ∥ {n}"),
        Axis => ("проводим осевую линию {n}", "проводимо осьову лінію {n}", "draw the centre line {n}"),
        Arc => ("из точки {c} радиусом {r} мм проводим дугу", "з точки {c} радіусом {r} мм проводимо дугу", "from {c} draw an arc of radius {r} mm"),
        Circle => ("из точки {c} радиусом {r} мм проводим окружность {n}", "з точки {c} радіусом {r} мм проводимо коло {n}", "from {c} draw the circle {n} of radius {r} mm"),
        LayOff => ("откладываем {n} = {l} мм", "відкладаємо {n} = {l} мм", "lay off {n} = {l} mm"),
        LayOffValue => ("откладываем {n} = {v} / μ = {l} мм", "відкладаємо {n} = {v} / μ = {l} мм", "lay off {n} = {v} / μ = {l} mm"),
        Curve => ("по {k} точкам проводим кривую {n}", "за {k} точками проводимо криву {n}", "draw the curve {n} through {k} points"),
        Polyline => ("соединяем {k} точек ломаной {n}", "з’єднуємо {k} точок ламаною {n}", "join {k} points by the broken line {n}"),
        Slider => ("ползун {n}", "повзун {n}", "the slider {n}"),
        Guide => ("направляющая {n}", "напрямна {n}", "the guide {n}"),
        Dimension => ("проставляем размер {n}", "проставляємо розмір {n}", "dimension {n}"),
        Angle => ("отмечаем угол {n}", "позначаємо кут {n}", "mark the angle {n}"),
        Moment => ("показываем момент {n} дуговой стрелкой", "показуємо момент {n} дуговою стрілкою", "show the moment {n} by an arc arrow"),
        Text => ("надпись {n}", "напис {n}", "the note {n}"),
        Hatch => ("штрихуем {n}", "штрихуємо {n}", "hatch {n}"),
    }
}
