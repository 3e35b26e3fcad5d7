# check.ftl (de): die Texte von „Mein T prüfen“: das Panel, seine Urteile und ihre Erklärungen.

## Zahlen und Vektoren in Erklärungen

check-number-not-finite = nicht endlich (NaN oder unendlich)
check-vector-not-finite = ein nicht endlicher Vektor (Komponenten NaN oder unendlich)

## Urteile über ein T in den Feldern dieses Projekts (auch die Erklärungen des Befehls `check`)

check-verdict-wrong-side = Dein T läuft zurück in das Medium, aus dem der Strahl kam: die andere Lösung für b (+, wo die Quadratwurzel - braucht). Meist liegt es an einer Normalen, die in Strahlrichtung zeigt, etwa der äußeren Normalen einer Kugel dort, wo der Strahl sie verlässt, die nicht umgekehrt wurde.
check-verdict-wrong-bend = Dein T wird in die falsche Richtung gebrochen: Das Vorzeichen von a ist umgekehrt, sodass es für μ → 1 nicht zum einfallenden Strahl wird. Meist sind die Konventionen vermischt: W zurück zum Ursprung (Abschnitt 1, a = −μ) in die Formel für W entlang des Strahls (Abschnitt 2, a = +μ) eingesetzt, oder umgekehrt.
check-verdict-reversed = Dein T ist -T und zeigt dorthin zurück, woher der Strahl kam: Beide Vorzeichen sind falsch. Meist wird die Richtung zum Ursprung statt der Laufrichtung zurückgegeben, oder W wurde zweimal negiert.
check-verdict-not-finite-tir = Dein T hat Komponenten NaN oder unendlich. Dieser Strahl wird totalreflektiert (k < 0): Dein Code hat die Quadratwurzel aus einem negativen k gezogen, statt k vorher zu prüfen.
check-verdict-not-finite-refracts = Dein T hat Komponenten NaN oder unendlich, obwohl dieser Strahl normal gebrochen wird (k ≥ 0): Suche nach einer Division durch null oder einem nicht initialisierten Vektor.
check-verdict-tir-right = Richtig: Dieser Strahl wird totalreflektiert (k < 0), und dein Code gab die Reflexion zurück (oder den Nullvektor, mit dem GLSL das anzeigt).
check-verdict-tir-but-refracted = Dieser Strahl wird totalreflektiert (k = { $k } < 0): Es gibt keinen gebrochenen Strahl, aber dein Code gab einen zurück. Prüfe k, bevor du die Quadratwurzel ziehst.
check-verdict-zero-vector = Dein T ist der Nullvektor, den GLSL bei Totalreflexion zurückgibt, aber dieser Strahl wird gebrochen (k ≥ 0). Prüfe das Vorzeichen von k und das Verhältnis der Brechungsindizes.
check-verdict-not-unit = Außerdem hat dein T die Länge { $length }, nicht 1: Normiere W und N vor der Brechung (die Formel setzt Einheitsvektoren voraus) oder T danach.
check-verdict-along-refracted = Dein T zeigt entlang des gebrochenen Strahls (auf { $off } rad genau).
check-verdict-right = Richtig: Dein T ist der gebrochene Strahl (auf { $off } rad genau).
check-verdict-ratio-upside-down = Dein T ist die Brechung mit umgekehrtem Indexverhältnis: μ muss μi/μt sein (das Medium, das der Strahl verlässt, durch das, in das er eintritt), und dein Code hat μt/μi verwendet.
check-verdict-out-of-plane = Dein T verlässt die Einfallsebene (die Ebene von W und N) um { $off } rad: T muss eine Kombination a·W + b·N der beiden sein.
check-verdict-no-candidate = Dein T passt zu keiner der vier Vorzeichenwahlen: Es liegt { $degrees } Grad neben dem gebrochenen Strahl. Prüfe μ und die Richtungen von W und N.

## t_yours aus einer JSON-Zeile lesen

check-t-yours-item-not-number = `t_yours[{ $index }]` muss eine Zahl oder null sein
check-t-yours-missing = das Feld `t_yours` fehlt (das T, das dein Code berechnet hat)

## Erklärungen zu einem API-Aufruf (`check --api` und das Panel): wie jede API spricht

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] dem Buch
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] refract(I, N, eta) von GLSL
    [pbrt] Refract(wi, n, eta) von pbrt
    [rtiow] refract(uv, n, etai_over_etat) aus dem Buch
   *[mitsuba] fresnel(cos_theta_i, eta) von Mitsuba mit refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, der Index, den der Strahl verlässt, durch den, in den er eintritt
    [pbrt] der Index auf der Seite, von der n wegzeigt, durch den Index auf der Seite, zu der n zeigt (n_inside/n_outside bei äußerer Normale)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index auf einer Vorderseite, refraction_index auf einer Rückseite)
   *[mitsuba] int_ior/ext_ior, der Index auf der Seite, von der die Normale wegzeigt, durch den Index auf der Seite, zu der sie zeigt
}
check-api-incident-means = { $api ->
    [glsl] die Richtung, in die der Strahl läuft, zur Oberfläche hin
    [pbrt] die Richtung zurück dorthin, woher der Strahl kam (-ray.d)
    [rtiow] die Einheitsrichtung, in die der Strahl läuft (unit_vector(r_in.direction()))
   *[mitsuba] wi, von der Oberfläche weg entlang des Strahls zurück (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] GLSL subtrahiert (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt nimmt (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel ist -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] cos_theta_t hat das entgegengesetzte Vorzeichen von cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] die äußere Normale mit dem eta des Materials (n_inside/n_outside)
    [mitsuba] die äußere Normale mit eta = int_ior/ext_ior
   *[other] {""}
}

