# Окно, его верхняя панель, инструменты и боковые панели, по-русски.
# Ключи записаны в kebab-case и начинаются с того, к чему относятся; подстановки ({ $name }) содержат
# числа, уже записанные по местным правилам (с десятичной запятой, где язык её использует).

## Верхняя панель

view-interface = Одна граница
view-scenes = Сцены
view-menu = Вид
view-accuracy = Точность/время
# Называет в сообщении об ошибке сцену, сохранившуюся с последнего запуска.
view-last-run-scene = сцена последнего запуска
# Что сделала последняя отмена или повтор ($change), и вид, на который произошло переключение ($view).
travel-in-view = { $change } (вид: { $view })
tool-check = Проверить мой T
tool-walk-through = Пошагово
tool-files = Сохранить/открыть
tool-fresnel = Френель
presentation-toggle = 🖵 Презентация
presentation-toggle-hover = Полный экран, всё крупнее (F11)
presentation-theme = Тема
presentation-theme-hover = Стандартная или высокий контраст: чёрное на белом или белое на чёрном
presentation-colour-blind = Для дальтоников
presentation-colour-blind-hover = Только цвета Okabe–Ito; у каждого луча также свой тип штриха и подпись
presentation-simple = Простой вид
presentation-simple-hover = Скрывает три отвергнутых выбора знаков и их (a, b): для класса, который ещё не знает четырёх кандидатов
presentation-look = Вид
presentation-diagram-only = Только схема (D)
language-menu = Язык
language-hover = Язык окна. Он совпадает с языком системы, если не выбран здесь.
effects-menu = Эффекты
effects-menu-hover = Интенсивности (Френель) и волновые фронты поверх схемы
effects-intensities = Интенсивности
effects-intensities-hover = Рисует отражённый и прошедший лучи по их доле света (Френель), с процентами
effects-wavefronts = Волновые фронты
effects-wavefronts-hover = Плоские волновые фронты через λ/μ в каждой среде, движущиеся со скоростью c/μ: вот почему луч преломляется
effects-moving = Движение
effects-huygens = Построение Гюйгенса
effects-huygens-hover = Две точки одного фронта и вторичная волна, выросшая за время между ними

## Боковые панели ($key — клавиша, которая их открывает и закрывает, например F2)

panel-show-controls = Показать управление ({ $key })
panel-hide-controls = Скрыть управление ({ $key })
panel-show-numbers = Показать числа ({ $key })
panel-hide-numbers = Скрыть числа ({ $key })

## Под схемой

canvas-hint = Перетащите W, N или метку μ либо нажимайте − и + ниже; Tab или щелчок выбирает маркер для стрелок
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Shift: 0,1°) · +/− μt · Tab: следующий маркер · перетаскивание — сдвиг
canvas-hint-index = ↑/↓ или +/− меняют показатель преломления на 0,01 (Shift: 0,001) · Tab: следующий маркер

## Панель управления

controls-lesson = Урок
controls-lesson-preset = Предустановка урока
controls-lesson-own = Свой случай
controls-lesson-changed = { $lesson }, изменено
controls-reset = Сбросить
controls-reset-hover = Вернуться к началу выбранного урока
controls-incidence = θi (градусы)
controls-convention = Соглашение
controls-convention-toward-origin = Раздел 1: W направлен обратно к началу луча
controls-convention-along-ray = Раздел 2: W — направление распространения
controls-flip-normal = Развернуть N
controls-flip-normal-hover = Развернуть нормаль: такова внешняя нормаль там, где луч выходит из стекла
controls-snap = W на θc
controls-snap-hover = Поставить W под предельным углом (нужно μi > μt)
controls-snap-disabled = Предельный угол есть только при μi > μt
controls-indices = Показатели преломления
# $symbol — μi или μt.
controls-index-value = Значение { $symbol }
controls-material = Материал { $symbol }
controls-custom-hint = свой: введите значение выше
controls-typed-vectors = Введённые W и N
controls-typed-vectors-hint = Вставьте записанные учащимся векторы (x, y, z); нажмите Enter.
controls-export-heading = Экспорт изображения (PNG или SVG)
controls-export-size = Размер
controls-export-file = Файл
controls-export-file-hint = имя .png или .svg либо нумерованное diagram-001.png
controls-browse = Обзор…
controls-export = Экспортировать изображение
controls-exported = записано: { $path }
# Введённое значение, которое не является числом: $name — то, для чего его вводили (θi, μt, W).
typed-not-a-number = { $name }: «{ $text }» — не число
typed-not-three-numbers = { $name }: ожидались три числа x, y, z, получено: { $count }

