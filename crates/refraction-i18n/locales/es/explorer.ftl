# La ventana, su barra superior, herramientas y paneles, en español.
# Las claves están en kebab-case y empiezan por aquello a lo que pertenecen; los marcadores ({ $name }) traen
# los números ya escritos a la manera local (con coma decimal donde el idioma la usa).

## La barra superior

view-interface = Una superficie
view-scenes = Escenas
view-menu = Vista
view-accuracy = Precisión/tiempo
# Nombra, en un mensaje de error, una escena conservada de la última ejecución.
view-last-run-scene = la escena de la última ejecución
# Lo que hizo el último deshacer o rehacer ($change) y la vista a la que cambió ($view).
travel-in-view = { $change } (en { $view })
tool-check = Comprobar mi T
tool-walk-through = Paso a paso
tool-files = Guardar, abrir, compartir
tool-fresnel = Fresnel
presentation-toggle = 🖵 Presentación
presentation-toggle-hover = Pantalla completa, todo más grande (F11)
presentation-theme = Tema
presentation-theme-hover = Estándar o alto contraste: negro sobre blanco o blanco sobre negro
presentation-colour-blind = Apto para daltónicos
presentation-colour-blind-hover = Solo colores Okabe–Ito; además, cada rayo tiene su propio trazo discontinuo y su etiqueta
presentation-simple = Vista sencilla
presentation-simple-hover = Omite las tres elecciones de signo rechazadas y su (a, b): para una clase que aún no conoce los cuatro candidatos
presentation-look = Aspecto
presentation-diagram-only = Solo el diagrama (D)
language-menu = Idioma
language-hover = El idioma de la ventana. Sigue el del sistema si aquí no se ha escogido otro.
effects-menu = Efectos
effects-menu-hover = Intensidades (Fresnel) y frentes de onda sobre el diagrama
effects-intensities = Intensidades
effects-intensities-hover = Dibuja los rayos reflejado y transmitido según su parte de la luz (Fresnel), con porcentajes
effects-wavefronts = Frentes de onda
effects-wavefronts-hover = Frentes de onda planos separados λ/μ en cada medio, que avanzan a c/μ: por eso se desvía el rayo
effects-moving = En movimiento
effects-huygens = Construcción de Huygens
effects-huygens-hover = Dos puntos de un mismo frente y la onda secundaria crecida en el tiempo entre ambos

## Los paneles laterales ($key es la tecla que los abre y los cierra, como F2)

panel-show-controls = Mostrar los controles ({ $key })
panel-hide-controls = Ocultar los controles ({ $key })
panel-show-numbers = Mostrar los números ({ $key })
panel-hide-numbers = Ocultar los números ({ $key })

## Bajo el diagrama

canvas-hint = Arrastra W, N o un marcador μ, o usa − y + debajo; Tab o un clic elige uno para las flechas del teclado
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Mayús: 0,1°) · +/− μt · Tab: siguiente tirador · arrastra para mover
canvas-hint-index = ↑/↓ o +/− cambian el índice en 0,01 (Mayús: 0,001) · Tab: siguiente tirador

## El panel de controles

controls-lesson = Lección
controls-lesson-preset = Lección predefinida
controls-lesson-own = Caso propio
controls-lesson-changed = { $lesson }, modificado
controls-reset = Restablecer
controls-reset-hover = Volver al inicio de la lección elegida
controls-incidence = θi (grados)
controls-convention = Convención
controls-convention-toward-origin = Sección 1: W apunta de vuelta hacia el origen
controls-convention-along-ray = Sección 2: W es la dirección de propagación
controls-flip-normal = Invertir N
controls-flip-normal-hover = Invierte la normal: así es una normal exterior donde un rayo sale del vidrio
controls-snap = Ajustar W a θc
controls-snap-hover = Pone W en el ángulo límite (requiere μi > μt)
controls-snap-disabled = Solo hay ángulo límite cuando μi > μt
controls-indices = Índices
# $symbol es μi o μt.
controls-index-value = Valor de { $symbol }
controls-material = Material de { $symbol }
controls-custom-hint = personalizado: escribe un valor arriba
controls-typed-vectors = W y N introducidos
controls-typed-vectors-hint = Pega los vectores registrados por un estudiante (x, y, z); pulsa Intro.
controls-export-heading = Exportar imagen (PNG o SVG)
controls-export-size = Tamaño
controls-export-file = Archivo
controls-export-file-hint = un nombre .png o .svg, o numerado diagram-001.png
controls-browse = Examinar…
controls-export = Exportar imagen
controls-exported = se escribió { $path }
# Un valor escrito que no es un número: $name es aquello para lo que se escribió (θi, μt, W).
typed-not-a-number = { $name }: «{ $text }» no es un número
typed-not-three-numbers = { $name }: se esperaban tres números x, y, z; se recibieron { $count }

