# check.ftl (pt-BR): os textos de “Verificar meu T”: o painel, seus veredictos e suas explicações.

## Números e vetores nas explicações

check-number-not-finite = não finito (NaN ou infinito)
check-vector-not-finite = um vetor não finito (componentes NaN ou infinitas)

## Veredictos sobre um T nos campos deste projeto (também as explicações do comando `check`)

check-verdict-wrong-side = Seu T volta para o meio de onde o raio veio: é a outra raiz para b (+ onde a raiz quadrada pede -). A causa comum é uma normal que aponta no sentido do raio, como a normal externa de uma esfera onde o raio sai dela, usada sem ser invertida.
check-verdict-wrong-bend = Seu T se desvia para o lado errado: o sinal de a está trocado, então ele não se tornaria o raio incidente quando μ → 1. A causa comum é misturar as convenções: W apontando de volta para a origem (Seção 1, a = −μ) usado na fórmula de W ao longo do raio (Seção 2, a = +μ), ou o contrário.
check-verdict-reversed = Seu T é -T e aponta de volta para onde o raio veio: os dois sinais estão errados. A causa comum é devolver a direção para a origem em vez da direção de propagação, ou negar W duas vezes.
check-verdict-not-finite-tir = Seu T tem componentes NaN ou infinitas. Este raio sofre reflexão total (k < 0): seu código tirou a raiz quadrada de um k negativo em vez de testar k antes.
check-verdict-not-finite-refracts = Seu T tem componentes NaN ou infinitas, embora este raio seja refratado normalmente (k ≥ 0): procure uma divisão por zero ou um vetor não inicializado.
check-verdict-tir-right = Certo: este raio sofre reflexão total (k < 0) e seu código devolveu a reflexão (ou o vetor nulo com que o GLSL indica isso).
check-verdict-tir-but-refracted = Este raio sofre reflexão total (k = { $k } < 0): não há raio refratado, mas seu código devolveu um. Teste k antes de tirar a raiz quadrada.
check-verdict-zero-vector = Seu T é o vetor nulo, que o GLSL devolve na reflexão total, mas este raio é refratado (k ≥ 0). Verifique o sinal de k e a razão dos índices.
check-verdict-not-unit = Além disso, seu T tem comprimento { $length }, não 1: normalize W e N antes de refratar (a fórmula supõe vetores unitários) ou T depois.
check-verdict-along-refracted = Seu T aponta ao longo do raio refratado (com até { $off } rad de diferença).
check-verdict-right = Certo: seu T é o raio refratado (com até { $off } rad de diferença).
check-verdict-ratio-upside-down = Seu T é a refração com a razão dos índices invertida: μ deve ser μi/μt (o meio que o raio deixa sobre aquele em que entra), e seu código usou μt/μi.
check-verdict-out-of-plane = Seu T sai do plano de incidência (o plano de W e N) por { $off } rad: T deve ser uma combinação a·W + b·N dos dois.
check-verdict-no-candidate = Seu T não corresponde a nenhuma das quatro escolhas de sinal: está a { $degrees } graus do raio refratado. Verifique μ e para onde apontam W e N.

## Leitura de t_yours numa linha JSON

check-t-yours-item-not-number = `t_yours[{ $index }]` deve ser um número ou null
check-t-yours-missing = falta o campo `t_yours` (o T que seu código produziu)

## Explicações de um veredicto sobre uma chamada de API (`check --api` e o painel): como cada API fala

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] livro
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] refract(I, N, eta) do GLSL
    [pbrt] Refract(wi, n, eta) do pbrt
    [rtiow] refract(uv, n, etai_over_etat) do livro
   *[mitsuba] fresnel(cos_theta_i, eta) do Mitsuba com refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, o índice do meio que o raio deixa sobre o do meio em que entra
    [pbrt] o índice do lado oposto a n sobre o índice do lado para onde n aponta (n_inside/n_outside com a normal externa)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index numa face frontal, refraction_index numa face traseira)
   *[mitsuba] int_ior/ext_ior, o índice do lado oposto à normal sobre o índice do lado para onde ela aponta
}
check-api-incident-means = { $api ->
    [glsl] a direção em que o raio viaja, em direção à superfície
    [pbrt] a direção de volta para onde o raio veio (-ray.d)
    [rtiow] a direção unitária em que o raio viaja (unit_vector(r_in.direction()))
   *[mitsuba] wi, afastando-se da superfície de volta ao longo do raio (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] o GLSL subtrai (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt usa (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel é -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] cos_theta_t tem o sinal oposto ao de cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] a normal externa com o eta do material (n_inside/n_outside)
    [mitsuba] a normal externa com eta = int_ior/ext_ior
   *[other] {""}
}

