## Accesibilidad: lo que dice un lector de pantalla del explorador, los botones junto al diagrama y los mandos propios de la página en un navegador

access-degrees = { $angle }°
access-normal-up = hacia arriba
access-normal-down = hacia abajo
access-normal-right = { $angle }° a la derecha de la vertical
access-normal-left = { $angle }° a la izquierda de la vertical
access-index-named = { $index } ({ $name })
access-media = El rayo viaja por el primer medio ({ $from }) y llega al segundo ({ $to }).
access-medium-named = { $name }, { $symbol } = { $index }
access-medium-custom = { $symbol } = { $index }
access-incidence-sentence = Llega a la superficie con θi = { $angle }° respecto a la normal.
access-incidence-along-normal = Llega a la superficie a lo largo de la normal: θi = 0°.
access-normal-sentence = Dirección de la normal N: { $direction }.
access-tir = Reflexión total: θi supera el ángulo límite θc = { $critical }°, así que no hay rayo refractado y toda la luz se refleja.
access-t-along-normal = La T sigue recta a lo largo de la normal: no se desvía.
access-t-straight = La T sigue recta, a { $angle }° de la normal: no se desvía.
access-t-toward = La T se desvía hacia la normal, a { $angle }° de ella.
access-t-away = La T se desvía alejándose de la normal, a { $angle }° de ella.
access-reflected = El rayo reflejado sale a { $angle }° de la normal, al otro lado de ella.
access-critical = El ángulo límite es θc = { $critical }°.
access-flipped = N apunta en sentido contrario al rayo incidente, así que el kernel usa −N.
access-sentence = { $text }.
access-change-value = { $name } { $before } → { $after }
access-change = { $changes }: { $outcome }.
access-change-tir-begins = ahora supera el ángulo límite { $critical }°; toda la luz se refleja
access-change-tir-ends = ahora queda por debajo del ángulo límite { $critical }°; la T sale a { $angle }° de la normal
access-change-t = la T a { $angle }° de la normal
access-step = Paso { $number } de { $count }: { $title }.
access-question = Pregunta: { $question }
access-view = Vista: { $view }.
access-scene = Escena: { $title }.
access-scene-hidden = Sus rayos se dibujan hasta la primera superficie que encuentran.
access-incidence-decrease = Reducir θi en 1°
access-incidence-increase = Aumentar θi en 1°
access-normal-turn-left = Girar N 1° a la izquierda
access-normal-turn-right = Girar N 1° a la derecha
access-index-decrease = Reducir { $symbol } en { $step }
access-index-increase = Aumentar { $symbol } en { $step }
access-page-controls = Los mandos del diagrama
access-page-keys = En el explorador de abajo, Tab recorre sus botones y campos y las flechas giran el tirador elegido; Esc y luego Mayús+Tab vuelve a estos mandos.
access-page-typing = Texto que se escribe en el explorador
access-title-scene = { $view }: { $scene }
