# Подписи на схеме, в сценах и на графиках, по-русски.
# Подписи на схеме должны быть короткими: не поместившиеся подписи не показываются.
# В параметрах числа уже записаны с десятичной запятой.

## Схема границы раздела

diagram-ghost-wrong-side = другой корень b: не та сторона
diagram-ghost-wrong-bend = другой знак a: преломляется не туда
diagram-ghost-reversed = оба знака неверны: −T
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = среда луча
diagram-medium-entered = среда, в которую он входит
diagram-material-vacuum = вакуум
diagram-material-air = воздух
diagram-material-water = вода
diagram-material-glass = стекло
diagram-material-diamond = алмаз
diagram-material-custom = своё значение
diagram-banner-tir =
    ПОЛНОЕ ВНУТРЕННЕЕ ОТРАЖЕНИЕ
    k = { $k } < 0: нет действительного корня для b, нет преломлённого луча; весь свет отражается (θi = { $theta_i }°)
diagram-banner-toward-origin = W направлен обратно к началу луча, поэтому a = −μ
diagram-banner-along-ray = W — направление распространения, поэтому a = +μ
diagram-banner-section = Раздел { $section }: { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Раздел 1: W направлен обратно к началу луча
diagram-banner-asked-along-ray = Раздел 2: W — направление распространения
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0: T существует
diagram-critical-angle = предельный угол θc = { $angle }°
diagram-kernel-normal = −N: нормаль, которую берёт ядро
diagram-outward-normal-bug =
    ошибка внешней нормали:
    T по формуле с N как есть
diagram-index-scale = показатель μ
diagram-incoming-ray = падающий луч
diagram-normal-incidence = нормальное падение: W, N и T лежат на одной прямой
diagram-normal-incidence-asked = нормальное падение: W направлен вдоль N
diagram-reflected = отражённый
diagram-reflected-light = отражённый ({ $light })
diagram-reflected-all = отражённый луч (весь свет)
diagram-w-along-ray = W (вдоль луча)
diagram-w-toward-origin = W (к началу луча)
diagram-transmitted = T: прошедший
diagram-no-reflected-ray = { $label }: нет отражённого луча

## Маркеры (что говорит программа чтения с экрана)

diagram-handle-w = Угол падения θi (W)
diagram-handle-n = Направление нормали N
diagram-handle-mu-i = Показатель преломления μi среды луча
diagram-handle-mu-t = Показатель преломления μt среды, в которую входит луч
diagram-handle-source = маркер источника
diagram-handle-aim = маркер направления источника
diagram-handle-shape = маркер фигуры { $number } ({ $medium })

## Уроки, темы, свет, анимации

diagram-lesson-air-to-glass = Воздух → стекло, 40°
diagram-lesson-beyond-critical = Стекло → воздух за θc
diagram-lesson-normal-incidence = Нормальное падение
diagram-lesson-brewster = Угол Брюстера
diagram-lesson-droplet-exit = Выход из капли
diagram-angle-out-of-range = θi должен быть не меньше 0° и меньше 90°, а не { $angle }°
diagram-theme-standard = Стандартная
diagram-theme-black-on-white = Чёрным по белому
diagram-theme-white-on-black = Белым по чёрному
diagram-light-s = s-свет
diagram-light-p = p-свет
diagram-light-unpolarised = неполяризованный свет
diagram-animation-mu = μ → 1: T превращается в W
diagram-animation-sweep = θi до скользящего падения: появляется полное внутреннее отражение
diagram-animation-wavefronts = Движущиеся волновые фронты

## Таблица кандидатов

diagram-role-chosen = T (выбран)
diagram-role-wrong-side = не та сторона
diagram-role-wrong-bend = неверное отклонение
diagram-role-reversed = обращён
diagram-rule-wrong-side = не та сторона поверхности: другой корень для b отправляет луч обратно в среду, из которой он пришёл
diagram-rule-wrong-bend = преломляется не туда: другой знак a обращает составляющую вдоль поверхности, поэтому при μ → 1 он не становится падающим лучом
diagram-rule-reversed = оба неверны (неверный знак a и неверный корень для b): это −T, направленный туда, откуда пришёл луч

## Трассированная сцена

diagram-screen = экран
diagram-index-at-wavelength = n = { $index } при { $wavelength } нм
diagram-stopped-at = остановлено после { $count ->
        [one] { $count } сегмента
        [few] { $count } сегментов
        [many] { $count } сегментов
       *[other] { $count } сегмента
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } вызов ядра
        [few] { $count } вызова ядра
        [many] { $count } вызовов ядра
       *[other] { $count } вызова ядра
    }
diagram-count-tir = { $count ->
        [one] { $count } полное внутреннее отражение
        [few] { $count } полных внутренних отражения
        [many] { $count } полных внутренних отражений
       *[other] { $count } полного внутреннего отражения
    }
