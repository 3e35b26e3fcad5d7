# The window, its top bar, tools and panels, in English (the source language).
# Keys are kebab-case and start with what they belong to; placeables ({ $name }) carry
# numbers already written the local way (a decimal comma where the language uses one).

## The bar at the top

view-interface = One interface
view-scenes = Scenes
view-menu = View
view-accuracy = Accuracy vs time
# Names a scene kept from the last run in an error message about it.
view-last-run-scene = the last run's scene
# What the last undo or redo did ($change), and the view it switched to ($view).
travel-in-view = { $change } (in { $view })
tool-check = Check my T
tool-walk-through = Walk-through
tool-files = Save, open, share
tool-fresnel = Fresnel
presentation-toggle = 🖵 Presentation
presentation-toggle-hover = Full screen, everything larger (F11)
presentation-theme = Theme
presentation-theme-hover = Standard, or high contrast: black on white or white on black
presentation-colour-blind = Colour-blind safe
presentation-colour-blind-hover = Okabe–Ito colours only; every ray also has its own dash and label
presentation-simple = Simple view
presentation-simple-hover = Leaves out the three rejected sign choices and their (a, b): for a class that has not met the four candidates yet
presentation-look = Look
presentation-diagram-only = Diagram only (D)
language-menu = Language
language-hover = The language of the window. It follows the system's unless chosen here.
effects-menu = Effects
effects-menu-hover = Intensities (Fresnel) and wavefronts over the diagram
effects-intensities = Intensities
effects-intensities-hover = Draw the reflected and transmitted rays by their share of the light (Fresnel), with percentages
effects-wavefronts = Wavefronts
effects-wavefronts-hover = Plane wavefronts λ/μ apart in each medium, moving at c/μ: why the ray bends
effects-moving = Moving
effects-huygens = Huygens's construction
effects-huygens-hover = Two points of one front and the wavelet grown in the time between them

## The side panels ($key is the key that opens and closes them, such as F2)

panel-show-controls = Show the controls ({ $key })
panel-hide-controls = Hide the controls ({ $key })
panel-show-numbers = Show the numbers ({ $key })
panel-hide-numbers = Hide the numbers ({ $key })

## Under the diagram

canvas-hint = Drag W, N or a μ marker, or use − and + below; Tab or a click selects one for the arrow keys
canvas-hint-ray = ↑/→ +1°, ↓/← −1° (Shift: 0.1°) · +/− μt · Tab: next handle · drag to move
canvas-hint-index = ↑/↓ or +/− change the index by 0.01 (Shift: 0.001) · Tab: next handle

## The controls panel

controls-lesson = Lesson
controls-lesson-preset = Lesson preset
controls-lesson-own = Your own case
controls-lesson-changed = { $lesson }, changed
controls-reset = Reset
controls-reset-hover = Back to the start of the lesson chosen
controls-incidence = θi (degrees)
controls-convention = Convention
controls-convention-toward-origin = Section 1: W points back toward the origin
controls-convention-along-ray = Section 2: W is the direction of travel
controls-flip-normal = Flip N
controls-flip-normal-hover = Turn the normal around, as an outward normal is where a ray leaves glass
controls-snap = Snap W to θc
controls-snap-hover = Put W at the critical angle (needs μi > μt)
controls-snap-disabled = There is a critical angle only when μi > μt
controls-indices = Indices
# $symbol is μi or μt.
controls-index-value = { $symbol } value
controls-material = { $symbol } material
controls-custom-hint = custom: type a value above
controls-typed-vectors = Typed W and N
controls-typed-vectors-hint = Paste a student's logged vectors (x, y, z); press Enter.
controls-export-heading = Export picture (PNG or SVG)
controls-export-size = Size
controls-export-file = File
controls-export-file-hint = a .png or .svg name, or numbered diagram-001.png
controls-browse = Browse…
controls-export = Export picture
controls-exported = wrote { $path }
# A typed value that is not a number: $name is what it was typed for (θi, μt, W).
typed-not-a-number = { $name }: “{ $text }” is not a number
typed-not-three-numbers = { $name }: expected three numbers x, y, z, got { $count }

## The numbers panel

