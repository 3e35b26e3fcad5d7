## Доступность: что программа чтения с экрана говорит о программе, кнопки рядом со схемой и элементы управления страницы в браузере

access-degrees = { $angle }°
access-normal-up = вертикально вверх
access-normal-down = вертикально вниз
access-normal-right = на { $angle }° правее вертикали
access-normal-left = на { $angle }° левее вертикали
access-index-named = { $index } ({ $name })
access-media = Луч идёт в первой среде ({ $from }) и падает на вторую ({ $to }).
access-medium-named = { $name }, { $symbol } = { $index }
access-medium-custom = { $symbol } = { $index }
access-incidence-sentence = Он падает на границу под углом θi = { $angle }° к нормали.
access-incidence-along-normal = Он падает на границу вдоль нормали: θi = 0°.
access-normal-sentence = Направление нормали N: { $direction }.
access-tir = Полное внутреннее отражение: θi больше предельного угла θc = { $critical }°, поэтому преломлённого луча нет и весь свет отражается.
access-t-along-normal = T идёт прямо вдоль нормали: он не отклоняется.
access-t-straight = T идёт прямо, под углом { $angle }° к нормали: он не отклоняется.
access-t-toward = T отклоняется к нормали, угол с ней { $angle }°.
access-t-away = T отклоняется от нормали, угол с ней { $angle }°.
access-reflected = Отражённый луч уходит под углом { $angle }° к нормали, по другую сторону от неё.
access-critical = Предельный угол θc = { $critical }°.
access-flipped = N направлена от падающего луча, поэтому ядро использует −N.
access-sentence = { $text }.
access-change-value = { $name } { $before } → { $after }
access-change = { $changes }: { $outcome }.
access-change-tir-begins = теперь больше предельного угла { $critical }°; весь свет отражается
access-change-tir-ends = теперь меньше предельного угла { $critical }°; T уходит под углом { $angle }° к нормали
access-change-t = T под углом { $angle }° к нормали
access-step = Шаг { $number } из { $count }: { $title }.
access-question = Вопрос: { $question }
access-view = Вид: { $view }.
access-scene = Сцена: { $title }.
access-scene-hidden = Её лучи нарисованы до первой поверхности, которую они встречают.
access-incidence-decrease = Уменьшить θi на 1°
access-incidence-increase = Увеличить θi на 1°
access-normal-turn-left = Повернуть N на 1° влево
access-normal-turn-right = Повернуть N на 1° вправо
access-index-decrease = Уменьшить { $symbol } на { $step }
access-index-increase = Увеличить { $symbol } на { $step }
access-page-controls = Элементы управления схемой
access-page-keys = В программе ниже Tab переходит между её кнопками и полями, а стрелки поворачивают выбранный маркер; Esc, затем Shift+Tab возвращает к этим элементам.
access-page-typing = Текст, который вводится в программу
access-title-scene = { $view }: { $scene }