diagram-count-reflections = { $count ->
        [one] { $count } порождённое отражение
        [few] { $count } порождённых отражения
        [many] { $count } порождённых отражений
       *[other] { $count } порождённого отражения
    }
diagram-count-fresnel = { $count ->
        [one] { $count } вычисление Френеля
        [few] { $count } вычисления Френеля
        [many] { $count } вычислений Френеля
       *[other] { $count } вычисления Френеля
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } длина волны
        [few] { $count } длины волны
        [many] { $count } длин волн
       *[other] { $count } длины волны
    }
diagram-count-source-rays = { $count ->
        [one] { $count } луч источника
        [few] { $count } луча источника
        [many] { $count } лучей источника
       *[other] { $count } луча источника
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } пропуск при равных показателях
        [few] { $count } пропуска при равных показателях
        [many] { $count } пропусков при равных показателях
       *[other] { $count } пропуска при равных показателях
    }
diagram-count-absorption = { $count ->
        [one] { $count } вычисление поглощения
        [few] { $count } вычисления поглощения
        [many] { $count } вычислений поглощения
       *[other] { $count } вычисления поглощения
    }
diagram-legend-colour = цвет:
diagram-legend-white-traced = белый свет, трассирован при { $wavelength } нм
diagram-legend-white-then = белый свет, затем
diagram-legend-nm = нм
diagram-legend-opacity = непрозрачность: интенсивность
diagram-legend-hits = попадания:
diagram-hit-entering = вход
diagram-hit-leaving = выход (N развёрнута)
diagram-hit-tir = полное внутреннее отражение

## Волны

diagram-fronts =
    фронты через λ/{ $index }
    скорость c/{ $index } = { $speed } c
diagram-huygens-touch =
    Гюйгенс: фронт достигает A через Δt после B;
    вторичная волна из B растёт на vt·Δt, новый фронт касается её
diagram-huygens-tir =
    Гюйгенс: вторичная волна из B больше BA:
    нет касательной из A, полное внутреннее отражение

## Ключевые уравнения

diagram-eq-toward-origin-a = W направлен от T, поэтому статья берёт a = −μ
diagram-eq-along-ray-a = W направлен вдоль T, поэтому статья берёт a = +μ
diagram-eq-no-refracted-ray = нет действительных (a, b): преломлённого луча нет
diagram-eq-no-b-with-10 = никакое действительное b не удовлетворяет ему вместе с ур. 10
diagram-eq-so = { $given }, поэтому { $then }
diagram-eq-negative-root = √({ $k }) из отрицательного числа: нет действительного b (полное внутреннее отражение)
diagram-eq-or = или
diagram-eq-outward-normal-bug = при N как задано b = { $b }: неверный корень, T идёт назад (ошибка внешней нормали); ядро берёт −N и получает b = { $kernel_b } для N
diagram-step-wn-flipped = W·N = { $given }: N направлена от луча, поэтому ядро использует −N: wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = нет действительного корня для выбора
diagram-eq-no-theta-t = { $given }, поэтому sinθt был бы { $sin_t } > 1: угла θt не существует
diagram-eq-with-chosen = { $lhs } = { $rhs } при выбранных (a, b)
diagram-eq-no-ab-with-12 = никакие действительные (a, b) не удовлетворяют ему вместе с ур. 12
# Обозначение синуса в формулах пошагового разбора, как его пишут в школах на этом языке.
diagram-math-sin = sin

## Пошагово

