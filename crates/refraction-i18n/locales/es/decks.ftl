## Secuencias didácticas: la herramienta que construye una, la franja que muestra su paso, la
## ventana de notas, el folleto y los títulos, preguntas y notas de las secuencias incluidas

tool-deck = Secuencia didáctica
deck-answer-hidden = La respuesta está oculta: primero predice, luego revélala

## La herramienta

deck-title-field = Título de la secuencia
deck-file = Archivo de la secuencia
deck-open-file = Abrir archivo
deck-save-file = Guardar archivo
deck-open-dialog-hover = Elige un archivo de secuencia para abrirlo
deck-built-in = Secuencias incluidas
deck-new = Nueva secuencia
deck-new-hover = Empieza una secuencia vacía; la mostrada se cierra (guárdala antes)
deck-add-step = Añadir el estado actual como paso
deck-add-step-hover = Un paso nuevo tras el mostrado, con el diagrama tal como está: W, N, los índices, la vista, su escena, la herramienta abierta y los efectos
deck-update-step = Conservar el estado actual en este paso
deck-update-step-hover = Arrastrar durante un paso solo cambia el diagrama; esto conserva en el paso lo que muestra ahora (guarda la secuencia para conservarlo en el archivo)
deck-steps = Pasos
deck-no-steps = Aún no hay pasos: prepara el diagrama y añádelo como paso.
# $number es el número del paso, $title su título
deck-step-row = { $number }. { $title }
deck-move-up = Subir el paso
deck-move-down = Bajar el paso
deck-delete = Borrar el paso
deck-step-title = Título
deck-step-question = Pregunta para la clase
deck-step-question-hint = ninguna: la respuesta se ve enseguida
deck-step-notes = Notas para el docente
deck-untitled = Paso { $number }
deck-edited = cambiada desde que se guardó
deck-saved = se guardó { $path }
deck-opened = se abrió { $path }
deck-not-saved = no se guardó: { $reason }
deck-nothing-to-save = La secuencia no tiene pasos que guardar: añade uno primero.

## Recorrer una secuencia

# $number es el paso mostrado, $count los pasos de la secuencia: «2 / 5»
deck-step-number = { $number } / { $count }
deck-previous = Paso anterior
deck-next = Paso siguiente
deck-reveal = Revelar la respuesta
deck-hide = Ocultar la respuesta
deck-notes-window = Ventana de notas
deck-notes-window-hover = Las notas del docente en una ventana propia, para la pantalla del portátil mientras el proyector muestra el diagrama
deck-keys = Av Pág, → o espacio: paso siguiente · Re Pág o ←: anterior · R: revelar la respuesta · N: ventana de notas
deck-hidden-hint = R revela la respuesta
deck-shown-hint = R vuelve a ocultar la respuesta
# $title es el título de la secuencia
deck-notes-title = Notas: { $title }
deck-notes-none = Este paso no tiene notas.
# $title es el título del paso siguiente
deck-notes-next = Siguiente: { $title }
deck-notes-last = Este es el último paso.

## El folleto (render --lesson … --out handout.pdf)

deck-handout-question = Pregunta
deck-handout-notes = Notas

## Secuencia incluida: la ley de Snell en diez minutos

deck-snell-title = La ley de Snell en diez minutos
deck-snell-1-title = Del aire al vidrio
deck-snell-1-question = El rayo pasa del aire al vidrio. ¿Se desvía hacia la normal o se aleja de ella?
deck-snell-1-notes = Hacia la normal: θt es menor que θi, porque el vidrio es el medio más denso. Arrastra W despacio de 0° a 80° y deja que la clase lea los dos ángulos.
deck-snell-2-title = Justo por la normal
deck-snell-2-question = Un rayo llega a la superficie a lo largo de la normal. ¿Hacia dónde se desvía?
deck-snell-2-notes = No se desvía: θi = θt = 0 para cualquier par de medios. La luz solo va más despacio en el vidrio.
deck-snell-3-title = La ley de Snell
deck-snell-3-notes = El primer paso de «Paso a paso»: μi sen θi = μt sen θt. Pide a dos estudiantes que lean θi y θt y calculen los dos lados; coinciden hasta la última cifra mostrada.
deck-snell-4-title = Del vidrio al aire
deck-snell-4-question = Ahora el rayo sale del vidrio. ¿Hacia dónde se desvía?
deck-snell-4-notes = Se aleja de la normal: θt es mayor que θi. Sube θi y la T gira hacia la superficie: el ángulo límite de la próxima clase.
deck-snell-5-title = A través de una lámina de vidrio
deck-snell-5-question = El rayo cruza una lámina de caras paralelas. ¿En qué dirección sale?
deck-snell-5-notes = Paralelo al rayo que llega, desplazado de lado: la segunda refracción deshace la primera. Arrastra la fuente para mostrar que el desplazamiento crece con el ángulo.

## Secuencia incluida: la reflexión total y la fibra

