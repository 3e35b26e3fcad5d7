# The window, its top bar, tools and panels, in English (the source language).
# Keys are kebab-case and start with what they belong to; placeables ({ $name }) carry
# numbers already written the local way.

language-menu = Language
language-hover = The language of the window. It follows the system's unless chosen here.