## Erklärungen zu einem API-Aufruf: die Bausteine

check-situation-entering = beim Eintritt in das Objekt (von n = { $from } nach n = { $to })
check-situation-leaving = beim Austritt aus dem Objekt (von n = { $from } nach n = { $to })
check-situation-going = von n = { $from } nach n = { $to }
check-nothing-zero-vector = Nullvektor
check-nothing-reflection = Reflexion
check-nothing-false-or-null = nichts (false oder null)
check-and = und
check-or = oder
check-field-from-and-to = from und to (oder entering mit --inside und --outside)
check-normal-fix-rtiow = die Normale des Trefferdatensatzes nach set_face_normal
check-normal-fix-facing = die Normale umgekehrt, wo immer dieses Skalarprodukt positiv ist
check-normal-inward-entering = sie zeigt ins Objekt, und der Strahl tritt ein
check-normal-inward-leaving = sie zeigt ins Objekt, und der Strahl tritt aus
check-looks-other-root = die andere Lösung, mit umgekehrtem Vorzeichen der Quadratwurzel ({ $hint })
check-looks-wrong-bend = der Anteil entlang der Oberfläche umgekehrt
check-looks-reversed = minus die Antwort der API
check-looks-length = dieselbe Richtung mit der { $ratio }-fachen Länge: Dein Code skaliert oder normiert anders
check-looks-reflection = die Reflexion, obwohl dieser Strahl gebrochen wird (protokolliere nur die Brechung, keine von Fresnel oder Schlick gewählte Reflexion)
check-looks-variant = was { $call } mit { $variant } zurückgibt: Deine Implementierung tut das intern
check-variant-eta-inverted = invertiertem eta
check-variant-normal-flipped = umgekehrter Normale
check-variant-incident-reversed = umgekehrtem Einfallsvektor
check-looks-nothing = { $what }, also wird nichts durchgelassen, obwohl dieser Strahl gebrochen wird (k = { $k } ≥ 0)
check-looks-not-finite = Komponenten NaN oder unendlich, obwohl dieser Strahl gebrochen wird
check-looks-off = { $degrees } Grad daneben
check-looks-off-unmeasurable = in keinem messbaren Winkel dazu
check-returned-pbrt-true = true mit wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter reflektiert)
check-returned-mitsuba-reflects = F = 1 (das BSDF reflektiert immer)
check-unchecked-mu = from und to (oder entering mit --inside und --outside), um { $eta } zu prüfen
check-unchecked-travel = travel, um zu prüfen, wohin { $incident } zeigt

## Erklärungen zu einem API-Aufruf: die Sätze

