# Das Fenster, seine Leiste, Werkzeuge und Bereiche, auf Deutsch.

language-hover = Die Sprache des Fensters. Sie folgt der des Systems, solange hier keine gewählt ist.
