## Acessibilidade: o que um leitor de tela diz do explorador, os botões ao lado do diagrama e os controles da própria página em um navegador

access-degrees = { $angle }°
access-normal-up = para cima
access-normal-down = para baixo
access-normal-right = { $angle }° à direita da vertical
access-normal-left = { $angle }° à esquerda da vertical
access-index-named = { $index } ({ $name })
access-media = O raio se propaga no primeiro meio ({ $from }) e chega ao segundo ({ $to }).
access-medium-named = { $name }, { $symbol } = { $index }
access-medium-custom = { $symbol } = { $index }
access-incidence-sentence = Ele atinge a superfície com θi = { $angle }° em relação à normal.
access-incidence-along-normal = Ele atinge a superfície ao longo da normal: θi = 0°.
access-normal-sentence = Direção da normal N: { $direction }.
access-tir = Reflexão total: θi passa do ângulo limite θc = { $critical }°, então não há raio refratado e toda a luz é refletida.
access-t-along-normal = O T segue reto ao longo da normal: não se desvia.
access-t-straight = O T segue reto, a { $angle }° da normal: não se desvia.
access-t-toward = O T se desvia em direção à normal, a { $angle }° dela.
access-t-away = O T se desvia afastando-se da normal, a { $angle }° dela.
access-reflected = O raio refletido sai a { $angle }° da normal, do outro lado dela.
access-critical = O ângulo limite é θc = { $critical }°.
access-flipped = N aponta para longe do raio incidente, então o kernel usa −N.
access-sentence = { $text }.
access-change-value = { $name } { $before } → { $after }
access-change = { $changes }: { $outcome }.
access-change-tir-begins = agora passa do ângulo limite { $critical }°; toda a luz é refletida
access-change-tir-ends = agora fica abaixo do ângulo limite { $critical }°; o T sai a { $angle }° da normal
access-change-t = o T a { $angle }° da normal
access-step = Passo { $number } de { $count }: { $title }.
access-question = Pergunta: { $question }
access-view = Visão: { $view }.
access-scene = Cena: { $title }.
access-scene-hidden = Os raios dela são desenhados até a primeira superfície que encontram.
access-incidence-decrease = Diminuir θi em 1°
access-incidence-increase = Aumentar θi em 1°
access-normal-turn-left = Girar N 1° para a esquerda
access-normal-turn-right = Girar N 1° para a direita
access-index-decrease = Diminuir { $symbol } em { $step }
access-index-increase = Aumentar { $symbol } em { $step }
access-page-controls = Os controles do diagrama
access-page-keys = No explorador abaixo, Tab percorre os botões e campos e as setas giram a alça selecionada; Esc e depois Shift+Tab volta a estes controles.
access-page-typing = Texto digitado no explorador
access-title-scene = { $view }: { $scene }
