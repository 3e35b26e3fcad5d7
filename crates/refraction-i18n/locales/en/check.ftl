# check.ftl (en): the words of "Check my T": the panel, its verdicts and their explanations.

## Numbers and vectors in explanations

check-number-not-finite = not finite (NaN or infinite)
check-vector-not-finite = a vector that is not finite (NaN or infinite components)

## Verdicts on a T in this project's fields (also the `check` command's explanations)

check-verdict-wrong-side = Your T goes back into the medium the ray came from: the other root for b (+ where the square root needs -). The usual cause is a normal that points along the ray, such as a sphere's outward normal where the ray leaves it, used without flipping.
check-verdict-wrong-bend = Your T bends the wrong way: the sign of a is flipped, so it would not become the incoming ray as μ → 1. The usual cause is mixing the conventions: W pointing back to the origin (Section 1, a = −μ) fed to the along-the-ray formula (Section 2, a = +μ), or the other way round.
check-verdict-reversed = Your T is -T, pointing back where the ray came from: both signs are wrong. The usual cause is returning the direction toward the origin instead of the direction of travel, or negating W twice.
check-verdict-not-finite-tir = Your T has NaN or infinite components. This ray is totally internally reflected (k < 0): your code took the square root of a negative k instead of checking k first.
check-verdict-not-finite-refracts = Your T has NaN or infinite components although this ray refracts normally (k ≥ 0): look for a division by zero or an un-initialised vector.
check-verdict-tir-right = Right: this ray is totally internally reflected (k < 0) and your code returned the reflection (or the zero vector GLSL uses to say so).
check-verdict-tir-but-refracted = This ray is totally internally reflected (k = { $k } < 0): there is no refracted ray, but your code returned one. Check k before taking its square root.
check-verdict-zero-vector = Your T is the zero vector, which GLSL returns for total internal reflection, but this ray refracts (k ≥ 0). Check the sign of k and the index ratio.
check-verdict-not-unit = Also, your T has length { $length }, not 1: normalise W and N before refracting (the formula assumes unit vectors) or T after.
check-verdict-along-refracted = Your T points along the refracted ray (within { $off } rad).
check-verdict-right = Right: your T is the refracted ray (within { $off } rad).
check-verdict-ratio-upside-down = Your T is the refraction with the index ratio upside down: μ must be μi/μt (the medium the ray leaves over the one it enters), and your code used μt/μi.
check-verdict-out-of-plane = Your T leaves the plane of incidence (the plane of W and N) by { $off } rad: T must be a combination a·W + b·N of the two.
check-verdict-no-candidate = Your T matches none of the four sign choices: it is { $degrees } degrees from the refracted ray. Check μ, and which way W and N point.

## Reading t_yours from a JSON line

check-t-yours-item-not-number = `t_yours[{ $index }]` must be a number or null
check-t-yours-missing = missing field `t_yours` (the T your code produced)

## Explanations of a verdict on an API call (`check --api` and the panel): how each API speaks

check-api-owner = { $api ->
    [glsl] GLSL
    [pbrt] pbrt
    [rtiow] The book
   *[mitsuba] Mitsuba
}
check-api-call = { $api ->
    [glsl] GLSL's refract(I, N, eta)
    [pbrt] pbrt's Refract(wi, n, eta)
    [rtiow] the book's refract(uv, n, etai_over_etat)
   *[mitsuba] Mitsuba's fresnel(cos_theta_i, eta) with refract
}
check-api-eta-means = { $api ->
    [glsl] n_from/n_to, the index the ray leaves over the one it enters
    [pbrt] the index on the side n points away from over the index on the side it points to (n_inside/n_outside with the outward normal)
    [rtiow] etai/etat = n_from/n_to (1/refraction_index on a front face, refraction_index on a back face)
   *[mitsuba] int_ior/ext_ior, the index on the side the normal points away from over the index on the side it points to
}
check-api-incident-means = { $api ->
    [glsl] the direction the ray travels, toward the surface
    [pbrt] the direction back toward where the ray came from (-ray.d)
    [rtiow] the unit direction the ray travels (unit_vector(r_in.direction()))
   *[mitsuba] wi, pointing away from the surface back along the ray (-ray.d)
}
check-api-root-hint = { $api ->
    [glsl] GLSL subtracts (eta * dot(N, I) + sqrt(k)) * N
    [pbrt] wt takes (cosTheta_i / eta - cosTheta_t) * n
    [rtiow] r_out_parallel is -sqrt(fabs(1 - r_out_perp.length_squared())) * n
   *[mitsuba] cos_theta_t has the opposite sign to cos_theta_i
}
check-api-usual = { $api ->
    [pbrt] the outward normal with the material's eta (n_inside/n_outside)
    [mitsuba] the exterior normal with eta = int_ior/ext_ior
   *[other] {""}
}

