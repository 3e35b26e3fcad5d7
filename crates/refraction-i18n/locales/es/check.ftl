# check.ftl (es): los textos de «Comprobar mi T»: el panel, sus veredictos y sus explicaciones.

## Números y vectores en las explicaciones

check-number-not-finite = no finito (NaN o infinito)
check-vector-not-finite = un vector no finito (componentes NaN o infinitas)

## Veredictos sobre una T en los campos de este proyecto (también las explicaciones de la orden `check`)

check-verdict-wrong-side = Tu T vuelve al medio del que venía el rayo: es la otra raíz para b (+ donde la raíz cuadrada necesita -). La causa habitual es una normal que apunta en el sentido del rayo, como la normal exterior de una esfera donde el rayo sale de ella, usada sin invertirla.
check-verdict-wrong-bend = Tu T se desvía hacia el lado equivocado: el signo de a está invertido, así que no se convertiría en el rayo incidente cuando μ → 1. La causa habitual es mezclar las convenciones: W apuntando hacia el origen (Sección 1, a = −μ) usado en la fórmula de W a lo largo del rayo (Sección 2, a = +μ), o al revés.
check-verdict-reversed = Tu T es -T y apunta hacia donde venía el rayo: ambos signos están mal. La causa habitual es devolver la dirección hacia el origen en lugar de la dirección de propagación, o negar W dos veces.
check-verdict-not-finite-tir = Tu T tiene componentes NaN o infinitas. Este rayo sufre reflexión total (k < 0): tu código tomó la raíz cuadrada de un k negativo en lugar de comprobar k antes.
check-verdict-not-finite-refracts = Tu T tiene componentes NaN o infinitas aunque este rayo se refracta con normalidad (k ≥ 0): busca una división por cero o un vector sin inicializar.
check-verdict-tir-right = Correcto: este rayo sufre reflexión total (k < 0) y tu código devolvió la reflexión (o el vector nulo con el que GLSL lo indica).
check-verdict-tir-but-refracted = Este rayo sufre reflexión total (k = { $k } < 0): no hay rayo refractado, pero tu código devolvió uno. Comprueba k antes de tomar su raíz cuadrada.
check-verdict-zero-vector = Tu T es el vector nulo, que GLSL devuelve en la reflexión total, pero este rayo se refracta (k ≥ 0). Comprueba el signo de k y el cociente de índices.
check-verdict-not-unit = Además, tu T tiene longitud { $length }, no 1: normaliza W y N antes de refractar (la fórmula supone vectores unitarios) o T después.
check-verdict-along-refracted = Tu T apunta a lo largo del rayo refractado (con { $off } rad de diferencia como mucho).
check-verdict-right = Correcto: tu T es el rayo refractado (con { $off } rad de diferencia como mucho).
check-verdict-ratio-upside-down = Tu T es la refracción con el cociente de índices al revés: μ debe ser μi/μt (el medio que deja el rayo entre aquel en el que entra), y tu código usó μt/μi.
check-verdict-out-of-plane = Tu T sale del plano de incidencia (el plano de W y N) en { $off } rad: T debe ser una combinación a·W + b·N de ambos.
check-verdict-no-candidate = Tu T no coincide con ninguna de las cuatro elecciones de signo: está a { $degrees } grados del rayo refractado. Comprueba μ y hacia dónde apuntan W y N.

## Lectura de t_yours en una línea JSON

check-t-yours-item-not-number = `t_yours[{ $index }]` debe ser un número o null
check-t-yours-missing = falta el campo `t_yours` (la T que produjo tu código)

## Explicaciones de un veredicto sobre una llamada a una API (`check --api` y el panel): cómo habla cada API

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] el libro
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] refract(I, N, eta) de GLSL
    [pbrt] Refract(wi, n, eta) de pbrt
    [rtiow] refract(uv, n, etai_over_etat) del libro
   *[mitsuba] fresnel(cos_theta_i, eta) de Mitsuba con refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, el índice del medio que deja el rayo entre el del medio en el que entra
    [pbrt] el índice del lado del que n se aleja entre el índice del lado hacia el que apunta (n_inside/n_outside con la normal exterior)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index en una cara frontal, refraction_index en una cara trasera)
   *[mitsuba] int_ior/ext_ior, el índice del lado del que la normal se aleja entre el índice del lado hacia el que apunta
}
check-api-incident-means = { $api ->
    [glsl] la dirección en la que viaja el rayo, hacia la superficie
    [pbrt] la dirección de vuelta hacia donde venía el rayo (-ray.d)
    [rtiow] la dirección unitaria en la que viaja el rayo (unit_vector(r_in.direction()))
   *[mitsuba] wi, que se aleja de la superficie de vuelta a lo largo del rayo (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] GLSL resta (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt toma (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel es -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] cos_theta_t tiene el signo opuesto a cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] la normal exterior con la eta del material (n_inside/n_outside)
    [mitsuba] la normal exterior con eta = int_ior/ext_ior
   *[other] {""}
}

