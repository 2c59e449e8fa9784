//! The words of the machine sheets: the rotor, the machine's dynamics, gears, cams and
//! friction.

use super::catalogue;

catalogue! {
    /// A word of the rotor's sheet.
    RotorText {
        MomentsPolygon => ("План моментов m·ρ·z", "План моментів m·ρ·z", "Polygon of moments m·ρ·z"),
        StaticMomentsPolygon => (
            "План статических моментов m·ρ",
            "План статичних моментів m·ρ",
            "Polygon of static moments m·ρ"
        ),
        Complete => ("Полное уравновешивание ротора", "Повне зрівноваження ротора", "Complete balancing of a rotor"),
        Static => ("Статическое уравновешивание ротора", "Статичне зрівноваження ротора", "Static balancing of a rotor"),
        Rotor => ("Ротор", "Ротор", "Rotor"),
        AlongAxis => ("Вид вдоль оси", "Вид уздовж осі", "View along the axis"),
        Disc => ("Ротор (диск)", "Ротор (диск)", "Rotor (disc)"),
        CorrectingMasses => ("Уравновешивающие массы", "Зрівноважувальні маси", "Correcting masses"),
        After => ("после", "після", "after"),
        Before => ("до", "до", "before"),
    }
}

catalogue! {
    /// A word of the dynamics sheet.
    DynamicsText {
        EnergyMass => ("Диаграмма энергомасс ΔT(J_{пр})", "Діаграма енергомас ΔT(J_{пр})", "Energy–mass diagram ΔT(J_{пр})"),
        OmegaWithFlywheel => ("ω(φ) с маховиком", "ω(φ) з маховиком", "ω(φ) with the flywheel"),
        Flywheel => ("Маховик", "Маховик", "Flywheel"),
        Title => ("Динамика машины", "Динаміка машини", "Machine dynamics"),
        NoFlywheel => ("маховик не нужен", "маховик не потрібен", "no flywheel is needed"),
        Wittenbauer => ("Виттенбауэр", "Віттенбауер", "Wittenbauer"),
        Mertsalov => ("Мерцалов", "Мерцалов", "Mertsalov"),
        // A line of the dynamics sheet opens with the kind of flywheel sized.
        Rim => ("Обод", "Обід", "Rim"),
        Disc => ("Диск", "Диск", "Disc"),
        // The part drawing's technical requirements for a cast flywheel (ГОСТ 2.316: numbered
        // items above the title block, under no heading where the drawing gives no technical
        // characteristic); "\n" breaks a line, each under 35 characters, the column beside an
        // A3's views.
        CastRadii => (
            "1. Литейные радиусы R3…5 мм.",
            "1. Ливарні радіуси R3…5 мм.",
            "1. Casting radii R3…5 mm."
        ),
        Tolerances => (
            "2. Неуказанные предельные\nотклонения размеров: отверстий\nH14, валов h14, остальных ±IT14/2.",
            "2. Невказані граничні відхилення\nрозмірів: отворів H14, валів h14,\nінших ±IT14/2.",
            "2. Unspecified limit deviations:\nholes H14, shafts h14,\nothers ±IT14/2."
        ),
        BalanceStatically => (
            "3. Маховик балансировать\nстатически.",
            "3. Маховик балансувати статично.",
            "3. Balance the flywheel\nstatically."
        ),
        Exact => ("точно", "точно", "exact"),
        SizedFrom => (
            "Размеры — по J_{м} построения (диаграмма энергомасс):",
            "Розміри — за J_{м} побудови (діаграма енергомас):",
            "Sized from the construction's J_{м} (the energy–mass diagram):"
        ),
        SizedByConstruction => (
            "размеры — по J_{м} построения",
            "розміри — за J_{м} побудови",
            "sized from the construction's J_{м}"
        ),
        CastIron => ("серый чугун", "сірий чавун", "grey cast iron"),
        Steel => ("сталь", "сталь", "steel"),
        // The title block's material (ГОСТ 2.104 graph 3): the grades the course takes for
        // a flywheel (seed 000 L1452: grey cast iron for a rim under 25 m/s).
        CastIronGrade => ("СЧ 15 ГОСТ 1412–85", "СЧ 15 ГОСТ 1412–85", "SCh 15 GOST 1412–85"),
        SteelGrade => ("Сталь 35Л ГОСТ 977–88", "Сталь 35Л ГОСТ 977–88", "Cast steel 35L, GOST 977–88"),
        Material => ("Материал", "Матеріал", "Material"),
        // The flywheel's conclusion, a line each (a line of the sheet's data stays under
        // 55 characters, within the field beside an A3's title block).
        DeltaVerdict => (
            "Вывод: δ = {got} {rel} [δ] = {asked}.",
            "Висновок: δ = {got} {rel} [δ] = {asked}.",
            "Conclusion: δ = {got} {rel} [δ] = {asked}."
        ),
        DeltaMet => (
            "Маховик D = {d} {mm} обеспечивает [δ].",
            "Маховик D = {d} {mm} забезпечує [δ].",
            "The flywheel of D = {d} {mm} keeps [δ]."
        ),
        DeltaShort => (
            "J маховика на {pct} % меньше точного J_{м} (по {n} положениям);",
            "J маховика на {pct} % менший за точний J_{м} (за {n} положеннями);",
            "The flywheel's J is {pct} % under the exact J_{м} ({n} positions);"
        ),
        // The diameter a designer takes: the worked one rounded up.
        Taken => ("принимаем D = {d} {mm}", "приймаємо D = {d} {mm}", "adopted D = {d} {mm}"),
        DeltaNeeds => (
            "[δ] обеспечивает J_{м} ≥ {exact} {kgm2} (D ≥ {d} {mm}).",
            "[δ] забезпечує J_{м} ≥ {exact} {kgm2} (D ≥ {d} {mm}).",
            "[δ] needs J_{м} ≥ {exact} {kgm2} (D ≥ {d} {mm})."
        ),
        Dimensions => ("Размеры маховика", "Розміри маховика", "The flywheel's dimensions"),
        Dimension => ("Размер", "Розмір", "Dimension"),
        Rule => ("Формула", "Формула", "Formula"),
        Millimetres => ("мм", "мм", "mm"),
        SpokeSections => (
            "Сечения спицы у ступицы и у обода — эллипсы, b/a = {ratio}",
            "Перерізи спиці біля маточини і біля обода — еліпси, b/a = {ratio}",
            "The spoke's sections at the hub and at the rim are ellipses, b/a = {ratio}"
        ),
        Tables => (
            "{M}, J_{пр}, ΔT по положениям: графически и аналитически (*), их расхождение δ, %; δ_{ΔT} — относительно наибольшего ΔT*",
            "{M}, J_{пр}, ΔT за положеннями: графічно й аналітично (*), їх розбіжність δ, %; δ_{ΔT} — відносно найбільшого ΔT*",
            "{M}, J_{пр}, ΔT by position: graphical and analytic (*), their difference δ, %; δ_{ΔT} relative to the largest ΔT*"
        ),
        EngineResults => (
            "A_{д}, M_{с}, маховик: графически и точно",
            "A_{д}, M_{с}, маховик: графічно і точно",
            "A_{д}, M_{с}, flywheel: graphical vs. exact"
        ),
        MachineResults => (
            "Работа, момент движущих сил, маховик: графически и точно",
            "Робота, момент рушійних сил, маховик: графічно і точно",
            "Work, driving moment, flywheel: graphical vs. exact"
        ),
    }
}