check-eta-inverted = In { $owner } ist { $eta } { $means }: Du hast { $value } für einen Strahl { $situation } übergeben; übergib 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = In { $owner } ist { $eta } { $means }: Du hast { $value } für diesen Strahl übergeben; übergib 1/{ $value } = { $inverse }.
check-incident-reversed = In { $owner } ist { $incident } { $means }; deiner zeigt in die Gegenrichtung: Übergib -{ $incident } = { $reversed }.
check-incident-reversed-travel = In { $owner } ist { $incident } { $means }; deiner zeigt in die Gegenrichtung (der Strahl läuft entlang { $travel }): Übergib -{ $incident } = { $reversed }.
check-not-unit-input = { $call } setzt Einheitsvektoren { $incident } und { $normal } voraus und normiert sie nicht: |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length }; normiere sie vorher.
check-normal-against = { $call } braucht { $normal } entgegen { $incident } (dot({ $normal }, { $incident }) < 0) und kehrt sie nicht um; bei dir ist dot({ $normal }, { $incident }) = { $dot }, wie bei einer äußeren Normalen dort, wo der Strahl das Objekt verlässt: Übergib -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } nimmt { $normal } auf beiden Seiten, aber { $eta } muss dazu passen: Es ist { $means }. Deine Normale { $normal } zeigt in die andere Richtung als die, für die { $eta } = { $value } gedacht war{ $inward }; übergib -{ $normal } = { $flipped } mit demselben { $eta } (oder behalte { $normal } und übergib 1/{ $eta }).
check-tir-glsl = Das refract von GLSL gibt hier den Nullvektor zurück (k = { $k } < 0: Totalreflexion); prüfe darauf und reflektiere stattdessen.
check-tir-pbrt = Das Refract von pbrt gibt hier false zurück (sin2Theta_t = { $sin2 } >= 1: Totalreflexion); reflektiere stattdessen.
check-tir-rtiow = Das cannot_refract von dielectric::scatter gilt hier (ri * sin_theta = { $sine } > 1): Das Buch reflektiert, statt refract aufzurufen.
check-tir-mitsuba = fresnel gibt hier F = 1 zurück (cos_theta_t_sqr = { $k } < 0): Mitsuba reflektiert immer.
check-tir-got-formula = Dein Code hat trotzdem den Vektor der Formel verwendet, { $vector } mit der Länge { $length }: kein Strahl.
check-tir-got-direction = Dein Code gab eine Richtung zurück, { $vector }, wo es keine gibt.
check-tir-got-not-finite = Dein Code gab Komponenten NaN oder unendlich zurück (die Quadratwurzel aus einem negativen k oder normalize() des Nullvektors).
check-result-differs = { $call } gibt für diese Argumente { $returned } zurück, aber der Aufruf ergab { $got }: { $detail }. Deine eigene Implementierung weicht von der API ab.
check-ties-no-field = Kein Referenzfeld unterscheidet sie: { $call } liest beide gleich; der übliche Aufruf übergibt { $usual }.
check-ties-give = Gib { $fields } an, um sie zu unterscheiden.
check-ties = Ebenso möglich: stattdessen { $readings }. { $hint }
check-unchecked = Nur gegen die eigenen Regeln der API geprüft: Gib { $missing } an.
check-unexplained-travel = Das protokollierte { $incident } liegt { $degrees } Grad neben der Laufrichtung { $travel } dieses Strahls: Es ist nicht die Richtung dieses Strahls (auch nicht ihre Umkehrung).
check-unexplained-eta = { $eta } = { $value } passt weder zu n_from/n_to = { $mu } noch zu dessen Kehrwert, so wie { $call } es liest: Das sind nicht die Brechungsindizes dieser Grenzfläche.
check-unexplained = Keine Kombination von Argumentfehlern bringt diesen Aufruf in Einklang mit der angegebenen Referenz.
check-right-tir = Richtig: { $call } zeigt hier Totalreflexion an ({ $returned }), und der Aufruf ergab { $what }.
check-right-for-ray = Richtig: Für einen Strahl { $situation } gibt { $call } mit diesen Argumenten { $returned } zurück.
check-right = Richtig: { $call } gibt für diese Argumente { $returned } zurück.

## Die Fehler eines API-Aufrufs, je in einer Zeile

check-mistake-eta-inverted = das Indexverhältnis ist für die Konvention dieser API umgekehrt
check-mistake-incident-reversed = der Einfallsvektor wurde falsch herum übergeben
check-mistake-normal-not-facing = die Normale liegt für diese API (oder für das übergebene eta) auf der falschen Seite
check-mistake-not-the-api-result = das Ergebnis ist nicht das, was die API für diese Argumente zurückgibt: Deine eigene Implementierung weicht ab
check-mistake-missed-tir = eine Richtung (oder NaN), wo die API Totalreflexion anzeigt
check-mistake-not-unit-input = Einfallsvektor oder Normale hat nicht die Länge 1

## Das Panel: die Felder dieses Projekts

check-source-own = W, N, μ (dieses Projekt)
check-code-calls = Dein Code ruft auf:
check-convention = Konvention:
check-convention-along-ray = Abschnitt 2: W entlang des Strahls
check-convention-along-ray-about = W ist die Richtung, in die der Strahl läuft, zur Oberfläche hin (I bei GLSL, uv im Buch).
check-convention-toward-origin = Abschnitt 1: W zum Ursprung
check-convention-toward-origin-about = W zeigt zurück dorthin, woher der Strahl kam (wi bei pbrt und Mitsuba).
check-convention-note = { $about } μ = μi/μt; N auf beliebiger Seite (der Kernel dreht sie zum Strahl).
check-paste-hint = Füge ein, was dein Raytracer protokolliert hat. Vektoren als 0.1, -0.9, 0 oder [0.1,-0.9,0] oder vec3(0.1, -0.9, 0.0); oder füge eine ganze JSON-Zeile mit t_yours in „Dein T“ ein.
check-use-current-case = Aktuellen Fall übernehmen
check-use-current-case-own-hover = W, N, μ und die Konvention aus dem Explorer übernehmen
check-use-current-case-api-hover = Argumente und Brechungsindizes aus dem Explorer übernehmen
check-your-t = Dein T
check-your-t-in-error = dein T
check-button = Prüfen
check-field-not-number = { $field }: „{ $text }“ ist keine Zahl
check-student-own = dein T: { $verdict }
check-headline-own = Dein T ist: { $verdict }
check-match-refracted = der gebrochene Strahl T
check-match-not-unit = die Richtung von T, aber nicht Länge 1
check-match-wrong-side = falsche Seite (die andere Lösung für b)
check-match-wrong-bend = falsch gebrochen (das andere Vorzeichen von a)
check-match-reversed = umgekehrt (−T: beide Vorzeichen falsch)
check-match-tir = Totalreflexion, richtig beantwortet
check-match-none = keiner der vier Kandidaten
check-no-refracted-ray = Es gibt keinen gebrochenen Strahl: Totalreflexion.
check-right-t = Das richtige T = { $t }
check-copy-right-t = T kopieren
check-not-drawn-changed = (Der Fall hat sich inzwischen geändert: Das Urteil wird nicht gezeichnet.)

