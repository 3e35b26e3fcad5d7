## Accessibility: what a screen reader says of the explorer (the names and values of the
## controls, the sentences that describe the diagram and what an edit changed), the step
## buttons beside the diagram, and the page's own controls in a browser.
## Placeables carry numbers already written the local way.

## The values of the four controls (their names are the handles', in diagram.ftl)

# A control's value in degrees: "40°", "41.8°"
access-degrees = { $angle }°
access-normal-up = straight up
access-normal-down = straight down
# $angle is how far N leans from straight up, in degrees
access-normal-right = { $angle }° right of straight up
access-normal-left = { $angle }° left of straight up
# An index with the name of the medium that has it: "1.5 (glass)"
access-index-named = { $index } ({ $name })

## The diagram in words

# $from and $to are each a medium with its index (access-medium-named or access-medium-custom)
access-media = The ray travels in { $from } and meets { $to }.
# "glass (μt = 1.5)"
access-medium-named = { $name } ({ $symbol } = { $index })
access-medium-custom = a medium with { $symbol } = { $index }
access-incidence-sentence = It meets the surface at θi = { $angle }° from the normal.
access-incidence-along-normal = It meets the surface along the normal: θi = 0°.
# $direction is access-normal-up, -down, -right or -left
access-normal-sentence = The normal N points { $direction }.
access-tir = Total internal reflection: θi is past the critical angle θc = { $critical }°, so there is no refracted ray and all light is reflected.
access-t-along-normal = T goes straight on along the normal: it does not bend.
access-t-straight = T goes straight on, { $angle }° from the normal: it does not bend.
access-t-toward = T bends toward the normal, { $angle }° from it.
access-t-away = T bends away from the normal, { $angle }° from it.
access-reflected = The reflected ray leaves at { $angle }° from the normal, on the other side of it.
access-critical = The critical angle is θc = { $critical }°.
access-flipped = N points away from the incoming ray, so the kernel uses −N.
# A phrase made a sentence
access-sentence = { $text }.
# One value that changed: "θi 41° → 43°"
access-change-value = { $name } { $before } → { $after }
# $changes lists the values that changed, $outcome what became of T
access-change = { $changes }: { $outcome }.
access-change-tir-begins = now past the critical angle { $critical }°; all light is reflected
access-change-tir-ends = now short of the critical angle { $critical }°; T leaves at { $angle }° from the normal
access-change-t = T at { $angle }° from the normal

## A lesson step and the view in words

# $number is the step shown, $count the deck's steps
access-step = Step { $number } of { $count }: { $title }.
access-question = Question: { $question }
# $view is the view's name in the bar
access-view = View: { $view }.
access-scene = Scene: { $title }.
access-scene-hidden = Its rays are drawn up to the first surface they meet.

## The step buttons beside the diagram (their names and hovers)

access-incidence-decrease = Decrease θi by 1°
access-incidence-increase = Increase θi by 1°
access-normal-turn-left = Turn N 1° to the left
access-normal-turn-right = Turn N 1° to the right
# $symbol is μi or μt, $step the change ("0.01")
access-index-decrease = Decrease { $symbol } by { $step }
access-index-increase = Increase { $symbol } by { $step }

## In a browser: the page's own controls beside the canvas

access-page-controls = The diagram's controls
access-page-keys = In the explorer below, Tab moves through its buttons and fields and the arrow keys turn a selected handle; Esc, then Shift+Tab comes back to these controls.
access-page-typing = Text being typed into the explorer
# The page's title: the view's name and the scene shown
access-title-scene = { $view }: { $scene }
