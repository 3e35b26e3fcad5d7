//! The animations as GIF files: each decodes with the requested size and frame count, loops,
//! and moves.

use refraction_diagram::{ANIMATION_FRAMES, Animation, Overlay};
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
    const { assert!(ANIMATION_FRAMES >= 24) };
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

/// The frames of `animation` drawn one by one on this thread, as RGBA pixels.
fn drawn_alone(animation: Animation, frames: usize, size: (u32, u32)) -> Vec<Vec<u8>> {
    let start = ExplorerState::default();
    (0..frames)
        .map(|index| {
            let frame = animation.frame(&start, index, frames);
            let draw = |size, _: &_| frame.primitives(size, &Overlay::default());
            let pixmap = refraction_render::pixmap(refraction_render::Picture::Drawn(&draw), size)
                .expect("the frame draws");
            pixmap.data().to_vec()
        })
        .collect()
}

/// How far apart two RGBA images are: the sum of their channels' differences.
fn distance(a: &[u8], b: &[u8]) -> u64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| u64::from(x.abs_diff(*y)))
        .sum()
}

#[test]
fn frames_drawn_on_several_threads_are_written_in_order() {
    // Issue 23: frames are drawn a batch at a time on every core; each must land in its place.
    let (frames, size) = (7, (160, 90));
    let spec = AnimationSpec {
        frames,
        ..AnimationSpec::new(Animation::Sweep, size)
    };
    let mut told = Vec::new();
    let bytes = gif(
        &ExplorerState::default(),
        &Overlay::default(),
        &spec,
        |done, all| {
            told.push((done, all));
            true
        },
    )
    .unwrap();
    let expected: Vec<(usize, usize)> = (1..=frames).map(|done| (done, frames)).collect();
    assert_eq!(told, expected, "progress is told once a frame, in order");
    let alone = drawn_alone(Animation::Sweep, frames, size);
    let (_, _, decoded) = decode(&bytes);
    for (index, frame) in decoded.iter().enumerate() {
        let nearest = (0..frames)
            .min_by_key(|&other| distance(&frame.3, &alone[other]))
            .unwrap();
        assert_eq!(
            nearest, index,
            "frame {index} of the GIF is frame {nearest} drawn alone"
        );
    }
}

#[test]
fn frames_drawn_on_other_threads_speak_the_language_of_the_thread_that_asked() {
    let spec = AnimationSpec {
        frames: 3,
        ..AnimationSpec::new(Animation::Mu, (320, 180))
    };
    let in_language = |locale| {
        refraction_i18n::set_locale(locale);
        let bytes = gif(
            &ExplorerState::default(),
            &Overlay::default(),
            &spec,
            |_, _| true,
        );
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
        decode(&bytes.unwrap()).2
    };
    let (english, german) = (
        in_language(refraction_i18n::Locale::En),
        in_language(refraction_i18n::Locale::De),
    );
    assert_eq!(english.len(), german.len());
    for (index, (en, de)) in english.iter().zip(&german).enumerate() {
        assert_ne!(
            en.3, de.3,
            "frame {index} has the words of the asking thread's language"
        );
    }
}
