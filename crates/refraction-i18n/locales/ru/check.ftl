# check.ftl (ru): тексты «Проверить мой T»: панель, её вердикты и их объяснения.

## Числа и векторы в объяснениях

check-number-not-finite = не конечное (NaN или бесконечность)
check-vector-not-finite = не конечный вектор (компоненты NaN или бесконечны)

## Вердикты о T в полях этого проекта (также объяснения команды `check`)

check-verdict-wrong-side = Ваш T уходит обратно в среду, из которой пришёл луч: это другой корень для b (+ там, где у квадратного корня нужен -). Обычная причина — нормаль, направленная вдоль луча, например внешняя нормаль сферы в точке, где луч из неё выходит, использованная без разворота.
check-verdict-wrong-bend = Ваш T преломляется не в ту сторону: у a противоположный знак, поэтому при μ → 1 он не переходит в падающий луч. Обычная причина — смешение соглашений: W, направленный назад к началу луча (раздел 1, a = −μ), подан в формулу для W вдоль луча (раздел 2, a = +μ), или наоборот.
check-verdict-reversed = Ваш T равен -T и указывает туда, откуда пришёл луч: оба знака неверны. Обычная причина — возврат направления к началу луча вместо направления распространения или двойное обращение W.
check-verdict-not-finite-tir = У вашего T есть компоненты NaN или бесконечность. Этот луч испытывает полное внутреннее отражение (k < 0): ваш код извлёк квадратный корень из отрицательного k, не проверив k заранее.
check-verdict-not-finite-refracts = У вашего T есть компоненты NaN или бесконечность, хотя этот луч обычно преломляется (k ≥ 0): ищите деление на ноль или неинициализированный вектор.
check-verdict-tir-right = Верно: этот луч испытывает полное внутреннее отражение (k < 0), и ваш код вернул отражённый луч (или нулевой вектор, которым GLSL это сообщает).
check-verdict-tir-but-refracted = Этот луч испытывает полное внутреннее отражение (k = { $k } < 0): преломлённого луча нет, но ваш код его вернул. Проверяйте k, прежде чем извлекать из него корень.
check-verdict-zero-vector = Ваш T — нулевой вектор, который GLSL возвращает при полном внутреннем отражении, но этот луч преломляется (k ≥ 0). Проверьте знак k и отношение показателей преломления.
check-verdict-not-unit = Кроме того, длина вашего T равна { $length }, а не 1: нормируйте W и N перед преломлением (формула предполагает единичные векторы) или T после.
check-verdict-along-refracted = Ваш T направлен вдоль преломлённого луча (с точностью до { $off } рад).
check-verdict-right = Верно: ваш T — преломлённый луч (с точностью до { $off } рад).
check-verdict-ratio-upside-down = Ваш T — преломление с обращённым отношением показателей: μ должно быть μi/μt (среда, которую луч покидает, к той, в которую входит), а ваш код использовал μt/μi.
check-verdict-out-of-plane = Ваш T выходит из плоскости падения (плоскости W и N) на { $off } рад: T должен быть комбинацией a·W + b·N этих двух векторов.
check-verdict-no-candidate = Ваш T не совпадает ни с одним из четырёх вариантов знаков: он отклоняется от преломлённого луча на { $degrees } град. Проверьте μ и направления W и N.

## Чтение t_yours из строки JSON

check-t-yours-item-not-number = `t_yours[{ $index }]` должно быть числом или null
check-t-yours-missing = нет поля `t_yours` (T, который получил ваш код)

## Объяснения вердикта о вызове API (`check --api` и панель): как говорит каждый API

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] книге
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] refract(I, N, eta) из GLSL
    [pbrt] Refract(wi, n, eta) из pbrt
    [rtiow] refract(uv, n, etai_over_etat) из книги
   *[mitsuba] fresnel(cos_theta_i, eta) из Mitsuba вместе с refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, показатель среды, которую луч покидает, к показателю среды, в которую он входит
    [pbrt] показатель на стороне, от которой n направлена, к показателю на стороне, куда она указывает (n_inside/n_outside при внешней нормали)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index на лицевой стороне, refraction_index на обратной)
   *[mitsuba] int_ior/ext_ior, показатель на стороне, от которой направлена нормаль, к показателю на стороне, куда она указывает
}
check-api-incident-means = { $api ->
    [glsl] направление, в котором идёт луч, к поверхности
    [pbrt] направление назад, туда, откуда пришёл луч (-ray.d)
    [rtiow] единичное направление, в котором идёт луч (unit_vector(r_in.direction()))
   *[mitsuba] wi, направленный от поверхности назад вдоль луча (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] GLSL вычитает (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt берёт (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel равен -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] у cos_theta_t знак, противоположный cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] внешнюю нормаль с eta материала (n_inside/n_outside)
    [mitsuba] внешнюю нормаль с eta = int_ior/ext_ior
   *[other] {""}
}

