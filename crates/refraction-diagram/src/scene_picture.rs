//! The picture of a traced scene: media shaded by index, rays coloured by wavelength with their
//! opacity by intensity, a marker at every kernel call, the source and shape handles, and a
//! banner with the title, the counts of what was computed and the legend. Built as
//! [`Primitive`]s directly (no dashes to lower), because a scene of a thousand rays is rebuilt
//! on every frame of a drag.

use crate::scene_words::{medium_name, scene_title};
use std::collections::{HashMap, HashSet};

use glam::{DVec2, Vec2};

use super::font::Typeface;
use super::geometry::{Colour, Rect, convex_pieces};
use super::layout::{SMALLEST_TEXT, Viewport, font_size};
use super::numbers::number;
use super::obstacle::Obstacle;
use super::palette::Palette;
use super::picture::{GRAB_SCALE, TOUCH_TARGET, medium_colour};
use super::placer::{Need, Placer};
use super::shapes::{Align, ArrowRole, Dash, Figure, Label, Primitive, Stroke};
use super::spectrum::{ray_colour, wavelength_colour};
use refraction_i18n::t;
use refraction_scene::{
    Bounds, Counts, EditError, Hit, Light, Outcome, Path, REFERENCE_WAVELENGTH_NM, Scene, Side,
    Trace,
};

/// Ray points closer than this many pixels to the previous one are left out: they change
/// nothing on screen and a dense scene has many.
const MIN_STEP: f32 = 0.5;

/// A draggable point of a scene picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SceneHandleId {
    /// The source's origin: the start of the ray, the centre of the beam, the apex of the fan.
    Source,
    /// A point ahead of the source along its direction: dragging it aims the source.
    Aim,
    /// A shape's anchor ([`refraction_scene::Shape::anchor`]), by position in the scene's shapes.
    Shape(usize),
}

impl SceneHandleId {
    /// The handle's name for screen readers and tests, e.g. `Shape 1 handle (water)`.
    #[must_use]
    pub fn label(self, scene: &Scene) -> String {
        match self {
            Self::Source => t!("diagram-handle-source"),
            Self::Aim => t!("diagram-handle-aim"),
            Self::Shape(i) => {
                let what = scene
                    .shapes()
                    .get(i)
                    .and_then(|s| s.medium())
                    .and_then(|m| scene.media().get(m))
                    .map_or_else(|| t!("diagram-screen"), |m| medium_name(&m.name));
                let number = (i + 1).to_string();
                t!("diagram-handle-shape", number = number, medium = what)
            }
        }
    }
}

/// A draggable point on the canvas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneHandle {
    /// Which handle.
    pub id: SceneHandleId,
    /// Its centre on the canvas.
    pub center: Vec2,
    /// Its radius in pixels.
    pub radius: f32,
}

impl SceneHandle {
    /// The square in which a press grabs the handle (a little larger than the handle).
    #[must_use]
    pub fn grab_area(&self) -> Rect {
        Rect::around(self.center, self.radius * GRAB_SCALE)
    }
}

/// Where things go on a canvas for a scene: the banner at the top and the world rectangle
/// fitted into the rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneLayout {
    /// The whole canvas, from (0, 0).
    pub canvas: Rect,
    /// The strip at the top: title, counts, legend.
    pub banner: Rect,
    /// The area the world is shown in.
    pub drawing: Rect,
    /// The world↔canvas map, fitted to the world rectangle.
    pub view: Viewport,
    /// The world rectangle it was fitted to.
    pub bounds: Bounds,
    /// The label font size in pixels; strokes, markers and handles scale with it.
    pub font: f32,
    /// Handles sized for a finger ([`SceneLayout::for_touch`]).
    pub touch: bool,
}

impl SceneLayout {
    /// The same layout with handles for a finger (a phone's student view): each handle's grab
    /// area at least [`TOUCH_TARGET`] across, the shapes' handles as far apart, and the world
    /// fitted half a target inside the drawing area, so that a handle on the world's edge (the
    /// fibre's source) keeps all its grab area on the canvas.
    #[must_use]
    pub fn for_touch(self) -> Self {
        let inset = Vec2::splat((self.font * 0.5).max(TOUCH_TARGET * 0.5));
        let inner = Rect {
            min: self.drawing.min + inset,
            max: (self.drawing.max - inset).max(self.drawing.min + inset + Vec2::ONE),
        };
        Self {
            touch: true,
            view: Viewport::fitted(self.bounds.min, self.bounds.max, &inner),
            ..self
        }
    }

    /// A handle's radius: `radius`, or for a finger at least what gives a grab area
    /// [`TOUCH_TARGET`] across.
    fn handle_radius(&self, radius: f32) -> f32 {
        if self.touch {
            radius.max(TOUCH_TARGET * 0.5 / GRAB_SCALE)
        } else {
            radius
        }
    }

    /// The layout that shows the world rectangle `bounds` on a canvas `size` pixels wide and
    /// high (sizes below 1 are treated as 1).
    #[must_use]
    pub fn new(bounds: Bounds, size: Vec2) -> Self {
        let size = size.max(Vec2::ONE);
        Self::with_banner(bounds, size, font_size(size) * 4.4)
    }

    /// The layout of `scene` traced as `trace` on a canvas `size` pixels wide and high: as
    /// [`SceneLayout::new`], with the banner as tall as its wrapped lines need (at most half
    /// the canvas).
    #[must_use]
    pub fn for_scene(scene: &Scene, trace: &Trace, size: Vec2) -> Self {
        let layout = Self::new(trace.bounds, size);
        let face = Typeface::egui_default();
        let rows = banner_rows(
            scene,
            trace,
            layout.font,
            (&Palette::STANDARD, Told::Everything),
        );
        let room = layout.banner_room();
        let lines: f32 = rows
            .iter()
            .map(|(pieces, size)| {
                let count = flow(&face, pieces, *size, room).len();
                count as f32 * face.line_height(*size)
            })
            .sum();
        let height = lines + layout.font * BANNER_PAD * 2.0;
        if height > layout.banner.size().y {
            Self::with_banner(trace.bounds, layout.canvas.size(), height)
        } else {
            layout
        }
    }

    /// The width a line of the banner may take.
    fn banner_room(&self) -> f32 {
        (self.canvas.size().x - 2.0 * self.font * BANNER_MARGIN).max(1.0)
    }

    fn with_banner(bounds: Bounds, size: Vec2, height: f32) -> Self {
        let font = font_size(size);
        let canvas = Rect::from_min_size(Vec2::ZERO, size);
        let banner = Rect::from_min_size(Vec2::ZERO, Vec2::new(size.x, height.min(size.y * 0.5)));
        let drawing = Rect {
            min: Vec2::new(0.0, banner.max.y),
            max: Vec2::new(size.x, size.y.max(banner.max.y + 1.0)),
        };
        let inset = Vec2::splat(font * 0.5);
        let inner = Rect {
            min: drawing.min + inset,
            max: (drawing.max - inset).max(drawing.min + inset + Vec2::ONE),
        };
        Self {
            canvas,
            banner,
            drawing,
            view: Viewport::fitted(bounds.min, bounds.max, &inner),
            bounds,
            font,
            touch: false,
        }
    }

