# python.ftl (fr) : le paquet Python refraction_check : pourquoi un argument de check() est
# refusé (son ValueError), et le court texte et le tableau du notebook qui montrent le résultat.

## Arguments refusés

python-unknown-api = api : API inconnue « { $name } » : attendu "glsl" (ou "hlsl", "wgsl", "glm", "glam"), "pbrt", "rtiow", "mitsuba", ou None pour la réfraction propre d’un moteur de rendu quelconque
python-unknown-argument = argument inconnu `{ $argument }` pour api={ $api } : les champs d’un appel sont { $fields } (`from` s’écrit from_), et les options inside, outside, normal, convention, precision et renderer
python-index = { $argument } doit être un nombre fini > 0 (un indice de réfraction), pas { $value }
python-sides-apart = { $given } sans { $missing } : donne les deux indices, ou aucun
python-not-with-api = { $argument } sert à la réfraction propre d’un moteur quelconque (api=None) : les appels de api="{ $api }" suivent la convention de cette API, leur normale dans un champ à elle
python-normal = normal doit être un axe ("+z", "-y"...) ou trois nombres finis non tous nuls, pas { $value }
python-unknown-word = { $argument } : valeur inconnue « { $value } » : attendu l’une de { $expected }
python-shape = { $argument } a la forme { $shape } : attendu { $expected }, N le nombre d’appels
python-not-numbers = { $argument } doit contenir des nombres : { $reason }
python-not-flag = { $argument } doit contenir True/False ou 1/0, pas { $value } (ligne { $row })
python-rows = { $argument } a { $rows ->
    [one] une ligne
   *[other] { $rows } lignes
} mais { $other } en a { $other_rows } : donne à chaque argument une ligne par appel, ou une valeur pour tous les appels
python-no-rows = { $argument } n’a aucune ligne : il n’y a aucun appel à vérifier
python-nothing-judged = { $calls ->
    [one] L’appel ne peut pas être jugé
   *[other] Aucun des { $calls } appels ne peut être jugé
} : { $reason }

## Le résultat

python-title = { $calls ->
    [one] 1 appel
   *[other] { $calls } appels
}, { $ok } justes
python-column-code = code
python-column-calls = appels
python-column-row = ligne
python-column-explanation = explication
python-first-wrong = { $wrong ->
    [one] L’appel faux :
   *[other] Les { $shown } premiers des { $wrong } appels faux :
}