## Explicações de uma chamada de API: as peças

check-situation-entering = entrando no objeto (de n = { $from } para n = { $to })
check-situation-leaving = saindo do objeto (de n = { $from } para n = { $to })
check-situation-going = indo de n = { $from } para n = { $to }
check-nothing-zero-vector = o vetor nulo
check-nothing-reflection = a reflexão
check-nothing-false-or-null = nada (false ou null)
check-and = e
check-or = ou
check-field-from-and-to = from e to (ou entering com --inside e --outside)
check-normal-fix-rtiow = a normal do registro de interseção depois de set_face_normal
check-normal-fix-facing = a normal invertida onde quer que esse produto escalar seja positivo
check-normal-inward-entering = ela aponta para dentro do objeto, e o raio está entrando
check-normal-inward-leaving = ela aponta para dentro do objeto, e o raio está saindo
check-looks-other-root = a outra raiz, com o sinal da raiz quadrada trocado ({ $hint })
check-looks-wrong-bend = a parte ao longo da superfície invertida
check-looks-reversed = o oposto da resposta da API
check-looks-length = a mesma direção com { $ratio } vezes o comprimento: seu código escala ou normaliza de outro jeito
check-looks-reflection = a reflexão, embora este raio seja refratado (registre só a refração, não uma reflexão escolhida por Fresnel ou Schlick)
check-looks-variant = o que { $call } devolve com { $variant }: sua implementação faz isso por dentro
check-variant-eta-inverted = eta invertido
check-variant-normal-flipped = a normal invertida
check-variant-incident-reversed = o vetor incidente ao contrário
check-looks-nothing = { $what }, que indica que nada é transmitido, embora este raio seja refratado (k = { $k } ≥ 0)
check-looks-not-finite = componentes NaN ou infinitas, embora este raio seja refratado
check-looks-off = a { $degrees } graus dela
check-looks-off-unmeasurable = a um ângulo que não se pode medir
check-returned-pbrt-true = true com wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter reflete)
check-returned-mitsuba-reflects = F = 1 (a BSDF sempre reflete)
check-unchecked-mu = from e to (ou entering com --inside e --outside) para verificar { $eta }
check-unchecked-travel = travel para verificar para onde { $incident } aponta

## Explicações de uma chamada de API: as frases