    /// One stroke-width unit in pixels.
    #[must_use]
    pub fn unit(&self) -> f32 {
        self.font / 14.0
    }

    /// The canvas point of a world point.
    #[must_use]
    pub fn at(&self, world: DVec2) -> Vec2 {
        self.view.to_canvas(world)
    }

    /// How far from a hit point (in pixels) a click still picks it.
    #[must_use]
    pub fn pick_radius(&self) -> f32 {
        self.font * 0.8
    }

    /// The handles of `scene`: the source, its aim, then each shape's anchor. A shape handle
    /// that would cover an earlier handle (a fibre's core and cladding share their centre) is
    /// moved down until it is clear; one that finds no clear place before the bottom of the
    /// canvas is left out, so that a scene of thousands of shapes gets as many handles as the
    /// canvas has room for, found in about one look each.
    #[must_use]
    pub fn handles(&self, scene: &Scene) -> Vec<SceneHandle> {
        let source = scene.source();
        let origin = self.at(source.origin);
        let aim = origin
            + self.view.direction(source.direction).normalize_or(Vec2::X) * (self.font * 5.0);
        let small = self.handle_radius(self.font * 0.5);
        let mut handles = vec![
            SceneHandle {
                id: SceneHandleId::Source,
                center: origin,
                radius: self.handle_radius(self.font * 0.6),
            },
            SceneHandle {
                id: SceneHandleId::Aim,
                center: aim,
                radius: small,
            },
        ];
        // Far enough apart for the two lines of a medium label beside each (and for a finger,
        // for their grab areas).
        let step = (self.font * 2.4).max(small * GRAB_SCALE * 2.1);
        // The handles by cell of a grid `step` wide: any handle nearer than `step` is in one of
        // the nine cells around.
        let cell = |p: Vec2| ((p.x / step).floor() as i64, (p.y / step).floor() as i64);
        let mut grid: HashMap<(i64, i64), Vec<Vec2>> = HashMap::new();
        for h in &handles {
            grid.entry(cell(h.center)).or_default().push(h.center);
        }
        let crowded = |grid: &HashMap<(i64, i64), Vec<Vec2>>, p: Vec2| {
            let (x, y) = cell(p);
            (x - 1..=x + 1)
                .flat_map(|cx| (y - 1..=y + 1).map(move |cy| (cx, cy)))
                .filter_map(|c| grid.get(&c))
                .flatten()
                .any(|q| q.distance(p) < step * 0.99)
        };
        // Enough moves to go down the whole canvas; more would only pile handles below it.
        let most_moves = (self.canvas.size().y / step).ceil() as usize + 1;
        for (i, shape) in scene.shapes().iter().enumerate() {
            let mut center = self.at(shape.anchor());
            let mut moves = 0;
            while moves <= most_moves && crowded(&grid, center) {
                center.y += step;
                moves += 1;
            }
            if moves > most_moves || (moves > 0 && center.y > self.canvas.max.y) {
                continue;
            }
            grid.entry(cell(center)).or_default().push(center);
            handles.push(SceneHandle {
                id: SceneHandleId::Shape(i),
                center,
                radius: small,
            });
        }
        handles
    }

    /// Moves `handle` to the canvas point `p`: the source starts there, aims at it, or the
    /// shape moves with its handle. The caller retraces.
    ///
    /// # Errors
    /// The scene's [`EditError`] (e.g. aiming the source at itself); the scene is unchanged.
    pub fn drag(&self, scene: &mut Scene, handle: SceneHandleId, p: Vec2) -> Result<(), EditError> {
        let world = self.view.to_world(p);
        match handle {
            SceneHandleId::Source => scene.set_source_origin(world),
            SceneHandleId::Aim => scene.set_source_direction(world - scene.source().origin),
            SceneHandleId::Shape(i) => {
                // The handle may sit beside the anchor: the shape moves as far as its handle.
                let at = self
                    .handles(scene)
                    .into_iter()
                    .find(|h| h.id == handle)
                    .map_or(p, |h| h.center);
                scene.move_shape(i, world - self.view.to_world(at))
            }
        }
    }

    /// The hit nearest to the canvas point `p`, if it lies within [`Self::pick_radius`].
    #[must_use]
    pub fn hit_near<'t>(&self, trace: &'t Trace, p: Vec2) -> Option<&'t Hit> {
        trace
            .nearest_hit(self.view.to_world(p))
            .filter(|hit| self.at(hit.point).distance(p) <= self.pick_radius())
    }
}

/// The banner's margin left and right, and above and below, in label font sizes.
const BANNER_MARGIN: f32 = 0.6;
const BANNER_PAD: f32 = 0.3;

/// One run of text of one colour on a banner line, starting `x` pixels from the margin.
struct Run {
    text: String,
    colour: Colour,
    x: f32,
}

/// Coloured pieces of text laid out in lines `room` pixels wide, broken between words.
fn flow(face: &Typeface, pieces: &[(String, Colour)], size: f32, room: f32) -> Vec<Vec<Run>> {
    let mut lines: Vec<Vec<Run>> = vec![Vec::new()];
    let mut x = 0.0;
    for (text, colour) in pieces {
        for word in text.split_inclusive(' ') {
            let width = face.measure(word, size).x;
            let inked = face.measure(word.trim_end(), size).x;
            if x > 0.0 && x + inked > room {
                lines.push(Vec::new());
                x = 0.0;
            }
            // untranslated: a panic message for developers, never shown to a user.
            let line = lines.last_mut().expect("lines start with one line");
            match line.last_mut() {
                Some(run) if run.colour == *colour => run.text.push_str(word),
                _ => line.push(Run {
                    text: word.to_owned(),
                    colour: *colour,
                    x,
                }),
            }
            x += width;
        }
    }
    lines
}

/// What a picture tells of its trace in words and marker colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Told {
    /// Everything the tracer counted, and what happened at each hit.
    Everything,
    /// A lesson's question is asked about what happens past the first surface: only what the
    /// class sees before it answers (the source's rays and colours; each hit by the side the
    /// ray meets it from). The counts of reflections and of total internal reflections, the
    /// kernel calls and the Fresnel evaluations would each give the answer away in words.
    Asking,
}

/// The banner's rows, each with its text size: the title, the counts, the legend.
fn banner_rows(
    scene: &Scene,
    trace: &Trace,
    font: f32,
    (p, told): (&Palette, Told),
) -> [(Vec<(String, Colour)>, f32); 3] {
    let small = (font * 0.85).max(SMALLEST_TEXT);
    let mut count_row = vec![(counts_text(&trace.counts, told), p.ink)];
    if trace.counts.truncated && told == Told::Everything {
        count_row.push((
            format!(
                " · {}",
                t!("diagram-stopped-at", count = trace.segments.len())
            ),
            p.alarm,
        ));
    }
    [
        (vec![(scene_title(scene), p.ink)], font * 1.05),
        (count_row, small),
        (legend(scene, trace, (p, told)), small),
    ]
}

/// Everything drawn for one traced scene on one canvas.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenePicture {
    /// What is drawn, back to front.
    pub primitives: Vec<Primitive>,
    /// The handles, as [`SceneLayout::handles`] gives them.
    pub handles: Vec<SceneHandle>,
    /// The labels left out for want of a free spot, at their anchors, for a hover to show.
    pub left_out: Vec<Label>,
    /// The title and the counts in words, for screen readers.
    pub summary: String,
}