## Explanations of a verdict on an API call: the pieces

check-situation-entering = entering the object (from n = { $from } into n = { $to })
check-situation-leaving = leaving the object (from n = { $from } into n = { $to })
check-situation-going = going from n = { $from } into n = { $to }
check-nothing-zero-vector = the zero vector
check-nothing-reflection = the reflection
check-nothing-false-or-null = nothing (false or null)
check-and = and
check-or = or
check-field-from-and-to = from and to (or entering with --inside and --outside)
check-normal-fix-rtiow = the hit record's normal after set_face_normal
check-normal-fix-facing = the normal turned round wherever that dot product is positive
check-normal-inward-entering = it points into the object, and the ray is entering
check-normal-inward-leaving = it points into the object, and the ray is leaving
check-looks-other-root = the other root, with the square root's sign flipped ({ $hint })
check-looks-wrong-bend = the part along the surface flipped
check-looks-reversed = minus the API's answer
check-looks-length = the same direction with { $ratio } times the length: your code scales or normalises differently
check-looks-reflection = the reflection, although this ray refracts (log only the refraction, not a reflection chosen by Fresnel or Schlick)
check-looks-variant = what { $call } returns with { $variant }: your implementation does that inside
check-variant-eta-inverted = eta inverted
check-variant-normal-flipped = the normal flipped
check-variant-incident-reversed = the incident vector reversed
check-looks-nothing = { $what }, which says nothing is transmitted, although this ray refracts (k = { $k } ≥ 0)
check-looks-not-finite = NaN or infinite components, although this ray refracts
check-looks-off = { $degrees } degrees from it
check-looks-off-unmeasurable = at no angle that can be measured from it
check-returned-pbrt-true = true with wt = { $wt }
check-returned-rtiow-cannot-refract = cannot_refract (dielectric::scatter reflects)
check-returned-mitsuba-reflects = F = 1 (the BSDF always reflects)
check-unchecked-mu = from and to (or entering with --inside and --outside) to check { $eta }
check-unchecked-travel = travel to check which way { $incident } points

## Explanations of a verdict on an API call: the sentences

