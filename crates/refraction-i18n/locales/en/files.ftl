# Files, exports and undo, in English (the source language): the file dialog and its Replace
# question, the "Save, open, share" tool, the picture and animation exports, undo and redo.
# { $path } is a file's path as the system writes it; { $reason } is the reader's or writer's
# own explanation, which may stay in English.

## What a file holds ($kind and $found: state, png, svg, scene, deck, gif; $found also: other)

files-wrong-extension = { $path }: { $kind ->
        [state] a saved state (JSON)
        [png] a PNG image
        [scene] a scene (TOML)
        [deck] a lesson deck (TOML)
        [gif] a GIF animation
       *[svg] an SVG image
    } is written to a { $extension } file; choose a name ending in { $extension }
files-is-a-folder = { $path } is a folder; choose a file name
files-holds-another-kind = { $path } holds { $found ->
        [state] a saved state (JSON)
        [png] a PNG image
        [scene] a scene (TOML)
        [deck] a lesson deck (TOML)
        [gif] a GIF animation
        [svg] an SVG image
       *[other] something else
    }, not { $kind ->
        [state] a saved state (JSON)
        [png] a PNG image
        [scene] a scene (TOML)
        [deck] a lesson deck (TOML)
        [gif] a GIF animation
       *[svg] an SVG image
    }: it is left as it is; choose another name

## The question before a file is replaced

files-replace-question = Replace the file?
files-already-exists = { $path } already exists.
files-replace = Replace
files-cancel = Cancel

## The open and save dialog

files-dialog-open-title = Open a file
files-dialog-save-title = Save as
files-folder = Folder
# $patterns: the file patterns listed, such as *.png, *.svg
files-showing = showing folders and { $patterns }
files-file-name = File name
files-open-file = Open file
files-save-file = Save file
files-cannot-list = cannot list { $path }: { $reason }
files-not-a-file = { $path } is not a file that can be opened
files-type-a-name = type a file name in an existing folder

## Save, open, share

files-state-file = State file
files-save = 💾 Save
files-save-hover = Write W, N, μ and the convention as a solve JSON line
files-open = 🗁 Open
files-open-hover = Read a solve JSON file; a bad file changes nothing
files-open-dialog = Open…
files-open-dialog-hover = Choose a state file to open
files-save-as = Save as…
files-save-as-hover = Choose where to save
files-saved = saved { $path }
files-not-saved = not saved: { $reason }
files-left-as-it-was = { $path } left as it was
files-opened = opened { $path }
files-opened-as-scene = { $path } is a scene, not a state: opened in the Scenes view
files-opened-as-deck = { $path } is a lesson deck, not a state: opened at its first step
files-neither-state-nor-scene = { $state }; read as a scene: { $scene }
files-cannot-read-state = cannot read state file { $path }: { $reason }
files-state-refused = state file { $path }: { $reason }
files-copy-share = 🔗 Copy share string
files-copy-share-hover = Reproduces this exact state on another machine, bit for bit
files-share-copied = copied the share string
files-paste-share = Paste a share string
files-apply = Apply
files-share-applied = applied the share string
files-share-refused = share string: { $reason }
files-copy-case-as = Copy the case as
# A button: the case as one line of input to the `solve` command
files-copy-solve-line = solve line
# A button: the case as a unit test's vector
files-copy-test-vector = test vector
# $what: the label of the button pressed (solve line, Rust, GLSL, …)
files-copied = copied the { $what }

## Exports

files-wrote = wrote { $path }
files-not-exported = not exported: { $reason }
files-export-cancelled = cancelled: nothing was written
files-export-crashed = the export stopped with an internal error
files-gif-needed = { $path }: an animation is written as a GIF; give a name ending in .gif
files-animation-heading = Animation for a slide
files-animation = Animation
files-gif-file = GIF file
# $percent: how much is done, a number from 0 to 100
files-drawing-frames = drawing frames… { $percent } %
files-export-animation = Export animation
files-export-animation-hover = Draws every frame in the background; the window stays live
files-frames = Frames
files-per-second = per second
files-gif-width = GIF width
files-height = height

## Undo and redo

files-undo = Undo
files-undo-hover = Undo the last change of W, N, μ or convention (Ctrl+Z)
files-redo = Redo
files-redo-hover = Redo what was undone (Ctrl+Shift+Z)
# $changes: what changed, such as "μt 1.333 → 1.5, N flipped"
files-undid = Undid { $changes }
files-redid = Redid { $changes }
# $from, $to: the convention's section number (1 or 2)
files-undo-convention = the convention (Section { $from } → { $to })
files-undo-n-turned = N turned
files-undo-n-flipped = N flipped
files-undo-scene-edit = the edit of { $scene }
files-undo-scene = the scene ({ $from } → { $to })
files-undo-w-or-n-typed = W or N typed
