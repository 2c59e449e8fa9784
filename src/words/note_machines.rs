//! The note's sentences of the kinetostatics and the dynamics worked out (seed 000 §2, §5):
//! each `{…}` a place the note fills (a link, a point, a value).

use super::catalogue;

catalogue! {
    /// A sentence of the kinetostatics and dynamics sections of the note.
    MachinesNote {
        InertiaIntro => (
            "Определяем силы инерции звеньев F_{и} = m·a_{S} и моменты сил инерции M_{и} = J_{S}·ε по ускорениям, найденным из плана ускорений:",
            "Визначаємо сили інерції ланок F_{и} = m·a_{S} і моменти сил інерції M_{и} = J_{S}·ε за прискореннями, знайденими з плану прискорень:",
            "The links' inertia forces F_{и} = m·a_{S} and the moments of their inertia forces M_{и} = J_{S}·ε follow from the accelerations off the acceleration plan:"
        ),
        GasForces => (
            "Силы давления газов на поршни приложены по осям цилиндров к кривошипу; давление p — по индикаторной диаграмме при угле цикла θ цилиндра, отсчитанном от φ_{0} в сторону вращения кривошипа:",
            "Сили тиску газів на поршні прикладені вздовж осей циліндрів до кривошипа; тиск p — за індикаторною діаграмою при куті циклу θ циліндра, відліченому від φ_{0} у бік обертання кривошипа:",
            "The gas forces act on the pistons along the cylinders' axes towards the crank; the pressure p is read off the indicator diagram at the cylinder's cycle angle θ, counted from φ_{0} in the crank's sense of rotation:"
        ),
        InertiaApplied => (
            "Силы инерции приложены в центрах масс звеньев ({points}) и направлены противоположно ускорениям центров масс; моменты сил инерции направлены противоположно угловым ускорениям звеньев.",
            "Сили інерції прикладені в центрах мас ланок ({points}) і напрямлені протилежно прискоренням центрів мас; моменти сил інерції напрямлені протилежно кутовим прискоренням ланок.",
            "The inertia forces act at the links' centres of mass ({points}), against the centres' accelerations; the moments of the inertia forces act against the links' angular accelerations."
        ),
        GroupEquation => (
            "Группа {links}. Действие отброшенных звеньев и стойки заменяем реакциями; условие равновесия группы в векторной форме:",
            "Група {links}. Дію відкинутих ланок і стояка замінюємо реакціями; умова рівноваги групи у векторній формі:",
            "Group {links}. The links and the frame taken away are replaced by their reactions; the group's equilibrium in vector form:"
        ),
        DriverEquation => (
            "Ведущее звено {link}. Условие равновесия ведущего звена в векторной форме:",
            "Ведуча ланка {link}. Умова рівноваги ведучої ланки у векторній формі:",
            "The driving link {link}. Its equilibrium in vector form:"
        ),
        MomentsOfLink => (
            "Составляем уравнение моментов сил, действующих на звено {links}, относительно точки {point} (плечи сил измерены на чертеже):",
            "Складаємо рівняння моментів сил, що діють на ланку {links}, відносно точки {point} (плечі сил виміряні на кресленні):",
            "The moments of the forces on link {links} about point {point} (the arms measured on the drawing):"
        ),
        MomentsOfLinks => (
            "Составляем уравнение моментов сил, действующих на звенья {links}, относительно точки {point} (плечи сил измерены на чертеже):",
            "Складаємо рівняння моментів сил, що діють на ланки {links}, відносно точки {point} (плечі сил виміряні на кресленні):",
            "The moments of the forces on links {links} about point {point} (the arms measured on the drawing):"
        ),
        Whence => ("откуда", "звідки", "whence"),
        OppositeSign => (
            "Знак минус означает, что сила направлена противоположно принятому на чертеже направлению.",
            "Знак мінус означає, що сила напрямлена протилежно прийнятому на кресленні напрямку.",
            "The minus sign means that the force acts opposite to the sense assumed on the drawing."
        ),
        PolygonScale => (
            "Векторное уравнение решаем построением плана сил в масштабе μ_{F} = {mu} Н/мм: сила {force} = {value} Н изображается отрезком {mm} мм. Реакции, найденные из плана сил, приведены в таблице ниже.",
            "Векторне рівняння розв’язуємо побудовою плану сил у масштабі μ_{F} = {mu} Н/мм: сила {force} = {value} Н зображується відрізком {mm} мм. Реакції, знайдені з плану сил, наведено в таблиці нижче.",
            "The vector equation is solved by the force polygon at μ_{F} = {mu} N/mm: the force {force} = {value} N is drawn {mm} mm long. The reactions read off the polygon are in the table below."
        ),
        DriverMoments => (
            "Уравнение моментов сил, действующих на ведущее звено, относительно точки {point}:",
            "Рівняння моментів сил, що діють на ведучу ланку, відносно точки {point}:",
            "The moments of the forces on the driving link about point {point}:"
        ),
        LeverIntro => (
            "Определяем уравновешивающую силу с помощью рычага Жуковского. Повёрнутый на 90° план скоростей рассматриваем как жёсткий рычаг с опорой в полюсе p; все внешние силы, силы тяжести, силы инерции и уравновешивающую силу переносим параллельно самим себе в соответствующие точки плана, момент сил инерции заменяем парой сил. Уравнение моментов относительно полюса (плечи h в миллиметрах измерены на рычаге):",
            "Визначаємо зрівноважувальну силу за допомогою важеля Жуковського. Повернутий на 90° план швидкостей розглядаємо як жорсткий важіль з опорою в полюсі p; усі зовнішні сили, сили ваги, сили інерції і зрівноважувальну силу переносимо паралельно самим собі у відповідні точки плану, момент сил інерції замінюємо парою сил. Рівняння моментів відносно полюса (плечі h у міліметрах виміряні на важелі):",
            "The balancing force by Zhukovsky's lever: the velocity plan turned through 90° is taken as a rigid lever pivoted at the pole p; every external force, weight, inertia force and the balancing force is carried parallel to itself to the image of its point, an inertia moment is replaced by a couple. The moments about the pole (the arms h in millimetres measured on the lever):"
        ),
        LeverMoment => (
            "откуда уравновешивающий момент по рычагу Жуковского (μ_{v} — масштаб рычага):",
            "звідки зрівноважувальний момент за важелем Жуковського (μ_{v} — масштаб важеля):",
            "whence the balancing moment by Zhukovsky's lever (μ_{v} the lever's scale):"
        ),
        LeverCrankMoment => (
            "Уравновешивающая сила приложена в точке {pin} кривошипа перпендикулярно {centre}{pin} (на рычаге — в точке изображения перпендикулярно лучу из полюса, который и служит её плечом); уравновешивающий момент на кривошипе:",
            "Зрівноважувальна сила прикладена в точці {pin} кривошипа перпендикулярно до {centre}{pin} (на важелі — у точці зображення перпендикулярно до променя з полюса, який і є її плечем); зрівноважувальний момент на кривошипі:",
            "The balancing force acts at the crank's point {pin} at right angles to {centre}{pin} (on the lever at the image, at right angles to the ray from the pole, which is its arm); the balancing moment on the crank:"
        ),
        CompareForces => (
            "Расхождение уравновешивающей силы, найденной по плану сил ведущего звена и по рычагу Жуковского:",
            "Розбіжність зрівноважувальної сили, знайденої за планом сил ведучої ланки і за важелем Жуковського:",
            "The balancing force by the driving link's polygon against Zhukovsky's lever:"
        ),
        PowerPV => (
            "Необходимую мощность привода определяем по силе полезного сопротивления, скорости точки её приложения и КПД привода:",
            "Необхідну потужність приводу визначаємо за силою корисного опору, швидкістю точки її прикладання і ККД приводу:",
            "The drive's power needed, from the useful resistance, its point's speed and the drive's efficiency:"
        ),
        EnginePower => (
            "Мощность на валу двигателя в этом положении (момент сопротивления на валу равен уравновешивающему):",
            "Потужність на валу двигуна в цьому положенні (момент опору на валу дорівнює зрівноважувальному):",
            "The power on the engine's shaft at this position (the shaft's resisting moment is the balancing moment):"
        ),
        ReducedMoment => (
            "Приведённый момент сил определяем из равенства мгновенной мощности приведённого момента сумме мгновенных мощностей приводимых сил (силами трения пренебрегаем):",
            "Зведений момент сил визначаємо з рівності миттєвої потужності зведеного моменту сумі миттєвих потужностей сил, що зводяться (силами тертя нехтуємо):",
            "The reduced moment of the forces: its instantaneous power equals the sum of the powers of the forces reduced (friction neglected):"
        ),
        ForPosition => (
            "Для положения {position} по данным таблицы выше:",
            "Для положення {position} за даними таблиці вище:",
            "At position {position}, with the data of the table above:"
        ),
        ReducedInertia => (
            "Приведённый момент инерции определяем из равенства кинетической энергии звена приведения сумме кинетических энергий звеньев:",
            "Зведений момент інерції визначаємо з рівності кінетичної енергії ланки зведення сумі кінетичних енергій ланок:",
            "The reduced moment of inertia: the kinetic energy of the reduction link equals the sum of the links' kinetic energies:"
        ),
        LinksEnergy => (
            "Кинетическую энергию звеньев, приведённый момент инерции которых переменен, определяем по формуле",
            "Кінетичну енергію ланок, зведений момент інерції яких змінний, визначаємо за формулою",
            "The kinetic energy of the links whose reduced inertia varies:"
        ),
        LinksEnergySeed => (
            "В источнике T_{зв} = ω_{ср}²·J_{пр}/2 включает и постоянную часть J_{const}; постоянное слагаемое J_{const}·ω_{ср}²/2 не меняет размаха T_{зв} и на момент инерции маховика не влияет.",
            "У джерелі T_{зв} = ω_{ср}²·J_{пр}/2 включає і сталу частину J_{const}; стале доданок J_{const}·ω_{ср}²/2 не змінює розмаху T_{зв} і на момент інерції маховика не впливає.",
            "The textbook's T_{зв} = ω_{ср}²·J_{пр}/2 includes the constant part J_{const}; the constant term J_{const}·ω_{ср}²/2 leaves the range of T_{зв} unchanged and does not affect the flywheel."
        ),
        WorkScale => (
            "Диаграмму работ строим графическим интегрированием диаграммы моментов методом хорд с полюсным расстоянием H; масштаб диаграммы работ:",
            "Діаграму робіт будуємо графічним інтегруванням діаграми моментів методом хорд з полюсною відстанню H; масштаб діаграми робіт:",
            "The work diagram is the moment diagram integrated by chords with the pole distance H; its scale:"
        ),
        WittenbauerWorked => (
            "По диаграмме энергомасс (метод Виттенбауэра): касательные к диаграмме под углами ψ_{max} и ψ_{min} к оси J_{пр} отсекают на оси ΔT отрезок kl; момент инерции маховика",
            "За діаграмою енергомас (метод Віттенбауера): дотичні до діаграми під кутами ψ_{max} і ψ_{min} до осі J_{пр} відтинають на осі ΔT відрізок kl; момент інерції маховика",
            "By the energy–mass diagram (Wittenbauer's method): the tangents to the diagram at ψ_{max} and ψ_{min} to the J_{пр} axis cut off kl on the ΔT axis; the flywheel's moment of inertia"
        ),
        MertsalovWorked => (
            "По диаграмме T_{I} = ΔT − ω_{ср}²·J_{пр}/2 (метод Мерцалова): её наибольший размах ΔT_{I}; момент инерции маховика",
            "За діаграмою T_{I} = ΔT − ω_{ср}²·J_{пр}/2 (метод Мерцалова): її найбільший розмах ΔT_{I}; момент інерції маховика",
            "By the diagram T_{I} = ΔT − ω_{ср}²·J_{пр}/2 (Mertsalov's method): its largest range ΔT_{I}; the flywheel's moment of inertia"
        ),
        RimWheel => (
            "Маховик выполняем в виде обода со спицами и ступицей из {material} плотностью ρ = {rho} кг/м³; для такого маховика J = K_{j}·ρ·D⁵, m = K_{m}·ρ·D³ с коэффициентами K_{j} = {kj}, K_{m} = {km}. По моменту инерции, найденному построением (диаграмма энергомасс), J_{м} = {jm} кг·м² — он даёт δ = {delta}; точное решение уравнения движения даёт J_{м} = {exact} кг·м² при δ = {asked} (D = {exact_d} м) — находим наружный диаметр и массу маховика:",
            "Маховик виконуємо у вигляді обода зі спицями і маточиною з {material} густиною ρ = {rho} кг/м³; для такого маховика J = K_{j}·ρ·D⁵, m = K_{m}·ρ·D³ з коефіцієнтами K_{j} = {kj}, K_{m} = {km}. За моментом інерції, знайденим побудовою (діаграма енергомас), J_{м} = {jm} кг·м² — він дає δ = {delta}; точний розв’язок рівняння руху дає J_{м} = {exact} кг·м² при δ = {asked} (D = {exact_d} м) — знаходимо зовнішній діаметр і масу маховика:",
            "The flywheel is a rim with spokes and a hub of {material} of density ρ = {rho} kg/m³; for it J = K_{j}·ρ·D⁵ and m = K_{m}·ρ·D³ with K_{j} = {kj}, K_{m} = {km}. From the moment of inertia the construction gives (the energy–mass diagram), J_{м} = {jm} kg·m², which gives δ = {delta} (the exact solution of the equation of motion gives J_{м} = {exact} kg·m² at δ = {asked}, D = {exact_d} m), its outer diameter and mass:"
        ),
        DiscWheel => (
            "Маховик выполняем в виде диска шириной b = 0,2·D с отверстием под вал d_{1} = 0,2·D из {material} плотностью ρ = {rho} кг/м³; для него J = K_{j}·ρ·D⁵, m = K_{m}·ρ·D³ с коэффициентами K_{j} = {kj}, K_{m} = {km}. По моменту инерции, найденному построением (диаграмма энергомасс), J_{м} = {jm} кг·м² — он даёт δ = {delta}; точное решение уравнения движения даёт J_{м} = {exact} кг·м² при δ = {asked} (D = {exact_d} м) — находим наружный диаметр и массу маховика:",
            "Маховик виконуємо у вигляді диска шириною b = 0,2·D з отвором під вал d_{1} = 0,2·D з {material} густиною ρ = {rho} кг/м³; для нього J = K_{j}·ρ·D⁵, m = K_{m}·ρ·D³ з коефіцієнтами K_{j} = {kj}, K_{m} = {km}. За моментом інерції, знайденим побудовою (діаграма енергомас), J_{м} = {jm} кг·м² — він дає δ = {delta}; точний розв’язок рівняння руху дає J_{м} = {exact} кг·м² при δ = {asked} (D = {exact_d} м) — знаходимо зовнішній діаметр і масу маховика:",
            "The flywheel is a disc b = 0.2·D wide with a bore d_{1} = 0.2·D for the shaft, of {material} of density ρ = {rho} kg/m³; for it J = K_{j}·ρ·D⁵ and m = K_{m}·ρ·D³ with K_{j} = {kj}, K_{m} = {km}. From the moment of inertia the construction gives (the energy–mass diagram), J_{м} = {jm} kg·m², which gives δ = {delta} (the exact solution of the equation of motion gives J_{м} = {exact} kg·m² at δ = {asked}, D = {exact_d} m), its outer diameter and mass:"
        ),
        DriveMomentRead => (
            "Постоянный момент движущих сил находим по диаграмме моментов: луч из полюса, параллельный прямой работ движущих сил, отсекает на оси моментов ординату y_{д}:",
            "Сталий момент рушійних сил знаходимо за діаграмою моментів: промінь з полюса, паралельний прямій робіт рушійних сил, відтинає на осі моментів ординату y_{д}:",
            "The constant driving moment off the moment diagram: the ray from the pole parallel to the driving work's line cuts off the ordinate y_{д} on the moment axis:"
        ),
        EngineMomentRead => (
            "Постоянный момент сил сопротивления на валу двигателя находим по диаграмме моментов: луч из полюса, параллельный прямой работ сил сопротивления, отсекает на оси моментов ординату y_{с}:",
            "Сталий момент сил опору на валу двигуна знаходимо за діаграмою моментів: промінь з полюса, паралельний прямій робіт сил опору, відтинає на осі моментів ординату y_{с}:",
            "The constant resisting moment on the engine's shaft off the moment diagram: the ray from the pole parallel to the resisting work's line cuts off the ordinate y_{с} on the moment axis:"
        ),
        CastIron => ("чугуна", "чавуну", "cast iron"),
        Steel => ("стали", "сталі", "steel"),
        TakenDiameter => (
            "Наружный диаметр округляем вверх до {step} мм: принимаем D = {d} м; момент инерции маховика при нём:",
            "Зовнішній діаметр округлюємо вгору до {step} мм: приймаємо D = {d} м; момент інерції маховика при ньому:",
            "The outer diameter is rounded up to {step} mm: D = {d} m is taken; the flywheel's moment of inertia at it:"
        ),
        RimSpeed => ("Окружная скорость обода:", "Колова швидкість обода:", "The rim's peripheral speed:"),
        RimSpeedWithin => (
            "Окружная скорость обода не превышает допускаемой для {material} скорости [v] = {limit} м/с.",
            "Колова швидкість обода не перевищує допустимої для {material} швидкості [v] = {limit} м/с.",
            "The rim speed is within the speed allowed for {material}, [v] = {limit} m/s."
        ),
        RimSpeedBeyond => (
            "Окружная скорость обода превышает допускаемую для {material} скорость [v] = {limit} м/с: маховик следует выполнить из более прочного материала или установить на быстроходном валу.",
            "Колова швидкість обода перевищує допустиму для {material} швидкість [v] = {limit} м/с: маховик слід виконати з міцнішого матеріалу або встановити на швидкохідному валу.",
            "The rim speed is beyond the speed allowed for {material}, [v] = {limit} m/s: the flywheel is to be made of a stronger material or put on a faster shaft."
        ),
    }
}
