# La fenêtre, sa barre supérieure, ses outils et ses panneaux, en français.
# Les clés sont en kebab-case et commencent par ce à quoi elles appartiennent ; les paramètres ({ $name }) contiennent
# des nombres déjà écrits à la manière locale (avec une virgule décimale là où la langue l’utilise).

## La barre du haut

view-interface = Une interface
view-scenes = Scènes
view-menu = Vue
view-accuracy = Précision/temps
# Désigne, dans un message d’erreur, une scène conservée de la dernière exécution.
view-last-run-scene = la scène de la dernière exécution
# Ce qu’a fait la dernière annulation ou le dernier rétablissement ($change), et la vue vers laquelle on est passé ($view).
travel-in-view = { $change } (vue { $view })
tool-check = Vérifier mon T
tool-walk-through = Pas à pas
tool-files = Enregistrer, ouvrir, partager
tool-fresnel = Fresnel
presentation-toggle = 🖵 Présentation
presentation-toggle-hover = Plein écran, tout en plus grand (F11)
presentation-theme = Thème
presentation-theme-hover = Standard, ou contraste élevé : noir sur blanc ou blanc sur noir
presentation-colour-blind = Adapté aux daltoniens
presentation-colour-blind-hover = Couleurs Okabe–Ito uniquement ; chaque rayon a aussi son propre tireté et son étiquette
presentation-simple = Vue simple
presentation-simple-hover = Omet les trois choix de signe rejetés et leur (a, b) : pour une classe qui ne connaît pas encore les quatre candidats
presentation-look = Apparence
presentation-diagram-only = Le schéma seul (D)
language-menu = Langue
language-hover = La langue de la fenêtre. Elle suit celle du système sauf si elle est choisie ici.
effects-menu = Effets
effects-menu-hover = Intensités (Fresnel) et fronts d’onde sur le schéma
effects-intensities = Intensités
effects-intensities-hover = Trace les rayons réfléchi et transmis selon leur part de la lumière (Fresnel), avec les pourcentages
effects-wavefronts = Fronts d’onde
effects-wavefronts-hover = Fronts d’onde plans espacés de λ/μ dans chaque milieu, avançant à c/μ : voilà pourquoi le rayon est dévié
effects-moving = En mouvement
effects-huygens = Construction de Huygens
effects-huygens-hover = Deux points d’un même front et l’onde secondaire formée pendant le temps qui les sépare

## Les panneaux latéraux ($key est la touche qui les ouvre et les ferme, par exemple F2)

panel-show-controls = Afficher les commandes ({ $key })
panel-hide-controls = Masquer les commandes ({ $key })
panel-show-numbers = Afficher les valeurs ({ $key })
panel-hide-numbers = Masquer les valeurs ({ $key })

## Sous le schéma

canvas-hint = Fais glisser W, N ou un repère μ, ou utilise − et + en dessous ; Tab ou un clic en choisit un pour les flèches du clavier
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Maj : 0,1°) · +/− μt · Tab : poignée suivante · glisser pour déplacer
canvas-hint-index = ↑/↓ ou +/− changent l’indice de 0,01 (Maj : 0,001) · Tab : poignée suivante

## Le panneau des commandes

controls-lesson = Leçon
controls-lesson-preset = Préréglage de la leçon
controls-lesson-own = Cas personnel
controls-lesson-changed = { $lesson }, modifié
controls-reset = Réinitialiser
controls-reset-hover = Revenir au début de la leçon choisie
controls-incidence = θi (degrés)
controls-convention = Convention
controls-convention-toward-origin = Section 1 : W pointe vers l’origine
controls-convention-along-ray = Section 2 : W est la direction de propagation
controls-flip-normal = Retourner N
controls-flip-normal-hover = Retourne la normale, comme l’est une normale extérieure là où un rayon quitte le verre
controls-snap = Caler W sur θc
controls-snap-hover = Place W à l’angle limite (il faut μi > μt)
controls-snap-disabled = Il n’y a d’angle limite que si μi > μt
controls-indices = Indices
# $symbol est μi ou μt.
controls-index-value = Valeur de { $symbol }
controls-material = Matériau de { $symbol }
controls-custom-hint = personnalisé : saisis une valeur ci-dessus
controls-typed-vectors = W et N saisis
controls-typed-vectors-hint = Colle les vecteurs consignés par un étudiant (x, y, z) ; appuie sur Entrée.
controls-export-heading = Exporter l’image (PNG ou SVG)
controls-export-size = Taille
controls-export-file = Fichier
controls-export-file-hint = un nom en .png ou .svg, ou numéroté diagram-001.png
controls-browse = Parcourir…
controls-export = Exporter l’image
controls-exported = { $path } écrit
# Une valeur saisie qui n’est pas un nombre : $name est ce pour quoi elle a été saisie (θi, μt, W).
typed-not-a-number = { $name } : « { $text } » n’est pas un nombre
typed-not-three-numbers = { $name } : trois nombres x, y, z attendus, { $count } reçus

