//! The tracer: follows each source ray from interface to interface, one kernel call per hit
//! between different indices, and computes only the effects the scene asks for.

use core::ops::Range;
use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::fmt;

use glam::{DVec2, DVec3};
use serde::Serialize;

use super::Scene;
use super::bounds::Bounds;
use super::fresnel::Fresnel;
use super::search::{MAX_INTERSECTION_TESTS, Search};
use super::source::{Light, serialize_wavelength, traced_wavelength};
pub use refraction_kernel::Side;
use refraction_kernel::{Convention, Incidence, refract_facing};

/// The most segments one trace records; past it the trace stops and says so
/// ([`Counts::truncated`]), so that no scene can exhaust memory.
pub const MAX_SEGMENTS: usize = 1_000_000;

/// The work one trace may do before it stops: [`Budget::DEFAULT`] for [`Scene::trace`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// The most segments recorded ([`MAX_SEGMENTS`] by default).
    pub segments: usize,
    /// The most intersection tests made ([`MAX_INTERSECTION_TESTS`] by default).
    pub tests: u64,
}

impl Budget {
    /// [`MAX_SEGMENTS`] segments and [`MAX_INTERSECTION_TESTS`] tests.
    pub const DEFAULT: Self = Self {
        segments: MAX_SEGMENTS,
        tests: MAX_INTERSECTION_TESTS,
    };
}

impl Default for Budget {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Why a trace stopped before every ray was followed to its end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// It recorded its budget of segments.
    Segments(usize),
    /// It made its budget of intersection tests.
    Tests(u64),
    /// It was cancelled ([`Progress::cancel`]).
    Cancelled,
}

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Segments(n) => write!(
                f,
                "the trace stopped at its budget of {n} segments: the rays not yet followed are \
                 left out (fewer rays, a lower max_depth or a higher min_intensity trace fully)"
            ),
            Self::Tests(n) => write!(
                f,
                "the trace stopped at its budget of {n} intersection tests: the rays not yet \
                 followed are left out (fewer rays, shapes or reflections trace fully)"
            ),
            Self::Cancelled => f.write_str("the trace was cancelled before it finished"),
        }
    }
}

impl Serialize for Stop {
    /// As its message: the `stopped` of the `trace` command's counts.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// What a trace on another thread shares with the one waiting for it: how far it has got and
/// whether it should stop. All of it is atomic, so a `&Progress` may be read and cancelled from
/// any thread while the trace runs.
#[derive(Debug, Default)]
pub struct Progress {
    cancelled: AtomicBool,
    rays_done: AtomicUsize,
    rays_total: AtomicUsize,
}

impl Progress {
    /// Asks the trace to stop at its next segment ([`Stop::Cancelled`]).
    pub fn cancel(&self) {
        self.cancelled.store(true, Ordering::Relaxed);
    }

    /// Whether [`Self::cancel`] was called.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// The fraction of source rays (over all colours) followed to their end so far, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        let total = self.rays_total.load(Ordering::Relaxed);
        let done = self.rays_done.load(Ordering::Relaxed);
        if total == 0 {
            0.0
        } else {
            (done as f64 / total as f64).min(1.0)
        }
    }
}

/// What the tracer computed: the measure of the work each effect costs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    /// Colours traced: 1 unless white light is dispersed.
    pub wavelengths: usize,
    /// Rays started by the source, over all colours.
    pub source_rays: usize,
    /// Refraction kernel calls: one per hit between different indices.
    pub kernel_calls: usize,
    /// Boundaries crossed between equal indices, where no kernel call was needed.
    pub equal_index_skips: usize,
    /// Hits where the ray was totally internally reflected.
    pub total_internal_reflections: usize,
    /// Partially reflected rays spawned.
    pub reflections_spawned: usize,
    /// Fresnel evaluations (s and p together count as one).
    pub fresnel_evaluations: usize,
    /// Beer–Lambert attenuations of a segment.
    pub absorption_evaluations: usize,
    /// Straight segments recorded.
    pub segments: usize,
    /// Paths recorded: source rays and spawned reflections.
    pub paths: usize,
    /// Whether the trace stopped before it finished (see [`Self::stopped`]).
    pub truncated: bool,
    /// Why it stopped before it finished, if it did: its message in the JSON, `null` otherwise.
    pub stopped: Option<Stop>,
}

