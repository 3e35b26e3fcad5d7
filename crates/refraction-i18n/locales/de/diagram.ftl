# Was auf dem Diagramm, den Szenen und den Plots steht, auf Deutsch.
# Beschriftungen im Diagramm kurz halten: was nicht passt, lässt der Platzierer weg.
# Platzhalter enthalten Zahlen, schon mit Dezimalkomma geschrieben.

## Das Diagramm der Grenzfläche

diagram-ghost-wrong-side = andere b-Lösung: falsche Seite
diagram-ghost-wrong-bend = anderes a-Vorzeichen: falsch gebrochen
diagram-ghost-reversed = beide Vorzeichen falsch: −T
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = Medium des Strahls
diagram-medium-entered = Medium, in das er eintritt
diagram-material-vacuum = Vakuum
diagram-material-air = Luft
diagram-material-water = Wasser
diagram-material-glass = Glas
diagram-material-diamond = Diamant
diagram-material-custom = eigener Wert
diagram-banner-tir =
    TOTALREFLEXION
    k = { $k } < 0: keine reelle Lösung für b, kein gebrochener Strahl; alles Licht wird reflektiert (θi = { $theta_i }°)
diagram-banner-toward-origin = W zeigt zurück zum Ursprung, also a = −μ
diagram-banner-along-ray = W ist die Ausbreitungsrichtung, also a = +μ
diagram-banner-section = Abschnitt { $section }: { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Abschnitt 1: W zeigt zurück zum Ursprung
diagram-banner-asked-along-ray = Abschnitt 2: W ist die Ausbreitungsrichtung
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0: T existiert
diagram-critical-angle = Grenzwinkel θc = { $angle }°
diagram-kernel-normal = −N: die Normale des Kernels
diagram-outward-normal-bug =
    Fehler der äußeren Normale:
    T der Formel mit N wie gegeben
diagram-index-scale = Index μ
diagram-incoming-ray = einfallender Strahl
diagram-normal-incidence = senkrechter Einfall: W, N und T liegen auf einer Linie
diagram-normal-incidence-asked = senkrechter Einfall: W liegt auf N
diagram-reflected = reflektiert
diagram-reflected-light = reflektiert ({ $light })
diagram-reflected-all = reflektierter Strahl (alles Licht)
diagram-w-along-ray = W (entlang des Strahls)
diagram-w-toward-origin = W (zum Ursprung)
diagram-transmitted = T: durchgelassen
diagram-no-reflected-ray = { $label }: kein reflektierter Strahl

## Anfasser (was ein Bildschirmleser sagt)

diagram-handle-w = Einfallswinkel θi (W)
diagram-handle-n = Richtung der Normalen N
diagram-handle-mu-i = Brechungsindex μi (Medium des Strahls)
diagram-handle-mu-t = Brechungsindex μt (Medium, in das der Strahl eintritt)
diagram-handle-source = Anfasser der Quelle
diagram-handle-aim = Anfasser der Quellrichtung
diagram-handle-shape = Anfasser von Form { $number } ({ $medium })

## Lektionen, Farbschemata, Licht, Animationen

diagram-lesson-air-to-glass = Luft → Glas, 40°
diagram-lesson-beyond-critical = Glas → Luft jenseits θc
diagram-lesson-normal-incidence = Senkrechter Einfall
diagram-lesson-brewster = Brewster-Winkel
diagram-lesson-droplet-exit = Austritt aus einem Tropfen
diagram-angle-out-of-range = θi muss mindestens 0° und kleiner als 90° sein, nicht { $angle }°
diagram-theme-standard = Standard
diagram-theme-black-on-white = Schwarz auf Weiß
diagram-theme-white-on-black = Weiß auf Schwarz
diagram-light-s = s-Licht
diagram-light-p = p-Licht
diagram-light-unpolarised = unpolarisiertes Licht
diagram-animation-mu = μ → 1: T wird zu W
diagram-animation-sweep = θi bis zum streifenden Einfall: Totalreflexion setzt ein
diagram-animation-wavefronts = Wandernde Wellenfronten

## Die Tabelle der Kandidaten

diagram-role-chosen = T (gewählt)
diagram-role-wrong-side = falsche Seite
diagram-role-wrong-bend = falsch gebrochen
diagram-role-reversed = umgekehrt
diagram-rule-wrong-side = falsche Seite der Fläche: die andere Lösung für b schickt den Strahl zurück in das Medium, aus dem er kam
diagram-rule-wrong-bend = falsch gebrochen: das andere Vorzeichen von a kehrt den Anteil entlang der Fläche um, sodass der Kandidat für μ → 1 nicht zum einfallenden Strahl wird
diagram-rule-reversed = beides falsch (falsches Vorzeichen von a und falsche Lösung für b): es ist −T und zeigt dorthin zurück, woher der Strahl kam

## Eine verfolgte Szene

diagram-screen = Schirm
diagram-index-at-wavelength = n = { $index } bei { $wavelength } nm
diagram-stopped-at = angehalten nach { $count ->
        [one] { $count } Segment
       *[other] { $count } Segmenten
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } Kernel-Aufruf
       *[other] { $count } Kernel-Aufrufe
    }
