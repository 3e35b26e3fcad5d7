# python.ftl (pt-BR): o pacote Python refraction_check: por que um argumento de check() é
# recusado (seu ValueError), e o texto curto e a tabela do notebook que mostram o resultado.

## Argumentos recusados

python-unknown-api = api: API desconhecida '{ $name }': esperado 'glsl' (ou 'hlsl', 'wgsl', 'glm', 'glam'), 'pbrt', 'rtiow', 'mitsuba', ou None para a refração própria de qualquer renderizador
python-unknown-argument = argumento desconhecido `{ $argument }` para api={ $api }: os campos de uma chamada são { $fields } (`from` se escreve from_), e as opções inside, outside, normal, convention, precision e renderer
python-index = { $argument } deve ser um número finito > 0 (um índice de refração), não { $value }
python-sides-apart = { $given } sem { $missing }: dê os dois índices, ou nenhum
python-not-with-api = { $argument } é para a refração própria de qualquer renderizador (api=None): as chamadas de api='{ $api }' seguem a convenção dessa API, com a normal num campo próprio
python-normal = normal deve ser um eixo ('+z', '-y'...) ou três números finitos não todos nulos, não { $value }
python-unknown-word = { $argument }: valor desconhecido '{ $value }': esperado um de { $expected }
python-shape = { $argument } tem forma { $shape }: esperado { $expected }, N o número de chamadas
python-not-numbers = { $argument } deve conter números: { $reason }
python-not-flag = { $argument } deve conter True/False ou 1/0, não { $value } (linha { $row })
python-rows = { $argument } tem { $rows ->
    [one] uma linha
   *[other] { $rows } linhas
} mas { $other } tem { $other_rows }: dê a cada argumento uma linha por chamada, ou um valor para todas as chamadas
python-no-rows = { $argument } não tem linhas: não há chamada a verificar
python-nothing-judged = { $calls ->
    [one] A chamada não pode ser julgada
   *[other] Nenhuma das { $calls } chamadas pode ser julgada
}: { $reason }

## O resultado

python-title = { $calls ->
    [one] 1 chamada
   *[other] { $calls } chamadas
}, { $ok } certas
python-column-code = código
python-column-calls = chamadas
python-column-row = linha
python-column-explanation = explicação
python-first-wrong = { $wrong ->
    [one] A chamada errada:
   *[other] As primeiras { $shown } de { $wrong } chamadas erradas:
}
