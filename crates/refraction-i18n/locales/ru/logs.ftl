# Целый журнал, проверенный в окне: его раздел в «Проверить мой T», файл, из которого он
# читается, его диагноз, карта ошибок и неверные строки, сохранённые как тесты.

logs-hint = Строки с полями { $fields }: JSON Lines, CSV с заголовком, который их называет, или строки printf, прочитанные по шаблону вроде REFR d={"{"}w{"}"} nl={"{"}n{"}"} into={"{"}entering{"}"} tdir={"{"}t_yours{"}"}. Вставьте не больше { $characters } символов или откройте файл журнала; первые { $count } строк показаны в таблице, в диагноз входят все.
logs-inside = Показатель внутри
logs-outside = снаружи
logs-indices-hint = показатель преломления тела и окружающей среды, для строк, в которых записан entering
logs-index-invalid = { $field }: «{ $text }» — не показатель преломления (конечное число больше 0)
logs-not-listed = { $count ->
    [one] ещё { $count } строка проверена, но не показана (в таблице первые { $first })
    [few] ещё { $count } строки проверены, но не показаны (в таблице первые { $first })
   *[other] ещё { $count } строк проверено, но не показано (в таблице первые { $first })
}
logs-diagnosis-heading = Диагноз всего журнала
logs-map-heading = Карта ошибок
logs-map-hover = Насколько направление каждой проверенной строки отклоняется от правильного, в зависимости от угла падения, по панели на каждую сторону, с которой приходят лучи. Квадраты: правильный ответ — полное внутреннее отражение.
logs-open = 🗁 Открыть журнал…
logs-open-hover = Прочитать файл журнала (или перетащить его на окно): проверяется и диагностируется до { $most } строк.
logs-what-log = журнал
logs-read-failed = Не удалось прочитать { $path }: { $reason }
logs-opened = Проверяется файл { $path }: { $lines ->
    [one] { $lines } строка
    [few] { $lines } строки
   *[other] { $lines } строк
} (не больше { $most }).
logs-close-file = Вместо этого ввести или вставить
logs-save-tests = Сохранить { $count ->
    [one] неверную строку
    [few] первые { $count } неверные строки
   *[other] первые { $count } неверных строк
} как тесты:
logs-tests-extension = { $path }: тесты на этом языке записываются в файл { $extension }; выберите имя, оканчивающееся на .{ $extension }
logs-tests-not-ours = { $path } — не файл тестов, записанный этой программой; выберите другое имя, чтобы ваш собственный код остался цел
logs-write-failed = Не удалось записать { $path }: { $reason }

diagram-failure-right = верно
diagram-failure-wrong = неверно
diagram-failure-past-critical = правильный ответ: полное внутреннее отражение
diagram-failure-panel = { $side ->
    [outside] Приходят снаружи
    [inside] Приходят изнутри
   *[unknown] Сторона не записана
}: { $lines ->
    [one] { $lines } строка
    [few] { $lines } строки
   *[other] { $lines } строк
}, { $wrong ->
    [0] неверных нет
   *[other] неверных: { $wrong }
}
diagram-failure-incidence-axis = угол падения θi
diagram-failure-error-axis = отклонение
diagram-failure-empty = Ни одна строка не проверена.
diagram-failure-about = Карта ошибок. { $panels }