readouts-discriminant = Discriminant k = μ²wn² − μ² + 1 = { $k } ≥ 0: T exists
readouts-discriminant-tir = Discriminant k = μ²wn² − μ² + 1 = { $k } < 0: total internal reflection
# $section is the paper's section (1 or 2) whose equation 20 this is.
readouts-quadratic = Eq. { $section }.20, the quadratic in b: b² + 2a·wn·b + a² − 1 = 0 with a = { $a }, wn = { $wn }
readouts-no-roots = no real roots: the parabola no longer reaches zero
readouts-roots = roots b = { $roots } (the candidates' b for this a)
readouts-candidates = The four candidates
readouts-candidate = candidate
# The checks' column headings: squared Snell's law (the paper's eq. 10), the side of the surface T is on, the way T bends.
readouts-check-snell = eq. 10
readouts-check-side = side
readouts-check-bend = bend
readouts-no-candidates = No candidates: k < 0, so b has no real roots and no T exists.
readouts-candidates-note = All four are unit length and satisfy squared Snell (eq. 10): squaring cannot tell them apart. Only the side and the bend (the paper's μ = 1 argument) pick T.
readouts-warnings = Kernel warnings
readouts-no-warnings = No warnings: W and N are unit length and N faces the ray.
readouts-warning-not-unit = { $vector } has length { $length }, not 1: it was normalised (un-normalised vectors are a common ray-tracer bug)
readouts-warning-flipped = N points away from the incoming ray (as an outward normal does where a ray leaves a sphere): the kernel used −N, the normal that faces the ray
readouts-equations = The paper's equations, Section { $section }

## The walk-through

walk-previous = Previous step
walk-next = Next step
walk-animate = Animate μ to 1
walk-animating = Animating μ to 1 …
walk-animate-hover = Morph μt to μi: the chosen T converges to the incoming ray
walk-animate-disabled = μ is already 1 (μi = μt), or the morph is running
walk-step = Step { $number } of { $count }: { $title }

## The Fresnel tool

fresnel-plot-about = Fresnel plot: reflected and transmitted light against θi, the cursor at θi = { $angle }°
fresnel-click-hint = Click or drag on the plot to set θi.
fresnel-at = At θi = { $angle }°, from μi = { $mu_i } into μt = { $mu_t }.
fresnel-brewster = Brewster's angle θB = { $angle }°: no p light is reflected there (tan θB = μt/μi).
fresnel-equal-indices = Equal indices: no interface, nothing is reflected.
fresnel-critical = Critical angle θc = { $angle }°: beyond it all the light is reflected (sin θc = μt/μi).
fresnel-no-critical = No critical angle: the light goes into a medium of higher index.

## The Scenes view

scenes-scene = Scene
scenes-rays = Rays
# While a handle is dragged in a scene of many rays, the canvas shows one ray in $every until the pointer lets go.
scenes-draft = Draft while dragging: one ray in { $every }
scenes-reset-hover = the scene as its file has it
scenes-file = Scene file
scenes-open = Open file
scenes-save = Save file
scenes-save-hover = the scene as edited, in the scene format (TOML)
scenes-open-dialog-hover = Choose a scene file to open
scenes-saved = saved { $path }
scenes-opened = opened { $path }
scenes-hint = Drag the source (amber), its direction (the ring at the end of the dashed arrow) or a shape's handle; click a hit point to open it in One interface.
# In presentation: the switch that unfolds (and folds away) the scene's files, description and hint.
scenes-more = Files and hint
scenes-less = Fewer controls
scenes-picture-file = Picture file (.png or .svg)
scenes-picture-hint = a .png or .svg name, or numbered scene-001.svg
scenes-export-size = Export { $width }×{ $height }
scenes-tracing = tracing… { $percent } % (the last finished trace is shown)
scenes-cancel = Cancel
scenes-cancel-hover = stop tracing and show what was traced so far
scenes-stopped-segments = the trace stopped at its budget of { $budget } segments: the rays not yet followed are left out (fewer rays, a lower max_depth or a higher min_intensity trace fully)
scenes-stopped-tests = the trace stopped at its budget of { $budget } intersection tests: the rays not yet followed are left out (fewer rays, shapes or reflections trace fully)
scenes-stopped-cancelled = the trace was cancelled before it finished
# The box beside a hovered hit point: the media the ray goes from and into, their indices and the wavelength traced.
scenes-hit =
    { $from } into { $to } ({ $side ->
        [entering] entering
       *[leaving] leaving: the kernel turns N round
    })
    μi = { $mu_i }, μt = { $mu_t }, { $wavelength } nm
    click: open in One interface

## The accuracy view

accuracy-heading = What accuracy costs in time
accuracy-intro = Times every kernel variant at f32 and f64 on this machine and measures its error against a double-double oracle on random and hard incidences. The plot shows the largest hard-set error in units of ε·κ (what the algorithm loses beyond what the problem itself amplifies) against nanoseconds per ray.
accuracy-quick = Quick run (a few seconds)
accuracy-measure = Measure
accuracy-measuring = measuring… { $percent } %
accuracy-press-measure = Press Measure to run the benchmark.
# $variant names a kernel variant and its precision, such as "stable f32".
accuracy-verdict = Fastest within 10× of the best accuracy: { $variant } at { $time } ns per ray (hard-set error { $error } ε·κ).
accuracy-footnote = { $random } random and { $hard } hard problems on { $cpu }. Timings depend on what else the machine is doing; `refraction-explorer bench` gives the same figures on the command line.
accuracy-plot-about = Accuracy against time: { $count } variants, each marked by its shape and named beside it
accuracy-hover =
    { $name }
    { $time } ns, { $error } ε·κ
accuracy-column-variant = variant
accuracy-column-time = ns/ray
accuracy-column-random = max err random
accuracy-column-hard = max err hard
accuracy-column-eps-kappa = hard ε·κ
accuracy-column-tir = TIR mismatches

## The student's view: what a phone (or a link with view=student) shows, and the buttons that
## change W, N and the indices a step at a time

# $symbol: μi or μt
student-index = Index { $symbol }
student-full = Full explorer
student-full-hover = The whole explorer, with its tools and panels (for a large screen)
student-view = Student view
student-view-hover = The view for a phone: the question, the diagram across the screen and buttons a finger can take
