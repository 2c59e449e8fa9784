//! The studio page's own words (`tmm serve`, `tmm render --format html`): its buttons,
//! headings and messages in the three languages. The page reads them by key
//! ([`STUDIO_KEYS`]).

use super::catalogue;

catalogue! {
    /// A word of the studio's page.
    StudioText {
        Gallery => ("Галерея", "Галерея", "Gallery"),
        Language => ("Язык", "Мова", "Language"),
        Drafting => ("Построение", "Побудова", "Drafting"),
        Hand => ("с точностью 0,5 мм", "з точністю 0,5 мм", "read to 0.5 mm"),
        Exact => ("точное", "точна", "exact"),
        Form => ("Форма", "Форма", "Form"),
        Text => ("Текст TOML", "Текст TOML", "TOML text"),
        Report => ("Графически и аналитически", "Графічно й аналітично", "Graphical and analytic"),
        From => ("Новый из этого", "Новий з цього", "New from this"),
        Quantity => ("величина", "величина", "quantity"),
        Graphical => ("графически", "графічно", "graphical"),
        Analytic => ("аналитически", "аналітично", "analytic"),
        Error => ("δ, %", "δ, %", "δ, %"),
        Drawing => ("Строится…", "Будується…", "Drawing…"),
        Drawn => ("Построено за", "Побудовано за", "Drawn in"),
        Ms => ("мс", "мс", "ms"),
        Kept => ("Показаны последние построенные листы", "Показано останні побудовані аркуші", "The last sheets drawn are shown"),
        Scene => ("Сцена", "Сцена", "Scene"),
        Note => ("Записка", "Записка", "Note"),
        Set => ("Листы PDF", "Аркуші PDF", "Sheets PDF"),
        Csv => ("Отчёт CSV", "Звіт CSV", "Report CSV"),
        Busy => ("Сервер занят", "Сервер зайнятий", "The server is busy"),
        Replay => ("Повтор построения:", "Повтор побудови:", "Replay:"),
        Whole => ("— весь лист —", "— весь аркуш —", "— the whole sheet —"),
        Project => ("Курсовой проект", "Курсовий проєкт", "Course project"),
        Linkages => ("Рычажные механизмы", "Важільні механізми", "Linkages"),
        Cams => ("Кулачковые механизмы", "Кулачкові механізми", "Cams"),
        Gears => ("Зубчатые зацепления", "Зубчасті зачеплення", "Gears"),
        Trains => ("Зубчатые передачи", "Зубчасті передачі", "Gear trains"),
        Friction => ("Трение", "Тертя", "Friction"),
        Balancing => ("Уравновешивание", "Зрівноваження", "Balancing"),
    }
}

/// Every word of the page with the key its script reads it by.
pub(crate) const STUDIO_KEYS: &[(&str, StudioText)] = &[
    ("gallery", StudioText::Gallery),
    ("language", StudioText::Language),
    ("drafting", StudioText::Drafting),
    ("hand", StudioText::Hand),
    ("exact", StudioText::Exact),
    ("form", StudioText::Form),
    ("text", StudioText::Text),
    ("report", StudioText::Report),
    ("from", StudioText::From),
    ("quantity", StudioText::Quantity),
    ("graphical", StudioText::Graphical),
    ("analytic", StudioText::Analytic),
    ("error", StudioText::Error),
    ("drawing", StudioText::Drawing),
    ("drawn", StudioText::Drawn),
    ("ms", StudioText::Ms),
    ("kept", StudioText::Kept),
    ("scene", StudioText::Scene),
    ("note", StudioText::Note),
    ("set", StudioText::Set),
    ("csv", StudioText::Csv),
    ("busy", StudioText::Busy),
    ("replay", StudioText::Replay),
    ("whole", StudioText::Whole),
];