## Панель чисел

readouts-discriminant = Дискриминант k = μ²wn² − μ² + 1 = { $k } ≥ 0: T существует
readouts-discriminant-tir = Дискриминант k = μ²wn² − μ² + 1 = { $k } < 0: полное внутреннее отражение
# $section — раздел статьи (1 или 2), к которому относится это уравнение 20.
readouts-quadratic = Ур. { $section }.20, квадратное уравнение относительно b: b² + 2a·wn·b + a² − 1 = 0 при a = { $a }, wn = { $wn }
readouts-no-roots = нет действительных корней: парабола больше не достигает нуля
readouts-roots = корни b = { $roots } (значения b кандидатов при этом a)
readouts-candidates = Четыре кандидата
readouts-candidate = кандидат
# Заголовки столбцов проверок: закон Снеллиуса в квадрате (ур. 10 статьи), сторона поверхности, на которой лежит T, направление, в котором T отклоняется.
readouts-check-snell = ур. 10
readouts-check-side = сторона
readouts-check-bend = отклонение
readouts-no-candidates = Нет кандидатов: k < 0, поэтому уравнение для b не имеет действительных корней и T не существует.
readouts-candidates-note = Все четыре единичной длины и удовлетворяют закону Снеллиуса в квадрате (ур. 10): возведение в квадрат их не различает. Только сторона и отклонение (довод статьи с μ = 1) выбирают T.
readouts-warnings = Предупреждения ядра
readouts-no-warnings = Нет предупреждений: W и N единичной длины, и N обращена к лучу.
readouts-warning-not-unit = { $vector } имеет длину { $length }, а не 1: вектор нормирован (ненормированные векторы — частая ошибка в трассировщиках лучей)
readouts-warning-flipped = N направлена от падающего луча (как внешняя нормаль там, где луч выходит из сферы): ядро использовало −N, нормаль, обращённую к лучу
readouts-equations = Уравнения статьи, раздел { $section }

## Пошаговый разбор

walk-previous = Предыдущий шаг
walk-next = Следующий шаг
walk-animate = Анимировать μ до 1
walk-animating = Анимация μ до 1 …
walk-animate-hover = Плавно перевести μt в μi: выбранный T сходится к падающему лучу
walk-animate-disabled = μ уже равно 1 (μi = μt), или анимация идёт
walk-step = Шаг { $number } из { $count }: { $title }

## Инструмент «Френель»

fresnel-plot-about = График Френеля: отражённый и прошедший свет в зависимости от θi, курсор при θi = { $angle }°
fresnel-click-hint = Щёлкните по графику или проведите по нему, чтобы задать θi.
fresnel-at = При θi = { $angle }°, из μi = { $mu_i } в μt = { $mu_t }.
fresnel-brewster = Угол Брюстера θB = { $angle }°: здесь p-поляризованный свет не отражается (tg θB = μt/μi).
fresnel-equal-indices = Показатели преломления равны: границы нет, ничего не отражается.
fresnel-critical = Предельный угол θc = { $angle }°: при больших углах весь свет отражается (sin θc = μt/μi).
fresnel-no-critical = Предельного угла нет: свет переходит в среду с большим показателем преломления.

## Вид «Сцены»

