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
    // The link reads back as the state shown.
    let fragment = &expected[expected.find('#').unwrap()..];
    let mut other = Explorer::new(Default::default());
    other.open_link(fragment).unwrap();
    assert_eq!(other.state(), h.state().state());
    // The QR code: its picture is named with the link, and Q closes it.
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
    assert!(String::from_utf8_lossy(&refused.stderr).contains("not the address of a web page"));
    std::fs::remove_dir_all(&folder).unwrap();
}
