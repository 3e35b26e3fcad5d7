# O que é desenhado no diagrama, nas cenas e nos gráficos, em português do Brasil.
# Os rótulos do diagrama devem ser curtos: o posicionador omite os que não cabem.
# Os marcadores trazem números já escritos com vírgula decimal.

## O diagrama da interface

diagram-ghost-wrong-side = outra raiz de b: lado errado
diagram-ghost-wrong-bend = outro sinal de a: desvia errado
diagram-ghost-reversed = ambos os sinais errados: −T
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = meio do raio
diagram-medium-entered = meio em que entra
diagram-material-vacuum = vácuo
diagram-material-air = ar
diagram-material-water = água
diagram-material-glass = vidro
diagram-material-diamond = diamante
diagram-material-custom = personalizado
diagram-banner-tir =
    REFLEXÃO TOTAL
    k = { $k } < 0: não há raiz real para b nem raio refratado; toda a luz é refletida (θi = { $theta_i }°)
diagram-banner-toward-origin = W aponta de volta para a origem, então a = −μ
diagram-banner-along-ray = W é a direção de propagação, então a = +μ
diagram-banner-section = Seção { $section }: { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Seção 1: W aponta de volta para a origem
diagram-banner-asked-along-ray = Seção 2: W é a direção de propagação
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0: T existe
diagram-critical-angle = ângulo limite θc = { $angle }°
diagram-kernel-normal = −N: a normal que o kernel usa
diagram-outward-normal-bug =
    defeito da normal externa:
    o T da fórmula com N como dado
diagram-index-scale = índice μ
diagram-incoming-ray = raio incidente
diagram-normal-incidence = incidência normal: W, N e T estão na mesma linha
diagram-normal-incidence-asked = incidência normal: W está ao longo de N
diagram-reflected = refletido
diagram-reflected-light = refletido ({ $light })
diagram-reflected-all = raio refletido (toda a luz)
diagram-w-along-ray = W (ao longo do raio)
diagram-w-toward-origin = W (para a origem)
diagram-transmitted = T: transmitido
diagram-no-reflected-ray = { $label }: sem raio refletido

## Alças (o que um leitor de tela diz)

diagram-handle-w = Ângulo de incidência θi (W)
diagram-handle-n = Direção da normal N
diagram-handle-mu-i = Índice μi do meio do raio
diagram-handle-mu-t = Índice μt do meio em que ele entra
diagram-handle-source = alça da fonte
diagram-handle-aim = alça da direção da fonte
diagram-handle-shape = alça da forma { $number } ({ $medium })

## Lições, temas, luz, animações

diagram-lesson-air-to-glass = Ar → vidro, 40°
diagram-lesson-beyond-critical = Vidro → ar além de θc
diagram-lesson-normal-incidence = Incidência normal
diagram-lesson-brewster = Ângulo de Brewster
diagram-lesson-droplet-exit = A saída de uma gota
diagram-angle-out-of-range = θi deve ser no mínimo 0° e menor que 90°, não { $angle }°
diagram-theme-standard = Padrão
diagram-theme-black-on-white = Preto sobre branco
diagram-theme-white-on-black = Branco sobre preto
diagram-light-s = luz s
diagram-light-p = luz p
diagram-light-unpolarised = luz não polarizada
diagram-animation-mu = μ → 1: T vira W
diagram-animation-sweep = Varrer θi até rasante: surge a reflexão total
diagram-animation-wavefronts = Frentes de onda em movimento

## A tabela de candidatos

diagram-role-chosen = T (escolhido)
diagram-role-wrong-side = lado errado
diagram-role-wrong-bend = desvio errado
diagram-role-reversed = invertido
diagram-rule-wrong-side = lado errado da superfície: a outra raiz de b manda o raio de volta ao meio de onde veio
diagram-rule-wrong-bend = desvia para o lado errado: o outro sinal de a inverte a componente ao longo da superfície, então ele não se torna o raio incidente quando μ → 1
diagram-rule-reversed = ambos errados (sinal errado de a e raiz errada de b): é −T, apontando de volta para onde o raio veio

## Uma cena traçada

diagram-screen = anteparo
diagram-index-at-wavelength = n = { $index } para { $wavelength } nm
diagram-stopped-at = parado após { $count ->
        [one] { $count } segmento
       *[other] { $count } segmentos
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } chamada ao kernel
       *[other] { $count } chamadas ao kernel
    }
