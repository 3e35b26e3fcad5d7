# check.ftl (fr) : les textes de « Vérifier mon T » : le panneau, ses verdicts et leurs explications.

## Nombres et vecteurs dans les explications

check-number-not-finite = non fini (NaN ou infini)
check-vector-not-finite = un vecteur non fini (composantes NaN ou infinies)

## Verdicts sur un T dans les champs de ce projet (aussi les explications de la commande `check`)

check-verdict-wrong-side = Ton T repart dans le milieu d’où venait le rayon : c’est l’autre racine pour b (+ là où la racine carrée demande -). La cause habituelle est une normale orientée dans le sens du rayon, comme la normale extérieure d’une sphère là où le rayon en sort, utilisée sans être retournée.
check-verdict-wrong-bend = Ton T est dévié du mauvais côté : le signe de a est inversé, il ne redeviendrait donc pas le rayon incident quand μ → 1. La cause habituelle est un mélange des conventions : W orienté vers l’origine (Section 1, a = −μ) donné à la formule de W le long du rayon (Section 2, a = +μ), ou l’inverse.
check-verdict-reversed = Ton T vaut -T et pointe vers là d’où venait le rayon : les deux signes sont faux. La cause habituelle est de renvoyer la direction vers l’origine au lieu de la direction de propagation, ou d’avoir inversé W deux fois.
check-verdict-not-finite-tir = Ton T a des composantes NaN ou infinies. Ce rayon subit une réflexion totale (k < 0) : ton code a pris la racine carrée d’un k négatif au lieu de tester k d’abord.
check-verdict-not-finite-refracts = Ton T a des composantes NaN ou infinies alors que ce rayon est réfracté normalement (k ≥ 0) : cherche une division par zéro ou un vecteur non initialisé.
check-verdict-tir-right = Juste : ce rayon subit une réflexion totale (k < 0) et ton code a renvoyé la réflexion (ou le vecteur nul par lequel GLSL l’indique).
check-verdict-tir-but-refracted = Ce rayon subit une réflexion totale (k = { $k } < 0) : il n’y a pas de rayon réfracté, mais ton code en a renvoyé un. Teste k avant d’en prendre la racine carrée.
check-verdict-zero-vector = Ton T est le vecteur nul, que GLSL renvoie en cas de réflexion totale, mais ce rayon est réfracté (k ≥ 0). Vérifie le signe de k et le rapport des indices.
check-verdict-not-unit = De plus, ton T a pour longueur { $length }, pas 1 : normalise W et N avant la réfraction (la formule suppose des vecteurs unitaires) ou T après.
check-verdict-along-refracted = Ton T pointe le long du rayon réfracté (à { $off } rad près).
check-verdict-right = Juste : ton T est le rayon réfracté (à { $off } rad près).
check-verdict-ratio-upside-down = Ton T est la réfraction avec le rapport des indices à l’envers : μ doit valoir μi/μt (le milieu que le rayon quitte sur celui où il entre), et ton code a utilisé μt/μi.
check-verdict-out-of-plane = Ton T sort du plan d’incidence (le plan de W et N) de { $off } rad : T doit être une combinaison a·W + b·N des deux.
check-verdict-no-candidate = Ton T ne correspond à aucun des quatre choix de signe : il est à { $degrees } degrés du rayon réfracté. Vérifie μ, et le sens de W et de N.

## Lecture de t_yours dans une ligne JSON

check-t-yours-item-not-number = `t_yours[{ $index }]` doit être un nombre ou null
check-t-yours-missing = champ `t_yours` manquant (le T produit par ton code)

## Explications d’un verdict sur un appel d’API (`check --api` et le panneau) : comment chaque API s’exprime

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] le livre
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] refract(I, N, eta) de GLSL
    [pbrt] Refract(wi, n, eta) de pbrt
    [rtiow] refract(uv, n, etai_over_etat) du livre
   *[mitsuba] fresnel(cos_theta_i, eta) de Mitsuba avec refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, l’indice du milieu que le rayon quitte sur celui du milieu où il entre
    [pbrt] l’indice du côté opposé à n sur l’indice du côté vers lequel n pointe (n_inside/n_outside avec la normale extérieure)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index sur une face avant, refraction_index sur une face arrière)
   *[mitsuba] int_ior/ext_ior, l’indice du côté opposé à la normale sur l’indice du côté vers lequel elle pointe
}
check-api-incident-means = { $api ->
    [glsl] la direction dans laquelle le rayon se propage, vers la surface
    [pbrt] la direction de retour vers là d’où venait le rayon (-ray.d)
    [rtiow] la direction unitaire dans laquelle le rayon se propage (unit_vector(r_in.direction()))
   *[mitsuba] wi, qui s’éloigne de la surface en remontant le rayon (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] GLSL soustrait (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt prend (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel vaut -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] cos_theta_t a le signe opposé à cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] la normale extérieure avec l’eta du matériau (n_inside/n_outside)
    [mitsuba] la normale extérieure avec eta = int_ior/ext_ior
   *[other] {""}
}

