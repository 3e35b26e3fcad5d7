# Ce qui est dessiné sur le schéma, les scènes et les graphiques, en français.
# Les étiquettes du schéma doivent rester courtes : le placeur omet celles qui ne tiennent pas.
# Les paramètres portent des nombres déjà écrits avec la virgule décimale.

## Le schéma de l’interface

diagram-ghost-wrong-side = autre racine b : mauvais côté
diagram-ghost-wrong-bend = autre signe de a : mauvaise déviation
diagram-ghost-reversed = deux signes faux : −T
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = milieu du rayon
diagram-medium-entered = milieu où il entre
diagram-material-vacuum = vide
diagram-material-air = air
diagram-material-water = eau
diagram-material-glass = verre
diagram-material-diamond = diamant
diagram-material-custom = personnalisé
diagram-banner-tir =
    RÉFLEXION TOTALE
    k = { $k } < 0 : pas de racine réelle pour b, pas de rayon réfracté ; toute la lumière est réfléchie (θi = { $theta_i }°)
diagram-banner-toward-origin = W pointe vers l’origine, donc a = −μ
diagram-banner-along-ray = W est la direction de propagation, donc a = +μ
diagram-banner-section = Section { $section } : { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Section 1 : W pointe vers l’origine
diagram-banner-asked-along-ray = Section 2 : W est la direction de propagation
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0 : T existe
diagram-critical-angle = angle limite θc = { $angle }°
diagram-kernel-normal = −N : la normale qu’utilise le noyau
diagram-outward-normal-bug =
    bogue de la normale extérieure :
    le T de la formule avec N tel quel
diagram-index-scale = indice μ
diagram-incoming-ray = rayon incident
diagram-normal-incidence = incidence normale : W, N et T sont sur une même droite
diagram-normal-incidence-asked = incidence normale : W est le long de N
diagram-reflected = réfléchi
diagram-reflected-light = réfléchi ({ $light })
diagram-reflected-all = rayon réfléchi (toute la lumière)
diagram-w-along-ray = W (le long du rayon)
diagram-w-toward-origin = W (vers l’origine)
diagram-transmitted = T : transmis
diagram-no-reflected-ray = { $label } : pas de rayon réfléchi

## Poignées (ce que dit un lecteur d’écran)

diagram-handle-w = Angle d’incidence θi (W)
diagram-handle-n = Direction de la normale N
diagram-handle-mu-i = Indice μi du milieu du rayon
diagram-handle-mu-t = Indice μt du milieu où il entre
diagram-handle-source = poignée de la source
diagram-handle-aim = poignée de la direction de la source
diagram-handle-shape = poignée de la forme { $number } ({ $medium })

## Leçons, thèmes, lumière, animations

diagram-lesson-air-to-glass = Air → verre, 40°
diagram-lesson-beyond-critical = Verre → air au-delà de θc
diagram-lesson-normal-incidence = Incidence normale
diagram-lesson-brewster = Angle de Brewster
diagram-lesson-droplet-exit = La sortie d’une goutte
diagram-angle-out-of-range = θi doit être compris entre 0° (inclus) et 90° (exclu), pas { $angle }°
diagram-theme-standard = Standard
diagram-theme-black-on-white = Noir sur blanc
diagram-theme-white-on-black = Blanc sur noir
diagram-light-s = lumière s
diagram-light-p = lumière p
diagram-light-unpolarised = lumière non polarisée
diagram-animation-mu = μ → 1 : T devient W
diagram-animation-sweep = Balayer θi jusqu’à l’incidence rasante : la réflexion totale apparaît
diagram-animation-wavefronts = Fronts d’onde en mouvement

## Le tableau des candidats

diagram-role-chosen = T (choisi)
diagram-role-wrong-side = mauvais côté
diagram-role-wrong-bend = mauvaise déviation
diagram-role-reversed = inversé
diagram-rule-wrong-side = mauvais côté de la surface : l’autre racine pour b renvoie le rayon dans le milieu d’où il venait
diagram-rule-wrong-bend = dévie du mauvais côté : l’autre signe de a retourne la composante le long de la surface, si bien qu’il ne devient pas le rayon incident quand μ → 1
diagram-rule-reversed = les deux faux (mauvais signe de a et mauvaise racine pour b) : c’est −T, qui pointe là d’où venait le rayon

## Une scène tracée

diagram-screen = écran
diagram-index-at-wavelength = n = { $index } à { $wavelength } nm
diagram-stopped-at = arrêté après { $count ->
        [one] { $count } segment
       *[other] { $count } segments
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } appel du noyau
       *[other] { $count } appels du noyau
    }
diagram-count-tir = { $count ->
        [one] { $count } réflexion totale
       *[other] { $count } réflexions totales
    }
