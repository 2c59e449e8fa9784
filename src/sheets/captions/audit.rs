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
        MissingOmega => ("нет множителя ω_1 (производная по φ)", "немає множника ω_1 (похідна за φ)", "ω_1 missing (a derivative by φ)"),
    }
}