diagram-count-tir = { $count ->
        [one] { $count } Totalreflexion
       *[other] { $count } Totalreflexionen
    }
diagram-count-reflections = { $count ->
        [one] { $count } Reflexion erzeugt
       *[other] { $count } Reflexionen erzeugt
    }
diagram-count-fresnel = { $count ->
        [one] { $count } Fresnel-Auswertung
       *[other] { $count } Fresnel-Auswertungen
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } Wellenlänge
       *[other] { $count } Wellenlängen
    }
diagram-count-source-rays = { $count ->
        [one] { $count } Quellstrahl
       *[other] { $count } Quellstrahlen
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } Übergang bei gleichem Index übersprungen
       *[other] { $count } Übergänge bei gleichem Index übersprungen
    }
diagram-count-absorption = { $count ->
        [one] { $count } Absorptionsauswertung
       *[other] { $count } Absorptionsauswertungen
    }
diagram-legend-colour = Farbe:
diagram-legend-white-traced = weißes Licht, verfolgt bei { $wavelength } nm
diagram-legend-white-then = weißes Licht, dann
diagram-legend-nm = nm
diagram-legend-opacity = Deckkraft: Intensität
diagram-legend-hits = Treffer:
diagram-hit-entering = eintretend
diagram-hit-leaving = austretend (N umgekehrt)
diagram-hit-tir = Totalreflexion

## Wellen

diagram-fronts =
    Frontabstand λ/{ $index }
    Geschwindigkeit c/{ $index } = { $speed } c
diagram-huygens-touch =
    Huygens: die Front erreicht A Δt nach B;
    die Elementarwelle von B wächst um vt·Δt, die neue Front berührt sie
diagram-huygens-tir =
    Huygens: die Elementarwelle von B wird größer als BA:
    keine Tangente von A aus, Totalreflexion

## Die Schlüsselgleichungen

