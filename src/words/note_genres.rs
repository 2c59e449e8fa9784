//! The words of the note that follow its genre: the title page of a course project, a
//! practical work's report (seed 002's form) and a lecture case's report, their headings, and
//! the sources each cites (ГОСТ Р 7.0.100 records; a source keeps its own language).

use super::catalogue;

catalogue! {
    /// A word of the title page, the headings or the references that follows the genre.
    GenreText {
        PracticumReport => ("Отчёт о практической работе №", "Звіт про практичну роботу №", "Report on practical work No."),
        LectureReport => ("Отчёт о решении задачи", "Звіт про розв’язання задачі", "Report on a worked problem"),
        InTheTheory => (
            "по теории механизмов и машин",
            "з теорії механізмів і машин",
            "in the theory of mechanisms and machines"
        ),
        Topic => ("Тема:", "Тема:", "Topic:"),
        Goal => ("Цель работы:", "Мета роботи:", "Goal of the work:"),
        Checked => ("Проверил", "Перевірив", "Checked by"),
        Done => ("Работу выполнил", "Роботу виконав", "Done by"),
        Accepted => ("Работу принял", "Роботу прийняв", "Accepted by"),
        Date => ("Дата", "Дата", "Date"),
        EngineForcesData => (
            "Массы звеньев и силы давления газов",
            "Маси ланок і сили тиску газів",
            "The links' masses and the gas forces"
        ),
        Wheel => ("Колесо", "Колесо", "Wheel"),
        Undercut => ("зуб подрезан (x < x_{min})", "зуб підрізаний (x < x_{min})", "the tooth is undercut (x < x_{min})"),
        NotUndercut => ("подреза нет (x ≥ x_{min})", "підрізу немає (x ≥ x_{min})", "no undercut (x ≥ x_{min})"),
        Pointed => ("зуб заострён (s_{a} < 0,3m)", "зуб загострений (s_{a} < 0,3m)", "the tooth is pointed (s_{a} < 0.3m)"),
        TipEnough => ("толщина зуба на окружности вершин достаточна (s_{a} ≥ 0,3m)", "товщина зуба на колі вершин достатня (s_{a} ≥ 0,3m)", "the tooth is thick enough at the tip (s_{a} ≥ 0.3m)"),
        ShiftEffect => (
            "Положительное смещение рейки устраняет подрез и утолщает зуб у основания и по делительной окружности (S_{t} = 0,5P_{t} + 2x·tg α), но утоняет его на окружности вершин; допустимое смещение лежит между x_{min} и смещением, при котором s_{a} = 0,3m.",
            "Додатне зміщення рейки усуває підріз і потовщує зуб біля основи та по ділильному колу (S_{t} = 0,5P_{t} + 2x·tg α), але стоншує його на колі вершин; допустиме зміщення лежить між x_{min} і зміщенням, за якого s_{a} = 0,3m.",
            "A positive shift of the rack removes the undercut and thickens the tooth at its root and on the pitch circle (S_{t} = 0.5P_{t} + 2x·tan α) but thins it at the tip; the shift allowed lies between x_{min} and the shift at which s_{a} = 0.3m."
        ),
        SameSense => (
            "ведущее и выходное звенья вращаются в одну сторону (передаточное отношение положительно).",
            "ведуча і вихідна ланки обертаються в один бік (передаточне відношення додатне).",
            "the driving and the output link turn the same way (the ratio is positive)."
        ),
        OppositeSense => (
            "ведущее и выходное звенья вращаются в противоположные стороны (передаточное отношение отрицательно).",
            "ведуча і вихідна ланки обертаються в протилежні боки (передаточне відношення від’ємне).",
            "the driving and the output link turn opposite ways (the ratio is negative)."
        ),
        GoalAndData => ("Цель работы и исходные данные", "Мета роботи та вихідні дані", "The goal and the data"),
        Problem => ("Условие задачи", "Умова задачі", "The problem"),
        Pz1Topic => (
            "Образование профиля зуба колеса методом обкатки",
            "Утворення профілю зуба колеса методом обкочування",
            "Cutting a wheel's tooth profile by the generating method"
        ),
        Pz1Goal => (
            "наглядно изучить теоретические основы проектирования зубчатых колёс с эвольвентным профилем.",
            "наочно вивчити теоретичні основи проектування зубчастих коліс з евольвентним профілем.",
            "to study on the drawn teeth the theory of designing involute gear wheels."
        ),
        Pz1Section => (
            "Параметры нулевого и положительного колёс",
            "Параметри нульового і додатного коліс",
            "The zero and the positive wheel"
        ),
        Pz1Summary => (
            "Итоги сравнения параметров нулевого и положительного колёс",
            "Підсумки порівняння параметрів нульового і додатного коліс",
            "The zero and the positive wheel compared"
        ),
        Pz2Topic => (
            "Кинематический анализ планетарного механизма",
            "Кінематичний аналіз планетарного механізму",
            "Kinematic analysis of a planetary gear train"
        ),
        Pz2Goal => (
            "провести кинематический анализ планетарного зубчатого механизма аналитическим методом.",
            "провести кінематичний аналіз планетарного зубчастого механізму аналітичним методом.",
            "to analyse the kinematics of a planetary gear train by the analytic method."
        ),
        Pz2Section => (
            "Степень подвижности и передаточное отношение механизма",
            "Ступінь рухомості та передаточне відношення механізму",
            "The train's mobility and gear ratio"
        ),
        Pz2Summary => (
            "Проверка передаточного отношения",
            "Перевірка передаточного відношення",
            "The gear ratio checked"
        ),
        Pz3Topic => (
            "Расчёт геометрических параметров зубчатого зацепления",
            "Розрахунок геометричних параметрів зубчастого зачеплення",
            "Calculating the geometry of a gear mesh"
        ),
        Pz3Goal => (
            "по заданному модулю и числам зубьев определить геометрические параметры внешнего эвольвентного зацепления и его коэффициент перекрытия.",
            "за заданим модулем і кількістю зубців визначити геометричні параметри зовнішнього евольвентного зачеплення та його коефіцієнт перекриття.",
            "to find, from the given module and numbers of teeth, the geometry of an external involute mesh and its contact ratio."
        ),
        Pz3Section => (
            "Геометрические параметры зацепления",
            "Геометричні параметри зачеплення",
            "The geometry of the mesh"
        ),
        Pz4Topic => (
            "Синтез кулачкового механизма с плоским толкателем",
            "Синтез кулачкового механізму з плоским штовхачем",
            "Synthesis of a cam mechanism with a flat-faced follower"
        ),
        Pz5Topic => (
            "Синтез кулачкового механизма с роликовым толкателем",
            "Синтез кулачкового механізму з роликовим штовхачем",
            "Synthesis of a cam mechanism with a roller follower"
        ),
        CamGoal => (
            "освоить практические навыки построения профиля кулачка с минимальным радиусом кулачковой шайбы.",
            "опанувати практичні навички в побудові профілю кулачка з мінімальним радіусом кулачкової шайби.",
            "to learn to construct the profile of a cam of the least base radius."
        ),
        CamPracticumSection => (
            "Диаграммы толкателя, масштабы, минимальный радиус и профиль кулачка",
            "Діаграми штовхача, масштаби, мінімальний радіус і профіль кулачка",
            "The follower's diagrams, the scales, the least radius and the cam's profile"
        ),
        SourceTextbook => (
            "Артоболевский, И. И. Теория механизмов и машин : учебник для втузов / И. И. Артоболевский. – 4-е изд., перераб. и доп. – Москва : Наука, 1988. – 640 с.",
            "Артоболевский, И. И. Теория механизмов и машин : учебник для втузов / И. И. Артоболевский. – 4-е изд., перераб. и доп. – Москва : Наука, 1988. – 640 с.",
            "Artobolevsky, I. I. Theory of Mechanisms and Machines / I. I. Artobolevsky. 4th ed. Moscow: Nauka, 1988. 640 p."
        ),
        SourceCourseDesign => (
            "Курсовое проектирование по теории механизмов и машин : учебное пособие / под редакцией А. С. Кореняко. – Киев : Вища школа, 1970. – 332 с.",
            "Курсовое проектирование по теории механизмов и машин : учебное пособие / под редакцией А. С. Кореняко. – Киев : Вища школа, 1970. – 332 с.",
            "Course Design in the Theory of Mechanisms and Machines / ed. A. S. Korenyako. Kyiv: Vyshcha shkola, 1970. 332 p."
        ),
        SourceExampleProject => (
            "Расчёт поперечно-строгального станка : пример курсового проекта по теории механизмов и машин. – Текст : непосредственный.",
            "Расчёт поперечно-строгального станка : пример курсового проекта по теории механизмов и машин. – Текст : непосредственный.",
            "Raschet poperechno-strogal'nogo stanka [Design of a shaping machine]: an example course project in the theory of mechanisms and machines."
        ),
        SourceLectures => (
            "Покровский, В. Б. Теория механизмов и машин. Строение механизмов. Кинематика, кинетостатика плоских рычажных механизмов. Трение в кинематических парах. Кулачковые механизмы. Уравновешивание и виброзащита механизмов и машин : конспект лекций / В. Б. Покровский, И. В. Троицкий ; научный редактор В. В. Каржавин. – Екатеринбург : УрФУ, 2010. – 115 с.",
            "Покровский, В. Б. Теория механизмов и машин. Строение механизмов. Кинематика, кинетостатика плоских рычажных механизмов. Трение в кинематических парах. Кулачковые механизмы. Уравновешивание и виброзащита механизмов и машин : конспект лекций / В. Б. Покровский, И. В. Троицкий ; научный редактор В. В. Каржавин. – Екатеринбург : УрФУ, 2010. – 115 с.",
            "Pokrovsky, V. B. Teoriya mekhanizmov i mashin [Theory of Mechanisms and Machines]: lecture notes / V. B. Pokrovsky, I. V. Troitsky; ed. V. V. Karzhavin. Yekaterinburg: UrFU, 2010. 115 p."
        ),
        SourcePracticum => (
            "Структурний, кінематичний та динамічний аналіз механізмів з вищими парами : посібник-практикум / О. Ю. Михайленко, О. О. Вершков, С. В. Галько [та ін.]. – Мелітополь ; Запоріжжя : ТДАТУ, 2023. – 118 с.",
            "Структурний, кінематичний та динамічний аналіз механізмів з вищими парами : посібник-практикум / О. Ю. Михайленко, О. О. Вершков, С. В. Галько [та ін.]. – Мелітополь ; Запоріжжя : ТДАТУ, 2023. – 118 с.",
            "Strukturnyi, kinematychnyi ta dynamichnyi analiz mekhanizmiv z vyshchymy paramy [Structural, kinematic and dynamic analysis of mechanisms with higher pairs]: a practicum / O. Yu. Mykhailenko, O. O. Vershkov, S. V. Halko [et al.]. Melitopol; Zaporizhzhia: TDATU, 2023. 118 p."
        ),
        SourcePracticumTextbook => (
            "Єременко, О. І. Інженерна механіка. Частина 2. Теорія механізмів і машин : підручник / О. І. Єременко. – Вінниця : Нова книга, 2009. – 368 с. – ISBN 978-966-382-217-4.",
            "Єременко, О. І. Інженерна механіка. Частина 2. Теорія механізмів і машин : підручник / О. І. Єременко. – Вінниця : Нова книга, 2009. – 368 с. – ISBN 978-966-382-217-4.",
            "Yeremenko, O. I. Inzhenerna mekhanika. Chastyna 2. Teoriia mekhanizmiv i mashyn [Engineering Mechanics. Part 2. Theory of Mechanisms and Machines]: a textbook / O. I. Yeremenko. Vinnytsia: Nova knyha, 2009. 368 p. ISBN 978-966-382-217-4."
        ),
        SourceTextDocuments => (
            "ГОСТ 2.105–2019. Единая система конструкторской документации. Общие требования к текстовым документам : межгосударственный стандарт : издание официальное : введен впервые : дата введения 2020-02-01. – Москва : Стандартинформ, 2019. – 36 с.",
            "ГОСТ 2.105–2019. Единая система конструкторской документации. Общие требования к текстовым документам : межгосударственный стандарт : издание официальное : введен впервые : дата введения 2020-02-01. – Москва : Стандартинформ, 2019. – 36 с.",
            "GOST 2.105-2019. Unified system for design documentation. General requirements for text documents. Moscow: Standartinform, 2019. 36 p."
        ),
        SourceTitleBlocks => (
            "ГОСТ 2.104–2006. Единая система конструкторской документации. Основные надписи : межгосударственный стандарт : издание официальное. – Москва : Стандартинформ, 2007. – 14 с.",
            "ГОСТ 2.104–2006. Единая система конструкторской документации. Основные надписи : межгосударственный стандарт : издание официальное. – Москва : Стандартинформ, 2007. – 14 с.",
            "GOST 2.104-2006. Unified system for design documentation. Basic inscriptions. Moscow: Standartinform, 2007. 14 p."
        ),
    }
}
