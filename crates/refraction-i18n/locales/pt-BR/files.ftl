# Arquivos, exportações e desfazer, em português do Brasil: o diálogo de arquivos e a pergunta antes de substituir,
# a ferramenta “Salvar, abrir, compartilhar”, as exportações de imagem e animação, desfazer e refazer.
# { $path } é o caminho de um arquivo; { $reason } é a explicação de quem leu ou gravou (pode ficar em inglês).

## O que um arquivo contém

files-wrong-extension = { $path }: { $kind ->
        [state] um estado salvo (JSON) é gravado
        [png] uma imagem PNG é gravada
        [scene] uma cena (TOML) é gravada
        [deck] uma sequência didática (TOML) é gravada
        [gif] uma animação GIF é gravada
       *[svg] uma imagem SVG é gravada
    } em um arquivo { $extension }; escolha um nome terminado em { $extension }
files-is-a-folder = { $path } é uma pasta; escolha um nome de arquivo
files-holds-another-kind = { $path } contém { $found ->
        [state] um estado salvo (JSON)
        [png] uma imagem PNG
        [scene] uma cena (TOML)
        [deck] uma sequência didática (TOML)
        [gif] uma animação GIF
        [svg] uma imagem SVG
       *[other] outra coisa
    }, não { $kind ->
        [state] um estado salvo (JSON)
        [png] uma imagem PNG
        [scene] uma cena (TOML)
        [deck] uma sequência didática (TOML)
        [gif] uma animação GIF
       *[svg] uma imagem SVG
    }: o arquivo fica como está; escolha outro nome

## A pergunta antes de substituir um arquivo

files-replace-question = Substituir o arquivo?
files-already-exists = { $path } já existe.
files-replace = Substituir
files-cancel = Cancelar

## O diálogo de abrir e salvar

files-dialog-open-title = Abrir um arquivo
files-dialog-save-title = Salvar como
files-folder = Pasta
files-showing = mostrando pastas e { $patterns }
files-file-name = Nome do arquivo
files-open-file = Abrir arquivo
files-save-file = Salvar arquivo
files-cannot-list = não é possível listar { $path }: { $reason }
files-not-a-file = { $path } não é um arquivo que possa ser aberto
files-type-a-name = digite um nome de arquivo em uma pasta existente

## Salvar, abrir, compartilhar

files-state-file = Arquivo de estado
files-save = 💾 Salvar
files-save-hover = Grava W, N, μ e a convenção como uma linha JSON do solve
files-open = 🗁 Abrir
files-open-hover = Lê um arquivo JSON do solve; um arquivo inválido não muda nada
files-open-dialog = Abrir…
files-open-dialog-hover = Escolher um arquivo de estado para abrir
files-save-as = Salvar como…
files-save-as-hover = Escolher onde salvar
files-saved = { $path } salvo
files-not-saved = não salvo: { $reason }
files-left-as-it-was = { $path } ficou como estava
files-opened = { $path } aberto
files-opened-as-scene = { $path } é uma cena, não um estado: aberta na visão Cenas
files-opened-as-deck = { $path } é uma sequência didática, não um estado: aberta no primeiro passo
files-neither-state-nor-scene = { $state }; lido como cena: { $scene }
files-cannot-read-state = não é possível ler o arquivo de estado { $path }: { $reason }
files-state-refused = arquivo de estado { $path }: { $reason }
files-copy-share = 🔗 Copiar texto de compartilhamento
files-copy-share-hover = Reproduz exatamente este estado em outra máquina, bit a bit
files-share-copied = texto de compartilhamento copiado
files-paste-share = Colar um texto de compartilhamento
files-apply = Aplicar
files-share-applied = texto de compartilhamento aplicado
files-share-refused = texto de compartilhamento: { $reason }
files-copy-case-as = Copiar o caso como
files-copy-solve-line = linha do solve
files-copy-test-vector = vetor de teste
files-copied = copiado: { $what }

## Exportações

files-wrote = { $path } gravado
files-not-exported = não exportado: { $reason }
files-export-cancelled = cancelado: nada foi gravado
files-export-crashed = a exportação parou com um erro interno
files-gif-needed = { $path }: uma animação é gravada como GIF; dê um nome terminado em .gif
files-animation-heading = Animação para um slide
files-animation = Animação
files-gif-file = Arquivo GIF
files-drawing-frames = desenhando quadros… { $percent } %
files-export-animation = Exportar animação
files-export-animation-hover = Desenha todos os quadros em segundo plano; a janela continua respondendo
files-frames = Quadros
files-per-second = por segundo
files-gif-width = Largura do GIF
files-height = altura

## Desfazer e refazer

files-undo = Desfazer
files-undo-hover = Desfaz a última mudança de W, N, μ ou da convenção (Ctrl+Z)
files-redo = Refazer
files-redo-hover = Refaz o que foi desfeito (Ctrl+Shift+Z)
files-undid = Desfeito: { $changes }
files-redid = Refeito: { $changes }
files-undo-convention = a convenção (seção { $from } → { $to })
files-undo-n-turned = N girada
files-undo-n-flipped = N invertida
files-undo-scene-edit = a edição de { $scene }
files-undo-scene = a cena ({ $from } → { $to })
files-undo-w-or-n-typed = W ou N digitado
