//! Animations as GIF files for slides: the frames of [`refraction_diagram::Animation`] drawn as
//! the PNG is, each reduced to its own 256-colour palette, looping.

use std::path::Path;

use gif::{Encoder, Frame, Repeat};
use tiny_skia::Pixmap;

use refraction_diagram::{ANIMATION_FPS, ANIMATION_FRAMES, Animation, Overlay};
use refraction_model::ExplorerState;

use crate::{RenderError, check_size, draw_primitives};
use refraction_files::write_atomically;

/// The fewest and the most frames an animation may have.
pub const FRAME_LIMITS: (usize, usize) = (2, 600);

/// The slowest and the fastest frame rate, frames per second: GIF counts time in hundredths
/// of a second, and viewers slow anything faster than 50 down to 10.
pub const FPS_LIMITS: (u32, u32) = (1, 50);

/// The colour reduction's speed, 1 (best) to 30 (fastest): 10 is the `gif` crate's
/// compromise, and the diagram's flat colours lose nothing visible at it.
const QUANTISATION_SPEED: i32 = 10;

/// What to animate, how long and how large.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AnimationSpec {
    /// Which animation.
    pub animation: Animation,
    /// How many frames (within [`FRAME_LIMITS`]).
    pub frames: usize,
    /// Frames per second (within [`FPS_LIMITS`]).
    pub fps: u32,
    /// Width and height in pixels (within [`crate::SIZE_LIMITS`]).
    pub size: (u32, u32),
}

impl AnimationSpec {
    /// `animation` with the default frames and rate at `size`.
    #[must_use]
    pub fn new(animation: Animation, size: (u32, u32)) -> Self {
        Self {
            animation,
            frames: ANIMATION_FRAMES,
            fps: ANIMATION_FPS,
            size,
        }
    }

    /// Checks the frames, rate and size before any frame is drawn.
    ///
    /// # Errors
    /// [`RenderError::BadAnimation`] or [`RenderError::BadSize`], naming the value and the limits.
    pub fn check(&self) -> Result<(), RenderError> {
        let (fewest, most) = FRAME_LIMITS;
        if !(fewest..=most).contains(&self.frames) {
            let frames = self.frames;
            let counted = if frames == 1 {
                "1 frame".to_owned()
            } else {
                format!("{frames} frames")
            };
            return Err(RenderError::BadAnimation(format!(
                "{counted} is not allowed: an animation has {fewest} to {most} frames"
            )));
        }
        let (slowest, fastest) = FPS_LIMITS;
        if !(slowest..=fastest).contains(&self.fps) {
            return Err(RenderError::BadAnimation(format!(
                "{} frames per second is not allowed: GIF plays {slowest} to {fastest}",
                self.fps
            )));
        }
        check_size(self.size.0, self.size.1)
    }

    /// How long each frame shows, in the hundredths of a second GIF counts in.
    #[must_use]
    pub fn delay(&self) -> u16 {
        (100.0 / f64::from(self.fps.max(1))).round() as u16
    }
}

/// A pixmap's pixels as straight (not premultiplied) RGBA, as the GIF encoder takes them.
fn straight_rgba(pixmap: &Pixmap) -> Vec<u8> {
    pixmap
        .pixels()
        .iter()
        .flat_map(|p| {
            let c = p.demultiply();
            [c.red(), c.green(), c.blue(), c.alpha()]
        })
        .collect()
}

fn encoding(e: &gif::EncodingError) -> RenderError {
    RenderError::EncodeGif(e.to_string())
}

/// One frame drawn and reduced to the GIF's colours: the slow part, done for several frames at
/// once on as many threads, in the language of the thread that asked (`locale`).
fn encoded_frame(
    start: &ExplorerState,
    overlay: &Overlay,
    spec: &AnimationSpec,
    index: usize,
    locale: refraction_i18n::Locale,
) -> Result<Frame<'static>, RenderError> {
    refraction_i18n::set_locale(locale);
    let (width, height) = spec.size;
    // Both fit: SIZE_LIMITS stop at 8192.
    let (w16, h16) = (width as u16, height as u16);
    let frame = spec.animation.frame(start, index, spec.frames);
    let pixmap = draw_primitives(width, height, |size, _| frame.primitives(size, overlay))?;
    let mut rgba = straight_rgba(&pixmap);
    let mut gif_frame = Frame::from_rgba_speed(w16, h16, &mut rgba, QUANTISATION_SPEED);
    gif_frame.delay = spec.delay();
    Ok(gif_frame)
}

