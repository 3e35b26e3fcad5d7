//! The built-in scenes' words in the user's language: their titles, descriptions and the
//! names of their media. The scene files keep English (they are data, written back as read);
//! a text is translated only where it is exactly a built-in scene's own, so that a user's
//! scene file shows what its author wrote.

use refraction_i18n::t;
use refraction_scene::Scene;

/// The title of the built-in scene `name`, in the current language.
#[must_use]
pub fn built_in_title(name: &str) -> Option<String> {
    Some(match name {
        "dispersing-prism" => t!("diagram-scene-dispersing-prism"),
        "droplet" => t!("diagram-scene-droplet"),
        "fibre" => t!("diagram-scene-fibre"),
        "interface" => t!("diagram-scene-interface"),
        "lens" => t!("diagram-scene-lens"),
        "right-angle-prism" => t!("diagram-scene-right-angle-prism"),
        "slab" => t!("diagram-scene-slab"),
        _ => return None,
    })
}

/// The description of the built-in scene `name`, in the current language.
fn built_in_description(name: &str) -> Option<String> {
    Some(match name {
        "dispersing-prism" => t!("diagram-scene-dispersing-prism-about"),
        "droplet" => t!("diagram-scene-droplet-about"),
        "fibre" => t!("diagram-scene-fibre-about"),
        "interface" => t!("diagram-scene-interface-about"),
        "lens" => t!("diagram-scene-lens-about"),
        "right-angle-prism" => t!("diagram-scene-right-angle-prism-about"),
        "slab" => t!("diagram-scene-slab-about"),
        _ => return None,
    })
}

/// Whether `scene` says what the built-in scene of its name says (`part` picks the text):
/// a file of the user's own with a built-in's name keeps its own words.
fn as_built_in(scene: &Scene, part: fn(&Scene) -> &str) -> bool {
    Scene::embedded(scene.name()).is_ok_and(|built_in| part(&built_in) == part(scene))
}

/// `scene`'s title, in the current language where it is a built-in scene's own.
#[must_use]
pub fn title(scene: &Scene) -> String {
    as_built_in(scene, Scene::title)
        .then(|| built_in_title(scene.name()))
        .flatten()
        .unwrap_or_else(|| scene.title().to_owned())
}

/// `scene`'s description, in the current language where it is a built-in scene's own.
#[must_use]
pub fn description(scene: &Scene) -> String {
    as_built_in(scene, Scene::description)
        .then(|| built_in_description(scene.name()))
        .flatten()
        .unwrap_or_else(|| scene.description().to_owned())
}

/// A medium's name as a built-in scene names it (`air`, `bk7`), in the current language;
/// any other name as it is.
#[must_use]
pub fn medium_name(name: &str) -> String {
    built_in_medium(name).unwrap_or_else(|| name.to_owned())
}

/// The name of a medium the built-in scenes use, in the current language.
fn built_in_medium(name: &str) -> Option<String> {
    Some(match name {
        "vacuum" => t!("diagram-material-vacuum"),
        "air" => t!("diagram-material-air"),
        "water" => t!("diagram-material-water"),
        "glass" => t!("diagram-material-glass"),
        "core" => t!("diagram-medium-core"),
        "cladding" => t!("diagram-medium-cladding"),
        "f2" => t!("diagram-medium-f2"),
        "bk7" => t!("diagram-medium-bk7"),
        "tinted-bk7" => t!("diagram-medium-tinted-bk7"),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_i18n::Locale;
    use refraction_scene::{Scene, catalogue};

    #[test]
    fn every_built_in_scene_has_its_words_in_every_language() {
        for locale in Locale::ALL {
            refraction_i18n::set_locale(locale);
            for info in catalogue() {
                let scene = Scene::embedded(info.name).unwrap();
                let words = [
                    (title(&scene), scene.title()),
                    (description(&scene), scene.description()),
                ];
                for (words, english) in words {
                    assert!(!words.starts_with('['), "{locale}: {words}");
                    if locale == Locale::En {
                        assert_eq!(words, english, "the English key says what the file says");
                    } else {
                        assert_ne!(words, english, "{locale}: {} is not translated", info.name);
                    }
                }
                for medium in scene.media() {
                    let name = built_in_medium(&medium.name);
                    assert!(
                        name.is_some(),
                        "{locale}: medium {} has no words",
                        medium.name
                    );
                }
            }
        }
        refraction_i18n::set_locale(Locale::En);
    }

    #[test]
    fn a_users_own_words_are_left_as_written() {
        refraction_i18n::set_locale(Locale::De);
        let mut own = Scene::embedded("slab").unwrap();
        let source = own.to_toml().unwrap().replace("Glass slab", "My bench");
        own = Scene::from_toml(&source, "test", "slab").unwrap();
        let words = (
            title(&own),
            medium_name("crown"),
            title(&Scene::embedded("slab").unwrap()),
        );
        refraction_i18n::set_locale(Locale::En);
        assert_eq!((words.0.as_str(), words.1.as_str()), ("My bench", "crown"));
        assert_ne!(words.2, "Glass slab", "the built-in one is translated");
    }
}
