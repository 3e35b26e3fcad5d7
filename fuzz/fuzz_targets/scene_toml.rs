//! A scene file: a scene that traces within its budget and writes back to a file that loads
//! as the same scene, or an error naming its place.
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_scene::Scene;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    match Scene::from_bytes(data, "fuzz.toml", "fuzz") {
        Ok(scene) => {
            let trace = scene.trace();
            assert!(trace.segments.len() <= 1_000_000);
            if let Ok(text) = scene.to_toml() {
                let again = Scene::from_toml(&text, "again.toml", "fuzz")
                    .unwrap_or_else(|e| panic!("written back, it does not load: {e}\n{text}"));
                assert_eq!(again.to_toml().ok(), Some(text));
            }
        }
        Err(e) => {
            let message = e.to_string();
            assert!(message.starts_with("fuzz.toml"), "{message}");
            message::assert_message(&message, data);
        }
    }
});