diagram-count-tir = { $count ->
        [one] { $count } reflexão total
       *[other] { $count } reflexões totais
    }
diagram-count-reflections = { $count ->
        [one] { $count } reflexão gerada
       *[other] { $count } reflexões geradas
    }
diagram-count-fresnel = { $count ->
        [one] { $count } avaliação de Fresnel
       *[other] { $count } avaliações de Fresnel
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } comprimento de onda
       *[other] { $count } comprimentos de onda
    }
diagram-count-source-rays = { $count ->
        [one] { $count } raio da fonte
       *[other] { $count } raios da fonte
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } salto por índice igual
       *[other] { $count } saltos por índice igual
    }
diagram-count-absorption = { $count ->
        [one] { $count } avaliação de absorção
       *[other] { $count } avaliações de absorção
    }
diagram-legend-colour = cor:
diagram-legend-white-traced = luz branca, traçada para { $wavelength } nm
diagram-legend-white-then = luz branca, depois
diagram-legend-nm = nm
diagram-legend-opacity = opacidade: intensidade
diagram-legend-hits = impactos:
diagram-hit-entering = entrando
diagram-hit-leaving = saindo (N invertida)
diagram-hit-tir = reflexão total

## Ondas

diagram-fronts =
    frentes a λ/{ $index } de distância
    velocidade c/{ $index } = { $speed } c
diagram-huygens-touch =
    Huygens: a frente chega a A Δt depois de B;
    a onda secundária de B cresce vt·Δt, a nova frente a tangencia
diagram-huygens-tir =
    Huygens: a onda secundária de B ultrapassa BA:
    não há tangente a partir de A, reflexão total

## As equações-chave

diagram-eq-toward-origin-a = W aponta para longe de T, então o artigo toma a = −μ
diagram-eq-along-ray-a = W aponta no sentido de T, então o artigo toma a = +μ
diagram-eq-no-refracted-ray = não há (a, b) real: não há raio refratado
diagram-eq-no-b-with-10 = nenhum b real a satisfaz junto com a eq. 10
diagram-eq-so = { $given }, então { $then }
diagram-eq-negative-root = √({ $k }) de um número negativo: não há b real (reflexão total)
diagram-eq-or = ou
diagram-eq-outward-normal-bug = com N como dada, b = { $b }: a raiz errada, T volta para trás (o defeito da normal externa); o kernel usa −N e obtém b = { $kernel_b } para N
diagram-step-wn-flipped = W·N = { $given }: N aponta para longe do raio, então o kernel usa −N: wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = nenhuma raiz real para escolher
diagram-eq-no-theta-t = { $given }, então senθt seria { $sin_t } > 1: não existe ângulo θt
diagram-eq-with-chosen = { $lhs } = { $rhs } com o (a, b) escolhido
diagram-eq-no-ab-with-12 = nenhum (a, b) real a satisfaz junto com a eq. 12
# O nome do seno nas fórmulas do passo a passo, como as escolas da língua o escrevem.
diagram-math-sin = sen

## Passo a passo

diagram-step-snell = Lei de Snell
diagram-step-snell-text = O raio desvia de modo que μi·senθi = μt·senθt; com μ = μi/μt, o seno do ângulo no novo meio é μ vezes o anterior.
diagram-step-square = Elevar ao quadrado e usar cossenos
diagram-step-square-text = Elevar ao quadrado permite que os cossenos (produtos escalares) substituam os senos, mas também deixa entrar soluções falsas: uma solução e sua oposta com sinal trocado satisfazem ambas.
diagram-step-decomposition = T como a·W + b·N
diagram-step-decomposition-text = T está no plano de W e N, então é a·W + b·N; os cossenos viram produtos escalares com wn = W·N, e cosθt = −a·wn − b. O raio se propaga ao longo de { $travel }.
diagram-step-constraints = As duas restrições ao quadrado
diagram-step-constraints-text = Snell ao quadrado (eq. 10) e o comprimento unitário (eq. 12) são duas equações quadráticas em a e b. Quatro pares (a, b) satisfazem ambas: T e os três fantasmas. Nada nelas distingue os quatro.
diagram-step-roots-a = As duas raízes de a
diagram-step-roots-a-text = Substituir a eq. 12 na eq. 10 deixa a² = μ²: a = +μ ou a = −μ. O outro sinal espelha T em relação à normal: desvia para o lado errado.
diagram-step-choice-a = Escolher a: o limite μ = 1
# “Animar μ até 1” é o nome do botão na janela.
diagram-step-choice-a-text = Quando μ = 1 nada desvia, então T deve ser a direção de propagação, { $travel }. Só a = { $a } dá isso; o outro sinal daria a imagem espelhada. Pressione “Animar μ até 1” para ver T convergir para { $travel } e os fantasmas não.
diagram-step-choice-a-typo = (O texto da seção 2 diz em seguida “once we decide upon using the a = −μ solution”: quer dizer a = +μ, a que escolheu.)
diagram-step-roots-b = As duas raízes de b
diagram-step-roots-b-text = Com a fixo, a eq. 12 é quadrática em b com as raízes −a·wn ± √k (k = μ²wn² − μ² + 1). A outra raiz espelha T em relação à superfície, de volta ao meio de onde o raio veio. k < 0 significa que não há raiz real: reflexão total.
diagram-step-choice-b = Escolher b
diagram-step-choice-b-text = Das duas raízes, só a com −√k se torna b = 0 em μ = 1, quando T deve ser o raio incidente inalterado; a outra manda T de volta através da superfície.
diagram-step-choice-b-flipped = A raiz com −√k tende a b = 0 em μ = 1, então T se torna o raio incidente. Mas aqui N aponta no sentido do raio (uma normal externa onde o raio sai do meio): com N como dada, essa raiz está do lado errado. O kernel inverte N primeiro.

