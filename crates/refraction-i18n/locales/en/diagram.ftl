# What is drawn on the diagram, the scenes and the plots, in English (the source language).
# Diagram labels must stay short: the label placer leaves out a label that does not fit.
# Placeables carry numbers already written the local way.

## The interface diagram

diagram-ghost-wrong-side = other b root: wrong side
diagram-ghost-wrong-bend = other a sign: bends wrong way
diagram-ghost-reversed = both signs wrong: −T
# A medium's index and name, e.g. "μt = 1.5 (glass)".
diagram-medium = { $mu } = { $index } ({ $name })
diagram-medium-of-ray = the ray's medium
diagram-medium-entered = the medium it enters
diagram-material-vacuum = vacuum
diagram-material-air = air
diagram-material-water = water
diagram-material-glass = glass
diagram-material-diamond = diamond
diagram-material-custom = custom
diagram-banner-tir =
    TOTAL INTERNAL REFLECTION
    k = { $k } < 0: no real root for b, no refracted ray; all light is reflected (θi = { $theta_i }°)
diagram-banner-toward-origin = W points back toward the origin, so a = −μ
diagram-banner-along-ray = W is the direction of travel, so a = +μ
diagram-banner-section = Section { $section }: { $words }
# The banner on paper while the answer is hidden: the convention without the sign of a,
# which a question may ask for
diagram-banner-asked-toward-origin = Section 1: W points back toward the origin
diagram-banner-asked-along-ray = Section 2: W is the direction of travel
# The banner's second line: the angles of incidence (i) and refraction (t) and k.
diagram-banner-numbers = θi = { $i }°   θt = { $t }°   k = { $k } ≥ 0: T exists
diagram-critical-angle = critical angle θc = { $angle }°
diagram-kernel-normal = −N: the normal the kernel uses
diagram-outward-normal-bug =
    outward-normal bug:
    the paper's T with N as given
diagram-index-scale = index μ
diagram-incoming-ray = incoming ray
diagram-normal-incidence = normal incidence: W, N and T lie on one line
diagram-normal-incidence-asked = normal incidence: W lies along N
diagram-reflected = reflected
diagram-reflected-light = reflected ({ $light })
diagram-reflected-all = reflected ray (all the light)
diagram-w-along-ray = W (along the ray)
diagram-w-toward-origin = W (toward the origin)
diagram-transmitted = T: transmitted
diagram-no-reflected-ray = { $label }: no reflected ray

## Handles (what a screen reader says)

diagram-handle-w = Angle of incidence θi (W)
diagram-handle-n = Direction of the normal N
diagram-handle-mu-i = Index μi of the ray's medium
diagram-handle-mu-t = Index μt of the medium entered
diagram-handle-source = Source handle
diagram-handle-aim = Source direction handle
diagram-handle-shape = Shape { $number } handle ({ $medium })

## Lessons, themes, light, animations

diagram-lesson-air-to-glass = Air → glass, 40°
diagram-lesson-beyond-critical = Glass → air beyond θc
diagram-lesson-normal-incidence = Normal incidence
diagram-lesson-brewster = Brewster's angle
diagram-lesson-droplet-exit = A droplet's exit
diagram-angle-out-of-range = θi must be at least 0° and less than 90°, got { $angle }°
diagram-theme-standard = Standard
diagram-theme-black-on-white = Black on white
diagram-theme-white-on-black = White on black
diagram-light-s = s light
diagram-light-p = p light
diagram-light-unpolarised = unpolarised light
diagram-animation-mu = μ → 1: T turns into W
diagram-animation-sweep = Sweep θi to grazing: total internal reflection appears
diagram-animation-wavefronts = Moving wavefronts

## The candidates table

diagram-role-chosen = T (chosen)
diagram-role-wrong-side = wrong side
diagram-role-wrong-bend = wrong bend
diagram-role-reversed = reversed
diagram-rule-wrong-side = wrong side of the surface: the other root for b sends the ray back into the medium it came from
diagram-rule-wrong-bend = bends the wrong way: the other sign of a flips the part along the surface, so it does not become the incoming ray as μ → 1
diagram-rule-reversed = both wrong (wrong sign of a and wrong root for b): it is −T, pointing back where the ray came from

## A traced scene

diagram-screen = screen
diagram-index-at-wavelength = n = { $index } at { $wavelength } nm
diagram-stopped-at = stopped at { $count ->
        [one] { $count } segment
       *[other] { $count } segments
    }