/// `draw` of each index of `batch`, in order: on a thread each when `threads` is more than one,
/// on this thread otherwise (a browser page has one thread, and spawns none).
fn frames_of<T: Send>(
    batch: core::ops::Range<usize>,
    threads: usize,
    draw: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    if threads <= 1 {
        return batch.map(draw).collect();
    }
    on_threads(batch, draw)
}

/// `draw` of each index of `batch`, in order, each on a thread of its own.
#[cfg(not(target_arch = "wasm32"))]
fn on_threads<T: Send>(batch: core::ops::Range<usize>, draw: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let draw = &draw;
    std::thread::scope(|scope| {
        let workers: Vec<_> = batch
            .map(|index| scope.spawn(move || draw(index)))
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}

/// In a browser page, which has one thread and spawns none: `draw` of each index of `batch`,
/// in order, on this thread (the wasm32 build is linted with threads disallowed).
#[cfg(target_arch = "wasm32")]
fn on_threads<T: Send>(batch: core::ops::Range<usize>, draw: impl Fn(usize) -> T + Sync) -> Vec<T> {
    batch.map(draw).collect()
}

/// The animation of `spec` from `start`, drawn with `overlay`, as GIF bytes: frames are drawn
/// and their colours reduced on every core, a batch at a time, and written in order. `progress`
/// is told (frames done, frames in all) after each frame and stops the work by returning false.
///
/// # Errors
/// A bad spec ([`AnimationSpec::check`]), an unreadable font, a failed encoding, or
/// [`RenderError::Cancelled`] when `progress` said stop.
pub fn gif(
    start: &ExplorerState,
    overlay: &Overlay,
    spec: &AnimationSpec,
    mut progress: impl FnMut(usize, usize) -> bool,
) -> Result<Vec<u8>, RenderError> {
    spec.check()?;
    let (width, height) = spec.size;
    // Both fit: SIZE_LIMITS stop at 8192.
    let (w16, h16) = (width as u16, height as u16);
    let mut bytes = Vec::new();
    let threads = std::thread::available_parallelism().map_or(1, core::num::NonZeroUsize::get);
    let locale = refraction_i18n::locale();
    {
        let mut encoder = Encoder::new(&mut bytes, w16, h16, &[]).map_err(|e| encoding(&e))?;
        encoder
            .set_repeat(Repeat::Infinite)
            .map_err(|e| encoding(&e))?;
        let mut done = 0;
        while done < spec.frames {
            let batch = done..(done + threads).min(spec.frames);
            let frames = frames_of(batch, threads, |index| {
                encoded_frame(start, overlay, spec, index, locale)
            });
            for frame in frames {
                encoder.write_frame(&frame?).map_err(|e| encoding(&e))?;
                done += 1;
                if !progress(done, spec.frames) {
                    return Err(RenderError::Cancelled);
                }
            }
        }
    }
    Ok(bytes)
}

/// Writes the animation of `spec` from `start` as a GIF file at `path`, atomically; nothing is
/// written when `progress` cancels.
///
/// # Errors
/// As [`gif()`], or the file cannot be written (the message names it).
pub fn export_gif(
    start: &ExplorerState,
    overlay: &Overlay,
    spec: &AnimationSpec,
    path: &Path,
    progress: impl FnMut(usize, usize) -> bool,
) -> Result<(), RenderError> {
    let bytes = gif(start, overlay, spec, progress)?;
    write_atomically(path, &bytes).map_err(RenderError::Write)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_frames_and_rates_are_refused_by_value() {
        let mut spec = AnimationSpec::new(Animation::Mu, (320, 180));
        spec.frames = 1;
        let one = spec.check().unwrap_err().to_string();
        assert!(one.contains("1 frame is not allowed"), "{one}");
        spec.frames = 24;
        spec.fps = 0;
        assert!(spec.check().unwrap_err().to_string().contains("1 to 50"));
        spec.fps = 12;
        assert_eq!(spec.delay(), 8);
        assert!(spec.check().is_ok());
    }

    #[test]
    fn cancelling_stops_after_the_frame_it_was_told_of() {
        let spec = AnimationSpec {
            frames: 5,
            ..AnimationSpec::new(Animation::Sweep, (96, 64))
        };
        let mut told = Vec::new();
        let result = gif(
            &ExplorerState::default(),
            &Overlay::default(),
            &spec,
            |done, all| {
                told.push((done, all));
                done < 2
            },
        );
        assert!(matches!(result, Err(RenderError::Cancelled)));
        assert_eq!(told, [(1, 5), (2, 5)]);
    }
}