## Das Panel: ein API-Aufruf

check-drawn-incident = { $api ->
    [glsl] I (Laufrichtung)
    [pbrt] wi (zurück zum Ursprung)
    [rtiow] uv (Laufrichtung)
   *[mitsuba] wi (von der Oberfläche weg)
}
check-drawn-about = { $api ->
    [glsl] I ist die Richtung, in die der Strahl läuft, gezeichnet als W entlang des Strahls (Abschnitt 2). N muss I entgegen zeigen: GLSL kehrt sie nicht um. eta = n_from/n_to = μi/μt. Der Nullvektor bedeutet Totalreflexion.
    [pbrt] wi zeigt zurück dorthin, woher der Strahl kam (−ray.d), gezeichnet als W zum Ursprung (Abschnitt 1). n darf auf beiden Seiten liegen: pbrt kehrt sie um und invertiert eta, wenn wi darunter liegt. eta = der Index hinter n durch den davor (μt/μi, wenn n zu wi zeigt). false bedeutet Totalreflexion.
    [rtiow] uv ist die Einheitsrichtung, in die der Strahl läuft, gezeichnet als W entlang des Strahls (Abschnitt 2). n muss uv entgegen zeigen (front_face). etai_over_etat = n_from/n_to = μi/μt. refract prüft nicht auf Totalreflexion: Das cannot_refract des Aufrufers reflektiert.
   *[mitsuba] wi zeigt von der Oberfläche weg, zurück entlang des Strahls, gezeichnet als W zum Ursprung (Abschnitt 1). n ist +z (das lokale Koordinatensystem), wenn leer. eta = int_ior/ext_ior, der Index hinter n durch den davor (μt/μi, wenn n zu wi zeigt). F = 1 bedeutet Totalreflexion: `wo` ist null.
}
check-convention-about = Konvention: { $about }
check-your-call = Dein Aufruf
check-truth = Referenz (optional)
check-picture-outside = μ = { $mu } braucht Brechungsindizes außerhalb des Bereichs { $low }…{ $high } des Explorers
check-student-api = dein { $result }: { $verdict }
check-student-right = richtig
check-student-wrong = falsch
check-api-right-headline = Richtig: was { $signature } für diesen Strahl bedeutet
check-api-mistakes = Fehler: { $codes }
check-api-unexplained-headline = Durch keinen einzelnen Fehler erklärt
check-api-returns = Ergebnis in { $owner }: { $value }
check-api-drawn = Gezeichnet: der richtige Aufruf, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = Nicht gezeichnet: { $why }.
check-copy-as-test = Als Unit-Test kopieren:

## Das Panel: eingefügte Log-Zeilen

check-paste-lines = 📋 Log-Zeilen einfügen
check-pattern = Muster
check-log-lines = Log-Zeilen
check-lines-button = Zeilen prüfen
check-read-as-pattern = das Muster
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (die erste Zeile ist die Kopfzeile)
check-bulk-summary = Gelesen als { $read_as }: { $count ->
    [one] { $count } Aufruf
   *[other] { $count } Aufrufe
}
check-bulk-left-out = { $count ->
    [one] { $count } Zeile nach den ersten { $first } ausgelassen
   *[other] { $count } Zeilen nach den ersten { $first } ausgelassen
}
check-column-line = Zeile
check-column-ok = ok
check-column-mistakes = Fehler
check-column-explanation = Erklärung
check-row-line = Zeile { $line }
check-row-open-hover = Diesen Aufruf im Panel und im Diagramm öffnen
check-row-error = Fehler

## Die Felder eines Aufrufs, einer CSV-Zeile, eines Musters und eines Vektors lesen (auch das Panel zeigt diese Meldungen)