## Explications d’un appel d’API : les éléments

check-situation-entering = qui entre dans l’objet (de n = { $from } vers n = { $to })
check-situation-leaving = qui sort de l’objet (de n = { $from } vers n = { $to })
check-situation-going = qui va de n = { $from } vers n = { $to }
check-nothing-zero-vector = le vecteur nul
check-nothing-reflection = la réflexion
check-nothing-false-or-null = rien (false ou null)
check-and = et
check-or = ou
check-field-from-and-to = from et to (ou entering avec --inside et --outside)
check-normal-fix-rtiow = la normale de l’enregistrement d’impact après set_face_normal
check-normal-fix-facing = la normale retournée partout où ce produit scalaire est positif
check-normal-inward-entering = elle pointe vers l’intérieur de l’objet, et le rayon entre
check-normal-inward-leaving = elle pointe vers l’intérieur de l’objet, et le rayon sort
check-looks-other-root = l’autre racine, avec le signe de la racine carrée inversé ({ $hint })
check-looks-wrong-bend = la composante le long de la surface inversée
check-looks-reversed = l’opposé de la réponse de l’API
check-looks-length = la même direction avec { $ratio } fois la longueur : ton code met à l’échelle ou normalise autrement
check-looks-reflection = la réflexion, alors que ce rayon est réfracté (n’enregistre que la réfraction, pas une réflexion choisie par Fresnel ou Schlick)
check-looks-variant = ce que { $call } renvoie avec { $variant } : ton implémentation fait cela en interne
check-variant-eta-inverted = eta inversé
check-variant-normal-flipped = la normale retournée
check-variant-incident-reversed = le vecteur incident inversé
check-looks-nothing = { $what }, ce qui signifie que rien n’est transmis, alors que ce rayon est réfracté (k = { $k } ≥ 0)
check-looks-not-finite = des composantes NaN ou infinies, alors que ce rayon est réfracté
check-looks-off = à { $degrees } degrés de celle-ci
check-looks-off-unmeasurable = à un angle impossible à mesurer
check-returned-pbrt-true = true avec wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter réfléchit)
check-returned-mitsuba-reflects = F = 1 (la BSDF réfléchit toujours)
check-unchecked-mu = from et to (ou entering avec --inside et --outside) pour vérifier { $eta }
check-unchecked-travel = travel pour vérifier dans quel sens pointe { $incident }

## Explications d’un appel d’API : les phrases