check-eta-inverted = { $owner }'s { $eta } is { $means }: you passed { $value } for a ray { $situation }; pass 1/{ $value } = { $inverse }.
check-eta-inverted-this-ray = { $owner }'s { $eta } is { $means }: you passed { $value } for this ray; pass 1/{ $value } = { $inverse }.
check-incident-reversed = { $owner }'s { $incident } is { $means }; yours points the other way: pass -{ $incident } = { $reversed }.
check-incident-reversed-travel = { $owner }'s { $incident } is { $means }; yours points the other way (the ray travels along { $travel }): pass -{ $incident } = { $reversed }.
check-not-unit-input = { $call } assumes unit { $incident } and { $normal } and does not normalise them: |{ $incident }| = { $incident_length }, |{ $normal }| = { $normal_length }; normalise them first.
check-normal-against = { $call } needs { $normal } against { $incident } (dot({ $normal }, { $incident }) < 0) and does not flip it; yours has dot({ $normal }, { $incident }) = { $dot }, as an outward normal has where the ray leaves the object: pass -{ $normal } = { $flipped } ({ $fix }).
check-normal-either-side = { $call } takes { $normal } on either side, but { $eta } must go with it: it is { $means }. Your { $normal } points the other way from the one { $eta } = { $value } was meant for{ $inward }; pass -{ $normal } = { $flipped } with the same { $eta } (or keep { $normal } and pass 1/{ $eta }).
check-tir-glsl = GLSL's refract returns the zero vector here (k = { $k } < 0: total internal reflection); test for it and reflect instead.
check-tir-pbrt = pbrt's Refract returns false here (sin2Theta_t = { $sin2 } >= 1: total internal reflection); reflect instead.
check-tir-rtiow = dielectric::scatter's cannot_refract holds here (ri * sin_theta = { $sine } > 1): the book reflects instead of calling refract.
check-tir-mitsuba = fresnel returns F = 1 here (cos_theta_t_sqr = { $k } < 0): Mitsuba always reflects.
check-tir-got-formula = Your code used the formula's vector anyway, { $vector } of length { $length }: not a ray.
check-tir-got-direction = Your code gave a direction, { $vector }, where there is none.
check-tir-got-not-finite = Your code gave NaN or infinite components (the square root of a negative k, or normalize() of the zero vector).
check-result-differs = { $call } returns { $returned } for these arguments, but the call gave { $got }: { $detail }. Your own implementation of it differs from the API's.
check-ties-no-field = No truth field tells them apart: { $call } reads both alike; the usual call passes { $usual }.
check-ties-give = Give { $fields } to tell them apart.
check-ties = Equally possible: { $readings } instead. { $hint }
check-unchecked = Checked against the API's own rules only: give { $missing }.
check-unexplained-travel = The logged { $incident } is { $degrees } degrees from this ray's travel { $travel }: it is not this ray's direction (nor its reverse).
check-unexplained-eta = { $eta } = { $value } fits neither n_from/n_to = { $mu } nor its inverse as { $call } reads it: these are not this interface's indices.
check-unexplained = No combination of argument mistakes makes this call fit the truth given.
check-right-tir = Right: { $call } signals total internal reflection here ({ $returned }), and the call gave { $what }.
check-right-for-ray = Right: { $call } returns { $returned } for these arguments, a ray { $situation }.
check-right = Right: { $call } returns { $returned } for these arguments.

## The mistakes of an API call, in one line each

check-mistake-eta-inverted = the index ratio upside down for this API's convention
check-mistake-incident-reversed = the incident vector passed the wrong way round
check-mistake-normal-not-facing = the normal on the wrong side for this API (or for the eta passed)
check-mistake-not-the-api-result = the result is not what the API returns for these arguments: your own implementation differs
check-mistake-missed-tir = a direction (or NaN) where the API signals total internal reflection
check-mistake-not-unit-input = the incident vector or the normal is not unit length

## The panel: this project's fields

check-source-own = W, N, μ (this project)
check-code-calls = Your code calls:
check-convention = Convention:
check-convention-along-ray = Section 2: W along the ray
check-convention-along-ray-about = W is the direction the ray travels, toward the surface (GLSL's I, the book's uv).
check-convention-toward-origin = Section 1: W toward the origin
check-convention-toward-origin-about = W points back toward where the ray came from (pbrt's and Mitsuba's wi).
check-convention-note = { $about } μ = μi/μt; N on either side (the kernel turns it to face the ray).
check-paste-hint = Paste what your ray tracer logged. Vectors as 0.1, -0.9, 0 or [0.1,-0.9,0] or vec3(0.1, -0.9, 0.0); or paste a whole JSON line with t_yours into "Your T".
check-use-current-case = Use the current case
check-use-current-case-own-hover = Fill W, N, μ and the convention from the explorer
check-use-current-case-api-hover = Fill the arguments and the indices from the explorer
check-your-t = Your T
check-your-t-in-error = your T
check-button = Check
check-field-not-number = { $field }: “{ $text }” is not a number
check-student-own = your T: { $verdict }
check-headline-own = Your T matches { $verdict }
check-match-refracted = the refracted ray T
check-match-not-unit = T's direction, but not unit length
check-match-wrong-side = wrong side (the other root for b)
check-match-wrong-bend = wrong bend (the other sign of a)
check-match-reversed = reversed (−T: both signs wrong)
check-match-tir = total internal reflection, answered right
check-match-none = none of the four candidates
check-no-refracted-ray = There is no refracted ray: total internal reflection.
check-right-t = The right T = { $t }
check-copy-right-t = Copy T
check-not-drawn-changed = (The case has changed since: the verdict is not drawn.)

