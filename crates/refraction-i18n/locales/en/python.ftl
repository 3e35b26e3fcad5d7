# python.ftl (en): the Python package refraction_check: why an argument of check() is refused
# (its ValueError), and the short text and notebook table that show what was found.

## Arguments refused

python-unknown-api = api: unknown API '{ $name }': expected 'glsl' (or 'hlsl', 'wgsl', 'glm', 'glam'), 'pbrt', 'rtiow', 'mitsuba', or None for any renderer's own refraction
python-unknown-argument = unknown argument `{ $argument }` for api={ $api }: a call's fields are { $fields } (write `from` as from_), and the options are inside, outside, normal, convention, precision and renderer
python-index = { $argument } must be a finite number > 0 (an index of refraction), not { $value }
python-sides-apart = { $given } without { $missing }: give both indices, or neither
python-not-with-api = { $argument } is for any renderer's own refraction (api=None): calls of api='{ $api }' follow that API's own convention, with their normal in its own field
python-normal = normal must be an axis ('+z', '-y'...) or three finite numbers other than zero, not { $value }
python-unknown-word = { $argument }: unknown value '{ $value }': expected one of { $expected }
python-shape = { $argument } has shape { $shape }: expected { $expected }, N the number of calls
python-not-numbers = { $argument } must hold numbers: { $reason }
python-not-flag = { $argument } must hold True/False or 1/0, not { $value } (row { $row })
python-rows = { $argument } has { $rows ->
    [one] one row
   *[other] { $rows } rows
} but { $other } has { $other_rows }: give every argument one row per call, or one value for all calls
python-no-rows = { $argument } has no rows: there is no call to check
python-nothing-judged = { $calls ->
    [one] The call cannot be judged
   *[other] None of the { $calls } calls can be judged
}: { $reason }

## What was found

python-title = { $calls ->
    [one] 1 call
   *[other] { $calls } calls
}, { $ok } right
python-column-code = code
python-column-calls = calls
python-column-row = row
python-column-explanation = explanation
python-first-wrong = { $wrong ->
    [one] The wrong call:
   *[other] The first { $shown } of { $wrong } wrong calls:
}
