//! Scenes: 2D arrangements of shapes and media that a ray, a beam or a fan crosses interface
//! after interface, one kernel call per hit, computing only the effects the scene asks for.
//!
//! - [`Scene`]: a loaded scene ([`Scene::load`], [`Scene::embedded`], [`Scene::from_toml`]),
//!   its setters for an editor, and [`Scene::trace`].
//! - [`Trace`]: segments, paths, hits and the [`Counts`] of what was computed.
//! - [`catalogue`]: the scenes built into the binary (from `assets/scenes/`).
//! - [`TraceReport`]: the JSON of the `trace` command.
//!
//! The file format is described in the repository's user guide (`docs/scenes.md`).

mod bounds;
mod effects;
mod embedded;
mod format;
mod fresnel;
mod medium;
mod outline;
mod search;
mod shape;
mod source;
mod spec;
mod trace;
mod trace_report;
mod write;

use glam::DVec2;

pub use bounds::Bounds;
pub use effects::{Effects, EffectsError};
pub use embedded::{DEFAULT_SCENE, SceneInfo, catalogue};
pub use format::{
    Invalid, LoadError, MAX_COORDINATE, MAX_POINTS, MAX_SCENE_FILE_BYTES, MAX_SHAPES, MIN_SIZE,
    Position, invalid, parse_toml, toml_text,
};
pub use fresnel::Fresnel;
pub use medium::{Dispersion, Medium, REFERENCE_WAVELENGTH_NM, WHITE_WAVELENGTHS_NM};
pub use outline::{Outline, Piece};
pub use search::MAX_INTERSECTION_TESTS;
pub use shape::{Crossing, Lens, Shape, T_MIN};
pub use source::{Light, Source, SourceKind, traced_wavelength};
pub use spec::Numbers;
pub use trace::{
    Budget, Counts, End, Hit, MAX_SEGMENTS, Outcome, Path, Progress, Segment, Side, Stop, Trace,
};
pub use trace_report::TraceReport;
pub use write::WriteError;

/// A scene ready to trace: media, shapes, a source and the effects it asks for.
///
/// Built only by loading a file, so every number in it has been checked; the setters keep it
/// that way.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    name: String,
    title: String,
    description: String,
    media: Vec<Medium>,
    background: usize,
    shapes: Vec<Shape>,
    source: Source,
    effects: Effects,
    view: Option<Bounds>,
}

/// Why an edit of a scene was refused (the scene is left as it was).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EditError {
    /// A coordinate is NaN or infinite.
    #[error("every coordinate must be a finite number")]
    NotFinite,
    /// A coordinate would lie beyond ±[`MAX_COORDINATE`].
    #[error("every coordinate must lie within ±{MAX_COORDINATE} (the range a scene file may use)")]
    OutOfRange,
    /// A direction is the zero vector.
    #[error("a direction must not be the zero vector")]
    NoDirection,
    /// No shape has this position in the list.
    #[error("the scene has no shape {0}")]
    NoSuchShape(usize),
    /// A ray count outside 1 ..= [`Source::MAX_RAYS`].
    #[error("{0} rays: a source has from 1 to {max} rays", max = Source::MAX_RAYS)]
    RayCount(usize),
    /// Effects that cannot be traced (see [`Effects::check`]).
    #[error(transparent)]
    Effects(#[from] EffectsError),
}

fn finite(v: DVec2) -> Result<DVec2, EditError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(EditError::NotFinite)
    }
}

/// `v` if it is a position a scene file could give.
fn in_range(v: DVec2) -> Result<DVec2, EditError> {
    if finite(v)?.abs().max_element() <= MAX_COORDINATE {
        Ok(v)
    } else {
        Err(EditError::OutOfRange)
    }
}

impl Scene {
    /// The embedded scene's name, or the file's name without its extension.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The title the file gives.
    #[must_use]
    pub fn title(&self) -> &str {
        &self.title
    }

    /// The description the file gives (may be empty).
    #[must_use]
    pub fn description(&self) -> &str {
        &self.description
    }

    /// Every medium; shapes, segments and hits refer to them by position.
    #[must_use]
    pub fn media(&self) -> &[Medium] {
        &self.media
    }

    /// The medium outside every shape (position in [`Self::media`]).
    #[must_use]
    pub fn background(&self) -> usize {
        self.background
    }

    /// The shapes; where regions overlap, the later one is on top and its medium counts.
    #[must_use]
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// The source.
    #[must_use]
    pub fn source(&self) -> &Source {
        &self.source
    }

    /// The effects the tracer computes.
    #[must_use]
    pub fn effects(&self) -> &Effects {
        &self.effects
    }

    /// The world rectangle: the file's `[view]`, else the shapes and the source with a margin.
    #[must_use]
    pub fn bounds(&self) -> Bounds {
        self.view.unwrap_or_else(|| {
            self.source
                .rays()
                .map(|(origin, _)| Bounds::point(origin))
                .chain(self.shapes.iter().filter_map(Shape::extent))
                .fold(Bounds::point(self.source.origin), Bounds::union)
                .padded(0.15, 0.5)
        })
    }