## The panel: an API call

check-drawn-incident = { $api ->
    [glsl] I (direction of travel)
    [pbrt] wi (back toward the origin)
    [rtiow] uv (direction of travel)
   *[mitsuba] wi (away from the surface)
}
check-drawn-about = { $api ->
    [glsl] I is the direction the ray travels, drawn as W along the ray (Section 2). N must face I: GLSL does not turn it. eta = n_from/n_to = μi/μt. The zero vector means total internal reflection.
    [pbrt] wi points back toward where the ray came from (−ray.d), drawn as W toward the origin (Section 1). n may face either side: pbrt flips it and inverts eta when wi is below it. eta = the index behind n over the one in front (μt/μi with n facing wi). false means total internal reflection.
    [rtiow] uv is the unit direction the ray travels, drawn as W along the ray (Section 2). n must face uv (front_face). etai_over_etat = n_from/n_to = μi/μt. refract has no TIR test: the caller's cannot_refract reflects.
   *[mitsuba] wi points away from the surface, back along the ray, drawn as W toward the origin (Section 1). n is +z (the local frame) when left empty. eta = int_ior/ext_ior, the index behind n over the one in front (μt/μi with n facing wi). F = 1 means total internal reflection: wo is null.
}
check-convention-about = Convention: { $about }
check-your-call = Your call
check-truth = Truth (optional)
check-picture-outside = μ = { $mu } needs indices outside the explorer's { $low }…{ $high }
check-student-api = your { $result }: { $verdict }
check-student-right = right
check-student-wrong = wrong
check-api-right-headline = Right: what { $signature } means for this ray
check-api-mistakes = Mistakes: { $codes }
check-api-unexplained-headline = Not explained by any single mistake
check-api-returns = { $owner } returns { $value }
check-api-drawn = Drawn: the right call, { $incident } = { $incident_value }, { $normal } = { $normal_value }, { $eta } = { $eta_value } (μi = { $mu_i }, μt = { $mu_t }).
check-api-not-drawn = Not drawn: { $why }.
check-copy-as-test = Copy as a unit test:

## The panel: pasted log lines

check-paste-lines = 📋 Paste log lines
check-pattern = Pattern
check-log-lines = Log lines
check-lines-button = Check the lines
check-read-as-pattern = the pattern
check-read-as-json-lines = JSON Lines
check-read-as-csv = CSV (the first line is the header)
check-bulk-summary = Read as { $read_as }: { $count ->
    [one] { $count } call
   *[other] { $count } calls
}
check-bulk-left-out = { $count ->
    [one] { $count } line after the first { $first } left out
   *[other] { $count } lines after the first { $first } left out
}
check-column-line = line
check-column-ok = ok
check-column-mistakes = mistakes
check-column-explanation = explanation
check-row-line = line { $line }
check-row-open-hover = Open this call in the panel and the diagram
check-row-error = error

## Reading the fields of a call, a CSV line, a pattern and a vector (the panel shows these too)

