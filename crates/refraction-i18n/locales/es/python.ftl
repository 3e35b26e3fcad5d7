# python.ftl (es): el paquete de Python refraction_check: por qué se rechaza un argumento de
# check() (su ValueError), y el texto breve y la tabla del cuaderno que muestran lo hallado.

## Argumentos rechazados

python-unknown-api = api: API desconocida '{ $name }': se espera 'glsl' (o 'hlsl', 'wgsl', 'glm', 'glam'), 'pbrt', 'rtiow', 'mitsuba', o None para la refracción propia de cualquier renderizador
python-unknown-argument = argumento desconocido `{ $argument }` para api={ $api }: los campos de una llamada son { $fields } (`from` se escribe from_), y las opciones inside, outside, normal, convention, precision y renderer
python-index = { $argument } debe ser un número finito > 0 (un índice de refracción), no { $value }
python-sides-apart = { $given } sin { $missing }: da ambos índices, o ninguno
python-not-with-api = { $argument } es para la refracción propia de cualquier renderizador (api=None): las llamadas de api='{ $api }' siguen la convención de esa API, con su normal en un campo propio
python-normal = normal debe ser un eje ('+z', '-y'...) o tres números finitos distintos de cero, no { $value }
python-unknown-word = { $argument }: valor desconocido '{ $value }': se espera uno de { $expected }
python-shape = { $argument } tiene forma { $shape }: se espera { $expected }, N el número de llamadas
python-not-numbers = { $argument } debe contener números: { $reason }
python-not-flag = { $argument } debe contener True/False o 1/0, no { $value } (fila { $row })
python-rows = { $argument } tiene { $rows ->
    [one] una fila
   *[other] { $rows } filas
} pero { $other } tiene { $other_rows }: da a cada argumento una fila por llamada, o un valor para todas las llamadas
python-no-rows = { $argument } no tiene filas: no hay ninguna llamada que comprobar
python-nothing-judged = { $calls ->
    [one] La llamada no se puede juzgar
   *[other] Ninguna de las { $calls } llamadas se puede juzgar
}: { $reason }

## Lo hallado

python-title = { $calls ->
    [one] 1 llamada
   *[other] { $calls } llamadas
}, { $ok } correctas
python-column-code = código
python-column-calls = llamadas
python-column-row = fila
python-column-explanation = explicación
python-first-wrong = { $wrong ->
    [one] La llamada errónea:
   *[other] Las primeras { $shown } de { $wrong } llamadas erróneas:
}
