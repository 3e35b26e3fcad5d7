# Ein ganzes Protokoll im Fenster geprüft: sein Abschnitt in „Mein T prüfen“, die Datei, aus
# der es gelesen wird, seine Diagnose, seine Fehlerkarte und seine falschen Zeilen als Tests.

logs-hint = Zeilen mit den Feldern { $fields }: JSON Lines, CSV mit einer Kopfzeile, die sie nennt, oder printf-Zeilen, gelesen mit einem Muster wie { $example }. Höchstens { $characters } Zeichen einfügen oder eine Protokolldatei öffnen; die ersten { $count } Zeilen werden aufgelistet, jede Zeile geht in die Diagnose ein.
logs-inside = Brechzahl innen
logs-outside = außen
logs-indices-hint = die Brechzahl des Körpers und seiner Umgebung, für Zeilen, die entering protokollieren
logs-index-invalid = { $field }: „{ $text }“ ist keine Brechzahl (eine endliche Zahl über 0)
logs-not-listed = { $count ->
    [one] { $count } weitere Zeile geprüft, aber nicht aufgelistet (die Tabelle zeigt die ersten { $first })
   *[other] { $count } weitere Zeilen geprüft, aber nicht aufgelistet (die Tabelle zeigt die ersten { $first })
}
logs-diagnosis-heading = Diagnose des ganzen Protokolls
logs-copy-diagnosis = Diagnose und Tabelle kopieren
logs-copy-diagnosis-hover = Als Text: die Zählung, die Diagnose, dann eine Zeile je Aufruf mit Tabulatoren zwischen den Zellen
logs-map-heading = Fehlerkarte
logs-map-hover = Wie weit die Richtung jeder geprüften Zeile von der richtigen abweicht, gegen den Einfallswinkel, in einem Feld für jede Seite, von der die Strahlen kommen. Quadrate: die richtige Antwort ist Totalreflexion.
logs-open = 🗁 Protokoll öffnen …
logs-open-hover = Eine Protokolldatei lesen (oder auf das Fenster ziehen): bis zu { $most } Zeilen werden geprüft und diagnostiziert.
logs-what-log = Protokoll
logs-read-failed = { $path } ließ sich nicht lesen: { $reason }
logs-opened = Geprüft wird die Datei { $path }: { $lines ->
    [one] { $lines } Zeile
   *[other] { $lines } Zeilen
} (höchstens { $most }).
logs-close-file = Stattdessen tippen oder einfügen
logs-save-tests = { $count ->
    [one] Die falsche Zeile
   *[other] Die ersten { $count } falschen Zeilen
} als Tests speichern:
logs-tests-extension = { $path }: Tests in dieser Sprache werden in eine { $extension }-Datei geschrieben; einen Namen auf .{ $extension } wählen
logs-tests-not-ours = { $path } ist keine Testdatei dieses Werkzeugs; einen anderen Namen wählen, damit der eigene Code erhalten bleibt
logs-write-failed = { $path } ließ sich nicht schreiben: { $reason }

diagram-failure-right = richtig
diagram-failure-wrong = falsch
diagram-failure-past-critical = richtige Antwort: Totalreflexion
diagram-failure-panel = { $side ->
    [outside] Von außen kommend
    [inside] Von innen kommend
   *[unknown] Seite nicht protokolliert
}: { $lines ->
    [one] { $lines } Zeile
   *[other] { $lines } Zeilen
}, { $wrong ->
    [0] keine falsch
   *[other] { $wrong } falsch
}
diagram-failure-caption = Wie weit die Richtung, in die jede geprüfte Zeile den Strahl schickt, von der richtigen abweicht, gegen den Einfallswinkel θi:
diagram-failure-empty = Keine Zeile wurde geprüft.
diagram-failure-about = Fehlerkarte. { $panels }

# check --tests and Save failing lines as tests: what is at the path cannot be read, or is not a file (issue 40)
logs-tests-unreadable = { $path } lässt sich nicht lesen ({ $reason }), also nicht vom eigenen Code unterscheiden: die Datei bleibt, wie sie ist; einen anderen Namen wählen
logs-tests-not-a-file = { $path } ist keine gewöhnliche Datei (eine Pipe, ein Gerät oder ein Link darauf): Tests werden nur in eine eigene Datei geschrieben; einen anderen Namen wählen
