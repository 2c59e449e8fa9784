//! The sentences, headers and captions of the note's kinematics worked as seed 000 works it
//! (issue 44 §1): θ and K, the drawn lengths, the vector equations' tables of what is known,
//! the similarity proportions, the normal and Coriolis parts, the diagrams' scales and the
//! analytic method.

use super::catalogue;

catalogue! {
    /// A sentence or a table's word of the note's kinematic analysis.
    KinematicsNote {
        DrawnLengths => (
            "Длины звеньев на чертеже находим делением действительных длин на масштаб длин, например:",
            "Довжини ланок на кресленні знаходимо діленням дійсних довжин на масштаб довжин, наприклад:",
            "The links' lengths on the drawing are their true lengths divided by the length scale, e.g.:"
        ),
        DrawnLengthsTable => ("Длины звеньев механизма и их отрезки на плане положений", "Довжини ланок механізму та їх відрізки на плані положень", "The links' lengths and their segments on the position diagram"),
        Dimension => ("размер", "розмір", "dimension"),
        Segment => ("отрезок", "відрізок", "segment"),
        LengthWord => ("длина", "довжина", "length"),
        OnDrawing => ("на чертеже", "на кресленні", "on the drawing"),
        ThetaSlotted => (
            "В крайних положениях кулиса касается окружности, описываемой пальцем кривошипа, поэтому угол θ между крайними положениями кулисы определяем из прямоугольного треугольника:",
            "У крайніх положеннях куліса дотикається до кола, яке описує палець кривошипа, тому кут θ між крайніми положеннями куліси визначаємо з прямокутного трикутника:",
            "At its extremes the slotted link is tangent to the circle of the crank's pin, so the angle θ between its extremes follows from the right triangle:"
        ),
        TimeRatio => (
            "Коэффициент изменения средней скорости хода выходного звена:",
            "Коефіцієнт зміни середньої швидкості ходу вихідної ланки:",
            "The time ratio of the output's strokes:"
        ),
        NoTimeRatio => (
            "Коэффициент изменения средней скорости хода выходного звена не определяется: выходное звено доходит до крайнего положения дважды за оборот (при φ₁ = {a}° и {b}°): какое из этих положений завершает рабочий ход, механизм не определяет.",
            "Коефіцієнт зміни середньої швидкості ходу вихідної ланки не визначається: вихідна ланка доходить до крайнього положення двічі за оберт (при φ₁ = {a}° і {b}°): яке з цих положень завершує робочий хід, механізм не визначає.",
            "The time ratio of the output's strokes is not defined: the output reaches an extreme position twice a turn (at φ₁ = {a}° and {b}°), and nothing in the mechanism decides which of the two ends the working stroke."
        ),
        Vector => ("вектор", "вектор", "vector"),
        Magnitude => ("величина", "величина", "magnitude"),
        Direction => ("направление", "напрям", "direction"),
        FromPlan => ("известна из плана", "відома з плану", "known from the plan"),
        Towards => ("к точке", "до точки", "towards"),
        KnownVelocities => ("Известные и неизвестные векторы уравнений скоростей группы", "Відомі та невідомі вектори рівнянь швидкостей групи", "The known and unknown vectors of the velocity equations of group"),
        KnownAccelerations => ("Известные и неизвестные векторы уравнений ускорений группы", "Відомі та невідомі вектори рівнянь прискорень групи", "The known and unknown vectors of the acceleration equations of group"),
        Similarity => (
            "Изображения остальных точек звеньев находим по теореме подобия: отрезки плана скоростей относятся как отрезки звена на плане положений (отрезки построения — до сотых долей миллиметра, при чтении скоростей отрезки округляются по точности чертежа):",
            "Зображення решти точок ланок знаходимо за теоремою подібності: відрізки плану швидкостей відносяться як відрізки ланки на плані положень (відрізки побудови — до сотих часток міліметра, при читанні швидкостей відрізки округлюються за точністю креслення):",
            "The images of the link's further points follow from the similarity theorem: the plan's segments are in the ratio of the link's segments on the position diagram (the construction's segments to a hundredth of a millimetre; the readings of the velocities are rounded to the drawing's precision):"
        ),
        NormalWorked => (
            "Нормальные ускорения в относительном вращательном движении определяем по угловым скоростям звеньев, найденным из плана скоростей:",
            "Нормальні прискорення у відносному обертальному русі визначаємо за кутовими швидкостями ланок, знайденими з плану швидкостей:",
            "The normal accelerations of the relative rotation follow from the links' angular velocities found on the velocity plan:"
        ),
        CoriolisRule => (
            "Направление кориолисова ускорения получаем, повернув вектор относительной скорости на 90° в сторону вращения звена, по которому движется точка (в сторону его угловой скорости).",
            "Напрям коріолісового прискорення отримуємо, повернувши вектор відносної швидкості на 90° у бік обертання ланки, по якій рухається точка (у бік її кутової швидкості).",
            "The Coriolis acceleration points along the relative velocity turned through 90° in the sense of the angular velocity of the link the point slides along."
        ),
        Table2 => ("Модули скоростей точек, найденные по планам скоростей", "Модулі швидкостей точок, знайдені за планами швидкостей", "The moduli of the points' velocities found from the velocity plans"),
        PhiScale => (
            "Ось абсцисс диаграмм соответствует одному обороту кривошипа; масштаб угла поворота определяем по длине этой оси на чертеже:",
            "Вісь абсцис діаграм відповідає одному оберту кривошипа; масштаб кута повороту визначаємо за довжиною цієї осі на кресленні:",
            "The diagrams' abscissa spans one turn of the crank; the angle scale follows from its length on the drawing:"
        ),
        DiagramWorked => (
            "Истинные значения получаем, умножая ординату диаграммы в миллиметрах на её масштаб и на угловую скорость кривошипа в соответствующей степени; для положения",
            "Дійсні значення отримуємо, множачи ординату діаграми в міліметрах на її масштаб і на кутову швидкість кривошипа у відповідному степені; для положення",
            "The true values are the diagram's ordinate in millimetres times its scale and the crank's angular velocity to the matching power; at position"
        ),
        HodographScale => (
            "Лучи годографа — скорости точки из планов скоростей, отложенные в масштабе годографа",
            "Промені годографа — швидкості точки з планів швидкостей, відкладені в масштабі годографа",
            "The hodograph's rays are the point's velocities from the velocity plans laid off at the hodograph's scale of"
        ),
        PlanSegments => ("отрезки планов скоростей — в масштабе плана", "відрізки планів швидкостей — у масштабі плану", "the velocity plans' segments at the plan's scale"),
        Ray => ("луч годографа", "промінь годографа", "hodograph ray"),
        LoopIntro => (
            "Составляем уравнение замкнутого векторного контура, образованного кривошипом, стойкой и кулисой:",
            "Складаємо рівняння замкненого векторного контуру, утвореного кривошипом, стояком і кулісою:",
            "The closed vector loop of the crank, the frame and the slotted link:"
        ),
        Projections => (
            "Проецируем его на оси неподвижной системы координат с началом в центре вращения кулисы:",
            "Проєктуємо його на осі нерухомої системи координат з початком у центрі обертання куліси:",
            "Its projections on the axes of the fixed frame with its origin at the slotted link's pivot:"
        ),
        PositionFormulas => (
            "Отсюда угол поворота кулисы и расстояние от её центра вращения до камня:",
            "Звідси кут повороту куліси і відстань від її центра обертання до каменя:",
            "Hence the slotted link's angle and the block's distance from its pivot:"
        ),
        VelocityFormulas => (
            "Дифференцируя уравнения проекций по времени, получаем угловую скорость кулисы и скорость камня относительно кулисы:",
            "Диференціюючи рівняння проєкцій за часом, отримуємо кутову швидкість куліси і швидкість каменя відносно куліси:",
            "Differentiating the projections in time gives the slotted link's angular velocity and the block's velocity along the slot:"
        ),
        AccelerationFormulas => (
            "Дифференцируя ещё раз при постоянной угловой скорости кривошипа, получаем угловое ускорение кулисы, затем скорость и ускорение её точки:",
            "Диференціюючи ще раз за сталої кутової швидкості кривошипа, отримуємо кутове прискорення куліси, потім швидкість і прискорення її точки:",
            "Differentiating once more at the crank's constant angular velocity gives the slotted link's angular acceleration, then its point's velocity and acceleration:"
        ),
        AnalyticWorked => (
            "Пример расчёта по этим формулам для положения",
            "Приклад розрахунку за цими формулами для положення",
            "These formulas worked at position"
        ),
    }
}