/// The opacity of a ray of this intensity (a fraction of the source ray's; `None` when the
/// scene computes none): faint rays stay visible, and the steps are coarse so that a path is
/// split into separately drawn pieces only where the change shows.
fn opacity(intensity: Option<f64>) -> u8 {
    let Some(i) = intensity else {
        return 255;
    };
    let i = if i.is_finite() {
        i.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let alpha = 0.15 + 0.85 * i.sqrt();
    // Sixteenths, rounded (the cast truncates a positive number).
    let step = (alpha * 16.0 + 0.5) as u32;
    (step * 255 / 16) as u8
}

/// The name and index of a medium for a label (dispersive media at the reference wavelength).
fn medium_text(scene: &Scene, medium: usize) -> String {
    scene.media().get(medium).map_or_else(String::new, |m| {
        let n = number(m.index(REFERENCE_WAVELENGTH_NM), 3);
        if m.dispersion.is_dispersive() {
            let nm = reference_wavelength();
            let at = t!("diagram-index-at-wavelength", index = n, wavelength = nm);
            format!("{}\n{at}", medium_name(&m.name))
        } else {
            format!("{}\nn = {n}", medium_name(&m.name))
        }
    })
}

/// The reference wavelength in nanometres, written the local way.
fn reference_wavelength() -> String {
    refraction_i18n::decimal(&REFERENCE_WAVELENGTH_NM.to_string())
}

/// The counts of what the tracer computed, in one line; while a question is asked, only the
/// source's rays and colours.
fn counts_text(c: &Counts, told: Told) -> String {
    if told == Told::Asking {
        return [
            t!("diagram-count-source-rays", count = c.source_rays),
            t!("diagram-count-wavelengths", count = c.wavelengths),
        ]
        .join(" · ");
    }
    let mut parts = vec![
        t!("diagram-count-kernel-calls", count = c.kernel_calls),
        t!("diagram-count-tir", count = c.total_internal_reflections),
        t!("diagram-count-reflections", count = c.reflections_spawned),
        t!("diagram-count-fresnel", count = c.fresnel_evaluations),
        t!("diagram-count-wavelengths", count = c.wavelengths),
        t!("diagram-count-source-rays", count = c.source_rays),
    ];
    if c.equal_index_skips > 0 {
        let count = c.equal_index_skips;
        parts.push(t!("diagram-count-equal-index-skips", count = count));
    }
    if c.absorption_evaluations > 0 {
        let count = c.absorption_evaluations;
        parts.push(t!("diagram-count-absorption", count = count));
    }
    parts.join(" · ")
}

/// Builds the primitives, with the layout at hand.
struct ScenePictureBuilder<'a> {
    layout: &'a SceneLayout,
    palette: Palette,
    /// Labels wait here to be placed once every marker and handle is known.
    labels: Vec<Label>,
    /// Where the hit markers and handles start in `out`: what labels must leave free.
    marks_from: usize,
    /// Where the rays start in `out` (they end where the marks start): labels stay off them.
    rays_from: usize,
    /// The shapes' outlines: a label over one would hide a face or a surface, so labels keep
    /// off them where they can.
    faces: Vec<(Vec2, Vec2)>,
    face: Typeface,
    out: Vec<Primitive>,
    /// What the banner and the hit markers tell.
    told: Told,
}