## Объяснения вызова API: части

check-situation-entering = входящего в объект (из n = { $from } в n = { $to })
check-situation-leaving = выходящего из объекта (из n = { $from } в n = { $to })
check-situation-going = идущего из n = { $from } в n = { $to }
check-nothing-zero-vector = нулевой вектор
check-nothing-reflection = отражённый луч
check-nothing-false-or-null = ничего (false или null)
check-and = и
check-or = или
check-field-from-and-to = from и to (или entering с --inside и --outside)
check-normal-fix-rtiow = нормаль из записи о попадании после set_face_normal
check-normal-fix-facing = нормаль, развёрнутая везде, где это скалярное произведение положительно
check-normal-inward-entering = она направлена внутрь объекта, а луч входит
check-normal-inward-leaving = она направлена внутрь объекта, а луч выходит
check-looks-other-root = другой корень, с обратным знаком квадратного корня ({ $hint })
check-looks-wrong-bend = составляющая вдоль поверхности обращена
check-looks-reversed = ответ API с обратным знаком
check-looks-length = то же направление, но длина умножена на { $ratio }: ваш код масштабирует или нормирует иначе
check-looks-reflection = отражённый луч, хотя этот луч преломляется (записывайте только преломление, а не отражение, выбранное по Френелю или Шлику)
check-looks-variant = то, что { $call } возвращает при { $variant }: ваша реализация делает это внутри
check-variant-eta-inverted = обращённом eta
check-variant-normal-flipped = развёрнутой нормали
check-variant-incident-reversed = обращённом падающем векторе
check-looks-nothing = { $what }, то есть ничего не проходит, хотя этот луч преломляется (k = { $k } ≥ 0)
check-looks-not-finite = компоненты NaN или бесконечность, хотя этот луч преломляется
check-looks-off = на { $degrees } град. в стороне от него
check-looks-off-unmeasurable = под углом, который невозможно измерить
check-returned-pbrt-true = true с wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter отражает)
check-returned-mitsuba-reflects = F = 1 (BSDF всегда отражает)
check-unchecked-mu = from и to (или entering с --inside и --outside), чтобы проверить { $eta }
check-unchecked-travel = travel, чтобы проверить, куда указывает { $incident }

## Объяснения вызова API: предложения