diagram-count-reflections = { $count ->
        [one] { $count } réflexion créée
       *[other] { $count } réflexions créées
    }
diagram-count-fresnel = { $count ->
        [one] { $count } évaluation de Fresnel
       *[other] { $count } évaluations de Fresnel
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } longueur d’onde
       *[other] { $count } longueurs d’onde
    }
diagram-count-source-rays = { $count ->
        [one] { $count } rayon source
       *[other] { $count } rayons source
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } saut à indice égal
       *[other] { $count } sauts à indice égal
    }
diagram-count-absorption = { $count ->
        [one] { $count } évaluation d’absorption
       *[other] { $count } évaluations d’absorption
    }
diagram-legend-colour = couleur :
diagram-legend-white-traced = lumière blanche, tracée à { $wavelength } nm
diagram-legend-white-then = lumière blanche, puis
diagram-legend-nm = nm
diagram-legend-opacity = opacité : intensité
diagram-legend-hits = impacts :
diagram-hit-entering = entrant
diagram-hit-leaving = sortant (N retournée)
diagram-hit-tir = réflexion totale

## Ondes

diagram-fronts =
    fronts espacés de λ/{ $index }
    vitesse c/{ $index } = { $speed } c
diagram-huygens-touch =
    Huygens : le front atteint A Δt après B ;
    l’ondelette de B croît de vt·Δt, le nouveau front la touche
diagram-huygens-tir =
    Huygens : l’ondelette de B dépasse BA :
    pas de tangente depuis A, réflexion totale

## Les équations clés

diagram-eq-toward-origin-a = W s’éloigne de T, donc l’article prend a = −μ
diagram-eq-along-ray-a = W pointe dans le sens de T, donc l’article prend a = +μ
diagram-eq-no-refracted-ray = pas de (a, b) réel : il n’y a pas de rayon réfracté
diagram-eq-no-b-with-10 = aucun b réel ne la vérifie avec l’éq. 10
diagram-eq-so = { $given }, donc { $then }
diagram-eq-negative-root = √({ $k }) d’un nombre négatif : pas de b réel (réflexion totale)
diagram-eq-or = ou
diagram-eq-outward-normal-bug = avec N tel quel, b = { $b } : la mauvaise racine, T repart en arrière (le bogue de la normale extérieure) ; le noyau utilise −N et obtient b = { $kernel_b } pour N
diagram-step-wn-flipped = W·N = { $given } : N pointe à l’opposé du rayon, donc le noyau utilise −N : wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = aucune racine réelle à choisir
diagram-eq-no-theta-t = { $given }, donc sinθt vaudrait { $sin_t } > 1 : aucun angle θt n’existe
diagram-eq-with-chosen = { $lhs } = { $rhs } avec le (a, b) choisi
diagram-eq-no-ab-with-12 = aucun (a, b) réel ne la vérifie avec l’éq. 12
# Le nom du sinus dans les formules du pas à pas, tel que l’écrivent les écoles de la langue.
diagram-math-sin = sin

## Pas à pas

diagram-step-snell = Loi de Snell-Descartes
diagram-step-snell-text = Le rayon dévie de sorte que μi·sinθi = μt·sinθt ; avec μ = μi/μt, le sinus de l’angle dans le nouveau milieu vaut μ fois l’ancien.
diagram-step-square = Élever au carré, passer aux cosinus
diagram-step-square-text = Élever au carré permet aux cosinus (produits scalaires) de remplacer les sinus, mais laisse aussi entrer de fausses solutions : une solution et son opposée la vérifient toutes les deux.
diagram-step-decomposition = T comme a·W + b·N
diagram-step-decomposition-text = T est dans le plan de W et N, donc T = a·W + b·N ; les cosinus deviennent des produits scalaires avec wn = W·N, et cosθt = −a·wn − b. Le rayon se propage selon { $travel }.
diagram-step-constraints = Les deux contraintes au carré
diagram-step-constraints-text = Snell-Descartes au carré (éq. 10) et la longueur unité (éq. 12) sont deux équations du second degré en a et b. Quatre couples (a, b) vérifient les deux : T et les trois fantômes. Rien en elles ne distingue les quatre.
diagram-step-roots-a = Les deux racines pour a
diagram-step-roots-a-text = Substituer l’éq. 12 dans l’éq. 10 laisse a² = μ² : a = +μ ou a = −μ. L’autre signe est le symétrique de T par rapport à la normale : il dévie du mauvais côté.
diagram-step-choice-a = Choisir a : la limite μ = 1
# « Animer μ jusqu’à 1 » est le nom du bouton dans la fenêtre.
diagram-step-choice-a-text = Quand μ = 1 rien ne dévie, donc T doit être la direction de propagation, { $travel }. Seul a = { $a } donne cela ; l’autre signe donnerait l’image miroir. Appuie sur « Animer μ jusqu’à 1 » pour voir T converger vers { $travel } et les fantômes non.
diagram-step-choice-a-typo = (Le texte de la section 2 dit ensuite « once we decide upon using the a = −μ solution » : il veut dire a = +μ, celle qu’il a choisie.)
diagram-step-roots-b = Les deux racines pour b
diagram-step-roots-b-text = Avec a fixé, l’éq. 12 est du second degré en b, de racines −a·wn ± √k (k = μ²wn² − μ² + 1). L’autre racine est le symétrique de T par rapport à la surface, renvoyé dans le milieu d’où venait le rayon. k < 0 signifie qu’il n’y a pas de racine réelle : réflexion totale.
diagram-step-choice-b = Choisir b
diagram-step-choice-b-text = Des deux racines, seule celle avec −√k devient b = 0 en μ = 1, quand T doit être le rayon incident inchangé ; l’autre renvoie T de l’autre côté de la surface.
diagram-step-choice-b-flipped = La racine avec −√k tend vers b = 0 en μ = 1, donc T devient le rayon incident. Mais ici N pointe dans le sens du rayon (une normale extérieure là où le rayon quitte le milieu) : avec N tel quel, cette racine est du mauvais côté. Le noyau retourne d’abord N.

