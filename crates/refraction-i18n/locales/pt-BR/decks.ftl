## Sequências didáticas: a ferramenta que monta uma, a faixa que mostra sua etapa, a janela
## de notas, a apostila e os títulos, perguntas e notas das sequências incluídas

tool-deck = Sequência didática
deck-answer-hidden = A resposta está oculta: primeiro preveja, depois revele

## A ferramenta

deck-title-field = Título da sequência
deck-file = Arquivo da sequência
deck-open-file = Abrir arquivo
deck-save-file = Salvar arquivo
deck-open-dialog-hover = Escolha um arquivo de sequência para abrir
deck-built-in = Sequências incluídas
deck-new = Nova sequência
deck-new-hover = Comece uma sequência vazia; a mostrada é fechada (salve-a antes)
deck-add-step = Adicionar o estado atual como etapa
deck-add-step-hover = Uma nova etapa depois da mostrada, com o diagrama como está agora: W, N, os índices, a vista, sua cena, a ferramenta aberta e os efeitos
deck-update-step = Manter o estado atual nesta etapa
deck-update-step-hover = Arrastar durante uma etapa só muda o diagrama; isto mantém na etapa o que ele mostra agora (salve a sequência para mantê-lo no arquivo)
deck-steps = Etapas
deck-no-steps = Ainda não há etapas: prepare o diagrama e adicione-o como etapa.
# $number é o número da etapa, $title seu título
deck-step-row = { $number }. { $title }
deck-move-up = Subir a etapa
deck-move-down = Descer a etapa
deck-delete = Apagar a etapa
deck-step-title = Título
deck-step-question = Pergunta para a turma
deck-step-question-hint = nenhuma: a resposta aparece logo
deck-step-notes = Notas para o professor
deck-untitled = Etapa { $number }
deck-edited = alterada desde que foi salva
deck-saved = { $path } salvo
deck-opened = { $path } aberto
deck-not-saved = não salvo: { $reason }
deck-nothing-to-save = A sequência não tem etapa para salvar: adicione uma antes.

## Percorrer uma sequência

# $number é a etapa mostrada, $count as etapas da sequência: “2 / 5”
deck-step-number = { $number } / { $count }
deck-previous = Etapa anterior
deck-next = Próxima etapa
deck-reveal = Revelar a resposta
deck-hide = Ocultar a resposta
deck-notes-window = Janela de notas
deck-notes-window-hover = As notas do professor numa janela própria, para o monitor do notebook enquanto o projetor mostra o diagrama
deck-keys = Page Down, → ou espaço: próxima etapa · Page Up ou ←: anterior · R: revelar a resposta · N: janela de notas
deck-hidden-hint = R revela a resposta
deck-shown-hint = R oculta a resposta de novo
# $title é o título da sequência
deck-notes-title = Notas: { $title }
deck-notes-none = Sem notas para esta etapa.
# $title é o título da próxima etapa
deck-notes-next = Próxima: { $title }
deck-notes-last = Esta é a última etapa.

## A apostila (render --lesson … --out handout.pdf)

deck-handout-question = Pergunta
deck-handout-notes = Notas

## Sequência incluída: a lei de Snell em dez minutos

deck-snell-title = A lei de Snell em dez minutos
deck-snell-1-title = Do ar para o vidro
deck-snell-1-question = O raio passa do ar para o vidro. Ele se desvia para perto da normal ou para longe dela?
deck-snell-1-notes = Para perto da normal: θt é menor que θi, porque o vidro é o meio mais refringente. Arraste W devagar de 0° a 80° e deixe a turma ler os dois ângulos.
deck-snell-2-title = Direto pela normal
deck-snell-2-question = Um raio chega à superfície ao longo da normal. Para que lado ele se desvia?
deck-snell-2-notes = Não se desvia: θi = θt = 0 para qualquer par de meios. A luz só fica mais lenta no vidro.
deck-snell-3-title = A lei de Snell
deck-snell-3-notes = A primeira etapa de “Passo a passo”: μi sen θi = μt sen θt. Peça a dois alunos que leiam θi e θt e calculem os dois lados; eles coincidem até o último algarismo mostrado.
deck-snell-4-title = Do vidro para o ar
deck-snell-4-question = Agora o raio sai do vidro. Para que lado ele se desvia?
deck-snell-4-notes = Para longe da normal: θt é maior que θi. Aumente θi e o T gira em direção à superfície: o ângulo limite da próxima aula.
deck-snell-5-title = Através de uma lâmina de vidro
deck-snell-5-question = O raio atravessa uma lâmina de faces paralelas. Em que direção ele sai?
deck-snell-5-notes = Paralelo ao raio que chega, deslocado para o lado: a segunda refração desfaz a primeira. Arraste a fonte para mostrar que o deslocamento cresce com o ângulo.

## Sequência incluída: a reflexão total e a fibra

