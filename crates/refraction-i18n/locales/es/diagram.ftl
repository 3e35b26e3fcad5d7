# Lo que se dibuja en el diagrama, las escenas y las gráficas, en español.
# Las etiquetas del diagrama deben ser cortas: el colocador omite las que no caben.
# Los marcadores llevan números ya escritos con coma decimal.

## El diagrama de la superficie de separación

diagram-ghost-wrong-side = otra raíz de b: lado equivocado
diagram-ghost-wrong-bend = otro signo de a: se desvía mal
diagram-ghost-reversed = ambos signos mal: −T
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = medio del rayo
diagram-medium-entered = medio en el que entra
diagram-material-vacuum = vacío
diagram-material-air = aire
diagram-material-water = agua
diagram-material-glass = vidrio
diagram-material-diamond = diamante
diagram-material-custom = personalizado
diagram-banner-tir =
    REFLEXIÓN TOTAL
    k = { $k } < 0: no hay raíz real para b ni rayo refractado; toda la luz se refleja (θi = { $theta_i }°)
diagram-banner-toward-origin = W apunta de vuelta al origen, así que a = −μ
diagram-banner-along-ray = W es la dirección de propagación, así que a = +μ
diagram-banner-section = Sección { $section }: { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Sección 1: W apunta de vuelta hacia el origen
diagram-banner-asked-along-ray = Sección 2: W es la dirección de propagación
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0: T existe
diagram-critical-angle = ángulo límite θc = { $angle }°
diagram-kernel-normal = −N: la normal que usa el kernel
diagram-outward-normal-bug =
    fallo de la normal exterior:
    la T de la fórmula con N tal cual
diagram-index-scale = índice μ
diagram-incoming-ray = rayo incidente
diagram-normal-incidence = incidencia normal: W, N y T están en una misma línea
diagram-normal-incidence-asked = incidencia normal: W va a lo largo de N
diagram-reflected = reflejado
diagram-reflected-light = reflejado ({ $light })
diagram-reflected-all = rayo reflejado (toda la luz)
diagram-w-along-ray = W (a lo largo del rayo)
diagram-w-toward-origin = W (hacia el origen)
diagram-transmitted = T: transmitida
diagram-no-reflected-ray = { $label }: sin rayo reflejado

## Tiradores (lo que dice un lector de pantalla)

diagram-handle-w = Ángulo de incidencia θi (W)
diagram-handle-n = Dirección de la normal N
diagram-handle-mu-i = Índice μi del medio del rayo
diagram-handle-mu-t = Índice μt del medio en el que entra
diagram-handle-source = tirador de la fuente
diagram-handle-aim = tirador de la dirección de la fuente
diagram-handle-shape = tirador de la forma { $number } ({ $medium })

## Lecciones, temas, luz, animaciones

diagram-lesson-air-to-glass = Aire → vidrio, 40°
diagram-lesson-beyond-critical = Vidrio → aire más allá de θc
diagram-lesson-normal-incidence = Incidencia normal
diagram-lesson-brewster = Ángulo de Brewster
diagram-lesson-droplet-exit = La salida de una gota
diagram-angle-out-of-range = θi debe ser al menos 0° y menor que 90°, no { $angle }°
diagram-theme-standard = Estándar
diagram-theme-black-on-white = Negro sobre blanco
diagram-theme-white-on-black = Blanco sobre negro
diagram-light-s = luz s
diagram-light-p = luz p
diagram-light-unpolarised = luz no polarizada
diagram-animation-mu = μ → 1: T se convierte en W
diagram-animation-sweep = Barrer θi hasta rasante: aparece la reflexión total
diagram-animation-wavefronts = Frentes de onda en movimiento

## La tabla de candidatos

diagram-role-chosen = T (elegida)
diagram-role-wrong-side = lado equivocado
diagram-role-wrong-bend = desvío equivocado
diagram-role-reversed = invertido
diagram-rule-wrong-side = lado equivocado de la superficie: la otra raíz de b devuelve el rayo al medio del que venía
diagram-rule-wrong-bend = se desvía hacia el lado equivocado: el otro signo de a invierte la componente a lo largo de la superficie, así que no se convierte en el rayo incidente cuando μ → 1
diagram-rule-reversed = ambos mal (signo equivocado de a y raíz equivocada de b): es −T, que apunta de vuelta hacia donde venía el rayo

## Una escena trazada

diagram-screen = pantalla
diagram-index-at-wavelength = n = { $index } a { $wavelength } nm
diagram-stopped-at = detenido tras { $count ->
        [one] { $count } segmento
       *[other] { $count } segmentos
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } llamada al kernel
       *[other] { $count } llamadas al kernel
    }