deck-tir-title = La reflexión total y la fibra
deck-tir-1-title = Saliendo del vidrio
deck-tir-1-question = El rayo pasa del vidrio al aire. ¿Qué les pasa a la T y al rayo reflejado cuando θi crece?
deck-tir-1-notes = La T gira hacia la superficie y se debilita mientras el rayo reflejado se hace más brillante: Intensidades dibuja cada rayo según su parte de la luz.
deck-tir-2-title = Justo antes del ángulo límite
deck-tir-2-question = ¿Con qué ángulo quedará la T a lo largo de la superficie?
deck-tir-2-notes = Con el ángulo límite: sen θc = μt/μi, 41,8° del vidrio al aire. A 41° la T casi roza la superficie; el botón «Ajustar W a θc» pone W justo ahí.
deck-tir-3-title = Más allá del ángulo límite
deck-tir-3-question = W está a 45°, más allá de 41,8°. ¿Adónde va la luz?
deck-tir-3-notes = Se refleja toda: reflexión total. El kernel no encuentra T, así que tampoco hay candidatos rechazados; la franja de arriba lo dice.
deck-tir-4-title = Del agua al aire
deck-tir-4-question = ¿El ángulo límite del agua es mayor o menor que el del vidrio?
deck-tir-4-notes = Mayor: arcsen(1/1,333) = 48,6°, porque el agua es menos densa que el vidrio. A 50° el rayo queda atrapado; un buceador ve el cielo solo dentro de un cono de 48,6°.
deck-tir-5-title = La fibra
deck-tir-5-question = La luz entra por el extremo de la fibra. ¿Se escapa por el costado?
deck-tir-5-notes = No: cada impacto en el costado de la fibra está más allá del ángulo límite, así que el rayo se refleja totalmente cada vez y la fibra lo guía. Gira la fuente hasta que la luz se escape.
deck-tir-6-title = El prisma como espejo
deck-tir-6-question = ¿Por qué un prisma de ángulo recto refleja como un espejo?
deck-tir-6-notes = Dentro, el rayo llega a la cara larga a 45°, más allá del ángulo límite del vidrio del prisma (41,3°): se refleja totalmente y casi no pierde luz; por eso los prismáticos llevan prismas.

## Secuencia incluida: Fresnel y Brewster

deck-fresnel-title = Fresnel y Brewster
deck-fresnel-1-title = ¿Cuánta luz se refleja?
deck-fresnel-1-question = A 40° del aire al vidrio, ¿qué parte de la luz se refleja?
deck-fresnel-1-notes = Cerca del 5 % (4 % en incidencia normal): el resto sigue como T. La gráfica de Fresnel muestra R y T frente a θi, con el θi del diagrama marcado.
deck-fresnel-2-title = Cerca de la incidencia rasante
deck-fresnel-2-question = A 80°, ¿la reflexión es más débil o más fuerte que a 40°?
deck-fresnel-2-notes = Mucho más fuerte: sube hacia el 100 % en incidencia rasante; por eso un lago refleja la orilla lejana y no el cielo que tiene encima.
deck-fresnel-3-title = El ángulo de Brewster
deck-fresnel-3-question = Luz p llega al vidrio a 56,3°. ¿Cuánta se refleja?
deck-fresnel-3-notes = Nada: en el ángulo de Brewster, tg θB = μt/μi, los rayos reflejado y refractado forman un ángulo recto y la luz p no se refleja en absoluto. Las gafas de sol polarizadas lo aprovechan.
deck-fresnel-4-title = Luz s con el mismo ángulo
deck-fresnel-4-notes = La luz s aún se refleja, cerca del 15 %: la luz reflejada está en parte polarizada, sobre todo en el ángulo de Brewster.
deck-fresnel-5-title = Reflexiones en una lámina
deck-fresnel-5-question = ¿Cuántos rayos salen de una lámina de vidrio si cada superficie refleja un poco?
deck-fresnel-5-notes = Cada impacto genera un rayo reflejado, cada vez más débil: dos rayos fuertes y luego una fila de débiles. Las intensidades bajan en cada rebote.

## Secuencia incluida: convenios de signos para trazadores de rayos

deck-signs-title = Convenios de signos para trazadores de rayos
deck-signs-1-title = Los cuatro candidatos
deck-signs-1-question = Elevar las ecuaciones al cuadrado deja entrar cuatro soluciones. ¿Cuál es la T?
deck-signs-1-notes = Los tres fantasmas rompen una regla cada uno: el lado equivocado (la otra raíz para b), el desvío equivocado (el otro signo de a) e invertido (los dos). Solo la T queda al otro lado y se desvía bien.
deck-signs-2-title = Al salir de una gota
deck-signs-2-question = El rayo sale de una gota y N apunta hacia fuera de la gota, a lo largo del rayo. ¿Qué debe hacer el código con N?
deck-signs-2-notes = Invertirla: el kernel necesita la normal que mira al rayo. El rayo de aviso discontinuo es la fórmula con N tal como se da: el error de un renderizador que olvida invertirla.
deck-signs-3-title = Sección 1: W de vuelta hacia el origen
deck-signs-3-question = Aquí W apunta de vuelta hacia donde vino el rayo. ¿Qué signo de la fórmula cambia?
deck-signs-3-notes = El signo de a: a = −μ en la sección 1, +μ en la sección 2. pbrt y Mitsuba pasan wi así; mezclar los dos convenios da el desvío equivocado.
deck-signs-4-title = Sección 2: W a lo largo del rayo
deck-signs-4-notes = El mismo rayo con W a lo largo de él, como lo pasan GLSL, glam y el libro: a = +μ, y la T es el mismo vector que en la sección 1.
deck-signs-5-title = Tres errores en una llamada a una API
deck-signs-5-question = La T de un renderizador está mal. ¿Qué tres errores en la llamada a refract cometen más los estudiantes?
deck-signs-5-notes = La razón al revés (μt/μi en vez de μi/μt), el vector incidente en el otro convenio y la normal exterior donde el rayo sale. Pega una llamada registrada en «Comprobar mi T»: nombra el error y su arreglo.
