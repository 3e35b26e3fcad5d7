# La ventana, su barra, herramientas y paneles, en español.

language-hover = El idioma de la ventana. Sigue el del sistema salvo que se elija aquí.