check-field-not-three = `{ $field }` muss genau 3 Zahlen haben, hat aber { $count }
check-field-not-a-vector = `{ $field }` muss ein Array aus 3 Zahlen sein oder ein Text wie „0.1, -0.9, 0“
check-field-not-flag-got = `{ $field }` muss true/false oder 1/0 sein, nicht „{ $text }“
check-field-not-number-json = `{ $field }` muss eine Zahl sein
check-field-not-flag = `{ $field }` muss true/false oder 1/0 sein
check-field-not-label = `{ $field }` muss ein Text oder eine Zahl sein
check-json-not-object = erwartet wird ein JSON-Objekt mit den Feldern { $fields }
check-unknown-field = unbekanntes Feld `{ $field }`
check-field-not-vector = `{ $field }` muss aus 3 Zahlen bestehen
check-field-missing = das Feld `{ $field }` fehlt ({ $what })
check-what-normal = die Flächennormale
check-what-incident = der Einfallsvektor
check-what-eta = das Indexverhältnis
check-field-not-finite = `{ $field }` muss endlich sein, ist aber { $value }
check-field-zero-vector = `{ $field }` ist der Nullvektor
check-field-not-positive = `{ $field }` muss eine endliche Zahl > 0 sein, ist aber { $value }
check-from-and-to-together = `from` und `to` gehören zusammen: Gib beide oder keines an
check-travel-not-finite = `travel` muss ein endlicher Vektor ungleich null sein
check-result-null = `{ $field }` ist null, obwohl `{ $returned }` true ist
check-result-missing = das Feld `{ $field }` fehlt (was der Aufruf zurückgab{ $api ->
    [pbrt] , oder "returned": false
    [mitsuba] , null, wenn er reflektiert hat
   *[other] {""}
})
check-unknown-precision = unbekannte Genauigkeit „{ $text }“: erwartet wird "f32" oder "f64"
check-too-large = { $value } ist zu groß für { $precision }
check-csv-unclosed-quote = nicht geschlossenes Anführungszeichen in der CSV-Zeile
check-csv-no-column = die CSV-Kopfzeile hat keine Spalte `{ $field }`, nur { $names }; erwartet wird { $expected }
check-csv-partial-vector = die CSV-Kopfzeile hat nur { $count } der 3 Komponenten von `{ $field }`
check-csv-duplicate-column = die CSV-Kopfzeile nennt `{ $column }` mehr als einmal
check-csv-cells = { $count ->
    [one] { $count } Zelle
   *[other] { $count } Zellen
}, wo die Kopfzeile { $columns ->
    [one] { $columns } Spalte
   *[other] { $columns } Spalten
} hat
check-csv-no-header = keine brauchbare CSV-Kopfzeile: { $reason }
check-pattern-unclosed = nicht geschlossenes `{"{"}` im Muster „{ $pattern }“
check-pattern-adjacent = zwei Felder ohne etwas dazwischen im Muster „{ $pattern }“
check-pattern-twice = das Feld {"{"}{ $field }{"}"} steht zweimal im Muster „{ $pattern }“: jedes Feld nur einmal nennen
check-pattern-too-many = das Muster hat { $count } Platzhalter: höchstens { $limit } werden gelesen
check-pattern-too-long = das Muster ist { $bytes } Bytes lang: höchstens { $limit } werden gelesen
check-pattern-no-field = das Muster „{ $pattern }“ nennt kein Feld
check-pattern-unknown-field = unbekanntes Feld {"{"}{ $field }{"}"} im Muster für --api { $api }: erwartet wird {"{"}_{"}"} oder eines von { $expected }
check-line-not-matching = die Zeile passt nicht zum Muster
check-tally-skipped = übersprungen (passen nicht zum Muster)
check-tally-unreadable = unlesbar
check-tally-unexplained = unerklärt
check-word-not-a-number = „{ $word }“ ist keine Zahl
check-vector-expected-named = erwartet wird `{ $expected }: <Zahl>`, gefunden „{ $found }“
check-vector-within = { $error } (in „{ $text }“)
check-vector-not-three = erwartet werden 3 Zahlen wie `0.1, -0.9, 0` oder `vec3(0.1, -0.9, 0.0)`, gefunden { $count } in „{ $text }“

# Fehler, die sich im Ergebnis zeigen
check-mistake-no-flip-inside = für einen Strahl von der Rückseite der Normale kehrt der Code weder die Normale noch das Verhältnis um
check-mistake-normal-term-sign = der Anteil des Ergebnisses entlang der Normale hat das falsche Vorzeichen; der Anteil quer dazu stimmt
check-mistake-other-root = die andere Lösung: Vorzeichen der Quadratwurzel umgekehrt, das Ergebnis an der Fläche gespiegelt
check-mistake-false-tir = Totalreflexion gemeldet, wo der Strahl gebrochen wird
check-diagnosis-no-lines = Keine Zeile wurde geprüft ({ $lines } gelesen): prüfe das Muster, die CSV-Kopfzeile oder die Felder der Zeilen; check --suggest-pattern liest die ersten Zeilen des Protokolls und schlägt ein Muster vor.
check-physics-explained = Genau das ergibt eine Brechung mit diesem Fehler: { $mistakes }.
check-looks-normal-term = die Antwort der API mit negiertem Anteil entlang der Normale: der Term entlang der Normale wird abgezogen statt addiert oder umgekehrt
check-looks-no-flip = was die Formel ohne Umkehren der Normale und von eta für einen Strahl von der Rückseite der Normale ergibt
check-looks-etap = die richtige Richtung, aber etap = { $logged }, wo der Aufruf { $used } verwendet hat

