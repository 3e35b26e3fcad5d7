# Um log inteiro julgado na janela: sua seção em “Verificar meu T”, o arquivo de onde é lido,
# seu diagnóstico, seu mapa de falhas e suas linhas erradas salvas como testes.

logs-hint = Linhas com os campos { $fields }: JSON Lines, CSV com um cabeçalho que os nomeia, ou linhas de printf lidas com um padrão como { $example }. Cole no máximo { $characters } caracteres ou abra um arquivo de log; as primeiras { $count } linhas são listadas e todas entram no diagnóstico.
logs-inside = Índice dentro
logs-outside = fora
logs-indices-hint = o índice do objeto e o do meio em volta, para as linhas que registram entering
logs-index-invalid = { $field }: “{ $text }” não é um índice (um número finito maior que 0)
logs-not-listed = { $count ->
    [one] mais { $count } linha julgada mas não listada (a tabela mostra as primeiras { $first })
   *[other] mais { $count } linhas julgadas mas não listadas (a tabela mostra as primeiras { $first })
}
logs-diagnosis-heading = Diagnóstico do log inteiro
logs-copy-diagnosis = Copiar o diagnóstico e a tabela
logs-copy-diagnosis-hover = Como texto: as contagens, o diagnóstico e depois uma linha por chamada com tabulações entre as células
logs-map-heading = Mapa de falhas
logs-map-hover = Quanto a direção de cada linha julgada se afasta da correta, em função do ângulo de incidência, num painel para cada lado de onde chegam os raios. Quadrados: a resposta correta é a reflexão total.
logs-open = 🗁 Abrir log…
logs-open-hover = Ler um arquivo de log (ou soltá-lo na janela): até { $most } linhas são julgadas e diagnosticadas.
logs-what-log = log
logs-read-failed = Não foi possível ler { $path }: { $reason }
logs-opened = Julgando o arquivo { $path }: { $lines ->
    [one] { $lines } linha
   *[other] { $lines } linhas
} (no máximo { $most }).
logs-close-file = Digitar ou colar em vez disso
logs-save-tests = Salvar { $count ->
    [one] a linha errada
   *[other] as primeiras { $count } linhas erradas
} como testes:
logs-tests-extension = { $path }: os testes nesta linguagem são escritos num arquivo { $extension }; escolha um nome terminado em .{ $extension }
logs-tests-not-ours = { $path } não é um arquivo de testes escrito por esta ferramenta; escolha outro nome para manter seu próprio código
logs-write-failed = Não foi possível escrever { $path }: { $reason }

diagram-failure-right = certa
diagram-failure-wrong = errada
diagram-failure-past-critical = resposta correta: reflexão total
diagram-failure-panel = { $side ->
    [outside] Chegando de fora
    [inside] Chegando de dentro
   *[unknown] Lado não registrado
}: { $lines ->
    [one] { $lines } linha
   *[other] { $lines } linhas
}, { $wrong ->
    [0] nenhuma errada
    [one] { $wrong } errada
   *[other] { $wrong } erradas
}
diagram-failure-caption = Quanto a direção em que cada linha julgada envia o raio se afasta da correta, em função do ângulo de incidência θi:
diagram-failure-empty = Nenhuma linha foi julgada.
diagram-failure-about = Mapa de falhas. { $panels }

# check --tests and Save failing lines as tests: what is at the path cannot be read, or is not a file (issue 40)
logs-tests-unreadable = { $path } não pode ser lido ({ $reason }), então não dá para distingui-lo do seu próprio código: ele fica como está; escolha outro nome
logs-tests-not-a-file = { $path } não é um arquivo comum (um pipe, um dispositivo ou um link para um deles): os testes só são escritos em um arquivo próprio; escolha outro nome
