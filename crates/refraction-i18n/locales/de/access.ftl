## Barrierefreiheit: was ein Bildschirmleser über den Explorer sagt, die Schaltflächen neben dem Diagramm und die Regler der Seite im Browser

access-degrees = { $angle }°
access-normal-up = senkrecht nach oben
access-normal-down = senkrecht nach unten
access-normal-right = { $angle }° rechts der Senkrechten
access-normal-left = { $angle }° links der Senkrechten
access-index-named = { $index } ({ $name })
access-media = Der Strahl verläuft im ersten Medium ({ $from }) und trifft auf das zweite ({ $to }).
access-medium-named = { $name }, { $symbol } = { $index }
access-medium-custom = { $symbol } = { $index }
access-incidence-sentence = Er trifft unter θi = { $angle }° zum Lot auf die Grenzfläche.
access-incidence-along-normal = Er trifft entlang des Lots auf die Grenzfläche: θi = 0°.
access-normal-sentence = Richtung der Normalen N: { $direction }.
access-tir = Totalreflexion: θi liegt über dem Grenzwinkel θc = { $critical }°, es gibt also keinen gebrochenen Strahl, und das ganze Licht wird reflektiert.
access-t-along-normal = T geht entlang des Lots geradeaus weiter: Es wird nicht gebrochen.
access-t-straight = T geht geradeaus weiter, { $angle }° zum Lot: Es wird nicht gebrochen.
access-t-toward = T wird zum Lot hin gebrochen, { $angle }° zum Lot.
access-t-away = T wird vom Lot weg gebrochen, { $angle }° zum Lot.
access-reflected = Der reflektierte Strahl verlässt die Grenzfläche unter { $angle }° zum Lot, auf dessen anderer Seite.
access-critical = Der Grenzwinkel ist θc = { $critical }°.
access-flipped = N zeigt vom einfallenden Strahl weg, daher nimmt der Kernel −N.
access-sentence = { $text }.
access-change-value = { $name } { $before } → { $after }
access-change = { $changes }: { $outcome }.
access-change-tir-begins = jetzt über dem Grenzwinkel { $critical }°; das ganze Licht wird reflektiert
access-change-tir-ends = jetzt unter dem Grenzwinkel { $critical }°; T verlässt die Grenzfläche unter { $angle }° zum Lot
access-change-t = T unter { $angle }° zum Lot
access-step = Schritt { $number } von { $count }: { $title }.
access-question = Frage: { $question }
access-view = Ansicht: { $view }.
access-scene = Szene: { $title }.
access-scene-hidden = Die Strahlen der Szene sind bis zur ersten Fläche gezeichnet, auf die sie treffen.
access-incidence-decrease = θi um 1° verkleinern
access-incidence-increase = θi um 1° vergrößern
access-normal-turn-left = N um 1° nach links drehen
access-normal-turn-right = N um 1° nach rechts drehen
access-index-decrease = { $symbol } um { $step } verringern
access-index-increase = { $symbol } um { $step } erhöhen
access-page-controls = Die Regler des Diagramms
access-page-keys = Im Explorer darunter wechselt Tab zwischen seinen Schaltflächen und Feldern, und die Pfeiltasten drehen einen ausgewählten Anfasser; Esc und dann Umschalt+Tab führt zu diesen Reglern zurück.
access-page-typing = Text, der in den Explorer getippt wird
access-title-scene = { $view }: { $scene }
