# python.ftl (de): das Python-Paket refraction_check: warum ein Argument von check() abgelehnt
# wird (sein ValueError), und der kurze Text und die Notebook-Tabelle mit dem Befund.

## Abgelehnte Argumente

python-unknown-api = api: unbekannte API '{ $name }': erwartet 'glsl' (oder 'hlsl', 'wgsl', 'glm', 'glam'), 'pbrt', 'rtiow', 'mitsuba' oder None für die eigene Brechung eines beliebigen Renderers
python-unknown-argument = unbekanntes Argument `{ $argument }` für api={ $api }: die Felder eines Aufrufs sind { $fields } (`from` wird from_ geschrieben), die Optionen inside, outside, normal, convention, precision und renderer
python-index = { $argument } muss eine endliche Zahl > 0 sein (ein Brechungsindex), nicht { $value }
python-sides-apart = { $given } ohne { $missing }: gib beide Indizes an oder keinen
python-not-with-api = { $argument } gilt für die eigene Brechung eines beliebigen Renderers (api=None): Aufrufe von api='{ $api }' folgen der Konvention dieser API, ihre Normale steht in einem eigenen Feld
python-normal = normal muss eine Achse ('+z', '-y'...) oder drei endliche Zahlen ungleich null sein, nicht { $value }
python-unknown-word = { $argument }: unbekannter Wert '{ $value }': erwartet wird einer von { $expected }
python-shape = { $argument } hat die Form { $shape }: erwartet { $expected }, N die Zahl der Aufrufe
python-not-numbers = { $argument } muss Zahlen enthalten: { $reason }
python-not-flag = { $argument } muss True/False oder 1/0 enthalten, nicht { $value } (Zeile { $row })
python-rows = { $argument } hat { $rows ->
    [one] eine Zeile
   *[other] { $rows } Zeilen
}, aber { $other } hat { $other_rows }: gib jedem Argument eine Zeile pro Aufruf oder einen Wert für alle Aufrufe
python-no-rows = { $argument } hat keine Zeilen: es gibt keinen Aufruf zu prüfen
python-nothing-judged = { $calls ->
    [one] Der Aufruf kann nicht beurteilt werden
   *[other] Keiner der { $calls } Aufrufe kann beurteilt werden
}: { $reason }

## Der Befund

python-title = { $calls ->
    [one] 1 Aufruf
   *[other] { $calls } Aufrufe
}, { $ok } richtig
python-column-code = Code
python-column-calls = Aufrufe
python-column-row = Zeile
python-column-explanation = Erklärung
python-first-wrong = { $wrong ->
    [one] Der falsche Aufruf:
   *[other] Die ersten { $shown } von { $wrong } falschen Aufrufen:
}