diagram-count-tir = { $count ->
        [one] { $count } reflexión total
       *[other] { $count } reflexiones totales
    }
diagram-count-reflections = { $count ->
        [one] { $count } reflexión generada
       *[other] { $count } reflexiones generadas
    }
diagram-count-fresnel = { $count ->
        [one] { $count } evaluación de Fresnel
       *[other] { $count } evaluaciones de Fresnel
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } longitud de onda
       *[other] { $count } longitudes de onda
    }
diagram-count-source-rays = { $count ->
        [one] { $count } rayo de la fuente
       *[other] { $count } rayos de la fuente
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } salto por índice igual
       *[other] { $count } saltos por índice igual
    }
diagram-count-absorption = { $count ->
        [one] { $count } evaluación de absorción
       *[other] { $count } evaluaciones de absorción
    }
diagram-legend-colour = color:
diagram-legend-white-traced = luz blanca, trazada a { $wavelength } nm
diagram-legend-white-then = luz blanca, luego
diagram-legend-nm = nm
diagram-legend-opacity = opacidad: intensidad
diagram-legend-hits = impactos:
diagram-hit-entering = entrando
diagram-hit-leaving = saliendo (N invertida)
diagram-hit-tir = reflexión total

## Ondas

diagram-fronts =
    frentes separados λ/{ $index }
    velocidad c/{ $index } = { $speed } c
diagram-huygens-touch =
    Huygens: el frente llega a A Δt después que a B;
    la onda secundaria de B crece vt·Δt, el nuevo frente la toca
diagram-huygens-tir =
    Huygens: la onda secundaria de B supera BA:
    no hay tangente desde A, reflexión total

## Las ecuaciones clave

diagram-eq-toward-origin-a = W se aleja de T, así que el artículo toma a = −μ
diagram-eq-along-ray-a = W apunta en el sentido de T, así que el artículo toma a = +μ
diagram-eq-no-refracted-ray = no hay (a, b) real: no hay rayo refractado
diagram-eq-no-b-with-10 = ningún b real la cumple junto con la ec. 10
diagram-eq-so = { $given }, así que { $then }
diagram-eq-negative-root = √({ $k }) de un número negativo: no hay b real (reflexión total)
diagram-eq-or = o
diagram-eq-outward-normal-bug = con N tal como se da, b = { $b }: la raíz equivocada, T vuelve atrás (el fallo de la normal exterior); el kernel usa −N y obtiene b = { $kernel_b } para N
diagram-step-wn-flipped = W·N = { $given }: N apunta en sentido contrario al rayo, así que el kernel usa −N: wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = no hay raíz real que elegir
diagram-eq-no-theta-t = { $given }, así que senθt sería { $sin_t } > 1: no existe ningún ángulo θt
diagram-eq-with-chosen = { $lhs } = { $rhs } con el (a, b) elegido
diagram-eq-no-ab-with-12 = ningún (a, b) real la cumple junto con la ec. 12
# El nombre del seno en las fórmulas del paso a paso, tal como lo escriben los colegios en este idioma.
diagram-math-sin = sen

## Paso a paso

diagram-step-snell = Ley de Snell
diagram-step-snell-text = El rayo se desvía de modo que μi·senθi = μt·senθt; con μ = μi/μt, el seno del ángulo en el nuevo medio es μ veces el anterior.
diagram-step-square = Elevar al cuadrado y usar cosenos
diagram-step-square-text = Elevar al cuadrado permite que los cosenos (productos escalares) sustituyan a los senos, pero también deja entrar soluciones falsas: una solución y su opuesta con signo la cumplen ambas.
diagram-step-decomposition = T como a·W + b·N
diagram-step-decomposition-text = T está en el plano de W y N, así que es a·W + b·N; los cosenos pasan a ser productos escalares con wn = W·N, y cosθt = −a·wn − b. El rayo viaja según { $travel }.
diagram-step-constraints = Las dos restricciones al cuadrado
diagram-step-constraints-text = Snell al cuadrado (ec. 10) y la longitud unitaria (ec. 12) son dos ecuaciones cuadráticas en a y b. Cuatro pares (a, b) cumplen ambas: T y los tres fantasmas. Nada en ellas distingue a los cuatro.
diagram-step-roots-a = Las dos raíces de a
diagram-step-roots-a-text = Sustituir la ec. 12 en la ec. 10 deja a² = μ²: a = +μ o a = −μ. El otro signo refleja T respecto a la normal: se desvía hacia el lado equivocado.
diagram-step-choice-a = Elegir a: el límite μ = 1
# «Animar μ hasta 1» es el nombre del botón en la ventana.
diagram-step-choice-a-text = Cuando μ = 1 nada se desvía, así que T debe ser la dirección de propagación, { $travel }. Solo a = { $a } da eso; el otro signo daría la imagen especular. Pulsa «Animar μ hasta 1» para ver cómo T converge a { $travel } y los fantasmas no.
diagram-step-choice-a-typo = (El texto de la sección 2 dice luego «once we decide upon using the a = −μ solution»: quiere decir a = +μ, la que eligió.)
diagram-step-roots-b = Las dos raíces de b
diagram-step-roots-b-text = Con a fijo, la ec. 12 es cuadrática en b con las raíces −a·wn ± √k (k = μ²wn² − μ² + 1). La otra raíz refleja T respecto a la superficie, de vuelta al medio del que venía el rayo. k < 0 significa que no hay raíz real: reflexión total.
diagram-step-choice-b = Elegir b
diagram-step-choice-b-text = De las dos raíces solo la de −√k se hace b = 0 en μ = 1, cuando T debe ser el rayo incidente sin cambios; la otra manda T de vuelta al otro lado de la superficie.
diagram-step-choice-b-flipped = La raíz con −√k tiende a b = 0 en μ = 1, así que T se convierte en el rayo incidente. Pero aquí N apunta en el sentido del rayo (una normal exterior donde el rayo sale del medio): con N tal como se da, esa raíz es la del lado equivocado. El kernel invierte N primero.

