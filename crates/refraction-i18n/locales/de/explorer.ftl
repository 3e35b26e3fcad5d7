# Das Fenster, seine obere Leiste, Werkzeuge und Bereiche, auf Deutsch.
# Schlüssel sind in kebab-case und beginnen mit dem, wozu sie gehören; Platzhalter ({ $name }) enthalten
# Zahlen, die bereits ortsüblich geschrieben sind (mit Dezimalkomma, wo die Sprache eines verwendet).

## Die Leiste oben

view-interface = Eine Grenzfläche
view-scenes = Szenen
view-menu = Ansicht
view-accuracy = Genauigkeit/Zeit
# Bezeichnet in einer Fehlermeldung eine Szene, die vom letzten Lauf übrig ist.
view-last-run-scene = die Szene des letzten Laufs
# Was das letzte Rückgängigmachen oder Wiederholen bewirkt hat ($change), und die Ansicht, zu der es gewechselt hat ($view).
travel-in-view = { $change } (Ansicht: { $view })
tool-check = Mein T prüfen
tool-walk-through = Schritt für Schritt
tool-files = Speichern, öffnen, teilen
tool-fresnel = Fresnel
presentation-toggle = 🖵 Präsentation
presentation-toggle-hover = Vollbild, alles größer (F11)
presentation-theme = Design
presentation-theme-hover = Standard oder hoher Kontrast: Schwarz auf Weiß oder Weiß auf Schwarz
presentation-colour-blind = Für Farbenblinde
presentation-colour-blind-hover = Nur Okabe–Ito-Farben; jeder Strahl hat zudem eigene Strichelung und Beschriftung
presentation-simple = Einfache Ansicht
presentation-simple-hover = Lässt die drei verworfenen Vorzeichenwahlen und ihr (a, b) weg: für eine Klasse, die die vier Kandidaten noch nicht kennt
presentation-look = Aussehen
presentation-diagram-only = Nur das Diagramm (D)
language-menu = Sprache
language-hover = Die Sprache des Fensters. Ohne Wahl hier folgt sie der des Systems.
effects-menu = Effekte
effects-menu-hover = Intensitäten (Fresnel) und Wellenfronten über dem Diagramm
effects-intensities = Intensitäten
effects-intensities-hover = Reflektierten und durchgelassenen Strahl nach ihrem Anteil am Licht zeichnen (Fresnel), mit Prozentangaben
effects-wavefronts = Wellenfronten
effects-wavefronts-hover = Ebene Wellenfronten im Abstand λ/μ in jedem Medium, die mit c/μ laufen: darum wird der Strahl gebrochen
effects-moving = Bewegt
effects-huygens = Huygenssche Konstruktion
effects-huygens-hover = Zwei Punkte einer Wellenfront und die in der Zeit dazwischen gewachsene Elementarwelle

## Die Seitenbereiche ($key ist die Taste, die sie öffnet und schließt, etwa F2)

panel-show-controls = Steuerung einblenden ({ $key })
panel-hide-controls = Steuerung ausblenden ({ $key })
panel-show-numbers = Zahlen einblenden ({ $key })
panel-hide-numbers = Zahlen ausblenden ({ $key })

## Unter dem Diagramm

canvas-hint = W, N oder eine μ-Marke ziehen oder − und + darunter nutzen; Tab oder ein Klick wählt einen Anfasser für die Pfeiltasten
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Umschalt: 0,1°) · +/− μt · Tab: nächster Anfasser · ziehen zum Verschieben
canvas-hint-index = ↑/↓ oder +/− ändern den Brechungsindex um 0,01 (Umschalt: 0,001) · Tab: nächster Anfasser

## Der Bereich Steuerung

controls-lesson = Lektion
controls-lesson-preset = Lektionsvorgabe
controls-lesson-own = Eigener Fall
controls-lesson-changed = { $lesson }, geändert
controls-reset = Zurücksetzen
controls-reset-hover = Zurück zum Anfang der gewählten Lektion
controls-incidence = θi (Grad)
controls-convention = Konvention
controls-convention-toward-origin = Abschnitt 1: W zeigt zurück zum Ursprung
controls-convention-along-ray = Abschnitt 2: W ist die Ausbreitungsrichtung
controls-flip-normal = N umkehren
controls-flip-normal-hover = Die Normale umkehren – so liegt eine äußere Normale dort, wo ein Strahl aus dem Glas austritt
controls-snap = W auf θc
controls-snap-hover = W auf den Grenzwinkel setzen (erfordert μi > μt)
controls-snap-disabled = Einen Grenzwinkel gibt es nur bei μi > μt
controls-indices = Brechungsindizes
# $symbol ist μi oder μt.
controls-index-value = Wert von { $symbol }
controls-material = Material für { $symbol }
controls-custom-hint = eigener Wert: oben einen Wert eingeben
controls-typed-vectors = W und N von Hand
controls-typed-vectors-hint = Von Lernenden protokollierte Vektoren einfügen (x, y, z); Enter drücken.
controls-export-heading = Bild exportieren (PNG oder SVG)
controls-export-size = Größe
controls-export-file = Datei
controls-export-file-hint = ein Name auf .png oder .svg, oder nummeriert diagram-001.png
controls-browse = Durchsuchen…
controls-export = Bild exportieren
controls-exported = { $path } geschrieben
# Ein eingegebener Wert, der keine Zahl ist: $name ist das, wofür er eingegeben wurde (θi, μt, W).
typed-not-a-number = { $name }: „{ $text }“ ist keine Zahl
typed-not-three-numbers = { $name }: drei Zahlen x, y, z erwartet, { $count } erhalten

