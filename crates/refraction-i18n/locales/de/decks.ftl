## Unterrichtsfolgen: das Werkzeug, das eine Folge baut, der Streifen mit ihrem Schritt, das
## Notizenfenster, das Handout und die Titel, Fragen und Notizen der eingebauten Folgen

tool-deck = Unterrichtsfolge
deck-answer-hidden = Die Antwort ist verborgen: erst vorhersagen, dann aufdecken

## Das Werkzeug

deck-title-field = Titel der Folge
deck-file = Datei der Folge
deck-open-file = Datei öffnen
deck-save-file = Datei speichern
deck-open-dialog-hover = Eine Datei mit einer Unterrichtsfolge zum Öffnen wählen
deck-built-in = Eingebaute Folgen
deck-new = Neue Folge
deck-new-hover = Eine leere Folge beginnen; die gezeigte wird geschlossen (vorher speichern)
deck-add-step = Den aktuellen Zustand als Schritt hinzufügen
deck-add-step-hover = Ein neuer Schritt nach dem gezeigten, mit dem Diagramm, wie es jetzt ist: W, N, die Brechzahlen, die Ansicht, ihre Szene, das offene Werkzeug und die Effekte
deck-update-step = Den aktuellen Zustand in diesem Schritt behalten
deck-update-step-hover = Ziehen während eines Schritts ändert nur das Diagramm; dies behält, was es jetzt zeigt, im Schritt (die Folge speichern, um es in der Datei zu behalten)
deck-steps = Schritte
deck-no-steps = Noch kein Schritt: das Diagramm einrichten, dann als Schritt hinzufügen.
# $number ist die Nummer des Schritts, $title sein Titel
deck-step-row = { $number }. { $title }
deck-move-up = Schritt nach oben
deck-move-down = Schritt nach unten
deck-delete = Schritt löschen
deck-step-title = Titel
deck-step-question = Frage an die Klasse
deck-step-question-hint = keine: die Antwort erscheint sofort
deck-step-notes = Notizen für die Lehrkraft
deck-untitled = Schritt { $number }
deck-edited = seit dem Speichern geändert
deck-saved = { $path } gespeichert
deck-opened = { $path } geöffnet
deck-not-saved = nicht gespeichert: { $reason }
deck-nothing-to-save = Die Folge hat keinen Schritt zum Speichern: zuerst einen hinzufügen.

## Durch eine Folge gehen

# $number ist der gezeigte Schritt, $count die Zahl der Schritte: „2 / 5“
deck-step-number = { $number } / { $count }
deck-previous = Voriger Schritt
deck-next = Nächster Schritt
deck-reveal = Antwort aufdecken
deck-hide = Antwort verbergen
deck-notes-window = Notizenfenster
deck-notes-window-hover = Die Notizen der Lehrkraft in einem eigenen Fenster, für den Laptop, während der Beamer das Diagramm zeigt
deck-keys = Bild ab, → oder Leertaste: nächster Schritt · Bild auf oder ←: voriger · R: Antwort aufdecken · N: Notizenfenster
deck-hidden-hint = R deckt die Antwort auf
deck-shown-hint = R verbirgt die Antwort wieder
# $title ist der Titel der Folge
deck-notes-title = Notizen: { $title }
deck-notes-none = Keine Notizen zu diesem Schritt.
# $title ist der Titel des nächsten Schritts
deck-notes-next = Als Nächstes: { $title }
deck-notes-last = Dies ist der letzte Schritt.

## Das Handout (render --lesson … --out handout.pdf)

deck-handout-question = Frage
deck-handout-notes = Notizen

## Eingebaute Folge: das Brechungsgesetz in zehn Minuten