## La vista de Fresnel

diagram-fresnel-title = Cuánta luz se refleja, de μi = { $mu_i } a μt = { $mu_t }
diagram-fresnel-axis = ángulo de incidencia θi
diagram-fresnel-brewster = ángulo de Brewster θB = { $angle }°: no se refleja luz p
diagram-fresnel-critical = ángulo límite θc = { $angle }°: más allá, todo se refleja
diagram-fresnel-brewster-short = ángulo de Brewster θB = { $angle }°
diagram-fresnel-critical-short = ángulo límite θc = { $angle }°
diagram-curve-rs = Rs (luz s reflejada)
diagram-curve-rp = Rp (luz p reflejada)
diagram-curve-r = R (no polarizada, reflejada)
diagram-curve-t = T (no polarizada, transmitida)
diagram-fresnel-source =
    Ecuaciones de Fresnel para la potencia reflejada (Hecht, Óptica, cap. 4): Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    a partir de los propios cosθi y cosθt del kernel, sin trigonometría; la luz no polarizada es la media de s y p. Más allá del ángulo límite toda la luz se refleja.

## La gráfica de precisión

diagram-accuracy-title = Precisión frente a tiempo en esta máquina
diagram-accuracy-error-axis = mayor error del conjunto difícil, en ε·κ (log)
diagram-accuracy-time-axis = tiempo por rayo, ns (log)
diagram-accuracy-bound = la cota del kernel predeterminado, 32 ε·κ
diagram-accuracy-markers = hueco: f32, relleno: f64

## Las escenas incluidas (títulos, descripciones y los nombres de sus medios)

diagram-scene-dispersing-prism = Prisma dispersor
diagram-scene-dispersing-prism-about = Luz blanca a través de un prisma equilátero de vidrio flint F2 cerca de la desviación mínima: el violeta se desvía más.
diagram-scene-droplet = Gota de agua (arcoíris)
diagram-scene-droplet-about = La luz blanca entra en una gota, se refleja dentro y sale; la dispersión abre el arcoíris primario cerca de 138 grados de desviación.
diagram-scene-fibre = Fibra óptica
diagram-scene-fibre-about = La reflexión total repetida guía la luz a lo largo del núcleo; los rayos más inclinados escapan al revestimiento.
diagram-scene-interface = Una superficie de separación
diagram-scene-interface-about = Un rayo en el aire llega a un vidrio plano (n = 1,5) a 45 grados y se acerca a la normal.
diagram-scene-lens = Lente convergente
diagram-scene-lens-about = Una lente biconvexa de BK7 enfoca un haz paralelo sobre una pantalla; los rayos marginales convergen antes.
diagram-scene-right-angle-prism = Prisma de ángulo recto
diagram-scene-right-angle-prism-about = La reflexión total en la hipotenusa desvía el haz 90 grados.
diagram-scene-slab = Lámina de vidrio
diagram-scene-slab-about = Caras paralelas: el rayo de salida es paralelo al de entrada, desplazado de lado. Pérdidas de Fresnel en ambas caras, absorción en el interior.
diagram-medium-core = núcleo
diagram-medium-cladding = revestimiento
diagram-medium-f2 = flint F2
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = BK7 tintado