diagram-eq-toward-origin-a = W zeigt von T weg, also wählt der Artikel a = −μ
diagram-eq-along-ray-a = W zeigt entlang T, also wählt der Artikel a = +μ
diagram-eq-no-refracted-ray = kein reelles (a, b): es gibt keinen gebrochenen Strahl
diagram-eq-no-b-with-10 = kein reelles b erfüllt sie zusammen mit Gl. 10
diagram-eq-so = { $given }, also { $then }
diagram-eq-negative-root = √({ $k }) einer negativen Zahl: kein reelles b (Totalreflexion)
diagram-eq-or = oder
diagram-eq-outward-normal-bug = mit N wie gegeben b = { $b }: die falsche Lösung, T läuft zurück (der Fehler mit äußerer Normale); der Kernel nimmt −N und erhält b = { $kernel_b } für N
diagram-step-wn-flipped = W·N = { $given }: N zeigt vom Strahl weg, daher verwendet der Kernel −N: wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = keine reelle Lösung zur Auswahl
diagram-eq-no-theta-t = { $given }, also wäre sinθt = { $sin_t } > 1: es gibt keinen Winkel θt
diagram-eq-with-chosen = { $lhs } = { $rhs } mit dem gewählten (a, b)
diagram-eq-no-ab-with-12 = kein reelles (a, b) erfüllt sie zusammen mit Gl. 12
# Der Name des Sinus in den Formeln von „Schritt für Schritt“, wie ihn die Schulen der Sprache schreiben.
diagram-math-sin = sin

## Schritt für Schritt

diagram-step-snell = Brechungsgesetz von Snellius
diagram-step-snell-text = Der Strahl wird so gebrochen, dass μi·sinθi = μt·sinθt; mit μ = μi/μt ist der Sinus des Winkels im neuen Medium μ-mal so groß wie der alte.
diagram-step-square = Quadrieren, dann Kosinus
diagram-step-square-text = Durch das Quadrieren können die Kosinus (Skalarprodukte) die Sinus ersetzen, aber es lässt auch falsche Lösungen zu: eine Lösung und ihr Gegenstück mit umgekehrtem Vorzeichen erfüllen es beide.
diagram-step-decomposition = T als a·W + b·N
diagram-step-decomposition-text = T liegt in der Ebene von W und N, also ist T = a·W + b·N; die Kosinus werden Skalarprodukte mit wn = W·N, und cosθt = −a·wn − b. Der Strahl läuft entlang { $travel }.
diagram-step-constraints = Die zwei quadrierten Bedingungen
diagram-step-constraints-text = Das quadrierte Brechungsgesetz (Gl. 10) und die Einheitslänge (Gl. 12) sind zwei quadratische Gleichungen in a und b. Vier Paare (a, b) erfüllen beide: T und die drei Scheinlösungen. Nichts in ihnen unterscheidet die vier.
diagram-step-roots-a = Die zwei Lösungen für a
diagram-step-roots-a-text = Setzt man Gl. 12 in Gl. 10 ein, bleibt a² = μ²: a = +μ oder a = −μ. Das andere Vorzeichen spiegelt T an der Normalen: es wird falsch gebrochen.
diagram-step-choice-a = Wahl von a: der Grenzfall μ = 1
# „μ gegen 1 animieren“ ist der Name der Schaltfläche im Fenster.
diagram-step-choice-a-text = Bei μ = 1 wird nichts gebrochen, also muss T die Ausbreitungsrichtung sein, { $travel }. Nur a = { $a } ergibt das; das andere Vorzeichen gäbe das Spiegelbild. Mit „μ gegen 1 animieren“ sieht man, wie T gegen { $travel } strebt und die Scheinlösungen nicht.
diagram-step-choice-a-typo = (Der Text von Abschnitt 2 sagt danach „once we decide upon using the a = −μ solution“: gemeint ist a = +μ, die gewählte Lösung.)
diagram-step-roots-b = Die zwei Lösungen für b
diagram-step-roots-b-text = Bei festem a ist Gl. 12 quadratisch in b mit den Lösungen −a·wn ± √k (k = μ²wn² − μ² + 1). Die andere Lösung spiegelt T an der Fläche, zurück in das Medium, aus dem der Strahl kam. k < 0 heißt: keine reelle Lösung, Totalreflexion.
diagram-step-choice-b = Wahl von b
diagram-step-choice-b-text = Von den zwei Lösungen wird nur die mit −√k bei μ = 1 zu b = 0, wenn T der unveränderte einfallende Strahl sein muss; die andere schickt T zurück über die Fläche.
diagram-step-choice-b-flipped = Die Lösung mit −√k geht bei μ = 1 gegen b = 0, T wird also der einfallende Strahl. Hier zeigt N aber entlang des Strahls (eine äußere Normale, wo der Strahl das Medium verlässt): mit N wie gegeben liegt diese Lösung auf der falschen Seite. Der Kernel kehrt N zuerst um.

