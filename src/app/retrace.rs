//! Retracing the Scenes view's scene without freezing the window: a trace that finishes within a
//! small budget is done at once on the UI thread (every built-in scene, even at 1,000 rays, so
//! that a drag shows its new rays in the same frame); a bigger one runs on a thread of its own,
//! with its progress shown and a way to cancel it, while the last finished trace stays on
//! screen.

use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, TryRecvError};

use refraction_scene::{Budget, Counts, MAX_INTERSECTION_TESTS, Progress, Scene, Stop, Trace};

/// What the view traces at most: a screen cannot show more segments than this (a 1280×720
/// canvas has under a million pixels, and rays are drawn wider than one), and a picture of them
/// still paints in a fraction of a second.
pub(super) const VIEW_BUDGET: Budget = Budget {
    segments: 200_000,
    tests: MAX_INTERSECTION_TESTS,
};

/// What a trace may cost on the UI thread: about 10 ms of tracing (the built-in scenes at 1,000
/// rays need at most two fifths of it: the droplet's 43,396 segments, 4.0 ms in `cargo bench -p
/// refraction-scene --bench trace`). A trace that reaches either limit is traced again in the
/// background, up to [`VIEW_BUDGET`].
const FOREGROUND: Budget = Budget {
    segments: VIEW_BUDGET.segments / 2,
    tests: 1_000_000,
};

/// A trace running on another thread: its progress (shared, to read and to cancel) and the
/// channel its finished trace comes back on.
#[derive(Debug)]
struct Job {
    progress: Arc<Progress>,
    done: Receiver<Trace>,
}

/// The traces of one view: the one running in the background, if any, and a spare trace whose
/// memory the next trace reuses.
#[derive(Debug, Default)]
pub(super) struct Retracer {
    job: Option<Job>,
    spare: Option<Trace>,
}

/// A trace with nothing in it yet, of `scene`'s world.
pub(super) fn empty(scene: &Scene) -> Trace {
    Trace {
        bounds: scene.bounds(),
        segments: Vec::new(),
        paths: Vec::new(),
        hits: Vec::new(),
        counts: Counts::default(),
    }
}

impl Retracer {
    /// Traces `scene` into `shown` if that fits in the foreground budget; otherwise leaves
    /// `shown` as it is and traces on another thread (see [`Self::poll`]). Either way a trace
    /// still running for an earlier version of the scene is cancelled and forgotten.
    pub(super) fn retrace(&mut self, scene: &Scene, shown: &mut Trace) {
        self.cancel();
        self.job = None;
        let mut next = self.spare.take().unwrap_or_else(|| empty(scene));
        scene.retrace_within(&mut next, FOREGROUND, &Progress::default());
        let over = [
            Stop::Tests(FOREGROUND.tests),
            Stop::Segments(FOREGROUND.segments),
        ];
        if !next.counts.stopped.is_some_and(|stop| over.contains(&stop)) {
            core::mem::swap(shown, &mut next);
            self.spare = Some(next);
            return;
        }
        let progress = Arc::new(Progress::default());
        let (send, done) = mpsc::channel();
        let (scene, shared) = (scene.clone(), Arc::clone(&progress));
        super::background::spawn(move || {
            scene.retrace_within(&mut next, VIEW_BUDGET, &shared);
            // The view may have moved on (a newer trace replaced this one): then nobody
            // listens, and the trace is simply dropped.
            send.send(next).ok();
        });
        self.job = Some(Job { progress, done });
    }

    /// The background trace, once it has finished (or been cancelled, then with what it had
    /// traced).
    pub(super) fn poll(&mut self) -> Option<Trace> {
        let job = self.job.as_ref()?;
        match job.done.try_recv() {
            Ok(trace) => {
                self.job = None;
                Some(trace)
            }
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => {
                // The thread ended without a trace (it cannot panic short of running out of
                // memory): nothing more will come.
                self.job = None;
                None
            }
        }
    }

    /// How far the background trace has got (0 to 1), or `None` when none is running.
    #[must_use]
    pub(super) fn progress(&self) -> Option<f64> {
        self.job.as_ref().map(|job| job.progress.fraction())
    }

    /// Asks the background trace to stop where it is ([`Self::poll`] then returns what it has).
    pub(super) fn cancel(&self) {
        if let Some(job) = &self.job {
            job.progress.cancel();
        }
    }

    /// Keeps `trace`'s memory for the next trace (the view no longer shows it).
    pub(super) fn recycle(&mut self, trace: Trace) {
        self.spare = Some(trace);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::time::Duration;
    use std::time::Instant;

    fn wait(retracer: &mut Retracer) -> Trace {
        let start = Instant::now();
        loop {
            if let Some(trace) = retracer.poll() {
                return trace;
            }
            assert!(
                start.elapsed() < Duration::from_mins(1),
                "the trace never came"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
    }

    /// The droplet asking for every reflection forever: far more than the foreground budget.
    fn deep_droplet() -> Scene {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/crates/refraction-scene/tests/data/deep-droplet.toml"
        );
        Scene::load(path).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn a_small_trace_is_done_at_once() {
        let scene = Scene::embedded("droplet").unwrap();
        let (mut retracer, mut shown) = (Retracer::default(), empty(&scene));
        retracer.retrace(&scene, &mut shown);
        assert_eq!(retracer.progress(), None);
        assert_eq!(shown, scene.trace());
    }

    #[test]
    fn a_big_trace_runs_in_the_background_and_stops_at_the_view_budget() {
        let scene = deep_droplet();
        let (mut retracer, mut shown) = (Retracer::default(), empty(&scene));
        let before = shown.clone();
        retracer.retrace(&scene, &mut shown);
        assert!(retracer.progress().is_some(), "it runs in the background");
        assert_eq!(shown, before, "the last finished trace stays");
        let done = wait(&mut retracer);
        assert_eq!(
            done.counts.stopped,
            Some(Stop::Segments(VIEW_BUDGET.segments))
        );
        assert_eq!(retracer.progress(), None);
    }

    #[test]
    fn a_background_trace_can_be_cancelled_or_replaced() {
        let scene = deep_droplet();
        let (mut retracer, mut shown) = (Retracer::default(), empty(&scene));
        retracer.retrace(&scene, &mut shown);
        retracer.cancel();
        let cancelled = wait(&mut retracer);
        assert_eq!(cancelled.counts.stopped, Some(Stop::Cancelled));
        retracer.retrace(&scene, &mut shown);
        let small = Scene::embedded("slab").unwrap();
        retracer.retrace(&small, &mut shown);
        assert_eq!(
            retracer.progress(),
            None,
            "the newer, small trace replaced it"
        );
        assert_eq!(shown, small.trace());
    }
}
