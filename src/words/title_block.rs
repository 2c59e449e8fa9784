//! The captions of the title block (ГОСТ 2.104) on the sheets and the note's frames.

use super::catalogue;

catalogue! {
    /// A caption of the title block.
    TitleBlockText {
        Rev => ("Изм.", "Зм.", "Rev."),
        Sheet => ("Лист", "Арк.", "Sheet"),
        DocNo => ("№ докум.", "№ докум.", "Doc. No."),
        Sign => ("Подп.", "Підпис", "Sign."),
        Date => ("Дата", "Дата", "Date"),
        Drawn => ("Разраб.", "Розроб.", "Drawn"),
        Checked => ("Пров.", "Перев.", "Checked"),
        TechCheck => ("Т.контр.", "Т.контр.", "Tech. check"),
        StdCheck => ("Н.контр.", "Н.контр.", "Std. check"),
        Approved => ("Утв.", "Затв.", "Approved"),
        Letter => ("Лит.", "Літ.", "Letter"),
        Mass => ("Масса", "Маса", "Mass"),
        Scale => ("Масштаб", "Масштаб", "Scale"),
        // An English drawing numbers its sheets "Sheet 1 of 2".
        Sheets => ("Листов", "Аркушів", "of"),
    }
}