check-eta-inverted = В { $owner } { $eta } — это { $means }: вы передали { $value } для луча, { $situation }; передайте 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = В { $owner } { $eta } — это { $means }: вы передали { $value } для этого луча; передайте 1/{ $value } = { $inverse }.
check-incident-reversed = В { $owner } { $incident } — это { $means }; ваш направлен в другую сторону: передайте -{ $incident } = { $reversed }.
check-incident-reversed-travel = В { $owner } { $incident } — это { $means }; ваш направлен в другую сторону (луч идёт вдоль { $travel }): передайте -{ $incident } = { $reversed }.
check-not-unit-input = { $call } предполагает единичные { $incident } и { $normal } и не нормирует их: |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length }; сначала нормируйте их.
check-normal-against = { $call } требует, чтобы { $normal } была направлена против { $incident } (dot({ $normal }, { $incident }) < 0), и не разворачивает её; у вас dot({ $normal }, { $incident }) = { $dot }, как у внешней нормали там, где луч выходит из объекта: передайте -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } принимает { $normal } с любой стороны, но { $eta } должно ей соответствовать: это { $means }. Ваша { $normal } направлена противоположно той, для которой предназначено { $eta } = { $value }{ $inward }; передайте -{ $normal } = { $flipped } с тем же { $eta } (или оставьте { $normal } и передайте 1/{ $eta }).
check-tir-glsl = refract из GLSL здесь возвращает нулевой вектор (k = { $k } < 0: полное внутреннее отражение); проверяйте это и отражайте вместо преломления.
check-tir-pbrt = Refract из pbrt здесь возвращает false (sin2Theta_t = { $sin2 } >= 1: полное внутреннее отражение); отражайте вместо преломления.
check-tir-rtiow = Здесь выполняется cannot_refract из dielectric::scatter (ri * sin_theta = { $sine } > 1): книга отражает, а не вызывает refract.
check-tir-mitsuba = fresnel здесь возвращает F = 1 (cos_theta_t_sqr = { $k } < 0): Mitsuba всегда отражает.
check-tir-got-formula = Ваш код всё равно использовал вектор из формулы, { $vector } длины { $length }: это не луч.
check-tir-got-direction = Ваш код выдал направление, { $vector }, там, где его нет.
check-tir-got-not-finite = Ваш код выдал компоненты NaN или бесконечность (квадратный корень из отрицательного k или normalize() нулевого вектора).
check-result-differs = { $call } возвращает { $returned } для этих аргументов, но вызов дал { $got }: { $detail }. Ваша собственная реализация отличается от API.
check-ties-no-field = Ни одно эталонное поле их не различает: { $call } читает оба одинаково; обычный вызов передаёт { $usual }.
check-ties-give = Укажите { $fields }, чтобы их различить.
check-ties = Столь же возможно: вместо этого { $readings }. { $hint }
check-unchecked = Проверено только по собственным правилам API: укажите { $missing }.
check-unexplained-travel = Записанный { $incident } отклоняется на { $degrees } град. от направления этого луча { $travel }: это не направление этого луча (и не обратное ему).
check-unexplained-eta = { $eta } = { $value } не соответствует ни n_from/n_to = { $mu }, ни обратной величине в том смысле, как его читает { $call }: это не показатели преломления этой границы.
check-unexplained = Никакое сочетание ошибок в аргументах не согласует этот вызов с данным эталоном.
check-right-tir = Верно: { $call } здесь сообщает о полном внутреннем отражении ({ $returned }), и вызов дал { $what }.
check-right-for-ray = Верно: { $call } возвращает { $returned } для этих аргументов, для луча, { $situation }.
check-right = Верно: { $call } возвращает { $returned } для этих аргументов.

## Ошибки вызова API, по одной строке

check-mistake-eta-inverted = отношение показателей обращено для соглашения этого API
check-mistake-incident-reversed = падающий вектор передан в обратную сторону
check-mistake-normal-not-facing = нормаль не с той стороны для этого API (или для переданного eta)
check-mistake-not-the-api-result = результат не тот, что API возвращает для этих аргументов: ваша собственная реализация отличается
check-mistake-missed-tir = направление (или NaN) там, где API сообщает о полном внутреннем отражении
check-mistake-not-unit-input = падающий вектор или нормаль не единичной длины

## Панель: поля этого проекта

check-source-own = W, N, μ (этот проект)
check-code-calls = Ваш код вызывает:
check-convention = Соглашение:
check-convention-along-ray = Раздел 2: W вдоль луча
check-convention-along-ray-about = W — направление, в котором идёт луч, к поверхности (I в GLSL, uv в книге).
check-convention-toward-origin = Раздел 1: W к началу луча
check-convention-toward-origin-about = W направлен назад, туда, откуда пришёл луч (wi в pbrt и Mitsuba).
check-convention-note = { $about } μ = μi/μt; N с любой стороны (ядро само разворачивает её к лучу).
check-paste-hint = Вставьте то, что записал ваш трассировщик лучей. Векторы в виде 0.1, -0.9, 0 или [0.1,-0.9,0] или vec3(0.1, -0.9, 0.0); или вставьте целую строку JSON с t_yours в поле «Ваш T».
check-use-current-case = Взять текущий случай
check-use-current-case-own-hover = Заполнить W, N, μ и соглашение из вида «Одна граница»
check-use-current-case-api-hover = Заполнить аргументы и показатели преломления из вида «Одна граница»
check-your-t = Ваш T
check-your-t-in-error = ваш T
check-button = Проверить
check-field-not-number = { $field }: «{ $text }» — не число
check-student-own = ваш T: { $verdict }
check-headline-own = Ваш T: { $verdict }
check-match-refracted = преломлённый луч T
check-match-not-unit = направление T, но не единичной длины
check-match-wrong-side = не та сторона (другой корень для b)
check-match-wrong-bend = неверное отклонение (другой знак a)
check-match-reversed = обращён (−T: оба знака неверны)
check-match-tir = полное внутреннее отражение, ответ верный
check-match-none = ни один из четырёх кандидатов
check-no-refracted-ray = Преломлённого луча нет: полное внутреннее отражение.
check-right-t = Правильный T = { $t }
check-copy-right-t = Скопировать T
check-not-drawn-changed = (Случай с тех пор изменился: вердикт не нарисован.)

