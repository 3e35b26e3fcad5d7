# El explorador en un navegador y los enlaces a él, en español: el enlace de lo que ve la
# clase (Copiar enlace, el código QR, la dirección web), un enlace que no se puede abrir, el
# folleto con sus enlaces y lo que hace una página del navegador (su selector de archivos,
# las descargas, la pantalla completa, el portapapeles y un solo hilo).

## Enlaces y el código QR

link-web-base = Dirección web
link-web-base-hover = Donde la clase abre el explorador en un navegador: la dirección de la carpeta que escribe cargo xtask web, publicada en un servidor (en un navegador, la dirección de la propia página)
link-copy = 🔗 Copiar enlace
link-copy-hover = Copia el enlace que abre en un navegador lo que la clase ve ahora (este paso de la secuencia o este estado)
link-copied = Enlace copiado.
link-qr = Código QR
link-qr-hover = Muestra el enlace de lo que ve la clase como código QR sobre el diagrama (Q)
link-no-web-base = No hay dirección web: escribe la dirección donde la clase abre el explorador en un navegador.
link-file-address = Esta página se abrió desde un archivo: un teléfono no puede abrir este enlace. Publica la carpeta en un servidor y escribe su dirección.
# $format: png o svg
link-qr-save = Guardar como { $format }
# $bytes: la longitud del enlace
link-qr-too-long = El enlace es demasiado largo para un código QR ({ $bytes } bytes): cópialo en su lugar.
link-qr-close = Q o Esc cierra
# The QR code dialog: its button that takes the web address typed
link-qr-show = Mostrar el código QR
link-notice-close = Cerrar (Esc)

## Un enlace que no se puede abrir ($reason: por qué, como abajo)

link-cut-short = el enlace está cortado: cópialo otra vez, entero
# $reason: dónde está dañado el enlace, o las palabras del lector de estados
link-malformed = el enlace está dañado ({ $reason })
# $part: la parte del enlace que esta versión no lee, como v=2
link-newer = el enlace lo hizo una versión más nueva del explorador ({ $part }): ábrelo donde se ejecute esa versión
# $step: el paso tal como lo da el enlace
link-bad-step = el paso { $step } no es un número a partir de 1
link-state-and-lesson = el enlace nombra a la vez un estado y una secuencia
link-step-without-lesson = el enlace nombra un paso pero ninguna secuencia
# $name: la secuencia que nombra el enlace; $names: las secuencias incluidas
link-no-lesson = no hay ninguna secuencia incluida llamada { $name } (las secuencias: { $names })
# $count: el número de pasos de la secuencia
link-no-step = la secuencia { $name } tiene { $count } pasos, no { $step }
# $reason: uno de los mensajes de arriba
web-link-not-opened = No se pudo abrir este enlace: { $reason }. El explorador muestra lo que mostraba antes.

## El folleto

handout-export = 📄 Folleto (PDF)
handout-export-hover = Escribe la secuencia como folleto: una página por paso, con su diagrama, pregunta, notas y, si hay una dirección web, su enlace y su código QR

## En un navegador

web-page-loading = Cargando el explorador de la refracción…
# $reason: las palabras del propio navegador
web-page-failed = Este navegador no pudo iniciar el explorador de la refracción ({ $reason }). Un Firefox, Chrome, Edge o Safari reciente con WebGL 2 lo ejecuta.
web-open-through-picker = Una página del navegador abre los archivos que eliges en el selector de archivos del navegador (o que sueltas sobre la página).
web-choose-file = Elegir un archivo…
web-saved-as-download = El archivo se descarga: el navegador lo guarda en su carpeta de descargas.
web-download = Descargar
# $reason: las palabras del propio navegador
web-full-screen-refused = El navegador no entró ni salió de la pantalla completa ({ $reason }): usa su propia tecla de pantalla completa (F11) o su menú.
web-copy-refused = El navegador no permitió copiar ({ $reason }): selecciona el texto y pulsa Ctrl+C.
web-not-secure = una página abierta desde un archivo o por http puede no tener acceso al portapapeles
web-one-thread = En un navegador esto se ejecuta en el único hilo de la página: la página no responde hasta que termina.

## The installable page, a panic over the page, the page's file reads, inside another page (issue 44)

web-manifest-description = Arrastra el rayo, la normal y los índices de refracción, y mira cómo responden el rayo refractado, sus cuatro candidatos de signo y la reflexión total.
web-crash-title = El explorador se detuvo: un error en su programa. Lo que dijo:
web-crash-reload = Recargar la página
web-crash-reopen = Recargar con el último estado, para no perder nada (o copia este enlace para guardarlo):
# $name: the file's name; $reason: the browser's own words
web-read-failed = El navegador no pudo leer { $name } ({ $reason }).
# $name: the file's name; $size and $limit: sizes in MB
web-file-too-large = { $name } ocupa { $size } MB: la página abre archivos de { $limit } MB como máximo.
web-open-in-tab = ↗ Abrir en una pestaña nueva
web-open-in-tab-hover = Esta página está dentro de otra: abre el explorador en una pestaña propia para la pantalla completa y para copiar

# Nada se pierde (issue 40): enlaces rechazados con un motivo claro, la dirección web comprobada en un solo sitio.
link-part-without-name = una parte del enlace no tiene nombre («{ $part }»)
link-part-twice = el enlace da { $part } dos veces
link-web-base-refused = Esta dirección web no se puede usar: { $reason }.
link-web-base-empty = no se dio ninguna dirección
link-web-base-scheme = empieza por «{ $scheme }», no por http://, https:// ni file://
link-web-base-unseen = contiene { $character }, que una dirección no puede contener (ni espacios, ni caracteres de control, ni marcas invisibles)
link-web-base-escape = «{ $escape }» no es un escape de porcentaje (tras % van dos dígitos hexadecimales)
link-web-base-credentials = contiene un nombre de usuario o una contraseña, que todo enlace y todo código QR mostrarían
link-web-base-too-long = mide { $bytes } bytes: como mucho { $most } mantienen legibles en papel los códigos QR de los enlaces
link-web-base-port = su puerto no es un número de 0 a 65535
link-web-base-host = falta su host o no es un nombre ni una dirección IP válidos ({ $reason })
storage-web-base-unusable = No se usa la dirección web guardada la última vez: { $reason }.
storage-state-unreadable = No se pudo leer el estado guardado la última vez ({ $reason }): el explorador empieza en el estado predeterminado.