deck-snell-title = Das Brechungsgesetz in zehn Minuten
deck-snell-1-title = Von Luft in Glas
deck-snell-1-question = Der Strahl geht von Luft in Glas. Wird er zum Lot hin oder vom Lot weg gebrochen?
deck-snell-1-notes = Zum Lot hin: θt ist kleiner als θi, denn Glas ist das optisch dichtere Medium. Zieh W langsam von 0° bis 80° und lass die Klasse beide Winkel ablesen.
deck-snell-2-title = Senkrecht entlang der Normalen
deck-snell-2-question = Ein Strahl trifft entlang der Normalen auf die Grenzfläche. Wohin wird er gebrochen?
deck-snell-2-notes = Gar nicht: θi = θt = 0 für jedes Paar von Medien. Das Licht wird im Glas nur langsamer.
deck-snell-3-title = Das Brechungsgesetz
deck-snell-3-notes = Der erste Schritt von „Schritt für Schritt“: μi sin θi = μt sin θt. Lass zwei Schüler θi und θt ablesen und beide Seiten ausrechnen; sie stimmen bis zur letzten gezeigten Stelle überein.
deck-snell-4-title = Von Glas in Luft
deck-snell-4-question = Jetzt verlässt der Strahl das Glas. Wohin wird er gebrochen?
deck-snell-4-notes = Vom Lot weg: θt ist größer als θi. Vergrößere θi, und T schwenkt zur Grenzfläche hin: der Grenzwinkel der nächsten Stunde.
deck-snell-5-title = Durch eine Glasplatte
deck-snell-5-question = Der Strahl durchquert eine Platte mit parallelen Flächen. In welche Richtung tritt er aus?
deck-snell-5-notes = Parallel zum einfallenden Strahl, seitlich versetzt: Die zweite Brechung hebt die erste auf. Zieh die Quelle, um zu zeigen, dass der Versatz mit dem Winkel wächst.

## Eingebaute Folge: Totalreflexion und die Glasfaser

deck-tir-title = Totalreflexion und die Glasfaser
deck-tir-1-title = Aus dem Glas heraus
deck-tir-1-question = Der Strahl geht von Glas in Luft. Was geschieht mit T und dem reflektierten Strahl, wenn θi wächst?
deck-tir-1-notes = T schwenkt zur Grenzfläche hin und wird schwächer, der reflektierte Strahl wird heller: Intensitäten zeichnet jeden Strahl nach seinem Anteil am Licht.
deck-tir-2-title = Knapp vor dem Grenzwinkel
deck-tir-2-question = Bei welchem Winkel liegt T entlang der Grenzfläche?
deck-tir-2-notes = Beim Grenzwinkel: sin θc = μt/μi, 41,8° von Glas in Luft. Bei 41° streift T fast die Grenzfläche; der Knopf „W auf θc“ setzt W genau dorthin.
deck-tir-3-title = Jenseits des Grenzwinkels
deck-tir-3-question = W steht bei 45°, jenseits von 41,8°. Wohin geht das Licht?
deck-tir-3-notes = Alles wird reflektiert: Totalreflexion. Der Kernel findet kein T, also auch keine Scheinlösung; das Band oben sagt es.
deck-tir-4-title = Von Wasser in Luft
deck-tir-4-question = Ist der Grenzwinkel von Wasser größer oder kleiner als der von Glas?
deck-tir-4-notes = Größer: arcsin(1/1,333) = 48,6°, denn Wasser ist optisch dünner als Glas. Bei 50° ist der Strahl gefangen; ein Taucher sieht den Himmel nur in einem Kegel von 48,6°.
deck-tir-5-title = Die Glasfaser
deck-tir-5-question = Das Licht tritt in das Ende der Faser ein. Entweicht es durch die Seite?
deck-tir-5-notes = Nein: Jeder Treffer auf die Seite der Faser liegt jenseits des Grenzwinkels, also wird der Strahl jedes Mal totalreflektiert und entlang der Faser geführt. Dreh die Quelle, bis Licht austritt.
deck-tir-6-title = Das Prisma als Spiegel
deck-tir-6-question = Warum reflektiert ein rechtwinkliges Prisma wie ein Spiegel?
deck-tir-6-notes = Innen trifft der Strahl die lange Fläche unter 45°, jenseits des Grenzwinkels des Prismenglases (41,3°): Er wird totalreflektiert und verliert fast kein Licht; deshalb haben Ferngläser Prismen.

## Eingebaute Folge: Fresnel und Brewster

