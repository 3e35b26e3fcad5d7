//! `--lang` end to end: what is drawn speaks the language asked for (`render`'s labels, in an
//! SVG where they are text), what scripts read does not (`check`'s JSON), and an unknown code
//! is refused with the codes there are.

use crate::cli;

use cli::{render, run};

#[test]
fn render_draws_its_labels_in_the_language_asked_for() {
    let out = cli::folder("languages-cli", "svg").join("diagram.svg");
    let output = render(&["--lang", "de", "--out", out.to_str().unwrap()]);
    assert!(output.status.success(), "{output:?}");
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.contains("μt = 1,5 (Glas)"),
        "German label with a decimal comma"
    );
    assert!(!svg.contains("(glass)"), "no English label left");
}

#[test]
fn check_answers_the_same_json_in_every_language() {
    // The wrong-side candidate of the default problem: an explanation with numbers in it.
    let line = r#"{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"t_yours":[0.4,0.9165,0]}"#;
    let english = run(&["check"], line);
    for code in ["de", "ru", "pt-BR"] {
        let other = run(&["--lang", code, "check"], line);
        assert_eq!(other.stdout, english.stdout, "--lang {code}");
        assert_eq!(other.status.code(), english.status.code());
    }
    assert!(!english.stdout.is_empty());
}

#[test]
fn an_unknown_language_is_refused_with_the_codes_there_are() {
    let output = render(&["--lang", "tlh", "--out", "-"]);
    assert_eq!(output.status.code(), Some(2));
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(message.contains("`tlh`"), "{message}");
    assert!(message.contains("en, de, es, fr, pt-BR, ru"), "{message}");
}
