# A whole log judged in the window: its section in Check my T, the file it is read from, its
# diagnosis, its failure map and its failing lines saved as tests.

logs-hint = Lines of the fields { $fields }: JSON Lines, CSV with a header naming them, or printf lines read with a pattern such as { $example }. Paste at most { $characters } characters, or open a log file; the first { $count } lines are listed, and every line is diagnosed.
logs-inside = Index inside
logs-outside = outside
logs-indices-hint = the object's index and its surroundings', for lines that log entering
logs-index-invalid = { $field }: “{ $text }” is not an index (a finite number above 0)
logs-not-listed = { $count ->
    [one] { $count } more line judged but not listed (the table shows the first { $first })
   *[other] { $count } more lines judged but not listed (the table shows the first { $first })
}
logs-diagnosis-heading = Diagnosis of the whole log
logs-copy-diagnosis = Copy the diagnosis and the table
logs-copy-diagnosis-hover = As text: the counts, the diagnosis, then one line per call with tabs between its cells
logs-map-heading = Failure map
logs-map-hover = How far each judged line's direction is from the right one, against the angle of incidence, in a panel for each side the rays arrive from. Squares: the right answer is total internal reflection.
logs-open = 🗁 Open log…
logs-open-hover = Read a log file (or drop one on the window): up to { $most } lines are judged and diagnosed.
logs-what-log = log
logs-read-failed = Could not read { $path }: { $reason }
logs-opened = Judging the file { $path }: { $lines ->
    [one] { $lines } line
   *[other] { $lines } lines
} (at most { $most }).
logs-close-file = Type or paste instead
logs-save-tests = Save the { $count ->
    [one] failing line
   *[other] first { $count } failing lines
} as tests:
logs-tests-extension = { $path }: tests in this language are written to a { $extension } file; choose a name ending in .{ $extension }
logs-tests-not-ours = { $path } is not a test file this tool wrote; choose another name so that your own code is kept
logs-write-failed = Could not write { $path }: { $reason }

diagram-failure-right = right
diagram-failure-wrong = wrong
diagram-failure-past-critical = right answer: total internal reflection
diagram-failure-panel = { $side ->
    [outside] Arriving from outside
    [inside] Arriving from inside
   *[unknown] Side not logged
}: { $lines ->
    [one] { $lines } line
   *[other] { $lines } lines
}, { $wrong ->
    [0] none wrong
   *[other] { $wrong } wrong
}
diagram-failure-caption = How far the direction each judged line sent the ray in is off from the right one, against the angle of incidence θi:
diagram-failure-empty = No line was judged.
diagram-failure-about = Failure map. { $panels }

# check --tests and Save failing lines as tests: what is at the path cannot be read, or is not a file (issue 40)
logs-tests-unreadable = { $path } cannot be read ({ $reason }), so it cannot be told from your own code: it is left as it is; choose another name
logs-tests-not-a-file = { $path } is not a regular file (a pipe, a device or a link to one): tests are written only to a file of their own; choose another name