## Explicaciones de una llamada a una API: las piezas

check-situation-entering = que entra en el objeto (de n = { $from } a n = { $to })
check-situation-leaving = que sale del objeto (de n = { $from } a n = { $to })
check-situation-going = que va de n = { $from } a n = { $to }
check-nothing-zero-vector = el vector nulo
check-nothing-reflection = la reflexión
check-nothing-false-or-null = nada (false o null)
check-and = y
check-or = o
check-field-from-and-to = from y to (o entering con --inside y --outside)
check-normal-fix-rtiow = la normal del registro de impacto tras set_face_normal
check-normal-fix-facing = la normal invertida allí donde ese producto escalar es positivo
check-normal-inward-entering = apunta hacia dentro del objeto, y el rayo está entrando
check-normal-inward-leaving = apunta hacia dentro del objeto, y el rayo está saliendo
check-looks-other-root = la otra raíz, con el signo de la raíz cuadrada invertido ({ $hint })
check-looks-wrong-bend = la parte a lo largo de la superficie invertida
check-looks-reversed = la respuesta de la API con el signo cambiado
check-looks-length = la misma dirección con { $ratio } veces la longitud: tu código escala o normaliza de otra manera
check-looks-reflection = la reflexión, aunque este rayo se refracta (registra solo la refracción, no una reflexión elegida por Fresnel o Schlick)
check-looks-variant = lo que devuelve { $call } con { $variant }: tu implementación hace eso por dentro
check-variant-eta-inverted = eta invertida
check-variant-normal-flipped = la normal invertida
check-variant-incident-reversed = el vector incidente al revés
check-looks-nothing = { $what }, que indica que no se transmite nada, aunque este rayo se refracta (k = { $k } ≥ 0)
check-looks-not-finite = componentes NaN o infinitas, aunque este rayo se refracta
check-looks-off = a { $degrees } grados de ella
check-looks-off-unmeasurable = a un ángulo que no se puede medir
check-returned-pbrt-true = true con wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter refleja)
check-returned-mitsuba-reflects = F = 1 (el BSDF siempre refleja)
check-unchecked-mu = from y to (o entering con --inside y --outside) para comprobar { $eta }
check-unchecked-travel = travel para comprobar hacia dónde apunta { $incident }

## Explicaciones de una llamada a una API: las frases