check-field-not-three = `{ $field }` must have exactly 3 numbers, got { $count }
check-field-not-a-vector = `{ $field }` must be an array of 3 numbers or a string like "0.1, -0.9, 0"
check-field-not-flag-got = `{ $field }` must be true/false or 1/0, got "{ $text }"
check-field-not-number-json = `{ $field }` must be a number
check-field-not-flag = `{ $field }` must be true/false or 1/0
check-field-not-label = `{ $field }` must be a string or a number
check-json-not-object = expected a JSON object with the fields { $fields }
check-unknown-field = unknown field `{ $field }`
check-field-not-vector = `{ $field }` must be 3 numbers
check-field-missing = missing field `{ $field }` ({ $what })
check-what-normal = the surface normal
check-what-incident = the incident vector
check-what-eta = the index ratio
check-field-not-finite = `{ $field }` must be finite, got { $value }
check-field-zero-vector = `{ $field }` is the zero vector
check-field-not-positive = `{ $field }` must be a finite number > 0, got { $value }
check-from-and-to-together = `from` and `to` go together: give both or neither
check-travel-not-finite = `travel` must be a finite non-zero vector
check-result-null = `{ $field }` is null although `{ $returned }` is true
check-result-missing = missing field `{ $field }` (what the call returned{ $api ->
    [pbrt] , or "returned": false
    [mitsuba] , null when it reflected
   *[other] {""}
})
check-unknown-precision = unknown precision "{ $text }": expected "f32" or "f64"
check-too-large = { $value } is too large for { $precision }
check-csv-unclosed-quote = unclosed quote in the CSV line
check-csv-no-column = the CSV header has no column `{ $field }`: it names { $names }; expected { $expected }
check-csv-partial-vector = the CSV header has only { $count } of `{ $field }`'s 3 components
check-csv-duplicate-column = the CSV header names `{ $column }` more than once
check-csv-cells = { $count ->
    [one] { $count } cell
   *[other] { $count } cells
} where the header has { $columns ->
    [one] { $columns } column
   *[other] { $columns } columns
}
check-csv-no-header = no usable CSV header: { $reason }
check-pattern-unclosed = unclosed `{"{"}` in the pattern "{ $pattern }"
check-pattern-adjacent = two fields with nothing between them in the pattern "{ $pattern }"
check-pattern-twice = the field {"{"}{ $field }{"}"} is named twice in the pattern "{ $pattern }": name each field once
check-pattern-too-many = the pattern has { $count } placeholders: at most { $limit } are read
check-pattern-too-long = the pattern is { $bytes } bytes long: at most { $limit } are read
check-pattern-no-field = the pattern "{ $pattern }" names no field
check-pattern-unknown-field = unknown field {"{"}{ $field }{"}"} in the pattern for --api { $api }: expected {"{"}_{"}"} or one of { $expected }
check-line-not-matching = the line does not match the pattern
check-tally-skipped = skipped (not matching the pattern)
check-tally-unreadable = unreadable
check-tally-unexplained = unexplained
check-word-not-a-number = "{ $word }" is not a number
check-vector-expected-named = expected `{ $expected }: <number>`, found "{ $found }"
check-vector-within = { $error } (in "{ $text }")
check-vector-not-three = expected 3 numbers such as `0.1, -0.9, 0` or `vec3(0.1, -0.9, 0.0)`, found { $count } in "{ $text }"

# Mistakes that show in what came back
check-mistake-no-flip-inside = for a ray from the normal's far side, the code does not turn the normal round and invert the ratio
check-mistake-normal-term-sign = the part of the result along the normal has the wrong sign; the part across it is right
check-mistake-other-root = the other root: the square root's sign flipped, the result mirrored across the surface
check-mistake-false-tir = total internal reflection reported where the ray refracts
check-diagnosis-no-lines = No line was judged ({ $lines } read): check the pattern, the CSV header or the fields the lines carry; check --suggest-pattern reads the log's first lines and suggests a pattern.
check-physics-explained = That is what a refraction gives with this mistake: { $mistakes }.
check-looks-normal-term = the API's answer with the part along the normal negated: the term along the normal is subtracted where it is added, or the other way round
check-looks-no-flip = what the formula gives without turning the normal round and inverting eta for a ray from the normal's far side
check-looks-etap = the right direction, but etap = { $logged } where the call used { $used }

