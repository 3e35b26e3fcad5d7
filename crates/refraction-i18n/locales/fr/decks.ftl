## Lesson decks: the tool that builds a deck, the strip that shows its step, the notes window,
## the handout, and the built-in decks' titles, questions and notes
