# Der Explorer im Browser und die Links dorthin, auf Deutsch: der Link dessen, was die Klasse
# sieht (Link kopieren, der QR-Code, die Webadresse), ein Link, der sich nicht öffnen lässt,
# das Handout mit seinen Links und was eine Browserseite sonst tut (Dateiauswahl, Downloads,
# Vollbild, Zwischenablage und ein einziger Thread).

## Links und der QR-Code

link-web-base = Webadresse
link-web-base-hover = Wo die Klasse den Explorer im Browser öffnet: die Adresse des Ordners, den cargo xtask web schreibt, auf einem Server (im Browser die Adresse der Seite selbst)
link-copy = 🔗 Link kopieren
link-copy-hover = Den Link kopieren, der öffnet, was die Klasse jetzt sieht (diesen Schritt der Folge oder diesen Zustand), im Browser
link-copied = Link kopiert.
link-qr = QR-Code
link-qr-hover = Den Link dessen, was die Klasse sieht, als QR-Code über dem Diagramm zeigen (Q)
link-no-web-base = Keine Webadresse gesetzt: die Adresse eingeben, unter der die Klasse den Explorer im Browser öffnet.
link-file-address = Diese Seite wurde aus einer Datei geöffnet: Ein Handy kann diesen Link nicht öffnen. Den Ordner auf einen Server legen und seine Adresse eingeben.
# $format: png oder svg
link-qr-save = Als { $format } speichern
# $bytes: die Länge des Links
link-qr-too-long = Der Link ist zu lang für einen QR-Code ({ $bytes } Bytes): ihn stattdessen kopieren.
link-qr-close = Q oder Esc schließt
# The QR code dialog: its button that takes the web address typed
link-qr-show = QR-Code zeigen
link-notice-close = Schließen (Esc)

## Ein Link, der sich nicht öffnen lässt ($reason: warum, wie unten)

link-cut-short = der Link ist abgeschnitten: kopiere ihn noch einmal, ganz
# $reason: wo der Link beschädigt ist, oder die Worte des Zustandslesers
link-malformed = der Link ist beschädigt ({ $reason })
# $part: der Teil des Links, den diese Version nicht liest, etwa v=2
link-newer = der Link stammt von einer neueren Version des Explorers ({ $part }): öffne ihn dort, wo diese Version läuft
# $step: der Schritt, wie der Link ihn angibt
link-bad-step = der Schritt { $step } ist keine Zahl ab 1
link-state-and-lesson = der Link nennt sowohl einen Zustand als auch eine Folge
link-step-without-lesson = der Link nennt einen Schritt, aber keine Folge
# $name: die Folge, die der Link nennt; $names: die eingebauten Folgen
link-no-lesson = es gibt keine eingebaute Folge namens { $name } (die Folgen: { $names })
# $count: die Zahl der Schritte der Folge
link-no-step = die Folge { $name } hat { $count } Schritte, nicht { $step }
# $reason: eine der Meldungen oben
web-link-not-opened = Dieser Link ließ sich nicht öffnen: { $reason }. Der Explorer zeigt, was er vorher zeigte.

## Das Handout

handout-export = 📄 Handout (PDF)
handout-export-hover = Die Folge als Handout schreiben: eine Seite je Schritt, mit Diagramm, Frage, Notizen und, wenn eine Webadresse gesetzt ist, Link und QR-Code

## Im Browser

web-page-loading = Der Brechungs-Explorer wird geladen…
# $reason: die Worte des Browsers
web-page-failed = Dieser Browser konnte den Brechungs-Explorer nicht starten ({ $reason }). Ein aktuelles Firefox, Chrome, Edge oder Safari mit WebGL 2 kann es.
web-open-through-picker = Eine Browserseite öffnet die Dateien, die du in der Dateiauswahl des Browsers wählst (oder auf die Seite ziehst).
web-choose-file = Datei wählen…
web-saved-as-download = Die Datei wird heruntergeladen: Der Browser legt sie in seinem Download-Ordner ab.
web-download = Herunterladen
# $reason: die Worte des Browsers
web-full-screen-refused = Der Browser hat den Vollbildmodus nicht gewechselt ({ $reason }): seine eigene Vollbildtaste (F11) oder sein Menü nutzen.
web-copy-refused = Der Browser hat das Kopieren nicht erlaubt ({ $reason }): den Text markieren und Strg+C drücken.
web-not-secure = eine Seite aus einer Datei oder über http darf die Zwischenablage nicht immer nutzen
web-one-thread = Im Browser läuft dies im einzigen Thread der Seite: Die Seite reagiert erst wieder, wenn es fertig ist.

## The installable page, a panic over the page, the page's file reads, inside another page (issue 44)

web-manifest-description = Den Strahl, die Normale und die Brechzahlen ziehen und zusehen, wie der gebrochene Strahl, seine vier Vorzeichenkandidaten und die Totalreflexion folgen.
web-crash-title = Der Explorer ist stehen geblieben: ein Fehler in seinem Programm. Was es meldete:
web-crash-reload = Seite neu laden
web-crash-reopen = Mit dem letzten Zustand neu laden, damit nichts verloren geht (oder diesen Link kopieren, um ihn aufzuheben):
# $name: the file's name; $reason: the browser's own words
web-read-failed = Der Browser konnte { $name } nicht lesen ({ $reason }).
# $name: the file's name; $size and $limit: sizes in MB
web-file-too-large = { $name } ist { $size } MB groß: Die Seite öffnet Dateien bis { $limit } MB.
web-open-in-tab = ↗ In neuem Tab öffnen
web-open-in-tab-hover = Diese Seite steckt in einer anderen Seite: den Explorer in einem eigenen Tab öffnen, für Vollbild und Kopieren

# Nichts geht verloren (Issue 40): Links mit klarem Grund abgelehnt, die Webadresse an einer Stelle geprüft.
link-part-without-name = ein Teil des Links hat keinen Namen („{ $part }“)
link-part-twice = der Link nennt { $part } zweimal
link-web-base-refused = Diese Webadresse ist nicht verwendbar: { $reason }.
link-web-base-empty = es wurde keine Adresse angegeben
link-web-base-scheme = sie beginnt mit „{ $scheme }“, nicht mit http://, https:// oder file://
link-web-base-unseen = sie enthält { $character }, was eine Adresse nicht enthalten darf (keine Leerzeichen, Steuerzeichen oder unsichtbaren Zeichen)
link-web-base-escape = „{ $escape }“ ist keine Prozent-Kodierung (auf % folgen zwei Hexadezimalziffern)
link-web-base-credentials = sie enthält einen Benutzernamen oder ein Passwort, die jeder Link und jeder QR-Code zeigen würde
link-web-base-too-long = sie ist { $bytes } Byte lang: höchstens { $most } halten die QR-Codes der Links auf Papier lesbar
link-web-base-port = ihr Port ist keine Zahl von 0 bis 65535
link-web-base-host = ihr Host fehlt oder ist kein gültiger Name und keine gültige IP-Adresse ({ $reason })
storage-web-base-unusable = Die vom letzten Mal gespeicherte Webadresse wird nicht verwendet: { $reason }.
storage-state-unreadable = Der vom letzten Mal gespeicherte Zustand ließ sich nicht lesen ({ $reason }): der Explorer beginnt mit dem Standardzustand.