check-eta-inverted = No { $owner }, { $eta } é { $means }: você passou { $value } para um raio { $situation }; passe 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = No { $owner }, { $eta } é { $means }: você passou { $value } para este raio; passe 1/{ $value } = { $inverse }.
check-incident-reversed = No { $owner }, { $incident } é { $means }; o seu aponta para o outro lado: passe -{ $incident } = { $reversed }.
check-incident-reversed-travel = No { $owner }, { $incident } é { $means }; o seu aponta para o outro lado (o raio viaja ao longo de { $travel }): passe -{ $incident } = { $reversed }.
check-not-unit-input = { $call } supõe { $incident } e { $normal } unitários e não os normaliza: |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length }; normalize-os antes.
check-normal-against = { $call } precisa de { $normal } oposta a { $incident } (dot({ $normal }, { $incident }) < 0) e não a inverte; a sua tem dot({ $normal }, { $incident }) = { $dot }, como uma normal externa onde o raio sai do objeto: passe -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } aceita { $normal } de qualquer lado, mas { $eta } deve combinar com ela: é { $means }. Sua { $normal } aponta para o lado oposto daquela para a qual { $eta } = { $value } foi pensado{ $inward }; passe -{ $normal } = { $flipped } com o mesmo { $eta } (ou mantenha { $normal } e passe 1/{ $eta }).
check-tir-glsl = O refract do GLSL devolve aqui o vetor nulo (k = { $k } < 0: reflexão total); teste isso e reflita em vez de refratar.
check-tir-pbrt = O Refract do pbrt devolve aqui false (sin2Theta_t = { $sin2 } >= 1: reflexão total); reflita em vez de refratar.
check-tir-rtiow = Aqui vale o cannot_refract de dielectric::scatter (ri * sin_theta = { $sine } > 1): o livro reflete em vez de chamar refract.
check-tir-mitsuba = fresnel devolve aqui F = 1 (cos_theta_t_sqr = { $k } < 0): o Mitsuba sempre reflete.
check-tir-got-formula = Seu código usou mesmo assim o vetor da fórmula, { $vector } de comprimento { $length }: não é um raio.
check-tir-got-direction = Seu código deu uma direção, { $vector }, onde não há nenhuma.
check-tir-got-not-finite = Seu código deu componentes NaN ou infinitas (a raiz quadrada de um k negativo, ou normalize() do vetor nulo).
check-result-differs = { $call } devolve { $returned } para estes argumentos, mas a chamada deu { $got }: { $detail }. Sua própria implementação difere da da API.
check-ties-no-field = Nenhum campo de referência os distingue: { $call } lê os dois igualmente; a chamada usual passa { $usual }.
check-ties-give = Informe { $fields } para distingui-los.
check-ties = Igualmente possível: { $readings } em vez disso. { $hint }
check-unchecked = Verificado só pelas regras da própria API: informe { $missing }.
check-unexplained-travel = O { $incident } registrado está a { $degrees } graus da direção { $travel } deste raio: não é a direção deste raio (nem a oposta).
check-unexplained-eta = { $eta } = { $value } não corresponde nem a n_from/n_to = { $mu } nem ao seu inverso do jeito que { $call } o lê: estes não são os índices desta interface.
check-unexplained = Nenhuma combinação de erros nos argumentos faz esta chamada corresponder à referência dada.
check-right-tir = Certo: { $call } indica aqui reflexão total ({ $returned }), e a chamada deu { $what }.
check-right-for-ray = Certo: { $call } devolve { $returned } para estes argumentos, para um raio { $situation }.
check-right = Certo: { $call } devolve { $returned } para estes argumentos.

## Os erros de uma chamada de API, um por linha

check-mistake-eta-inverted = a razão dos índices invertida para a convenção desta API
check-mistake-incident-reversed = o vetor incidente passado ao contrário
check-mistake-normal-not-facing = a normal do lado errado para esta API (ou para o eta passado)
check-mistake-not-the-api-result = o resultado não é o que a API devolve para estes argumentos: sua própria implementação difere
check-mistake-missed-tir = uma direção (ou NaN) onde a API indica reflexão total
check-mistake-not-unit-input = o vetor incidente ou a normal não tem comprimento unitário

## O painel: os campos deste projeto

check-source-own = W, N, μ (este projeto)
check-code-calls = Seu código chama:
check-convention = Convenção:
check-convention-along-ray = Seção 2: W ao longo do raio
check-convention-along-ray-about = W é a direção em que o raio viaja, em direção à superfície (o I do GLSL, o uv do livro).
check-convention-toward-origin = Seção 1: W para a origem
check-convention-toward-origin-about = W aponta de volta para onde o raio veio (o wi do pbrt e do Mitsuba).
check-convention-note = { $about } μ = μi/μt; N de qualquer lado (o kernel a vira para o raio).
check-paste-hint = Cole o que seu traçador de raios registrou. Vetores como 0.1, -0.9, 0 ou [0.1,-0.9,0] ou vec3(0.1, -0.9, 0.0); ou cole uma linha JSON inteira com t_yours em “Seu T”.
check-use-current-case = Usar o caso atual
check-use-current-case-own-hover = Preencher W, N, μ e a convenção a partir do explorador
check-use-current-case-api-hover = Preencher os argumentos e os índices a partir do explorador
check-your-t = Seu T
check-your-t-in-error = seu T
check-button = Verificar
check-field-not-number = { $field }: “{ $text }” não é um número
check-student-own = seu T: { $verdict }
check-headline-own = Seu T corresponde a: { $verdict }
check-match-refracted = o raio refratado T
check-match-not-unit = a direção de T, mas sem comprimento unitário
check-match-wrong-side = lado errado (a outra raiz para b)
check-match-wrong-bend = desvio errado (o outro sinal de a)
check-match-reversed = invertido (−T: os dois sinais errados)
check-match-tir = reflexão total, respondida corretamente
check-match-none = nenhum dos quatro candidatos
check-no-refracted-ray = Não há raio refratado: reflexão total.
check-right-t = O T correto = { $t }
check-copy-right-t = Copiar T
check-not-drawn-changed = (O caso mudou desde então: o veredicto não é desenhado.)

