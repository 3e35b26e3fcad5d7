# Un registro entero juzgado en la ventana: su sección en «Comprobar mi T», el archivo del que
# se lee, su diagnóstico, su mapa de fallos y sus líneas erróneas guardadas como pruebas.

logs-hint = Líneas con los campos { $fields }: JSON Lines, CSV con una cabecera que los nombre, o líneas de printf leídas con un patrón como { $example }. Pega como mucho { $characters } caracteres o abre un archivo de registro; se listan las primeras { $count } líneas y todas entran en el diagnóstico.
logs-inside = Índice dentro
logs-outside = fuera
logs-indices-hint = el índice del objeto y el de su entorno, para las líneas que registran entering
logs-index-invalid = { $field }: «{ $text }» no es un índice (un número finito mayor que 0)
logs-not-listed = { $count ->
    [one] { $count } línea más juzgada pero no listada (la tabla muestra las primeras { $first })
   *[other] { $count } líneas más juzgadas pero no listadas (la tabla muestra las primeras { $first })
}
logs-diagnosis-heading = Diagnóstico del registro entero
logs-copy-diagnosis = Copiar el diagnóstico y la tabla
logs-copy-diagnosis-hover = Como texto: los recuentos, el diagnóstico y luego una línea por llamada con tabuladores entre sus celdas
logs-map-heading = Mapa de fallos
logs-map-hover = Cuánto se aleja la dirección de cada línea juzgada de la correcta, frente al ángulo de incidencia, en un panel por cada lado del que llegan los rayos. Cuadrados: la respuesta correcta es la reflexión total.
logs-open = 🗁 Abrir registro…
logs-open-hover = Lee un archivo de registro (o suéltalo en la ventana): se juzgan y diagnostican hasta { $most } líneas.
logs-what-log = registro
logs-read-failed = No se pudo leer { $path }: { $reason }
logs-opened = Se juzga el archivo { $path }: { $lines ->
    [one] { $lines } línea
   *[other] { $lines } líneas
} (como mucho { $most }).
logs-close-file = Escribir o pegar en su lugar
logs-save-tests = Guardar { $count ->
    [one] la línea errónea
   *[other] las primeras { $count } líneas erróneas
} como pruebas:
logs-tests-extension = { $path }: las pruebas en este lenguaje se escriben en un archivo { $extension }; elige un nombre que termine en .{ $extension }
logs-tests-not-ours = { $path } no es un archivo de pruebas escrito por esta herramienta; elige otro nombre para conservar tu propio código
logs-write-failed = No se pudo escribir { $path }: { $reason }

diagram-failure-right = correcta
diagram-failure-wrong = errónea
diagram-failure-past-critical = respuesta correcta: reflexión total
diagram-failure-panel = { $side ->
    [outside] Llegan desde fuera
    [inside] Llegan desde dentro
   *[unknown] Lado no registrado
}: { $lines ->
    [one] { $lines } línea
   *[other] { $lines } líneas
}, { $wrong ->
    [0] ninguna errónea
    [one] { $wrong } errónea
   *[other] { $wrong } erróneas
}
diagram-failure-caption = Cuánto se desvía de la correcta la dirección en que cada línea juzgada envía el rayo, frente al ángulo de incidencia θi:
diagram-failure-empty = No se juzgó ninguna línea.
diagram-failure-about = Mapa de fallos. { $panels }

# check --tests and Save failing lines as tests: what is at the path cannot be read, or is not a file (issue 40)
logs-tests-unreadable = { $path } no se puede leer ({ $reason }), así que no se distingue de tu propio código: se deja como está; elige otro nombre
logs-tests-not-a-file = { $path } no es un archivo normal (una tubería, un dispositivo o un enlace a uno): las pruebas solo se escriben en un archivo propio; elige otro nombre