check-eta-inverted = En { $owner }, { $eta } es { $means }: pasaste { $value } para un rayo { $situation }; pasa 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = En { $owner }, { $eta } es { $means }: pasaste { $value } para este rayo; pasa 1/{ $value } = { $inverse }.
check-incident-reversed = En { $owner }, { $incident } es { $means }; el tuyo apunta al revés: pasa -{ $incident } = { $reversed }.
check-incident-reversed-travel = En { $owner }, { $incident } es { $means }; el tuyo apunta al revés (el rayo viaja a lo largo de { $travel }): pasa -{ $incident } = { $reversed }.
check-not-unit-input = { $call } supone { $incident } y { $normal } unitarios y no los normaliza: |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length }; normalízalos antes.
check-normal-against = { $call } necesita { $normal } opuesta a { $incident } (dot({ $normal }, { $incident }) < 0) y no la invierte; la tuya tiene dot({ $normal }, { $incident }) = { $dot }, como una normal exterior donde el rayo sale del objeto: pasa -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } acepta { $normal } en cualquier lado, pero { $eta } debe ir de acuerdo con ella: es { $means }. Tu { $normal } apunta al lado contrario de aquella para la que era { $eta } = { $value }{ $inward }; pasa -{ $normal } = { $flipped } con la misma { $eta } (o conserva { $normal } y pasa 1/{ $eta }).
check-tir-glsl = El refract de GLSL devuelve aquí el vector nulo (k = { $k } < 0: reflexión total); compruébalo y refleja en su lugar.
check-tir-pbrt = El Refract de pbrt devuelve aquí false (sin2Theta_t = { $sin2 } >= 1: reflexión total); refleja en su lugar.
check-tir-rtiow = Aquí se cumple cannot_refract de dielectric::scatter (ri * sin_theta = { $sine } > 1): el libro refleja en lugar de llamar a refract.
check-tir-mitsuba = fresnel devuelve aquí F = 1 (cos_theta_t_sqr = { $k } < 0): Mitsuba siempre refleja.
check-tir-got-formula = Tu código usó de todos modos el vector de la fórmula, { $vector } de longitud { $length }: no es un rayo.
check-tir-got-direction = Tu código dio una dirección, { $vector }, donde no hay ninguna.
check-tir-got-not-finite = Tu código dio componentes NaN o infinitas (la raíz cuadrada de un k negativo, o normalize() del vector nulo).
check-result-differs = { $call } devuelve { $returned } con estos argumentos, pero la llamada dio { $got }: { $detail }. Tu propia implementación difiere de la de la API.
check-ties-no-field = Ningún campo de referencia los distingue: { $call } lee ambos igual; la llamada habitual pasa { $usual }.
check-ties-give = Indica { $fields } para distinguirlos.
check-ties = Igual de posible: { $readings } en su lugar. { $hint }
check-unchecked = Comprobado solo con las reglas propias de la API: indica { $missing }.
check-unexplained-travel = El { $incident } registrado está a { $degrees } grados de la dirección { $travel } de este rayo: no es la dirección de este rayo (ni su opuesta).
check-unexplained-eta = { $eta } = { $value } no encaja ni con n_from/n_to = { $mu } ni con su inverso tal como lo lee { $call }: no son los índices de esta superficie de separación.
check-unexplained = Ninguna combinación de errores en los argumentos hace que esta llamada encaje con la referencia dada.
check-right-tir = Correcto: { $call } indica aquí reflexión total ({ $returned }), y la llamada dio { $what }.
check-right-for-ray = Correcto: { $call } devuelve { $returned } con estos argumentos, para un rayo { $situation }.
check-right = Correcto: { $call } devuelve { $returned } con estos argumentos.

## Los errores de una llamada a una API, en una línea cada uno

check-mistake-eta-inverted = el cociente de índices al revés para la convención de esta API
check-mistake-incident-reversed = el vector incidente pasado al revés
check-mistake-normal-not-facing = la normal en el lado equivocado para esta API (o para la eta pasada)
check-mistake-not-the-api-result = el resultado no es lo que devuelve la API con estos argumentos: tu propia implementación difiere
check-mistake-missed-tir = una dirección (o NaN) donde la API indica reflexión total
check-mistake-not-unit-input = el vector incidente o la normal no es unitario

## El panel: los campos de este proyecto

check-source-own = W, N, μ (este proyecto)
check-code-calls = Tu código llama a:
check-convention = Convención:
check-convention-along-ray = Sección 2: W a lo largo del rayo
check-convention-along-ray-about = W es la dirección en la que viaja el rayo, hacia la superficie (la I de GLSL, el uv del libro).
check-convention-toward-origin = Sección 1: W hacia el origen
check-convention-toward-origin-about = W apunta hacia donde venía el rayo (el wi de pbrt y de Mitsuba).
check-convention-note = { $about } μ = μi/μt; N en cualquier lado (el kernel la gira hacia el rayo).
check-paste-hint = Pega lo que registró tu trazador de rayos. Vectores como 0.1, -0.9, 0 o [0.1,-0.9,0] o vec3(0.1, -0.9, 0.0); o pega una línea JSON entera con t_yours en «Tu T».
check-use-current-case = Usar el caso actual
check-use-current-case-own-hover = Rellenar W, N, μ y la convención desde el explorador
check-use-current-case-api-hover = Rellenar los argumentos y los índices desde el explorador
check-your-t = Tu T
check-your-t-in-error = tu T
check-button = Comprobar
check-field-not-number = { $field }: «{ $text }» no es un número
check-student-own = tu T: { $verdict }
check-headline-own = Tu T coincide con { $verdict }
check-match-refracted = el rayo refractado T
check-match-not-unit = la dirección de T, pero no unitaria
check-match-wrong-side = lado equivocado (la otra raíz para b)
check-match-wrong-bend = desvío equivocado (el otro signo de a)
check-match-reversed = invertido (−T: ambos signos mal)
check-match-tir = reflexión total, bien respondida
check-match-none = ninguno de los cuatro candidatos
check-no-refracted-ray = No hay rayo refractado: reflexión total.
check-right-t = La T correcta = { $t }
check-copy-right-t = Copiar T
check-not-drawn-changed = (El caso ha cambiado desde entonces: el veredicto no se dibuja.)