impl fmt::Display for Counts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rows = [
            ("wavelengths", self.wavelengths),
            ("source rays", self.source_rays),
            ("kernel calls", self.kernel_calls),
            ("equal-index skips", self.equal_index_skips),
            (
                "total internal reflections",
                self.total_internal_reflections,
            ),
            ("reflections spawned", self.reflections_spawned),
            ("Fresnel evaluations", self.fresnel_evaluations),
            ("absorption evaluations", self.absorption_evaluations),
            ("segments", self.segments),
            ("paths", self.paths),
        ];
        for (name, count) in rows {
            writeln!(f, "{name:<28}{count}")?;
        }
        if let Some(stop) = self.stopped {
            writeln!(f, "{stop}")?;
        }
        Ok(())
    }
}

/// What happened at a hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// The ray went through (and, with partial reflection, also reflected).
    Refracted,
    /// Total internal reflection.
    TotalInternalReflection,
}

/// One kernel call: an interface hit between different indices.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Hit {
    /// Where, in world coordinates.
    pub point: DVec2,
    /// W: the unit direction the ray travels in.
    pub w: DVec2,
    /// N: the shape's unit outward normal, as given (not turned to face the ray).
    pub n: DVec2,
    /// The index of the medium the ray comes from.
    pub mu_i: f64,
    /// The index of the medium beyond.
    pub mu_t: f64,
    /// The medium the ray comes from (position in [`Scene::media`]).
    pub from_medium: usize,
    /// The medium beyond.
    pub to_medium: usize,
    /// Into or out of the shape's region.
    pub side: Side,
    /// The shape hit (position in [`Scene::shapes`]).
    pub shape: usize,
    /// The path that reached it (position in [`Trace::paths`]).
    pub path: usize,
    /// The light traced: one wavelength, or white light traced once.
    #[serde(rename = "wavelength_nm", serialize_with = "serialize_wavelength")]
    pub light: Light,
    /// Refracted or totally internally reflected.
    pub outcome: Outcome,
    /// The Fresnel intensities, when the scene asks for them.
    pub fresnel: Option<Fresnel>,
}

impl Hit {
    /// The hit as a problem for the single-interface kernel ([`refraction_kernel::refract`]): W
    /// along the ray, N the outward normal as the shape gives it, so that a ray leaving a
    /// region shows the normal being turned around.
    #[must_use]
    pub fn incidence(&self) -> Incidence<f64> {
        Incidence {
            w: self.w.extend(0.0),
            n: self.n.extend(0.0),
            mu_i: self.mu_i,
            mu_t: self.mu_t,
            convention: Convention::AlongRay,
        }
    }
}

/// One straight piece of a path, inside one medium.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Segment {
    /// Where it starts.
    pub from: DVec2,
    /// Where it ends.
    pub to: DVec2,
    /// The path it belongs to.
    pub path: usize,
    /// The medium it crosses (position in [`Scene::media`]).
    pub medium: usize,
    /// The light traced: one wavelength, or white light traced once.
    #[serde(rename = "wavelength_nm", serialize_with = "serialize_wavelength")]
    pub light: Light,
    /// The intensity at `from` as a fraction of the source ray's, when intensities are traced.
    pub intensity: Option<f64>,
    /// The intensity at `to` (less than at `from` in an absorbing medium).
    pub intensity_end: Option<f64>,
}