## El panel de números

readouts-discriminant = Discriminante k = μ²wn² − μ² + 1 = { $k } ≥ 0: T existe
readouts-discriminant-tir = Discriminante k = μ²wn² − μ² + 1 = { $k } < 0: reflexión total
# $section es la sección del artículo (1 o 2) cuya ecuación 20 es esta.
readouts-quadratic = Ec. { $section }.20, la ecuación cuadrática en b: b² + 2a·wn·b + a² − 1 = 0 con a = { $a }, wn = { $wn }
readouts-no-roots = sin raíces reales: la parábola ya no llega a cero
readouts-roots = raíces b = { $roots } (los b de los candidatos para este a)
readouts-candidates = Los cuatro candidatos
readouts-candidate = candidato
# Los encabezados de columna de las comprobaciones: la ley de Snell al cuadrado (la ec. 10 del artículo), el lado de la superficie en que está T, el sentido en que se desvía T.
readouts-check-snell = ec. 10
readouts-check-side = lado
readouts-check-bend = desvío
readouts-no-candidates = Sin candidatos: k < 0, así que b no tiene raíces reales y no existe T.
readouts-candidates-note = Los cuatro son unitarios y cumplen la ley de Snell al cuadrado (ec. 10): elevar al cuadrado no permite distinguirlos. Solo el lado y el desvío (el argumento μ = 1 del artículo) eligen T.
readouts-warnings = Avisos del kernel
readouts-no-warnings = Sin avisos: W y N son unitarios y N mira hacia el rayo.
readouts-warning-not-unit = { $vector } tiene longitud { $length }, no 1: se normalizó (los vectores sin normalizar son un error común en los trazadores de rayos)
readouts-warning-flipped = N apunta en sentido contrario al rayo incidente (como una normal exterior donde un rayo sale de una esfera): el kernel usó −N, la normal que mira hacia el rayo
readouts-equations = Ecuaciones del artículo, sección { $section }

## El paso a paso

walk-previous = Paso anterior
walk-next = Paso siguiente
walk-animate = Animar μ hasta 1
walk-animating = Animando μ hasta 1 …
walk-animate-hover = Transforma μt en μi: la T elegida converge al rayo incidente
walk-animate-disabled = μ ya es 1 (μi = μt), o la animación está en curso
walk-step = Paso { $number } de { $count }: { $title }

## La herramienta Fresnel

fresnel-plot-about = Gráfica de Fresnel: luz reflejada y transmitida frente a θi, el cursor en θi = { $angle }°
fresnel-click-hint = Haz clic o arrastra en la gráfica para fijar θi.
fresnel-at = Con θi = { $angle }°, de μi = { $mu_i } a μt = { $mu_t }.
fresnel-brewster = Ángulo de Brewster θB = { $angle }°: ahí no se refleja luz polarizada p (tg θB = μt/μi).
fresnel-equal-indices = Índices iguales: no hay superficie de separación, no se refleja nada.
fresnel-critical = Ángulo límite θc = { $angle }°: más allá de él, toda la luz se refleja (sen θc = μt/μi).
fresnel-no-critical = Sin ángulo límite: la luz pasa a un medio de índice mayor.

## La vista Escenas