## O painel: uma chamada de API

check-drawn-incident = { $api ->
    [glsl] I (direção de propagação)
    [pbrt] wi (de volta para a origem)
    [rtiow] uv (direção de propagação)
   *[mitsuba] wi (afastando-se da superfície)
}
check-drawn-about = { $api ->
    [glsl] I é a direção em que o raio viaja, desenhada como W ao longo do raio (Seção 2). N deve ficar oposta a I: o GLSL não a vira. eta = n_from/n_to = μi/μt. O vetor nulo significa reflexão total.
    [pbrt] wi aponta de volta para onde o raio veio (−ray.d), desenhado como W para a origem (Seção 1). n pode ficar de qualquer lado: o pbrt a inverte e inverte eta quando wi está abaixo dela. eta = o índice atrás de n sobre o da frente (μt/μi com n voltada para wi). false significa reflexão total.
    [rtiow] uv é a direção unitária em que o raio viaja, desenhada como W ao longo do raio (Seção 2). n deve ficar oposta a uv (front_face). etai_over_etat = n_from/n_to = μi/μt. refract não testa a reflexão total: quem reflete é o cannot_refract de quem chama.
   *[mitsuba] wi se afasta da superfície, de volta ao longo do raio, desenhado como W para a origem (Seção 1). n é +z (o referencial local) quando fica vazio. eta = int_ior/ext_ior, o índice atrás de n sobre o da frente (μt/μi com n voltada para wi). F = 1 significa reflexão total: wo é null.
}
check-convention-about = Convenção: { $about }
check-your-call = Sua chamada
check-truth = Referência (opcional)
check-picture-outside = μ = { $mu } exige índices fora da faixa { $low }…{ $high } do explorador
check-student-api = seu { $result }: { $verdict }
check-student-right = certo
check-student-wrong = errado
check-api-right-headline = Certo: o que { $signature } significa para este raio
check-api-mistakes = Erros: { $codes }
check-api-unexplained-headline = Nenhum erro isolado explica isto
check-api-returns = Resultado no { $owner }: { $value }
check-api-drawn = Desenhado: a chamada correta, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = Não desenhado: { $why }.
check-copy-as-test = Copiar como teste unitário:

## O painel: linhas de log coladas

check-paste-lines = 📋 Colar linhas de log
check-pattern = Padrão
check-log-lines = Linhas de log
check-lines-button = Verificar as linhas
check-read-as-pattern = o padrão
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (a primeira linha é o cabeçalho)
check-bulk-summary = Lido como { $read_as }: { $count ->
    [one] { $count } chamada
   *[other] { $count } chamadas
}
check-bulk-left-out = { $count ->
    [one] { $count } linha depois das primeiras { $first } ficou de fora
   *[other] { $count } linhas depois das primeiras { $first } ficaram de fora
}
check-column-line = linha
check-column-ok = ok
check-column-mistakes = erros
check-column-explanation = explicação
check-row-line = linha { $line }
check-row-open-hover = Abrir esta chamada no painel e no diagrama
check-row-error = erro

## Leitura dos campos de uma chamada, de uma linha CSV, de um padrão e de um vetor (o painel também mostra estas mensagens)