impl ScenePictureBuilder<'_> {
    fn unit(&self) -> f32 {
        self.layout.unit()
    }

    /// A label with a light box behind it, placed (or left out) by [`ScenePictureBuilder::place`].
    fn boxed_label(&mut self, text: String, at: Vec2, (h, v): (Align, Align), size: f32) {
        self.labels.push(Label {
            text,
            at,
            h,
            v,
            size,
            colour: self.palette.ink,
            background: Some(self.palette.label_background),
        });
    }

    /// The ray segments labels keep off: each segment of each ray drawn, or of every few where
    /// thousands are drawn (their fans are dense; the labels still find the gaps).
    fn ray_obstacles(&self) -> impl Iterator<Item = Obstacle> + '_ {
        /// The most ray segments the labels are checked against.
        const MOST_SEGMENTS: usize = 3000;
        let rays = &self.out[self.rays_from..self.marks_from];
        let count: usize = rays
            .iter()
            .map(|p| match p {
                Primitive::Polyline { points, .. } => points.len().saturating_sub(1),
                _ => 0,
            })
            .sum();
        let stride = count.div_ceil(MOST_SEGMENTS).max(1);
        let segments = rays.iter().flat_map(|p| match p {
            Primitive::Polyline { points, width, .. } => points
                .windows(2)
                .map(|w| (w[0], w[1], *width))
                .collect::<Vec<_>>(),
            _ => Vec::new(),
        });
        segments
            .step_by(stride)
            .map(|(a, b, width)| Obstacle::Shaft {
                a,
                b,
                half_width: width * 0.5 + 1.0,
                firm: false,
            })
    }

    /// Everything the labels keep off: the hit markers, the aim's arrowhead, the handles'
    /// grab areas, the rays ([`Self::ray_obstacles`]) and the shapes' faces.
    fn obstacles(&self, handles: &[SceneHandle]) -> Vec<Obstacle> {
        let marks = self.out[self.marks_from..].iter().filter_map(|p| match p {
            Primitive::Disc { center, radius, .. } => Some(Obstacle::Disc {
                center: *center,
                radius: *radius,
            }),
            Primitive::Polygon { points, .. } if points.len() == 3 => {
                Some(Obstacle::Polygon(points.clone()))
            }
            _ => None,
        });
        let grabs = handles.iter().map(|h| Obstacle::Box(h.grab_area()));
        // A curved face is many short pieces: every few of them is enough to keep off it.
        let stride = self.faces.len().div_ceil(1000).max(1);
        let faces = self
            .faces
            .iter()
            .step_by(stride)
            .map(|&(a, b)| Obstacle::Shaft {
                a,
                b,
                half_width: 1.5 * self.unit(),
                firm: false,
            });
        marks
            .chain(grabs)
            .chain(self.ray_obstacles())
            .chain(faces)
            .collect()
    }

    /// Places the waiting labels inside the drawing area, off the hit markers, the handles,
    /// the aim's arrowhead and the rays, through the [`Placer`], with a leader line where the
    /// nearest free spot is far; none is left out (a scene's labels name what it teaches).
    fn place(&mut self, handles: &[SceneHandle]) -> Vec<Label> {
        let labels = core::mem::take(&mut self.labels);
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        for obstacle in self.obstacles(handles) {
            placer.avoid(obstacle);
        }
        let drawing = self.layout.drawing;
        let mut placement = placer.place_all(labels.into_iter().map(|l| (l, drawing, Need::Shown)));
        let left_out = core::mem::take(&mut placement.left_out);
        for figure in placement.figures() {
            figure.lower(&mut self.out);
        }
        left_out
    }

    /// The world rectangle in the background medium's shade (rays end at its edge), then each
    /// shape filled with its medium's shade and outlined; a
    /// screen as a thick line. Edges along the world rectangle's border are the view's edge,
    /// not a surface, and are not outlined.
    fn shapes(&mut self, scene: &Scene) {
        let background = scene
            .media()
            .get(scene.background())
            .map_or(1.0, |m| m.index(REFERENCE_WAVELENGTH_NM));
        self.out.push(Primitive::Polygon {
            points: self.layout.canvas.corners().to_vec(),
            colour: self.palette.outside_world,
        });
        let bounds = self.layout.bounds;
        self.out.push(Primitive::Polygon {
            points: bounds.corners().map(|p| self.layout.at(p)).to_vec(),
            colour: medium_colour(&self.palette, background),
        });
        let max_step = 2.0 / f64::from(self.layout.view.scale);
        let on_border = |a: DVec2, b: DVec2| {
            let same = |x: f64, y: f64| (x - y).abs() <= 1e-9 * (1.0 + x.abs());
            (0..2).any(|axis| {
                (same(a[axis], bounds.min[axis]) && same(b[axis], bounds.min[axis]))
                    || (same(a[axis], bounds.max[axis]) && same(b[axis], bounds.max[axis]))
            })
        };
        for outline in scene.outlines_within(bounds) {
            let world = outline.polyline(max_step);
            let points: Vec<Vec2> = world.iter().map(|p| self.layout.at(*p)).collect();
            let medium = scene.shapes().get(outline.shape).and_then(|s| s.medium());
            let Some(medium) = medium else {
                self.faces.extend(points.windows(2).map(|w| (w[0], w[1])));
                self.out.push(Primitive::Polyline {
                    points,
                    width: 4.0 * self.unit(),
                    colour: self.palette.ink,
                });
                continue;
            };
            let index = scene
                .media()
                .get(medium)
                .map_or(1.0, |m| m.index(REFERENCE_WAVELENGTH_NM));
            for piece in convex_pieces(&points) {
                self.out.push(Primitive::Polygon {
                    points: piece,
                    colour: medium_colour(&self.palette, index),
                });
            }
            let mut run: Vec<Vec2> = Vec::new();
            for (pair, canvas) in world.windows(2).zip(points.windows(2)) {
                if on_border(pair[0], pair[1]) {
                    self.edge(core::mem::take(&mut run));
                } else {
                    if run.is_empty() {
                        run.push(canvas[0]);
                    }
                    run.push(canvas[1]);
                }
            }
            self.edge(run);
        }
    }

    fn edge(&mut self, points: Vec<Vec2>) {
        if points.len() > 1 {
            self.faces.extend(points.windows(2).map(|w| (w[0], w[1])));
            self.out.push(Primitive::Polyline {
                points,
                width: 1.5 * self.unit(),
                colour: self.palette.ink,
            });
        }
    }

    /// Every path as polylines in its wavelength's colour, split where its opacity changes.
    /// When white light is dispersed, what every colour shares (a source ray up to its first
    /// kernel call, and the reflection there) is drawn once, as white light, and the colours
    /// are drawn shuffled ([`drawing_order`]): drawn colour by colour or ray by ray, one
    /// colour would lie on top wherever rays crowd, and a droplet of a thousand rays would be
    /// a red blob instead of a spectrum.
    fn rays(&mut self, trace: &Trace) {
        let wavelengths = trace.counts.wavelengths.max(1);
        let per_colour = (trace.counts.source_rays / wavelengths).max(1) as f32;
        let width = (2.2 * self.unit() * (30.0 / per_colour).sqrt().min(1.0)).max(0.8);
        // Dense dispersed light is drawn translucent, so that where many rays of every colour
        // cross, the colours mix (as light adds up) instead of the last drawn hiding the rest.
        let blend = if wavelengths > 1 {
            (30.0 / per_colour).sqrt().clamp(0.2, 1.0)
        } else {
            1.0
        };
        let faded = |alpha: u8| (f32::from(alpha) * blend).round() as u8;
        let mut white = HashSet::new();
        let mut last_colour = None;
        for path in drawing_order(trace).map(|i| &trace.paths[i]) {
            // Paths come colour after colour: look each colour up once.
            let colour = match last_colour {
                Some((traced, colour)) if traced == path.light => colour,
                _ => ray_colour(path.light),
            };
            last_colour = Some((path.light, colour));
            let mut segments = trace.segments.get(path.segments.clone()).unwrap_or(&[]);
            if wavelengths > 1
                && starts_colour_blind(trace, path)
                && let Some((first, rest)) = segments.split_first()
            {
                let key = [first.from, first.to].map(|p| [p.x.to_bits(), p.y.to_bits()]);
                if white.insert(key) {
                    let points = vec![self.layout.at(first.from), self.layout.at(first.to)];
                    let alpha = opacity(first.intensity);
                    self.ray(points, self.palette.white_light.with_alpha(alpha), width);
                }
                segments = rest;
            }
            let mut run: Vec<Vec2> = Vec::new();
            let mut alpha = 0;
            for s in segments {
                let mean = s
                    .intensity
                    .map(|i| (i + s.intensity_end.unwrap_or(i)) * 0.5);
                let a = faded(opacity(mean));
                let (from, to) = (self.layout.at(s.from), self.layout.at(s.to));
                if a != alpha {
                    self.ray(core::mem::take(&mut run), colour.with_alpha(alpha), width);
                    alpha = a;
                }
                if run.is_empty() {
                    run.push(from);
                }
                if run.last().is_some_and(|p| p.distance(to) >= MIN_STEP) {
                    run.push(to);
                }
            }
            self.ray(run, colour.with_alpha(alpha), width);
        }
    }

    fn ray(&mut self, points: Vec<Vec2>, colour: Colour, width: f32) {
        if points.len() > 1 {
            self.out.push(Primitive::Polyline {
                points,
                width,
                colour,
            });
        }
    }

    /// A small disc at each kernel call: light where the ray enters a shape, orange where it
    /// leaves one (the outward normal points along the ray and the kernel turns it round),
    /// purple at total internal reflection. At most one per marker-sized cell, so that a dense
    /// scene shows where hits are without drawing thousands of discs on one spot.
    fn hits(&mut self, trace: &Trace) {
        let radius = self.layout.font * 0.25;
        let cell = radius * 1.5;
        let cells = (self.layout.canvas.size() / cell).ceil();
        let (columns, rows) = (cells.x as usize, cells.y as usize);
        let mut taken = vec![false; columns * rows];
        for hit in &trace.hits {
            let center = self.layout.at(hit.point);
            // Off the canvas (only while a drag keeps an old layout) nothing would show.
            if !self.layout.canvas.contains(center) {
                continue;
            }
            let (column, row) = ((center.x / cell) as usize, (center.y / cell) as usize);
            let Some(cell) = taken.get_mut(row.min(rows - 1) * columns + column.min(columns - 1))
            else {
                continue;
            };
            if core::mem::replace(cell, true) {
                continue;
            }
            self.out.push(Primitive::Disc {
                center,
                radius,
                fill: HitKind::of(hit, self.told).colour(&self.palette),
                outline_width: self.unit(),
                outline: self.palette.ink,
            });
        }
    }

    /// Each shape's medium named beside its handle, and the background's in the world's top-left
    /// corner.
    fn media_labels(&mut self, scene: &Scene, handles: &[SceneHandle]) {
        let size = (self.layout.font * 0.8).max(SMALLEST_TEXT);
        let bounds = self.layout.bounds;
        let top_left = self.layout.at(DVec2::new(bounds.min.x, bounds.max.y));
        let corner = top_left.max(self.layout.drawing.min) + Vec2::splat(self.layout.font * 0.6);
        let text = medium_text(scene, scene.background());
        self.boxed_label(text, corner, (Align::Start, Align::Start), size);
        for handle in handles {
            let SceneHandleId::Shape(i) = handle.id else {
                continue;
            };
            let text = scene
                .shapes()
                .get(i)
                .and_then(|s| s.medium())
                .map_or_else(|| t!("diagram-screen"), |m| medium_text(scene, m));
            let at = handle.center + Vec2::new(handle.radius * GRAB_SCALE + size * 0.3, 0.0);
            self.boxed_label(text, at, (Align::Start, Align::Center), size);
        }
    }

    /// The source as a filled disc with an arrow to its aim handle; each shape's handle as a
    /// ring with a dot.
    fn handles(&mut self, handles: &[SceneHandle]) {
        let unit = self.unit();
        let ring = |colour| Stroke {
            width: 2.0 * unit,
            colour,
            dash: Dash::Solid,
        };
        let source = handles.iter().find(|h| h.id == SceneHandleId::Source);
        if let (Some(source), Some(aim)) =
            (source, handles.iter().find(|h| h.id == SceneHandleId::Aim))
        {
            Figure::Arrow {
                from: source.center,
                to: aim.center,
                stroke: Stroke {
                    dash: Dash::Dashed,
                    ..ring(self.palette.w)
                },
                role: ArrowRole::Ray,
            }
            .lower(&mut self.out);
        }
        for handle in handles {
            let (fill, outline) = match handle.id {
                SceneHandleId::Source => (self.palette.w, self.palette.ink),
                SceneHandleId::Aim => (self.palette.background, self.palette.w),
                SceneHandleId::Shape(_) => (self.palette.background, self.palette.ink),
            };
            Figure::Disc {
                center: handle.center,
                radius: handle.radius,
                fill,
                outline: ring(outline),
            }
            .lower(&mut self.out);
            if matches!(handle.id, SceneHandleId::Shape(_)) {
                Figure::Disc {
                    center: handle.center,
                    radius: handle.radius * 0.3,
                    fill: self.palette.ink,
                    outline: ring(self.palette.ink),
                }
                .lower(&mut self.out);
            }
        }
    }

    /// The banner, drawn last so that nothing covers it: the title, the counts, the legend,
    /// each wrapped to the canvas's width (a [`SceneLayout::for_scene`] banner is tall enough).
    fn banner(&mut self, scene: &Scene, trace: &Trace) -> String {
        let banner = self.layout.banner;
        self.out.push(Primitive::Polygon {
            points: banner.corners().to_vec(),
            colour: self.palette.calm,
        });
        let font = self.layout.font;
        let margin = font * BANNER_MARGIN;
        let room = self.layout.banner_room();
        let mut y = banner.min.y + font * BANNER_PAD;
        for (pieces, size) in banner_rows(scene, trace, font, (&self.palette, self.told)) {
            for line in flow(&self.face, &pieces, size, room) {
                for run in line {
                    self.out.push(Primitive::Text(Label {
                        text: run.text,
                        at: Vec2::new(margin + run.x, y),
                        h: Align::Start,
                        v: Align::Start,
                        size,
                        colour: run.colour,
                        background: None,
                    }));
                }
                y += self.face.line_height(size);
            }
        }
        format!(
            "{}: {}",
            scene_title(scene),
            counts_text(&trace.counts, self.told)
        )
    }
}

