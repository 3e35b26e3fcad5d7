## Accessibilité : ce qu’un lecteur d’écran dit de l’explorateur, les boutons à côté du schéma et les commandes de la page dans un navigateur

access-degrees = { $angle }°
access-normal-up = verticale vers le haut
access-normal-down = verticale vers le bas
access-normal-right = { $angle }° à droite de la verticale
access-normal-left = { $angle }° à gauche de la verticale
access-index-named = { $index } ({ $name })
access-media = Le rayon se propage dans le premier milieu ({ $from }) et rencontre le second ({ $to }).
access-medium-named = { $name }, { $symbol } = { $index }
access-medium-custom = { $symbol } = { $index }
access-incidence-sentence = Il arrive sur la surface à θi = { $angle }° de la normale.
access-incidence-along-normal = Il arrive sur la surface le long de la normale : θi = 0°.
access-normal-sentence = Direction de la normale N : { $direction }.
access-tir = Réflexion totale : θi dépasse l’angle limite θc = { $critical }°, il n’y a donc pas de rayon réfracté et toute la lumière est réfléchie.
access-t-along-normal = T continue tout droit le long de la normale : il n’est pas dévié.
access-t-straight = T continue tout droit, à { $angle }° de la normale : il n’est pas dévié.
access-t-toward = T est dévié vers la normale, à { $angle }° d’elle.
access-t-away = T est dévié en s’écartant de la normale, à { $angle }° d’elle.
access-reflected = Le rayon réfléchi repart à { $angle }° de la normale, de l’autre côté.
access-critical = L’angle limite est θc = { $critical }°.
access-flipped = N pointe à l’opposé du rayon incident, donc le noyau utilise −N.
access-sentence = { $text }.
access-change-value = { $name } { $before } → { $after }
access-change = { $changes } : { $outcome }.
access-change-tir-begins = désormais au-delà de l’angle limite { $critical }° ; toute la lumière est réfléchie
access-change-tir-ends = désormais en deçà de l’angle limite { $critical }° ; T repart à { $angle }° de la normale
access-change-t = T à { $angle }° de la normale
access-step = Étape { $number } sur { $count } : { $title }.
access-question = Question : { $question }
access-view = Vue : { $view }.
access-scene = Scène : { $title }.
access-scene-hidden = Ses rayons sont tracés jusqu’à la première surface qu’ils rencontrent.
access-incidence-decrease = Diminuer θi de 1°
access-incidence-increase = Augmenter θi de 1°
access-normal-turn-left = Tourner N de 1° vers la gauche
access-normal-turn-right = Tourner N de 1° vers la droite
access-index-decrease = Diminuer { $symbol } de { $step }
access-index-increase = Augmenter { $symbol } de { $step }
access-page-controls = Les commandes du schéma
access-page-keys = Dans l’explorateur ci-dessous, Tab passe d’un bouton ou d’un champ à l’autre et les flèches tournent la poignée choisie ; Échap puis Maj+Tab ramène à ces commandes.
access-page-typing = Texte saisi dans l’explorateur
access-title-scene = { $view } : { $scene }