## La vue de Fresnel

diagram-fresnel-title = Quelle part de la lumière est réfléchie, de μi = { $mu_i } vers μt = { $mu_t }
diagram-fresnel-axis = angle d’incidence θi
diagram-fresnel-brewster = angle de Brewster θB = { $angle }° : pas de lumière p réfléchie
diagram-fresnel-critical = angle limite θc = { $angle }° : au-delà, tout est réfléchi
diagram-fresnel-brewster-short = angle de Brewster θB = { $angle }°
diagram-fresnel-critical-short = angle limite θc = { $angle }°
diagram-curve-rs = Rs (lumière s réfléchie)
diagram-curve-rp = Rp (lumière p réfléchie)
diagram-curve-r = R (non polarisée, réfléchie)
diagram-curve-t = T (non polarisée, transmise)
diagram-fresnel-source =
    Formules de Fresnel pour la puissance réfléchie (Hecht, Optique, chap. 4) : Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    à partir des cosθi et cosθt du noyau lui-même, sans trigonométrie ; la lumière non polarisée est la moyenne de s et p. Au-delà de l’angle limite, toute la lumière est réfléchie.

## Le graphique de précision

diagram-accuracy-title = Précision en fonction du temps sur cette machine
diagram-accuracy-error-axis = plus grande erreur du jeu difficile, en ε·κ (log)
diagram-accuracy-time-axis = temps par rayon, ns (log)
diagram-accuracy-bound = la borne du noyau par défaut, 32 ε·κ
diagram-accuracy-markers = creux : f32, plein : f64

## Les scènes intégrées (titres, descriptions et noms de leurs milieux)

diagram-scene-dispersing-prism = Prisme dispersif
diagram-scene-dispersing-prism-about = Lumière blanche à travers un prisme équilatéral en verre flint F2 près du minimum de déviation : le violet est le plus dévié.
diagram-scene-droplet = Goutte d’eau (arc-en-ciel)
diagram-scene-droplet-about = La lumière blanche entre dans une goutte, s’y réfléchit et en sort ; la dispersion étale l’arc-en-ciel primaire vers 138 degrés de déviation.
diagram-scene-fibre = Fibre optique
diagram-scene-fibre-about = La réflexion totale répétée guide la lumière dans le cœur ; les rayons les plus inclinés fuient dans la gaine.
diagram-scene-interface = Une interface
diagram-scene-interface-about = Un rayon dans l’air atteint un verre plan (n = 1,5) sous 45 degrés et se rapproche de la normale.
diagram-scene-lens = Lentille convergente
diagram-scene-lens-about = Une lentille biconvexe en BK7 focalise un faisceau parallèle sur un écran ; les rayons marginaux convergent avant.
diagram-scene-right-angle-prism = Prisme à angle droit
diagram-scene-right-angle-prism-about = La réflexion totale sur l’hypoténuse dévie le faisceau de 90 degrés.
diagram-scene-slab = Lame de verre
diagram-scene-slab-about = Faces parallèles : le rayon sortant est parallèle au rayon entrant, décalé latéralement. Pertes de Fresnel sur les deux faces, absorption à l’intérieur.
diagram-medium-core = cœur
diagram-medium-cladding = gaine
diagram-medium-f2 = flint F2
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = BK7 teinté