check-eta-inverted = Dans { $owner }, { $eta } est { $means } : tu as passé { $value } pour un rayon { $situation } ; passe 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = Dans { $owner }, { $eta } est { $means } : tu as passé { $value } pour ce rayon ; passe 1/{ $value } = { $inverse }.
check-incident-reversed = Dans { $owner }, { $incident } est { $means } ; le tien pointe dans l’autre sens : passe -{ $incident } = { $reversed }.
check-incident-reversed-travel = Dans { $owner }, { $incident } est { $means } ; le tien pointe dans l’autre sens (le rayon se propage selon { $travel }) : passe -{ $incident } = { $reversed }.
check-not-unit-input = { $call } suppose { $incident } et { $normal } unitaires et ne les normalise pas : |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length } ; normalise-les d’abord.
check-normal-against = { $call } exige { $normal } opposée à { $incident } (dot({ $normal }, { $incident }) < 0) et ne la retourne pas ; la tienne a dot({ $normal }, { $incident }) = { $dot }, comme une normale extérieure là où le rayon sort de l’objet : passe -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } accepte { $normal } de chaque côté, mais { $eta } doit aller avec : c’est { $means }. Ta { $normal } pointe à l’opposé de celle pour laquelle { $eta } = { $value } était prévu{ $inward } ; passe -{ $normal } = { $flipped } avec le même { $eta } (ou garde { $normal } et passe 1/{ $eta }).
check-tir-glsl = Le refract de GLSL renvoie ici le vecteur nul (k = { $k } < 0 : réflexion totale) ; teste ce cas et réfléchis à la place.
check-tir-pbrt = Le Refract de pbrt renvoie ici false (sin2Theta_t = { $sin2 } >= 1 : réflexion totale) ; réfléchis à la place.
check-tir-rtiow = Le cannot_refract de dielectric::scatter est vrai ici (ri * sin_theta = { $sine } > 1) : le livre réfléchit au lieu d’appeler refract.
check-tir-mitsuba = fresnel renvoie ici F = 1 (cos_theta_t_sqr = { $k } < 0) : Mitsuba réfléchit toujours.
check-tir-got-formula = Ton code a quand même utilisé le vecteur de la formule, { $vector } de longueur { $length } : ce n’est pas un rayon.
check-tir-got-direction = Ton code a donné une direction, { $vector }, là où il n’y en a pas.
check-tir-got-not-finite = Ton code a donné des composantes NaN ou infinies (la racine carrée d’un k négatif, ou normalize() du vecteur nul).
check-result-differs = { $call } renvoie { $returned } pour ces arguments, mais l’appel a donné { $got } : { $detail }. Ta propre implémentation diffère de celle de l’API.
check-ties-no-field = Aucun champ de référence ne les distingue : { $call } lit les deux de la même façon ; l’appel habituel passe { $usual }.
check-ties-give = Donne { $fields } pour les distinguer.
check-ties = Tout aussi possible : { $readings } à la place. { $hint }
check-unchecked = Vérifié seulement selon les règles propres de l’API : donne { $missing }.
check-unexplained-travel = Le { $incident } enregistré est à { $degrees } degrés de la direction { $travel } de ce rayon : ce n’est pas la direction de ce rayon (ni son opposée).
check-unexplained-eta = { $eta } = { $value } ne correspond ni à n_from/n_to = { $mu } ni à son inverse tel que { $call } le lit : ce ne sont pas les indices de cette interface.
check-unexplained = Aucune combinaison d’erreurs d’arguments ne fait correspondre cet appel à la référence donnée.
check-right-tir = Juste : { $call } signale ici une réflexion totale ({ $returned }), et l’appel a donné { $what }.
check-right-for-ray = Juste : { $call } renvoie { $returned } pour ces arguments, pour un rayon { $situation }.
check-right = Juste : { $call } renvoie { $returned } pour ces arguments.

## Les erreurs d’un appel d’API, une ligne chacune

check-mistake-eta-inverted = le rapport des indices à l’envers pour la convention de cette API
check-mistake-incident-reversed = le vecteur incident passé à l’envers
check-mistake-normal-not-facing = la normale du mauvais côté pour cette API (ou pour l’eta passé)
check-mistake-not-the-api-result = le résultat n’est pas ce que l’API renvoie pour ces arguments : ta propre implémentation diffère
check-mistake-missed-tir = une direction (ou NaN) là où l’API signale une réflexion totale
check-mistake-not-unit-input = le vecteur incident ou la normale n’est pas de longueur unité

## Le panneau : les champs de ce projet

check-source-own = W, N, μ (ce projet)
check-code-calls = Ton code appelle :
check-convention = Convention :
check-convention-along-ray = Section 2 : W le long du rayon
check-convention-along-ray-about = W est la direction dans laquelle le rayon se propage, vers la surface (le I de GLSL, le uv du livre).
check-convention-toward-origin = Section 1 : W vers l’origine
check-convention-toward-origin-about = W pointe vers là d’où venait le rayon (le wi de pbrt et de Mitsuba).
check-convention-note = { $about } μ = μi/μt ; N d’un côté ou de l’autre (le noyau la tourne vers le rayon).
check-paste-hint = Colle ce que ton moteur de lancer de rayons a enregistré. Vecteurs sous la forme 0.1, -0.9, 0 ou [0.1,-0.9,0] ou vec3(0.1, -0.9, 0.0) ; ou colle une ligne JSON entière avec t_yours dans « Ton T ».
check-use-current-case = Prendre le cas actuel
check-use-current-case-own-hover = Remplir W, N, μ et la convention depuis l’explorateur
check-use-current-case-api-hover = Remplir les arguments et les indices depuis l’explorateur
check-your-t = Ton T
check-your-t-in-error = ton T
check-button = Vérifier
check-field-not-number = { $field } : « { $text } » n’est pas un nombre
check-student-own = ton T : { $verdict }
check-headline-own = Ton T correspond à : { $verdict }
check-match-refracted = le rayon réfracté T
check-match-not-unit = la direction de T, mais pas de longueur unité
check-match-wrong-side = mauvais côté (l’autre racine pour b)
check-match-wrong-bend = mauvaise déviation (l’autre signe de a)
check-match-reversed = inversé (−T : les deux signes faux)
check-match-tir = réflexion totale, bien traitée
check-match-none = aucun des quatre candidats
check-no-refracted-ray = Il n’y a pas de rayon réfracté : réflexion totale.
check-right-t = Le bon T = { $t }
check-copy-right-t = Copier T
check-not-drawn-changed = (Le cas a changé depuis : le verdict n’est pas dessiné.)

