# L’explorateur dans un navigateur et les liens vers lui, en français : le lien de ce que
# voit la classe (Copier le lien, le code QR, l’adresse web), un lien qui ne s’ouvre pas, le
# polycopié avec ses liens et ce que fait une page du navigateur (son sélecteur de fichiers,
# les téléchargements, le plein écran, le presse-papiers et un seul fil d’exécution).

## Les liens et le code QR

link-web-base = Adresse web
link-web-base-hover = Où la classe ouvre l’explorateur dans un navigateur : l’adresse du dossier qu’écrit cargo xtask web, publié sur un serveur (dans un navigateur, l’adresse de la page elle-même)
link-copy = 🔗 Copier le lien
link-copy-hover = Copie le lien qui ouvre dans un navigateur ce que la classe voit maintenant (cette étape de la séquence ou cet état)
link-copied = Lien copié.
link-qr = Code QR
link-qr-hover = Montre le lien de ce que voit la classe en code QR sur le schéma (Q)
link-no-web-base = Aucune adresse web : saisis l’adresse où la classe ouvre l’explorateur dans un navigateur.
link-file-address = Cette page a été ouverte depuis un fichier : un téléphone ne peut pas ouvrir ce lien. Publie le dossier sur un serveur et saisis son adresse.
# $format : png ou svg
link-qr-save = Enregistrer en { $format }
# $bytes : la longueur du lien
link-qr-too-long = Le lien est trop long pour un code QR ({ $bytes } octets) : copie-le plutôt.
link-qr-close = Q ou Échap ferme
# The QR code dialog: its button that takes the web address typed
link-qr-show = Afficher le code QR
link-notice-close = Fermer (Échap)

## Un lien qui ne s’ouvre pas ($reason : pourquoi, comme ci-dessous)

link-cut-short = le lien est coupé : copie-le à nouveau, en entier
# $reason : où le lien est abîmé, ou les mots du lecteur d’états
link-malformed = le lien est abîmé ({ $reason })
# $part : la partie du lien que cette version ne lit pas, comme v=2
link-newer = le lien vient d’une version plus récente de l’explorateur ({ $part }) : ouvre-le là où cette version tourne
# $step : l’étape telle que le lien la donne
link-bad-step = l’étape { $step } n’est pas un nombre à partir de 1
link-state-and-lesson = le lien nomme à la fois un état et une séquence
link-step-without-lesson = le lien nomme une étape mais aucune séquence
# $name : la séquence que nomme le lien ; $names : les séquences intégrées
link-no-lesson = il n’y a pas de séquence intégrée appelée { $name } (les séquences : { $names })
# $count : le nombre d’étapes de la séquence
link-no-step = la séquence { $name } a { $count } étapes, pas { $step }
# $reason : l’un des messages ci-dessus
web-link-not-opened = Ce lien n’a pas pu être ouvert : { $reason }. L’explorateur montre ce qu’il montrait avant.

## Le polycopié

handout-export = 📄 Polycopié (PDF)
handout-export-hover = Écrit la séquence en polycopié : une page par étape, avec son schéma, sa question, ses notes et, si une adresse web est donnée, son lien et son code QR

## Dans un navigateur

web-page-loading = Chargement de l’explorateur de la réfraction…
# $reason : les mots du navigateur lui-même
web-page-failed = Ce navigateur n’a pas pu lancer l’explorateur de la réfraction ({ $reason }). Un Firefox, Chrome, Edge ou Safari récent avec WebGL 2 le fait tourner.
web-open-through-picker = Une page du navigateur ouvre les fichiers que tu choisis dans le sélecteur de fichiers du navigateur (ou que tu déposes sur la page).
web-choose-file = Choisir un fichier…
web-saved-as-download = Le fichier est téléchargé : le navigateur l’enregistre dans son dossier de téléchargements.
web-download = Télécharger
# $reason : les mots du navigateur lui-même
web-full-screen-refused = Le navigateur n’est pas entré en plein écran ou n’en est pas sorti ({ $reason }) : utilise sa propre touche de plein écran (F11) ou son menu.
web-copy-refused = Le navigateur n’a pas permis de copier ({ $reason }) : sélectionne le texte et appuie sur Ctrl+C.
web-not-secure = une page ouverte depuis un fichier ou par http n’a pas toujours accès au presse-papiers
web-one-thread = Dans un navigateur, ceci tourne sur le seul fil d’exécution de la page : la page ne répond plus jusqu’à la fin.

## The installable page, a panic over the page, the page's file reads, inside another page (issue 44)

web-manifest-description = Fais glisser le rayon, la normale et les indices de réfraction, et regarde le rayon réfracté, ses quatre candidats de signe et la réflexion totale suivre.
web-crash-title = L’explorateur s’est arrêté : une erreur dans son programme. Ce qu’il a dit :
web-crash-reload = Recharger la page
web-crash-reopen = Recharger avec le dernier état, pour ne rien perdre (ou copie ce lien pour le garder) :
# $name: the file's name; $reason: the browser's own words
web-read-failed = Le navigateur n’a pas pu lire { $name } ({ $reason }).
# $name: the file's name; $size and $limit: sizes in MB
web-file-too-large = { $name } pèse { $size } Mo : la page ouvre des fichiers de { $limit } Mo au plus.
web-open-in-tab = ↗ Ouvrir dans un nouvel onglet
web-open-in-tab-hover = Cette page est dans une autre page : ouvre l’explorateur dans un onglet à lui pour le plein écran et la copie

# Rien de perdu (issue 40) : liens refusés avec une raison claire, l’adresse web vérifiée en un seul endroit.
link-part-without-name = une partie du lien n’a pas de nom (« { $part } »)
link-part-twice = le lien donne { $part } deux fois
link-web-base-refused = Cette adresse web ne peut pas servir : { $reason }.
link-web-base-empty = aucune adresse n’a été donnée
link-web-base-scheme = elle commence par « { $scheme } », et non par http://, https:// ou file://
link-web-base-unseen = elle contient { $character }, qu’une adresse ne peut pas contenir (ni espace, ni caractère de contrôle, ni marque invisible)
link-web-base-escape = « { $escape } » n’est pas un échappement pour cent (un % est suivi de deux chiffres hexadécimaux)
link-web-base-credentials = elle contient un nom d’utilisateur ou un mot de passe, que chaque lien et chaque code QR montreraient
link-web-base-too-long = elle fait { $bytes } octets : au plus { $most } gardent les codes QR des liens lisibles sur papier
link-web-base-port = son port n’est pas un nombre de 0 à 65535
link-web-base-host = son hôte manque ou n’est ni un nom ni une adresse IP valides ({ $reason })
storage-web-base-unusable = L’adresse web gardée de la dernière fois n’est pas utilisée : { $reason }.
storage-state-unreadable = L’état gardé de la dernière fois n’a pas pu être lu ({ $reason }) : l’explorateur part de l’état par défaut.
