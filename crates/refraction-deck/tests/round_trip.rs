//! A deck goes through its file and comes back equal: every built-in deck in every language,
//! and a hand-written deck that uses every field; a file's errors name their line and column.

use refraction_deck::{Deck, Effect, StepTool, StepView, builtin};
use refraction_i18n::{Locale, set_locale};
use refraction_model::Polarisation;

/// A deck file that sets every field of a step, and one step that sets none it may leave out.
const EVERY_FIELD: &str = r#"
# A teacher's own deck.
[deck]
version = 1
title = "Prisms, my way"

[[step]]
title = "The prism"
question = "Where does the light go?"
notes = """
First line.
Second line, with "quotes" and a tab\there."""
view = "scenes"
w = [0.6427876096865393, -0.766044443118978, 0.0]
n = [0.0, 1.0, 0.0]
mu_i = 1.000293
mu_t = 1.5
convention = "toward_origin"
scene = "right-angle-prism"
tool = "fresnel"
effects = ["fresnel", "intensities", "huygens", "wavefronts", "moving", "partial_reflection", "dispersion", "absorption"]
light = "p"

[[step]]
title = ""
w = [0.1, -1, 0]
n = [0, 1, 0]
mu_i = 1
mu_t = 1.333
"#;

#[test]
fn a_deck_that_sets_every_field_comes_back_from_its_file_equal() {
    let deck = Deck::from_toml(EVERY_FIELD, "mine.toml", None).unwrap();
    let step = &deck.steps[0];
    assert_eq!(deck.title, "Prisms, my way");
    assert_eq!(step.view, StepView::Scenes);
    assert_eq!(step.tool, Some(StepTool::Fresnel));
    assert_eq!(step.light, Polarisation::P);
    assert_eq!(
        step.effects,
        Effect::ALL,
        "every effect, in the file's order"
    );
    assert_eq!(
        step.notes,
        "First line.\nSecond line, with \"quotes\" and a tab\there."
    );
    assert_eq!(step.question.as_deref(), Some("Where does the light go?"));
    let written = deck.to_toml().unwrap();
    let again = Deck::from_toml(&written, "written.toml", None).unwrap();
    assert_eq!(again, deck, "{written}");
    assert_eq!(
        again.to_toml().unwrap(),
        written,
        "written the same way twice"
    );
    assert!(refraction_deck::looks_like_deck(&written));
    let traced = deck.scene(step).unwrap();
    assert!(traced.effects().partial_reflection && traced.effects().dispersion);
    assert_eq!(deck.steps[1].scene_name(), refraction_scene::DEFAULT_SCENE);
}

#[test]
fn every_built_in_deck_comes_back_from_its_file_equal_in_every_language() {
    for locale in Locale::ALL {
        set_locale(locale);
        for name in builtin::names() {
            let deck = Deck::load(name).unwrap();
            let text = deck.to_toml().unwrap();
            let back = Deck::from_toml(&text, name, None).unwrap();
            assert_eq!(back, deck, "{locale} {name}");
            assert!(
                deck.steps.iter().all(|s| !s.title.is_empty()),
                "{locale} {name}"
            );
        }
    }
    set_locale(Locale::En);
}

#[test]
fn a_deck_file_on_disk_finds_its_scene_beside_it_and_says_where_it_is_wrong() {
    let folder = std::env::temp_dir().join(format!("deck-files-{}", std::process::id()));
    std::fs::create_dir_all(folder.join("scenes")).unwrap();
    let scene = refraction_scene::Scene::embedded("slab").unwrap();
    std::fs::write(folder.join("scenes/mine.toml"), scene.to_toml().unwrap()).unwrap();
    let deck = EVERY_FIELD.replace("\"right-angle-prism\"", "\"scenes/mine.toml\"");
    std::fs::write(folder.join("deck.toml"), &deck).unwrap();
    let path = folder.join("deck.toml");
    let loaded = Deck::load(path.to_str().unwrap()).unwrap();
    assert_eq!(loaded.folder.as_deref(), Some(folder.as_path()));
    assert_eq!(
        loaded.scene(&loaded.steps[0]).unwrap().title(),
        scene.title()
    );
    std::fs::write(&path, deck.replace("mu_t = 1.5", "mu_t = 1.5\nmu = 2")).unwrap();
    let error = Deck::load(path.to_str().unwrap()).unwrap_err();
    assert_eq!(error.position.map(|p| (p.line, p.column)), Some((18, 1)));
    assert!(error.message.contains("unknown field `mu`"), "{error}");
    std::fs::write(&path, b"[deck]\nversion = 1\ntitle = \"\xff\"\n").unwrap();
    let error = Deck::load(path.to_str().unwrap()).unwrap_err();
    assert!(
        error
            .to_string()
            .ends_with(":3:10: not UTF-8 text: a deck file is TOML, which is UTF-8"),
        "{error}"
    );
    std::fs::remove_dir_all(&folder).unwrap();
}