## Панель: вызов API

check-drawn-incident = { $api ->
    [glsl] I (направление распространения)
    [pbrt] wi (назад к началу луча)
    [rtiow] uv (направление распространения)
   *[mitsuba] wi (от поверхности)
}
check-drawn-about = { $api ->
    [glsl] I — направление, в котором идёт луч, нарисовано как W вдоль луча (раздел 2). N должна быть направлена против I: GLSL её не разворачивает. eta = n_from/n_to = μi/μt. Нулевой вектор означает полное внутреннее отражение.
    [pbrt] wi направлен назад, туда, откуда пришёл луч (−ray.d), нарисован как W к началу луча (раздел 1). n может быть с любой стороны: pbrt разворачивает её и обращает eta, когда wi под ней. eta = показатель за n к показателю перед ней (μt/μi при n, обращённой к wi). false означает полное внутреннее отражение.
    [rtiow] uv — единичное направление, в котором идёт луч, нарисовано как W вдоль луча (раздел 2). n должна быть направлена против uv (front_face). etai_over_etat = n_from/n_to = μi/μt. refract не проверяет полное внутреннее отражение: отражает cannot_refract вызывающего кода.
   *[mitsuba] wi направлен от поверхности назад вдоль луча, нарисован как W к началу луча (раздел 1). n равна +z (локальная система координат), если поле пустое. eta = int_ior/ext_ior, показатель за n к показателю перед ней (μt/μi при n, обращённой к wi). F = 1 означает полное внутреннее отражение: wo равен null.
}
check-convention-about = Соглашение: { $about }
check-your-call = Ваш вызов
check-truth = Эталон (необязательно)
check-picture-outside = μ = { $mu } требует показателей вне диапазона программы { $low }…{ $high }
check-student-api = ваш { $result }: { $verdict }
check-student-right = верно
check-student-wrong = неверно
check-api-right-headline = Верно: что { $signature } означает для этого луча
check-api-mistakes = Ошибки: { $codes }
check-api-unexplained-headline = Ни одна отдельная ошибка этого не объясняет
check-api-returns = Результат в { $owner }: { $value }
check-api-drawn = Нарисовано: правильный вызов, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = Не нарисовано: { $why }.
check-copy-as-test = Скопировать как модульный тест:

## Панель: вставленные строки журнала

check-paste-lines = 📋 Вставить строки журнала
check-pattern = Шаблон
check-log-lines = Строки журнала
check-lines-button = Проверить строки
check-read-as-pattern = шаблон
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (первая строка — заголовок)
check-bulk-summary = Прочитано как { $read_as }: { $count ->
    [one] { $count } вызов
    [few] { $count } вызова
    [many] { $count } вызовов
   *[other] { $count } вызова
}
check-bulk-left-out = { $count ->
    [one] { $count } строка после первых { $first } пропущена
    [few] { $count } строки после первых { $first } пропущены
    [many] { $count } строк после первых { $first } пропущены
   *[other] { $count } строки после первых { $first } пропущены
}
check-column-line = строка
check-column-ok = ok
check-column-mistakes = ошибки
check-column-explanation = объяснение
check-row-line = строка { $line }
check-row-open-hover = Открыть этот вызов в панели и на схеме
check-row-error = ошибка

## Чтение полей вызова, строки CSV, шаблона и вектора (эти сообщения показывает и панель)

