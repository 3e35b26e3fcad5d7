# Archivos, exportaciones y deshacer, en español: el diálogo de archivos y su pregunta antes de reemplazar,
# la herramienta «Guardar, abrir, compartir», las exportaciones de imagen y animación, deshacer y rehacer.
# { $path } es la ruta de un archivo; { $reason } es la explicación del lector o escritor (puede quedar en inglés).

## Lo que contiene un archivo

files-wrong-extension = { $path }: { $kind ->
        [state] un estado guardado (JSON)
        [png] una imagen PNG
        [scene] una escena (TOML)
        [deck] una secuencia didáctica (TOML)
        [gif] una animación GIF
       *[svg] una imagen SVG
    } se escribe en un archivo { $extension }; elige un nombre terminado en { $extension }
files-is-a-folder = { $path } es una carpeta; elige un nombre de archivo
files-holds-another-kind = { $path } contiene { $found ->
        [state] un estado guardado (JSON)
        [png] una imagen PNG
        [scene] una escena (TOML)
        [deck] una secuencia didáctica (TOML)
        [gif] una animación GIF
        [svg] una imagen SVG
       *[other] otra cosa
    }, no { $kind ->
        [state] un estado guardado (JSON)
        [png] una imagen PNG
        [scene] una escena (TOML)
        [deck] una secuencia didáctica (TOML)
        [gif] una animación GIF
       *[svg] una imagen SVG
    }: se deja como está; elige otro nombre

## La pregunta antes de reemplazar un archivo

files-replace-question = ¿Reemplazar el archivo?
files-already-exists = { $path } ya existe.
files-replace = Reemplazar
files-cancel = Cancelar

## El diálogo de abrir y guardar

files-dialog-open-title = Abrir un archivo
files-dialog-save-title = Guardar como
files-folder = Carpeta
files-showing = se muestran carpetas y { $patterns }
files-file-name = Nombre de archivo
files-open-file = Abrir archivo
files-save-file = Guardar archivo
files-cannot-list = no se puede listar { $path }: { $reason }
files-not-a-file = { $path } no es un archivo que se pueda abrir
files-type-a-name = escribe un nombre de archivo en una carpeta existente

## Guardar, abrir, compartir

files-state-file = Archivo de estado
files-save = 💾 Guardar
files-save-hover = Escribe W, N, μ y la convención como una línea JSON de solve
files-open = 🗁 Abrir
files-open-hover = Lee un archivo JSON de solve; un archivo incorrecto no cambia nada
files-open-dialog = Abrir…
files-open-dialog-hover = Elegir un archivo de estado para abrir
files-save-as = Guardar como…
files-save-as-hover = Elegir dónde guardar
files-saved = se guardó { $path }
files-not-saved = no se guardó: { $reason }
files-left-as-it-was = { $path } se dejó como estaba
files-opened = se abrió { $path }
files-opened-as-scene = { $path } es una escena, no un estado: abierta en la vista Escenas
files-opened-as-deck = { $path } es una secuencia didáctica, no un estado: abierta en su primer paso
files-neither-state-nor-scene = { $state }; leído como escena: { $scene }
files-cannot-read-state = no se puede leer el archivo de estado { $path }: { $reason }
files-state-refused = archivo de estado { $path }: { $reason }
files-copy-share = 🔗 Copiar cadena para compartir
files-copy-share-hover = Reproduce exactamente este estado en otra máquina, bit a bit
files-share-copied = se copió la cadena para compartir
files-paste-share = Pegar una cadena para compartir
files-apply = Aplicar
files-share-applied = se aplicó la cadena para compartir
files-share-refused = cadena para compartir: { $reason }
files-copy-case-as = Copiar el caso como
files-copy-solve-line = línea de solve
files-copy-test-vector = vector de prueba
files-copied = se copió: { $what }

## Exportaciones

files-wrote = se escribió { $path }
files-not-exported = no se exportó: { $reason }
files-export-cancelled = cancelado: no se escribió nada
files-export-crashed = la exportación se detuvo por un error interno
files-gif-needed = { $path }: una animación se escribe como GIF; da un nombre terminado en .gif
files-animation-heading = Animación para una diapositiva
files-animation = Animación
files-gif-file = Archivo GIF
files-drawing-frames = dibujando fotogramas… { $percent } %
files-export-animation = Exportar animación
files-export-animation-hover = Dibuja todos los fotogramas en segundo plano; la ventana sigue respondiendo
files-frames = Fotogramas
files-per-second = por segundo
files-gif-width = Ancho del GIF
files-height = alto

## Deshacer y rehacer

files-undo = Deshacer
files-undo-hover = Deshace el último cambio de W, N, μ o la convención (Ctrl+Z)
files-redo = Rehacer
files-redo-hover = Rehace lo deshecho (Ctrl+Mayús+Z)
files-undid = Deshecho: { $changes }
files-redid = Rehecho: { $changes }
files-undo-convention = la convención (sección { $from } → { $to })
files-undo-n-turned = N girada
files-undo-n-flipped = N invertida
files-undo-scene-edit = la edición de { $scene }
files-undo-scene = la escena ({ $from } → { $to })
files-undo-w-or-n-typed = W o N escritos