diagram-count-kernel-calls = { $count ->
        [one] { $count } kernel call
       *[other] { $count } kernel calls
    }
diagram-count-tir = { $count ->
        [one] { $count } total internal reflection
       *[other] { $count } total internal reflections
    }
diagram-count-reflections = { $count ->
        [one] { $count } reflection spawned
       *[other] { $count } reflections spawned
    }
diagram-count-fresnel = { $count ->
        [one] { $count } Fresnel evaluation
       *[other] { $count } Fresnel evaluations
    }
diagram-count-wavelengths = { $count ->
        [one] { $count } wavelength
       *[other] { $count } wavelengths
    }
diagram-count-source-rays = { $count ->
        [one] { $count } source ray
       *[other] { $count } source rays
    }
diagram-count-equal-index-skips = { $count ->
        [one] { $count } equal-index skip
       *[other] { $count } equal-index skips
    }
diagram-count-absorption = { $count ->
        [one] { $count } absorption evaluation
       *[other] { $count } absorption evaluations
    }
diagram-legend-colour = colour:
diagram-legend-white-traced = white light, traced at { $wavelength } nm
diagram-legend-white-then = white light, then
diagram-legend-nm = nm
diagram-legend-opacity = opacity: intensity
diagram-legend-hits = hits:
diagram-hit-entering = entering
diagram-hit-leaving = leaving (N turned round)
diagram-hit-tir = total internal reflection

## Waves

diagram-fronts =
    fronts λ/{ $index } apart
    speed c/{ $index } = { $speed } c
diagram-huygens-touch =
    Huygens: the front reaches A Δt after B;
    B's wavelet grows vt·Δt, the new front touches it
diagram-huygens-tir =
    Huygens: B's wavelet outgrows BA:
    no tangent from A, total internal reflection

## The key equations

diagram-eq-toward-origin-a = W points away from T, so the paper takes a = −μ
diagram-eq-along-ray-a = W points along T, so the paper takes a = +μ
diagram-eq-no-refracted-ray = no real (a, b): there is no refracted ray
diagram-eq-no-b-with-10 = no real b satisfies it together with eq. 10
# An equation with numbers, and what follows from it.
diagram-eq-so = { $given }, so { $then }
diagram-eq-negative-root = √({ $k }) of a negative number: no real b (total internal reflection)
diagram-eq-or = or
diagram-eq-outward-normal-bug = with N as given b = { $b }: the wrong root, T goes back (the outward-normal bug); the kernel uses −N and gets b = { $kernel_b } for N
diagram-step-wn-flipped = W·N = { $given }: N faces away from the ray, so the kernel uses −N: wn = { $wn }, cosθi = { $cos }
diagram-eq-no-root = no real root to choose
diagram-eq-no-theta-t = { $given }, so sinθt would be { $sin_t } > 1: no angle θt exists
diagram-eq-with-chosen = { $lhs } = { $rhs } with the chosen (a, b)
diagram-eq-no-ab-with-12 = no real (a, b) satisfies it with eq. 12
# The sine's name in the walk-through's formulas, as the language's schools write it.
diagram-math-sin = sin

## The walk-through