/// The order to draw the paths of `trace` in: as traced for one colour; for several, each
/// source ray of each colour (with the reflections spawned from it) in an order that is
/// shuffled but the same every time. Any order that follows the rays or the colours is
/// biased: where a fan spreads by colour, the red ray through a point comes from a later
/// source ray than the violet one, so drawing ray after ray puts red on top across a whole
/// fan (and violet across another). Shuffled, every colour is as likely to lie on top
/// anywhere, and where colours cross they mix.
fn drawing_order(trace: &Trace) -> Box<dyn Iterator<Item = usize> + '_> {
    let colours = trace.counts.wavelengths;
    if colours <= 1 {
        return Box::new(0..trace.paths.len());
    }
    // (source ray, colour) of every path, a reflection's those of the path it came from: the
    // colour is the light's place among the lights met, the ray how many source rays of that
    // light came before (the tracer may list them colour after colour or ray after ray).
    let mut of = vec![(0, 0); trace.paths.len()];
    let mut lights: Vec<(Light, usize)> = Vec::with_capacity(colours);
    for (i, path) in trace.paths.iter().enumerate() {
        of[i] = match path.parent_hit {
            None => {
                let colour = lights
                    .iter()
                    .position(|(light, _)| *light == path.light)
                    .unwrap_or_else(|| {
                        lights.push((path.light, 0));
                        lights.len() - 1
                    });
                lights[colour].1 += 1;
                (lights[colour].1, colour)
            }
            Some(h) => trace
                .hits
                .get(h)
                .and_then(|hit| of.get(hit.path).copied())
                .unwrap_or((0, 0)),
        };
    }
    let mut order: Vec<usize> = (0..trace.paths.len()).collect();
    // Stable: a path's reflections keep the traced order after it.
    order.sort_by_key(|&i| {
        let (ray, colour) = of[i];
        shuffled((ray * colours + colour) as u64)
    });
    Box::new(order.into_iter())
}

/// `n` well mixed (the finaliser of `SplitMix64`, by Sebastiano Vigna): sorting by it shuffles,
/// the same way every time.
fn shuffled(n: u64) -> u64 {
    let mut z = n.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Whether the first segment of `path` is the same for every wavelength: a source ray's (it
/// ends at its first kernel call), or a reflection's off a source ray's first kernel call
/// (reflection does not depend on the index).
fn starts_colour_blind(trace: &Trace, path: &Path) -> bool {
    let Some(h) = path.parent_hit else {
        return true;
    };
    let Some(parent) = trace.hits.get(h) else {
        return false;
    };
    let first_of_its_path = h == 0 || trace.hits.get(h - 1).is_none_or(|p| p.path != parent.path);
    first_of_its_path
        && trace
            .paths
            .get(parent.path)
            .is_some_and(|p| p.parent_hit.is_none())
}

/// The kinds of hit marker the picture tells apart, in the legend's order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum HitKind {
    Entering,
    Leaving,
    TotalInternalReflection,
}

impl HitKind {
    const ALL: [Self; 3] = [Self::Entering, Self::Leaving, Self::TotalInternalReflection];

    /// The kind `hit` is shown as: while a question is asked, by the side the ray meets the
    /// surface from only (a total internal reflection marked as such would answer it).
    fn of(hit: &Hit, told: Told) -> Self {
        match (hit.outcome, hit.side) {
            (Outcome::TotalInternalReflection, _) if told == Told::Everything => {
                Self::TotalInternalReflection
            }
            (_, Side::Inside) => Self::Leaving,
            (_, Side::Outside) => Self::Entering,
        }
    }