/// Why a path ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum End {
    /// It left every shape and reached the edge of the world bounds.
    Escaped,
    /// It reached a screen.
    Screen,
    /// It reached the scene's maximum depth.
    MaxDepth,
    /// Its intensity fell below the scene's minimum.
    Faint,
    /// The trace stopped here, at its [`Budget`] or cancelled ([`Counts::stopped`]).
    Truncated,
}

/// A ray from its start (the source, or a hit where it was reflected off) to its end,
/// following refraction and total internal reflection.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Path {
    /// The light traced: one wavelength, or white light traced once.
    #[serde(rename = "wavelength_nm", serialize_with = "serialize_wavelength")]
    pub light: Light,
    /// Its segments: a range of [`Trace::segments`].
    pub segments: Range<usize>,
    /// The hit it was reflected off (position in [`Trace::hits`]), or `None` for a source ray.
    pub parent_hit: Option<usize>,
    /// How many partial reflections lie between it and the source.
    pub reflections: u32,
    /// Why it ends.
    pub end: End,
}

/// Everything one trace found, in world coordinates.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Trace {
    /// The world rectangle the trace was clipped to.
    pub bounds: Bounds,
    /// Every straight segment of every path, path after path.
    pub segments: Vec<Segment>,
    /// Every path.
    pub paths: Vec<Path>,
    /// Every kernel call.
    pub hits: Vec<Hit>,
    /// What was computed.
    pub counts: Counts,
}

impl Trace {
    /// The hit nearest to a world point, if there is any hit.
    #[must_use]
    pub fn nearest_hit(&self, point: DVec2) -> Option<&Hit> {
        self.hits.iter().min_by(|a, b| {
            point
                .distance_squared(a.point)
                .total_cmp(&point.distance_squared(b.point))
        })
    }

    /// A path's points: its start, then the end of each segment.
    #[must_use]
    pub fn points(&self, path: &Path) -> Vec<DVec2> {
        let segments = &self.segments[path.segments.clone()];
        segments
            .first()
            .map(|s| s.from)
            .into_iter()
            .chain(segments.iter().map(|s| s.to))
            .collect()
    }
}

/// Unpolarised light split into its s and p halves (fractions of the source ray's intensity).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Intensity {
    s: f64,
    p: f64,
}

impl Intensity {
    const SOURCE: Self = Self { s: 0.5, p: 0.5 };

    fn total(self) -> f64 {
        self.s + self.p
    }

    fn scaled(self, s: f64, p: f64) -> Self {
        Self {
            s: self.s * s,
            p: self.p * p,
        }
    }
}

/// A ray waiting to be followed.
#[derive(Clone, Copy, Debug)]
struct Ray {
    origin: DVec2,
    direction: DVec2,
    intensity: Option<Intensity>,
    depth: u32,
    parent_hit: Option<usize>,
    reflections: u32,
}

/// The state of one trace of a scene.
struct Tracer<'a> {
    scene: &'a Scene,
    trace: &'a mut Trace,
    search: Search<'a>,
    budget: Budget,
    progress: &'a Progress,
    pending: Vec<Ray>,
    /// The position in [`Trace::paths`] of the path being followed.
    path: usize,
}

impl Scene {
    /// Traces the scene's source through its shapes with the effects the scene asks for.
    #[must_use]
    pub fn trace(&self) -> Trace {
        let mut trace = Trace {
            bounds: self.bounds(),
            segments: Vec::new(),
            paths: Vec::new(),
            hits: Vec::new(),
            counts: Counts::default(),
        };
        self.retrace(&mut trace);
        trace
    }

    /// Traces the scene again into `trace`, replacing what it held but keeping its memory:
    /// what an editor calls on every drag, where allocating afresh would cost more than the
    /// tracing itself.
    pub fn retrace(&self, trace: &mut Trace) {
        self.retrace_within(trace, Budget::DEFAULT, &Progress::default());
    }

