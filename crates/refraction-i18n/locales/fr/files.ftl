# Fichiers, exports et annulation, en français : la boîte de dialogue des fichiers et sa question avant de remplacer,
# l’outil « Enregistrer, ouvrir, partager », les exports d’image et d’animation, annuler et rétablir.
# { $path } est le chemin d’un fichier ; { $reason } est l’explication du lecteur ou de l’écrivain (peut rester en anglais).

## Ce que contient un fichier

files-wrong-extension = { $path } : { $kind ->
        [state] un état enregistré (JSON)
        [png] une image PNG
        [scene] une scène (TOML)
        [deck] une séquence pédagogique (TOML)
        [gif] une animation GIF
       *[svg] une image SVG
    } s’écrit dans un fichier { $extension } ; choisis un nom se terminant par { $extension }
files-is-a-folder = { $path } est un dossier ; choisis un nom de fichier
files-holds-another-kind = { $path } contient { $found ->
        [state] un état enregistré (JSON)
        [png] une image PNG
        [scene] une scène (TOML)
        [deck] une séquence pédagogique (TOML)
        [gif] une animation GIF
        [svg] une image SVG
       *[other] autre chose
    }, pas { $kind ->
        [state] un état enregistré (JSON)
        [png] une image PNG
        [scene] une scène (TOML)
        [deck] une séquence pédagogique (TOML)
        [gif] une animation GIF
       *[svg] une image SVG
    } : le fichier reste inchangé ; choisis un autre nom

## La question avant de remplacer un fichier

files-replace-question = Remplacer le fichier ?
files-already-exists = { $path } existe déjà.
files-replace = Remplacer
files-cancel = Annuler

## La boîte de dialogue d’ouverture et d’enregistrement

files-dialog-open-title = Ouvrir un fichier
files-dialog-save-title = Enregistrer sous
files-folder = Dossier
files-showing = dossiers et { $patterns } affichés
files-file-name = Nom du fichier
files-open-file = Ouvrir
files-save-file = Enregistrer
files-cannot-list = impossible de lister { $path } : { $reason }
files-not-a-file = { $path } n’est pas un fichier qui peut être ouvert
files-type-a-name = saisis un nom de fichier dans un dossier existant

## Enregistrer, ouvrir, partager

files-state-file = Fichier d’état
files-save = 💾 Enregistrer
files-save-hover = Écrit W, N, μ et la convention sur une ligne JSON de solve
files-open = 🗁 Ouvrir
files-open-hover = Lit un fichier JSON de solve ; un fichier erroné ne change rien
files-open-dialog = Ouvrir…
files-open-dialog-hover = Choisir un fichier d’état à ouvrir
files-save-as = Enregistrer sous…
files-save-as-hover = Choisir où enregistrer
files-saved = { $path } enregistré
files-not-saved = non enregistré : { $reason }
files-left-as-it-was = { $path } laissé tel quel
files-opened = { $path } ouvert
files-opened-as-scene = { $path } est une scène, pas un état : ouverte dans la vue Scènes
files-opened-as-deck = { $path } est une séquence pédagogique, pas un état : ouverte à sa première étape
files-neither-state-nor-scene = { $state } ; lu comme une scène : { $scene }
files-cannot-read-state = impossible de lire le fichier d’état { $path } : { $reason }
files-state-refused = fichier d’état { $path } : { $reason }
files-copy-share = 🔗 Copier la chaîne de partage
files-copy-share-hover = Reproduit exactement cet état sur une autre machine, bit pour bit
files-share-copied = chaîne de partage copiée
files-paste-share = Coller une chaîne de partage
files-apply = Appliquer
files-share-applied = chaîne de partage appliquée
files-share-refused = chaîne de partage : { $reason }
files-copy-case-as = Copier le cas en
files-copy-solve-line = ligne solve
files-copy-test-vector = vecteur de test
files-copied = copié : { $what }

## Exports

files-wrote = { $path } écrit
files-not-exported = non exporté : { $reason }
files-export-cancelled = annulé : rien n’a été écrit
files-export-crashed = l’export s’est arrêté sur une erreur interne
files-gif-needed = { $path } : une animation s’écrit en GIF ; donne un nom se terminant par .gif
files-animation-heading = Animation pour une diapositive
files-animation = Animation
files-gif-file = Fichier GIF
files-drawing-frames = dessin des images… { $percent } %
files-export-animation = Exporter l’animation
files-export-animation-hover = Dessine chaque image en arrière-plan ; la fenêtre reste réactive
files-frames = Images
files-per-second = par seconde
files-gif-width = Largeur du GIF
files-height = hauteur

## Annuler et rétablir

files-undo = Annuler
files-undo-hover = Annule la dernière modification de W, N, μ ou de la convention (Ctrl+Z)
files-redo = Rétablir
files-redo-hover = Rétablit ce qui a été annulé (Ctrl+Maj+Z)
files-undid = Annulé : { $changes }
files-redid = Rétabli : { $changes }
files-undo-convention = la convention (section { $from } → { $to })
files-undo-n-turned = N tournée
files-undo-n-flipped = N retournée
files-undo-scene-edit = la modification de { $scene }
files-undo-scene = la scène ({ $from } → { $to })
files-undo-w-or-n-typed = W ou N saisi
