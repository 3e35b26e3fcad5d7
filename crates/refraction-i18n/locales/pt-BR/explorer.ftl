# A janela, sua barra superior, ferramentas e painéis, em português do Brasil.
# As chaves estão em kebab-case e começam por aquilo a que pertencem; os marcadores ({ $name }) trazem
# os números já escritos do jeito local (com vírgula decimal onde o idioma a usa).

## A barra superior

view-interface = Uma interface
view-scenes = Cenas
view-menu = Visão
view-accuracy = Precisão/tempo
# Nomeia, em uma mensagem de erro, uma cena guardada da última execução.
view-last-run-scene = a cena da última execução
# O que o último desfazer ou refazer fez ($change) e a visão para a qual mudou ($view).
travel-in-view = { $change } (em { $view })
tool-check = Verificar meu T
tool-walk-through = Passo a passo
tool-files = Salvar, abrir, compartilhar
tool-fresnel = Fresnel
presentation-toggle = 🖵 Apresentação
presentation-toggle-hover = Tela cheia, tudo maior (F11)
presentation-theme = Tema
presentation-theme-hover = Padrão ou alto contraste: preto sobre branco ou branco sobre preto
presentation-colour-blind = Para daltônicos
presentation-colour-blind-hover = Só cores Okabe–Ito; cada raio também tem seu próprio tracejado e rótulo
presentation-simple = Visão simples
presentation-simple-hover = Omite as três escolhas de sinal rejeitadas e seu (a, b): para uma turma que ainda não conhece os quatro candidatos
presentation-look = Aparência
presentation-diagram-only = Só o diagrama (D)
language-menu = Idioma
language-hover = O idioma da janela. Segue o do sistema, a menos que seja escolhido aqui.
effects-menu = Efeitos
effects-menu-hover = Intensidades (Fresnel) e frentes de onda sobre o diagrama
effects-intensities = Intensidades
effects-intensities-hover = Desenha os raios refletido e transmitido conforme sua parcela da luz (Fresnel), com porcentagens
effects-wavefronts = Frentes de onda
effects-wavefronts-hover = Frentes de onda planas separadas por λ/μ em cada meio, movendo-se a c/μ: é por isso que o raio se desvia
effects-moving = Em movimento
effects-huygens = Construção de Huygens
effects-huygens-hover = Dois pontos de uma mesma frente e a onda secundária que cresce no tempo entre eles

## Os painéis laterais ($key é a tecla que os abre e fecha, como F2)

panel-show-controls = Mostrar os controles ({ $key })
panel-hide-controls = Ocultar os controles ({ $key })
panel-show-numbers = Mostrar os números ({ $key })
panel-hide-numbers = Ocultar os números ({ $key })

## Abaixo do diagrama

canvas-hint = Arraste W, N ou um marcador μ, ou use − e + abaixo; Tab ou um clique escolhe um para as setas do teclado
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Shift: 0,1°) · +/− μt · Tab: próxima alça · arraste para mover
canvas-hint-index = ↑/↓ ou +/− mudam o índice em 0,01 (Shift: 0,001) · Tab: próxima alça

## O painel de controles

controls-lesson = Aula
controls-lesson-preset = Predefinição da aula
controls-lesson-own = Caso próprio
controls-lesson-changed = { $lesson }, alterado
controls-reset = Reiniciar
controls-reset-hover = Voltar ao início da aula escolhida
controls-incidence = θi (graus)
controls-convention = Convenção
controls-convention-toward-origin = Seção 1: W aponta de volta para a origem
controls-convention-along-ray = Seção 2: W é a direção de propagação
controls-flip-normal = Inverter N
controls-flip-normal-hover = Inverte a normal, como fica uma normal externa onde um raio sai do vidro
controls-snap = Ajustar W a θc
controls-snap-hover = Coloca W no ângulo limite (requer μi > μt)
controls-snap-disabled = Só há ângulo limite quando μi > μt
controls-indices = Índices
# $symbol é μi ou μt.
controls-index-value = Valor de { $symbol }
controls-material = Material de { $symbol }
controls-custom-hint = personalizado: digite um valor acima
controls-typed-vectors = W e N digitados
controls-typed-vectors-hint = Cole os vetores registrados por um aluno (x, y, z); pressione Enter.
controls-export-heading = Exportar imagem (PNG ou SVG)
controls-export-size = Tamanho
controls-export-file = Arquivo
controls-export-file-hint = um nome .png ou .svg, ou numerado diagram-001.png
controls-browse = Procurar…
controls-export = Exportar imagem
controls-exported = { $path } gravado
# Um valor digitado que não é um número: $name é aquilo para que foi digitado (θi, μt, W).
typed-not-a-number = { $name }: “{ $text }” não é um número
typed-not-three-numbers = { $name }: esperados três números x, y, z; recebidos { $count }