    /// [`Self::retrace`] within `budget`, reporting to `progress` and stopping when it is
    /// cancelled: what a trace on another thread calls.
    pub fn retrace_within(&self, trace: &mut Trace, budget: Budget, progress: &Progress) {
        trace.bounds = self.bounds();
        trace.segments.clear();
        trace.paths.clear();
        trace.hits.clear();
        trace.counts = Counts::default();
        Tracer {
            scene: self,
            trace,
            search: Search::new(self),
            budget,
            progress,
            pending: Vec::new(),
            path: 0,
        }
        .run();
    }
}

impl Tracer<'_> {
    fn run(&mut self) {
        let scene = self.scene;
        let effects = scene.effects();
        let colours = scene.source().colours(effects.dispersion);
        self.progress
            .rays_total
            .store(colours.len() * scene.source().rays, Ordering::Relaxed);
        for colour in colours {
            self.trace.counts.wavelengths += 1;
            let wavelength = traced_wavelength(colour);
            let indices: Vec<f64> = scene.media().iter().map(|m| m.index(wavelength)).collect();
            for (origin, direction) in scene.source().rays() {
                self.trace.counts.source_rays += 1;
                self.pending.push(Ray {
                    origin,
                    direction,
                    intensity: effects.intensities().then_some(Intensity::SOURCE),
                    depth: 0,
                    parent_hit: None,
                    reflections: 0,
                });
                while let Some(ray) = self.pending.pop() {
                    self.follow(ray, colour, &indices);
                }
                self.progress.rays_done.fetch_add(1, Ordering::Relaxed);
                if self.trace.counts.truncated {
                    return;
                }
            }
        }
    }

    /// Records a segment, attenuating the intensity in an absorbing medium when asked to.
    fn segment(&mut self, from: DVec2, to: DVec2, medium: usize, colour: Light, ray: &mut Ray) {
        let effects = self.scene.effects();
        let start = ray.intensity;
        let absorption = self.scene.media()[medium].absorption;
        if let Some(i) = ray.intensity
            && effects.absorption
            && absorption > 0.0
        {
            self.trace.counts.absorption_evaluations += 1;
            let kept = (-absorption * from.distance(to)).exp();
            ray.intensity = Some(i.scaled(kept, kept));
        }
        self.trace.segments.push(Segment {
            from,
            to,
            path: self.path,
            medium,
            light: colour,
            intensity: start.map(Intensity::total),
            intensity_end: ray.intensity.map(Intensity::total),
        });
    }

    /// Why the trace must stop before its next segment, if it must.
    fn over_budget(&self) -> Option<Stop> {
        if self.trace.segments.len() >= self.budget.segments {
            Some(Stop::Segments(self.budget.segments))
        } else if self.search.tests() >= self.budget.tests {
            Some(Stop::Tests(self.budget.tests))
        } else if self.progress.is_cancelled() {
            Some(Stop::Cancelled)
        } else {
            None
        }
    }

    fn is_faint(&self, intensity: Option<Intensity>) -> bool {
        intensity.is_some_and(|i| i.total() < self.scene.effects().min_intensity)
    }

    /// Follows one ray to its end, queueing the reflections it spawns.
    fn follow(&mut self, mut ray: Ray, colour: Light, indices: &[f64]) {
        let scene = self.scene;
        let first_segment = self.trace.segments.len();
        self.path = self.trace.paths.len();
        let mut medium = self.search.medium_where(ray.origin, None);
        let end = loop {
            if let Some(stop) = self.over_budget() {
                self.trace.counts.truncated = true;
                self.trace.counts.stopped = Some(stop);
                break End::Truncated;
            }
            let (origin, d) = (ray.origin, ray.direction);
            let Some((shape, crossing)) = self.search.first_crossing(origin, d) else {
                let to = origin + d * self.trace.bounds.exit(origin, d);
                self.segment(origin, to, medium, colour, &mut ray);
                break End::Escaped;
            };
            let x = origin + d * crossing.t;
            if scene.shapes()[shape].medium().is_none() {
                self.segment(origin, x, medium, colour, &mut ray);
                break End::Screen;
            }
            let side = if d.dot(crossing.normal) < 0.0 {
                Side::Outside
            } else {
                Side::Inside
            };
            let entering = side == Side::Outside;
            let before = self.search.medium_where(x, Some((shape, !entering)));
            let after = self.search.medium_where(x, Some((shape, entering)));
            self.segment(origin, x, before, colour, &mut ray);
            ray.origin = x;
            medium = after;
            if self.is_faint(ray.intensity) {
                break End::Faint;
            }
            let (mu_i, mu_t) = (indices[before], indices[after]);
            if mu_i == mu_t {
                self.trace.counts.equal_index_skips += 1;
                continue;
            }
            if ray.depth >= scene.effects().max_depth {
                break End::MaxDepth;
            }
            let hit = Hit {
                point: x,
                w: d,
                n: crossing.normal,
                mu_i,
                mu_t,
                from_medium: before,
                to_medium: after,
                side,
                shape,
                path: self.path,
                light: colour,
                outcome: Outcome::Refracted,
                fresnel: None,
            };
            if self.interact(&mut ray, hit) == Outcome::TotalInternalReflection {
                medium = before;
            }
        };
        self.trace.paths.push(Path {
            light: colour,
            segments: first_segment..self.trace.segments.len(),
            parent_hit: ray.parent_hit,
            reflections: ray.reflections,
            end,
        });
        self.trace.counts.segments = self.trace.segments.len();
        self.trace.counts.paths = self.trace.paths.len();
    }

    /// One kernel call at `hit` (its outcome and Fresnel intensities not yet filled in): turns
    /// `ray` into the transmitted or totally reflected ray, records the hit and, when asked
    /// for, queues the partial reflection.
    fn interact(&mut self, ray: &mut Ray, mut hit: Hit) -> Outcome {
        let effects = *self.scene.effects();
        let facing = match hit.side {
            Side::Outside => hit.n,
            Side::Inside => -hit.n,
        };
        let mu = hit.mu_i / hit.mu_t;
        self.trace.counts.kernel_calls += 1;
        ray.depth += 1;
        let kernel = refract_facing(hit.w.extend(0.0), facing.extend(0.0), mu);
        let reflected = (hit.w + facing * (2.0 * kernel.cos_i)).normalize();
        let Some(transmitted) = kernel.transmitted else {
            self.trace.counts.total_internal_reflections += 1;
            hit.outcome = Outcome::TotalInternalReflection;
            hit.fresnel = effects.fresnel.then_some(Fresnel::TOTAL_REFLECTION);
            self.trace.hits.push(hit);
            ray.direction = reflected;
            return hit.outcome;
        };
        hit.fresnel = effects.fresnel.then(|| {
            self.trace.counts.fresnel_evaluations += 1;
            Fresnel::new(mu, kernel.cos_i, transmitted.cos_t)
        });
        self.trace.hits.push(hit);
        // Without Fresnel the split is unknown: both rays keep the incoming intensity.
        let (r, t) = hit
            .fresnel
            .map_or(((1.0, 1.0), (1.0, 1.0)), |f| ((f.rs, f.rp), (f.ts, f.tp)));
        if effects.partial_reflection {
            let intensity = ray.intensity.map(|i| i.scaled(r.0, r.1));
            if !self.is_faint(intensity) {
                self.trace.counts.reflections_spawned += 1;
                self.pending.push(Ray {
                    origin: hit.point,
                    direction: reflected,
                    intensity,
                    depth: ray.depth,
                    parent_hit: Some(self.trace.hits.len() - 1),
                    reflections: ray.reflections + 1,
                });
            }
        }
        ray.intensity = ray.intensity.map(|i| i.scaled(t.0, t.1));
        ray.direction = project(transmitted.t);
        hit.outcome
    }
}

/// The kernel's 3D direction (z = 0 up to rounding) back in the plane, unit length.
fn project(v: DVec3) -> DVec2 {
    v.truncate().normalize()
}