# The diagnosis of a whole log: where a mistake shows, and its fix
check-where-every = { $count ->
    [one] on the one judged line
   *[other] on every judged line ({ $count })
}
check-where-inside = { $count ->
    [one] on the one line arriving from inside, and on none from outside
   *[other] on every line arriving from inside ({ $count }), and on none from outside
}
check-where-outside = { $count ->
    [one] on the one line arriving from outside, and on none from inside
   *[other] on every line arriving from outside ({ $count }), and on none from inside
}
check-where-past-critical = { $count ->
    [one] on the one line past the critical angle, and on no other
   *[other] on every line past the critical angle ({ $count }), and on no other
}
check-where-some-sides = on { $count } of { $all } judged lines ({ $inside } arriving from inside, { $outside } from outside)
check-where-some = on { $count } of { $all } judged lines
check-fix-pass = pass `{ $code }`
check-fix-write = write `{ $code }`
check-fix-restore = restore `{ $code }`
check-fix-generic-eta-inverted = use μ = n_from / n_to, the index of the medium the ray leaves over the one it enters: it inverts where the ray leaves the object (there μ = n_inside / n_outside; entering, μ = n_outside / n_inside)
check-fix-generic-incident-reversed = pass the ray's direction of travel as W, not its negative
check-fix-generic-normal-not-facing = where the ray leaves the object, use the normal that faces the ray in every term (the outward one turned round), or the outward one with its sign turned, but not both
check-fix-generic-no-flip-inside = for a ray arriving from inside, turn the normal round and invert the ratio before refracting
check-fix-generic-normal-term-sign = add the term along the normal: T = μ·W + (μ·cosθi − cosθt)·N, with N facing the ray
check-fix-generic-other-root = give the part of T along the normal facing the ray the sign that takes T through the surface: −cosθt (the variable holding cosθt, or the sign taken from cosθi, is flipped)
check-fix-generic-missed-tir = reflect when k = 1 − μ²·(1 − cos²θi) is negative, before taking its square root
check-fix-generic-false-tir = report total internal reflection only where k = 1 − μ²·(1 − cos²θi) is negative
check-fix-generic-not-unit-input = normalise W and N before refracting
check-fix-generic-not-the-api-result = no single mistake of the formula, nor a pair, reproduces these lines: each line's explanation says what came back and what the right T is
check-physics-no-indices = no indices: give `mu_i` and `mu_t`, or `entering` with --inside and --outside
check-physics-unknown-convention = unknown convention "{ $text }": expected "along_ray" or "toward_origin"
check-diagnosis-none = No mistake: the log is right { $place }.
check-diagnosis-verdict = The bug: { $code } ({ $meaning }), { $place }. Fix: { $fix }.
check-diagnosis-also = Also: { $code } ({ $meaning }), { $place }. Fix: { $fix }.
check-diagnosis-alike = The log cannot tell it from { $alike }; log { $fields } to tell them apart.
check-pattern-too-many-lines = the pattern takes { $count } lines: at most { $limit } are read
check-pattern-negated-not-flag = {"{"}!{ $field }{"}"} negates a flag, and { $field } is not one: write {"{"}!entering{"}"} for a flag printed the other way round (inside, backfacing)
check-suggest-toward-origin = the incident vector is printed as wi, pointing back toward where the ray came from: add --convention toward-origin
check-suggest-no-normal = no normal is printed: if it is a local frame's z axis (Mitsuba, Tungsten), add --normal +z
check-suggest-no-side = nothing printed says whether the ray enters the object: print it ({"{"}entering{"}"}, or {"{"}!entering{"}"} for a flag such as backfacing) and pass --inside and --outside, or the ratio cannot be checked
check-suggest-none = no line of the first { $lines } looks like a refraction (an incident vector, a ratio and a result, each after its name): write the --pattern by hand (docs/check.md, Logs as programs print them)
check-situation-outward = taking { $normal } as the outward normal, as the indices given say nothing of the side
check-right-sampled = Right as a sampled reflection: { $call } refracts here ({ $returned }), but Mitsuba reflects with probability F = { $f }, and the null wo says it did. The diagnosis of the whole log checks that the code transmits at these angles elsewhere.
check-physics-sampled = Nothing came back where the ray refracts: right as a reflection sampled with probability F = { $f }, as renderers that choose reflection or refraction at random log it. The diagnosis of the whole log checks that the code transmits at these angles elsewhere.
check-fix-in = { $fix } (in { $place })
check-fix-part = { $part }; { $fix }
check-sides-entering = {" "}for rays entering the object
check-sides-leaving = {" "}for rays leaving the object
check-part-ratio = T is refracted with the ratio upside down{ $sides }: 1/μ in every part, in the test for total internal reflection too (the variable holding μ, or the ternary choosing it)
check-part-across = the part of T across N is scaled by 1/μ instead of μ (1/μ² of the right one){ $sides }, and the part along N is right: the ratio that multiplies the incident vector is upside down
check-part-along = the part of T along N, cosθt = √(1 − μ²·sin²θi), comes from 1/μ instead of μ{ $sides } (so does the test for total internal reflection), and the part across N is right: the ratio in cosθt is upside down
check-part-normal = the part of T along N has the wrong sign{ $sides }: the normal used does not face the ray
check-part-incident = the part of T across N has the wrong sign (T mirrored across the normal, bent the wrong way): the incident vector enters the formula the wrong way round
check-part-root = the part of T along N has the wrong sign: cosθt is put on the side the ray comes from, so T stays in its medium (the other root)
check-part-term = the term along N, (μ·cosθi − cosθt)·N, is subtracted where it must be added{ $sides }; the part across N is right
check-part-no-flip = for rays from the normal's far side, neither is the normal turned round nor the ratio inverted: T is the other root at 1/μ
check-fix-generic-ratio-across = scale the incident vector's part across N by μ = n_from / n_to, the same ratio cosθt is computed with
check-fix-generic-ratio-along = compute cosθt = √(1 − μ²·sin²θi) with μ = n_from / n_to, the ratio that scales the part across N (a cosine passed with its sign makes a helper invert the ratio again)
check-fix-generic-across-sign = the part across N is μ times the incident vector's own (μ·(W + cosθi·N) with W along the ray): take it with the incident vector's sign
check-fix-generic-never-transmits = the code never transmits these rays although they refract: if it samples reflection, its probability (F, the Fresnel reflectance) must stay below 1 there; report total internal reflection only where k = 1 − μ²·(1 − cos²θi) is negative
check-diagnosis-unchecked = Cannot be checked without knowing which side each ray comes from, { $place }: every line is right as far as its API's own rules go, but nothing in the log or the options tells a right ratio from a wrong one. { $fix }.
check-diagnosis-alike-no-field = The log cannot tell it from { $alike }.
check-unchecked-log-entering = Log entering on each line (true when the ray enters the object; {"{"}!entering{"}"} reads a flag such as inside or backfacing), or from and to
check-unchecked-pass-indices = Pass --inside and --outside (the indices inside and outside the object) with entering logged, or for pbrt and Mitsuba with the outward normal; or log from and to
check-mistake-across-sign = the part of the result across the normal has the wrong sign; the part along it is right (the result mirrored across the normal)
check-part-across-sign = the part of T across N has the wrong sign (T mirrored across the normal, bent the wrong way), and the part along N is right: the minus before the ratio times the incident vector is lost
check-tally-sampled = reflected (sampled)