## El panel: una llamada a una API

check-drawn-incident = { $api ->
    [glsl] I (dirección de propagación)
    [pbrt] wi (de vuelta hacia el origen)
    [rtiow] uv (dirección de propagación)
   *[mitsuba] wi (alejándose de la superficie)
}
check-drawn-about = { $api ->
    [glsl] I es la dirección en la que viaja el rayo, dibujada como W a lo largo del rayo (Sección 2). N debe estar opuesta a I: GLSL no la gira. eta = n_from/n_to = μi/μt. El vector nulo significa reflexión total.
    [pbrt] wi apunta hacia donde venía el rayo (−ray.d), dibujado como W hacia el origen (Sección 1). n puede estar en cualquier lado: pbrt la invierte e invierte eta cuando wi queda por debajo. eta = el índice detrás de n entre el de delante (μt/μi con n hacia wi). false significa reflexión total.
    [rtiow] uv es la dirección unitaria en la que viaja el rayo, dibujada como W a lo largo del rayo (Sección 2). n debe estar opuesta a uv (front_face). etai_over_etat = n_from/n_to = μi/μt. refract no comprueba la reflexión total: la refleja cannot_refract de quien llama.
   *[mitsuba] wi se aleja de la superficie, de vuelta a lo largo del rayo, dibujado como W hacia el origen (Sección 1). n es +z (el sistema local) si se deja vacío. eta = int_ior/ext_ior, el índice detrás de n entre el de delante (μt/μi con n hacia wi). F = 1 significa reflexión total: wo es null.
}
check-convention-about = Convención: { $about }
check-your-call = Tu llamada
check-truth = Referencia (opcional)
check-picture-outside = μ = { $mu } necesita índices fuera del rango { $low }…{ $high } del explorador
check-student-api = tu { $result }: { $verdict }
check-student-right = correcto
check-student-wrong = incorrecto
check-api-right-headline = Correcto: lo que { $signature } significa para este rayo
check-api-mistakes = Errores: { $codes }
check-api-unexplained-headline = Ningún error por sí solo lo explica
check-api-returns = Resultado en { $owner }: { $value }
check-api-drawn = Dibujado: la llamada correcta, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = No dibujado: { $why }.
check-copy-as-test = Copiar como prueba unitaria:

## El panel: líneas de registro pegadas

check-paste-lines = 📋 Pegar líneas de registro
check-pattern = Patrón
check-log-lines = Líneas de registro
check-lines-button = Comprobar las líneas
check-read-as-pattern = el patrón
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (la primera línea es la cabecera)
check-bulk-summary = Leído como { $read_as }: { $count ->
    [one] { $count } llamada
   *[other] { $count } llamadas
}
check-bulk-left-out = { $count ->
    [one] { $count } línea tras las primeras { $first } queda fuera
   *[other] { $count } líneas tras las primeras { $first } quedan fuera
}
check-column-line = línea
check-column-ok = ok
check-column-mistakes = errores
check-column-explanation = explicación
check-row-line = línea { $line }
check-row-open-hover = Abrir esta llamada en el panel y en el diagrama
check-row-error = error

## Lectura de los campos de una llamada, una línea CSV, un patrón y un vector (el panel también muestra estos mensajes)

