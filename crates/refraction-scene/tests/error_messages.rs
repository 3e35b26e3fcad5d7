//! The scene crate's errors say what was wrong in the words the README and the window show.

use glam::DVec2;
use refraction_scene::{EditError, Effects, EffectsError, LoadError, Position, Scene};

#[test]
fn edit_errors_name_what_was_refused() {
    let mut droplet = Scene::embedded("droplet").unwrap();
    let before = droplet.clone();
    let refused = [
        (
            droplet.set_source_origin(DVec2::new(f64::NAN, 0.0)),
            "every coordinate must be a finite number",
        ),
        (
            droplet.set_source_direction(DVec2::ZERO),
            "a direction must not be the zero vector",
        ),
        (
            droplet.move_shape(99, DVec2::X),
            "the scene has no shape 99",
        ),
        (
            droplet.set_ray_count(100_001),
            "100001 rays: a source has from 1 to 100000 rays",
        ),
    ];
    for (outcome, message) in refused {
        assert_eq!(outcome.unwrap_err().to_string(), message);
    }
    assert_eq!(droplet, before);
}

#[test]
fn effects_errors_give_the_value_and_the_limit_and_refuse_the_edit() {
    let deep = Effects {
        max_depth: 1001,
        ..Effects::default()
    };
    assert_eq!(deep.check(), Err(EffectsError::MaxDepth(1001)));
    assert_eq!(
        deep.check().unwrap_err().to_string(),
        "max_depth is 1001: at most 1000 hits per ray are traced"
    );
    let faint = Effects {
        min_intensity: 1.5,
        ..Effects::default()
    };
    assert_eq!(
        faint.check().unwrap_err().to_string(),
        "min_intensity is 1.5: expected a fraction from 0 to 1"
    );
    let mut droplet = Scene::embedded("droplet").unwrap();
    let edit = droplet.set_effects(faint).unwrap_err();
    assert_eq!(edit, EditError::Effects(EffectsError::MinIntensity(1.5)));
    assert_eq!(
        edit.to_string(),
        "min_intensity is 1.5: expected a fraction from 0 to 1"
    );
}

#[test]
fn load_errors_start_with_the_file_and_the_position_when_there_is_one() {
    let mut error = LoadError {
        file: "lens.toml".to_owned(),
        position: Some(Position { line: 3, column: 7 }),
        message: "unknown medium `glas`".to_owned(),
    };
    assert_eq!(error.to_string(), "lens.toml:3:7: unknown medium `glas`");
    error.position = None;
    assert_eq!(error.to_string(), "lens.toml: unknown medium `glas`");
}
