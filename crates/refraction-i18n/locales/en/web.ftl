# The explorer in a browser and the links to it, in English (the source language): the link
# of what the class sees (Copy link, the QR code, the web build's address), a link that
# cannot be opened, the handout with its links, and what a browser page does otherwise (its
# file picker, downloads, full screen, clipboard and one thread).

## Links and the QR code

link-web-base = Web address
link-web-base-hover = Where the class opens the explorer in a browser: the address of the folder that cargo xtask web writes, hosted (in a browser, the page's own address)
link-copy = 🔗 Copy link
link-copy-hover = Copy the link that opens what the class sees now (this step of the deck, or this state) in a browser
link-copied = Link copied.
link-qr = QR code
link-qr-hover = Show the link of what the class sees as a QR code over the diagram (Q)
link-no-web-base = No web address is set: type the address where the class opens the explorer in a browser.
link-file-address = This page was opened from a file: a phone cannot open this link. Host the folder and type its address.
# $format: png or svg
link-qr-save = Save as { $format }
# $bytes: the link's length
link-qr-too-long = The link is too long for a QR code ({ $bytes } bytes): copy it instead.
link-qr-close = Q or Esc closes
# The QR code dialog: its button that takes the web address typed
link-qr-show = Show the QR code
link-notice-close = Close (Esc)

## A link that cannot be opened ($reason: why, as below)

link-cut-short = the link is cut short: copy it again, whole
# $reason: where the link is damaged, or the state reader's own words
link-malformed = the link is damaged ({ $reason })
# $part: the part of the link this version does not read, such as v=2
link-newer = the link was made by a newer version of the explorer ({ $part }): open it where that version runs
# $step: the step as the link gives it
link-bad-step = the step { $step } is not a number from 1 on
link-state-and-lesson = the link names both a state and a lesson
link-step-without-lesson = the link names a step but no lesson
# $name: the lesson the link names; $names: the built-in lessons
link-no-lesson = there is no built-in lesson called { $name } (the lessons: { $names })
# $count: the number of steps of the lesson
link-no-step = the lesson { $name } has { $count } steps, not { $step }
# $reason: one of the messages above
web-link-not-opened = This link could not be opened: { $reason }. The explorer shows what it showed before.

## The handout

handout-export = 📄 Handout (PDF)
handout-export-hover = Write the deck as a handout: one page per step, with its diagram, question, notes and, when a web address is set, its link and QR code

## In a browser

web-page-loading = Loading the refraction explorer…
# $reason: the browser's own words
web-page-failed = This browser could not start the refraction explorer ({ $reason }). A recent Firefox, Chrome, Edge or Safari with WebGL 2 runs it.
web-open-through-picker = A browser page opens the files you choose in the browser's file picker (or drop on the page).
web-choose-file = Choose a file…
web-saved-as-download = The file is downloaded: the browser saves it in its downloads folder.
web-download = Download
# $reason: the browser's own words
web-full-screen-refused = The browser did not enter or leave full screen ({ $reason }): use its own full-screen key (F11) or menu.
web-copy-refused = The browser did not allow copying ({ $reason }): select the text and press Ctrl+C.
web-not-secure = a page opened from a file or over http may not use the clipboard
web-one-thread = In a browser this runs on the page's only thread: the page does not respond until it is done.

## The installable page, a panic over the page, the page's file reads, inside another page (issue 44)

web-manifest-description = Drag the ray, the normal and the indices of refraction, and watch the refracted ray, its four sign candidates and total internal reflection respond.
web-crash-title = The explorer stopped: an error in its program. What it said:
web-crash-reload = Reload the page
web-crash-reopen = Reload with the last state, so that nothing is lost (or copy this link to keep it):
# $name: the file's name; $reason: the browser's own words
web-read-failed = The browser could not read { $name } ({ $reason }).
# $name: the file's name; $size and $limit: sizes in MB
web-file-too-large = { $name } is { $size } MB: the page opens files of at most { $limit } MB.
web-open-in-tab = ↗ Open in a new tab
web-open-in-tab-hover = This page is inside another page: open the explorer in a tab of its own for full screen and copying

# Nothing lost (issue 40): links refused with a clear reason, the web address checked in one place.
# $part: the part of the link, as written
link-part-without-name = a part of the link has no name (“{ $part }”)
link-part-twice = the link gives { $part } twice
# $reason: one of the link-web-base-* reasons below
link-web-base-refused = This web address cannot be used: { $reason }.
link-web-base-empty = no address was given
# $scheme: what the address starts with, before its colon
link-web-base-scheme = it starts with “{ $scheme }”, not http://, https:// or file://
# $character: the character, escaped as in Rust source
link-web-base-unseen = it holds { $character }, which an address cannot hold (no spaces, control characters or invisible marks)
link-web-base-escape = “{ $escape }” is no percent escape (a % is followed by two hexadecimal digits)
link-web-base-credentials = it holds a user name or password, which every link and QR code would show
link-web-base-too-long = it is { $bytes } bytes long: at most { $most } keep the links' QR codes readable on paper
link-web-base-port = its port is not a number from 0 to 65535
# $reason: the URL parser's own words
link-web-base-host = its host is missing or is no valid name or IP address ({ $reason })
storage-web-base-unusable = The web address kept from last time is not used: { $reason }.
# $reason: what reading it said
storage-state-unreadable = The state kept from last time could not be read ({ $reason }): the explorer starts from the default state.