## A vista de Fresnel

diagram-fresnel-title = Quanta luz é refletida, de μi = { $mu_i } para μt = { $mu_t }
diagram-fresnel-axis = ângulo de incidência θi
diagram-fresnel-brewster = ângulo de Brewster θB = { $angle }°: nenhuma luz p refletida
diagram-fresnel-critical = ângulo limite θc = { $angle }°: além dele, tudo é refletido
diagram-fresnel-brewster-short = ângulo de Brewster θB = { $angle }°
diagram-fresnel-critical-short = ângulo limite θc = { $angle }°
diagram-curve-rs = Rs (luz s refletida)
diagram-curve-rp = Rp (luz p refletida)
diagram-curve-r = R (não polarizada, refletida)
diagram-curve-t = T (não polarizada, transmitida)
diagram-fresnel-source =
    Equações de Fresnel para a potência refletida (Hecht, Óptica, cap. 4): Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    a partir dos próprios cosθi e cosθt do kernel, sem trigonometria; a luz não polarizada é a média de s e p. Além do ângulo limite toda a luz é refletida.

## O gráfico de precisão

diagram-accuracy-title = Precisão em função do tempo nesta máquina
diagram-accuracy-error-axis = maior erro do conjunto difícil, em ε·κ (log)
diagram-accuracy-time-axis = tempo por raio, ns (log)
diagram-accuracy-bound = o limite do kernel padrão, 32 ε·κ
diagram-accuracy-markers = vazado: f32, cheio: f64

## As cenas embutidas (títulos, descrições e os nomes de seus meios)

diagram-scene-dispersing-prism = Prisma dispersivo
diagram-scene-dispersing-prism-about = Luz branca através de um prisma equilátero de vidro flint F2 perto do desvio mínimo: o violeta desvia mais.
diagram-scene-droplet = Gota d’água (arco-íris)
diagram-scene-droplet-about = A luz branca entra numa gota, reflete dentro dela e sai; a dispersão abre o arco-íris primário perto de 138 graus de desvio.
diagram-scene-fibre = Fibra óptica
diagram-scene-fibre-about = A reflexão total repetida guia a luz ao longo do núcleo; os raios mais inclinados escapam para a casca.
diagram-scene-interface = Uma interface
diagram-scene-interface-about = Um raio no ar atinge um vidro plano (n = 1,5) a 45 graus e se aproxima da normal.
diagram-scene-lens = Lente convergente
diagram-scene-lens-about = Uma lente biconvexa de BK7 foca um feixe paralelo num anteparo; os raios marginais convergem antes dele.
diagram-scene-right-angle-prism = Prisma de ângulo reto
diagram-scene-right-angle-prism-about = A reflexão total na hipotenusa desvia o feixe em 90 graus.
diagram-scene-slab = Lâmina de vidro
diagram-scene-slab-about = Faces paralelas: o raio que sai é paralelo ao que entra, deslocado para o lado. Perdas de Fresnel nas duas faces, absorção no interior.
diagram-medium-core = núcleo
diagram-medium-cladding = casca
diagram-medium-f2 = flint F2
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = BK7 tingido