check-field-not-three = `{ $field }` должно содержать ровно 3 числа, а содержит { $count }
check-field-not-a-vector = `{ $field }` должно быть массивом из 3 чисел или строкой вида «0.1, -0.9, 0»
check-field-not-flag-got = `{ $field }` должно быть true/false или 1/0, а не «{ $text }»
check-field-not-number-json = `{ $field }` должно быть числом
check-field-not-flag = `{ $field }` должно быть true/false или 1/0
check-field-not-label = `{ $field }` должно быть строкой или числом
check-json-not-object = ожидается объект JSON с полями { $fields }
check-unknown-field = неизвестное поле `{ $field }`
check-field-not-vector = `{ $field }` должно состоять из 3 чисел
check-field-missing = нет поля `{ $field }` ({ $what })
check-what-normal = нормаль к поверхности
check-what-incident = падающий вектор
check-what-eta = отношение показателей
check-field-not-finite = `{ $field }` должно быть конечным, а равно { $value }
check-field-zero-vector = `{ $field }` — нулевой вектор
check-field-not-positive = `{ $field }` должно быть конечным числом > 0, а равно { $value }
check-from-and-to-together = `from` и `to` задаются вместе: укажите оба или ни одного
check-travel-not-finite = `travel` должен быть конечным ненулевым вектором
check-result-null = `{ $field }` равно null, хотя `{ $returned }` равно true
check-result-missing = нет поля `{ $field }` (что вернул вызов{ $api ->
    [pbrt] , или "returned": false
    [mitsuba] , null при отражении
   *[other] {""}
})
check-unknown-precision = неизвестная точность «{ $text }»: ожидается "f32" или "f64"
check-too-large = { $value } слишком велико для { $precision }
check-csv-unclosed-quote = незакрытая кавычка в строке CSV
check-csv-no-column = в заголовке CSV нет столбца `{ $field }`: в нём { $names }; ожидается { $expected }
check-csv-partial-vector = в заголовке CSV есть только { $count } из 3 компонент `{ $field }`
check-csv-duplicate-column = в заголовке CSV `{ $column }` указан больше одного раза
check-csv-cells = { $count ->
    [one] { $count } ячейка
    [few] { $count } ячейки
    [many] { $count } ячеек
   *[other] { $count } ячейки
}, а в заголовке { $columns ->
    [one] { $columns } столбец
    [few] { $columns } столбца
    [many] { $columns } столбцов
   *[other] { $columns } столбца
}
check-csv-no-header = нет пригодного заголовка CSV: { $reason }
check-pattern-unclosed = незакрытая `{"{"}` в шаблоне «{ $pattern }»
check-pattern-adjacent = два поля подряд без разделителя в шаблоне «{ $pattern }»
check-pattern-twice = поле {"{"}{ $field }{"}"} названо дважды в шаблоне «{ $pattern }»: назовите каждое поле один раз
check-pattern-too-many = в шаблоне { $count } заполнителей: читается не более { $limit }
check-pattern-too-long = длина шаблона { $bytes } байт: читается не более { $limit }
check-pattern-no-field = шаблон «{ $pattern }» не называет ни одного поля
check-pattern-unknown-field = неизвестное поле {"{"}{ $field }{"}"} в шаблоне для --api { $api }: ожидается {"{"}_{"}"} или одно из { $expected }
check-line-not-matching = строка не соответствует шаблону
check-tally-skipped = пропущено (не соответствует шаблону)
check-tally-unreadable = не прочитано
check-tally-unexplained = не объяснено
check-word-not-a-number = «{ $word }» — не число
check-vector-expected-named = ожидается `{ $expected }: <число>`, найдено «{ $found }»
check-vector-within = { $error } (в «{ $text }»)
check-vector-not-three = ожидаются 3 числа, например `0.1, -0.9, 0` или `vec3(0.1, -0.9, 0.0)`, найдено { $count } в «{ $text }»

# Ошибки, видимые в результате
check-mistake-no-flip-inside = для луча с обратной стороны нормали код не разворачивает нормаль и не обращает отношение
check-mistake-normal-term-sign = составляющая результата вдоль нормали имеет неверный знак; поперечная составляющая верна
check-mistake-other-root = другой корень: знак квадратного корня обращён, результат отражён относительно поверхности
check-mistake-false-tir = полное внутреннее отражение указано там, где луч преломляется
check-diagnosis-no-lines = Ни одна строка не проверена (прочитано: { $lines }): проверьте шаблон, заголовок CSV или поля строк; check --suggest-pattern читает первые строки журнала и предлагает шаблон.
check-physics-explained = Именно это даёт преломление с такой ошибкой: { $mistakes }.
check-looks-normal-term = ответ API с обращённой составляющей вдоль нормали: член вдоль нормали вычитается вместо сложения или наоборот
check-looks-no-flip = то, что даёт формула без разворота нормали и обращения eta для луча с обратной стороны нормали
check-looks-etap = верное направление, но etap = { $logged }, тогда как вызов использовал { $used }

