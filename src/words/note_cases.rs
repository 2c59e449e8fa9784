//! The sentences of the lecture cases' short reports (seed 001's way of working a case:
//! what is found, the formula, the numbers, the result): the friction cases and the rotor's
//! balancing.

use super::catalogue;

catalogue! {
    /// A sentence of a lecture case's worked report.
    CaseText {
        FrictionIntro => (
            "Каждый случай строим планом сил (рисунки ниже) и проверяем расчётом по формулам лекций; значения по построению и по расчёту сведены в таблицу 1.",
            "Кожен випадок будуємо планом сил (рисунки нижче) і перевіряємо розрахунком за формулами лекцій; значення за побудовою і за розрахунком зведено в таблицю 1.",
            "Each case is constructed by a force plan (the figures below) and checked by the lectures' formulas; the values by construction and by calculation are in Table 1."
        ),
        FrictionAngle => (
            "Угол трения определяем по коэффициенту трения:",
            "Кут тертя визначаємо за коефіцієнтом тертя:",
            "The friction angle follows from the coefficient of friction:"
        ),
        InclineForce => (
            "Реакция плоскости R отклонена от нормали на угол трения против движения; из треугольника сил Q + P + R = 0 находим силу P, поддерживающую равномерное движение, и реакцию:",
            "Реакція площини R відхилена від нормалі на кут тертя проти руху; з трикутника сил Q + P + R = 0 знаходимо силу P, що підтримує рівномірний рух, і реакцію:",
            "The plane's reaction R leans from the normal by the friction angle against the motion; the force triangle Q + P + R = 0 gives the force P that keeps the motion uniform, and the reaction:"
        ),
        InclineIdeal => (
            "Ту же силу без трения и коэффициент полезного действия находим из треугольника с реакцией по нормали:",
            "Ту саму силу без тертя і коефіцієнт корисної дії знаходимо з трикутника з реакцією по нормалі:",
            "The same force without friction, from the triangle with the reaction along the normal, gives the efficiency:"
        ),
        SelfBraking => (
            "Угол наклона не больше угла трения: тело самоторможится и без силы P не опускается.",
            "Кут нахилу не більший за кут тертя: тіло самогальмується і без сили P не опускається.",
            "The slope is no steeper than the friction angle: the body brakes itself and does not descend without P."
        ),
        WedgeWorked => (
            "Нагрузка Q распределяется на две грани паза; сила трения на обеих гранях равна силе, толкающей ползун. Клинчатый ползун ведёт себя как плоский с приведённым коэффициентом трения:",
            "Навантаження Q розподіляється на дві грані паза; сила тертя на обох гранях дорівнює силі, що штовхає повзун. Клинчастий повзун поводиться як плоский зі зведеним коефіцієнтом тертя:",
            "The load Q is shared by the groove's two flanks; the friction on both is the force that pushes the slider. The V-slider acts as a flat one with a reduced coefficient of friction:"
        ),
        ScrewWorked => (
            "Элемент гайки рассматриваем как тело на развёртке резьбы — наклонной плоскости с углом подъёма λ; трение в треугольной резьбе учитываем приведённым коэффициентом:",
            "Елемент гайки розглядаємо як тіло на розгортці різьби — похилій площині з кутом підйому λ; тертя в трикутній різьбі враховуємо зведеним коефіцієнтом:",
            "An element of the nut is a body on the unrolled thread, an inclined plane of the lead angle λ; the friction in a triangular thread is taken with a reduced coefficient:"
        ),
        ScrewForce => (
            "Окружная сила на среднем радиусе резьбы, момент на гайке и коэффициент полезного действия:",
            "Колова сила на середньому радіусі різьби, момент на гайці і коефіцієнт корисної дії:",
            "The tangential force at the thread's mean radius, the moment on the nut and the efficiency:"
        ),
        SelfLocking => (
            "Угол подъёма не больше приведённого угла трения: резьба самотормозящая, нагрузка не отвинчивает гайку.",
            "Кут підйому не більший за зведений кут тертя: різьба самогальмівна, навантаження не відгвинчує гайку.",
            "The lead angle is no larger than the reduced friction angle: the thread locks itself, the load does not unscrew the nut."
        ),
        JournalWorked => (
            "Вал накатывается на подшипник до точки, где полная реакция, отклонённая от нормали на угол трения, уравновешивает нагрузку Q; линия реакции касается круга трения. Его радиус и момент трения в цапфе:",
            "Вал накочується на підшипник до точки, де повна реакція, відхилена від нормалі на кут тертя, врівноважує навантаження Q; лінія реакції дотикається до кола тертя. Його радіус і момент тертя в цапфі:",
            "The shaft rolls up its bearing until the total reaction, turned from the normal by the friction angle, balances the load Q; its line is tangent to the friction circle. The circle's radius and the friction moment:"
        ),
        RollingWorked => (
            "Нормальные реакции смещены вперёд на коэффициенты трения качения k₁ и k₂; из равенства моментов относительно точки касания катка с плоскостью находим силу, перекатывающую груз:",
            "Нормальні реакції зміщені вперед на коефіцієнти тертя кочення k₁ і k₂; з рівності моментів відносно точки дотику котка з площиною знаходимо силу, що перекочує вантаж:",
            "The normal reactions are shifted forward by the coefficients of rolling friction k₁ and k₂; the moments about a roller's contact with the plane give the force that rolls the load:"
        ),
        RollingPure => (
            "Качение чистое: отношения k₁/d и k₂/d меньше коэффициентов трения скольжения в тех же парах.",
            "Кочення чисте: відношення k₁/d і k₂/d менші за коефіцієнти тертя ковзання в тих самих парах.",
            "The rolling is pure: k₁/d and k₂/d are below the coefficients of sliding friction of the same contacts."
        ),
        RollingSlides => (
            "Качение не чистое: катки проскальзывают, и груз передвигается силой трения скольжения.",
            "Кочення не чисте: котки проковзують, і вантаж пересувається силою тертя ковзання.",
            "The rolling is not pure: the rollers slip and the load moves against sliding friction."
        ),
        RollingWithout => (
            "Без катков груз скользит по плоскости; сила во много раз больше:",
            "Без котків вантаж ковзає по площині; сила в багато разів більша:",
            "Without rollers the load slides on the plane, at a force many times larger:"
        ),
        SliderWorked => (
            "Силу P раскладываем на нормальную составляющую N и составляющую P₁ вдоль плоскости; состояние ползуна определяет положение линии силы P относительно конусов трения покоя и скольжения:",
            "Силу P розкладаємо на нормальну складову N і складову P₁ вздовж площини; стан повзуна визначає положення лінії сили P відносно конусів тертя спокою і ковзання:",
            "P is split into its normal component N and its component P₁ along the plane; the slider's state follows from the line of P against the cones of static and sliding friction:"
        ),
        SliderRest => (
            "Угол α меньше угла трения покоя: линия силы P проходит внутри конуса трения, и ползун остаётся в покое при любой величине силы P (ΔP < 0 — запас силы трения покоя).",
            "Кут α менший за кут тертя спокою: лінія сили P проходить усередині конуса тертя, і повзун залишається в спокої за будь-якої величини сили P (ΔP < 0 — запас сили тертя спокою).",
            "α is below the angle of static friction: the line of P lies inside the friction cone and the slider stays at rest whatever P is (ΔP < 0 is the static friction's reserve)."
        ),
        SliderUniform => (
            "Угол α равен углу трения: линия силы P лежит на образующей конуса трения, ползун движется равномерно.",
            "Кут α дорівнює куту тертя: лінія сили P лежить на твірній конуса тертя, повзун рухається рівномірно.",
            "α equals the friction angle: the line of P lies on the cone's generator and the slider moves uniformly."
        ),
        SliderAccelerates => (
            "Угол α больше угла трения: линия силы P выходит из конуса трения, ползун движется ускоренно под действием избытка ΔP.",
            "Кут α більший за кут тертя: лінія сили P виходить з конуса тертя, повзун рухається прискорено під дією надлишку ΔP.",
            "α exceeds the friction angle: the line of P leaves the friction cone and the excess ΔP accelerates the slider."
        ),
        RotorIntro => (
            "Ротор уравновешен, когда главный вектор сил инерции его масс равен нулю. Силы инерции масс:",
            "Ротор зрівноважений, коли головний вектор сил інерції його мас дорівнює нулю. Сили інерції мас:",
            "The rotor is balanced when the resultant of its masses' inertia forces is zero. The inertia forces of the masses:"
        ),
        RotorStatic => (
            "Условие статического уравновешивания — сумма статических моментов масс вместе с корректирующей равна нулю; план статических моментов (рисунок ниже) замыкает вектор корректирующей массы. Аналитически проекции суммы на оси:",
            "Умова статичного зрівноваження — сума статичних моментів мас разом із коригувальною дорівнює нулю; план статичних моментів (рисунок нижче) замикає вектор коригувальної маси. Аналітично проєкції суми на осі:",
            "The condition of static balance: the masses' static moments with the correcting one sum to zero; the plan of static moments (the figure below) closes with the correcting mass's vector. Analytically, the sum's projections:"
        ),
        RotorCorrection => (
            "Статический момент, масса и угол корректирующей массы:",
            "Статичний момент, маса і кут коригувальної маси:",
            "The correcting mass's static moment, mass and angle:"
        ),
        RotorDynamic => (
            "Для полного уравновешивания длинного ротора массу каждой плоскости переносим в плоскости коррекции I и II по правилу рычага: в плоскость II — доля z/L, в плоскость I — доля (L − z)/L. В каждой плоскости коррекции условие статического уравновешивания даёт свою корректирующую массу:",
            "Для повного зрівноваження довгого ротора масу кожної площини переносимо в площини корекції I і II за правилом важеля: у площину II — частку z/L, у площину I — частку (L − z)/L. У кожній площині корекції умова статичного зрівноваження дає свою коригувальну масу:",
            "For the complete balance of a long rotor each plane's mass is carried into the correction planes I and II by the lever rule: the share z/L into plane II, (L − z)/L into plane I. In each correction plane the static condition gives its correcting mass:"
        ),
    }
}