## Le panneau des valeurs

readouts-discriminant = Discriminant k = μ²wn² − μ² + 1 = { $k } ≥ 0 : T existe
readouts-discriminant-tir = Discriminant k = μ²wn² − μ² + 1 = { $k } < 0 : réflexion totale
# $section est la section de l’article (1 ou 2) dont c’est l’équation 20.
readouts-quadratic = Éq. { $section }.20, l’équation du second degré en b : b² + 2a·wn·b + a² − 1 = 0 avec a = { $a }, wn = { $wn }
readouts-no-roots = pas de racine réelle : la parabole n’atteint plus zéro
readouts-roots = racines b = { $roots } (les b des candidats pour ce a)
readouts-candidates = Les quatre candidats
readouts-candidate = candidat
# Les en-têtes de colonne des vérifications : la loi de Snell-Descartes au carré (l’éq. 10 de l’article), le côté de la surface où se trouve T, le sens dans lequel T est dévié.
readouts-check-snell = éq. 10
readouts-check-side = côté
readouts-check-bend = déviation
readouts-no-candidates = Aucun candidat : k < 0, donc b n’a pas de racine réelle et T n’existe pas.
readouts-candidates-note = Les quatre sont unitaires et vérifient la loi de Snell-Descartes au carré (éq. 10) : l’élévation au carré ne permet pas de les distinguer. Seuls le côté et la déviation (l’argument μ = 1 de l’article) désignent T.
readouts-warnings = Avertissements du noyau
readouts-no-warnings = Aucun avertissement : W et N sont unitaires et N fait face au rayon.
readouts-warning-not-unit = { $vector } a une longueur de { $length }, pas 1 : il a été normalisé (les vecteurs non normalisés sont un bogue courant en lancer de rayons)
readouts-warning-flipped = N pointe à l’opposé du rayon incident (comme une normale extérieure là où un rayon sort d’une sphère) : le noyau a utilisé −N, la normale tournée vers le rayon
readouts-equations = Équations de l’article, section { $section }

## Le pas à pas

walk-previous = Étape précédente
walk-next = Étape suivante
walk-animate = Animer μ jusqu’à 1
walk-animating = Animation de μ jusqu’à 1 …
walk-animate-hover = Fait passer μt à μi : le T choisi converge vers le rayon incident
walk-animate-disabled = μ vaut déjà 1 (μi = μt), ou l’animation est en cours
walk-step = Étape { $number } sur { $count } : { $title }

## L’outil Fresnel

fresnel-plot-about = Courbe de Fresnel : lumière réfléchie et transmise en fonction de θi, le curseur à θi = { $angle }°
fresnel-click-hint = Clique ou fais glisser sur le graphique pour régler θi.
fresnel-at = À θi = { $angle }°, de μi = { $mu_i } vers μt = { $mu_t }.
fresnel-brewster = Angle de Brewster θB = { $angle }° : aucune lumière polarisée p n’y est réfléchie (tan θB = μt/μi).
fresnel-equal-indices = Indices égaux : pas d’interface, rien n’est réfléchi.
fresnel-critical = Angle limite θc = { $angle }° : au-delà, toute la lumière est réfléchie (sin θc = μt/μi).
fresnel-no-critical = Pas d’angle limite : la lumière passe dans un milieu d’indice plus élevé.

## La vue Scènes

