## Lesson decks: the tool that builds a deck, the strip that shows its step, the notes window,
## the handout, and the built-in decks' titles, questions and notes

tool-deck = Lesson deck
deck-answer-hidden = The answer is hidden: predict, then reveal it

## The tool

deck-title-field = Deck title
deck-file = Deck file
deck-open-file = Open file
deck-save-file = Save file
deck-open-dialog-hover = Choose a deck file to open
deck-built-in = Built-in decks
deck-new = New deck
deck-new-hover = Start an empty deck; the one shown is closed (save it first)
deck-add-step = Add the current state as a step
deck-add-step-hover = A new step after the one shown, with the diagram as it is now: W, N, the indices, the view, its scene, the open tool and effects
deck-update-step = Keep the current state in this step
deck-update-step-hover = Dragging during a step changes only the diagram; this keeps what it shows now in the step (save the deck to keep it in the file)
deck-steps = Steps
deck-no-steps = No step yet: set up the diagram, then add it as a step.
# $number is the step's number, $title its title
deck-step-row = { $number }. { $title }
deck-move-up = Move the step up
deck-move-down = Move the step down
deck-delete = Delete the step
deck-step-title = Title
deck-step-question = Question for the class
deck-step-question-hint = none: the answer shows at once
deck-step-notes = Notes for the teacher
deck-untitled = Step { $number }
deck-edited = edited since it was saved
deck-saved = saved { $path }
deck-opened = opened { $path }
deck-not-saved = not saved: { $reason }
deck-nothing-to-save = The deck has no step to save: add one first.

## Stepping through a deck

# $number is the step shown, $count the deck's steps: "2 / 5"
deck-step-number = { $number } / { $count }
deck-previous = Previous step
deck-next = Next step
deck-reveal = Reveal the answer
deck-hide = Hide the answer
deck-notes-window = Notes window
deck-notes-window-hover = The teacher's notes in a window of their own, to put on the laptop's screen while the projector shows the diagram
deck-keys = Page Down, → or space: next step · Page Up or ←: previous · R: reveal the answer · N: notes window
deck-hidden-hint = R reveals the answer
deck-shown-hint = R hides the answer again
# $title is the deck's title
deck-notes-title = Notes: { $title }
deck-notes-none = No notes for this step.
# $title is the next step's title
deck-notes-next = Next: { $title }
deck-notes-last = This is the last step.

## The handout (render --lesson … --out handout.pdf)

deck-handout-question = Question
deck-handout-notes = Notes

## Built-in deck: Snell's law in ten minutes

deck-snell-title = Snell's law in ten minutes
deck-snell-1-title = From air into glass
deck-snell-1-question = The ray goes from air into glass. Does it bend toward the normal or away from it?
deck-snell-1-notes = Toward the normal: θt is smaller than θi, because glass is the denser medium. Drag W slowly from 0° to 80° and let the class read both angles.
deck-snell-2-title = Straight down the normal
deck-snell-2-question = A ray meets the surface along the normal. Which way does it bend?
deck-snell-2-notes = It does not bend: θi = θt = 0 for any pair of media. The light only slows down in the glass.
deck-snell-3-title = Snell's law
deck-snell-3-notes = The walk-through's first step: μi sin θi = μt sin θt. Ask two students to read θi and θt and work out both sides; they agree to the last digit shown.
deck-snell-4-title = From glass into air
deck-snell-4-question = Now the ray leaves the glass. Which way does it bend?
deck-snell-4-notes = Away from the normal: θt is larger than θi. Push θi up and T swings toward the surface: the next lesson's critical angle.
deck-snell-5-title = Through a slab of glass
deck-snell-5-question = The ray crosses a slab with parallel faces. In which direction does it leave?
deck-snell-5-notes = Parallel to the incoming ray, shifted sideways: the second refraction undoes the first. Drag the source to show that the shift grows with the angle.

## Built-in deck: total internal reflection and the fibre