## O painel de números

readouts-discriminant = Discriminante k = μ²wn² − μ² + 1 = { $k } ≥ 0: T existe
readouts-discriminant-tir = Discriminante k = μ²wn² − μ² + 1 = { $k } < 0: reflexão total
# $section é a seção do artigo (1 ou 2) cuja equação 20 é esta.
readouts-quadratic = Eq. { $section }.20, a equação do segundo grau em b: b² + 2a·wn·b + a² − 1 = 0 com a = { $a }, wn = { $wn }
readouts-no-roots = sem raízes reais: a parábola não chega mais a zero
readouts-roots = raízes b = { $roots } (os b dos candidatos para este a)
readouts-candidates = Os quatro candidatos
readouts-candidate = candidato
# Os cabeçalhos de coluna das verificações: a lei de Snell ao quadrado (a eq. 10 do artigo), o lado da superfície em que T está, o sentido em que T se desvia.
readouts-check-snell = eq. 10
readouts-check-side = lado
readouts-check-bend = desvio
readouts-no-candidates = Nenhum candidato: k < 0, então b não tem raízes reais e T não existe.
readouts-candidates-note = Os quatro são unitários e satisfazem a lei de Snell ao quadrado (eq. 10): elevar ao quadrado não os distingue. Só o lado e o desvio (o argumento μ = 1 do artigo) escolhem T.
readouts-warnings = Avisos do kernel
readouts-no-warnings = Sem avisos: W e N são unitários e N está voltado para o raio.
readouts-warning-not-unit = { $vector } tem comprimento { $length }, não 1: foi normalizado (vetores não normalizados são um bug comum em traçadores de raios)
readouts-warning-flipped = N aponta para longe do raio incidente (como uma normal externa onde um raio sai de uma esfera): o kernel usou −N, a normal voltada para o raio
readouts-equations = Equações do artigo, seção { $section }

## O passo a passo

walk-previous = Passo anterior
walk-next = Próximo passo
walk-animate = Animar μ até 1
walk-animating = Animando μ até 1 …
walk-animate-hover = Transforma μt em μi: o T escolhido converge para o raio incidente
walk-animate-disabled = μ já é 1 (μi = μt), ou a animação está em andamento
walk-step = Passo { $number } de { $count }: { $title }

## A ferramenta Fresnel

fresnel-plot-about = Gráfico de Fresnel: luz refletida e transmitida em função de θi, o cursor em θi = { $angle }°
fresnel-click-hint = Clique ou arraste no gráfico para definir θi.
fresnel-at = Em θi = { $angle }°, de μi = { $mu_i } para μt = { $mu_t }.
fresnel-brewster = Ângulo de Brewster θB = { $angle }°: ali nenhuma luz polarizada p é refletida (tg θB = μt/μi).
fresnel-equal-indices = Índices iguais: não há interface, nada é refletido.
fresnel-critical = Ângulo limite θc = { $angle }°: além dele, toda a luz é refletida (sen θc = μt/μi).
fresnel-no-critical = Sem ângulo limite: a luz passa para um meio de índice maior.

## A visão Cenas

