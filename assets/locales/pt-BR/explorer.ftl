# A janela, sua barra, ferramentas e painéis, em português do Brasil.

language-hover = O idioma da janela. Segue o do sistema, a menos que seja escolhido aqui.
