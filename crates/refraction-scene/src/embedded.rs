//! The scenes built into the binary from `assets/scenes/`, so that they load from any folder.

use serde::Serialize;

use super::Scene;

/// The scene shown first: a single interface.
pub const DEFAULT_SCENE: &str = "interface";

/// (name, file text) of every file in `assets/scenes/`, in the order a picker lists them.
macro_rules! embed {
    ($($name:literal),* $(,)?) => {
        &[$(($name, include_str!(concat!("../assets/scenes/", $name, ".toml")))),*]
    };
}

const SCENES: &[(&str, &str)] = embed!(
    "interface",
    "slab",
    "right-angle-prism",
    "droplet",
    "lens",
    "fibre",
    "dispersing-prism",
);

/// A built-in scene as a picker lists it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SceneInfo {
    /// What to pass to [`Scene::embedded`] (and to `refraction-explorer trace`).
    pub name: &'static str,
    /// The title from the file.
    pub title: String,
}

/// The text of the built-in scene `name`.
pub(super) fn text(name: &str) -> Option<&'static str> {
    SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

/// The names of the built-in scenes.
pub(super) fn names() -> Vec<&'static str> {
    SCENES.iter().map(|(name, _)| *name).collect()
}

/// Every built-in scene's name and title (a scene that fails to load is listed under its
/// name, and says why when it is loaded).
#[must_use]
pub fn catalogue() -> Vec<SceneInfo> {
    SCENES
        .iter()
        .map(|(name, _)| SceneInfo {
            name,
            title: Scene::embedded(name).map_or_else(|_| (*name).to_owned(), |s| s.title),
        })
        .collect()
}