diagram-step-snell = Закон Снеллиуса
diagram-step-snell-text = Луч преломляется так, что μi·sinθi = μt·sinθt; при μ = μi/μt синус угла в новой среде равен прежнему, умноженному на μ.
diagram-step-square = Возвести в квадрат, перейти к косинусам
diagram-step-square-text = Возведение в квадрат позволяет заменить синусы косинусами (скалярными произведениями), но впускает и ложные решения: решение и противоположное ему по знаку удовлетворяют ему оба.
diagram-step-decomposition = T как a·W + b·N
diagram-step-decomposition-text = T лежит в плоскости W и N, поэтому T = a·W + b·N; косинусы становятся скалярными произведениями с wn = W·N, и cosθt = −a·wn − b. Луч распространяется вдоль { $travel }.
diagram-step-constraints = Два условия в квадрате
diagram-step-constraints-text = Закон Снеллиуса в квадрате (ур. 10) и единичная длина (ур. 12) — два квадратных уравнения относительно a и b. Им удовлетворяют четыре пары (a, b): T и три призрака. Ничто в них не различает эти четыре.
diagram-step-roots-a = Два корня для a
diagram-step-roots-a-text = Подстановка ур. 12 в ур. 10 даёт a² = μ²: a = +μ или a = −μ. Другой знак отражает T относительно нормали: луч преломляется не туда.
diagram-step-choice-a = Выбор a: предел μ = 1
# «Анимировать μ до 1» — название кнопки в окне.
diagram-step-choice-a-text = При μ = 1 ничего не преломляется, значит T должен совпадать с направлением распространения, { $travel }. Это даёт только a = { $a }; другой знак дал бы зеркальный образ. Нажмите «Анимировать μ до 1», чтобы увидеть, как T стремится к { $travel }, а призраки — нет.
diagram-step-choice-a-typo = (Далее текст раздела 2 говорит «once we decide upon using the a = −μ solution»: имеется в виду a = +μ, выбранное решение.)
diagram-step-roots-b = Два корня для b
diagram-step-roots-b-text = При фиксированном a ур. 12 — квадратное уравнение относительно b с корнями −a·wn ± √k (k = μ²wn² − μ² + 1). Другой корень отражает T относительно поверхности, обратно в среду, из которой пришёл луч. k < 0 означает, что действительного корня нет: полное внутреннее отражение.
diagram-step-choice-b = Выбор b
diagram-step-choice-b-text = Из двух корней только корень с −√k обращается в b = 0 при μ = 1, когда T должен быть неизменённым падающим лучом; другой отправляет T обратно через поверхность.
diagram-step-choice-b-flipped = Корень с −√k стремится к b = 0 при μ = 1, так что T становится падающим лучом. Но здесь N направлена вдоль луча (внешняя нормаль там, где луч выходит из среды): при N как задано этот корень лежит не с той стороны. Ядро сначала разворачивает N.

## Окно Френеля

diagram-fresnel-title = Какая доля света отражается, из μi = { $mu_i } в μt = { $mu_t }
diagram-fresnel-axis = угол падения θi
diagram-fresnel-brewster = угол Брюстера θB = { $angle }°: p-свет не отражается
diagram-fresnel-critical = предельный угол θc = { $angle }°: дальше отражается всё
diagram-fresnel-brewster-short = угол Брюстера θB = { $angle }°
diagram-fresnel-critical-short = предельный угол θc = { $angle }°
diagram-curve-rs = Rs (отражённый s-свет)
diagram-curve-rp = Rp (отражённый p-свет)
diagram-curve-r = R (неполяризованный, отражённый)
diagram-curve-t = T (неполяризованный, прошедший)
diagram-fresnel-source =
    Формулы Френеля для отражённой мощности (Хехт, «Оптика», гл. 4): Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    из собственных cosθi и cosθt ядра, без тригонометрии; неполяризованный свет — среднее s и p. За предельным углом отражается весь свет.

## График точности

diagram-accuracy-title = Точность и время на этой машине
diagram-accuracy-error-axis = наибольшая ошибка на трудном наборе, в ε·κ (лог.)
diagram-accuracy-time-axis = время на луч, нс (лог.)
diagram-accuracy-bound = граница ядра по умолчанию, 32 ε·κ
diagram-accuracy-markers = полые: f32, закрашенные: f64

## Встроенные сцены (названия, описания и имена их сред)

diagram-scene-dispersing-prism = Дисперсионная призма
diagram-scene-dispersing-prism-about = Белый свет проходит через равностороннюю призму из флинта F2 вблизи наименьшего отклонения: фиолетовый отклоняется сильнее всего.
diagram-scene-droplet = Капля воды (радуга)
diagram-scene-droplet-about = Белый свет входит в каплю, отражается внутри и выходит; дисперсия растягивает первичную радугу около 138 градусов отклонения.
diagram-scene-fibre = Оптическое волокно
diagram-scene-fibre-about = Многократное полное внутреннее отражение ведёт свет по сердцевине; самые крутые лучи уходят в оболочку.
diagram-scene-interface = Одна граница
diagram-scene-interface-about = Луч в воздухе падает на плоское стекло (n = 1,5) под углом 45 градусов и преломляется к нормали.
diagram-scene-lens = Собирающая линза
diagram-scene-lens-about = Двояковыпуклая линза из BK7 фокусирует параллельный пучок на экран; краевые лучи фокусируются ближе.
diagram-scene-right-angle-prism = Прямоугольная призма
diagram-scene-right-angle-prism-about = Полное внутреннее отражение на гипотенузе поворачивает пучок на 90 градусов.
diagram-scene-slab = Стеклянная пластина
diagram-scene-slab-about = Параллельные грани: выходящий луч параллелен входящему и смещён вбок. Потери Френеля на обеих гранях, поглощение внутри.
diagram-medium-core = сердцевина
diagram-medium-cladding = оболочка
diagram-medium-f2 = флинт F2
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = тонированное BK7