    /// The marker's fill.
    fn colour(self, p: &Palette) -> Colour {
        match self {
            Self::Entering => p.background,
            Self::Leaving => p.warning,
            Self::TotalInternalReflection => p.critical,
        }
    }

    /// The legend's words for it, in the shade they are written in.
    fn words(self, p: &Palette) -> (String, Colour) {
        match self {
            Self::Entering => (t!("diagram-hit-entering"), p.ink),
            Self::Leaving => (
                t!("diagram-hit-leaving"),
                p.text_shade_on(p.warning, p.calm),
            ),
            Self::TotalInternalReflection => {
                (t!("diagram-hit-tir"), p.text_shade_on(p.critical, p.calm))
            }
        }
    }
}

/// The legend row: the colours traced, what opacity means, the kinds of hit marker shown.
fn legend(scene: &Scene, trace: &Trace, (p, told): (&Palette, Told)) -> Vec<(String, Colour)> {
    let ink = p.ink;
    let mut pieces = vec![(format!("{} ", t!("diagram-legend-colour")), ink)];
    let colours = scene.source().colours(scene.effects().dispersion);
    if let [Light::White] = colours.as_slice() {
        let nm = reference_wavelength();
        let text = t!("diagram-legend-white-traced", wavelength = nm);
        pieces.push((text, p.text_shade_on(p.white_light, p.calm)));
    } else {
        if colours.len() > 1 {
            let then = t!("diagram-legend-white-then");
            pieces.push((format!("{then} "), p.text_shade_on(p.white_light, p.calm)));
        }
        for nm in colours.iter().filter_map(|light| light.wavelength_nm()) {
            // The colour's own shade, darkened or lightened until it reads at 4.5:1.
            let shade = p.text_shade_on(wavelength_colour(nm), p.calm);
            pieces.push((format!("{} ", number(nm, 0)), shade));
        }
        pieces.push((t!("diagram-legend-nm"), ink));
    }
    if scene.effects().intensities() {
        pieces.push((format!(" · {}", t!("diagram-legend-opacity")), ink));
    }
    // Each kind once, told by what the hit was, never by its colour (two may share one).
    let shown = HitKind::ALL
        .into_iter()
        .filter(|kind| trace.hits.iter().any(|h| HitKind::of(h, told) == *kind));
    for (i, kind) in shown.enumerate() {
        let lead = if i == 0 {
            format!(" · {} ", t!("diagram-legend-hits"))
        } else {
            ", ".to_owned()
        };
        pieces.push((lead, ink));
        pieces.push(kind.words(p));
    }
    pieces
}

impl ScenePicture {
    /// The picture of `scene` traced as `trace`, laid out by `layout` (normally
    /// `SceneLayout::new(trace.bounds, size)`; an editor keeps the layout of the start of a
    /// drag until it ends, so that the world does not move under the pointer).
    #[must_use]
    pub fn new(scene: &Scene, trace: &Trace, layout: &SceneLayout) -> Self {
        Self::with_palette(scene, trace, layout, &Palette::STANDARD)
    }

    /// [`ScenePicture::new`] in the colours of `palette` (a theme, the colour-blind choice).
    #[must_use]
    pub fn with_palette(
        scene: &Scene,
        trace: &Trace,
        layout: &SceneLayout,
        palette: &Palette,
    ) -> Self {
        Self::told(scene, trace, layout, (palette, Told::Everything))
    }

    /// The picture a lesson step shows while its question hides what happens past the first
    /// surface: `shown` is the trace cut there (`refraction_deck::answer::up_to_first_surface`),
    /// laid out by `layout` (the whole trace's, so that the reveal does not move the view). Its
    /// banner and its summary count only the source's rays and colours, and each hit is marked
    /// by the side the ray meets it from, not by what happens there: no word or colour says how
    /// many times the light is reflected, nor whether totally.
    #[must_use]
    pub fn asking(scene: &Scene, shown: &Trace, layout: &SceneLayout, palette: &Palette) -> Self {
        Self::told(scene, shown, layout, (palette, Told::Asking))
    }

    fn told(scene: &Scene, trace: &Trace, layout: &SceneLayout, look: (&Palette, Told)) -> Self {
        let (mut b, handles) = ScenePictureBuilder::drawn(scene, trace, layout, look);
        let left_out = b.place(&handles);
        let summary = b.banner(scene, trace);
        Self {
            primitives: b.out,
            handles,
            left_out,
            summary,
        }
    }

    /// What the labels of [`ScenePicture::new`]'s picture are kept off (the hit markers, the
    /// aim's arrowhead, the handles, at most 3,000 ray segments and 1,000 pieces of the faces),
    /// in the order the placer is given them: what the frame benchmark's placer works on.
    #[must_use]
    pub fn label_obstacles(scene: &Scene, trace: &Trace, layout: &SceneLayout) -> Vec<Obstacle> {
        let look = (&Palette::STANDARD, Told::Everything);
        let (b, handles) = ScenePictureBuilder::drawn(scene, trace, layout, look);
        b.obstacles(&handles)
    }
}