deck-tir-title = Total internal reflection and the fibre
deck-tir-1-title = Leaving the glass
deck-tir-1-question = The ray leaves glass for air. What happens to T and to the reflected ray as θi grows?
deck-tir-1-notes = T swings toward the surface and grows fainter while the reflected ray grows brighter: Intensities draws each ray by its share of the light.
deck-tir-2-title = Just short of the critical angle
deck-tir-2-question = At what angle will T lie along the surface?
deck-tir-2-notes = At the critical angle: sin θc = μt/μi, 41.8° for glass into air. At 41° T nearly grazes the surface; the θc button in the controls puts W exactly there.
deck-tir-3-title = Past the critical angle
deck-tir-3-question = W is at 45°, past 41.8°. Where does the light go?
deck-tir-3-notes = All of it reflects: total internal reflection. The kernel finds no T, so there is no rejected candidate either; the banner says so.
deck-tir-4-title = From water into air
deck-tir-4-question = Is water's critical angle larger or smaller than glass's?
deck-tir-4-notes = Larger: arcsin(1/1.333) = 48.6°, because water is less dense than glass. At 50° the ray is trapped; a diver sees the sky only within a cone of 48.6°.
deck-tir-5-title = The fibre
deck-tir-5-question = The light enters the end of the fibre. Does it escape through the side?
deck-tir-5-notes = No: every hit on the side of the fibre is past the critical angle, so the ray reflects totally each time and is guided along the fibre. Turn the source until light leaks out.
deck-tir-6-title = The prism as a mirror
deck-tir-6-question = Why does a right-angle prism reflect like a mirror?
deck-tir-6-notes = Inside, the ray meets the long face at 45°, past the critical angle of the prism's glass (41.3°): it reflects totally and loses almost no light, which is why binoculars use prisms.

## Built-in deck: Fresnel and Brewster

deck-fresnel-title = Fresnel and Brewster
deck-fresnel-1-title = How much light reflects?
deck-fresnel-1-question = At 40° from air into glass, what share of the light is reflected?
deck-fresnel-1-notes = About 5 % (4 % at normal incidence): the rest goes on as T. The Fresnel plot shows R and T against θi with the diagram's θi marked.
deck-fresnel-2-title = Near grazing incidence
deck-fresnel-2-question = At 80°, is the reflection weaker or stronger than at 40°?
deck-fresnel-2-notes = Much stronger: it climbs toward 100 % at grazing incidence, which is why a lake mirrors the far shore but not the sky overhead.
deck-fresnel-3-title = Brewster's angle
deck-fresnel-3-question = p light meets glass at 56.3°. How much of it is reflected?
deck-fresnel-3-notes = None: at Brewster's angle, tan θB = μt/μi, the reflected and refracted rays are at right angles and p light is not reflected at all. Polarising sunglasses use it.
deck-fresnel-4-title = s light at the same angle
deck-fresnel-4-notes = s light still reflects, about 15 %: reflected light is partly polarised, most of all at Brewster's angle.
deck-fresnel-5-title = Reflections in a slab
deck-fresnel-5-question = How many rays leave a glass slab when every surface reflects a little?
deck-fresnel-5-notes = Each hit spawns a reflected ray, ever fainter: two strong rays, then a row of weak ones. The intensities fall at every bounce.

## Built-in deck: sign conventions for ray tracers

deck-signs-title = Sign conventions for ray tracers
deck-signs-1-title = The four candidates
deck-signs-1-question = Squaring the equations lets in four solutions. Which one is T?
deck-signs-1-notes = The three ghosts break one rule each: the wrong side (the other root for b), the wrong bend (the other sign of a) and reversed (both). Only T stays on the far side and bends the right way.
deck-signs-2-title = Leaving a droplet
deck-signs-2-question = The ray leaves a droplet, and N points out of the droplet, along the ray. What must the code do with N?
deck-signs-2-notes = Flip it: the kernel needs the normal that faces the ray. The dashed warning ray is the formula with N as given, the bug of a renderer that forgets the flip.
deck-signs-3-title = Section 1: W back toward the origin
deck-signs-3-question = Here W points back toward where the ray came from. Which sign in the formula changes?
deck-signs-3-notes = The sign of a: a = −μ in Section 1, +μ in Section 2. pbrt and Mitsuba pass wi this way; mixing the two conventions gives the wrong bend.
deck-signs-4-title = Section 2: W along the ray
deck-signs-4-notes = The same ray with W along it, as GLSL, glam and the book pass it: a = +μ, and T is the same vector as in Section 1.
deck-signs-5-title = Three mistakes in an API call
deck-signs-5-question = A renderer's T is wrong. Which three mistakes in the call to refract do students make most?
deck-signs-5-notes = The ratio upside down (μt/μi for μi/μt), the incident vector in the other convention, and the outward normal where the ray leaves. Paste a logged call into Check my T: it names the mistake and its fix.