deck-fresnel-title = Fresnel und Brewster
deck-fresnel-1-title = Wie viel Licht wird reflektiert?
deck-fresnel-1-question = Bei 40° von Luft in Glas: Welcher Anteil des Lichts wird reflektiert?
deck-fresnel-1-notes = Etwa 5 % (4 % bei senkrechtem Einfall): Der Rest geht als T weiter. Der Fresnel-Graph zeigt R und T über θi, mit dem θi des Diagramms markiert.
deck-fresnel-2-title = Nahe streifendem Einfall
deck-fresnel-2-question = Ist die Reflexion bei 80° schwächer oder stärker als bei 40°?
deck-fresnel-2-notes = Viel stärker: Die Reflexion steigt bei streifendem Einfall gegen 100 %; darum spiegelt ein See das ferne Ufer, aber nicht den Himmel darüber.
deck-fresnel-3-title = Der Brewster-Winkel
deck-fresnel-3-question = p-Licht trifft unter 56,3° auf Glas. Wie viel davon wird reflektiert?
deck-fresnel-3-notes = Nichts: Beim Brewster-Winkel, tan θB = μt/μi, stehen reflektierter und gebrochener Strahl senkrecht aufeinander, und p-Licht wird gar nicht reflektiert. Polarisierende Sonnenbrillen nutzen das.
deck-fresnel-4-title = s-Licht beim gleichen Winkel
deck-fresnel-4-notes = s-Licht wird noch reflektiert, etwa 15 %: Reflektiertes Licht ist teilweise polarisiert, am stärksten beim Brewster-Winkel.
deck-fresnel-5-title = Reflexionen in einer Platte
deck-fresnel-5-question = Wie viele Strahlen verlassen eine Glasplatte, wenn jede Fläche ein wenig reflektiert?
deck-fresnel-5-notes = Jeder Treffer erzeugt einen reflektierten Strahl, immer schwächer: zwei starke Strahlen, dann eine Reihe schwacher. Die Intensitäten fallen bei jeder Reflexion.

## Eingebaute Folge: Vorzeichenkonventionen für Raytracer

deck-signs-title = Vorzeichenkonventionen für Raytracer
deck-signs-1-title = Die vier Kandidaten
deck-signs-1-question = Das Quadrieren der Gleichungen lässt vier Lösungen zu. Welche ist T?
deck-signs-1-notes = Die drei Scheinlösungen verletzen je eine Regel: falsche Seite (die andere Lösung für b), falsch gebrochen (das andere Vorzeichen von a) und umgekehrt (beides). Nur T bleibt auf der anderen Seite und wird richtig gebrochen.
deck-signs-2-title = Aus einem Tropfen heraus
deck-signs-2-question = Der Strahl verlässt einen Tropfen, und N zeigt aus dem Tropfen heraus, in Richtung des Strahls. Was muss der Code mit N tun?
deck-signs-2-notes = Es umkehren: Der Kernel braucht die Normale, die dem Strahl entgegenzeigt. Der gestrichelte Warnstrahl ist die Formel mit N, wie gegeben: der Fehler eines Renderers, der das Umkehren vergisst.
deck-signs-3-title = Abschnitt 1: W zurück zum Ursprung
deck-signs-3-question = Hier zeigt W zurück dorthin, woher der Strahl kam. Welches Vorzeichen in der Formel ändert sich?
deck-signs-3-notes = Das Vorzeichen von a: a = −μ in Abschnitt 1, +μ in Abschnitt 2. pbrt und Mitsuba übergeben wi so; wer die beiden Konventionen mischt, bekommt einen falsch gebrochenen Strahl.
deck-signs-4-title = Abschnitt 2: W entlang des Strahls
deck-signs-4-notes = Derselbe Strahl mit W entlang des Strahls, wie GLSL, glam und das Buch es übergeben: a = +μ, und T ist derselbe Vektor wie in Abschnitt 1.
deck-signs-5-title = Drei Fehler in einem API-Aufruf
deck-signs-5-question = Das T eines Renderers ist falsch. Welche drei Fehler beim Aufruf von refract machen Schüler am häufigsten?
deck-signs-5-notes = Das Verhältnis auf dem Kopf (μt/μi statt μi/μt), der einfallende Vektor in der anderen Konvention und die äußere Normale, wo der Strahl austritt. Füge einen protokollierten Aufruf in „Mein T prüfen“ ein: Es nennt den Fehler und seine Behebung.