## Der Bereich Zahlen

readouts-discriminant = Diskriminante k = μ²wn² − μ² + 1 = { $k } ≥ 0: T existiert
readouts-discriminant-tir = Diskriminante k = μ²wn² − μ² + 1 = { $k } < 0: Totalreflexion
# $section ist der Abschnitt des Artikels (1 oder 2), dessen Gleichung 20 dies ist.
readouts-quadratic = Gl. { $section }.20, die quadratische Gleichung in b: b² + 2a·wn·b + a² − 1 = 0 mit a = { $a }, wn = { $wn }
readouts-no-roots = keine reellen Nullstellen: Die Parabel erreicht null nicht mehr
readouts-roots = Lösungen b = { $roots } (die b der Kandidaten für dieses a)
readouts-candidates = Die vier Kandidaten
readouts-candidate = Kandidat
# Die Spaltenköpfe der Prüfungen: das quadrierte Snelliussche Brechungsgesetz (Gl. 10 des Artikels), die Seite der Fläche, auf der T liegt, die Richtung, in die T gebrochen wird.
readouts-check-snell = Gl. 10
readouts-check-side = Seite
readouts-check-bend = Brechung
readouts-no-candidates = Keine Kandidaten: k < 0, also gibt es keine reelle Lösung für b und kein T.
readouts-candidates-note = Alle vier haben die Länge 1 und erfüllen das quadrierte Snelliussche Gesetz (Gl. 10): Durch das Quadrieren lassen sie sich nicht unterscheiden. Nur Seite und Brechung (das Argument μ = 1 des Artikels) wählen T aus.
readouts-warnings = Kernel-Warnungen
readouts-no-warnings = Keine Warnungen: W und N haben die Länge 1, und N zeigt zum Strahl.
readouts-warning-not-unit = { $vector } hat die Länge { $length }, nicht 1: Er wurde normiert (nicht normierte Vektoren sind ein häufiger Fehler in Raytracern)
readouts-warning-flipped = N zeigt vom einfallenden Strahl weg (wie eine äußere Normale dort, wo ein Strahl eine Kugel verlässt): Der Kernel hat −N verwendet, die Normale, die zum Strahl zeigt
readouts-equations = Gleichungen des Artikels, Abschnitt { $section }

## Schritt für Schritt

walk-previous = Vorheriger Schritt
walk-next = Nächster Schritt
walk-animate = μ gegen 1 animieren
walk-animating = μ wird gegen 1 animiert …
walk-animate-hover = μt in μi überführen: Das gewählte T konvergiert gegen den einfallenden Strahl
walk-animate-disabled = μ ist bereits 1 (μi = μt), oder die Animation läuft
walk-step = Schritt { $number } von { $count }: { $title }

## Das Fresnel-Werkzeug

fresnel-plot-about = Fresnel-Diagramm: reflektiertes und durchgelassenes Licht gegen θi, der Cursor bei θi = { $angle }°
fresnel-click-hint = In den Graphen klicken oder darin ziehen, um θi zu setzen.
fresnel-at = Bei θi = { $angle }°, von μi = { $mu_i } nach μt = { $mu_t }.
fresnel-brewster = Brewster-Winkel θB = { $angle }°: Dort wird kein p-polarisiertes Licht reflektiert (tan θB = μt/μi).
fresnel-equal-indices = Gleiche Brechungsindizes: keine Grenzfläche, nichts wird reflektiert.
fresnel-critical = Grenzwinkel θc = { $angle }°: Darüber wird alles Licht reflektiert (sin θc = μt/μi).
fresnel-no-critical = Kein Grenzwinkel: Das Licht geht in ein Medium mit höherem Brechungsindex über.

## Die Ansicht Szenen

