//! The words of the explanatory note: its headings, its sentences and its tables' captions.

use super::catalogue;

catalogue! {
    /// A heading, sentence or caption of the explanatory note.
    NoteText {
        ExplanatoryNote => ("Пояснительная записка", "Пояснювальна записка", "Explanatory note"),
        ToTheCourseProject => (
            "к курсовому проекту по теории механизмов и машин",
            "до курсового проєкту з теорії механізмів і машин",
            "to the course project in the theory of mechanisms and machines"
        ),
        NoteCode => ("ПЗ", "ПЗ", "EN"),
        FigureWord => ("Рисунок", "Рисунок", "Figure"),
        TableWord => ("Таблица", "Таблиця", "Table"),
        TableContinued => ("Продолжение таблицы", "Продовження таблиці", "Continuation of Table"),
        Where => ("где", "де", "where"),
        // What joins a symbol to its meaning after «где»: ГОСТ 2.105's dash; English says "is".
        Is => ("—", "—", "is"),
        Student => ("Выполнил студент", "Виконав студент", "Student"),
        OfGroup => ("группы", "групи", "group"),
        Supervisor => ("Руководитель", "Керівник", "Supervisor"),
        Contents => ("Содержание", "Зміст", "Contents"),
        SheetNo => ("лист", "аркуш", "sheet"),
        Task => ("Задание", "Завдання", "The task"),
        MechanismData => ("Исходные данные механизма", "Вихідні дані механізму", "The mechanism's data"),
        ForcesData => ("Массы звеньев и силы сопротивления", "Маси ланок і сили опору", "The links' masses and the resistances"),
        GearsData => ("Исходные данные зубчатых механизмов", "Вихідні дані зубчастих механізмів", "The gears' data"),
        PairPart => ("Зубчатая пара", "Зубчаста пара", "The gear pair"),
        RackCutPart => ("Колесо, нарезаемое рейкой", "Колесо, що нарізається рейкою", "The wheel cut by the rack"),
        TrainPart => ("Планетарный редуктор", "Планетарний редуктор", "The planetary train"),
        DifferentialPart => ("Дифференциальный механизм", "Диференціальний механізм", "The differential"),
        Value => ("значение", "значення", "value"),
        StructureAndKinematics => (
            "Структурный и кинематический анализ механизма",
            "Структурний і кінематичний аналіз механізму",
            "Structural and kinematic analysis of the mechanism"
        ),
        MobilityChebyshev => (
            "Степень подвижности механизма определяем по формуле Чебышева;",
            "Ступінь рухомості механізму визначаємо за формулою Чебишева;",
            "The mobility of the mechanism by Chebyshev's formula;"
        ),
        WithRedundantPairs => (
            "С избыточными (пассивными) парами",
            "З надлишковими (пасивними) парами",
            "With the redundant (passive) pairs"
        ),
        RedundantPairExplained => (
            "Избыточная пара повторяет связь, уже наложенную другой парой, и на движение механизма не влияет; при структурном анализе она не учитывается.",
            "Надлишкова пара повторює зв’язок, уже накладений іншою парою, і на рух механізму не впливає; при структурному аналізі вона не враховується.",
            "A redundant pair repeats a constraint another pair imposes already and does not affect the motion; the structural analysis leaves it out."
        ),
        AssurGroups => (
            "Механизм раскладываем на ведущее звено и структурные группы Ассура (таблица ниже); степень подвижности каждой группы равна нулю.",
            "Механізм розкладаємо на ведучу ланку і структурні групи Ассура (таблиця нижче); ступінь рухомості кожної групи дорівнює нулю.",
            "The mechanism is split into the driving link and Assur groups (the table below); each group's mobility is zero."
        ),
        GroupsTable => ("Структурные группы механизма", "Структурні групи механізму", "The mechanism's structural groups"),
        KindWord => ("вид", "вид", "type"),
        Pairs => ("кинематические пары (звенья, тип)", "кінематичні пари (ланки, тип)", "kinematic pairs (links, type)"),
        GroupMobility => ("подвижность", "рухомість", "mobility"),
        Prismatic => ("поступательная", "поступальна", "prismatic"),
        Revolute => ("вращательная", "обертальна", "revolute"),
        ClassOfMechanism => ("механизм класса", "механізм класу", "a mechanism of class"),
        LengthScale => (
            "Масштаб длин выбираем по длине кривошипа на чертеже:",
            "Масштаб довжин вибираємо за довжиною кривошипа на кресленні:",
            "The length scale from the crank's length on the drawing:"
        ),
        MetreUnit => ("м", "м", "m"),
        MmUnit => ("мм", "мм", "mm"),
        PositionsConstruction => (
            "План положений строим методом засечек: окружность кривошипа делим на равные части от начала рабочего хода, для каждого положения кривошипа точки групп находим пересечением дуг, описанных циркулем радиусами звеньев, или дуги с направляющей. Крайние положения выходного звена находим построением.",
            "План положень будуємо методом засічок: коло кривошипа ділимо на рівні частини від початку робочого ходу, для кожного положення кривошипа точки груп знаходимо перетином дуг, описаних циркулем радіусами ланок, або дуги з напрямною. Крайні положення вихідної ланки знаходимо побудовою.",
            "The position diagram by compass arcs: the crank's circle divided into equal parts from the start of the working stroke; for each crank position the groups' points where the arcs of the links' lengths meet each other or a guide. The output's extreme positions by construction."
        ),
        StrokeIs => ("Ход (размах) выходного звена между крайними положениями:", "Хід (розмах) вихідної ланки між крайніми положеннями:", "The stroke (swing) of the output between its extremes:"),
        AlongGuideOf => ("направляющей звена", "напрямній ланки", "the guide of link"),
        VelocityPlans => ("Планы скоростей", "Плани швидкостей", "Velocity plans"),
        CrankPinVelocity => ("Скорость пальца кривошипа:", "Швидкість пальця кривошипа:", "The velocity of the crank pin:"),
        VelocityScale => ("Масштаб плана скоростей:", "Масштаб плану швидкостей:", "The velocity plan's scale:"),
        VectorEquations => (
            "Для каждой структурной группы составляем два векторных уравнения; известные векторы известны по величине и направлению, у неизвестных известны только линии действия:",
            "Для кожної структурної групи складаємо два векторні рівняння; відомі вектори відомі за величиною і напрямом, у невідомих відомі лише лінії дії:",
            "Each structural group gives two vector equations; the known vectors are known in magnitude and direction, the unknown ones by their lines only:"
        ),
        WorkedVelocities => ("Скорости, измеренные на плане скоростей в положении", "Швидкості, виміряні на плані швидкостей у положенні", "The velocities measured on the velocity plan at position"),
        VelocityErrors => ("Расхождение скоростей с аналитическим расчётом", "Розбіжність швидкостей з аналітичним розрахунком", "The velocities' difference from the analytic solution"),
        AngularVelocityErrors => ("Расхождение угловых скоростей с аналитическим расчётом", "Розбіжність кутових швидкостей з аналітичним розрахунком", "The angular velocities' difference from the analytic solution"),
        AccelerationErrors => ("Расхождение ускорений с аналитическим расчётом", "Розбіжність прискорень з аналітичним розрахунком", "The accelerations' difference from the analytic solution"),
        AngularAccelerationErrors => ("Расхождение угловых ускорений с аналитическим расчётом", "Розбіжність кутових прискорень з аналітичним розрахунком", "The angular accelerations' difference from the analytic solution"),
        DiagramErrors => ("Расхождение значений по диаграммам с аналитическим расчётом", "Розбіжність значень за діаграмами з аналітичним розрахунком", "The diagrams' difference from the analytic solution"),
        DiagramAll => ("Величины, найденные по диаграммам", "Величини, знайдені за діаграмами", "The quantities read off the diagrams"),
        AngularVelocitiesTable => ("Угловые скорости звеньев", "Кутові швидкості ланок", "Angular velocities of the links"),
        VelocityPlanWord => ("План скоростей", "План швидкостей", "Velocity plan"),
        VerdictIntro => (
            "Сравнивая направления угловых скоростей и угловых ускорений звеньев, определяем характер их движения: при совпадающих направлениях звено вращается ускоренно, при противоположных — замедленно.",
            "Порівнюючи напрямки кутових швидкостей і кутових прискорень ланок, визначаємо характер їхнього руху: за однакових напрямків ланка обертається прискорено, за протилежних — сповільнено.",
            "Comparing the senses of the links' angular velocities and angular accelerations: a link whose ε turns with its ω accelerates, one whose ε opposes it decelerates."
        ),
        AccelerationPlans => ("Планы ускорений", "Плани прискорень", "Acceleration plans"),
        CrankPinAcceleration => ("Ускорение пальца кривошипа (ω₁ = const):", "Прискорення пальця кривошипа (ω₁ = const):", "The acceleration of the crank pin (ω₁ = const):"),
        AccelerationScale => ("Масштаб плана ускорений:", "Масштаб плану прискорень:", "The acceleration plan's scale:"),
        AccelerationEquations => (
            "Векторные уравнения ускорений групп (относительное ускорение во вращательном движении — нормальная и касательная составляющие, в поступательном — кориолисово и релятивное):",
            "Векторні рівняння прискорень груп (відносне прискорення в обертальному русі — нормальна і дотична складові, у поступальному — коріолісове і релятивне):",
            "The groups' acceleration equations (a relative acceleration in rotation: normal and tangential parts; along a slide: Coriolis and relative parts):"
        ),
        CoriolisWorked => ("Кориолисово ускорение в положении", "Коріолісове прискорення в положенні", "The Coriolis acceleration at position"),
        WorkedAccelerations => ("Ускорения, измеренные на плане ускорений в положении", "Прискорення, виміряні на плані прискорень у положенні", "The accelerations measured on the acceleration plan at position"),
        AccelerationsTable => ("Ускорения точек по планам ускорений", "Прискорення точок за планами прискорень", "Accelerations of the points by the acceleration plans"),
        AngularAccelerationsTable => ("Угловые ускорения звеньев", "Кутові прискорення ланок", "Angular accelerations of the links"),
        KinematicDiagrams => ("Кинематические диаграммы", "Кінематичні діаграми", "Kinematic diagrams"),
        ChordMethod => (
            "Диаграмму перемещений строим по плану положений; диаграммы аналогов скорости и ускорения получаем графическим дифференцированием методом хорд с полюсными расстояниями H₁ и H₂. Масштабы производных:",
            "Діаграму переміщень будуємо за планом положень; діаграми аналогів швидкості і прискорення отримуємо графічним диференціюванням методом хорд з полюсними відстанями H₁ і H₂. Масштаби похідних:",
            "The displacement diagram from the position diagram; the analogues of velocity and acceleration by graphical differentiation (the method of chords) with the pole distances H₁ and H₂. The scales of the derivatives:"
        ),
        AtPositions => ("В положении", "У положенні", "At position"),
        CornerOfS => (
            "звенья группы ложатся на одну прямую, и механизм переходит на другую ветвь: диаграмма перемещений имеет здесь излом. Каждую её ветвь дифференцируем отдельно, и производные в этом положении имеют по два значения — в конце одной ветви и в начале другой.",
            "ланки групи лягають на одну пряму, і механізм переходить на іншу гілку: діаграма переміщень має тут злам. Кожну її гілку диференціюємо окремо, і похідні в цьому положенні мають по два значення — в кінці однієї гілки і на початку іншої.",
            "the group's links fall into one line and the mechanism passes onto its other branch: the displacement diagram has a corner there. Each branch is differentiated on its own, and the derivatives have two values at that position, at the end of one branch and at the start of the other."
        ),
        DiagramValues => (
            "Скорость и ускорение: V = ω₁·(dS/dφ), a = ω₁²·(d²S/dφ²); значения в положениях механизма — в таблице.",
            "Швидкість і прискорення: V = ω₁·(dS/dφ), a = ω₁²·(d²S/dφ²); значення в положеннях механізму — у таблиці.",
            "The velocity and acceleration: V = ω₁·(dS/dφ), a = ω₁²·(d²S/dφ²); the values at the positions in the table."
        ),
        DiagramTable => ("Перемещение, скорость и ускорение по диаграммам", "Переміщення, швидкість і прискорення за діаграмами", "Displacement, velocity and acceleration by the diagrams"),
        Hodograph => ("Годограф скорости", "Годограф швидкості", "The velocity hodograph"),
        HodographText => (
            "Векторы скорости точки из планов скоростей переносим параллельно к общему полюсу; их концы соединяем плавной кривой — годографом скорости.",
            "Вектори швидкості точки з планів швидкостей переносимо паралельно до спільного полюса; їх кінці з’єднуємо плавною кривою — годографом швидкості.",
            "The point's velocity vectors from the velocity plans carried parallel to one pole; their ends joined by a smooth curve, the hodograph."
        ),
        HodographTable => ("Отрезки годографа скорости", "Відрізки годографа швидкості", "The hodograph's rays"),
        AnalyticMethod => ("Аналитический метод", "Аналітичний метод", "The analytic method"),
        AnalyticText => (
            "Положения, скорости и ускорения найдены аналитически из уравнений замкнутых векторных контуров; по ним проверены графические построения.",
            "Положення, швидкості і прискорення знайдено аналітично з рівнянь замкнених векторних контурів; за ними перевірено графічні побудови.",
            "The positions, velocities and accelerations are found analytically from the equations of the closed vector loops; the graphical constructions are checked against them."
        ),
        AnalyticTable => ("Аналитический расчёт", "Аналітичний розрахунок", "The analytic solution"),
        Kinetostatics => ("Кинетостатический анализ механизма", "Кінетостатичний аналіз механізму", "Kinetostatic analysis of the mechanism"),
        KinetostaticsIntro => (
            "Силовой расчёт выполняем методом кинетостатики: к внешним силам прикладываем силы и моменты сил инерции; группы Ассура рассматриваем, начиная с последней присоединённой, реакции находим из уравнений моментов и планов сил; уравновешивающий момент находим по ведущему звену и по рычагу Жуковского.",
            "Силовий розрахунок виконуємо методом кінетостатики: до зовнішніх сил прикладаємо сили і моменти сил інерції; групи Ассура розглядаємо, починаючи з останньої приєднаної, реакції знаходимо з рівнянь моментів і планів сил; зрівноважувальний момент знаходимо за ведучою ланкою і за важелем Жуковського.",
            "The force analysis by kinetostatics: the inertia forces and moments are added to the external loads; the Assur groups are taken from the last attached, their reactions from the moment equations and the force polygons; the balancing moment from the driving link and by Zhukovsky's lever."
        ),
        LoadsAtPosition => ("Силовой расчёт в положении", "Силовий розрахунок у положенні", "The force analysis at position"),
        ReactionsTable => ("Реакции и уравновешивающая сила, положение", "Реакції і зрівноважувальна сила, положення", "Reactions and the balancing load, position"),
        BalancingBothRoutes => (
            "Уравновешивающий момент по плану сил ведущего звена и по рычагу Жуковского; расхождение:",
            "Зрівноважувальний момент за планом сил ведучої ланки і за важелем Жуковського; розбіжність:",
            "The balancing moment by the driving link's polygon and by Zhukovsky's lever; their difference:"
        ),
        PolygonShort => ("пл", "пл", "pol"),
        LeverShort => ("Ж", "Ж", "Zh"),
        MotorPower => (
            "Мощность двигателя с учётом КПД привода η:",
            "Потужність двигуна з урахуванням ККД приводу η:",
            "The motor's power with the drive's efficiency η:"
        ),
        DrivePower => ("Мощность привода:", "Потужність приводу:", "The drive's power:"),
        Dynamics => ("Динамика машины", "Динаміка машини", "Machine dynamics"),
        DynamicsIntro => (
            "Силы и массы приводим к валу кривошипа: приведённый момент сил сопротивления M_пр и приведённый момент инерции J_пр — по планам скоростей в каждом положении. Графическим интегрированием диаграммы M_пр строим диаграмму работ сил сопротивления; работу движущих сил за цикл принимаем равной ей; разность работ даёт изменение кинетической энергии ΔT.",
            "Сили і маси зводимо до вала кривошипа: зведений момент сил опору M_пр і зведений момент інерції J_пр — за планами швидкостей у кожному положенні. Графічним інтегруванням діаграми M_пр будуємо діаграму робіт сил опору; роботу рушійних сил за цикл приймаємо рівною їй; різниця робіт дає зміну кінетичної енергії ΔT.",
            "The forces and masses reduced to the crank shaft: the reduced resisting moment M_red and the reduced moment of inertia J_red from the velocity plans at each position. Integrating the M_red diagram graphically gives the work of the resisting forces; the driving work over the cycle equals it; their difference is the change of kinetic energy ΔT."
        ),
        ReductionInput => ("Исходные данные для приведения сил и масс (аналитически)", "Вихідні дані для зведення сил і мас (аналітично)", "The input of the reduction of forces and masses (analytic)"),
        ReducedMoments => ("Приведённые моменты сил", "Зведені моменти сил", "Reduced moments of the forces"),
        ReducedInertias => ("Приведённые моменты инерции по звеньям и кинетическая энергия звеньев", "Зведені моменти інерції за ланками і кінетична енергія ланок", "Reduced moments of inertia by links and the links' kinetic energy"),
        ConstantInertia => ("Постоянная часть приведённого момента инерции (редуктор, коробка скоростей):", "Стала частина зведеного моменту інерції (редуктор, коробка швидкостей):", "The constant part of the reduced moment of inertia (reducer, gearbox):"),
        EnergyTable => ("Изменение кинетической энергии", "Зміна кінетичної енергії", "Change of kinetic energy"),
        FlywheelSize => ("Размеры маховика:", "Розміри маховика:", "The flywheel's size:"),
        FlywheelRoutes => (
            "Момент инерции маховика находим по диаграмме энергомасс (Виттенбауэр: касательные под углами ψ_max, ψ_min отсекают отрезок kl), по диаграмме T_I (Мерцалов) и точным интегрированием уравнения движения:",
            "Момент інерції маховика знаходимо за діаграмою енергомас (Віттенбауер: дотичні під кутами ψ_max, ψ_min відтинають відрізок kl), за діаграмою T_I (Мерцалов) і точним інтегруванням рівняння руху:",
            "The flywheel's moment of inertia by the energy–mass diagram (Wittenbauer: the tangents at ψ_max, ψ_min cut off kl), by the T_I diagram (Mertsalov) and by integrating the equation of motion exactly:"
        ),
        FlywheelTable => ("Работы, момент инерции маховика и коэффициент неравномерности", "Роботи, момент інерції маховика і коефіцієнт нерівномірності", "Works, the flywheel's moment of inertia and the coefficient of irregularity"),
        ExactFlywheel => ("Момент инерции маховика по точному решению:", "Момент інерції маховика за точним розв’язком:", "The flywheel's moment of inertia by the exact solution:"),
        CamSection => ("Синтез кулачкового механизма", "Синтез кулачкового механізму", "Design of the cam mechanism"),
        CamIntro => (
            "По заданному закону движения толкателя строим диаграмму аналога ускорения, графическим интегрированием — аналога скорости и перемещения; по совмещённой диаграмме с лучами под допустимым углом передачи (давления) находим минимальный радиус кулачка; профиль строим методом обращения движения.",
            "За заданим законом руху штовхача будуємо діаграму аналога прискорення, графічним інтегруванням — аналога швидкості і переміщення; за суміщеною діаграмою з променями під допустимим кутом передачі (тиску) знаходимо мінімальний радіус кулачка; профіль будуємо методом обернення руху.",
            "From the follower's law: the diagram of the acceleration analogue, by graphical integration those of the velocity analogue and the displacement; the least base radius from the combined diagram with the rays at the admissible transmission (pressure) angle; the profile by inversion."
        ),
        CamIntroDifferentiated => (
            "По заданному закону движения толкателя строим диаграмму перемещений, графическим дифференцированием (методом хорд) — аналога скорости и аналога ускорения; по совмещённой диаграмме с лучами под допустимым углом передачи (давления) находим минимальный радиус кулачка; профиль строим методом обращения движения.",
            "За заданим законом руху штовхача будуємо діаграму переміщень, графічним диференціюванням (методом хорд) — аналога швидкості і аналога прискорення; за суміщеною діаграмою з променями під допустимим кутом передачі (тиску) знаходимо мінімальний радіус кулачка; профіль будуємо методом обернення руху.",
            "From the follower's law: the displacement diagram, by graphical differentiation (chords) those of the velocity and the acceleration analogues; the least base radius from the combined diagram with the rays at the admissible transmission (pressure) angle; the profile by inversion."
        ),
        CamLawAssumed => (
            "Диаграммы закона движения в источнике утеряны; закон движения толкателя принят, как указано в исходных данных.",
            "Діаграми закону руху в джерелі втрачено; закон руху штовхача прийнято, як зазначено у вихідних даних.",
            "The textbook's diagrams of the law are lost; the follower's law is assumed as the data state it."
        ),
        CamFlatRockerIntro => (
            "Коромысло с плоской тарелкой: по заданному закону качания коромысла строим диаграмму аналога ускорения, графическим интегрированием — аналога скорости и перемещения (дуги S = L·β); профиль строим методом обращения движения: центр качания O₂ поворачиваем вокруг O₁ на −φ, проводим тарелку под углом ψ = ψ₀ + β на расстоянии e от O₂, профиль — огибающая этих прямых; точку касания находим как середину между точками пересечения соседних прямых, радиус кривизны — по расстоянию между ними.",
            "Коромисло з плоскою тарілкою: за заданим законом гойдання коромисла будуємо діаграму аналога прискорення, графічним інтегруванням — аналога швидкості і переміщення (дуги S = L·β); профіль будуємо методом обернення руху: центр гойдання O₂ повертаємо навколо O₁ на −φ, проводимо тарілку під кутом ψ = ψ₀ + β на відстані e від O₂, профіль — обвідна цих прямих; точку дотику знаходимо як середину між точками перетину сусідніх прямих, радіус кривини — за відстанню між ними.",
            "A rocker with a flat face: from the rocker's law, the diagram of the acceleration analogue, by graphical integration those of the velocity analogue and the displacement (the arcs S = L·β); the profile by inversion: the pivot O₂ turned about O₁ by −φ, the face drawn at ψ = ψ₀ + β at the distance e from O₂, the profile the envelope of these lines; the contact is the middle of the crossings with the neighbouring lines, the radius of curvature follows from their distance."
        ),
        CamSlidingIntro => (
            "Кулачок движется поступательно вдоль направляющей и поднимает роликовый толкатель, движущийся перпендикулярно ей. По заданному закону строим диаграммы аналогов графическим интегрированием; цикл закона 2π откладываем вдоль хода кулачка X (ξ = X·φ/2π). Профиль строим обращением движения: ось толкателя в каждом положении, центр ролика на высоте S, окружности ролика, рабочий профиль — их огибающая; угол давления читаем по нормали к хорде через соседние центры.",
            "Кулачок рухається поступально вздовж напрямної і піднімає роликовий штовхач, що рухається перпендикулярно до неї. За заданим законом будуємо діаграми аналогів графічним інтегруванням; цикл закону 2π відкладаємо вздовж ходу кулачка X (ξ = X·φ/2π). Профіль будуємо оберненням руху: вісь штовхача в кожному положенні, центр ролика на висоті S, кола ролика, робочий профіль — їхня обвідна; кут тиску читаємо за нормаллю до хорди через сусідні центри.",
            "The cam slides along its guide and lifts a roller follower moving across it. From the law, the analogues' diagrams by graphical integration; the law's cycle 2π laid along the cam's travel X (ξ = X·φ/2π). The profile by inversion: the follower's axis at every position, the roller's centre at the height S, the roller circles, the working profile their envelope; the pressure angle read off the normal to the chord through the neighbouring centres."
        ),
        CamFlatRockerStart => (
            "На ближнем выстое тарелка касается начальной окружности r₀; её начальный угол:",
            "На ближньому вистої тарілка дотикається до початкового кола r₀; її початковий кут:",
            "On the near dwell the face touches the base circle r₀; its starting angle:"
        ),
        CamFlatRockerCurvature => (
            "Радиус кривизны профиля (h — расстояние тарелки от O₁, α — угол её нормали в обращённом движении) должен оставаться положительным и не меньше заданного ρ_min:",
            "Радіус кривини профілю (h — відстань тарілки від O₁, α — кут її нормалі в оберненому русі) має лишатися додатним і не меншим за заданий ρ_min:",
            "The profile's radius of curvature (h the face's distance from O₁, α its normal's angle in the inverted motion) must stay positive and at least the ρ_min asked:"
        ),
        CamOnTheBoard => ("по чертежу", "за кресленням", "on the drawing"),
        CamSlidingAngle => (
            "Толкатель движется перпендикулярно направляющей, поэтому угол давления — наклон центрового профиля; наименьший ход кулачка, при котором λ ≤ λ_max:",
            "Штовхач рухається перпендикулярно до напрямної, тому кут тиску — нахил центрового профілю; найменший хід кулачка, за якого λ ≤ λ_max:",
            "The follower moves across the guide, so the pressure angle is the pitch curve's slope; the shortest travel keeping λ ≤ λ_max:"
        ),
        CamSlidingRoller => (
            "Радиус ролика должен быть меньше наименьшего радиуса кривизны выпуклых участков центрового профиля, иначе рабочий профиль подрезается:",
            "Радіус ролика має бути меншим за найменший радіус кривини опуклих ділянок центрового профілю, інакше робочий профіль підрізається:",
            "The roller must be smaller than the least radius of curvature of the pitch curve's convex stretches, else the working profile is undercut:"
        ),
        CamSpecialScene => ("Наименьший размер, радиус кривизны и точность профиля", "Найменший розмір, радіус кривини і точність профілю", "The smallest size, the radius of curvature and the profile's accuracy"),
        CamPeaks => (
            "Наибольшие значения аналогов скорости и ускорения толкателя на фазах:",
            "Найбільші значення аналогів швидкості і прискорення штовхача на фазах:",
            "The largest values of the follower's velocity and acceleration analogues on the phases:"
        ),
        CamScalesWorked => (
            "Масштабы диаграмм: ось абсцисс — один оборот кулачка; масштабы аналогов следуют из масштаба перемещений через полюсные расстояния:",
            "Масштаби діаграм: вісь абсцис — один оберт кулачка; масштаби аналогів випливають з масштабу переміщень через полюсні відстані:",
            "The diagrams' scales: the abscissa spans one turn of the cam; the analogues' scales follow from the displacement scale through the pole distances:"
        ),
        CamNoAccelerationPole => (
            "Внутри фаз закон задаёт d²S/dφ² = 0 (жёсткие удары — только на границах фаз): интегрировать нечего, диаграмма dS/dφ каждой фазы — прямая, параллельная оси φ, на высоте, равной ходу толкателя, делённому на угол фазы; полюс P₁ не нужен и масштаб μ_S″ не выбирается.",
            "Усередині фаз закон задає d²S/dφ² = 0 (жорсткі удари — лише на межах фаз): інтегрувати нічого, діаграма dS/dφ кожної фази — пряма, паралельна осі φ, на висоті, що дорівнює ходу штовхача, поділеному на кут фази; полюс P₁ не потрібен і масштаб μ_S″ не обирається.",
            "Within the phases the law gives d²S/dφ² = 0 (rigid shocks only at the phases' ends): there is nothing to integrate, each phase's dS/dφ is a line parallel to the φ axis at the follower's stroke divided by the phase angle, so no pole P₁ is needed and no scale μ_S″ is chosen."
        ),
        CamRadiusWorked => (
            "Минимальный радиус кулачка — расстояние от центра O₁, выбранного в зоне допустимых центров совмещённой диаграммы, до начальной точки B₀, в масштабе диаграммы:",
            "Мінімальний радіус кулачка — відстань від центра O₁, обраного в зоні допустимих центрів суміщеної діаграми, до початкової точки B₀, у масштабі діаграми:",
            "The least base radius: the distance from the centre O₁, chosen in the zone of admissible centres of the combined diagram, to the initial point B₀, at the diagram's scale:"
        ),
        CamRollerWorked => (
            "Радиус ролика — не больше 0,4 минимального радиуса и 0,8 наименьшего радиуса кривизны центрового профиля (иначе профиль заостряется или подрезается):",
            "Радіус ролика — не більше 0,4 мінімального радіуса і 0,8 найменшого радіуса кривини центрового профілю (інакше профіль загострюється або підрізається):",
            "The roller's radius: at most 0.4 of the base radius and 0.8 of the pitch curve's least radius of curvature (else the profile comes to a point or is undercut):"
        ),
        CamTable => ("Перемещение, аналоги, углы и радиус-вектор профиля по положениям", "Переміщення, аналоги, кути і радіус-вектор профілю за положеннями", "Displacement, analogues, angles and the profile's radius vector by positions"),
        CamTableNoAngles => ("Перемещение, аналоги и радиус-вектор профиля по положениям", "Переміщення, аналоги і радіус-вектор профілю за положеннями", "Displacement, analogues and the profile's radius vector by positions"),
        TransmissionTable => ("Углы передачи в точках профиля", "Кути передачі в точках профілю", "The transmission angles at the profile's points"),
        PressureTable => ("Углы давления в точках профиля", "Кути тиску в точках профілю", "The pressure angles at the profile's points"),
        OnDrawing => ("по чертежу", "за кресленням", "drawn"),
        ExactShort => ("точно", "точно", "exact"),
        Allowed => ("допускается", "допускається", "allowed:"),
        Holds => ("выполнено", "виконано", "holds"),
        Fails => ("нарушено", "порушено", "fails"),
        WorstKeeps => (
            "Экстремальный угол на всём цикле, включая участки между точками, не выходит за допустимый:",
            "Екстремальний кут на всьому циклі, включно з ділянками між точками, не виходить за допустимий:",
            "The extreme angle over the whole cycle, between the points as well, keeps the limit:"
        ),
        WorstKeepsRise => (
            "Экстремальный угол на фазе удаления, включая участки между точками, не выходит за допустимый:",
            "Екстремальний кут на фазі віддалення, включно з ділянками між точками, не виходить за допустимий:",
            "The extreme angle over the rise, between the points as well, keeps the limit:"
        ),
        WorstBreaksRise => (
            "Между расчётными точками угол выходит за допустимый: центр кулачка выбран по минимальному радиусу, считанному с совмещённой диаграммы в расчётных точках, и на фазе удаления экстремальный угол равен",
            "Між розрахунковими точками кут виходить за допустимий: центр кулачка вибрано за мінімальним радіусом, зчитаним із суміщеної діаграми в розрахункових точках, і на фазі віддалення екстремальний кут дорівнює",
            "Between the points the angle passes the limit: the cam's centre is chosen by the least radius read off the combined diagram at the points, and over the rise the extreme angle is"
        ),
        ForceClosureUnchecked => (
            "Прочерк в графе допустимости: при силовом замыкании угол ограничивают только на фазе удаления, на фазе возвращения толкатель ведёт замыкающая пружина.",
            "Прочерк у графі допустимості: при силовому замиканні кут обмежують лише на фазі віддалення, на фазі повернення штовхач веде замикальна пружина.",
            "A dash in the limit's column: under force closure the angle is limited on the rise only; on the return the closing spring drives the follower."
        ),
        WorstBreaks => (
            "Между расчётными точками угол выходит за допустимый: центр кулачка выбран по минимальному радиусу, считанному с совмещённой диаграммы в расчётных точках, и на всём цикле экстремальный угол равен",
            "Між розрахунковими точками кут виходить за допустимий: центр кулачка вибрано за мінімальним радіусом, зчитаним із суміщеної діаграми в розрахункових точках, і на всьому циклі екстремальний кут дорівнює",
            "Between the points the angle passes the limit: the cam's centre is chosen by the least radius read off the combined diagram at the points, and over the whole cycle the extreme angle is"
        ),
        CamScene => ("Минимальный радиус, ролик и точность профиля", "Мінімальний радіус, ролик і точність профілю", "The least radius, the roller and the profile's accuracy"),
        GearsSection => ("Зубчатые механизмы", "Зубчасті механізми", "Gear mechanisms"),
        GearsIntroPair => (
            "Геометрия эвольвентного зацепления со смещением рассчитана по формулам и проверена по картине зацепления; коэффициент перекрытия — по формуле и по чертежу (отношение B₁B₂ к основному шагу).",
            "Геометрію евольвентного зачеплення зі зміщенням розраховано за формулами і перевірено за картиною зачеплення; коефіцієнт перекриття — за формулою і за кресленням (відношення B₁B₂ до основного кроку).",
            "The geometry of the shifted involute pair by the formulas, checked on the meshing diagram; the contact ratio by formula and off the drawing (B₁B₂ over the base pitch)."
        ),
        GearsIntroRack => (
            "Зубья нарезаны рейкой по огибающей её положений.",
            "Зуби нарізано рейкою за обвідною її положень.",
            "The teeth cut by the rack as the envelope of its positions."
        ),
        GearsIntroTrain => (
            "Передаточное отношение планетарного редуктора — по формуле Виллиса и графически по треугольникам скоростей.",
            "Передаточне відношення планетарного редуктора — за формулою Вілліса і графічно за трикутниками швидкостей.",
            "The planetary train's ratio by Willis's formula and graphically by the velocity triangles."
        ),
        GearsIntroDifferential => (
            "Частота вращения выходного звена дифференциала по двум заданным входным — по формуле Виллиса и графически по треугольникам скоростей.",
            "Частота обертання вихідної ланки диференціала за двома заданими вхідними — за формулою Вілліса і графічно за трикутниками швидкостей.",
            "The differential's output speed from its two given inputs by Willis's formula and graphically by the velocity triangles."
        ),
        PairWorked => (
            "Геометрический расчёт зацепления (размеры в мм):",
            "Геометричний розрахунок зачеплення (розміри в мм):",
            "The geometry of the pair (lengths in mm):"
        ),
        WheelWord => ("Колесо", "Колесо", "Wheel"),
        TableShift => (
            "Коэффициент уравнительного смещения принят по таблицам: Δy = {dy} (по формуле Δy = x_{1} + x_{2} − y = {exact}); радиусы вершин считаем с ним.",
            "Коефіцієнт зрівняльного зміщення взято за таблицями: Δy = {dy} (за формулою Δy = x_{1} + x_{2} − y = {exact}); радіуси вершин рахуємо з ним.",
            "The equalising shift is taken from the tables: Δy = {dy} (by the formula Δy = x_{1} + x_{2} − y = {exact}); the tip radii are worked with it."
        ),
        ContactRatioWorked => (
            "Коэффициент перекрытия по формуле:",
            "Коефіцієнт перекриття за формулою:",
            "The contact ratio by the formula:"
        ),
        ContactRatioPicture => (
            "и по картине зацепления — активная линия зацепления B₁B₂, измеренная на чертеже, к шагу по основной окружности:",
            "і за картиною зачеплення — активна лінія зачеплення B₁B₂, виміряна на кресленні, до кроку по основному колу:",
            "and off the meshing diagram: the active line of action B₁B₂ measured on the drawing over the base pitch:"
        ),
        PairTable => ("Геометрия зубчатой передачи", "Геометрія зубчастої передачі", "The gear pair's geometry"),
        SlidingTable => ("Удельное скольжение", "Питоме ковзання", "Specific sliding"),
        SlidingAtPoints => (
            "Удельное скольжение в точках линии зацепления",
            "Питоме ковзання в точках лінії зачеплення",
            "Specific sliding at the points of the line of action"
        ),
        SlidingWorked => (
            "Удельное скольжение профилей в точках линии зацепления находим по формулам",
            "Питоме ковзання профілів у точках лінії зачеплення знаходимо за формулами",
            "The specific sliding of the profiles at the points of the line of action is found by the formulas"
        ),
        PointOfLine => ("Точка", "Точка", "Point"),
        FormulaColumn => ("формула", "формула", "formula"),
        ByFormula => ("по формуле", "за формулою", "by formula"),
        OnTheDrawing => ("по чертежу", "за кресленням", "on the drawing"),
        ByEnvelope => ("по огибающей (точно)", "за обвідною (точно)", "by the envelope (exact)"),
        ZeroWheelForm => (
            "нулевое колесо (форма отчёта ПЗ1, таблица 1.1)",
            "нульове колесо (форма звіту ПЗ1, таблиця 1.1)",
            "the zero wheel (report form of practical work 1, Table 1.1)"
        ),
        ShiftedWheelForm => (
            "колесо со смещением (форма отчёта ПЗ1, таблица 1.2)",
            "колесо зі зміщенням (форма звіту ПЗ1, таблиця 1.2)",
            "the shifted wheel (report form of practical work 1, Table 1.2)"
        ),
        UndercutThins => (
            "Зуб подрезан: на основной окружности его толщина по чертежу и по точной огибающей меньше, чем по формуле неподрезанной эвольвенты S_b.",
            "Зуб підрізано: на основному колі його товщина за кресленням і за точною обвідною менша, ніж за формулою непідрізаної евольвенти S_b.",
            "The tooth is undercut: on the base circle its thickness on the drawing and by the exact envelope is less than the uncut involute's formula S_b gives."
        ),
        FilletAboveBase => (
            "Эвольвента начинается выше основной окружности: у основной окружности зуб очерчен переходной кривой, и его толщина там больше, чем по формуле эвольвенты S_b.",
            "Евольвента починається вище основного кола: біля основного кола зуб окреслено перехідною кривою, і його товщина там більша, ніж за формулою евольвенти S_b.",
            "The involute starts above the base circle: there the tooth is bounded by the fillet and is thicker than the involute's formula S_b gives."
        ),
        RackTable => ("Нарезание колеса рейкой", "Нарізання колеса рейкою", "The wheel cut by the rack"),
        TrainClosing => (
            "Модуль в задаче дан один на всю передачу (или не дан вовсе), и при нём суммы чисел зубьев ступени не замыкаются: сателлит не достаёт до второго центрального колеса, передачу в таком виде не собрать. Формула Виллиса требует только чисел зубьев; для треугольников скоростей зацепление принято с модулем, при котором ось центрального колеса совпадает с осью водила (в задаче не дан):",
            "Модуль у задачі дано один на всю передачу (або не дано зовсім), і за нього суми чисел зубців ступеня не замикаються: сателіт не дістає до другого центрального колеса, передачу в такому вигляді не зібрати. Формула Вілліса потребує лише чисел зубців; для трикутників швидкостей зачеплення прийнято з модулем, за якого вісь центрального колеса збігається з віссю водила (у задачі не дано):",
            "The textbook gives one module for the whole train (or none), and with it the stage's tooth sums do not close: the satellite does not reach the second central wheel, and the train as given cannot be assembled. Willis's formula needs the teeth only; for the velocity triangles the mesh is taken at the module that brings the central wheel's axis onto the carrier's (the textbook gives none):"
        ),
        TrainUncuttable => (
            "Колесо {name} (z = {z}) стандартной рейкой (ГОСТ 13755) не нарезать: без подреза — только при x ≥ x_min = {least}, а зуб заостряется уже при x = {pointed}. Число зубьев взято из задачи как есть: формуле Виллиса нужны только числа зубьев.",
            "Колесо {name} (z = {z}) стандартною рейкою (ГОСТ 13755) не нарізати: без підрізання — лише за x ≥ x_min = {least}, а зуб загострюється вже за x = {pointed}. Число зубців узято із задачі як є: формулі Вілліса потрібні лише числа зубців.",
            "Wheel {name} (z = {z}) cannot be cut by the standard rack (GOST 13755): it is free of undercut only from x_min = {least}, and its tooth is pointed already at x = {pointed}. The tooth count is taken from the task as given: Willis's formula needs the teeth only."
        ),
        TrainDifferential => (
            "Дифференциал (W = 2): при остановленном водиле отношение частот вращения центральных колёс — по числам зубьев; формула Виллиса даёт частоту вращения выходного звена по двум заданным:",
            "Диференціал (W = 2): при зупиненому водилі відношення частот обертання центральних коліс — за числами зубців; формула Вілліса дає частоту обертання вихідної ланки за двома заданими:",
            "A differential (W = 2): with the carrier stopped the central wheels' speeds are in the ratio of the teeth; Willis's formula gives the output's speed from the two given ones:"
        ),
        TrainWorked => (
            "Передаточное отношение редуктора по ступеням: у зацепления на неподвижных осях — отношение чисел зубьев ведомого и ведущего колёс, со знаком минус для внешнего зацепления и плюс для внутреннего; планетарная ступень — по формуле Виллиса при остановленном водиле:",
            "Передаточне відношення редуктора за ступенями: у зачеплення на нерухомих осях — відношення чисел зубців веденого і ведучого коліс, зі знаком мінус для зовнішнього зачеплення і плюс для внутрішнього; планетарний ступінь — за формулою Вілліса при зупиненому водилі:",
            "The train's ratio stage by stage: a mesh on fixed axes gives the driven wheel's teeth over the driving wheel's, negative for an external mesh and positive for an internal one; the planetary stage by Willis's formula with the carrier stopped:"
        ),
        TrainWillis => (
            "Совместное решение уравнений Виллиса всех зацеплений (аналитическая проверка) даёт:",
            "Спільний розв’язок рівнянь Вілліса всіх зачеплень (аналітична перевірка) дає:",
            "Willis's relations of every mesh solved together (the analytic check) give:"
        ),
        TrainRequired => (
            "Требуемое передаточное отношение и отношение ступени на неподвижных осях, которого оно требует при остальных ступенях:",
            "Потрібне передаточне відношення і відношення ступеня на нерухомих осях, якого воно вимагає при інших ступенях:",
            "The required ratio and the ratio it asks of the fixed-axis stage, the other stages as they are:"
        ),
        TrainChosen => (
            "Принятые числа зубьев дают:",
            "Прийняті числа зубців дають:",
            "The chosen tooth numbers give:"
        ),
        TrainOutput => (
            "Частота вращения выходного вала и её отклонение от требуемой:",
            "Частота обертання вихідного вала та її відхилення від потрібної:",
            "The output's speed and its difference from the required one:"
        ),
        TrainTable => ("Передаточное отношение и угловые скорости редуктора", "Передаточне відношення і кутові швидкості редуктора", "The train's ratio and angular velocities"),
        BalancingSection => ("Уравновешивание ротора", "Зрівноваження ротора", "Balancing of the rotor"),
        BalancingTable => ("Уравновешивающие массы", "Зрівноважувальні маси", "The correcting masses"),
        FrictionSection => ("Трение в кинематических парах", "Тертя в кінематичних парах", "Friction in the kinematic pairs"),
        FrictionTable => ("Силы, моменты и КПД с учётом трения", "Сили, моменти і ККД з урахуванням тертя", "Forces, moments and efficiencies with friction"),
        BlockingTable => (
            "Значения в точках блокирующего контура",
            "Значення в точках блокувального контуру",
            "The values at the points of the blocking contour"
        ),
        FrictionTask => (
            "Определить графически (планами сил) и проверить аналитическим расчётом силы, моменты и коэффициенты полезного действия с учётом трения в следующих случаях:",
            "Визначити графічно (планами сил) і перевірити аналітичним розрахунком сили, моменти й коефіцієнти корисної дії з урахуванням тертя в таких випадках:",
            "Find graphically (by force polygons), and check by calculation, the forces, moments and efficiencies with friction in the following cases:"
        ),
        FollowerGuideWorked => (
            "Кулачок давит на толкатель силой P по общей нормали под углом давления λ к оси; сопротивление Q — вдоль оси; опоры направляющей (на расстояниях l и l + b от точки контакта K) отвечают нормальными реакциями N₁, N₂, каждая с трением f·N против движения. Из равновесия толкателя (проекции на ось и поперёк неё, моменты относительно K):",
            "Кулачок тисне на штовхач силою P по спільній нормалі під кутом тиску λ до осі; опір Q — уздовж осі; опори напрямної (на відстанях l і l + b від точки контакту K) відповідають нормальними реакціями N₁, N₂, кожна з тертям f·N проти руху. З рівноваги штовхача (проекції на вісь і поперек неї, моменти відносно K):",
            "The cam pushes the follower with the force P along the common normal, at the pressure angle λ to its axis; the resistance Q acts along the axis; the guide's bearings (l and l + b from the contact K) answer with the normal reactions N₁, N₂, each with its friction f·N against the motion. The follower's equilibrium (along the axis, across it, moments about K) gives:"
        ),
        FollowerPivotWorked => (
            "Опора коромысла (цапфа диаметром d) воспринимает всю силу P; её реакция R = −P, повёрнутая от нормали на угол трения φ, касается круга трения. Силы P и R образуют пару с плечом h, уравновешивающую момент сопротивления M_с:",
            "Опора коромисла (цапфа діаметром d) сприймає всю силу P; її реакція R = −P, повернута від нормалі на кут тертя φ, дотикається до кола тертя. Сили P і R утворюють пару з плечем h, що врівноважує момент опору M_с:",
            "The rocker's pivot (a journal of diameter d) carries the whole of P; its reaction R = −P, turned from the normal by the friction angle φ, is tangent to the friction circle. P and R make a couple of arm h that balances the moment of resistance M_с:"
        ),
        FollowerLock => (
            "Механизм заклинивает (никакая сила P не сдвинет ведомое звено), когда угол давления достигает критического:",
            "Механізм заклинює (жодна сила P не зрушить ведену ланку), коли кут тиску досягає критичного:",
            "The mechanism jams (no force P moves the follower) when the pressure angle reaches the critical one:"
        ),
        FollowerLecture => (
            "Лекционная оценка M_тр = P^n·f·d/2 (нагрузка опоры — лишь P^n = P·sin λ) даёт меньший угол:",
            "Лекційна оцінка M_тр = P^n·f·d/2 (навантаження опори — лише P^n = P·sin λ) дає менший кут:",
            "The lecture's estimate M_тр = P^n·f·d/2 (the pivot loaded by P^n = P·sin λ alone) gives a smaller angle:"
        ),
        Conclusions => ("Выводы", "Висновки", "Conclusions"),
        ConclusionsErrors => (
            "Графические построения проверены аналитическим расчётом. Погрешности графических методов по величинам и методам — в таблицах ниже (δ — относительное расхождение графического значения с аналитическим).",
            "Графічні побудови перевірено аналітичним розрахунком. Похибки графічних методів за величинами і методами — у таблицях нижче (δ — відносна розбіжність графічного значення з аналітичним).",
            "The graphical constructions are checked by the analytic solution. The errors of the graphical methods by quantity and method are in the tables below (δ: the graphical value's relative difference from the analytic one)."
        ),
        ErrorsByQuantity => ("Погрешность графических методов по величинам", "Похибка графічних методів за величинами", "Errors of the graphical methods by quantity"),
        ErrorsByMethod => ("Средняя погрешность по методам", "Середня похибка за методами", "Mean error by method"),
        Count => ("число", "кількість", "count"),
        AtPosition => ("в положении", "у положенні", "at position"),
        ExactReading => (
            "Длины отсчитаны с чертежа точно (без погрешности отсчёта): погрешность планов скоростей, ускорений и сил — только округление, погрешность диаграмм — погрешность метода хорд.",
            "Довжини зчитано з креслення точно (без похибки відліку): похибка планів швидкостей, прискорень і сил — лише округлення, похибка діаграм — похибка методу хорд.",
            "Lengths are read off the drawing exactly (no reading error): the plans of velocities, accelerations and forces err by rounding only, the diagrams by the method of chords."
        ),
        HandReadingLead => (
            "Длины отсчитаны с чертежа с точностью",
            "Довжини зчитано з креслення з точністю",
            "Lengths are read off the drawing to"
        ),
        HandReadingRest => (
            "как при построении вручную. Погрешность графического значения складывается из погрешности отсчёта, тем большей в процентах, чем короче отрезок на чертеже, и у диаграмм — из погрешности метода хорд; аналитические значения вычислены точно. Расхождение в несколько процентов на коротком отрезке — следствие отсчёта, а не ошибка построения.",
            "як під час побудови вручну. Похибка графічного значення складається з похибки відліку, тим більшої у відсотках, чим коротший відрізок на кресленні, і в діаграм — з похибки методу хорд; аналітичні значення обчислено точно. Розбіжність у кілька відсотків на короткому відрізку — наслідок відліку, а не помилка побудови.",
            "as in a construction by hand. A graphical value's error is the reading's, the larger in per cent the shorter the segment on the drawing, and for the diagrams also the method of chords'; the analytic values are exact. A few per cent on a short segment come from the reading, not from a wrong construction."
        ),
        SeedNotReproduced => (
            "Значения источника, которые проект не воспроизводит, с точным значением и причиной:",
            "Значення джерела, які проєкт не відтворює, з точним значенням і причиною:",
            "The textbook's values this project does not reproduce, with the exact value and the reason:"
        ),
        SeedNoReason => (
            "не следует из данных источника",
            "не випливає з даних джерела",
            "does not follow from the textbook's data"
        ),
        SeedGives => ("в источнике", "у джерелі", "the textbook gives"),
        SeedExactValue => ("точное значение", "точне значення", "the exact value is"),
        SeedOffBy => ("расхождение", "розбіжність", "off by"),
        SeedFlywheel => (
            "не следует из данных источника: точное интегрирование уравнения движения",
            "не випливає з даних джерела: точне інтегрування рівняння руху",
            "does not follow from the textbook's data: the equation of motion integrated exactly"
        ),
        SeedContactRatio => (
            "в источнике основные радиусы взяты как r·cos α_{w}, а шаг — как πm·cos α_{w}",
            "у джерелі основні радіуси взято як r·cos α_{w}, а крок — як πm·cos α_{w}",
            "the textbook takes the base radii as r·cos α_{w} and the base pitch as πm·cos α_{w}"
        ),
        SeedTrainNeeds => (
            "при остальных ступенях по числам зубьев напечатанное значение требует",
            "при інших ступенях за числами зубців надруковане значення вимагає",
            "with the other stages as their teeth give, the printed value needs"
        ),
        SeedTrainTeeth => ("а по числам зубьев", "а за числами зубців", "whereas the teeth give"),
        SeedMinRadius => (
            "при γ ≥ γ_{min} на всём цикле радиус не может быть меньше точного",
            "при γ ≥ γ_{min} на всьому циклі радіус не може бути меншим за точний",
            "with γ ≥ γ_{min} over the whole cycle the radius cannot be below the exact one"
        ),
        References => ("Список использованных источников", "Список використаних джерел", "References"),
        // The references as ГОСТ Р 7.0.100 records, each in the language of the work it
        // cites (a Ukrainian note lists the Russian books and standards in Russian).
        GraphicalShort => ("гр.", "гр.", "gr."),
        AnalyticShort => ("ан.", "ан.", "an."),
        Part => ("часть", "частина", "part"),
        PositionShort => ("пол.", "пол.", "pos."),
    }
}
