//! What the symbols of the note's formulas mean, for the «где» under a formula (ГОСТ 2.105):
//! the symbols of the structural analysis and of the gears' geometry. A section with symbols
//! of its own keeps their meanings in its own catalogue beside this one.

use super::catalogue;

catalogue! {
    /// The meaning of a symbol of a formula, as the «где» under it writes it.
    Meaning {
        Mobility => ("степень подвижности механизма", "ступінь рухомості механізму", "the mechanism's mobility"),
        MovingLinks => ("число подвижных звеньев", "кількість рухомих ланок", "the number of moving links"),
        LowerPairs => ("число кинематических пар пятого класса (низших)", "кількість кінематичних пар п'ятого класу (нижчих)", "the number of fifth-class (lower) pairs"),
        HigherPairs => ("число кинематических пар четвёртого класса (высших)", "кількість кінематичних пар четвертого класу (вищих)", "the number of fourth-class (higher) pairs"),
    }
}