## Le panneau : un appel d’API

check-drawn-incident = { $api ->
    [glsl] I (sens de propagation)
    [pbrt] wi (retour vers l’origine)
    [rtiow] uv (sens de propagation)
   *[mitsuba] wi (s’éloignant de la surface)
}
check-drawn-about = { $api ->
    [glsl] I est la direction dans laquelle le rayon se propage, dessinée comme W le long du rayon (Section 2). N doit être opposée à I : GLSL ne la retourne pas. eta = n_from/n_to = μi/μt. Le vecteur nul signifie réflexion totale.
    [pbrt] wi pointe vers là d’où venait le rayon (−ray.d), dessiné comme W vers l’origine (Section 1). n peut être de chaque côté : pbrt la retourne et inverse eta quand wi est en dessous. eta = l’indice derrière n sur celui de devant (μt/μi avec n tournée vers wi). false signifie réflexion totale.
    [rtiow] uv est la direction unitaire dans laquelle le rayon se propage, dessinée comme W le long du rayon (Section 2). n doit être opposée à uv (front_face). etai_over_etat = n_from/n_to = μi/μt. refract ne teste pas la réflexion totale : c’est le cannot_refract de l’appelant qui réfléchit.
   *[mitsuba] wi s’éloigne de la surface, en remontant le rayon, dessiné comme W vers l’origine (Section 1). n vaut +z (le repère local) s’il est laissé vide. eta = int_ior/ext_ior, l’indice derrière n sur celui de devant (μt/μi avec n tournée vers wi). F = 1 signifie réflexion totale : wo est null.
}
check-convention-about = Convention : { $about }
check-your-call = Ton appel
check-truth = Référence (facultative)
check-picture-outside = μ = { $mu } demande des indices hors de la plage { $low }…{ $high } de l’explorateur
check-student-api = ton { $result } : { $verdict }
check-student-right = juste
check-student-wrong = faux
check-api-right-headline = Juste : ce que { $signature } signifie pour ce rayon
check-api-mistakes = Erreurs : { $codes }
check-api-unexplained-headline = Aucune erreur seule ne l’explique
check-api-returns = Résultat dans { $owner } : { $value }
check-api-drawn = Dessiné : le bon appel, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = Non dessiné : { $why }.
check-copy-as-test = Copier comme test unitaire :

## Le panneau : lignes de journal collées

check-paste-lines = 📋 Coller des lignes de journal
check-pattern = Motif
check-log-lines = Lignes de journal
check-lines-button = Vérifier les lignes
check-read-as-pattern = le motif
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (la première ligne est l’en-tête)
check-bulk-summary = Lu comme { $read_as } : { $count ->
    [one] { $count } appel
   *[other] { $count } appels
}
check-bulk-left-out = { $count ->
    [one] { $count } ligne après les { $first } premières laissée de côté
   *[other] { $count } lignes après les { $first } premières laissées de côté
}
check-column-line = ligne
check-column-ok = ok
check-column-mistakes = erreurs
check-column-explanation = explication
check-row-line = ligne { $line }
check-row-open-hover = Ouvrir cet appel dans le panneau et le schéma
check-row-error = erreur

## Lecture des champs d’un appel, d’une ligne CSV, d’un motif et d’un vecteur (le panneau affiche aussi ces messages)