scenes-scene = Cena
scenes-rays = Raios
scenes-draft = Rascunho ao arrastar: um raio a cada { $every }
scenes-reset-hover = a cena como está no seu arquivo
scenes-file = Arquivo de cena
scenes-open = Abrir arquivo
scenes-save = Salvar arquivo
scenes-save-hover = a cena editada, no formato de cena (TOML)
scenes-open-dialog-hover = Escolher um arquivo de cena para abrir
scenes-saved = { $path } salvo
scenes-opened = { $path } aberto
scenes-hint = Arraste a fonte (âmbar), sua direção (o anel na ponta da seta tracejada) ou a alça de uma forma; clique em um ponto de impacto para abri-lo em “Uma interface”.
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Arquivos e dica
scenes-less = Menos controles
scenes-picture-file = Arquivo de imagem (.png ou .svg)
scenes-picture-hint = um nome .png ou .svg, ou numerado scene-001.svg
scenes-export-size = Exportar { $width }×{ $height }
scenes-tracing = traçando… { $percent } % (é exibido o último traçado concluído)
scenes-cancel = Cancelar
scenes-cancel-hover = parar o traçado e mostrar o que foi traçado até agora
scenes-stopped-segments = o traçado parou no seu limite de { $budget } segmentos: os raios ainda não seguidos ficam de fora (com menos raios, um max_depth menor ou um min_intensity maior, o traçado fica completo)
scenes-stopped-tests = o traçado parou no seu limite de { $budget } testes de interseção: os raios ainda não seguidos ficam de fora (com menos raios, formas ou reflexões, o traçado fica completo)
scenes-stopped-cancelled = o traçado foi cancelado: os raios ainda não seguidos ficam de fora
# A caixa ao lado de um ponto de impacto sob o ponteiro: os meios de onde vem e para onde vai o raio, seus índices e o comprimento de onda traçado.
scenes-hit =
    de { $from } para { $to } ({ $side ->
        [entering] entrando
       *[leaving] saindo: o kernel inverte N
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } nm
    clique: abrir em “Uma interface”

## A visão de precisão

accuracy-heading = Quanto tempo custa a precisão
accuracy-intro = Cronometra cada variante do kernel em f32 e f64 nesta máquina e mede seu erro em relação a um oráculo double-double em incidências aleatórias e difíceis. O gráfico mostra o maior erro do conjunto difícil em unidades de ε·κ (o que o algoritmo perde além do que o próprio problema amplifica) em função dos nanossegundos por raio.
accuracy-quick = Execução rápida (alguns segundos)
accuracy-measure = Medir
accuracy-measuring = medindo… { $percent } %
accuracy-press-measure = Pressione “Medir” para executar o benchmark.
# $variant nomeia uma variante do kernel e sua precisão, como “stable f32”.
accuracy-verdict = A mais rápida a até 10× da melhor precisão: { $variant }, com { $time } ns por raio (erro no conjunto difícil: { $error } ε·κ).
accuracy-footnote = { $random } problemas aleatórios e { $hard } difíceis em { $cpu }. Os tempos dependem do que mais a máquina está fazendo; `refraction-explorer bench` dá os mesmos números na linha de comando.
accuracy-plot-about = Precisão em função do tempo: { $count } variantes, cada uma marcada pela sua forma e nomeada ao lado
accuracy-hover =
    { $name }
    { $time } ns, { $error } ε·κ
accuracy-column-variant = variante
accuracy-column-time = ns/raio
accuracy-column-random = erro máx. aleatório
accuracy-column-hard = erro máx. difícil
accuracy-column-eps-kappa = difícil ε·κ
accuracy-column-tir = divergências de reflexão total

## A visão do aluno: o que um celular (ou um link com view=student) mostra, e os botões que
## mudam W, N e os índices passo a passo

# $symbol: μi ou μt
student-index = Índice { $symbol }
student-full = Explorador completo
student-full-hover = O explorador inteiro, com suas ferramentas e painéis (para um monitor grande)
student-view = Visão do aluno
student-view-hover = A visão para um celular: a pergunta, o diagrama em toda a largura e botões para o dedo
