//! The diagram drawn in other languages: the banner, the labels and the walk-through speak
//! the chosen language and write numbers with its decimal separator.

use glam::Vec2;
use refraction_diagram::{Diagram, Figure, walkthrough_steps};
use refraction_i18n::{Locale, set_locale, t};
use refraction_model::Lesson;

/// Every label's text: those placed on the canvas and those left out for want of room.
fn label_texts(diagram: &Diagram) -> Vec<String> {
    let placed = diagram.shapes.iter().filter_map(|shape| match shape {
        Figure::Text(label) => Some(label.text.clone()),
        _ => None,
    });
    let left_out = diagram.left_out.iter().map(|label| label.text.clone());
    placed.chain(left_out).collect()
}

/// The diagram of glass into air at 45°, beyond the critical angle, drawn in `locale`; the
/// thread goes back to English before the test looks at it.
fn total_internal_reflection_in(locale: Locale) -> Diagram {
    let state = Lesson::BeyondCritical.state();
    assert!(
        state.refraction().is_tir(),
        "the state is past the critical angle"
    );
    set_locale(locale);
    let diagram = Diagram::new(&state, Vec2::new(1600.0, 1000.0));
    set_locale(Locale::En);
    diagram
}

#[test]
fn german_total_internal_reflection_says_totalreflexion_with_decimal_commas() {
    let diagram = total_internal_reflection_in(Locale::De);
    assert!(
        diagram.summary.to_lowercase().contains("totalreflexion"),
        "{}",
        diagram.summary
    );
    assert!(
        diagram.summary.contains("θi = 45,0°"),
        "{}",
        diagram.summary
    );
    let labels = label_texts(&diagram);
    assert!(
        labels.iter().any(|l| l == "Grenzwinkel θc = 41,8°"),
        "{labels:?}"
    );
    assert!(
        labels.iter().any(|l| l.starts_with("μi = 1,5 (Glas)")),
        "{labels:?}"
    );
    assert!(
        !labels
            .iter()
            .any(|l| l.contains("critical") || l.contains("reflected")),
        "English left in {labels:?}"
    );
}

#[test]
fn russian_total_internal_reflection_is_named_so() {
    let diagram = total_internal_reflection_in(Locale::Ru);
    assert!(
        diagram
            .summary
            .to_lowercase()
            .contains("полное внутреннее отражение"),
        "{}",
        diagram.summary
    );
    let labels = label_texts(&diagram);
    assert!(
        labels.iter().any(|l| l == "предельный угол θc = 41,8°"),
        "{labels:?}"
    );
    assert!(
        labels.iter().any(|l| l == "отражённый луч (весь свет)"),
        "{labels:?}"
    );
}

#[test]
fn the_same_diagram_in_english_is_unchanged() {
    let diagram = total_internal_reflection_in(Locale::En);
    assert!(diagram.summary.starts_with("TOTAL INTERNAL REFLECTION\n"));
    assert!(
        diagram.summary.contains("θi = 45.0°"),
        "{}",
        diagram.summary
    );
    let labels = label_texts(&diagram);
    assert!(
        labels.iter().any(|l| l == "critical angle θc = 41.8°"),
        "{labels:?}"
    );
}

#[test]
fn counts_take_each_languages_plural_forms() {
    set_locale(Locale::Ru);
    let russian = [1_usize, 3, 5, 21].map(|n| t!("diagram-count-kernel-calls", count = n));
    set_locale(Locale::De);
    let german = [1_usize, 2].map(|n| t!("diagram-count-source-rays", count = n));
    set_locale(Locale::En);
    assert_eq!(
        russian,
        [
            "1 вызов ядра",
            "3 вызова ядра",
            "5 вызовов ядра",
            "21 вызов ядра"
        ]
    );
    assert_eq!(german, ["1 Quellstrahl", "2 Quellstrahlen"]);
}

#[test]
fn the_walk_through_speaks_german_with_the_kernels_numbers() {
    let state = refraction_model::ExplorerState::default();
    set_locale(Locale::De);
    let steps = walkthrough_steps(state.refraction());
    set_locale(Locale::En);
    assert_eq!(steps[0].title, "Brechungsgesetz von Snellius");
    assert!(
        steps[0].equations[0]
            .substituted
            .contains("μ = μi/μt = 0,6669"),
        "{:?}",
        steps[0].equations[0]
    );
    assert!(
        steps[0].equations[0]
            .substituted
            .contains(", also sinθt = ")
    );
}

/// What `text` says in each of `locales`, the thread back in English after.
fn in_each(locales: &[Locale], text: impl Fn() -> String) -> Vec<String> {
    let all = locales
        .iter()
        .map(|&locale| {
            set_locale(locale);
            text()
        })
        .collect();
    set_locale(Locale::En);
    all
}

#[test]
fn the_fresnel_tool_and_the_checks_write_the_schools_notation() {
    let locales = [
        Locale::En,
        Locale::De,
        Locale::Es,
        Locale::Fr,
        Locale::PtBr,
        Locale::Ru,
    ];
    let brewster = in_each(&locales, || t!("fresnel-brewster", angle = "56,3"));
    let tangents = ["tan θB", "tan θB", "tg θB", "tan θB", "tg θB", "tg θB"];
    for (text, tangent) in brewster.iter().zip(tangents) {
        assert!(text.contains(&format!("({tangent} = μt/μi)")), "{text}");
    }
    let critical = in_each(&locales, || t!("fresnel-critical", angle = "41,8"));
    let sines = ["sin θc", "sin θc", "sen θc", "sin θc", "sen θc", "sin θc"];
    for (text, sine) in critical.iter().zip(sines) {
        assert!(text.contains(&format!("({sine} = μt/μi)")), "{text}");
    }
    let snell = in_each(&locales, || t!("readouts-check-snell"));
    assert_eq!(
        snell,
        ["eq. 10", "Gl. 10", "ec. 10", "éq. 10", "eq. 10", "ур. 10"]
    );
}