check-field-not-three = `{ $field }` doit avoir exactement 3 nombres, il en a { $count }
check-field-not-a-vector = `{ $field }` doit être un tableau de 3 nombres ou un texte comme « 0.1, -0.9, 0 »
check-field-not-flag-got = `{ $field }` doit valoir true/false ou 1/0, pas « { $text } »
check-field-not-number-json = `{ $field }` doit être un nombre
check-field-not-flag = `{ $field }` doit valoir true/false ou 1/0
check-field-not-label = `{ $field }` doit être un texte ou un nombre
check-json-not-object = un objet JSON avec les champs { $fields } est attendu
check-unknown-field = champ inconnu `{ $field }`
check-field-not-vector = `{ $field }` doit être 3 nombres
check-field-missing = champ `{ $field }` manquant ({ $what })
check-what-normal = la normale à la surface
check-what-incident = le vecteur incident
check-what-eta = le rapport des indices
check-field-not-finite = `{ $field }` doit être fini, il vaut { $value }
check-field-zero-vector = `{ $field }` est le vecteur nul
check-field-not-positive = `{ $field }` doit être un nombre fini > 0, il vaut { $value }
check-from-and-to-together = `from` et `to` vont ensemble : donne les deux ou aucun
check-travel-not-finite = `travel` doit être un vecteur fini non nul
check-result-null = `{ $field }` est null alors que `{ $returned }` vaut true
check-result-missing = champ `{ $field }` manquant (ce que l’appel a renvoyé{ $api ->
    [pbrt] , ou "returned": false
    [mitsuba] , null s’il a réfléchi
   *[other] {""}
})
check-unknown-precision = précision inconnue « { $text } » : "f32" ou "f64" attendu
check-too-large = { $value } est trop grand pour { $precision }
check-csv-unclosed-quote = guillemet non fermé dans la ligne CSV
check-csv-no-column = l’en-tête CSV n’a pas de colonne `{ $field }` : il nomme { $names } ; attendu : { $expected }
check-csv-partial-vector = l’en-tête CSV n’a que { $count } des 3 composantes de `{ $field }`
check-csv-duplicate-column = l’en-tête CSV nomme `{ $column }` plus d’une fois
check-csv-cells = { $count ->
    [one] { $count } cellule
   *[other] { $count } cellules
} là où l’en-tête a { $columns ->
    [one] { $columns } colonne
   *[other] { $columns } colonnes
}
check-csv-no-header = aucun en-tête CSV utilisable : { $reason }
check-pattern-unclosed = `{"{"}` non fermé dans le motif « { $pattern } »
check-pattern-adjacent = deux champs sans rien entre eux dans le motif « { $pattern } »
check-pattern-twice = le champ {"{"}{ $field }{"}"} est nommé deux fois dans le motif « { $pattern } » : nommez chaque champ une seule fois
check-pattern-too-many = le motif a { $count } emplacements : { $limit } au plus sont lus
check-pattern-too-long = le motif fait { $bytes } octets : { $limit } au plus sont lus
check-pattern-no-field = le motif « { $pattern } » ne nomme aucun champ
check-pattern-unknown-field = champ inconnu {"{"}{ $field }{"}"} dans le motif pour --api { $api } : {"{"}_{"}"} ou l’un de { $expected } attendu
check-line-not-matching = la ligne ne correspond pas au motif
check-tally-skipped = ignorées (ne correspondent pas au motif)
check-tally-unreadable = illisibles
check-tally-unexplained = inexpliquées
check-word-not-a-number = « { $word } » n’est pas un nombre
check-vector-expected-named = `{ $expected }: <nombre>` attendu, « { $found } » trouvé
check-vector-within = { $error } (dans « { $text } »)
check-vector-not-three = 3 nombres attendus, comme `0.1, -0.9, 0` ou `vec3(0.1, -0.9, 0.0)`, { $count } trouvés dans « { $text } »

# Erreurs visibles dans ce qui est renvoyé
check-mistake-no-flip-inside = pour un rayon venant de l’autre côté de la normale, le code ne retourne pas la normale et n’inverse pas le rapport
check-mistake-normal-term-sign = la composante du résultat le long de la normale a le mauvais signe ; la composante transverse est juste
check-mistake-other-root = l’autre racine : le signe de la racine carrée inversé, le résultat réfléchi par rapport à la surface
check-mistake-false-tir = réflexion totale annoncée là où le rayon est réfracté
check-diagnosis-no-lines = Aucune ligne n’a été jugée ({ $lines } lues) : vérifie le motif, l’en-tête CSV ou les champs des lignes ; check --suggest-pattern lit les premières lignes du journal et propose un motif.
check-physics-explained = C’est ce que donne une réfraction avec cette erreur : { $mistakes }.
check-looks-normal-term = la réponse de l’API avec la composante le long de la normale opposée : le terme le long de la normale est soustrait au lieu d’être ajouté, ou l’inverse
check-looks-no-flip = ce que donne la formule sans retourner la normale ni inverser eta pour un rayon venant de l’autre côté de la normale
check-looks-etap = la bonne direction, mais etap = { $logged } là où l’appel a utilisé { $used }