impl<'a> ScenePictureBuilder<'a> {
    /// The picture up to its labels: the shapes, the rays, the hit markers and the handles
    /// drawn, the labels waiting to be placed; and the handles.
    fn drawn(
        scene: &Scene,
        trace: &Trace,
        layout: &'a SceneLayout,
        (palette, told): (&Palette, Told),
    ) -> (Self, Vec<SceneHandle>) {
        let mut b = ScenePictureBuilder {
            layout,
            palette: *palette,
            told,
            labels: Vec::new(),
            rays_from: 0,
            faces: Vec::new(),
            marks_from: 0,
            face: Typeface::egui_default(),
            out: Vec::with_capacity(trace.segments.len() + trace.hits.len() / 4 + 64),
        };
        let handles = layout.handles(scene);
        b.shapes(scene);
        b.rays_from = b.out.len();
        b.rays(trace);
        b.marks_from = b.out.len();
        b.hits(trace);
        b.handles(&handles);
        b.media_labels(scene, &handles);
        (b, handles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette;

    fn traced(name: &str) -> (Scene, Trace) {
        let scene = Scene::embedded(name).unwrap();
        let trace = scene.trace();
        (scene, trace)
    }

    fn texts(picture: &ScenePicture) -> Vec<&Label> {
        picture
            .primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Text(l) => Some(l),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_picture_asking_a_question_counts_only_the_source_and_never_names_a_reflection() {
        let (scene, trace) = traced("fibre");
        assert!(trace.counts.total_internal_reflections > 0);
        let layout = SceneLayout::for_scene(&scene, &trace, Vec2::new(1200.0, 800.0));
        let told = ScenePicture::new(&scene, &trace, &layout);
        let asking = ScenePicture::asking(&scene, &trace, &layout, &Palette::STANDARD);
        let words = |p: &ScenePicture| {
            let labels: Vec<String> = texts(p).iter().map(|l| l.text.clone()).collect();
            format!("{} {}", labels.join(" "), p.summary)
        };
        let tir = t!("diagram-hit-tir");
        assert!(words(&told).contains(&tir), "{}", words(&told));
        let asked = words(&asking);
        for counted in [
            "total internal",
            "reflections spawned",
            "kernel call",
            "Fresnel",
        ] {
            assert!(!asked.contains(counted), "{counted}: {asked}");
        }
        assert!(asked.contains("source rays"), "{asked}");
        let critical = palette::Palette::STANDARD.critical;
        let marked_total = |p: &ScenePicture| {
            p.primitives
                .iter()
                .any(|p| matches!(p, Primitive::Disc { fill, .. } if *fill == critical))
        };
        assert!(marked_total(&told) && !marked_total(&asking));
    }

    #[test]
    fn the_legend_names_each_kind_of_hit_drawn_even_when_two_kinds_share_a_colour() {
        let mut one_colour = Palette::STANDARD;
        one_colour.warning = one_colour.background;
        one_colour.critical = one_colour.background;
        let mut seen_tir = false;
        for info in refraction_scene::catalogue() {
            let (scene, trace) = traced(info.name);
            let words: String = legend(&scene, &trace, (&one_colour, Told::Everything))
                .into_iter()
                .map(|(text, _)| text)
                .collect();
            for kind in HitKind::ALL {
                let drawn = trace
                    .hits
                    .iter()
                    .any(|h| HitKind::of(h, Told::Everything) == kind);
                let named = words.contains(&kind.words(&one_colour).0);
                assert_eq!(drawn, named, "{} {kind:?}: {words}", info.name);
                seen_tir |= drawn && kind == HitKind::TotalInternalReflection;
            }
        }
        assert!(seen_tir, "some built-in scene reflects totally");
    }

    #[test]
    fn rays_take_their_wavelengths_colour_and_faint_rays_are_translucent() {
        let (scene, trace) = traced("droplet");
        let layout = SceneLayout::new(trace.bounds, Vec2::new(1200.0, 800.0));
        let picture = ScenePicture::new(&scene, &trace, &layout);
        let lines: Vec<Colour> = picture
            .primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Polyline { colour, .. } => Some(*colour),
                _ => None,
            })
            .collect();
        for nm in [400.0, 550.0, 700.0] {
            let c = wavelength_colour(nm);
            assert!(
                lines.iter().any(|l| (l.r, l.g, l.b) == (c.r, c.g, c.b)),
                "no ray at {nm} nm"
            );
        }
        assert!(lines.iter().any(|l| l.a < 128), "reflections are faint");
        assert!(lines.iter().any(|l| l.a > 200), "source rays are strong");
        let legend: String = texts(&picture).iter().map(|l| l.text.as_str()).collect();
        assert!(
            legend.contains("400 450 500 550 600 650 700 nm"),
            "{legend}"
        );
        assert!(legend.contains("leaving (N turned round)"), "{legend}");
        assert!(picture.summary.contains("kernel calls"));
    }

    /// A colour without its opacity.
    type Rgb = (u8, u8, u8);

    /// The colour of the last ray drawn over each of a grid of points on the canvas (`None`
    /// where no coloured ray passes within half a pixel), as `(r, g, b)`.
    fn colour_on_top(picture: &ScenePicture, size: Vec2, step: f32) -> Vec<Option<Rgb>> {
        let spectral = |c: &Colour| c.r != c.g || c.g != c.b;
        let rays: Vec<(&Vec<Vec2>, Rgb)> = picture
            .primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Polyline { points, colour, .. } if spectral(colour) => {
                    Some((points, (colour.r, colour.g, colour.b)))
                }
                _ => None,
            })
            .collect();
        let near = |points: &Vec<Vec2>, p: Vec2| {
            points.windows(2).any(|s| {
                let (a, b) = (s[0], s[1]);
                let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-6)).clamp(0.0, 1.0);
                p.distance(a + (b - a) * t) < 0.5
            })
        };
        let (columns, rows) = ((size.x / step) as usize, (size.y / step) as usize);
        (0..rows * columns)
            .map(|k| {
                let p = Vec2::new((k % columns) as f32 + 0.5, (k / columns) as f32 + 0.5) * step;
                rays.iter()
                    .rev()
                    .find(|(points, _)| near(points, p))
                    .map(|(_, c)| *c)
            })
            .collect()
    }

    #[test]
    fn a_scenes_labels_lie_off_its_rays() {
        // Issue 22: "F2 flint" covered the prism's fan, "BK7" the lens's converging rays,
        // "cladding" lay inside the core.
        let face = Typeface::egui_default();
        for name in [
            "dispersing-prism",
            "lens",
            "fibre",
            "slab",
            "right-angle-prism",
        ] {
            let (scene, trace) = traced(name);
            for size in [Vec2::new(760.0, 430.0), Vec2::new(1280.0, 620.0)] {
                let layout = SceneLayout::new(trace.bounds, size);
                let picture = ScenePicture::new(&scene, &trace, &layout);
                let rays: Vec<Obstacle> = trace
                    .segments
                    .iter()
                    .map(|s| Obstacle::Shaft {
                        a: layout.at(s.from),
                        b: layout.at(s.to),
                        half_width: 0.5,
                        firm: false,
                    })
                    .collect();
                for p in &picture.primitives {
                    let Primitive::Text(l) = p else { continue };
                    if l.background.is_none() {
                        continue;
                    }
                    let extent = face.measure(&l.text, l.size);
                    let min = l.at - extent * Vec2::new(l.h.fraction(), l.v.fraction());
                    let text_box = Rect::from_min_size(min, extent);
                    let covered = rays.iter().filter(|r| r.touches(&text_box)).count();
                    assert_eq!(covered, 0, "{name} at {size}: {:?} covers rays", l.text);
                }
            }
        }
    }

    #[test]
    fn no_colour_of_dispersed_light_lies_on_top_across_a_fan() {
        let (mut scene, _) = traced("droplet");
        scene.set_ray_count(300).unwrap();
        let trace = scene.trace();
        assert!(trace.counts.wavelengths > 3);
        let size = Vec2::new(600.0, 500.0);
        let layout = SceneLayout::new(trace.bounds, size);
        let picture = ScenePicture::new(&scene, &trace, &layout);
        let tops = colour_on_top(&picture, size, 5.0);
        // Over each tenth of the canvas (five columns, two rows) that coloured rays cover, no
        // one colour is on top at more than half the points: drawn ray after ray, red lay on
        // top over the whole fan leaving the drop, violet over the light inside it.
        let (columns, rows) = ((size.x / 5.0) as usize, (size.y / 5.0) as usize);
        let mut checked = 0;
        for cell in 0..10 {
            let mut count: HashMap<Rgb, usize> = HashMap::new();
            for (k, top) in tops.iter().enumerate() {
                let (x, y) = (k % columns * 5 / columns, k / columns * 2 / rows);
                if x + 5 * y == cell
                    && let Some(c) = top
                {
                    *count.entry(*c).or_default() += 1;
                }
            }
            let all: usize = count.values().sum();
            if all < 100 {
                continue;
            }
            checked += 1;
            let most = count.values().max().copied().unwrap_or(0);
            assert!(
                2 * most <= all,
                "cell {cell}: {most} of {all} points in one colour: {count:?}"
            );
        }
        assert!(checked >= 3, "coloured rays cover {checked} cells");
    }

    #[test]
    fn every_theme_reaches_the_scene() {
        use crate::palette::Theme;
        let (scene, trace) = traced("slab");
        let layout = SceneLayout::for_scene(&scene, &trace, Vec2::new(800.0, 600.0));
        let dark = Palette::new(Theme::HighContrastDark, true);
        let picture = ScenePicture::with_palette(&scene, &trace, &layout, &dark);
        let texts: Vec<_> = texts(&picture);
        assert!(texts.iter().all(|l| l.colour != palette::INK));
        assert!(picture.primitives.iter().any(
            |p| matches!(p, Primitive::Polygon { colour, .. } if *colour == dark.outside_world)
        ));
    }

    #[test]
    fn dispersed_white_light_is_white_until_it_first_refracts() {
        let (scene, trace) = traced("dispersing-prism");
        let layout = SceneLayout::new(trace.bounds, Vec2::new(1200.0, 800.0));
        let picture = ScenePicture::new(&scene, &trace, &layout);
        let source = layout.at(scene.source().origin);
        let from_source: Vec<Colour> = picture
            .primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Polyline { points, colour, .. } if points[0] == source => Some(*colour),
                _ => None,
            })
            .collect();
        // Once in white, and (besides the aim arrow) in no other colour.
        let white = from_source.iter().filter(|c| **c == palette::WHITE_LIGHT);
        assert_eq!(white.count(), 1);
        assert!(
            from_source
                .iter()
                .all(|c| [palette::WHITE_LIGHT, palette::W].contains(c)),
            "{from_source:?}"
        );
    }

    #[test]
    fn handles_move_the_source_aim_it_and_move_shapes() {
        let (mut scene, trace) = traced("droplet");
        let layout = SceneLayout::new(trace.bounds, Vec2::new(1000.0, 700.0));
        let handles = layout.handles(&scene);
        assert_eq!(handles.len(), 2 + scene.shapes().len());
        assert_eq!(handles[2].center, layout.at(DVec2::ZERO));
        let p = layout.at(DVec2::new(-2.0, 1.0));
        layout.drag(&mut scene, SceneHandleId::Source, p).unwrap();
        assert!(scene.source().origin.distance(DVec2::new(-2.0, 1.0)) < 1e-5);
        let p = layout.at(DVec2::new(-2.0, 2.0));
        layout.drag(&mut scene, SceneHandleId::Aim, p).unwrap();
        assert!(scene.source().direction.distance(DVec2::Y) < 1e-5);
        let p = layout.at(DVec2::new(0.5, 0.0));
        layout.drag(&mut scene, SceneHandleId::Shape(0), p).unwrap();
        assert!(scene.shapes()[0].anchor().distance(DVec2::new(0.5, 0.0)) < 1e-5);
        let origin = layout.at(scene.source().origin);
        let before = scene.clone();
        assert!(layout.drag(&mut scene, SceneHandleId::Aim, origin).is_err());
        assert!(
            layout
                .drag(&mut scene, SceneHandleId::Shape(9), origin)
                .is_err()
        );
        assert_eq!(scene, before);
        assert_eq!(
            SceneHandleId::Shape(0).label(&scene),
            "Shape 1 handle (water)"
        );
    }

    #[test]
    fn shapes_sharing_an_anchor_get_handles_apart_that_move_them_alike() {
        let (mut scene, trace) = traced("fibre");
        let layout = SceneLayout::new(trace.bounds, Vec2::new(1000.0, 700.0));
        let handles = layout.handles(&scene);
        let (cladding, core) = (handles[2], handles[3]);
        assert_eq!(cladding.center, layout.at(scene.shapes()[0].anchor()));
        assert!(!cladding.grab_area().overlaps(&core.grab_area()));
        let anchor = scene.shapes()[1].anchor();
        let p = core.center + Vec2::new(50.0, 0.0);
        layout.drag(&mut scene, SceneHandleId::Shape(1), p).unwrap();
        let moved = scene.shapes()[1].anchor() - anchor;
        assert!((moved - DVec2::new(50.0 / f64::from(layout.view.scale), 0.0)).length() < 1e-5);
    }

    #[test]
    fn hundreds_of_shapes_on_one_spot_get_the_handles_the_canvas_has_room_for() {
        let circle = "[[shapes]]\ncircle = { center = [0, 0], radius = 1, medium = \"vacuum\" }\n";
        let text = format!(
            "title = \"t\"\n{}[source]\nkind = \"ray\"\norigin = [-2, 0]\ndirection = [1, 0]\n",
            circle.repeat(refraction_scene::MAX_SHAPES)
        );
        let scene = Scene::from_toml(&text, "x.toml", "x").unwrap();
        let layout = SceneLayout::new(scene.bounds(), Vec2::new(1000.0, 700.0));
        let handles = layout.handles(&scene);
        let shape_handles = handles.len() - 2;
        assert!(shape_handles > 3 && shape_handles < 40, "{shape_handles}");
        for (i, a) in handles.iter().enumerate() {
            assert!(layout.canvas.contains(a.center) || i < 2, "{a:?}");
            for b in &handles[..i] {
                assert!(
                    a.center.distance(b.center) >= layout.font * 2.3,
                    "{a:?} {b:?}"
                );
            }
        }
    }

    #[test]
    fn a_click_picks_the_nearest_hit_only_when_close() {
        let (_, trace) = traced("droplet");
        let layout = SceneLayout::new(trace.bounds, Vec2::new(1000.0, 700.0));
        let hit = trace.hits.iter().find(|h| h.side == Side::Inside).unwrap();
        let p = layout.at(hit.point) + Vec2::new(2.0, 0.0);
        let picked = layout.hit_near(&trace, p).unwrap();
        assert!(layout.at(picked.point).distance(p) <= layout.pick_radius());
        assert!(layout.hit_near(&trace, Vec2::new(5.0, 690.0)).is_none());
    }

    #[test]
    fn every_scene_draws_with_every_label_inside_the_canvas() {
        let face = Typeface::egui_default();
        for info in refraction_scene::catalogue() {
            let (scene, trace) = traced(info.name);
            for size in [Vec2::new(640.0, 360.0), Vec2::new(1920.0, 1080.0)] {
                let layout = SceneLayout::new(trace.bounds, size);
                let picture = ScenePicture::new(&scene, &trace, &layout);
                assert!(picture.primitives.len() > 5, "{}", info.name);
                for l in texts(&picture) {
                    let extent = face.measure(&l.text, l.size);
                    let min = l.at - extent * Vec2::new(l.h.fraction(), l.v.fraction());
                    let inside =
                        layout.canvas.contains(min) && layout.canvas.contains(min + extent);
                    assert!(inside, "{}: {l:?} is cut off at {size}", info.name);
                    assert!(l.text.chars().all(|c| c == '\n' || face.covers(c)), "{l:?}");
                }
            }
        }
    }

    #[test]
    fn opacity_follows_intensity_in_coarse_steps() {
        assert_eq!(opacity(None), 255);
        assert_eq!(opacity(Some(1.0)), 255);
        assert_eq!(opacity(Some(0.0)), opacity(Some(f64::NAN)));
        assert!(opacity(Some(0.04)) < 128);
        assert_eq!(opacity(Some(0.96)), opacity(Some(0.97)));
    }
}