scenes-scene = Сцена
scenes-rays = Лучи
scenes-draft = Черновик при перетаскивании: каждый { $every }-й луч
scenes-reset-hover = сцена в том виде, в каком она записана в файле
scenes-file = Файл сцены
scenes-open = Открыть файл
scenes-save = Сохранить файл
scenes-save-hover = отредактированная сцена в формате сцен (TOML)
scenes-open-dialog-hover = Выбрать файл сцены для открытия
scenes-saved = сохранено: { $path }
scenes-opened = открыто: { $path }
scenes-hint = Перетащите источник (янтарный), его направление (кольцо на конце пунктирной стрелки) или маркер фигуры; щёлкните по точке попадания, чтобы открыть её в виде «Одна граница».
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Файлы и подсказка
scenes-less = Меньше элементов
scenes-picture-file = Файл изображения (.png или .svg)
scenes-picture-hint = имя .png или .svg, либо по номеру scene-001.svg
scenes-export-size = Экспорт { $width }×{ $height }
scenes-tracing = трассировка… { $percent } % (показан последний завершённый результат)
scenes-cancel = Отмена
scenes-cancel-hover = остановить трассировку и показать то, что уже просчитано
scenes-stopped-segments = трассировка остановлена на лимите сегментов ({ $budget }): ещё не прослеженные лучи опущены (меньше лучей, меньший max_depth или больший min_intensity дают полную трассировку)
scenes-stopped-tests = трассировка остановлена на лимите проверок пересечения ({ $budget }): ещё не прослеженные лучи опущены (меньше лучей, фигур или отражений дают полную трассировку)
scenes-stopped-cancelled = трассировка отменена: ещё не прослеженные лучи опущены
# Окошко рядом с точкой попадания под указателем: среды, из которой и в которую идёт луч, их показатели преломления и длина волны трассировки.
scenes-hit =
    { $from } → { $to } ({ $side ->
        [entering] вход
       *[leaving] выход: ядро разворачивает N
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } нм
    щелчок: открыть в виде «Одна граница»

## Вид «Точность/время»

accuracy-heading = Чего стоит точность по времени
accuracy-intro = Замеряет время каждого варианта ядра в f32 и f64 на этом компьютере и измеряет его ошибку относительно эталона double-double на случайных и трудных углах падения. График показывает наибольшую ошибку на трудном наборе в единицах ε·κ (то, что алгоритм теряет сверх того, что усиливает сама задача) в зависимости от наносекунд на луч.
accuracy-quick = Быстрый прогон (несколько секунд)
accuracy-measure = Измерить
accuracy-measuring = измерение… { $percent } %
accuracy-press-measure = Нажмите «Измерить», чтобы запустить тест производительности.
# $variant называет вариант ядра и его точность, например «stable f32».
accuracy-verdict = Самый быстрый в пределах 10× от лучшей точности: { $variant }, { $time } нс на луч (ошибка на трудном наборе: { $error } ε·κ).
accuracy-footnote = Случайных задач: { $random }, трудных: { $hard }; процессор: { $cpu }. Время зависит от того, чем ещё занят компьютер; `refraction-explorer bench` даёт те же цифры в командной строке.
accuracy-plot-about = Точность в зависимости от времени: вариантов { $count }, у каждого своя форма метки и подпись рядом
accuracy-hover =
    { $name }
    { $time } нс, { $error } ε·κ
accuracy-column-variant = вариант
accuracy-column-time = нс/луч
accuracy-column-random = макс. ош. случ.
accuracy-column-hard = макс. ош. трудн.
accuracy-column-eps-kappa = трудн. ε·κ
accuracy-column-tir = расхождения по полному отражению

## Вид ученика: что показывает телефон (или ссылка с view=student), и кнопки, которые меняют W,
## N и показатели преломления по шагу

# $symbol: μi или μt
student-index = Показатель преломления { $symbol }
student-full = Вся программа
student-full-hover = Вся программа, с инструментами и панелями (для большого экрана)
student-view = Вид ученика
student-view-hover = Вид для телефона: вопрос, схема во всю ширину и кнопки под палец