catalogue! {
    /// A word of the gear sheet.
    GearText {
        DataAndResults => ("Исходные данные и результаты", "Вихідні дані та результати", "Data and results"),
        Meshing => ("Картина зацепления", "Картина зачеплення", "Meshing diagram"),
        Sliding => ("Удельное скольжение", "Питоме ковзання", "Specific sliding"),
        Along => ("вдоль", "уздовж", "along"),
        Blocking => ("Блокирующий контур", "Блокувальний контур", "Blocking contour"),
        Interference => ("интерференция", "інтерференція", "interference"),
        CutByRack => ("Нарезание рейкой:", "Нарізання рейкою:", "Cut by the rack:"),
        UndercutHatched => ("; подрез заштрихован", "; підріз заштриховано", "; the undercut hatched"),
        // Where the undercut is too fine to see at the picture's scale, its detail shows it.
        UndercutInDetail => (
            "; подрез заштрихован на выносном элементе {letter}",
            "; підріз заштриховано на виносному елементі {letter}",
            "; the undercut hatched in detail {letter}"
        ),
        Undercut => (", подрез", ", підріз", ", undercut"),
        PositionsDrawn => ("показаны {n}", "показано {n}", "{n} drawn"),
        Pointed => (", заострение", ", загострення", ", pointed"),
        Triangles => (
            "Треугольники скоростей и план угловых скоростей",
            "Трикутники швидкостей і план кутових швидкостей",
            "Velocity triangles and the plan of angular velocities"
        ),
        SlowLinks => (
            "Звенья {links} (ω_{{pivot}} с первого плана)",
            "Ланки {links} (ω_{{pivot}} з першого плану)",
            "Links {links} (ω_{{pivot}} from the first plan)"
        ),
        Willis => ("формула Виллиса", "формула Вілліса", "Willis"),
        ByTriangles => ("треугольники", "трикутники", "triangles"),
        Assembly => ("условие сборки", "умова складання", "assembly condition"),
        Holds => ("выполнено", "виконано", "holds"),
        Fails => ("не выполнено", "не виконано", "fails"),
        ForCoaxiality => ("по соосности", "за співвісністю", "for coaxiality"),
        ChoiceMargin => (
            "Точки выбора взяты на {m} внутри ограничений: ε_α ≥ {eps}, s_a ≥ {sa}m, x ≥ x_{min} + {m}",
            "Точки вибору взято на {m} всередині обмежень: ε_α ≥ {eps}, s_a ≥ {sa}m, x ≥ x_{min} + {m}",
            "The chosen points lie {m} inside the limits: ε_α ≥ {eps}, s_a ≥ {sa}m, x ≥ x_{min} + {m}"
        ),
        EpsDrawn => (
            "по чертежу: ε_α = B_1B_2/p_b = {ab}/{pb} = {eps}",
            "за кресленням: ε_α = B_1B_2/p_b = {ab}/{pb} = {eps}",
            "on the drawing: ε_α = B_1B_2/p_b = {ab}/{pb} = {eps}"
        ),
        ReadOff => (
            "Считано с чертежа и аналитический расчёт",
            "Зчитано з креслення і аналітичний розрахунок",
            "Read off the drawing vs. analytical"
        ),
        Computed => (
            "Вычислено, не считано с чертежа",
            "Обчислено, не знято з креслення",
            "Computed, not read off the drawing"
        ),
        ComputedValue => ("вычислено", "обчислено", "computed"),
        XMinRule => (
            "x_{min}: вычислено по (17 − z)/17 (1/17 ≈ sin²20°/2, округление), проверка — точное h_{a}* − z·sin²α/2",
            "x_{min}: обчислено за (17 − z)/17 (1/17 ≈ sin²20°/2, округлення), перевірка — точне h_{a}* − z·sin²α/2",
            "x_{min}: computed by (17 − z)/17 (1/17 ≈ sin²20°/2, rounded), check — the exact h_{a}* − z·sin²α/2"
        ),
        OtherRoute => ("проверка", "перевірка", "check"),
        ChosenBy => (
            "K: x_1, x_2 выбраны на блокирующем контуре по критерию:",
            "K: x_1, x_2 вибрано на блокувальному контурі за критерієм:",
            "K: x_1, x_2 chosen on the blocking contour by the criterion:"
        ),
        LargestContactRatio => ("наибольший ε_α", "найбільший ε_α", "the largest ε_α"),
        EqualSliding => ("равное скольжение λ_1(B_1) = λ_2(B_2) при x_1 + x_2 =", "рівне ковзання λ_1(B_1) = λ_2(B_2) при x_1 + x_2 =", "equal sliding λ_1(B_1) = λ_2(B_2) on x_1 + x_2 ="),
        GreatestSum => ("наибольшая сумма x_1 + x_2 при s_a ≥", "найбільша сума x_1 + x_2 при s_a ≥", "the greatest x_1 + x_2 with s_a ≥"),
        DetailInvolute => ("эвольвента", "евольвента", "involute"),
        DetailJunction => ("граничная точка", "гранична точка", "limit point"),
        DetailFillet => ("переходная кривая", "перехідна крива", "fillet"),
        DetailUndercut => ("подрез", "підріз", "undercut"),
        DetailRackTip => ("головка рейки", "головка рейки", "rack tip"),
        Title => ("Зубчатые передачи", "Зубчасті передачі", "Gears"),
    }
}