check-field-not-three = `{ $field }` deve ter exatamente 3 números, tem { $count }
check-field-not-a-vector = `{ $field }` deve ser um array de 3 números ou um texto como “0.1, -0.9, 0”
check-field-not-flag-got = `{ $field }` deve ser true/false ou 1/0, não “{ $text }”
check-field-not-number-json = `{ $field }` deve ser um número
check-field-not-flag = `{ $field }` deve ser true/false ou 1/0
check-field-not-label = `{ $field }` deve ser um texto ou um número
check-json-not-object = esperava-se um objeto JSON com os campos { $fields }
check-unknown-field = campo desconhecido `{ $field }`
check-field-not-vector = `{ $field }` deve ser 3 números
check-field-missing = falta o campo `{ $field }` ({ $what })
check-what-normal = a normal à superfície
check-what-incident = o vetor incidente
check-what-eta = a razão dos índices
check-field-not-finite = `{ $field }` deve ser finito, é { $value }
check-field-zero-vector = `{ $field }` é o vetor nulo
check-field-not-positive = `{ $field }` deve ser um número finito > 0, é { $value }
check-from-and-to-together = `from` e `to` andam juntos: informe os dois ou nenhum
check-travel-not-finite = `travel` deve ser um vetor finito não nulo
check-result-null = `{ $field }` é null, embora `{ $returned }` seja true
check-result-missing = falta o campo `{ $field }` (o que a chamada devolveu{ $api ->
    [pbrt] , ou "returned": false
    [mitsuba] , null quando refletiu
   *[other] {""}
})
check-unknown-precision = precisão desconhecida “{ $text }”: esperava-se "f32" ou "f64"
check-too-large = { $value } é grande demais para { $precision }
check-csv-unclosed-quote = aspas não fechadas na linha CSV
check-csv-no-column = o cabeçalho CSV não tem a coluna `{ $field }`: ele nomeia { $names }; esperava-se { $expected }
check-csv-partial-vector = o cabeçalho CSV tem só { $count } das 3 componentes de `{ $field }`
check-csv-duplicate-column = o cabeçalho CSV nomeia `{ $column }` mais de uma vez
check-csv-cells = { $count ->
    [one] { $count } célula
   *[other] { $count } células
} onde o cabeçalho tem { $columns ->
    [one] { $columns } coluna
   *[other] { $columns } colunas
}
check-csv-no-header = nenhum cabeçalho CSV utilizável: { $reason }
check-pattern-unclosed = `{"{"}` não fechado no padrão “{ $pattern }”
check-pattern-adjacent = dois campos sem nada entre eles no padrão “{ $pattern }”
check-pattern-twice = o campo {"{"}{ $field }{"}"} aparece duas vezes no padrão “{ $pattern }”: nomeie cada campo uma vez
check-pattern-too-many = o padrão tem { $count } marcadores: no máximo { $limit } são lidos
check-pattern-too-long = o padrão tem { $bytes } bytes: no máximo { $limit } são lidos
check-pattern-no-field = o padrão “{ $pattern }” não nomeia nenhum campo
check-pattern-unknown-field = campo desconhecido {"{"}{ $field }{"}"} no padrão para --api { $api }: esperava-se {"{"}_{"}"} ou um de { $expected }
check-line-not-matching = a linha não corresponde ao padrão
check-tally-skipped = ignoradas (não correspondem ao padrão)
check-tally-unreadable = ilegíveis
check-tally-unexplained = sem explicação
check-word-not-a-number = “{ $word }” não é um número
check-vector-expected-named = esperava-se `{ $expected }: <número>`, encontrou-se “{ $found }”
check-vector-within = { $error } (em “{ $text }”)
check-vector-not-three = esperavam-se 3 números como `0.1, -0.9, 0` ou `vec3(0.1, -0.9, 0.0)`, encontraram-se { $count } em “{ $text }”

# Erros que aparecem no que voltou
check-mistake-no-flip-inside = para um raio que chega do outro lado da normal, o código não inverte a normal nem a razão
check-mistake-normal-term-sign = a parte do resultado ao longo da normal tem o sinal errado; a parte transversal está certa
check-mistake-other-root = a outra raiz: o sinal da raiz quadrada trocado, o resultado espelhado em relação à superfície
check-mistake-false-tir = reflexão total indicada onde o raio refrata
check-diagnosis-no-lines = Nenhuma linha foi julgada ({ $lines } lidas): confira o padrão, o cabeçalho CSV ou os campos das linhas; check --suggest-pattern lê as primeiras linhas do log e sugere um padrão.
check-physics-explained = É isso que uma refração dá com este erro: { $mistakes }.
check-looks-normal-term = a resposta da API com a parte ao longo da normal negada: o termo ao longo da normal é subtraído onde é somado, ou o contrário
check-looks-no-flip = o que a fórmula dá sem inverter a normal e eta para um raio que chega do outro lado da normal
check-looks-etap = a direção certa, mas etap = { $logged } onde a chamada usou { $used }