## Die Fresnel-Ansicht

diagram-fresnel-title = Wie viel Licht reflektiert wird, von μi = { $mu_i } nach μt = { $mu_t }
diagram-fresnel-axis = Einfallswinkel θi
diagram-fresnel-brewster = Brewster-Winkel θB = { $angle }°: kein p-Licht reflektiert
diagram-fresnel-critical = Grenzwinkel θc = { $angle }°: darüber alles reflektiert
diagram-fresnel-brewster-short = Brewster-Winkel θB = { $angle }°
diagram-fresnel-critical-short = Grenzwinkel θc = { $angle }°
diagram-curve-rs = Rs (s-Licht reflektiert)
diagram-curve-rp = Rp (p-Licht reflektiert)
diagram-curve-r = R (unpolarisiert, reflektiert)
diagram-curve-t = T (unpolarisiert, durchgelassen)
diagram-fresnel-source =
    Fresnelsche Formeln für die reflektierte Leistung (Hecht, Optik, Kap. 4): Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    aus den eigenen cosθi und cosθt des Kernels, ohne Trigonometrie; unpolarisiertes Licht ist der Mittelwert von s und p. Jenseits des Grenzwinkels wird alles Licht reflektiert.

## Der Genauigkeitsplot

diagram-accuracy-title = Genauigkeit gegen Zeit auf diesem Rechner
diagram-accuracy-error-axis = größter Fehler der schweren Fälle, in ε·κ (log)
diagram-accuracy-time-axis = Zeit pro Strahl, ns (log)
diagram-accuracy-bound = Schranke des Standard-Kernels, 32 ε·κ
diagram-accuracy-markers = hohl: f32, gefüllt: f64

## Die eingebauten Szenen (Titel, Beschreibungen und die Namen ihrer Medien)

diagram-scene-dispersing-prism = Dispersionsprisma
diagram-scene-dispersing-prism-about = Weißes Licht durch ein gleichseitiges F2-Flintglasprisma nahe der minimalen Ablenkung: Violett wird am stärksten gebrochen.
diagram-scene-droplet = Wassertropfen (Regenbogen)
diagram-scene-droplet-about = Weißes Licht tritt in einen Tropfen ein, wird innen reflektiert und tritt wieder aus; die Dispersion fächert den Hauptregenbogen bei etwa 138 Grad Ablenkung auf.
diagram-scene-fibre = Lichtleiter
diagram-scene-fibre-about = Wiederholte Totalreflexion führt das Licht durch den Kern; die steilsten Strahlen treten in den Mantel aus.
diagram-scene-interface = Eine Grenzfläche
diagram-scene-interface-about = Ein Strahl in Luft trifft unter 45 Grad auf ebenes Glas (n = 1,5) und wird zum Lot hin gebrochen.
diagram-scene-lens = Sammellinse
diagram-scene-lens-about = Eine bikonvexe BK7-Linse fokussiert ein paralleles Strahlenbündel auf einen Schirm; Randstrahlen treffen sich schon davor.
diagram-scene-right-angle-prism = Umlenkprisma
diagram-scene-right-angle-prism-about = Totalreflexion an der Hypotenuse lenkt das Bündel um 90 Grad um.
diagram-scene-slab = Glasplatte
diagram-scene-slab-about = Parallele Flächen: Der austretende Strahl ist parallel zum eintretenden, seitlich versetzt. Fresnel-Verluste an beiden Flächen, Absorption im Inneren.
diagram-medium-core = Kern
diagram-medium-cladding = Mantel
diagram-medium-f2 = F2-Flintglas
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = getöntes BK7
