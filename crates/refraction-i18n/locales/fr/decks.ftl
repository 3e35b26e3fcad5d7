## Séquences pédagogiques : l’outil qui en construit une, le bandeau qui montre son étape, la
## fenêtre des notes, le polycopié, et les titres, questions et notes des séquences intégrées

tool-deck = Séquence pédagogique
deck-answer-hidden = La réponse est cachée : prédis d’abord, puis révèle-la

## L’outil

deck-title-field = Titre de la séquence
deck-file = Fichier de la séquence
deck-open-file = Ouvrir le fichier
deck-save-file = Enregistrer le fichier
deck-open-dialog-hover = Choisis un fichier de séquence à ouvrir
deck-built-in = Séquences intégrées
deck-new = Nouvelle séquence
deck-new-hover = Commence une séquence vide ; celle qui est affichée se ferme (enregistre-la d’abord)
deck-add-step = Ajouter l’état actuel comme étape
deck-add-step-hover = Une nouvelle étape après celle qui est affichée, avec le schéma tel qu’il est : W, N, les indices, la vue, sa scène, l’outil ouvert et les effets
deck-update-step = Garder l’état actuel dans cette étape
deck-update-step-hover = Faire glisser pendant une étape ne change que le schéma ; ceci garde dans l’étape ce qu’il montre maintenant (enregistre la séquence pour le garder dans le fichier)
deck-steps = Étapes
deck-no-steps = Pas encore d’étape : prépare le schéma, puis ajoute-le comme étape.
# $number est le numéro de l’étape, $title son titre
deck-step-row = { $number }. { $title }
deck-move-up = Monter l’étape
deck-move-down = Descendre l’étape
deck-delete = Supprimer l’étape
deck-step-title = Titre
deck-step-question = Question pour la classe
deck-step-question-hint = aucune : la réponse s’affiche tout de suite
deck-step-notes = Notes pour l’enseignant
deck-untitled = Étape { $number }
deck-edited = modifiée depuis l’enregistrement
deck-saved = { $path } enregistré
deck-opened = { $path } ouvert
deck-not-saved = non enregistré : { $reason }
deck-nothing-to-save = La séquence n’a aucune étape à enregistrer : ajoutes-en une d’abord.

## Parcourir une séquence

# $number est l’étape affichée, $count le nombre d’étapes : « 2 / 5 »
deck-step-number = { $number } / { $count }
deck-previous = Étape précédente
deck-next = Étape suivante
deck-reveal = Révéler la réponse
deck-hide = Cacher la réponse
deck-notes-window = Fenêtre des notes
deck-notes-window-hover = Les notes de l’enseignant dans une fenêtre à part, à placer sur l’écran du portable pendant que le projecteur montre le schéma
deck-keys = Page suivante, → ou espace : étape suivante · Page précédente ou ← : précédente · R : révéler la réponse · N : fenêtre des notes
deck-hidden-hint = R révèle la réponse
deck-shown-hint = R cache de nouveau la réponse
# $title est le titre de la séquence
deck-notes-title = Notes : { $title }
deck-notes-none = Pas de notes pour cette étape.
# $title est le titre de l’étape suivante
deck-notes-next = Ensuite : { $title }
deck-notes-last = C’est la dernière étape.

## Le polycopié (render --lesson … --out handout.pdf)

deck-handout-question = Question
deck-handout-notes = Notes

## Séquence intégrée : la loi de Snell-Descartes en dix minutes

deck-snell-title = La loi de Snell-Descartes en dix minutes
deck-snell-1-title = De l’air au verre
deck-snell-1-question = Le rayon passe de l’air au verre. Dévie-t-il vers la normale ou s’en écarte-t-il ?
deck-snell-1-notes = Vers la normale : θt est plus petit que θi, car le verre est le milieu le plus réfringent. Fais glisser W lentement de 0° à 80° et laisse la classe lire les deux angles.
deck-snell-2-title = Droit le long de la normale
deck-snell-2-question = Un rayon arrive sur la surface le long de la normale. De quel côté dévie-t-il ?
deck-snell-2-notes = Il ne dévie pas : θi = θt = 0 pour tout couple de milieux. La lumière ralentit seulement dans le verre.
deck-snell-3-title = La loi de Snell-Descartes
deck-snell-3-notes = La première étape de « Pas à pas » : μi sin θi = μt sin θt. Demande à deux élèves de lire θi et θt et de calculer les deux membres ; ils sont égaux jusqu’au dernier chiffre affiché.
deck-snell-4-title = Du verre à l’air
deck-snell-4-question = Maintenant le rayon sort du verre. De quel côté dévie-t-il ?
deck-snell-4-notes = Il s’écarte de la normale : θt est plus grand que θi. Augmente θi et T pivote vers la surface : l’angle limite de la prochaine séance.
deck-snell-5-title = À travers une lame de verre
deck-snell-5-question = Le rayon traverse une lame à faces parallèles. Dans quelle direction en sort-il ?
deck-snell-5-notes = Parallèle au rayon incident, décalé sur le côté : la seconde réfraction défait la première. Fais glisser la source pour montrer que le décalage croît avec l’angle.

## Séquence intégrée : la réflexion totale et la fibre