# check: a log whose read lines are right but some lines could not be read (issue 40)
check-diagnosis-unreadable = { $lines } of the log's lines could not be read (each is answered with its error), and no line that was read is wrong: not a pass; correct those lines or the way they are read.

# check --suggest-pattern on JSON Lines (issue 40)
check-suggest-json-lines = the log is JSON Lines, whose keys name the fields: it needs no pattern

# check: calls whose printed digits cannot tell them right or wrong (issue 43, item 1)
check-undecided = Cannot tell from the printed digits: as printed the call looks like { $shown }, but numbers within their rounding make it a right call (a sign the verdict rests on, of N·I, of k or of a root, is closer to zero than the digits show). Print more digits to judge it.
check-diagnosis-too-few-digits = Cannot be told right or wrong from the printed digits, { $place }: each is wrong as printed but right for numbers within their rounding; the log's digits are too few to tell (a sign the verdict rests on, of N·I, of k = 1 − η²·(1 − (N·I)²) or of a root, may be closer to zero than they show). The log's precision is too low: { $fix }.
check-too-few-digits-fix = print every number with at least 6 significant digits (printf in C or a shader: %.6g; C#: ToString("G9"), Unity's Vector3: ToString("F6"); C++ streams: std::setprecision(9); Rust: {"{"}:?{"}"}; Python: repr)

# check --suggest-pattern and a log none of whose lines is judged (issue 43, item 6)
check-suggest-indices-read = --inside { $inside } --outside 1 are read from the ratio the lines print, for an object denser than what is outside it (glass or water in air): give your scene's indices if they differ
check-diagnosis-none-judged = None of the { $lines } lines the pattern read could be judged, so the pattern is not at fault; the first says: { $error }.
check-suggest-indices-assumed = --inside { $inside } --outside 1 are glass in air, assumed as the lines print no ratio: give your scene's indices if they differ

# check: vectors printed one number a line (issue 43, item 2)
check-field-column-vector = `{ $field }` is printed one number a line (as Eigen's cout << v prints a vector): its lines cannot be joined for sure; print each vector on one line (Eigen: v.transpose(); nalgebra: v.transpose() or {"{"}:?{"}"}; numpy: np.array2string(v, max_line_width=1000) or v.tolist())
check-suggest-column-vectors = the first { $lines } lines print vectors one number a line (as Eigen's cout << v does), which no pattern can join for sure: print each vector on one line (Eigen: v.transpose(); nalgebra: v.transpose() or {"{"}:?{"}"}; numpy: v.tolist()), each after its name, then ask again

# check: compound bugs named as causes (issue 43, item 4)
check-mistake-refracted-twice = refracted twice at one surface crossing: T is what the ratio squared (μ²) gives
check-mistake-fresnel-cos-sign = the code never transmits, at any angle, although k > 0: the cosine's sign lost where the Fresnel reflectance (or the choice to transmit) is computed
check-mistake-normals-mixed = the side decided with one normal (the geometric one) and refract given another (the shading one), turned by that decision: where the two disagree, the normal passed does not face the ray
check-fix-generic-refracted-twice = call refract once per surface crossing: T here is refracted again (or μ applied twice), as if with μ² = (n_from / n_to)²; keep the first T and trace the ray to the next surface
check-fix-generic-fresnel-cos-sign = the test for total internal reflection is not the cause (below 15° no ratio makes k negative): where F or the choice to transmit is computed, take cosθi with its sign off, |N·I| (or −N·I with N facing the ray); a negative cosine makes F ≥ 1, so the ray always reflects
check-fix-generic-normals-mixed = decide the side (entering, the ratio) and turn the normal passed to refract with the same normal: the shading one for both, or the geometric one for both (keep the geometric one for offsetting the ray's origin)
check-fix-normals-print = If the code decides the side with another normal than the one it passes (a geometric normal beside a shading one), log `entering` too: then the diagnosis can tell.