scenes-scene = Scène
scenes-rays = Rayons
scenes-draft = Esquisse pendant le glissement : un rayon sur { $every }
scenes-reset-hover = la scène telle que son fichier la décrit
scenes-file = Fichier de scène
scenes-open = Ouvrir un fichier
scenes-save = Enregistrer le fichier
scenes-save-hover = la scène modifiée, au format de scène (TOML)
scenes-open-dialog-hover = Choisir un fichier de scène à ouvrir
scenes-saved = { $path } enregistré
scenes-opened = { $path } ouvert
scenes-hint = Fais glisser la source (ambre), sa direction (l’anneau au bout de la flèche en tirets) ou la poignée d’une forme ; clique sur un point d’impact pour l’ouvrir dans « Une interface ».
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Fichiers et aide
scenes-less = Moins de commandes
scenes-picture-file = Fichier image (.png ou .svg)
scenes-picture-hint = un nom en .png ou .svg, ou numéroté scene-001.svg
scenes-export-size = Exporter en { $width }×{ $height }
scenes-tracing = tracé en cours… { $percent } % (le dernier tracé terminé est affiché)
scenes-cancel = Annuler
scenes-cancel-hover = arrêter le tracé et afficher ce qui a été tracé jusqu’ici
scenes-stopped-segments = le tracé s’est arrêté à sa limite de { $budget } segments : les rayons pas encore suivis sont omis (avec moins de rayons, un max_depth plus petit ou un min_intensity plus grand, le tracé est complet)
scenes-stopped-tests = le tracé s’est arrêté à sa limite de { $budget } tests d’intersection : les rayons pas encore suivis sont omis (avec moins de rayons, de formes ou de réflexions, le tracé est complet)
scenes-stopped-cancelled = le tracé a été annulé : les rayons pas encore suivis sont omis
# L’encadré à côté d’un point d’impact survolé : les milieux d’où vient et où va le rayon, leurs indices et la longueur d’onde tracée.
scenes-hit =
    { $from } vers { $to } ({ $side ->
        [entering] entrée
       *[leaving] sortie : le noyau retourne N
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } nm
    clic : ouvrir dans « Une interface »

## La vue précision

accuracy-heading = Ce que la précision coûte en temps
accuracy-intro = Chronomètre chaque variante du noyau en f32 et f64 sur cette machine et mesure son erreur par rapport à un oracle double-double sur des incidences aléatoires et difficiles. Le graphique montre la plus grande erreur de l’ensemble difficile en unités de ε·κ (ce que l’algorithme perd au-delà de ce que le problème lui-même amplifie) en fonction des nanosecondes par rayon.
accuracy-quick = Mesure rapide (quelques secondes)
accuracy-measure = Mesurer
accuracy-measuring = mesure en cours… { $percent } %
accuracy-press-measure = Appuie sur « Mesurer » pour lancer le banc d’essai.
# $variant désigne une variante du noyau et sa précision, par exemple « stable f32 ».
accuracy-verdict = La plus rapide à moins de 10× de la meilleure précision : { $variant }, { $time } ns par rayon (erreur sur l’ensemble difficile : { $error } ε·κ).
accuracy-footnote = { $random } problèmes aléatoires et { $hard } difficiles sur { $cpu }. Les temps dépendent de ce que fait par ailleurs la machine ; `refraction-explorer bench` donne les mêmes chiffres en ligne de commande.
accuracy-plot-about = Précision en fonction du temps : { $count } variantes, chacune marquée par sa forme et nommée à côté
accuracy-hover =
    { $name }
    { $time } ns, { $error } ε·κ
accuracy-column-variant = variante
accuracy-column-time = ns/rayon
accuracy-column-random = err. max aléatoire
accuracy-column-hard = err. max difficile
accuracy-column-eps-kappa = difficile ε·κ
accuracy-column-tir = écarts en réflexion totale

## La vue élève : ce qu’affiche un téléphone (ou un lien avec view=student), et les boutons qui
## changent W, N et les indices pas à pas

# $symbol : μi ou μt
student-index = Indice { $symbol }
student-full = Explorateur complet
student-full-hover = Tout l’explorateur, avec ses outils et ses panneaux (pour un grand écran)
student-view = Vue élève
student-view-hover = La vue pour un téléphone : la question, le schéma sur toute la largeur et des boutons pour le doigt
