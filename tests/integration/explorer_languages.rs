//! The window in another language, driven as a German teacher would: the words of the bar,
//! θi and an index typed with a decimal comma, and the language menu, whose choice the next
//! run keeps and which wins over the system's language.

use crate::common;

use common::{click, harness_for, type_into};
use egui::Role;
use egui_kittest::kittest::Queryable as _;
use refraction_explorer::app::{Explorer, Launch};
use refraction_i18n::{Locale, t};
use refraction_model::ExplorerState;

/// An explorer that opens as a real run does, on a German system, with nothing saved.
fn german_system() -> Explorer {
    let launch = Launch {
        system_language: Some(Locale::De),
        ..Launch::default()
    };
    Explorer::launched(launch, |_| None)
}

#[test]
fn a_german_teacher_types_decimal_commas() {
    let mut h = harness_for(german_system());
    assert_eq!(h.state().language(), Locale::De);
    assert!(
        h.query_by_label("🖵 Präsentation").is_some(),
        "the bar in German"
    );
    type_into(&mut h, "θi (Grad)", "45,5");
    let degrees = h.state().state().incidence_degrees();
    type_into(&mut h, "Wert von μt", "1,33");
    let mu_t = h.state().state().mu_t();
    refraction_i18n::set_locale(Locale::En);
    assert!((degrees - 45.5).abs() < 1e-9, "θi = {degrees}");
    assert_eq!(mu_t, 1.33);
}

#[test]
fn the_language_chosen_in_the_bar_is_kept_and_wins_over_the_systems() {
    let mut h = harness_for(german_system());
    h.get_by_role_and_label(Role::ComboBox, "Sprache").click();
    h.run();
    click(&mut h, "Русский");
    let speaking = h.state().language();
    let bar_in_russian = h.query_by_label(&t!("presentation-toggle")).is_some();
    let look = h.state().presentation().look();
    refraction_i18n::set_locale(Locale::En);
    assert_eq!(speaking, Locale::Ru);
    assert!(bar_in_russian);
    // The next run, on the same German system, speaks Russian; `--lang` wins for one run.
    let saved = |key: &str| (key == "explorer_look").then(|| look.clone());
    let next = Explorer::launched(
        Launch {
            system_language: Some(Locale::De),
            ..Launch::default()
        },
        saved,
    );
    assert_eq!(next.language(), Locale::Ru);
    let for_one_run = Explorer::launched(
        Launch {
            system_language: Some(Locale::De),
            language: Some(Locale::Fr),
            ..Launch::default()
        },
        saved,
    );
    assert_eq!(for_one_run.language(), Locale::Fr);
    refraction_i18n::set_locale(Locale::En);
    assert_eq!(
        Explorer::new(ExplorerState::default()).language(),
        Locale::En
    );
}