diagram-step-snell = Snell's law
diagram-step-snell-text = The ray bends so that μi·sinθi = μt·sinθt; with μ = μi/μt, the sine of the angle in the new medium is μ times the old one.
diagram-step-square = Square it, and use cosines
diagram-step-square-text = Squaring lets the cosines (dot products) replace the sines, but it also lets in false solutions: a solution and its signed opposite both satisfy it.
diagram-step-decomposition = T as a·W + b·N
diagram-step-decomposition-text = T lies in the plane of W and N, so it is a·W + b·N; the cosines become dot products with wn = W·N, and cosθt = −a·wn − b. The ray travels along { $travel }.
diagram-step-constraints = The two squared constraints
diagram-step-constraints-text = Squared Snell (eq. 10) and unit length (eq. 12) are two quadratics in a and b. Four pairs (a, b) satisfy both: T and the three ghosts. Nothing in them tells the four apart.
diagram-step-roots-a = The two roots for a
diagram-step-roots-a-text = Substituting eq. 12 into eq. 10 leaves a² = μ²: a = +μ or a = −μ. The other sign mirrors T across the normal: it bends the wrong way.
diagram-step-choice-a = Choosing a: the limit μ = 1
# "Animate μ to 1" is the button's name in the window.
diagram-step-choice-a-text = When μ = 1 nothing bends, so T must be the direction of travel, { $travel }. Only a = { $a } gives that; the other sign would give the mirror image. Press “Animate μ to 1” to watch T converge to { $travel } and the ghosts not.
diagram-step-choice-a-typo = (Section 2's text then says “once we decide upon using the a = −μ solution”: it means a = +μ, the one it chose.)
diagram-step-roots-b = The two roots for b
diagram-step-roots-b-text = With a fixed, eq. 12 is a quadratic in b with the roots −a·wn ± √k (k = μ²wn² − μ² + 1). The other root mirrors T across the surface, back into the medium the ray came from. k < 0 means no real root: total internal reflection.
diagram-step-choice-b = Choosing b
diagram-step-choice-b-text = Of the two roots only the one with −√k becomes b = 0 at μ = 1, when T must be the incoming ray unchanged; the other sends T back across the surface.
diagram-step-choice-b-flipped = The root with −√k goes to b = 0 at μ = 1, so T becomes the incoming ray. But here N points along the ray (an outward normal where the ray leaves the medium): with N as given that root is the wrong side. The kernel turns N around first.

## The Fresnel view

diagram-fresnel-title = How much light is reflected, from μi = { $mu_i } into μt = { $mu_t }
diagram-fresnel-axis = angle of incidence θi
diagram-fresnel-brewster = Brewster's angle θB = { $angle }°: no p light reflected
diagram-fresnel-critical = critical angle θc = { $angle }°: all reflected beyond
diagram-fresnel-brewster-short = Brewster θB = { $angle }°
diagram-fresnel-critical-short = critical θc = { $angle }°
diagram-curve-rs = Rs (s light reflected)
diagram-curve-rp = Rp (p light reflected)
diagram-curve-r = R (unpolarised, reflected)
diagram-curve-t = T (unpolarised, transmitted)
diagram-fresnel-source =
    Fresnel's equations for the power reflected (Hecht, Optics, ch. 4): Rs = ((μi·cosθi − μt·cosθt)/(μi·cosθi + μt·cosθt))², Rp = ((μt·cosθi − μi·cosθt)/(μt·cosθi + μi·cosθt))², T = 1 − R,
    from the kernel's own cosθi and cosθt, without trigonometry; unpolarised light is the mean of s and p. Past the critical angle all light is reflected.

## The accuracy plot

diagram-accuracy-title = Accuracy against time on this machine
diagram-accuracy-error-axis = largest hard-set error, in ε·κ (log)
diagram-accuracy-time-axis = time per ray, ns (log)
diagram-accuracy-bound = the default kernel's bound, 32 ε·κ
diagram-accuracy-markers = hollow: f32, filled: f64

## The built-in scenes (their titles and descriptions, and the names of their media)

diagram-scene-dispersing-prism = Dispersing prism
diagram-scene-dispersing-prism-about = White light through an equilateral F2 flint prism near minimum deviation: violet bends most.
diagram-scene-droplet = Water droplet (rainbow)
diagram-scene-droplet-about = White light enters a droplet, reflects inside and leaves; dispersion spreads the primary rainbow near 138 degrees deviation.
diagram-scene-fibre = Optical fibre
diagram-scene-fibre-about = Repeated total internal reflection guides light along a core; the steepest rays leak into the cladding.
diagram-scene-interface = Single interface
diagram-scene-interface-about = A ray in air meets flat glass (n = 1.5) at 45 degrees and bends toward the normal.
diagram-scene-lens = Converging lens
diagram-scene-lens-about = A biconvex BK7 lens focuses a parallel beam onto a screen; marginal rays focus short of it.
diagram-scene-right-angle-prism = Right-angle prism
diagram-scene-right-angle-prism-about = Total internal reflection at the hypotenuse turns the beam through 90 degrees.
diagram-scene-slab = Glass slab
diagram-scene-slab-about = Parallel faces: the exit ray is parallel to the entry ray, shifted sideways. Fresnel losses at both faces, absorption inside.
diagram-medium-core = core
diagram-medium-cladding = cladding
diagram-medium-f2 = F2 flint
diagram-medium-bk7 = BK7
diagram-medium-tinted-bk7 = tinted BK7