# O diagnóstico de um log inteiro: onde um erro aparece e sua correção
check-where-every = { $count ->
    [one] na única linha julgada
   *[other] em todas as linhas julgadas ({ $count })
}
check-where-inside = { $count ->
    [one] na única linha cujo raio chega de dentro, e em nenhuma de fora
   *[other] em todas as linhas cujo raio chega de dentro ({ $count }), e em nenhuma de fora
}
check-where-outside = { $count ->
    [one] na única linha cujo raio chega de fora, e em nenhuma de dentro
   *[other] em todas as linhas cujo raio chega de fora ({ $count }), e em nenhuma de dentro
}
check-where-past-critical = { $count ->
    [one] na única linha além do ângulo limite, e em nenhuma outra
   *[other] em todas as linhas além do ângulo limite ({ $count }), e em nenhuma outra
}
check-where-some-sides = em { $count } de { $all } linhas julgadas ({ $inside } vindas de dentro, { $outside } de fora)
check-where-some = em { $count } de { $all } linhas julgadas
check-fix-pass = passe `{ $code }`
check-fix-write = escreva `{ $code }`
check-fix-restore = restaure `{ $code }`
check-fix-generic-eta-inverted = use μ = n_from / n_to, o índice do meio que o raio deixa sobre o do meio em que entra: ele se inverte onde o raio sai do objeto (ali μ = n_interno / n_externo; ao entrar, μ = n_externo / n_interno)
check-fix-generic-incident-reversed = passe como W a direção em que o raio viaja, não a oposta
check-fix-generic-normal-not-facing = onde o raio sai do objeto, use em cada termo a normal voltada para o raio (a externa, invertida) ou a externa com o sinal trocado, mas não as duas coisas
check-fix-generic-no-flip-inside = para um raio que chega de dentro, inverta a normal e a razão antes de refratar
check-fix-generic-normal-term-sign = some o termo ao longo da normal: T = μ·W + (μ·cosθi − cosθt)·N, com N voltada para o raio
check-fix-generic-other-root = dê à parte de T ao longo da normal voltada para o raio o sinal que leva T através da superfície: −cosθt (a variável com cosθt, ou o sinal tirado de cosθi, está invertido)
check-fix-generic-missed-tir = reflita quando k = 1 − μ²·(1 − cos²θi) for negativo, antes de tirar a raiz quadrada
check-fix-generic-false-tir = indique reflexão total só onde k = 1 − μ²·(1 − cos²θi) for negativo
check-fix-generic-not-unit-input = normalize W e N antes de refratar
check-fix-generic-not-the-api-result = nenhum erro da fórmula, nem um par, reproduz estas linhas: a explicação de cada linha diz o que voltou e qual é o T correto
check-physics-no-indices = faltam os índices: dê `mu_i` e `mu_t`, ou `entering` com --inside e --outside
check-physics-unknown-convention = convenção desconhecida "{ $text }": esperava "along_ray" ou "toward_origin"
check-diagnosis-none = Nenhum erro: o log está certo { $place }.
check-diagnosis-verdict = O erro: { $code } ({ $meaning }), { $place }. Correção: { $fix }.
check-diagnosis-also = Também: { $code } ({ $meaning }), { $place }. Correção: { $fix }.
check-diagnosis-alike = O log não o distingue de { $alike }; registre { $fields } para distingui-los.
check-pattern-too-many-lines = o padrão ocupa { $count } linhas: no máximo { $limit } são lidas
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} nega um indicador, e { $field } não é um: escreva {"{"}!entering{"}"} para um indicador impresso ao contrário (inside, backfacing)
check-suggest-toward-origin = o vetor incidente é impresso como wi, apontando para a origem do raio: acrescente --convention toward-origin
check-suggest-no-normal = nenhuma normal é impressa: se for o eixo z de um referencial local (Mitsuba, Tungsten), acrescente --normal +z
check-suggest-no-side = nada do que é impresso diz se o raio entra no objeto: imprima-o ({"{"}entering{"}"}, ou {"{"}!entering{"}"} para um indicador como backfacing) e passe --inside e --outside, ou a razão não pode ser verificada
check-suggest-none = nenhuma das primeiras { $lines } linhas parece uma refração (um vetor incidente, uma razão e um resultado, cada um após seu nome): escreva o --pattern à mão (docs/check.md)
check-situation-outward = tomando { $normal } como a normal externa, pois os índices nada dizem do lado
check-right-sampled = Certo como reflexão amostrada: { $call } refrata aqui ({ $returned }), mas o Mitsuba reflete com probabilidade F = { $f }, e o wo nulo diz que refletiu. O diagnóstico do log inteiro verifica que o código transmite nesses ângulos em outras linhas.
check-physics-sampled = Nada voltou onde o raio refrata: certo como reflexão amostrada com probabilidade F = { $f }, como a registram os renderizadores que escolhem ao acaso entre reflexão e refração. O diagnóstico do log inteiro verifica que o código transmite nesses ângulos em outras linhas.
check-fix-in = { $fix } (em { $place })
check-fix-part = { $part }; { $fix }
check-sides-entering = {" "}para os raios que entram no objeto
check-sides-leaving = {" "}para os raios que saem do objeto
check-part-ratio = T é refratado com a razão invertida{ $sides }: 1/μ em cada parte, também no teste de reflexão total (a variável com μ, ou o ternário que a escolhe)
check-part-across = a parte de T transversal a N está escalada por 1/μ em vez de μ (1/μ² da certa){ $sides }, e a parte ao longo de N está certa: a razão que multiplica o vetor incidente está invertida
check-part-along = a parte de T ao longo de N, cosθt = √(1 − μ²·sen²θi), vem de 1/μ em vez de μ{ $sides } (o teste de reflexão total também), e a parte transversal a N está certa: a razão em cosθt está invertida
check-part-normal = a parte de T ao longo de N tem o sinal errado{ $sides }: a normal usada não está voltada para o raio
check-part-incident = a parte de T transversal a N tem o sinal errado (a imagem espelhada de T em relação à normal, desvio errado): o vetor incidente entra invertido na fórmula
check-part-root = a parte de T ao longo de N tem o sinal errado: cosθt fica do lado de onde o raio vem, então T permanece no seu meio (a outra raiz)
check-part-term = o termo ao longo de N, (μ·cosθi − cosθt)·N, é subtraído onde deve ser somado{ $sides }; a parte transversal a N está certa
check-part-no-flip = para os raios do lado oposto da normal, nem a normal é invertida nem a razão: T é a outra raiz com 1/μ
check-fix-generic-ratio-across = escale a parte do vetor incidente transversal a N por μ = n_from / n_to, a mesma razão com que cosθt é calculado
check-fix-generic-ratio-along = calcule cosθt = √(1 − μ²·sen²θi) com μ = n_from / n_to, a razão que escala a parte transversal a N (um cosseno passado com seu sinal faz uma função auxiliar inverter a razão outra vez)
check-fix-generic-across-sign = a parte transversal a N é μ vezes a do vetor incidente (μ·(W + cosθi·N) com W ao longo do raio): tome-a com o sinal do vetor incidente
check-fix-generic-never-transmits = o código nunca transmite esses raios embora eles refratem: se amostra a reflexão, a probabilidade dela (F, a refletância de Fresnel) deve ficar abaixo de 1 ali; indique reflexão total só onde k = 1 − μ²·(1 − cos²θi) é negativo
check-diagnosis-unchecked = Não pode ser verificado sem saber de que lado vem cada raio, { $place }: cada linha está certa pelas regras da sua API, mas nada no log nem nas opções distingue uma razão certa de uma errada. { $fix }.
check-diagnosis-alike-no-field = O log não consegue distingui-lo de { $alike }.
check-unchecked-log-entering = Registre entering em cada linha (true quando o raio entra no objeto; {"{"}!entering{"}"} lê um indicador como inside ou backfacing), ou from e to
check-unchecked-pass-indices = Passe --inside e --outside (os índices dentro e fora do objeto) com entering registrado, ou no pbrt e no Mitsuba com a normal externa; ou registre from e to
check-mistake-across-sign = a parte do resultado transversal à normal tem o sinal errado; a parte ao longo dela está certa (a imagem espelhada do resultado em relação à normal)
check-part-across-sign = a parte de T transversal a N tem o sinal errado (a imagem espelhada de T em relação à normal, desvio errado), e a parte ao longo de N está certa: falta o menos antes da razão vezes o vetor incidente
check-tally-sampled = refletidas (amostradas)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } linhas do log não puderam ser lidas (cada uma é respondida com seu erro), e nenhuma linha lida está errada: não é uma aprovação; corrija essas linhas ou a forma de lê-las.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = o log é JSON Lines, cujas chaves nomeiam os campos: ele não precisa de padrão

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = Não dá para dizer pelos dígitos impressos: como foi impressa, a chamada parece { $shown }, mas números dentro do seu arredondamento a tornam uma chamada certa (um sinal de que o veredito depende, de N·I, de k ou de uma raiz, está mais perto de zero do que os dígitos mostram). Imprima mais dígitos para julgá-la.
check-diagnosis-too-few-digits = Não dá para dizer se estão certas ou erradas pelos dígitos impressos, { $place }: cada uma está errada como foi impressa, mas certa para números dentro do seu arredondamento; os dígitos do log são poucos demais para dizer (um sinal de que o veredito depende, de N·I, de k = 1 − η²·(1 − (N·I)²) ou de uma raiz, pode estar mais perto de zero do que eles mostram). A precisão do log é baixa demais: { $fix }.
check-too-few-digits-fix = imprima cada número com pelo menos 6 dígitos significativos (printf em C ou num shader: %.6g; C#: ToString("G9"), o Vector3 do Unity: ToString("F6"); streams de C++: std::setprecision(9); Rust: {"{"}:?{"}"}; Python: repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 foram lidos da razão que as linhas imprimem, para um objeto mais denso do que o que o cerca (vidro ou água no ar): informe os índices da sua cena se forem outros
check-diagnosis-none-judged = Nenhuma das { $lines } linhas que o padrão leu pôde ser julgada, então o padrão não é o problema; a primeira diz: { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 são vidro no ar, supostos porque as linhas não imprimem nenhuma razão: informe os índices da sua cena se forem outros

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` é impresso com um número por linha (como o cout << v do Eigen imprime um vetor): suas linhas não podem ser juntadas com segurança; imprima cada vetor em uma linha (Eigen: v.transpose(); nalgebra: v.transpose() ou {"{"}:?{"}"}; numpy: np.array2string(v, max_line_width=1000) ou v.tolist())
check-suggest-column-vectors = as primeiras { $lines } linhas imprimem vetores com um número por linha (como o cout << v do Eigen), que nenhum padrão consegue juntar com segurança: imprima cada vetor em uma linha (Eigen: v.transpose(); nalgebra: v.transpose() ou {"{"}:?{"}"}; numpy: v.tolist()), cada um depois do seu nome, e peça de novo

# check: bugs compostos nomeados como causas (issue 43, item 4)
check-mistake-refracted-twice = refratado duas vezes em uma única travessia da superfície: T é o que a razão ao quadrado (μ²) dá
check-mistake-fresnel-cos-sign = o código nunca transmite, em nenhum ângulo, embora k > 0: o sinal do cosseno se perdeu onde a refletância de Fresnel (ou a escolha de transmitir) é calculada
check-mistake-normals-mixed = o lado decidido com uma normal (a geométrica) e refract recebe outra (a de shading), invertida por essa decisão: onde as duas discordam, a normal passada não está voltada para o raio
check-fix-generic-refracted-twice = chame refract uma vez por travessia da superfície: aqui T é refratado de novo (ou μ aplicado duas vezes), como com μ² = (n_origem / n_destino)²; mantenha o primeiro T e siga o raio até a próxima superfície
check-fix-generic-fresnel-cos-sign = o teste de reflexão total não é a causa (abaixo de 15° nenhuma razão torna k negativo): onde F ou a escolha de transmitir é calculada, use cosθi sem o sinal, |N·I| (ou −N·I com N voltada para o raio); um cosseno negativo faz F ≥ 1, e o raio sempre reflete
check-fix-generic-normals-mixed = decida o lado (entering, a razão) e inverta a normal passada a refract com a mesma normal: a de shading para ambos, ou a geométrica para ambos (a geométrica serve para deslocar a origem do raio)
check-fix-normals-print = Se o código decide o lado com outra normal que não a que passa (uma geométrica ao lado de uma de shading), registre também `entering`: assim o diagnóstico consegue distinguir.