# Le diagnostic d’un journal entier : où une erreur se voit, et sa correction
check-where-every = { $count ->
    [one] sur la seule ligne jugée
   *[other] sur chaque ligne jugée ({ $count })
}
check-where-inside = { $count ->
    [one] sur la seule ligne dont le rayon arrive de l’intérieur, et sur aucune de l’extérieur
   *[other] sur chaque ligne dont le rayon arrive de l’intérieur ({ $count }), et sur aucune de l’extérieur
}
check-where-outside = { $count ->
    [one] sur la seule ligne dont le rayon arrive de l’extérieur, et sur aucune de l’intérieur
   *[other] sur chaque ligne dont le rayon arrive de l’extérieur ({ $count }), et sur aucune de l’intérieur
}
check-where-past-critical = { $count ->
    [one] sur la seule ligne au-delà de l’angle limite, et sur aucune autre
   *[other] sur chaque ligne au-delà de l’angle limite ({ $count }), et sur aucune autre
}
check-where-some-sides = sur { $count } des { $all } lignes jugées ({ $inside } de l’intérieur, { $outside } de l’extérieur)
check-where-some = sur { $count } des { $all } lignes jugées
check-fix-pass = passe `{ $code }`
check-fix-write = écris `{ $code }`
check-fix-restore = rétablis `{ $code }`
check-fix-generic-eta-inverted = utilise μ = n_from / n_to, l’indice du milieu que le rayon quitte sur celui du milieu où il entre : il s’inverse là où le rayon sort de l’objet (là μ = n_intérieur / n_extérieur ; en entrant, μ = n_extérieur / n_intérieur)
check-fix-generic-incident-reversed = passe comme W la direction de propagation du rayon, pas son opposée
check-fix-generic-normal-not-facing = là où le rayon sort de l’objet, utilise dans chaque terme la normale tournée vers le rayon (l’extérieure, retournée), ou l’extérieure avec son signe changé, mais pas les deux
check-fix-generic-no-flip-inside = pour un rayon qui arrive de l’intérieur, retourne la normale et inverse le rapport avant de réfracter
check-fix-generic-normal-term-sign = ajoute le terme le long de la normale : T = μ·W + (μ·cosθi − cosθt)·N, N tournée vers le rayon
check-fix-generic-other-root = donne à la partie de T le long de la normale tournée vers le rayon le signe qui fait traverser la surface à T : −cosθt (la variable qui porte cosθt, ou le signe pris sur cosθi, est inversé)
check-fix-generic-missed-tir = réfléchis quand k = 1 − μ²·(1 − cos²θi) est négatif, avant d’en prendre la racine carrée
check-fix-generic-false-tir = n’annonce une réflexion totale que là où k = 1 − μ²·(1 − cos²θi) est négatif
check-fix-generic-not-unit-input = normalise W et N avant de réfracter
check-fix-generic-not-the-api-result = aucune erreur de la formule, ni paire d’erreurs, ne reproduit ces lignes : l’explication de chaque ligne dit ce qui est revenu et quel est le bon T
check-physics-no-indices = pas d’indices : donne `mu_i` et `mu_t`, ou `entering` avec --inside et --outside
check-physics-unknown-convention = convention inconnue « { $text } » : attendu "along_ray" ou "toward_origin"
check-diagnosis-none = Aucune erreur : le journal est juste { $place }.
check-diagnosis-verdict = L’erreur : { $code } ({ $meaning }), { $place }. Correction : { $fix }.
check-diagnosis-also = Aussi : { $code } ({ $meaning }), { $place }. Correction : { $fix }.
check-diagnosis-alike = Le journal ne la distingue pas de { $alike } ; journalise { $fields } pour les distinguer.
check-pattern-too-many-lines = le motif occupe { $count } lignes : { $limit } au plus sont lues
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} nie un indicateur, et { $field } n’en est pas un : écris {"{"}!entering{"}"} pour un indicateur imprimé à l’envers (inside, backfacing)
check-suggest-toward-origin = le vecteur incident est imprimé comme wi, tourné vers l’origine du rayon : ajoute --convention toward-origin
check-suggest-no-normal = aucune normale n’est imprimée : si c’est l’axe z d’un repère local (Mitsuba, Tungsten), ajoute --normal +z
check-suggest-no-side = rien d’imprimé ne dit si le rayon entre dans l’objet : imprime-le ({"{"}entering{"}"}, ou {"{"}!entering{"}"} pour un indicateur comme backfacing) et passe --inside et --outside, sinon le rapport ne peut pas être vérifié
check-suggest-none = aucune des { $lines } premières lignes ne ressemble à une réfraction (un vecteur incident, un rapport et un résultat, chacun après son nom) : écris le --pattern à la main (docs/check.md)
check-situation-outward = en prenant { $normal } pour la normale extérieure, les indices ne disant rien du côté
check-right-sampled = Juste comme réflexion tirée : { $call } réfracte ici ({ $returned }), mais Mitsuba réfléchit avec la probabilité F = { $f }, et le wo nul dit qu’il l’a fait. Le diagnostic du journal entier vérifie que le code transmet à ces angles ailleurs.
check-physics-sampled = Rien n’est revenu là où le rayon se réfracte : juste comme réflexion tirée avec la probabilité F = { $f }, comme l’écrivent les moteurs qui choisissent au hasard entre réflexion et réfraction. Le diagnostic du journal entier vérifie que le code transmet à ces angles ailleurs.
check-fix-in = { $fix } (dans { $place })
check-fix-part = { $part } ; { $fix }
check-sides-entering = {" "}pour les rayons qui entrent dans l’objet
check-sides-leaving = {" "}pour les rayons qui sortent de l’objet
check-part-ratio = T est réfracté avec le rapport inversé{ $sides } : 1/μ dans chaque partie, dans le test de réflexion totale aussi (la variable qui porte μ, ou le ternaire qui la choisit)
check-part-across = la partie de T transverse à N est multipliée par 1/μ au lieu de μ (1/μ² de la bonne){ $sides }, et la partie le long de N est juste : le rapport qui multiplie le vecteur incident est inversé
check-part-along = la partie de T le long de N, cosθt = √(1 − μ²·sin²θi), vient de 1/μ au lieu de μ{ $sides } (le test de réflexion totale aussi), et la partie transverse à N est juste : le rapport dans cosθt est inversé
check-part-normal = la partie de T le long de N a le mauvais signe{ $sides } : la normale utilisée ne fait pas face au rayon
check-part-incident = la partie de T transverse à N a le mauvais signe (l’image miroir de T par rapport à la normale, mauvaise déviation) : le vecteur incident entre à l’envers dans la formule
check-part-root = la partie de T le long de N a le mauvais signe : cosθt est mis du côté d’où vient le rayon, donc T reste dans son milieu (l’autre racine)
check-part-term = le terme le long de N, (μ·cosθi − cosθt)·N, est soustrait là où il faut l’ajouter{ $sides } ; la partie transverse à N est juste
check-part-no-flip = pour les rayons venant de l’autre côté de la normale, ni la normale n’est retournée ni le rapport inversé : T est l’autre racine avec 1/μ
check-fix-generic-ratio-across = multiplie la partie du vecteur incident transverse à N par μ = n_from / n_to, le rapport même avec lequel cosθt est calculé
check-fix-generic-ratio-along = calcule cosθt = √(1 − μ²·sin²θi) avec μ = n_from / n_to, le rapport qui multiplie la partie transverse à N (un cosinus passé avec son signe fait inverser le rapport une seconde fois par une fonction d’aide)
check-fix-generic-across-sign = la partie transverse à N vaut μ fois celle du vecteur incident (μ·(W + cosθi·N) avec W le long du rayon) : prends-la avec le signe du vecteur incident
check-fix-generic-never-transmits = le code ne transmet jamais ces rayons bien qu’ils se réfractent : s’il tire la réflexion, sa probabilité (F, la réflectance de Fresnel) doit y rester sous 1 ; ne signale la réflexion totale que là où k = 1 − μ²·(1 − cos²θi) est négatif
check-diagnosis-unchecked = Impossible à vérifier sans savoir de quel côté vient chaque rayon, { $place } : chaque ligne est juste selon les règles de son API, mais rien dans le journal ni dans les options ne distingue un bon rapport d’un mauvais. { $fix }.
check-diagnosis-alike-no-field = Le journal ne peut pas le distinguer de { $alike }.
check-unchecked-log-entering = Écris entering sur chaque ligne (true quand le rayon entre dans l’objet ; {"{"}!entering{"}"} lit un indicateur comme inside ou backfacing), ou from et to
check-unchecked-pass-indices = Passe --inside et --outside (les indices à l’intérieur et à l’extérieur de l’objet) avec entering écrit, ou pour pbrt et Mitsuba avec la normale extérieure ; ou écris from et to
check-mistake-across-sign = la partie du résultat transverse à la normale a le mauvais signe ; la partie le long de la normale est juste (l’image miroir du résultat par rapport à la normale)
check-part-across-sign = la partie de T transverse à N a le mauvais signe (l’image miroir de T par rapport à la normale, mauvaise déviation), et la partie le long de N est juste : le moins devant le rapport fois le vecteur incident est perdu
check-tally-sampled = réfléchies (tirées)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } lignes du journal n’ont pas pu être lues (chacune reçoit son erreur), et aucune ligne lue n’est fausse : ce n’est pas une réussite ; corrige ces lignes ou la façon de les lire.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = le journal est en JSON Lines, dont les clés nomment les champs : il n’a pas besoin de motif

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = Impossible à dire avec les chiffres imprimés : tel qu’il est imprimé, l’appel ressemble à { $shown }, mais des nombres dans les limites de leur arrondi en font un appel juste (un signe dont dépend le verdict, de N·I, de k ou d’une racine, est plus proche de zéro que ne le montrent les chiffres). Imprime plus de chiffres pour en juger.
check-diagnosis-too-few-digits = Impossible de dire si elles sont justes ou fausses avec les chiffres imprimés, { $place } : chacune est fausse telle qu’elle est imprimée mais juste pour des nombres dans les limites de leur arrondi ; les chiffres du journal sont trop peu nombreux pour le dire (un signe dont dépend le verdict, de N·I, de k = 1 − η²·(1 − (N·I)²) ou d’une racine, peut être plus proche de zéro qu’ils ne le montrent). La précision du journal est trop faible : { $fix }.
check-too-few-digits-fix = imprime chaque nombre avec au moins 6 chiffres significatifs (printf en C ou dans un shader : %.6g ; C# : ToString("G9"), le Vector3 de Unity : ToString("F6") ; flux C++ : std::setprecision(9) ; Rust : {"{"}:?{"}"} ; Python : repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 sont lus dans le rapport que les lignes impriment, pour un objet plus dense que ce qui l’entoure (verre ou eau dans l’air) : donne les indices de ta scène s’ils diffèrent
check-diagnosis-none-judged = Aucune des { $lines } lignes lues par le motif n’a pu être jugée ; le motif n’est donc pas en cause. La première dit : { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 sont du verre dans l’air, supposés car les lignes n’impriment aucun rapport : donne les indices de ta scène s’ils diffèrent

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` est imprimé un nombre par ligne (comme le cout << v d’Eigen imprime un vecteur) : ses lignes ne peuvent pas être jointes à coup sûr ; imprime chaque vecteur sur une ligne (Eigen : v.transpose() ; nalgebra : v.transpose() ou {"{"}:?{"}"} ; numpy : np.array2string(v, max_line_width=1000) ou v.tolist())
check-suggest-column-vectors = les { $lines } premières lignes impriment des vecteurs un nombre par ligne (comme le cout << v d’Eigen), qu’aucun motif ne peut joindre à coup sûr : imprime chaque vecteur sur une ligne (Eigen : v.transpose() ; nalgebra : v.transpose() ou {"{"}:?{"}"} ; numpy : v.tolist()), chacun après son nom, puis redemande

# check : bogues composés nommés comme causes (issue 43, point 4)
check-mistake-refracted-twice = réfracté deux fois pour une seule traversée de surface : T est ce que donne le rapport au carré (μ²)
check-mistake-fresnel-cos-sign = le code ne transmet jamais, à aucun angle, bien que k > 0 : le signe du cosinus est perdu là où la réflectance de Fresnel (ou le choix de transmettre) est calculée
check-mistake-normals-mixed = le côté décidé avec une normale (la géométrique) et refract reçoit une autre (celle d’ombrage), retournée selon cette décision : là où les deux divergent, la normale passée ne fait pas face au rayon
check-fix-generic-refracted-twice = appelez refract une fois par traversée de surface : T est ici réfracté une seconde fois (ou μ appliqué deux fois), comme avec μ² = (n_départ / n_arrivée)² ; gardez le premier T et suivez le rayon jusqu’à la surface suivante
check-fix-generic-fresnel-cos-sign = le test de réflexion totale n’est pas la cause (sous 15°, aucun rapport ne rend k négatif) : là où F ou le choix de transmettre est calculé, prenez cosθi sans son signe, |N·I| (ou −N·I avec N face au rayon) ; un cosinus négatif donne F ≥ 1, et le rayon est toujours réfléchi
check-fix-generic-normals-mixed = décidez le côté (entering, le rapport) et retournez la normale passée à refract avec la même normale : celle d’ombrage pour les deux, ou la géométrique pour les deux (la géométrique sert à décaler l’origine du rayon)
check-fix-normals-print = Si le code décide du côté avec une autre normale que celle qu’il passe (une normale géométrique à côté d’une normale d’ombrage), journalisez aussi `entering` : le diagnostic pourra alors les distinguer.
