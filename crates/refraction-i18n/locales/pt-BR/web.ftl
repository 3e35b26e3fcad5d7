# O explorador no navegador e os links para ele, em português: o link do que a turma vê
# (Copiar link, o código QR, o endereço web), um link que não abre, a apostila com seus links
# e o que uma página do navegador faz (seu seletor de arquivos, os downloads, a tela cheia, a
# área de transferência e uma única thread).

## Links e o código QR

link-web-base = Endereço web
link-web-base-hover = Onde a turma abre o explorador no navegador: o endereço da pasta que cargo xtask web escreve, publicada num servidor (no navegador, o endereço da própria página)
link-copy = 🔗 Copiar link
link-copy-hover = Copia o link que abre no navegador o que a turma vê agora (este passo da sequência ou este estado)
link-copied = Link copiado.
link-qr = Código QR
link-qr-hover = Mostra o link do que a turma vê como código QR sobre o diagrama (Q)
link-no-web-base = Nenhum endereço web definido: digite o endereço onde a turma abre o explorador no navegador.
link-file-address = Esta página foi aberta de um arquivo: um celular não consegue abrir este link. Publique a pasta num servidor e digite o endereço dela.
# $format: png ou svg
link-qr-save = Salvar como { $format }
# $bytes: o comprimento do link
link-qr-too-long = O link é longo demais para um código QR ({ $bytes } bytes): copie-o em vez disso.
link-qr-close = Q ou Esc fecha
# The QR code dialog: its button that takes the web address typed
link-qr-show = Mostrar o código QR
link-notice-close = Fechar (Esc)

## Um link que não abre ($reason: por quê, como abaixo)

link-cut-short = o link está cortado: copie-o de novo, inteiro
# $reason: onde o link está danificado, ou as palavras do leitor de estados
link-malformed = o link está danificado ({ $reason })
# $part: a parte do link que esta versão não lê, como v=2
link-newer = o link foi feito por uma versão mais nova do explorador ({ $part }): abra-o onde essa versão roda
# $step: o passo como o link o dá
link-bad-step = o passo { $step } não é um número a partir de 1
link-state-and-lesson = o link nomeia ao mesmo tempo um estado e uma sequência
link-step-without-lesson = o link nomeia um passo, mas nenhuma sequência
# $name: a sequência que o link nomeia; $names: as sequências embutidas
link-no-lesson = não há nenhuma sequência embutida chamada { $name } (as sequências: { $names })
# $count: o número de passos da sequência
link-no-step = a sequência { $name } tem { $count } passos, não { $step }
# $reason: uma das mensagens acima
web-link-not-opened = Não foi possível abrir este link: { $reason }. O explorador mostra o que mostrava antes.

## A apostila

handout-export = 📄 Apostila (PDF)
handout-export-hover = Escreve a sequência como apostila: uma página por passo, com seu diagrama, pergunta, notas e, se houver um endereço web, seu link e código QR

## No navegador

web-page-loading = Carregando o explorador da refração…
# $reason: as palavras do próprio navegador
web-page-failed = Este navegador não conseguiu iniciar o explorador da refração ({ $reason }). Um Firefox, Chrome, Edge ou Safari recente com WebGL 2 o executa.
web-open-through-picker = Uma página do navegador abre os arquivos que você escolhe no seletor de arquivos do navegador (ou solta sobre a página).
web-choose-file = Escolher um arquivo…
web-saved-as-download = O arquivo é baixado: o navegador o salva na pasta de downloads.
web-download = Baixar
# $reason: as palavras do próprio navegador
web-full-screen-refused = O navegador não entrou nem saiu da tela cheia ({ $reason }): use a tecla de tela cheia dele (F11) ou o menu.
web-copy-refused = O navegador não permitiu copiar ({ $reason }): selecione o texto e pressione Ctrl+C.
web-not-secure = uma página aberta de um arquivo ou por http pode não ter acesso à área de transferência
web-one-thread = No navegador isto roda na única thread da página: a página não responde até terminar.

## The installable page, a panic over the page, the page's file reads, inside another page (issue 44)

web-manifest-description = Arraste o raio, a normal e os índices de refração e veja o raio refratado, seus quatro candidatos de sinal e a reflexão total responderem.
web-crash-title = O explorador parou: um erro no seu programa. O que ele disse:
web-crash-reload = Recarregar a página
web-crash-reopen = Recarregar com o último estado, para nada se perder (ou copie este link para guardá-lo):
# $name: the file's name; $reason: the browser's own words
web-read-failed = O navegador não conseguiu ler { $name } ({ $reason }).
# $name: the file's name; $size and $limit: sizes in MB
web-file-too-large = { $name } tem { $size } MB: a página abre arquivos de no máximo { $limit } MB.
web-open-in-tab = ↗ Abrir em uma nova aba
web-open-in-tab-hover = Esta página está dentro de outra: abra o explorador em uma aba própria para apresentar em todo o monitor e para copiar

# Nada se perde (issue 40): links recusados com um motivo claro, o endereço web verificado em um só lugar.
link-part-without-name = uma parte do link não tem nome (“{ $part }”)
link-part-twice = o link dá { $part } duas vezes
link-web-base-refused = Este endereço web não pode ser usado: { $reason }.
link-web-base-empty = nenhum endereço foi dado
link-web-base-scheme = ele começa com “{ $scheme }”, não com http://, https:// ou file://
link-web-base-unseen = ele contém { $character }, que um endereço não pode conter (nem espaços, nem caracteres de controle, nem marcas invisíveis)
link-web-base-escape = “{ $escape }” não é um escape de porcentagem (um % é seguido de dois dígitos hexadecimais)
link-web-base-credentials = ele contém um nome de usuário ou uma senha, que todo link e todo código QR mostrariam
link-web-base-too-long = ele tem { $bytes } bytes: no máximo { $most } mantêm os códigos QR dos links legíveis no papel
link-web-base-port = sua porta não é um número de 0 a 65535
link-web-base-host = seu host falta ou não é um nome nem um endereço IP válido ({ $reason })
storage-web-base-unusable = O endereço web guardado da última vez não é usado: { $reason }.
storage-state-unreadable = Não foi possível ler o estado guardado da última vez ({ $reason }): o explorador começa no estado padrão.
