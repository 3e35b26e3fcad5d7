# Файлы, экспорт и отмена, по-русски: диалог файлов и вопрос перед заменой,
# инструмент «Сохранить, открыть, поделиться», экспорт изображений и анимаций, отмена и повтор.
# { $path } — путь к файлу; { $reason } — объяснение от чтения или записи (может остаться по-английски).

## Что содержит файл

files-wrong-extension = { $path }: { $kind ->
        [state] сохранённое состояние (JSON)
        [png] изображение PNG
        [scene] сцена (TOML)
        [deck] сценарий урока (TOML)
        [gif] анимация GIF
       *[svg] изображение SVG
    } записывается в файл { $extension }; выберите имя с расширением { $extension }
files-is-a-folder = { $path } — это папка; выберите имя файла
files-holds-another-kind = { $path } содержит { $found ->
        [state] сохранённое состояние (JSON)
        [png] изображение PNG
        [scene] сцену (TOML)
        [deck] сценарий урока (TOML)
        [gif] анимацию GIF
        [svg] изображение SVG
       *[other] что-то другое
    }, а не { $kind ->
        [state] сохранённое состояние (JSON)
        [png] изображение PNG
        [scene] сцену (TOML)
        [deck] сценарий урока (TOML)
        [gif] анимацию GIF
       *[svg] изображение SVG
    }: файл оставлен без изменений; выберите другое имя

## Вопрос перед заменой файла

files-replace-question = Заменить файл?
files-already-exists = { $path } уже существует.
files-replace = Заменить
files-cancel = Отмена

## Диалог открытия и сохранения

files-dialog-open-title = Открыть файл
files-dialog-save-title = Сохранить как
files-folder = Папка
files-showing = показаны папки и { $patterns }
files-file-name = Имя файла
files-open-file = Открыть
files-save-file = Сохранить
files-cannot-list = не удаётся прочитать папку { $path }: { $reason }
files-not-a-file = { $path } — не файл, который можно открыть
files-type-a-name = введите имя файла в существующей папке

## Сохранить, открыть, поделиться

files-state-file = Файл состояния
files-save = 💾 Сохранить
files-save-hover = Записать W, N, μ и соглашение как строку JSON для solve
files-open = 🗁 Открыть
files-open-hover = Прочитать файл JSON для solve; неверный файл ничего не меняет
files-open-dialog = Открыть…
files-open-dialog-hover = Выбрать файл состояния для открытия
files-save-as = Сохранить как…
files-save-as-hover = Выбрать, куда сохранить
files-saved = сохранено: { $path }
files-not-saved = не сохранено: { $reason }
files-left-as-it-was = { $path } оставлен без изменений
files-opened = открыто: { $path }
files-opened-as-scene = { $path } — сцена, а не состояние: открыта в режиме «Сцены»
files-opened-as-deck = { $path } — сценарий урока, а не состояние: открыт на первом шаге
files-neither-state-nor-scene = { $state }; как сцена: { $scene }
files-cannot-read-state = не удаётся прочитать файл состояния { $path }: { $reason }
files-state-refused = файл состояния { $path }: { $reason }
files-copy-share = 🔗 Копировать строку обмена
files-copy-share-hover = Воспроизводит ровно это состояние на другом компьютере, бит в бит
files-share-copied = строка обмена скопирована
files-paste-share = Вставить строку обмена
files-apply = Применить
files-share-applied = строка обмена применена
files-share-refused = строка обмена: { $reason }
files-copy-case-as = Копировать случай как
files-copy-solve-line = строка solve
files-copy-test-vector = тестовый вектор
files-copied = скопировано: { $what }

## Экспорт

files-wrote = записано: { $path }
files-not-exported = не экспортировано: { $reason }
files-export-cancelled = отменено: ничего не записано
files-export-crashed = экспорт остановлен внутренней ошибкой
files-gif-needed = { $path }: анимация записывается как GIF; укажите имя с расширением .gif
files-animation-heading = Анимация для слайда
files-animation = Анимация
files-gif-file = Файл GIF
files-drawing-frames = рисуются кадры… { $percent } %
files-export-animation = Экспорт анимации
files-export-animation-hover = Рисует все кадры в фоне; окно продолжает работать
files-frames = Кадры
files-per-second = в секунду
files-gif-width = Ширина GIF
files-height = высота

## Отмена и повтор

files-undo = Отменить
files-undo-hover = Отменить последнее изменение W, N, μ или соглашения (Ctrl+Z)
files-redo = Повторить
files-redo-hover = Повторить отменённое (Ctrl+Shift+Z)
files-undid = Отменено: { $changes }
files-redid = Повторено: { $changes }
files-undo-convention = соглашение (раздел { $from } → { $to })
files-undo-n-turned = N повёрнута
files-undo-n-flipped = N развёрнута
files-undo-scene-edit = правка сцены { $scene }
files-undo-scene = сцена ({ $from } → { $to })
files-undo-w-or-n-typed = W или N введены