check-field-not-three = `{ $field }` debe tener exactamente 3 números, tiene { $count }
check-field-not-a-vector = `{ $field }` debe ser un array de 3 números o un texto como «0.1, -0.9, 0»
check-field-not-flag-got = `{ $field }` debe ser true/false o 1/0, no «{ $text }»
check-field-not-number-json = `{ $field }` debe ser un número
check-field-not-flag = `{ $field }` debe ser true/false o 1/0
check-field-not-label = `{ $field }` debe ser un texto o un número
check-json-not-object = se esperaba un objeto JSON con los campos { $fields }
check-unknown-field = campo desconocido `{ $field }`
check-field-not-vector = `{ $field }` debe ser 3 números
check-field-missing = falta el campo `{ $field }` ({ $what })
check-what-normal = la normal a la superficie
check-what-incident = el vector incidente
check-what-eta = el cociente de índices
check-field-not-finite = `{ $field }` debe ser finito, es { $value }
check-field-zero-vector = `{ $field }` es el vector nulo
check-field-not-positive = `{ $field }` debe ser un número finito > 0, es { $value }
check-from-and-to-together = `from` y `to` van juntos: indica ambos o ninguno
check-travel-not-finite = `travel` debe ser un vector finito no nulo
check-result-null = `{ $field }` es null aunque `{ $returned }` es true
check-result-missing = falta el campo `{ $field }` (lo que devolvió la llamada{ $api ->
    [pbrt] , o "returned": false
    [mitsuba] , null cuando reflejó
   *[other] {""}
})
check-unknown-precision = precisión desconocida «{ $text }»: se esperaba "f32" o "f64"
check-too-large = { $value } es demasiado grande para { $precision }
check-csv-unclosed-quote = comilla sin cerrar en la línea CSV
check-csv-no-column = la cabecera CSV no tiene la columna `{ $field }`: nombra { $names }; se esperaba { $expected }
check-csv-partial-vector = la cabecera CSV solo tiene { $count } de las 3 componentes de `{ $field }`
check-csv-duplicate-column = la cabecera CSV nombra `{ $column }` más de una vez
check-csv-cells = { $count ->
    [one] { $count } celda
   *[other] { $count } celdas
} donde la cabecera tiene { $columns ->
    [one] { $columns } columna
   *[other] { $columns } columnas
}
check-csv-no-header = no hay cabecera CSV utilizable: { $reason }
check-pattern-unclosed = `{"{"}` sin cerrar en el patrón «{ $pattern }»
check-pattern-adjacent = dos campos sin nada entre ellos en el patrón «{ $pattern }»
check-pattern-twice = el campo {"{"}{ $field }{"}"} aparece dos veces en el patrón «{ $pattern }»: nombre cada campo una vez
check-pattern-too-many = el patrón tiene { $count } marcadores: se leen como máximo { $limit }
check-pattern-too-long = el patrón mide { $bytes } bytes: se leen como máximo { $limit }
check-pattern-no-field = el patrón «{ $pattern }» no nombra ningún campo
check-pattern-unknown-field = campo desconocido {"{"}{ $field }{"}"} en el patrón para --api { $api }: se esperaba {"{"}_{"}"} o uno de { $expected }
check-line-not-matching = la línea no coincide con el patrón
check-tally-skipped = omitidas (no coinciden con el patrón)
check-tally-unreadable = ilegibles
check-tally-unexplained = sin explicar
check-word-not-a-number = «{ $word }» no es un número
check-vector-expected-named = se esperaba `{ $expected }: <número>`, se encontró «{ $found }»
check-vector-within = { $error } (en «{ $text }»)
check-vector-not-three = se esperaban 3 números como `0.1, -0.9, 0` o `vec3(0.1, -0.9, 0.0)`, se encontraron { $count } en «{ $text }»

# Errores que se ven en lo devuelto
check-mistake-no-flip-inside = para un rayo que llega del otro lado de la normal, el código no invierte la normal ni el cociente
check-mistake-normal-term-sign = la parte del resultado a lo largo de la normal tiene el signo equivocado; la parte transversal es correcta
check-mistake-other-root = la otra raíz: el signo de la raíz cuadrada invertido, el resultado reflejado respecto a la superficie
check-mistake-false-tir = reflexión total indicada donde el rayo se refracta
check-diagnosis-no-lines = No se juzgó ninguna línea ({ $lines } leídas): revisa el patrón, la cabecera CSV o los campos de las líneas; check --suggest-pattern lee las primeras líneas del registro y sugiere un patrón.
check-physics-explained = Eso es lo que da una refracción con este error: { $mistakes }.
check-looks-normal-term = la respuesta de la API con la parte a lo largo de la normal negada: el término a lo largo de la normal se resta donde se suma, o al revés
check-looks-no-flip = lo que da la fórmula sin invertir la normal ni eta para un rayo que llega del otro lado de la normal
check-looks-etap = la dirección correcta, pero etap = { $logged } donde la llamada usó { $used }