scenes-scene = Szene
scenes-rays = Strahlen
scenes-draft = Entwurf beim Ziehen: jeder { $every }. Strahl
scenes-reset-hover = die Szene so, wie sie in ihrer Datei steht
scenes-file = Szenendatei
scenes-open = Datei öffnen
scenes-save = Datei speichern
scenes-save-hover = die bearbeitete Szene, im Szenenformat (TOML)
scenes-open-dialog-hover = Eine Szenendatei zum Öffnen wählen
scenes-saved = { $path } gespeichert
scenes-opened = { $path } geöffnet
scenes-hint = Die Quelle (bernsteinfarben), ihre Richtung (den Ring am Ende des gestrichelten Pfeils) oder den Anfasser einer Form ziehen; einen Trefferpunkt anklicken, um ihn in „Eine Grenzfläche“ zu öffnen.
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Dateien und Hinweis
scenes-less = Weniger Bedienelemente
scenes-picture-file = Bilddatei (.png oder .svg)
scenes-picture-hint = ein Name auf .png oder .svg, oder nummeriert scene-001.svg
scenes-export-size = { $width }×{ $height } exportieren
scenes-tracing = Strahlverfolgung… { $percent } % (gezeigt wird die letzte fertige Verfolgung)
scenes-cancel = Abbrechen
scenes-cancel-hover = die Verfolgung stoppen und zeigen, was bisher verfolgt wurde
scenes-stopped-segments = die Verfolgung hielt an ihrem Limit von { $budget } Segmenten an: Die noch nicht verfolgten Strahlen fehlen (weniger Strahlen, ein kleineres max_depth oder ein größeres min_intensity werden vollständig verfolgt)
scenes-stopped-tests = die Verfolgung hielt an ihrem Limit von { $budget } Schnitttests an: Die noch nicht verfolgten Strahlen fehlen (weniger Strahlen, Formen oder Reflexionen werden vollständig verfolgt)
scenes-stopped-cancelled = die Verfolgung wurde abgebrochen: Die noch nicht verfolgten Strahlen fehlen
# Der Kasten neben einem Trefferpunkt unter dem Mauszeiger: die Medien, aus denen und in die der Strahl geht, ihre Brechungsindizes und die verfolgte Wellenlänge.
scenes-hit =
    von { $from } in { $to } ({ $side ->
        [entering] Eintritt
       *[leaving] Austritt: Der Kernel kehrt N um
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } nm
    Klick: in „Eine Grenzfläche“ öffnen

## Die Ansicht Genauigkeit

accuracy-heading = Was Genauigkeit an Zeit kostet
accuracy-intro = Misst auf diesem Rechner die Laufzeit jeder Kernel-Variante in f32 und f64 und ihren Fehler gegenüber einem Double-Double-Orakel bei zufälligen und schwierigen Einfallsrichtungen. Der Graph zeigt den größten Fehler der schwierigen Fälle in Einheiten von ε·κ (was der Algorithmus über das hinaus verliert, was das Problem selbst verstärkt) über den Nanosekunden pro Strahl.
accuracy-quick = Kurzlauf (wenige Sekunden)
accuracy-measure = Messen
accuracy-measuring = Messung… { $percent } %
accuracy-press-measure = „Messen“ drücken, um den Benchmark zu starten.
# $variant benennt eine Kernel-Variante und ihre Genauigkeit, etwa „stable f32“.
accuracy-verdict = Am schnellsten innerhalb 10× der besten Genauigkeit: { $variant } mit { $time } ns pro Strahl (Fehler schwierige Fälle { $error } ε·κ).
accuracy-footnote = { $random } zufällige und { $hard } schwierige Probleme auf { $cpu }. Die Zeiten hängen davon ab, was der Rechner sonst tut; `refraction-explorer bench` liefert dieselben Werte auf der Kommandozeile.
accuracy-plot-about = Genauigkeit gegen Zeit: { $count } Varianten, jede an ihrer Form zu erkennen und daneben benannt
accuracy-hover =
    { $name }
    { $time } ns, { $error } ε·κ
accuracy-column-variant = Variante
accuracy-column-time = ns/Strahl
accuracy-column-random = max. Fehler zufällig
accuracy-column-hard = max. Fehler schwierig
accuracy-column-eps-kappa = schwierig ε·κ
accuracy-column-tir = Abweichungen Totalreflexion

## Die Schüleransicht: was ein Handy (oder ein Link mit view=student) zeigt, und die Knöpfe,
## die W, N und die Brechzahlen schrittweise ändern

# $symbol: μi oder μt
student-index = Brechzahl { $symbol }
student-full = Ganzer Explorer
student-full-hover = Der ganze Explorer mit seinen Werkzeugen und Leisten (für ein großes Display)
student-view = Schüleransicht
student-view-hover = Die Ansicht für ein Handy: die Frage, das Diagramm über die ganze Breite und Knöpfe für den Finger
