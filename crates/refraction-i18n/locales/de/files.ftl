# Dateien, Exporte und Rückgängig auf Deutsch: der Dateidialog und die Frage vor dem Ersetzen,
# das Werkzeug „Speichern, öffnen, teilen“, der Bild- und Animationsexport, Rückgängig und Wiederholen.
# { $path } ist ein Dateipfad; { $reason } ist die Erklärung des Lese- oder Schreibvorgangs (kann Englisch bleiben).

## Was eine Datei enthält

files-wrong-extension = { $path }: { $kind ->
        [state] Ein gespeicherter Zustand (JSON)
        [png] Ein PNG-Bild
        [scene] Eine Szene (TOML)
        [deck] Eine Unterrichtsfolge (TOML)
        [gif] Eine GIF-Animation
       *[svg] Ein SVG-Bild
    } wird als { $extension }-Datei geschrieben; bitte einen Namen mit der Endung { $extension } wählen
files-is-a-folder = { $path } ist ein Ordner; bitte einen Dateinamen wählen
files-holds-another-kind = { $path } enthält { $found ->
        [state] einen gespeicherten Zustand (JSON)
        [png] ein PNG-Bild
        [scene] eine Szene (TOML)
        [deck] eine Unterrichtsfolge (TOML)
        [gif] eine GIF-Animation
        [svg] ein SVG-Bild
       *[other] etwas anderes
    }, { $kind ->
        [state] keinen gespeicherten Zustand (JSON)
        [png] kein PNG-Bild
        [scene] keine Szene (TOML)
        [deck] keine Unterrichtsfolge (TOML)
        [gif] keine GIF-Animation
       *[svg] kein SVG-Bild
    }: Die Datei bleibt unverändert; bitte einen anderen Namen wählen

## Die Frage vor dem Ersetzen

files-replace-question = Datei ersetzen?
files-already-exists = { $path } ist bereits vorhanden.
files-replace = Ersetzen
files-cancel = Abbrechen

## Der Dialog zum Öffnen und Speichern

files-dialog-open-title = Datei öffnen
files-dialog-save-title = Speichern unter
files-folder = Ordner
files-showing = angezeigt: Ordner und { $patterns }
files-file-name = Dateiname
files-open-file = Öffnen
files-save-file = Speichern
files-cannot-list = Ordner { $path } lässt sich nicht auflisten: { $reason }
files-not-a-file = { $path } ist keine Datei, die sich öffnen lässt
files-type-a-name = bitte einen Dateinamen in einem vorhandenen Ordner eingeben

## Speichern, öffnen, teilen

files-state-file = Zustandsdatei
files-save = 💾 Speichern
files-save-hover = W, N, μ und die Konvention als JSON-Zeile für solve schreiben
files-open = 🗁 Öffnen
files-open-hover = Eine JSON-Datei für solve lesen; eine fehlerhafte Datei ändert nichts
files-open-dialog = Öffnen…
files-open-dialog-hover = Eine Zustandsdatei zum Öffnen auswählen
files-save-as = Speichern unter…
files-save-as-hover = Speicherort wählen
files-saved = gespeichert: { $path }
files-not-saved = nicht gespeichert: { $reason }
files-left-as-it-was = { $path } bleibt unverändert
files-opened = geöffnet: { $path }
files-opened-as-scene = { $path } ist eine Szene, kein Zustand: in der Szenenansicht geöffnet
files-opened-as-deck = { $path } ist eine Unterrichtsfolge, kein Zustand: beim ersten Schritt geöffnet
files-neither-state-nor-scene = { $state }; als Szene gelesen: { $scene }
files-cannot-read-state = Zustandsdatei { $path } lässt sich nicht lesen: { $reason }
files-state-refused = Zustandsdatei { $path }: { $reason }
files-copy-share = 🔗 Zustandscode kopieren
files-copy-share-hover = Stellt genau diesen Zustand auf einem anderen Rechner wieder her, Bit für Bit
files-share-copied = Zustandscode kopiert
files-paste-share = Zustandscode einfügen
files-apply = Anwenden
files-share-applied = Zustandscode angewendet
files-share-refused = Zustandscode: { $reason }
files-copy-case-as = Den Fall kopieren als
files-copy-solve-line = solve-Zeile
files-copy-test-vector = Testvektor
files-copied = kopiert: { $what }

## Exporte

files-wrote = geschrieben: { $path }
files-not-exported = nicht exportiert: { $reason }
files-export-cancelled = abgebrochen: nichts wurde geschrieben
files-export-crashed = der Export brach mit einem internen Fehler ab
files-gif-needed = { $path }: Eine Animation wird als GIF geschrieben; bitte einen Namen mit der Endung .gif wählen
files-animation-heading = Animation für eine Folie
files-animation = Animation
files-gif-file = GIF-Datei
files-drawing-frames = Bilder werden gezeichnet… { $percent } %
files-export-animation = Animation exportieren
files-export-animation-hover = Zeichnet alle Bilder im Hintergrund; das Fenster bleibt bedienbar
files-frames = Bilder
files-per-second = pro Sekunde
files-gif-width = GIF-Breite
files-height = Höhe

## Rückgängig und Wiederholen

files-undo = Rückgängig
files-undo-hover = Die letzte Änderung von W, N, μ oder Konvention rückgängig machen (Strg+Z)
files-redo = Wiederholen
files-redo-hover = Rückgängig Gemachtes wiederholen (Strg+Umschalt+Z)
files-undid = Rückgängig: { $changes }
files-redid = Wiederholt: { $changes }
files-undo-convention = Konvention (Abschnitt { $from } → { $to })
files-undo-n-turned = N gedreht
files-undo-n-flipped = N umgekehrt
files-undo-scene-edit = Bearbeitung von { $scene }
files-undo-scene = Szene ({ $from } → { $to })
files-undo-w-or-n-typed = W oder N eingegeben