scenes-scene = Escena
scenes-rays = Rayos
scenes-draft = Borrador al arrastrar: un rayo de cada { $every }
scenes-reset-hover = la escena tal como está en su archivo
scenes-file = Archivo de escena
scenes-open = Abrir archivo
scenes-save = Guardar archivo
scenes-save-hover = la escena editada, en el formato de escenas (TOML)
scenes-open-dialog-hover = Elegir un archivo de escena para abrir
scenes-saved = se guardó { $path }
scenes-opened = se abrió { $path }
scenes-hint = Arrastra la fuente (ámbar), su dirección (el anillo al final de la flecha discontinua) o el tirador de una forma; haz clic en un punto de impacto para abrirlo en «Una superficie».
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Archivos y ayuda
scenes-less = Menos controles
scenes-picture-file = Archivo de imagen (.png o .svg)
scenes-picture-hint = un nombre .png o .svg, o numerado scene-001.svg
scenes-export-size = Exportar { $width }×{ $height }
scenes-tracing = trazando… { $percent } % (se muestra el último trazado terminado)
scenes-cancel = Cancelar
scenes-cancel-hover = detener el trazado y mostrar lo trazado hasta ahora
scenes-stopped-segments = el trazado se detuvo en su límite de { $budget } segmentos: faltan los rayos aún no seguidos (con menos rayos, un max_depth menor o un min_intensity mayor se traza por completo)
scenes-stopped-tests = el trazado se detuvo en su límite de { $budget } pruebas de intersección: faltan los rayos aún no seguidos (con menos rayos, formas o reflexiones se traza por completo)
scenes-stopped-cancelled = se canceló el trazado: faltan los rayos aún no seguidos
# El recuadro junto a un punto de impacto bajo el puntero: los medios de los que sale y a los que entra el rayo, sus índices y la longitud de onda trazada.
scenes-hit =
    de { $from } a { $to } ({ $side ->
        [entering] entrada
       *[leaving] salida: el kernel invierte N
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } nm
    clic: abrir en «Una superficie»

## La vista de precisión

accuracy-heading = Lo que cuesta la precisión en tiempo
accuracy-intro = Cronometra cada variante del kernel en f32 y f64 en esta máquina y mide su error frente a un oráculo double-double con incidencias aleatorias y difíciles. La gráfica muestra el mayor error del conjunto difícil en unidades de ε·κ (lo que el algoritmo pierde más allá de lo que el propio problema amplifica) frente a los nanosegundos por rayo.
accuracy-quick = Ejecución rápida (unos segundos)
accuracy-measure = Medir
accuracy-measuring = midiendo… { $percent } %
accuracy-press-measure = Pulsa «Medir» para ejecutar la prueba de rendimiento.
# $variant nombra una variante del kernel y su precisión, como «stable f32».
accuracy-verdict = La más rápida dentro de 10× la mejor precisión: { $variant } con { $time } ns por rayo (error del conjunto difícil: { $error } ε·κ).
accuracy-footnote = { $random } problemas aleatorios y { $hard } difíciles en { $cpu }. Los tiempos dependen de qué más esté haciendo la máquina; `refraction-explorer bench` da las mismas cifras en la línea de comandos.
accuracy-plot-about = Precisión frente a tiempo: { $count } variantes, cada una marcada por su forma y nombrada al lado
accuracy-hover =
    { $name }
    { $time } ns, { $error } ε·κ
accuracy-column-variant = variante
accuracy-column-time = ns/rayo
accuracy-column-random = err. máx. aleatorio
accuracy-column-hard = err. máx. difícil
accuracy-column-eps-kappa = difícil ε·κ
accuracy-column-tir = discrepancias en reflexión total

## La vista del alumno: lo que muestra un móvil (o un enlace con view=student), y los botones
## que cambian W, N y los índices paso a paso

# $symbol: μi o μt
student-index = Índice { $symbol }
student-full = Explorador completo
student-full-hover = Todo el explorador, con sus herramientas y paneles (para una pantalla grande)
student-view = Vista del alumno
student-view-hover = La vista para un móvil: la pregunta, el diagrama a todo el ancho y botones para el dedo