# El diagnóstico de un registro entero: dónde se ve un error y cómo se corrige
check-where-every = { $count ->
    [one] en la única línea juzgada
   *[other] en todas las líneas juzgadas ({ $count })
}
check-where-inside = { $count ->
    [one] en la única línea cuyo rayo llega desde dentro, y en ninguna desde fuera
   *[other] en todas las líneas cuyo rayo llega desde dentro ({ $count }), y en ninguna desde fuera
}
check-where-outside = { $count ->
    [one] en la única línea cuyo rayo llega desde fuera, y en ninguna desde dentro
   *[other] en todas las líneas cuyo rayo llega desde fuera ({ $count }), y en ninguna desde dentro
}
check-where-past-critical = { $count ->
    [one] en la única línea más allá del ángulo límite, y en ninguna otra
   *[other] en todas las líneas más allá del ángulo límite ({ $count }), y en ninguna otra
}
check-where-some-sides = en { $count } de { $all } líneas juzgadas ({ $inside } desde dentro, { $outside } desde fuera)
check-where-some = en { $count } de { $all } líneas juzgadas
check-fix-pass = pasa `{ $code }`
check-fix-write = escribe `{ $code }`
check-fix-restore = restablece `{ $code }`
check-fix-generic-eta-inverted = usa μ = n_from / n_to, el índice del medio que el rayo deja entre el del medio en que entra: se invierte donde el rayo sale del objeto (allí μ = n_interior / n_exterior; al entrar, μ = n_exterior / n_interior)
check-fix-generic-incident-reversed = pasa como W la dirección en que viaja el rayo, no su opuesta
check-fix-generic-normal-not-facing = donde el rayo sale del objeto, usa en cada término la normal orientada hacia el rayo (la exterior, invertida) o la exterior con el signo cambiado, pero no ambas cosas
check-fix-generic-no-flip-inside = para un rayo que llega desde dentro, invierte la normal y el cociente antes de refractar
check-fix-generic-normal-term-sign = suma el término a lo largo de la normal: T = μ·W + (μ·cosθi − cosθt)·N, con N orientada hacia el rayo
check-fix-generic-other-root = da a la parte de T a lo largo de la normal que mira al rayo el signo que lleva T a través de la superficie: −cosθt (la variable con cosθt, o el signo tomado de cosθi, está invertido)
check-fix-generic-missed-tir = refleja cuando k = 1 − μ²·(1 − cos²θi) es negativo, antes de tomar su raíz cuadrada
check-fix-generic-false-tir = indica reflexión total solo donde k = 1 − μ²·(1 − cos²θi) es negativo
check-fix-generic-not-unit-input = normaliza W y N antes de refractar
check-fix-generic-not-the-api-result = ningún error de la fórmula, ni un par, reproduce estas líneas: la explicación de cada línea dice qué volvió y cuál es la T correcta
check-physics-no-indices = faltan los índices: da `mu_i` y `mu_t`, o `entering` con --inside y --outside
check-physics-unknown-convention = convención desconocida "{ $text }": se esperaba "along_ray" o "toward_origin"
check-diagnosis-none = Ningún error: el registro es correcto { $place }.
check-diagnosis-verdict = El error: { $code } ({ $meaning }), { $place }. Corrección: { $fix }.
check-diagnosis-also = Además: { $code } ({ $meaning }), { $place }. Corrección: { $fix }.
check-diagnosis-alike = El registro no lo distingue de { $alike }; registra { $fields } para distinguirlos.
check-pattern-too-many-lines = el patrón ocupa { $count } líneas: se leen como máximo { $limit }
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} niega un indicador, y { $field } no lo es: escribe {"{"}!entering{"}"} para un indicador impreso al revés (inside, backfacing)
check-suggest-toward-origin = el vector incidente se imprime como wi, apuntando hacia el origen del rayo: añade --convention toward-origin
check-suggest-no-normal = no se imprime ninguna normal: si es el eje z de un marco local (Mitsuba, Tungsten), añade --normal +z
check-suggest-no-side = nada de lo impreso dice si el rayo entra en el objeto: imprímelo ({"{"}entering{"}"}, o {"{"}!entering{"}"} para un indicador como backfacing) y pasa --inside y --outside, o la razón no se puede comprobar
check-suggest-none = ninguna de las primeras { $lines } líneas parece una refracción (un vector incidente, una razón y un resultado, cada uno tras su nombre): escribe el --pattern a mano (docs/check.md)
check-situation-outward = tomando { $normal } como la normal exterior, pues los índices no dicen nada del lado
check-right-sampled = Correcto como reflexión muestreada: { $call } refracta aquí ({ $returned }), pero Mitsuba refleja con probabilidad F = { $f }, y el wo nulo dice que lo hizo. El diagnóstico del registro completo comprueba que el código transmite en estos ángulos en otras líneas.
check-physics-sampled = No volvió nada donde el rayo se refracta: correcto como reflexión muestreada con probabilidad F = { $f }, como la registran los renderizadores que eligen al azar entre reflexión y refracción. El diagnóstico del registro completo comprueba que el código transmite en estos ángulos en otras líneas.
check-fix-in = { $fix } (en { $place })
check-fix-part = { $part }; { $fix }
check-sides-entering = {" "}para los rayos que entran en el objeto
check-sides-leaving = {" "}para los rayos que salen del objeto
check-part-ratio = T se refracta con la razón invertida{ $sides }: 1/μ en cada parte, también en la prueba de reflexión total (la variable con μ, o el ternario que la elige)
check-part-across = la parte de T transversal a N está escalada por 1/μ en vez de μ (1/μ² de la correcta){ $sides }, y la parte a lo largo de N es correcta: la razón que multiplica el vector incidente está invertida
check-part-along = la parte de T a lo largo de N, cosθt = √(1 − μ²·sen²θi), sale de 1/μ en vez de μ{ $sides } (también la prueba de reflexión total), y la parte transversal a N es correcta: la razón en cosθt está invertida
check-part-normal = la parte de T a lo largo de N tiene el signo equivocado{ $sides }: la normal usada no mira al rayo
check-part-incident = la parte de T transversal a N tiene el signo equivocado (la imagen especular de T respecto a la normal, desvío equivocado): el vector incidente entra al revés en la fórmula
check-part-root = la parte de T a lo largo de N tiene el signo equivocado: cosθt queda del lado de donde viene el rayo, así que T se queda en su medio (la otra raíz)
check-part-term = el término a lo largo de N, (μ·cosθi − cosθt)·N, se resta donde debe sumarse{ $sides }; la parte transversal a N es correcta
check-part-no-flip = para los rayos del lado opuesto de la normal, ni se invierte la normal ni la razón: T es la otra raíz con 1/μ
check-fix-generic-ratio-across = escala la parte del vector incidente transversal a N por μ = n_from / n_to, la misma razón con la que se calcula cosθt
check-fix-generic-ratio-along = calcula cosθt = √(1 − μ²·sen²θi) con μ = n_from / n_to, la razón que escala la parte transversal a N (un coseno pasado con su signo hace que una función auxiliar invierta la razón otra vez)
check-fix-generic-across-sign = la parte transversal a N es μ por la del vector incidente (μ·(W + cosθi·N) con W a lo largo del rayo): tómala con el signo del vector incidente
check-fix-generic-never-transmits = el código nunca transmite estos rayos aunque se refractan: si muestrea la reflexión, su probabilidad (F, la reflectancia de Fresnel) debe quedar por debajo de 1 ahí; indica reflexión total solo donde k = 1 − μ²·(1 − cos²θi) es negativo
check-diagnosis-unchecked = No se puede comprobar sin saber de qué lado viene cada rayo, { $place }: cada línea es correcta según las reglas de su API, pero nada en el registro ni en las opciones distingue una razón correcta de una equivocada. { $fix }.
check-diagnosis-alike-no-field = El registro no puede distinguirlo de { $alike }.
check-unchecked-log-entering = Registra entering en cada línea (true cuando el rayo entra en el objeto; {"{"}!entering{"}"} lee un indicador como inside o backfacing), o from y to
check-unchecked-pass-indices = Pasa --inside y --outside (los índices dentro y fuera del objeto) con entering registrado, o en pbrt y Mitsuba con la normal exterior; o registra from y to
check-mistake-across-sign = la parte del resultado transversal a la normal tiene el signo equivocado; la parte a lo largo de ella es correcta (la imagen especular del resultado respecto a la normal)
check-part-across-sign = la parte de T transversal a N tiene el signo equivocado (la imagen especular de T respecto a la normal, desvío equivocado), y la parte a lo largo de N es correcta: falta el menos delante de la razón por el vector incidente
check-tally-sampled = reflejadas (muestreadas)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } líneas del registro no se pudieron leer (cada una se responde con su error) y ninguna línea leída está mal: no es un aprobado; corrige esas líneas o la forma de leerlas.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = el registro es JSON Lines, cuyas claves nombran los campos: no necesita patrón

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = No se puede saber con las cifras impresas: tal como se imprimió, la llamada parece { $shown }, pero números dentro de su redondeo la hacen correcta (un signo del que depende el veredicto, de N·I, de k o de una raíz, está más cerca de cero de lo que muestran las cifras). Imprime más cifras para juzgarla.
check-diagnosis-too-few-digits = No se puede saber si son correctas o erróneas con las cifras impresas, { $place }: cada una es errónea tal como se imprimió pero correcta para números dentro de su redondeo; las cifras del registro son muy pocas para saberlo (un signo del que depende el veredicto, de N·I, de k = 1 − η²·(1 − (N·I)²) o de una raíz, puede estar más cerca de cero de lo que muestran). La precisión del registro es demasiado baja: { $fix }.
check-too-few-digits-fix = imprime cada número con al menos 6 cifras significativas (printf en C o en un shader: %.6g; C#: ToString("G9"), el Vector3 de Unity: ToString("F6"); flujos de C++: std::setprecision(9); Rust: {"{"}:?{"}"}; Python: repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 se leen de la razón que imprimen las líneas, para un objeto más denso que lo que lo rodea (vidrio o agua en aire): da los índices de tu escena si son otros
check-diagnosis-none-judged = Ninguna de las { $lines } líneas que leyó el patrón pudo juzgarse, así que el patrón no tiene la culpa; la primera dice: { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 son vidrio en aire, supuestos porque las líneas no imprimen ninguna razón: da los índices de tu escena si son otros

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` se imprime con un número por línea (como imprime un vector el cout << v de Eigen): sus líneas no se pueden unir con seguridad; imprime cada vector en una línea (Eigen: v.transpose(); nalgebra: v.transpose() o {"{"}:?{"}"}; numpy: np.array2string(v, max_line_width=1000) o v.tolist())
check-suggest-column-vectors = las primeras { $lines } líneas imprimen vectores con un número por línea (como el cout << v de Eigen), que ningún patrón puede unir con seguridad: imprime cada vector en una línea (Eigen: v.transpose(); nalgebra: v.transpose() o {"{"}:?{"}"}; numpy: v.tolist()), cada uno tras su nombre, y vuelve a pedirlo

# check: errores compuestos nombrados como causas (issue 43, punto 4)
check-mistake-refracted-twice = refractado dos veces en un mismo cruce de superficie: T es lo que da la razón al cuadrado (μ²)
check-mistake-fresnel-cos-sign = el código nunca transmite, en ningún ángulo, aunque k > 0: el signo del coseno se perdió donde se calcula la reflectancia de Fresnel (o la decisión de transmitir)
check-mistake-normals-mixed = el lado se decide con una normal (la geométrica) y refract recibe otra (la de sombreado), invertida según esa decisión: donde ambas discrepan, la normal pasada no mira hacia el rayo
check-fix-generic-refracted-twice = llama a refract una vez por cada cruce de superficie: aquí T se refracta otra vez (o μ se aplica dos veces), como con μ² = (n_origen / n_destino)²; conserva el primer T y sigue el rayo hasta la siguiente superficie
check-fix-generic-fresnel-cos-sign = la prueba de reflexión total no es la causa (por debajo de 15° ninguna razón hace k negativo): donde se calcula F o la decisión de transmitir, toma cosθi sin su signo, |N·I| (o −N·I con N mirando hacia el rayo); un coseno negativo hace F ≥ 1, y el rayo siempre se refleja
check-fix-generic-normals-mixed = decide el lado (entering, la razón) e invierte la normal que pasas a refract con la misma normal: la de sombreado para ambos, o la geométrica para ambos (la geométrica sirve para desplazar el origen del rayo)
check-fix-normals-print = Si el código decide el lado con otra normal distinta de la que pasa (una geométrica junto a una de sombreado), registra también `entering`: así el diagnóstico puede distinguirlo.
