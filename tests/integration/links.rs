//! Links to the web build (issue 33), on the desktop: *Copy link* and the QR code in the
//! window, a link opened (what a browser page does with its address's fragment), and the
//! handout's links and QR codes (`render --lesson … --web-base`).

use crate::cli;
use crate::common;

use cli::render;
use common::{click, drag, harness, harness_for, leaving_glass, type_into};
use egui::{Key, Role};
use egui_kittest::kittest::Queryable as _;
use refraction_explorer::app::{Explorer, Launch};
use refraction_tools::link::{self, Link};

const BASE: &str = "https://school.example/explorer/";

#[test]
fn copy_link_gives_the_state_at_the_web_address_and_the_qr_code_shows_it() {
    let mut h = harness(leaving_glass());
    click(&mut h, "💾 Save, open, share");
    assert!(h.query_by_label_contains("No web address is set").is_some());
    type_into(&mut h, "Web address", BASE);
    let expected = link::url(BASE, &Link::State(Box::new(leaving_glass())));
    assert!(h.query_by_label(&expected).is_some(), "the link is shown");
    click(&mut h, "🔗 Copy link");
    assert!(h.query_by_label("Link copied.").is_some());
    // The link reads back as the state shown, to far below what the diagram shows.
    let fragment = &expected[expected.find('#').unwrap()..];
    let mut other = Explorer::new(Default::default());
    other.open_link(fragment).unwrap();
    let (opened, shown) = (other.state(), h.state().state());
    assert!((opened.incidence_degrees() - shown.incidence_degrees()).abs() < 1e-4);
    assert_eq!((opened.mu_i(), opened.mu_t()), (shown.mu_i(), shown.mu_t()));
    // The QR code: its picture is named with the link for the students' phones (the student's
    // view), and Q closes it.
    let expected = format!("{expected}&view=student");
    click(&mut h, "QR code");
    let qr = h.get_by_role_and_label(Role::Figure, &expected);
    assert!(qr.rect().width() >= 300.0, "large: {:?}", qr.rect());
    h.key_press(Key::Q);
    h.run();
    assert!(h.query_by_role_and_label(Role::Figure, &expected).is_none());
    h.key_press(Key::Q);
    h.run();
    assert!(
        h.query_by_role_and_label(Role::Figure, &expected).is_some(),
        "Q opens it too"
    );
}

/// Q with no web address set, the documented first use in front of a class: the dialog's
/// field has the keyboard at once and takes the whole address typed key by key (it took one
/// letter, then showed that letter's QR code); Enter shows the QR code of the whole link.
#[test]
fn the_qr_dialog_takes_a_whole_address_typed_key_by_key() {
    let mut h = harness(leaving_glass());
    h.key_press(Key::Q);
    h.run();
    assert!(h.query_by_label_contains("No web address is set").is_some());
    h.run();
    for key in BASE.chars() {
        h.event(egui::Event::Text(key.to_string()));
        h.run();
    }
    let field = h.get_by_role_and_label(Role::TextInput, "Web address");
    assert_eq!(
        field.value().as_deref(),
        Some(BASE),
        "every key typed is kept"
    );
    assert_eq!(h.state().web_base(), "", "nothing is set before Enter");
    h.key_press(Key::Enter);
    h.run();
    h.run();
    let expected = link::student_url(BASE, &Link::State(Box::new(leaving_glass())));
    assert_eq!(h.state().web_base(), BASE);
    let qr = h.get_by_role_and_label(Role::Figure, &expected);
    assert!(qr.rect().width() >= 300.0, "large: {:?}", qr.rect());
    // The code is drawn from the link it is named with (one `url` in the dialog), and the
    // link is written under it.
    assert_eq!(
        h.query_all_by_label(&expected).count(),
        2,
        "the code and the link"
    );
}