catalogue! {
    /// A word of the cam sheet.
    CamText {
        FlatCombined => (
            "Совмещённая диаграмма S(d^2S/dφ^2), касательная 45°",
            "Суміщена діаграма S(d^2S/dφ^2), дотична 45°",
            "Combined diagram S(d^2S/dφ^2), the 45° tangent"
        ),
        RockerCombined => (
            "Определение r_{min}: dS/dφ по коромыслу, лучи γ_{min}",
            "Визначення r_{min}: dS/dφ уздовж коромисла, промені γ_{min}",
            "r_{min}: dS/dφ along the rocker, the γ_{min} lines"
        ),
        TranslatingCombined => (
            "Совмещённая диаграмма S(dS/dφ), зона центра",
            "Суміщена діаграма S(dS/dφ), зона центру",
            "Combined diagram S(dS/dφ), the centre's zone"
        ),
        AccelerationAnalogue => ("Аналог ускорения d^2S/dφ^2", "Аналог прискорення d^2S/dφ^2", "Acceleration analogue d^2S/dφ^2"),
        VelocityAnalogue => ("Аналог скорости dS/dφ", "Аналог швидкості dS/dφ", "Velocity analogue dS/dφ"),
        Displacement => ("Перемещение S", "Переміщення S", "Displacement S"),
        Profile => ("Профиль кулачка (обращение движения)", "Профіль кулачка (обернення руху)", "Cam profile by inversion"),
        TransmissionAngle => ("Угол передачи γ(φ)", "Кут передачі γ(φ)", "Transmission angle γ(φ)"),
        PressureAngle => ("Угол давления λ(φ)", "Кут тиску λ(φ)", "Pressure angle λ(φ)"),
        Title => ("Синтез кулачкового механизма", "Синтез кулачкового механізму", "Cam mechanism synthesis"),
        Uniform => ("равномерный (жёсткие удары)", "рівномірний (жорсткі удари)", "uniform (rigid shocks)"),
        Ratio => ("доля разгона", "частка розгону", "ratio"),
        PlusMinus => ("«+ −»", "«+ −»", "constant acceleration “+ −”"),
        RiseIndex => ("у", "в", "rise"),
        ReturnIndex => ("п", "н", "ret"),
        Cosine => ("косинусоидальный", "косинусоїдальний", "cosine"),
        Sine => ("синусоидальный", "синусоїдальний", "sine (cycloidal)"),
        Trapezoidal => ("трапецеидальный", "трапецієподібний", "trapezoidal"),
        Polynomial => ("полином 3-4-5", "поліном 3-4-5", "3-4-5 polynomial"),
        LinearBlended => ("линейный со скруглениями", "лінійний із заокругленнями", "linear with blends"),
        Blend => ("доля скругления", "частка заокруглення", "blend"),
        PhaseRise => ("φ_{у}", "φ_{в}", "φ_{rise}"),
        PhaseFar => ("φ_{д.в.}", "φ_{д.в.}", "φ_{far}"),
        PhaseReturn => ("φ_{п}", "φ_{н}", "φ_{ret}"),
        PhaseNear => ("φ_{б.в.}", "φ_{б.в.}", "φ_{near}"),
        Accepted => (
            "Принимаем r_{0} = {r0} ≥ r_{min} = {rmin}",
            "Приймаємо r_{0} = {r0} ≥ r_{min} = {rmin}",
            "Adopted r_{0} = {r0} ≥ r_{min} = {rmin}"
        ),
        GivenUnder => (
            "r_{0} = {r0} (задано) < r_{min}: центр O_{1}′ в недопустимой зоне",
            "r_{0} = {r0} (задано) < r_{min}: центр O_{1}′ у недопустимій зоні",
            "r_{0} = {r0} (given) < r_{min}: the centre O_{1}′ lies in the inadmissible zone"
        ),
        Raised => (
            "При r_{0} = {r0} по профилю в точке {point} {angle}",
            "При r_{0} = {r0} за профілем у точці {point} {angle}",
            "At r_{0} = {r0} the profile reads {angle} at point {point}"
        ),
        TravelCombined => (
            "Определение X_{min}: совмещённая диаграмма S(dS/dφ), луч γ_{min}",
            "Визначення X_{min}: суміщена діаграма S(dS/dφ), промінь γ_{min}",
            "X_{min}: combined diagram S(dS/dφ), the γ_{min} line"
        ),
        Clockwise => ("Кулачок вращается по часовой стрелке", "Кулачок обертається за годинниковою стрілкою", "The cam turns clockwise"),
        CounterClockwise => (
            "Кулачок вращается против часовой стрелки",
            "Кулачок обертається проти годинникової стрілки",
            "The cam turns counter-clockwise"
        ),
        RiseLaw => ("закон удаления", "закон віддалення", "rise law"),
        ReturnLaw => ("приближения", "наближення", "return"),
        Given => ("задано", "задано", "given"),
        Undercut => ("ПОДРЕЗ: r_{р} >", "ПІДРІЗ: r_{р} >", "UNDERCUT: r_{р} >"),
        RollerCusp => ("ЗАОСТРЕНИЕ: r_{р} =", "ЗАГОСТРЕННЯ: r_{р} =", "CUSP: r_{р} ="),
        Cusp => (
            "ЗАОСТРЕНИЕ: ρ = r_{0} + S + S″ < 0, огибающая образует петлю",
            "ЗАГОСТРЕННЯ: ρ = r_{0} + S + S″ < 0, обвідна утворює петлю",
            "CUSP: ρ = r_{0} + S + S″ < 0, the envelope loops"
        ),
        RigidShocks => ("Жёсткие удары на границах фаз", "Жорсткі удари на межах фаз", "Rigid shocks at the phase ends"),
        // The angle's limit holds on the rise only under force closure (seed 002 L1463).
        ReturnUnlimited => (
            "На фазе приближения {angle} = {value}° {rel} {limit}°: допустимо — ведомое звено возвращает пружина (силовое замыкание)",
            "На фазі наближення {angle} = {value}° {rel} {limit}°: допустимо — ведену ланку повертає пружина (силове замикання)",
            "On the return {angle} = {value}° {rel} {limit}°: admitted — the spring returns the follower (force closure)"
        ),
        WrongSide => ("Смещение e с неблагоприятной стороны", "Зміщення e з несприятливого боку", "The offset e is on the unfavourable side"),
        Read => ("граф.", "граф.", "graph."),
        Points => ("Точки диаграмм и профиля", "Точки діаграм і профілю", "Points of the diagrams and the profile"),
        Results => ("Графически и точно, мм", "Графічно і точно, мм", "Graphical vs. exact, mm"),
        RadiusVector => ("R: радиус-вектор точки профиля", "R: радіус-вектор точки профілю", "R: the radius vector of a profile point"),
        TravelAt => ("ξ: положение оси толкателя на кулачке", "ξ: положення осі штовхача на кулачку", "ξ: where the follower's axis stands on the cam"),
        DeviationRule => (
            "Δ_{проф}: наибольшее отклонение профиля, проведённого лекалом, от точного",
            "Δ_{проф}: найбільше відхилення профілю, проведеного лекалом, від точного",
            "Δ_{prof}: the greatest deviation of the French-curve profile from the exact one"
        ),
        Slides => (
            "Кулачок движется поступательно вдоль направляющей",
            "Кулачок рухається поступально вздовж напрямної",
            "The cam slides along its guide"
        ),
        FlatRockerProfile => (
            "Профиль кулачка: тарелка коромысла в обращённом движении и огибающая",
            "Профіль кулачка: тарілка коромисла в оберненому русі й обвідна",
            "Cam profile: the rocker's flat face in the inverted motion and its envelope"
        ),
        SlidingProfile => (
            "Поступательно движущийся кулачок: положения толкателя, центровой и рабочий профили",
            "Кулачок, що рухається поступально: положення штовхача, центровий і робочий профілі",
            "Translating cam: the follower's positions, the pitch and working profiles"
        ),
        Concave => ("ВОГНУТОСТЬ: ρ_{min} <", "УГНУТІСТЬ: ρ_{min} <", "CONCAVE: ρ_{min} <"),
        Exceeded => ("ПРЕВЫШЕН λ_{max}: X < X_{min}", "ПЕРЕВИЩЕНО λ_{max}: X < X_{min}", "λ_{max} EXCEEDED: X < X_{min}"),
    }
}