deck-tir-title = La réflexion totale et la fibre
deck-tir-1-title = En sortant du verre
deck-tir-1-question = Le rayon passe du verre à l’air. Que deviennent T et le rayon réfléchi quand θi augmente ?
deck-tir-1-notes = T pivote vers la surface et faiblit tandis que le rayon réfléchi s’intensifie : Intensités dessine chaque rayon selon sa part de la lumière.
deck-tir-2-title = Juste avant l’angle limite
deck-tir-2-question = Pour quel angle T sera-t-il le long de la surface ?
deck-tir-2-notes = Pour l’angle limite : sin θc = μt/μi, 41,8° du verre à l’air. À 41°, T rase presque la surface ; le bouton « Caler W sur θc » y place W exactement.
deck-tir-3-title = Au-delà de l’angle limite
deck-tir-3-question = W est à 45°, au-delà de 41,8°. Où va la lumière ?
deck-tir-3-notes = Elle est toute réfléchie : réflexion totale. Le noyau ne trouve pas de T, donc pas non plus de candidat rejeté ; le bandeau le dit.
deck-tir-4-title = De l’eau à l’air
deck-tir-4-question = L’angle limite de l’eau est-il plus grand ou plus petit que celui du verre ?
deck-tir-4-notes = Plus grand : arcsin(1/1,333) = 48,6°, car l’eau est moins réfringente que le verre. À 50°, le rayon est piégé ; un plongeur ne voit le ciel que dans un cône de 48,6°.
deck-tir-5-title = La fibre
deck-tir-5-question = La lumière entre par le bout de la fibre. S’échappe-t-elle par le côté ?
deck-tir-5-notes = Non : chaque impact sur le côté de la fibre est au-delà de l’angle limite, donc le rayon est totalement réfléchi à chaque fois et guidé le long de la fibre. Tourne la source jusqu’à ce que la lumière s’échappe.
deck-tir-6-title = Le prisme comme miroir
deck-tir-6-question = Pourquoi un prisme à angle droit réfléchit-il comme un miroir ?
deck-tir-6-notes = À l’intérieur, le rayon atteint la grande face à 45°, au-delà de l’angle limite du verre du prisme (41,3°) : il est totalement réfléchi et ne perd presque pas de lumière ; c’est pourquoi les jumelles contiennent des prismes.

## Séquence intégrée : Fresnel et Brewster

deck-fresnel-title = Fresnel et Brewster
deck-fresnel-1-title = Quelle part de la lumière est réfléchie ?
deck-fresnel-1-question = À 40° de l’air au verre, quelle part de la lumière est réfléchie ?
deck-fresnel-1-notes = Environ 5 % (4 % en incidence normale) : le reste continue comme T. Le graphique de Fresnel montre R et T en fonction de θi, avec le θi du schéma marqué.
deck-fresnel-2-title = Près de l’incidence rasante
deck-fresnel-2-question = À 80°, la réflexion est-elle plus faible ou plus forte qu’à 40° ?
deck-fresnel-2-notes = Bien plus forte : elle monte vers 100 % en incidence rasante ; c’est pourquoi un lac reflète la rive lointaine mais pas le ciel au-dessus.
deck-fresnel-3-title = L’angle de Brewster
deck-fresnel-3-question = De la lumière p arrive sur le verre à 56,3°. Quelle part en est réfléchie ?
deck-fresnel-3-notes = Aucune : à l’angle de Brewster, tan θB = μt/μi, les rayons réfléchi et réfracté sont à angle droit et la lumière p n’est pas réfléchie du tout. Les lunettes de soleil polarisantes s’en servent.
deck-fresnel-4-title = La lumière s au même angle
deck-fresnel-4-notes = La lumière s est encore réfléchie, environ 15 % : la lumière réfléchie est en partie polarisée, surtout à l’angle de Brewster.
deck-fresnel-5-title = Les réflexions dans une lame
deck-fresnel-5-question = Combien de rayons sortent d’une lame de verre quand chaque surface réfléchit un peu ?
deck-fresnel-5-notes = Chaque impact crée un rayon réfléchi, de plus en plus faible : deux rayons forts, puis une rangée de faibles. Les intensités baissent à chaque rebond.

## Séquence intégrée : les conventions de signe des moteurs de lancer de rayons

deck-signs-title = Les conventions de signe des moteurs de lancer de rayons
deck-signs-1-title = Les quatre candidats
deck-signs-1-question = Élever les équations au carré fait entrer quatre solutions. Laquelle est T ?
deck-signs-1-notes = Les trois fantômes enfreignent chacun une règle : le mauvais côté (l’autre racine pour b), la mauvaise déviation (l’autre signe de a) et inversé (les deux). Seul T reste de l’autre côté et dévie dans le bon sens.
deck-signs-2-title = En sortant d’une goutte
deck-signs-2-question = Le rayon sort d’une goutte, et N pointe hors de la goutte, le long du rayon. Que doit faire le code de N ?
deck-signs-2-notes = La retourner : le noyau a besoin de la normale tournée vers le rayon. Le rayon d’alerte en tirets est la formule avec N tel quel : le bogue d’un moteur de rendu qui oublie de la retourner.
deck-signs-3-title = Section 1 : W vers l’origine
deck-signs-3-question = Ici W pointe vers l’endroit d’où vient le rayon. Quel signe de la formule change ?
deck-signs-3-notes = Le signe de a : a = −μ dans la section 1, +μ dans la section 2. pbrt et Mitsuba passent wi ainsi ; mélanger les deux conventions donne la mauvaise déviation.
deck-signs-4-title = Section 2 : W le long du rayon
deck-signs-4-notes = Le même rayon avec W le long de lui, comme le passent GLSL, glam et le livre : a = +μ, et T est le même vecteur que dans la section 1.
deck-signs-5-title = Trois erreurs dans un appel d’API
deck-signs-5-question = Le T d’un moteur de rendu est faux. Quelles trois erreurs dans l’appel à refract les élèves font-ils le plus ?
deck-signs-5-notes = Le rapport à l’envers (μt/μi au lieu de μi/μt), le vecteur incident dans l’autre convention et la normale extérieure là où le rayon sort. Colle un appel journalisé dans « Vérifier mon T » : il nomme l’erreur et sa correction.