/// On a 1280×720 projector (presentation) the QR code of a state's link stays inside the
/// window with its quiet zone, the link and the buttons under it (it ran off the top), and
/// the link's numbers are as short as the diagram shows them.
#[test]
fn the_qr_code_stays_inside_a_projectors_window() {
    let launch = Launch {
        state: Some(leaving_glass()),
        web_base: Some(BASE.to_owned()),
        present: true,
        ..Launch::default()
    };
    let mut h = common::harness_sized(Explorer::launched(launch, |_| None), (1280.0, 720.0));
    h.key_press(Key::Q);
    h.run();
    h.run();
    let expected = link::student_url(BASE, &Link::State(Box::new(leaving_glass())));
    assert!(
        expected.len() < 150,
        "{} characters: {expected}",
        expected.len()
    );
    let window = h.ctx.content_rect();
    let qr = h.get_by_role_and_label(Role::Figure, &expected).rect();
    assert!(window.contains_rect(qr), "{qr:?} in {window:?}");
    assert!(qr.height() >= window.height() * 0.4, "large: {qr:?}");
    let close = h.get_by_label("Save as svg").rect();
    assert!(
        window.contains_rect(close),
        "the buttons: {close:?} in {window:?}"
    );
}

#[test]
fn a_lesson_link_opens_the_step_and_the_link_follows_what_the_class_sees() {
    let launch = Launch {
        web_base: Some(BASE.to_owned()),
        ..Launch::default()
    };
    let mut explorer = Explorer::launched(launch, |_| None);
    explorer.open_link("#lesson=snell&step=2").unwrap();
    assert_eq!(explorer.lesson().current().map(|(i, _)| i), Some(1));
    assert_eq!(
        explorer.link_url().as_deref(),
        Some("https://school.example/explorer/#lesson=snell&step=2")
    );
    // Dragging W during the step: the class now sees a state, not the step as saved.
    let mut h = harness_for(explorer);
    let w = h.get_by_label("Angle of incidence θi (W)").rect().center();
    drag(&mut h, w, w + egui::vec2(40.0, -20.0));
    let seen = h.state().link_url().unwrap();
    assert!(
        seen.starts_with("https://school.example/explorer/#state=%7B"),
        "{seen}"
    );
}

#[test]
fn a_broken_link_changes_nothing_and_says_why() {
    let mut explorer = Explorer::new(leaving_glass());
    for (fragment, why) in [
        ("#state=%7B%22w%22:%5B0.8", "cut short"),
        ("#state=%7Bnot%7D", "damaged"),
        ("#lesson=snell&step=99", "not 99"),
        ("#lesson=nonesuch", "no built-in lesson called nonesuch"),
        ("#lesson=snell&v=2", "newer version"),
        ("#zoom=2", "newer version"),
    ] {
        let said = explorer.open_link(fragment).unwrap_err().to_string();
        assert!(said.contains(why), "{fragment}: {said}");
        assert_eq!(explorer.state(), &leaving_glass(), "{fragment}");
        assert!(explorer.lesson().current().is_none(), "{fragment}");
    }
    assert_eq!(explorer.open_link(""), Ok(()));
}

#[test]
fn the_handout_carries_each_steps_link_and_qr_code() {
    let folder = cli::folder("links", "handout");
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("snell.pdf");
    let out = render(&[
        "--lesson",
        "snell",
        "--out",
        path.to_str().unwrap(),
        "--web-base",
        BASE,
    ]);
    assert!(out.status.success(), "{out:?}");
    let bytes = std::fs::read(&path).unwrap();
    let pages = pdf_extract::extract_text_from_mem_by_pages(&bytes).unwrap();
    let bare = |text: &str| text.split_whitespace().collect::<String>();
    for (i, page) in pages.iter().enumerate() {
        let link = format!("{BASE}#lesson=snell&step={}", i + 1);
        assert!(bare(page).contains(&link), "page {}: {page}", i + 1);
    }
    // Without --web-base, no link; a web address must be one.
    let plain = folder.join("plain.pdf");
    let out = render(&["--lesson", "snell", "--out", plain.to_str().unwrap()]);
    assert!(out.status.success(), "{out:?}");
    let text = pdf_extract::extract_text_from_mem(&std::fs::read(&plain).unwrap()).unwrap();
    assert!(!text.contains("#lesson="), "{text}");
    let refused = render(&[
        "--lesson",
        "snell",
        "--out",
        plain.to_str().unwrap(),
        "--web-base",
        "ftp://x",
    ]);
    assert!(!refused.status.success());
    assert!(
        String::from_utf8_lossy(&refused.stderr)
            .contains("cannot start a link: it starts with `ftp`")
    );
    std::fs::remove_dir_all(&folder).unwrap();
}