catalogue! {
    /// A word of the friction sheet.
    FrictionText {
        Case => ("Случай", "Випадок", "Case"),
        Incline => ("наклонная плоскость", "похила площина", "inclined plane"),
        Up => ("подъём", "підйом", "up"),
        Down => ("спуск", "спуск", "down"),
        Wedge => ("клинчатый ползун, сечение", "клинчастий повзун, переріз", "V-groove slider, section"),
        Screw => ("развёртка резьбы", "розгортка різьби", "unrolled thread"),
        Journal => ("цапфа, круг трения", "цапфа, коло тертя", "journal, friction circle"),
        Rolling => ("груз на катках", "вантаж на котках", "load on rollers"),
        Slider => ("ползун на плоскости", "повзун на площині", "slider on a plane"),
        Guide => ("толкатель в направляющей", "штовхач у напрямній", "follower in its guide"),
        Pivot => ("коромысло в опоре, круг трения", "коромисло в опорі, коло тертя", "rocker in its pivot, friction circle"),
        Moves => ("движение возможно", "рух можливий", "the follower moves"),
        // The lecture's jamming angle (M_тр = P·f·d/2) beside the exact one: an approximation.
        Approximately => ("приближённо", "наближено", "approximately"),
        AtRest => ("ползун в покое", "повзун у спокої", "the slider stays at rest"),
        Uniform => ("равномерное движение", "рівномірний рух", "uniform motion"),
        Accelerating => ("движение с ускорением", "рух із прискоренням", "accelerated motion"),
        Triangle => ("план сил", "план сил", "force triangle"),
        Flanks => ("план сил: N_{1}, N_{2}; вид сбоку", "план сил: N_{1}, N_{2}; вид збоку", "forces: N_{1}, N_{2}; side view"),
        Balance => ("равновесие моментов", "рівновага моментів", "moment balance"),
        Sliding => ("без катков", "без котків", "without rollers"),
        SelfBraking => ("самоторможение", "самогальмування", "self-locking"),
        PureRolling => ("чистое качение", "чисте кочення", "pure rolling"),
        RollersSlide => ("катки скользят", "котки ковзають", "the rollers slide"),
        Title => ("Трение", "Тертя", "Friction"),
    }
}
