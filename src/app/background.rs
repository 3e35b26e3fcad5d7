//! Work that would freeze the window, done off its thread: on a thread of its own on a desktop;
//! in a browser, which gives a page one thread and no way to start another, on the window's
//! thread at once, so that the same code path serves both (the page does not answer while it
//! runs, and the window says so beside the buttons that start such work: [`ONE_THREAD`]).

/// Whether work started here runs on the window's own thread (in a browser).
pub(super) const ONE_THREAD: bool = cfg!(target_arch = "wasm32");

/// Work started by [`spawn`]: running on its thread, or done.
#[derive(Debug)]
pub(super) struct Job<T> {
    #[cfg(not(target_arch = "wasm32"))]
    handle: std::thread::JoinHandle<T>,
    #[cfg(target_arch = "wasm32")]
    done: T,
}

/// Starts `work` on a thread of its own (on the window's thread, to the end, in a browser).
pub(super) fn spawn<T: Send + 'static>(work: impl FnOnce() -> T + Send + 'static) -> Job<T> {
    Job {
        #[cfg(not(target_arch = "wasm32"))]
        handle: std::thread::spawn(work),
        #[cfg(target_arch = "wasm32")]
        done: work(),
    }
}

impl<T> Job<T> {
    /// Whether the work has ended.
    #[must_use]
    #[cfg_attr(
        target_arch = "wasm32",
        // untranslated: a lint's reason, for developers.
        expect(clippy::unused_self, reason = "a desktop's job asks its thread")
    )]
    pub(super) fn is_finished(&self) -> bool {
        #[cfg(not(target_arch = "wasm32"))]
        return self.handle.is_finished();
        #[cfg(target_arch = "wasm32")]
        return true;
    }

    /// What the work returned, once it has ended (waiting for it until then).
    ///
    /// # Errors
    /// The work panicked: the panic's payload.
    #[cfg_attr(
        target_arch = "wasm32",
        expect(
            clippy::unnecessary_wraps,
            reason = "a desktop's thread may have panicked"
        )
    )]
    pub(super) fn join(self) -> std::thread::Result<T> {
        #[cfg(not(target_arch = "wasm32"))]
        return self.handle.join();
        #[cfg(target_arch = "wasm32")]
        return Ok(self.done);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_job_gives_back_what_its_work_returned() {
        let job = spawn(|| 6 * 7);
        assert_eq!(job.join().ok(), Some(42));
    }
}