# Диагноз всего журнала: где видна ошибка и как её исправить
check-where-every = { $count ->
    [1] в единственной проверенной строке
   *[other] во всех проверенных строках ({ $count })
}
check-where-inside = { $count ->
    [1] в единственной строке с лучом изнутри и ни в одной с лучом снаружи
   *[other] во всех строках с лучом изнутри ({ $count }) и ни в одной с лучом снаружи
}
check-where-outside = { $count ->
    [1] в единственной строке с лучом снаружи и ни в одной с лучом изнутри
   *[other] во всех строках с лучом снаружи ({ $count }) и ни в одной с лучом изнутри
}
check-where-past-critical = { $count ->
    [1] в единственной строке за предельным углом и ни в одной другой
   *[other] во всех строках за предельным углом ({ $count }) и ни в одной другой
}
check-where-some-sides = в { $count } из { $all } проверенных строк ({ $inside } изнутри, { $outside } снаружи)
check-where-some = в { $count } из { $all } проверенных строк
check-fix-pass = передавайте `{ $code }`
check-fix-write = пишите `{ $code }`
check-fix-restore = верните `{ $code }`
check-fix-generic-eta-inverted = используйте μ = n_from / n_to, показатель среды, которую луч покидает, к показателю среды, в которую он входит: он обращается там, где луч выходит из объекта (там μ = n_внутри / n_снаружи; при входе μ = n_снаружи / n_внутри)
check-fix-generic-incident-reversed = передавайте как W направление распространения луча, а не противоположное
check-fix-generic-normal-not-facing = там, где луч выходит из объекта, используйте в каждом члене нормаль, обращённую к лучу (внешнюю, развёрнутую), или внешнюю с обращённым знаком, но не то и другое вместе
check-fix-generic-no-flip-inside = для луча изнутри разверните нормаль и обратите отношение перед преломлением
check-fix-generic-normal-term-sign = прибавляйте член вдоль нормали: T = μ·W + (μ·cosθi − cosθt)·N, где N обращена к лучу
check-fix-generic-other-root = дайте части T вдоль нормали, обращённой к лучу, знак, уводящий T через поверхность: −cosθt (знак переменной с cosθt или знак, взятый у cosθi, обращён)
check-fix-generic-missed-tir = отражайте, когда k = 1 − μ²·(1 − cos²θi) отрицательно, до извлечения квадратного корня
check-fix-generic-false-tir = сообщайте о полном внутреннем отражении только там, где k = 1 − μ²·(1 − cos²θi) отрицательно
check-fix-generic-not-unit-input = нормируйте W и N перед преломлением
check-fix-generic-not-the-api-result = ни одна ошибка формулы, ни пара ошибок не воспроизводит эти строки: объяснение каждой строки говорит, что вернулось и каков правильный T
check-physics-no-indices = нет показателей преломления: укажите `mu_i` и `mu_t` или `entering` вместе с --inside и --outside
check-physics-unknown-convention = неизвестное соглашение "{ $text }": ожидалось "along_ray" или "toward_origin"
check-diagnosis-none = Ошибок нет: журнал верен { $place }.
check-diagnosis-verdict = Ошибка: { $code } ({ $meaning }), { $place }. Исправление: { $fix }.
check-diagnosis-also = Кроме того: { $code } ({ $meaning }), { $place }. Исправление: { $fix }.
check-diagnosis-alike = По журналу её нельзя отличить от { $alike }; запишите { $fields }, чтобы различить их.
check-pattern-too-many-lines = шаблон занимает { $count } строк: читается не более { $limit }
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} обращает флаг, а { $field } не флаг: пишите {"{"}!entering{"}"} для флага, напечатанного наоборот (inside, backfacing)
check-suggest-toward-origin = падающий вектор напечатан как wi и направлен обратно к началу луча: добавьте --convention toward-origin
check-suggest-no-normal = нормаль не напечатана: если это ось z локальной системы (Mitsuba, Tungsten), добавьте --normal +z
check-suggest-no-side = ничто напечатанное не говорит, входит ли луч в объект: напечатайте это ({"{"}entering{"}"} или {"{"}!entering{"}"} для флага вроде backfacing) и передайте --inside и --outside, иначе отношение не проверить
check-suggest-none = ни одна из первых { $lines } строк не похожа на преломление (падающий вектор, отношение и результат, каждый после своего имени): напишите --pattern вручную (docs/check.md)
check-situation-outward = считая { $normal } внешней нормалью: индексы ничего не говорят о стороне
check-right-sampled = Верно как выбранное отражение: { $call } здесь преломляет ({ $returned }), но Mitsuba отражает с вероятностью F = { $f }, и пустой wo говорит, что отразил. Диагноз всего журнала проверяет, что код пропускает луч при этих углах в других строках.
check-physics-sampled = Там, где луч преломляется, ничего не вернулось: верно как отражение, выбранное с вероятностью F = { $f }, как его пишут рендереры, случайно выбирающие отражение или преломление. Диагноз всего журнала проверяет, что код пропускает луч при этих углах в других строках.
check-fix-in = { $fix } (в { $place })
check-fix-part = { $part }; { $fix }
check-sides-entering = {" "}для лучей, входящих в объект
check-sides-leaving = {" "}для лучей, выходящих из объекта
check-part-ratio = T преломлён с обращённым отношением{ $sides }: 1/μ во всех частях, и в проверке полного внутреннего отражения (переменная с μ или тернарный оператор, выбирающий её)
check-part-across = часть T поперёк N умножена на 1/μ вместо μ (1/μ² от верной){ $sides }, а часть вдоль N верна: отношение, умножающее падающий вектор, обращено
check-part-along = часть T вдоль N, cosθt = √(1 − μ²·sin²θi), получена из 1/μ вместо μ{ $sides } (и проверка полного внутреннего отражения тоже), а часть поперёк N верна: отношение в cosθt обращено
check-part-normal = часть T вдоль N имеет не тот знак{ $sides }: использованная нормаль не обращена к лучу
check-part-incident = часть T поперёк N имеет не тот знак (зеркальный образ T относительно нормали, преломляется не туда): падающий вектор входит в формулу наоборот
check-part-root = часть T вдоль N имеет не тот знак: cosθt поставлен на сторону, откуда идёт луч, и T остаётся в своей среде (другой корень)
check-part-term = член вдоль N, (μ·cosθi − cosθt)·N, вычитается там, где его нужно прибавить{ $sides }; часть поперёк N верна
check-part-no-flip = для лучей с обратной стороны нормали ни нормаль не развёрнута, ни отношение не обращено: T — другой корень при 1/μ
check-fix-generic-ratio-across = умножайте часть падающего вектора поперёк N на μ = n_from / n_to, то же отношение, с которым вычислен cosθt
check-fix-generic-ratio-along = вычисляйте cosθt = √(1 − μ²·sin²θi) с μ = n_from / n_to, тем же отношением, что масштабирует часть поперёк N (косинус, переданный со знаком, заставляет вспомогательную функцию обратить отношение ещё раз)
check-fix-generic-across-sign = часть поперёк N — это μ, умноженное на такую же часть падающего вектора (μ·(W + cosθi·N), W вдоль луча): берите её со знаком падающего вектора
check-fix-generic-never-transmits = код никогда не пропускает эти лучи, хотя они преломляются: если он выбирает отражение случайно, его вероятность (F, отражательная способность по Френелю) должна быть там меньше 1; сообщайте о полном внутреннем отражении только там, где k = 1 − μ²·(1 − cos²θi) отрицательно
check-diagnosis-unchecked = Нельзя проверить, не зная, с какой стороны идёт каждый луч, { $place }: каждая строка верна по правилам своего API, но ничто в журнале и в параметрах не отличает верное отношение от неверного. { $fix }.
check-diagnosis-alike-no-field = Журнал не может отличить это от { $alike }.
check-unchecked-log-entering = Пишите entering в каждой строке (true, когда луч входит в объект; {"{"}!entering{"}"} читает флаг вроде inside или backfacing) или from и to
check-unchecked-pass-indices = Передайте --inside и --outside (индексы внутри и снаружи объекта) с записанным entering, а для pbrt и Mitsuba — с внешней нормалью; или пишите from и to
check-mistake-across-sign = часть результата поперёк нормали имеет не тот знак; часть вдоль неё верна (зеркальный образ результата относительно нормали)
check-part-across-sign = часть T поперёк N имеет не тот знак (зеркальный образ T относительно нормали, преломляется не туда), а часть вдоль N верна: потерян минус перед отношением, умноженным на падающий вектор
check-tally-sampled = отражено (выбрано случайно)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } строк журнала не удалось прочитать (на каждую дан ответ с её ошибкой), а среди прочитанных ошибок нет: это не успех; исправьте эти строки или способ их чтения.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = журнал в формате JSON Lines, ключи которого называют поля: шаблон не нужен

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = По напечатанным цифрам не понять: в напечатанном виде вызов похож на { $shown }, но числа в пределах их округления делают его верным (знак, от которого зависит вердикт, — N·I, k или корня — ближе к нулю, чем показывают цифры). Печатайте больше цифр, чтобы его оценить.
check-diagnosis-too-few-digits = По напечатанным цифрам не понять, верны они или нет, { $place }: каждая неверна в напечатанном виде, но верна для чисел в пределах их округления; цифр лога слишком мало, чтобы решить (знак, от которого зависит вердикт, — N·I, k = 1 − η²·(1 − (N·I)²) или корня — может быть ближе к нулю, чем они показывают). Точность лога слишком мала: { $fix }.
check-too-few-digits-fix = печатайте каждое число хотя бы с 6 значащими цифрами (printf в C или в шейдере: %.6g; C#: ToString("G9"), Vector3 в Unity: ToString("F6"); потоки C++: std::setprecision(9); Rust: {"{"}:?{"}"}; Python: repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 прочитаны из отношения, которое печатают строки, для объекта плотнее того, что его окружает (стекло или вода в воздухе): укажите индексы вашей сцены, если они другие
check-diagnosis-none-judged = Ни одну из { $lines } строк, прочитанных шаблоном, не удалось оценить, так что дело не в шаблоне; первая сообщает: { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 — это стекло в воздухе, принятое, потому что строки не печатают отношения: укажите индексы вашей сцены, если они другие

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` напечатан по одному числу в строке (как cout << v в Eigen печатает вектор): его строки нельзя надёжно соединить; печатайте каждый вектор в одной строке (Eigen: v.transpose(); nalgebra: v.transpose() или {"{"}:?{"}"}; numpy: np.array2string(v, max_line_width=1000) или v.tolist())
check-suggest-column-vectors = первые { $lines } строк печатают векторы по одному числу в строке (как cout << v в Eigen), что ни один шаблон не может надёжно соединить: печатайте каждый вектор в одной строке (Eigen: v.transpose(); nalgebra: v.transpose() или {"{"}:?{"}"}; numpy: v.tolist()), каждый после своего имени, и спросите снова

# check: составные ошибки, названные причинами (issue 43, пункт 4)
check-mistake-refracted-twice = преломлён дважды при одном пересечении поверхности: T — то, что даёт квадрат отношения (μ²)
check-mistake-fresnel-cos-sign = код никогда не пропускает луч, ни при каком угле, хотя k > 0: знак косинуса потерян там, где вычисляется коэффициент отражения Френеля (или выбор пропустить луч)
check-mistake-normals-mixed = сторона определяется по одной нормали (геометрической), а в refract передаётся другая (нормаль затенения), развёрнутая по этому решению: где они расходятся, переданная нормаль не обращена к лучу
check-fix-generic-refracted-twice = вызывайте refract один раз на каждое пересечение поверхности: здесь T преломляется ещё раз (или μ применяется дважды), как с μ² = (n_откуда / n_куда)²; сохраните первое T и проследите луч до следующей поверхности
check-fix-generic-fresnel-cos-sign = проверка полного внутреннего отражения ни при чём (ниже 15° никакое отношение не делает k отрицательным): там, где вычисляется F или выбор пропустить луч, берите cosθi без знака, |N·I| (или −N·I с N, обращённой к лучу); отрицательный косинус даёт F ≥ 1, и луч всегда отражается
check-fix-generic-normals-mixed = определяйте сторону (entering, отношение) и разворачивайте нормаль для refract по одной и той же нормали: по нормали затенения в обоих случаях или по геометрической в обоих (геометрическая остаётся для смещения начала луча)
check-fix-normals-print = Если код определяет сторону по другой нормали, чем та, что он передаёт (геометрическая рядом с нормалью затенения), выводите в журнал и `entering`: тогда диагностика сможет их различить.