deck-tir-title = A reflexão total e a fibra
deck-tir-1-title = Saindo do vidro
deck-tir-1-question = O raio passa do vidro para o ar. O que acontece com o T e com o raio refletido quando θi cresce?
deck-tir-1-notes = O T gira em direção à superfície e enfraquece enquanto o raio refletido fica mais forte: Intensidades desenha cada raio pela sua parte da luz.
deck-tir-2-title = Logo antes do ângulo limite
deck-tir-2-question = Com que ângulo o T ficará ao longo da superfície?
deck-tir-2-notes = Com o ângulo limite: sen θc = μt/μi, 41,8° do vidro para o ar. A 41° o T quase rasa a superfície; o botão “Ajustar W a θc” coloca W exatamente ali.
deck-tir-3-title = Além do ângulo limite
deck-tir-3-question = W está a 45°, além de 41,8°. Para onde vai a luz?
deck-tir-3-notes = Toda ela é refletida: reflexão total. O kernel não encontra T, então também não há candidato rejeitado; a faixa de cima diz isso.
deck-tir-4-title = Da água para o ar
deck-tir-4-question = O ângulo limite da água é maior ou menor que o do vidro?
deck-tir-4-notes = Maior: arcsen(1/1,333) = 48,6°, porque a água é menos refringente que o vidro. A 50° o raio fica preso; um mergulhador só vê o céu dentro de um cone de 48,6°.
deck-tir-5-title = A fibra
deck-tir-5-question = A luz entra pela ponta da fibra. Ela escapa pela lateral?
deck-tir-5-notes = Não: cada impacto na lateral da fibra está além do ângulo limite, então o raio é totalmente refletido a cada vez e guiado ao longo da fibra. Gire a fonte até a luz escapar.
deck-tir-6-title = O prisma como espelho
deck-tir-6-question = Por que um prisma de ângulo reto reflete como um espelho?
deck-tir-6-notes = Dentro, o raio atinge a face longa a 45°, além do ângulo limite do vidro do prisma (41,3°): é totalmente refletido e quase não perde luz; por isso os binóculos usam prismas.

## Sequência incluída: Fresnel e Brewster

deck-fresnel-title = Fresnel e Brewster
deck-fresnel-1-title = Quanta luz é refletida?
deck-fresnel-1-question = A 40° do ar para o vidro, que parte da luz é refletida?
deck-fresnel-1-notes = Cerca de 5 % (4 % na incidência normal): o resto segue como T. O gráfico de Fresnel mostra R e T em função de θi, com o θi do diagrama marcado.
deck-fresnel-2-title = Perto da incidência rasante
deck-fresnel-2-question = A 80°, a reflexão é mais fraca ou mais forte que a 40°?
deck-fresnel-2-notes = Muito mais forte: sobe para perto de 100 % na incidência rasante; por isso um lago reflete a margem distante, mas não o céu logo acima.
deck-fresnel-3-title = O ângulo de Brewster
deck-fresnel-3-question = Luz p chega ao vidro a 56,3°. Quanto dela é refletido?
deck-fresnel-3-notes = Nada: no ângulo de Brewster, tg θB = μt/μi, os raios refletido e refratado formam um ângulo reto e a luz p não é refletida. Os óculos de sol polarizados aproveitam isso.
deck-fresnel-4-title = Luz s no mesmo ângulo
deck-fresnel-4-notes = A luz s ainda é refletida, cerca de 15 %: a luz refletida é parcialmente polarizada, sobretudo no ângulo de Brewster.
deck-fresnel-5-title = Reflexões numa lâmina
deck-fresnel-5-question = Quantos raios saem de uma lâmina de vidro quando cada superfície reflete um pouco?
deck-fresnel-5-notes = Cada impacto gera um raio refletido, cada vez mais fraco: dois raios fortes e depois uma fileira de fracos. As intensidades caem a cada reflexão.

## Sequência incluída: convenções de sinal para traçadores de raios

deck-signs-title = Convenções de sinal para traçadores de raios
deck-signs-1-title = Os quatro candidatos
deck-signs-1-question = Elevar as equações ao quadrado deixa entrar quatro soluções. Qual delas é o T?
deck-signs-1-notes = Os três fantasmas quebram uma regra cada: o lado errado (a outra raiz para b), o desvio errado (o outro sinal de a) e invertido (os dois). Só o T fica do outro lado e se desvia do jeito certo.
deck-signs-2-title = Saindo de uma gota
deck-signs-2-question = O raio sai de uma gota, e N aponta para fora da gota, ao longo do raio. O que o código deve fazer com N?
deck-signs-2-notes = Invertê-la: o kernel precisa da normal voltada para o raio. O raio de alerta tracejado é a fórmula com N como foi dada: o erro de um renderizador que esquece de invertê-la.
deck-signs-3-title = Seção 1: W de volta para a origem
deck-signs-3-question = Aqui W aponta de volta para de onde o raio veio. Que sinal da fórmula muda?
deck-signs-3-notes = O sinal de a: a = −μ na seção 1, +μ na seção 2. pbrt e Mitsuba passam wi assim; misturar as duas convenções dá o desvio errado.
deck-signs-4-title = Seção 2: W ao longo do raio
deck-signs-4-notes = O mesmo raio com W ao longo dele, como GLSL, glam e o livro o passam: a = +μ, e o T é o mesmo vetor da seção 1.
deck-signs-5-title = Três erros numa chamada de API
deck-signs-5-question = O T de um renderizador está errado. Quais três erros na chamada a refract os alunos mais cometem?
deck-signs-5-notes = A razão invertida (μt/μi em vez de μi/μt), o vetor incidente na outra convenção e a normal externa onde o raio sai. Cole uma chamada registrada em “Verificar meu T”: ele nomeia o erro e sua correção.
