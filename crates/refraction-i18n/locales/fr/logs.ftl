# Un journal entier jugé dans la fenêtre : sa section dans « Vérifier mon T », le fichier d’où
# il est lu, son diagnostic, sa carte des erreurs et ses lignes fausses enregistrées en tests.

logs-hint = Lignes portant les champs { $fields } : JSON Lines, CSV avec un en-tête qui les nomme, ou lignes de printf lues avec un motif comme { $example }. Colle au plus { $characters } caractères ou ouvre un fichier journal ; les { $count } premières lignes sont listées et toutes entrent dans le diagnostic.
logs-inside = Indice à l’intérieur
logs-outside = à l’extérieur
logs-indices-hint = l’indice de l’objet et celui de son milieu, pour les lignes qui journalisent entering
logs-index-invalid = { $field } : « { $text } » n’est pas un indice (un nombre fini supérieur à 0)
logs-not-listed = { $count ->
    [one] { $count } ligne de plus jugée mais non listée (le tableau montre les { $first } premières)
   *[other] { $count } lignes de plus jugées mais non listées (le tableau montre les { $first } premières)
}
logs-diagnosis-heading = Diagnostic du journal entier
logs-copy-diagnosis = Copier le diagnostic et le tableau
logs-copy-diagnosis-hover = En texte : les comptes, le diagnostic, puis une ligne par appel avec des tabulations entre ses cellules
logs-map-heading = Carte des erreurs
logs-map-hover = L’écart entre la direction de chaque ligne jugée et la bonne, en fonction de l’angle d’incidence, dans un panneau par côté d’où arrivent les rayons. Carrés : la bonne réponse est la réflexion totale.
logs-open = 🗁 Ouvrir un journal…
logs-open-hover = Lire un fichier journal (ou le déposer sur la fenêtre) : jusqu’à { $most } lignes sont jugées et diagnostiquées.
logs-what-log = journal
logs-read-failed = Impossible de lire { $path } : { $reason }
logs-opened = Jugement du fichier { $path } : { $lines ->
    [one] { $lines } ligne
   *[other] { $lines } lignes
} (au plus { $most }).
logs-close-file = Saisir ou coller à la place
logs-save-tests = Enregistrer { $count ->
    [one] la ligne fausse
   *[other] les { $count } premières lignes fausses
} comme tests :
logs-tests-extension = { $path } : les tests dans ce langage s’écrivent dans un fichier { $extension } ; choisis un nom finissant par .{ $extension }
logs-tests-not-ours = { $path } n’est pas un fichier de tests écrit par cet outil ; choisis un autre nom pour garder ton propre code
logs-write-failed = Impossible d’écrire { $path } : { $reason }

diagram-failure-right = juste
diagram-failure-wrong = faux
diagram-failure-past-critical = bonne réponse : réflexion totale
diagram-failure-panel = { $side ->
    [outside] Venant de l’extérieur
    [inside] Venant de l’intérieur
   *[unknown] Côté non journalisé
} : { $lines ->
    [one] { $lines } ligne
   *[other] { $lines } lignes
}, { $wrong ->
    [0] aucune fausse
    [one] { $wrong } fausse
   *[other] { $wrong } fausses
}
diagram-failure-caption = L’écart entre la direction où chaque ligne jugée envoie le rayon et la bonne, en fonction de l’angle d’incidence θi :
diagram-failure-empty = Aucune ligne n’a été jugée.
diagram-failure-about = Carte des erreurs. { $panels }

# check --tests and Save failing lines as tests: what is at the path cannot be read, or is not a file (issue 40)
logs-tests-unreadable = { $path } ne peut pas être lu ({ $reason }), donc pas distingué de ton propre code : il est laissé tel quel ; choisis un autre nom
logs-tests-not-a-file = { $path } n’est pas un fichier ordinaire (un tube, un périphérique ou un lien vers l’un d’eux) : les tests ne s’écrivent que dans un fichier à eux ; choisis un autre nom
