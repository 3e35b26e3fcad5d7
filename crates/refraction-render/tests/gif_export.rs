//! The animations as GIF files: each decodes with the requested size and frame count, loops,
//! and moves.

use refraction_diagram::Overlay;
use refraction_diagram::animation::{Animation, DEFAULT_FRAMES};
use refraction_model::ExplorerState;
use refraction_render::animation::{AnimationSpec, export_gif, gif};

/// One decoded frame: width, height, delay (hundredths of a second) and RGBA pixels.
type DecodedFrame = (u16, u16, u16, Vec<u8>);

/// The GIF's size and its frames.
fn decode(bytes: &[u8]) -> (u16, u16, Vec<DecodedFrame>) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(bytes).expect("the GIF decodes");
    let (width, height) = (decoder.width(), decoder.height());
    let mut frames = Vec::new();
    while let Some(frame) = decoder.read_next_frame().expect("every frame decodes") {
        frames.push((
            frame.width,
            frame.height,
            frame.delay,
            frame.buffer.to_vec(),
        ));
    }
    (width, height, frames)
}

#[test]
fn every_animation_decodes_with_the_requested_size_and_frame_count() {
    const { assert!(DEFAULT_FRAMES >= 24) };
    for animation in Animation::ALL {
        let spec = AnimationSpec {
            frames: 24,
            fps: 20,
            ..AnimationSpec::new(animation, (240, 136))
        };
        let bytes = gif(
            &ExplorerState::default(),
            &Overlay::default(),
            &spec,
            |_, _| true,
        )
        .unwrap();
        let (width, height, frames) = decode(&bytes);
        let name = animation.name();
        assert_eq!((width, height), (240, 136), "{name}");
        assert_eq!(frames.len(), 24, "{name}");
        assert!(
            frames.iter().all(|f| (f.0, f.1, f.2) == (240, 136, 5)),
            "{name}"
        );
        let distinct = frames.windows(2).filter(|w| w[0].3 != w[1].3).count();
        assert!(
            distinct >= 20,
            "{name}: only {distinct} of 23 frames differ from the one before"
        );
    }
}

#[test]
fn the_file_is_written_atomically_and_not_at_all_when_cancelled() {
    let folder = std::env::temp_dir().join(format!("gif-export-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("sweep.gif");
    let spec = AnimationSpec {
        frames: 3,
        ..AnimationSpec::new(Animation::Sweep, (128, 72))
    };
    let state = ExplorerState::default();
    assert!(
        export_gif(&state, &Overlay::default(), &spec, &path, |done, _| done
            < 2)
        .is_err()
    );
    assert!(!path.exists());
    export_gif(&state, &Overlay::default(), &spec, &path, |_, _| true).unwrap();
    let (_, _, frames) = decode(&std::fs::read(&path).unwrap());
    assert_eq!(frames.len(), 3);
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 1);
    std::fs::remove_dir_all(&folder).unwrap();
}
