# python.ftl (ru): пакет Python refraction_check: почему аргумент check() отклонён (его
# ValueError), и краткий текст и таблица в блокноте, показывающие найденное.

## Отклонённые аргументы

python-unknown-api = api: неизвестный API '{ $name }': ожидается 'glsl' (или 'hlsl', 'wgsl', 'glm', 'glam'), 'pbrt', 'rtiow', 'mitsuba' или None для собственного преломления любого рендерера
python-unknown-argument = неизвестный аргумент `{ $argument }` для api={ $api }: поля вызова: { $fields } (`from` пишется как from_), а параметры: inside, outside, normal, convention, precision и renderer
python-index = { $argument } должен быть конечным числом > 0 (показатель преломления), а не { $value }
python-sides-apart = { $given } без { $missing }: укажите оба показателя или ни одного
python-not-with-api = { $argument } относится к собственному преломлению любого рендерера (api=None): вызовы api='{ $api }' следуют соглашению этого API, а нормаль передают в своём поле
python-normal = normal должна быть осью ('+z', '-y'...) или тремя конечными числами, не всеми нулевыми, а не { $value }
python-unknown-word = { $argument }: неизвестное значение '{ $value }': ожидается одно из { $expected }
python-shape = у { $argument } форма { $shape }: ожидается { $expected }, где N — число вызовов
python-not-numbers = { $argument } должен содержать числа: { $reason }
python-not-flag = { $argument } должен содержать True/False или 1/0, а не { $value } (строка { $row })
python-rows = у { $argument } { $rows ->
    [one] { $rows } строка
    [few] { $rows } строки
    [many] { $rows } строк
   *[other] { $rows } строки
}, а у { $other } — { $other_rows }: дайте каждому аргументу по строке на вызов или одно значение для всех вызовов
python-no-rows = у { $argument } нет строк: проверять нечего
python-nothing-judged = { $calls ->
    [1] Вызов не может быть оценён
    [one] Ни один из { $calls } вызова не может быть оценён
   *[other] Ни один из { $calls } вызовов не может быть оценён
}: { $reason }

## Найденное

python-title = { $calls ->
    [one] { $calls } вызов
    [few] { $calls } вызова
    [many] { $calls } вызовов
   *[other] { $calls } вызова
}, верных: { $ok }
python-column-code = код
python-column-calls = вызовы
python-column-row = строка
python-column-explanation = объяснение
python-first-wrong = { $wrong ->
    [1] Неверный вызов:
    [one] Первые { $shown } из { $wrong } неверного вызова:
   *[other] Первые { $shown } из { $wrong } неверных вызовов:
}