# Die Diagnose eines ganzen Logs: wo sich ein Fehler zeigt, und seine Behebung
check-where-every = { $count ->
    [one] in der einen geprüften Zeile
   *[other] in jeder geprüften Zeile ({ $count })
}
check-where-inside = { $count ->
    [one] in der einen Zeile, deren Strahl von innen kommt, und in keiner von außen
   *[other] in jeder Zeile, deren Strahl von innen kommt ({ $count }), und in keiner von außen
}
check-where-outside = { $count ->
    [one] in der einen Zeile, deren Strahl von außen kommt, und in keiner von innen
   *[other] in jeder Zeile, deren Strahl von außen kommt ({ $count }), und in keiner von innen
}
check-where-past-critical = { $count ->
    [one] in der einen Zeile jenseits des Grenzwinkels und in keiner anderen
   *[other] in jeder Zeile jenseits des Grenzwinkels ({ $count }) und in keiner anderen
}
check-where-some-sides = in { $count } von { $all } geprüften Zeilen ({ $inside } von innen, { $outside } von außen)
check-where-some = in { $count } von { $all } geprüften Zeilen
check-fix-pass = übergib `{ $code }`
check-fix-write = schreib `{ $code }`
check-fix-restore = stell `{ $code }` wieder her
check-fix-generic-eta-inverted = verwende μ = n_from / n_to, den Brechungsindex des Mediums, das der Strahl verlässt, durch den des Mediums, in das er eintritt: Es kehrt sich um, wo der Strahl das Objekt verlässt (dort μ = n_innen / n_außen; beim Eintritt μ = n_außen / n_innen)
check-fix-generic-incident-reversed = übergib als W die Ausbreitungsrichtung des Strahls, nicht ihr Negatives
check-fix-generic-normal-not-facing = wo der Strahl das Objekt verlässt, verwende in jedem Term die Normale, die dem Strahl zugewandt ist (die äußere, umgekehrt), oder die äußere mit umgekehrtem Vorzeichen, aber nicht beides
check-fix-generic-no-flip-inside = kehr für einen Strahl von innen die Normale und das Verhältnis um, bevor du brichst
check-fix-generic-normal-term-sign = addiere den Term entlang der Normale: T = μ·W + (μ·cosθi − cosθt)·N, mit N dem Strahl zugewandt
check-fix-generic-other-root = gib dem Teil von T längs der zum Strahl zeigenden Normale das Vorzeichen, das T durch die Fläche führt: −cosθt (die Variable mit cosθt oder das von cosθi übernommene Vorzeichen ist umgekehrt)
check-fix-generic-missed-tir = reflektiere, wenn k = 1 − μ²·(1 − cos²θi) negativ ist, bevor du die Quadratwurzel ziehst
check-fix-generic-false-tir = melde Totalreflexion nur, wo k = 1 − μ²·(1 − cos²θi) negativ ist
check-fix-generic-not-unit-input = normiere W und N, bevor du brichst
check-fix-generic-not-the-api-result = kein einzelner Fehler der Formel, auch kein Paar, erzeugt diese Zeilen: die Erklärung jeder Zeile sagt, was zurückkam und was das richtige T ist
check-physics-no-indices = keine Brechungsindizes: gib `mu_i` und `mu_t` an, oder `entering` mit --inside und --outside
check-physics-unknown-convention = unbekannte Konvention "{ $text }": erwartet "along_ray" oder "toward_origin"
check-diagnosis-none = Kein Fehler: Das Log stimmt { $place }.
check-diagnosis-verdict = Der Fehler: { $code } ({ $meaning }), { $place }. Behebung: { $fix }.
check-diagnosis-also = Außerdem: { $code } ({ $meaning }), { $place }. Behebung: { $fix }.
check-diagnosis-alike = Das Log kann ihn nicht von { $alike } unterscheiden; protokolliere { $fields }, um sie zu unterscheiden.
check-pattern-too-many-lines = das Muster umfasst { $count } Zeilen: höchstens { $limit } werden gelesen
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} verneint ein Flag, und { $field } ist keines: schreib {"{"}!entering{"}"} für ein umgekehrt ausgegebenes Flag (inside, backfacing)
check-suggest-toward-origin = der einfallende Vektor wird als wi ausgegeben und zeigt zurück zum Ursprung des Strahls: füge --convention toward-origin hinzu
check-suggest-no-normal = es wird keine Normale ausgegeben: ist sie die z-Achse eines lokalen Systems (Mitsuba, Tungsten), füge --normal +z hinzu
check-suggest-no-side = nichts Ausgegebenes sagt, ob der Strahl in das Objekt eintritt: gib es aus ({"{"}entering{"}"}, oder {"{"}!entering{"}"} für ein Flag wie backfacing) und übergib --inside und --outside, sonst kann das Verhältnis nicht geprüft werden
check-suggest-none = keine der ersten { $lines } Zeilen sieht nach einer Brechung aus (einfallender Vektor, Verhältnis und Ergebnis, jeweils nach seinem Namen): schreib das --pattern von Hand (docs/check.md)
check-situation-outward = wobei { $normal } als die äußere Normale gilt, da die Indizes nichts über die Seite sagen
check-right-sampled = Richtig als gezogene Reflexion: { $call } bricht hier ({ $returned }), aber Mitsuba reflektiert mit Wahrscheinlichkeit F = { $f }, und das leere wo sagt, dass es das tat. Die Diagnose des ganzen Protokolls prüft, dass der Code bei diesen Winkeln anderswo durchlässt.
check-physics-sampled = Nichts kam zurück, wo der Strahl gebrochen wird: richtig als mit Wahrscheinlichkeit F = { $f } gezogene Reflexion, wie Renderer sie protokollieren, die zufällig zwischen Reflexion und Brechung wählen. Die Diagnose des ganzen Protokolls prüft, dass der Code bei diesen Winkeln anderswo durchlässt.
check-fix-in = { $fix } (in { $place })
check-fix-part = { $part }; { $fix }
check-sides-entering = {" "}für Strahlen, die in das Objekt eintreten
check-sides-leaving = {" "}für Strahlen, die das Objekt verlassen
check-part-ratio = T wird mit umgekehrtem Verhältnis gebrochen{ $sides }: 1/μ in jedem Teil, auch im Test auf Totalreflexion (die Variable mit μ oder der Ausdruck, der es wählt)
check-part-across = der Teil von T quer zu N ist mit 1/μ statt μ skaliert (1/μ² des richtigen){ $sides }, der Teil längs N ist richtig: das Verhältnis, das den einfallenden Vektor multipliziert, ist umgekehrt
check-part-along = der Teil von T längs N, cosθt = √(1 − μ²·sin²θi), kommt von 1/μ statt μ{ $sides } (ebenso der Test auf Totalreflexion), der Teil quer zu N ist richtig: das Verhältnis in cosθt ist umgekehrt
check-part-normal = der Teil von T längs N hat das falsche Vorzeichen{ $sides }: die verwendete Normale zeigt nicht zum Strahl
check-part-incident = der Teil von T quer zu N hat das falsche Vorzeichen (T an der Normale gespiegelt, falsch gebrochen): der einfallende Vektor geht verkehrt herum in die Formel ein
check-part-root = der Teil von T längs N hat das falsche Vorzeichen: cosθt liegt auf der Seite, von der der Strahl kommt, also bleibt T in seinem Medium (die andere Lösung)
check-part-term = der Term längs N, (μ·cosθi − cosθt)·N, wird abgezogen statt addiert{ $sides }; der Teil quer zu N ist richtig
check-part-no-flip = für Strahlen von der abgewandten Seite der Normale wird weder die Normale umgekehrt noch das Verhältnis invertiert: T ist die andere Lösung bei 1/μ
check-fix-generic-ratio-across = skaliere den Teil des einfallenden Vektors quer zu N mit μ = n_from / n_to, demselben Verhältnis, mit dem cosθt berechnet wird
check-fix-generic-ratio-along = berechne cosθt = √(1 − μ²·sin²θi) mit μ = n_from / n_to, dem Verhältnis, das den Teil quer zu N skaliert (ein mit Vorzeichen übergebener Kosinus lässt eine Hilfsfunktion das Verhältnis erneut invertieren)
check-fix-generic-across-sign = der Teil quer zu N ist μ mal der des einfallenden Vektors (μ·(W + cosθi·N) mit W entlang des Strahls): nimm ihn mit dem Vorzeichen des einfallenden Vektors
check-fix-generic-never-transmits = der Code lässt diese Strahlen nie durch, obwohl sie gebrochen werden: wenn er Reflexion zieht, muss deren Wahrscheinlichkeit (F, die Fresnel-Reflektanz) dort unter 1 bleiben; melde Totalreflexion nur, wo k = 1 − μ²·(1 − cos²θi) negativ ist
check-diagnosis-unchecked = Ohne zu wissen, von welcher Seite jeder Strahl kommt, nicht prüfbar, { $place }: jede Zeile ist nach den Regeln ihrer API richtig, aber nichts im Protokoll oder in den Optionen unterscheidet ein richtiges Verhältnis von einem falschen. { $fix }.
check-diagnosis-alike-no-field = Das Protokoll kann es nicht von { $alike } unterscheiden.
check-unchecked-log-entering = Protokolliere entering in jeder Zeile (true, wenn der Strahl in das Objekt eintritt; {"{"}!entering{"}"} liest ein Flag wie inside oder backfacing), oder from und to
check-unchecked-pass-indices = Übergib --inside und --outside (die Indizes innen und außen) mit protokolliertem entering, oder bei pbrt und Mitsuba mit der äußeren Normale; oder protokolliere from und to
check-mistake-across-sign = der Teil des Ergebnisses quer zur Normale hat das falsche Vorzeichen; der Teil längs der Normale ist richtig (das Spiegelbild des Ergebnisses an der Normale)
check-part-across-sign = der Teil von T quer zu N hat das falsche Vorzeichen (T an der Normale gespiegelt, falsch gebrochen), der Teil längs N ist richtig: das Minus vor Verhältnis mal einfallendem Vektor fehlt
check-tally-sampled = reflektiert (gezogen)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } Zeilen des Logs ließen sich nicht lesen (jede wird mit ihrem Fehler beantwortet), und keine gelesene Zeile ist falsch: kein Bestehen; diese Zeilen oder die Art, sie zu lesen, berichtigen.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = das Log besteht aus JSON Lines, deren Schlüssel die Felder benennen: es braucht kein Muster

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = An den gedruckten Ziffern nicht zu entscheiden: so gedruckt sieht der Aufruf aus wie { $shown }, aber Zahlen innerhalb ihrer Rundung machen ihn zu einem richtigen Aufruf (ein Vorzeichen, an dem das Urteil hängt, von N·I, von k oder einer Lösung, liegt näher an null, als die Ziffern zeigen). Drucke mehr Ziffern, um ihn zu beurteilen.
check-diagnosis-too-few-digits = An den gedruckten Ziffern nicht als richtig oder falsch zu erkennen, { $place }: jede ist so gedruckt falsch, aber richtig für Zahlen innerhalb ihrer Rundung; die Ziffern des Logs reichen nicht, um es zu entscheiden (ein Vorzeichen, an dem das Urteil hängt, von N·I, von k = 1 − η²·(1 − (N·I)²) oder einer Lösung, kann näher an null liegen, als sie zeigen). Die Genauigkeit des Logs ist zu gering: { $fix }.
check-too-few-digits-fix = drucke jede Zahl mit mindestens 6 signifikanten Ziffern (printf in C oder einem Shader: %.6g; C#: ToString("G9"), Unitys Vector3: ToString("F6"); C++-Streams: std::setprecision(9); Rust: {"{"}:?{"}"}; Python: repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 sind aus dem ausgegebenen Verhältnis gelesen, für ein Objekt, das dichter ist als seine Umgebung (Glas oder Wasser in Luft): gib die Indizes deiner Szene an, wenn sie abweichen
check-diagnosis-none-judged = Keine der { $lines } Zeilen, die das Muster gelesen hat, ließ sich beurteilen; am Muster liegt es also nicht. Die erste sagt: { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 sind Glas in Luft, angenommen, weil die Zeilen kein Verhältnis ausgeben: gib die Indizes deiner Szene an, wenn sie abweichen

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` ist eine Zahl pro Zeile ausgegeben (wie Eigens cout << v einen Vektor ausgibt): die Zeilen lassen sich nicht sicher zusammenfügen; gib jeden Vektor in einer Zeile aus (Eigen: v.transpose(); nalgebra: v.transpose() oder {"{"}:?{"}"}; numpy: np.array2string(v, max_line_width=1000) oder v.tolist())
check-suggest-column-vectors = die ersten { $lines } Zeilen geben Vektoren mit einer Zahl pro Zeile aus (wie Eigens cout << v), was kein Muster sicher zusammenfügen kann: gib jeden Vektor in einer Zeile aus (Eigen: v.transpose(); nalgebra: v.transpose() oder {"{"}:?{"}"}; numpy: v.tolist()), jeden nach seinem Namen, dann frag erneut

# check: zusammengesetzte Fehler als Ursachen benannt (Issue 43, Punkt 4)
check-mistake-refracted-twice = bei einem Durchgang durch die Grenzfläche zweimal gebrochen: T ist, was das quadrierte Verhältnis (μ²) ergibt
check-mistake-fresnel-cos-sign = der Code transmittiert nie, bei keinem Winkel, obwohl k > 0: das Vorzeichen des Kosinus ging dort verloren, wo der Fresnel-Reflexionsgrad (oder die Wahl zu transmittieren) berechnet wird
check-mistake-normals-mixed = die Seite mit einer Normalen (der geometrischen) entschieden und refract eine andere (die Shading-Normale) übergeben, nach dieser Entscheidung umgekehrt: wo beide nicht übereinstimmen, zeigt die übergebene Normale nicht gegen den Strahl
check-fix-generic-refracted-twice = ruf refract einmal pro Durchgang durch die Grenzfläche auf: T wird hier noch einmal gebrochen (oder μ zweimal angewandt), wie mit μ² = (n_von / n_nach)²; behalte das erste T und verfolge den Strahl bis zur nächsten Fläche
check-fix-generic-fresnel-cos-sign = der Test auf Totalreflexion ist nicht die Ursache (unter 15° macht kein Verhältnis k negativ): wo F oder die Wahl zu transmittieren berechnet wird, nimm cosθi ohne Vorzeichen, |N·I| (oder −N·I mit N gegen den Strahl); ein negativer Kosinus macht F ≥ 1, also wird der Strahl immer reflektiert
check-fix-generic-normals-mixed = entscheide die Seite (entering, das Verhältnis) und kehre die an refract übergebene Normale mit derselben Normalen um: beide Male die Shading-Normale oder beide Male die geometrische (die geometrische bleibt für das Versetzen des Strahlursprungs)
check-fix-normals-print = Wenn der Code die Seite mit einer anderen Normalen entscheidet als der übergebenen (eine geometrische neben einer Shading-Normalen), gib auch `entering` aus: dann kann die Diagnose es unterscheiden.
