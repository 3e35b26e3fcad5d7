//! The built-in scenes' words in the user's language: their titles, descriptions and the
//! names of their media. The scene files keep English (they are data, written back as read);
//! a text is translated only where it is exactly a built-in scene's own, so that a user's
//! scene file shows what its author wrote.

use std::sync::OnceLock;

use refraction_i18n::t;
use refraction_scene::{Scene, catalogue};

/// Where a scene's title is in [`built_in_words`] and [`file_words`].
const TITLE: usize = 0;
/// Where a scene's description is.
const DESCRIPTION: usize = 1;

/// The title and the description of the built-in scene `name`, in the current language.
fn built_in_words(name: &str) -> Option<[String; 2]> {
    Some(match name {
        "dispersing-prism" => [
            t!("diagram-scene-dispersing-prism"),
            t!("diagram-scene-dispersing-prism-about"),
        ],
        "droplet" => [
            t!("diagram-scene-droplet"),
            t!("diagram-scene-droplet-about"),
        ],
        "fibre" => [t!("diagram-scene-fibre"), t!("diagram-scene-fibre-about")],
        "interface" => [
            t!("diagram-scene-interface"),
            t!("diagram-scene-interface-about"),
        ],
        "lens" => [t!("diagram-scene-lens"), t!("diagram-scene-lens-about")],
        "right-angle-prism" => [
            t!("diagram-scene-right-angle-prism"),
            t!("diagram-scene-right-angle-prism-about"),
        ],
        "slab" => [t!("diagram-scene-slab"), t!("diagram-scene-slab-about")],
        _ => return None,
    })
}

/// The English title and description the built-in scene file `name` carries, read from the
/// files once: the window asks for a scene's words every frame.
fn file_words(name: &str) -> Option<&'static [String; 2]> {
    static WORDS: OnceLock<Vec<(&'static str, [String; 2])>> = OnceLock::new();
    let words = WORDS.get_or_init(|| {
        catalogue()
            .into_iter()
            .filter_map(|info| {
                let scene = Scene::embedded(info.name).ok()?;
                let words = [scene.title().to_owned(), scene.description().to_owned()];
                Some((info.name, words))
            })
            .collect()
    });
    words.iter().find(|(n, _)| *n == name).map(|(_, w)| w)
}

/// The title of the built-in scene `name`, in the current language.
#[must_use]
pub fn built_in_scene_title(name: &str) -> Option<String> {
    built_in_words(name).map(|[title, _]| title)
}

/// `scene`'s title or description (`part`), in the current language where it says what the
/// built-in scene of its name says: a file of the user's own keeps its own words.
fn words(scene: &Scene, part: usize) -> String {
    let own = [scene.title(), scene.description()][part];
    let as_built_in = file_words(scene.name()).is_some_and(|words| words[part] == own);
    as_built_in
        .then(|| built_in_words(scene.name()))
        .flatten()
        .map_or_else(|| own.to_owned(), |words| words[part].clone())
}

/// `scene`'s title, in the current language where it is a built-in scene's own.
#[must_use]
pub fn scene_title(scene: &Scene) -> String {
    words(scene, TITLE)
}

/// `scene`'s description, in the current language where it is a built-in scene's own.
#[must_use]
pub fn scene_description(scene: &Scene) -> String {
    words(scene, DESCRIPTION)
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

    #[test]
    fn every_built_in_scene_has_its_words_in_every_language() {
        for locale in Locale::ALL {
            refraction_i18n::set_locale(locale);
            for info in catalogue() {
                let scene = Scene::embedded(info.name).unwrap();
                let words = [
                    (scene_title(&scene), scene.title()),
                    (scene_description(&scene), scene.description()),
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
            scene_title(&own),
            medium_name("crown"),
            scene_title(&Scene::embedded("slab").unwrap()),
        );
        refraction_i18n::set_locale(Locale::En);
        assert_eq!((words.0.as_str(), words.1.as_str()), ("My bench", "crown"));
        assert_ne!(words.2, "Glass slab", "the built-in one is translated");
    }
}