    /// The scene with its world widened to `aspect` (width over height, see
    /// [`Bounds::widened_to`]): what a canvas of that shape shows, traced to its edges.
    #[must_use]
    pub fn framed(&self, aspect: f64) -> Self {
        Self {
            view: Some(self.bounds().widened_to(aspect)),
            ..self.clone()
        }
    }

    /// The outline of every shape, a line's half-plane cut to [`Self::bounds`].
    #[must_use]
    pub fn outlines(&self) -> Vec<Outline> {
        self.outlines_within(self.bounds())
    }

    /// The outline of every shape, a line's half-plane cut to `bounds` (a trace's world, which
    /// may be the scene's framed to a canvas).
    #[must_use]
    pub fn outlines_within(&self, bounds: Bounds) -> Vec<Outline> {
        self.shapes
            .iter()
            .enumerate()
            .map(|(i, shape)| Outline {
                shape: i,
                medium: shape.medium().map(|m| self.media[m].name.clone()),
                closed: shape.medium().is_some(),
                pieces: shape.pieces(bounds),
            })
            .collect()
    }

    /// The medium at `p`: that of the topmost region containing it, or the background.
    /// `on_boundary` = (shape, inside) decides that shape's side for a point on its boundary.
    #[must_use]
    pub fn medium_where(&self, p: DVec2, on_boundary: Option<(usize, bool)>) -> usize {
        self.shapes
            .iter()
            .enumerate()
            .rev()
            .find_map(|(i, shape)| {
                let medium = shape.medium()?;
                let inside = match on_boundary {
                    Some((hit, inside)) if hit == i => inside,
                    _ => shape.contains(p),
                };
                inside.then_some(medium)
            })
            .unwrap_or(self.background)
    }

    /// The first boundary the ray `origin + t·direction` (unit `direction`) crosses at
    /// t > [`T_MIN`]: the shape's position in [`Self::shapes`] and the crossing.
    #[must_use]
    pub fn first_crossing(&self, origin: DVec2, direction: DVec2) -> Option<(usize, Crossing)> {
        // Piece by piece in one plain loop, the first of equal crossings kept: the tracer's
        // inner loop (each shape's own first crossing, folded, took three times as long).
        let mut best: Option<(usize, Crossing)> = None;
        for (i, shape) in self.shapes.iter().enumerate() {
            for piece in 0..shape.piece_count() {
                let Some(c) = shape.piece_crossing(piece, origin, direction) else {
                    continue;
                };
                if best.is_none_or(|(_, b)| c.t < b.t) {
                    best = Some((i, c));
                }
            }
        }
        best
    }

    /// Moves the source to start at `origin`.
    ///
    /// # Errors
    /// [`EditError::NotFinite`], or [`EditError::OutOfRange`] beyond ±[`MAX_COORDINATE`].
    pub fn set_source_origin(&mut self, origin: DVec2) -> Result<(), EditError> {
        self.source.origin = in_range(origin)?;
        Ok(())
    }

    /// Points the source along `direction` (any non-zero length).
    ///
    /// # Errors
    /// [`EditError::NotFinite`] or [`EditError::NoDirection`].
    pub fn set_source_direction(&mut self, direction: DVec2) -> Result<(), EditError> {
        let d = finite(direction)?;
        // Scaled by its largest component first, so that no length over- or underflows.
        let unit = (d / d.abs().max_element())
            .try_normalize()
            .ok_or(EditError::NoDirection)?;
        self.source.direction = unit;
        Ok(())
    }

    /// Sets how many rays a beam or fan has (a single ray keeps one).
    ///
    /// # Errors
    /// [`EditError::RayCount`] outside 1 ..= [`Source::MAX_RAYS`].
    pub fn set_ray_count(&mut self, rays: usize) -> Result<(), EditError> {
        if !(1..=Source::MAX_RAYS).contains(&rays) {
            return Err(EditError::RayCount(rays));
        }
        if self.source.kind != SourceKind::Ray {
            self.source.rays = rays;
        }
        Ok(())
    }

    /// Moves shape `index` by `delta` world units.
    ///
    /// # Errors
    /// [`EditError::NoSuchShape`], [`EditError::NotFinite`], or [`EditError::OutOfRange`] when
    /// the move would take a coordinate beyond ±[`MAX_COORDINATE`].
    pub fn move_shape(&mut self, index: usize, delta: DVec2) -> Result<(), EditError> {
        let delta = finite(delta)?;
        let shape = self
            .shapes
            .get(index)
            .ok_or(EditError::NoSuchShape(index))?;
        let mut moved = shape.clone();
        moved.translate(delta);
        // The delta and the shape are finite, so the moved shape is finite or infinite, never NaN.
        if moved.reach() > MAX_COORDINATE {
            return Err(EditError::OutOfRange);
        }
        self.shapes[index] = moved;
        Ok(())
    }

    /// Replaces the effects, e.g. with [`Effects::everything`] to see what leaving nothing out
    /// costs.
    ///
    /// # Errors
    /// [`EditError::Effects`] when [`Effects::check`] refuses them.
    pub fn set_effects(&mut self, effects: Effects) -> Result<(), EditError> {
        effects.check()?;
        self.effects = effects;
        Ok(())
    }
}
