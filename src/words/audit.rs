//! The words of `tmm audit`: its verdicts and the headings of the marked-up table.

use super::catalogue;

catalogue! {
    /// A word of the audit of a student's table.
    AuditText {
        Title => ("Проверка таблицы студента", "Перевірка таблиці студента", "Student's table checked"),
        Audit => ("Проверка таблицы", "Перевірка таблиці", "Table checked"),
        Line => ("стр.", "рядок", "line"),
        Written => ("записано", "записано", "written"),
        Exact => ("точно", "точно", "exact"),
        Error => ("погр., %", "похибка, %", "error, %"),
        Verdict => ("оценка", "оцінка", "verdict"),
        Analytic => ("аналитический", "аналітичний", "analytic"),
        Right => ("верно", "вірно", "right"),
        Wrong => ("неверно", "невірно", "wrong"),
        Nearest => ("ближе всего", "найближче", "nearest"),
        Or => ("или", "або", "or"),
        Ambiguous => ("неоднозначно", "неоднозначно", "ambiguous"),
        Sign => ("знак", "знак", "sign"),
        Coarse => ("мало значащих цифр", "мало значущих цифр", "too few digits"),
        Truncated => ("цифры отброшены, не округлены", "цифри відкинуто, не округлено", "digits cut, not rounded"),
        Scale => ("масштаб", "масштаб", "scale"),
        InsteadOf => ("вместо", "замість", "for"),
        UnitSlip => ("единица: число в", "одиниця: число в", "unit: the number is in"),
        Transposed => ("переставлены цифры", "переставлено цифри", "digits swapped"),
        Dropped => ("пропущена цифра", "пропущено цифру", "a digit dropped"),
        Added => ("лишняя цифра", "зайва цифра", "a digit added"),
        OtherPosition => ("значение пол.", "значення пол.", "the value of pos."),
        OtherQuantity => ("значение", "значення", "the value of"),
        BaseRadius => ("r_b = r·cos α_w (верно r·cos α)", "r_b = r·cos α_w (вірно r·cos α)", "r_b = r·cos α_w (r·cos α is meant)"),
        ContactRatio => ("ε_α по шагу πm·cos α_w (верно πm·cos α)", "ε_α за кроком πm·cos α_w (вірно πm·cos α)", "ε_α over πm·cos α_w (πm·cos α is meant)"),
        NotInReport => ("нет в отчёте", "немає у звіті", "not in the report"),
        NoQuantity => ("нет такой величины в отчёте", "немає такої величини у звіті", "no such quantity in the report"),
        ReportHas => ("в отчёте", "у звіті", "the report has"),
        AtPositions => ("пол.", "пол.", "at pos."),
        ToleranceOf => ("допуск пол.", "допуск пол.", "tolerance of pos."),
        Signs => ("Знаки", "Знаки", "Signs"),
        SignedAsTextbook => (
            "значения со знаком, как в таблицах учебника: ω и ε положительны против часовой стрелки, скорость камня по кулисе V = dL/dt, скорость точки звена, вращающегося вокруг неподвижной оси, V = ω·r",
            "значення зі знаком, як у таблицях підручника: ω і ε додатні проти годинникової стрілки, швидкість каменя по кулісі V = dL/dt, швидкість точки ланки, що обертається навколо нерухомої осі, V = ω·r",
            "signed values, as the textbook's tables: ω and ε counter-clockwise positive, a slide's velocity V = dL/dt, the velocity of a point of a link turning about a fixed pivot V = ω·r"
        ),
        ReadAsMagnitudes => (
            "Модули (в столбце нет отрицательных чисел, а среди точных значений есть)",
            "Модулі (у стовпці немає від’ємних чисел, а серед точних значень є)",
            "Read as magnitudes (no value of the column written negative, though exact values are)"
        ),
        OppositeSense => (
            "Знак противоположен во всём столбце (направление вращения кривошипа принято обратным?)",
            "Знак протилежний у всьому стовпці (напрям обертання кривошипа прийнято зворотним?)",
            "The opposite sign throughout the column (the crank's sense of rotation taken the other way?)"
        ),
        NoSigns => (
            "в таблице нет знаков: сравниваются модули",
            "у таблиці немає знаків: порівнюються модулі",
            "the table has no signs: magnitudes are compared"
        ),
        MissingOmega => ("нет множителя ω_1 (производная по φ)", "немає множника ω_1 (похідна за φ)", "ω_1 missing (a derivative by φ)"),
    }
}
