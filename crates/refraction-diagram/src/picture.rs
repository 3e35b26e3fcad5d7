//! The interface diagram for one state: media, surface, rays, candidates, angles, banner and
//! index scale, as [`Figure`]s on a canvas of a given size, plus the draggable handles.

use glam::{DVec2, DVec3, Vec2};

use super::font::Typeface;
use super::geometry::{Colour, Rect, arc, clip_rect_to_half_plane, clip_segment};
use super::intensities::{Shares, stroke_for};
use super::layout::Layout;
use super::numbers::{number, significant};
use super::obstacle::Obstacle;
use super::overlay::{Overlay, Part};
use super::palette::Palette;
use super::placer::{Need, Placer, wrap};
use super::shapes::{Align, ArrowRole, Dash, Figure, Label, Primitive, Stroke, lower_all};
use super::wavefronts;
use refraction_i18n::t;
use refraction_kernel::{Convention, Refraction, Rejection, seed};
use refraction_model::{ExplorerState, HandleId, INDEX_RANGE, MATERIALS, material_of};

/// A draggable point on the canvas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handle {
    /// Which handle.
    pub id: HandleId,
    /// Its centre on the canvas.
    pub center: Vec2,
    /// Its radius in pixels (the grab area is a little larger).
    pub radius: f32,
}

/// Everything drawn for one state on one canvas size.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// Where things go.
    pub layout: Layout,
    /// What is drawn, back to front.
    pub shapes: Vec<Figure>,
    /// The handles, in [`HandleId::ALL`] order: W and N, then the μ markers unless the index
    /// scale is folded away.
    pub handles: Vec<Handle>,
    /// The banner's text: what the picture says in words, for screen readers.
    pub summary: String,
    /// The labels the placer left out for want of a free spot, at their anchors: the window
    /// shows their text when the pointer is near.
    pub left_out: Vec<Label>,
    /// Whether W is drawn arriving at the hit point (its handle at its tail) so as not to show
    /// a hidden answer past the interface: a drag of its handle then points W away from it.
    pub w_arriving: bool,
}

/// The lengths of the diagram's rays, in world units (W, N and T are 1).
const INCOMING_LENGTH: f64 = 1.25;
/// W drawn arriving at the hit point while an answer is hidden: shorter than N, so that at
/// normal incidence its handle is not on N's.
const ARRIVING_LENGTH: f64 = 0.8;
const GHOST_LENGTH: f64 = 0.9;
const ARC_RADIUS: f64 = 0.28;

/// The short form of each rejection, for the label beside its ghost.
fn short_rule(rejection: Rejection) -> String {
    match rejection {
        Rejection::WrongSide => t!("diagram-ghost-wrong-side"),
        Rejection::WrongBend => t!("diagram-ghost-wrong-bend"),
        Rejection::Reversed => t!("diagram-ghost-reversed"),
    }
}

/// The name and index of a medium, e.g. `μt = 1.5 (glass)`.
fn medium_text(symbol: &str, index: f64) -> String {
    let name = material_of(index).map_or_else(|| t!("diagram-material-custom"), |m| m.label());
    let index = significant(index, 4);
    t!("diagram-medium", mu = symbol, index = index, name = name)
}

/// The banner's text: the convention in words, or total internal reflection.
fn banner_text(r: &Refraction<f64>) -> String {
    let theta_i = number(r.cos_i.clamp(-1.0, 1.0).acos().to_degrees(), 1);
    let k = significant(r.k, 4);
    match r.transmission {
        None => t!("diagram-banner-tir", k = k, theta_i = theta_i),
        Some(tr) => {
            let words = match r.convention {
                Convention::TowardOrigin => t!("diagram-banner-toward-origin"),
                Convention::AlongRay => t!("diagram-banner-along-ray"),
            };
            let theta_t = number(tr.cos_t.clamp(-1.0, 1.0).acos().to_degrees(), 1);
            let section = r.convention.section().to_string();
            let numbers = t!("diagram-banner-numbers", i = theta_i, t = theta_t, k = k);
            let title = t!("diagram-banner-section", section = section, words = words);
            format!("{title}\n{numbers}")
        }
    }
}

/// What the diagram of `state` says in words, as its banner does (the convention and the
/// angles, or total internal reflection), or that the answer is hidden: its [`Diagram::summary`]
/// without laying it out.
#[must_use]
pub fn diagram_summary(state: &ExplorerState, hide_answer: bool) -> String {
    if hide_answer {
        t!("deck-answer-hidden")
    } else {
        banner_text(state.refraction())
    }
}

/// The banner's words for `overlay`: the [`summary`], or on paper with the answer hidden the
/// convention alone, without the sign of a it gives (a sheet has nothing to reveal with, and
/// a question may ask for the sign).
fn banner_words(state: &ExplorerState, overlay: &Overlay) -> String {
    if overlay.paper && overlay.hide_answer {
        match state.convention() {
            Convention::TowardOrigin => t!("diagram-banner-asked-toward-origin"),
            Convention::AlongRay => t!("diagram-banner-asked-along-ray"),
        }
    } else {
        diagram_summary(state, overlay.hide_answer)
    }
}

/// The banner's margins left and right, in label font sizes.
const BANNER_MARGIN: f32 = 0.6;

/// The layout of a canvas `size` with the banner tall enough for `text` wrapped to its width,
/// and the text so wrapped.
fn layout_with_banner(
    size: Vec2,
    text: &str,
    face: &Typeface,
    index_scale: bool,
) -> (Layout, String) {
    let layout = Layout::new(size);
    let layout = if index_scale {
        layout
    } else {
        layout.without_scale()
    };
    let font = layout.font;
    let room = layout.banner.size().x - 2.0 * font * BANNER_MARGIN;
    let wrapped = wrap(face, text, font, room);
    let height = face.measure(&wrapped, font).y + font * 0.8;
    let layout = if height > layout.banner.size().y {
        layout.with_banner_height(height)
    } else {
        layout
    };
    (layout, wrapped)
}

/// How much larger than a handle its grab area is (half-side over radius).
pub(crate) const GRAB_SCALE: f32 = 1.6;

/// The least side of a handle's grab area for a finger ([`Overlay::touch`]), in pixels (CSS
/// pixels in a browser): 44, WCAG 2.1's target size (2.5.5) and Apple's and Google's guides.
pub const TOUCH_TARGET: f32 = 44.0;

/// The shade of a medium in `palette`: lighter for lower index (clamped to [`INDEX_RANGE`]).
#[must_use]
pub(crate) fn medium_colour(palette: &Palette, index: f64) -> Colour {
    let (low, high) = INDEX_RANGE;
    palette
        .thin_medium
        .lerp(palette.dense_medium, ((index - low) / (high - low)) as f32)
}

/// Builds the shapes, with the world→canvas map at hand.
struct DiagramBuilder<'a> {
    layout: &'a Layout,
    state: &'a ExplorerState,
    overlay: &'a Overlay,
    palette: Palette,
    shapes: Vec<Figure>,
    /// Labels wait here, with their rank, to be placed last and on top.
    labels: Vec<(Rank, Label)>,
    /// The rank of the labels added next.
    rank: Rank,
    /// Lines labels keep off where they can (the interface, the critical angle's): drawn as
    /// guides, but a box over them hides where the surface or the limit is.
    keep_clear: Vec<(Vec2, Vec2)>,
}

/// The order in which the diagram's labels are placed, first to last: a label placed earlier
/// keeps its spot and one placed later that would cover it moves aside. So the vectors the
/// diagram is about are never pushed off their tips by the annotations around them, and the
/// media's names, placed last, give way to everything.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Rank {
    /// W, N, T, the student's T and the index scale.
    Vectors,
    /// The angles θi and θt and the incoming and reflected rays.
    Rays,
    /// The outward-normal bug: −N and the wrong T of the paper's formula.
    Bug,
    /// The three rejected candidates.
    Candidates,
    /// The critical angle and the wavefronts' names, landmarks a lesson names.
    Landmark,
    /// The construction: T's decomposition into a·W and b·N.
    Construction,
    /// The two media's names and indices, in the corners.
    Media,
}

impl DiagramBuilder<'_> {
    fn font(&self) -> f32 {
        self.layout.font
    }

    /// A handle's radius: `radius`, or for a finger at least what gives a grab area
    /// [`TOUCH_TARGET`] across.
    fn handle_radius(&self, radius: f32) -> f32 {
        if self.overlay.touch {
            radius.max(TOUCH_TARGET * 0.5 / GRAB_SCALE)
        } else {
            radius
        }
    }

    fn stroke(&self, width: f32, colour: Colour, dash: Dash) -> Stroke {
        Stroke {
            width: width * self.layout.unit(),
            colour,
            dash,
        }
    }

    /// The unit diagram direction of a 3D vector of the plane.
    fn flat(&self, v: DVec3) -> DVec2 {
        self.state.plane().project(v).normalize_or(DVec2::X)
    }

    fn at(&self, world: DVec2) -> Vec2 {
        self.layout.view.to_canvas(world)
    }

    fn label(&mut self, text: impl Into<String>, at: Vec2, (h, v): (Align, Align), size: f32) {
        self.label_coloured(text, at, (h, v), size, self.palette.ink);
    }

    fn label_coloured(
        &mut self,
        text: impl Into<String>,
        at: Vec2,
        (h, v): (Align, Align),
        size: f32,
        colour: Colour,
    ) {
        let label = Label {
            text: text.into(),
            at,
            h,
            v,
            size: self.layout.text_size(size),
            colour,
            background: Some(self.palette.label_background),
        };
        self.labels.push((self.rank, label));
    }

    /// Places the waiting labels, by rank, on top of everything else, through the
    /// [`Placer`]: a label anchored in the drawing area stays inside it (clear of the banner
    /// and the index scale), every label stays off the arrowheads, the handles' grab areas and
    /// the labels placed before it, and one with no free spot is left out (returned second).
    fn finish(mut self, handles: &[Handle]) -> (Vec<Figure>, Vec<Label>) {
        let mut labels = core::mem::take(&mut self.labels);
        labels.sort_by_key(|(rank, _)| *rank);
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        self.avoid_figures(&mut placer, handles);
        let drawing = self.layout.drawing;
        let below_banner = Rect {
            min: Vec2::new(0.0, self.layout.banner.max.y),
            max: self.layout.canvas.max,
        };
        let mut placement = placer.place_all(labels.into_iter().map(|(rank, label)| {
            let bounds = if drawing.contains(label.at) {
                drawing
            } else {
                below_banner
            };
            // The labels a lesson teaches are never dropped; the construction and the media's
            // names give way first.
            let need = if rank <= Rank::Landmark {
                Need::Shown
            } else {
                Need::Optional
            };
            (label, bounds, need)
        }));
        let left_out = core::mem::take(&mut placement.left_out);
        self.shapes.extend(placement.figures());
        (self.shapes, left_out)
    }

    /// Tells `placer` what no label may cover: marked points, every arrow's shaft and head
    /// (W, N and T firmly), the lines kept clear, the hit point and the handles.
    fn avoid_figures(&self, placer: &mut Placer<'_>, handles: &[Handle]) {
        for shape in &self.shapes {
            // A marked point (Huygens's A and B, a student's tip): no label covers it.
            if let Figure::Disc { center, radius, .. } = shape {
                placer.avoid(Obstacle::Disc {
                    center: *center,
                    radius: radius + 1.5,
                });
            }
            if let Figure::Arrow {
                from,
                to,
                stroke,
                role,
            } = shape
            {
                // Its shaft and its head: no label covers a ray, nor ever W, N or T.
                placer.avoid(Obstacle::Shaft {
                    a: *from,
                    b: *to,
                    half_width: stroke.width * 0.5 + 1.5,
                    firm: *role == ArrowRole::Vector,
                });
                let mut lowered = Vec::new();
                shape.lower(&mut lowered);
                for p in lowered {
                    if let Primitive::Polygon { points, .. } = p {
                        placer.avoid(Obstacle::Polygon(points));
                    }
                }
            }
        }
        for &(a, b) in &self.keep_clear {
            placer.avoid(Obstacle::Shaft {
                a,
                b,
                half_width: 2.0 * self.layout.unit(),
                firm: false,
            });
        }
        // The hit point, where every ray meets.
        placer.avoid(Obstacle::Disc {
            center: self.at(DVec2::ZERO),
            radius: self.font() * 0.4,
        });
        for handle in handles {
            placer.avoid(Obstacle::Box(Diagram::grab_area(handle)));
        }
    }

    /// An arrow from the hit point along the unit diagram direction `d`, `length` long, with a
    /// label beyond its tip.
    fn ray(
        &mut self,
        d: DVec2,
        (length, role): (f64, ArrowRole),
        stroke: Stroke,
        text: &str,
        size: f32,
    ) {
        let tip = self.at(d * length);
        self.shapes.push(Figure::Arrow {
            from: self.at(DVec2::ZERO),
            to: tip,
            stroke,
            role,
        });
        if !text.is_empty() {
            let away = self.layout.view.direction(d);
            let at = tip + away * (self.font() * 0.9);
            let colour = self.palette.text_shade(stroke.colour);
            let anchor = (Align::away(away.x), Align::away(away.y));
            self.label_coloured(text, at, anchor, size, colour);
        }
    }

    /// A wide translucent stroke along `points` when the walk-through highlights `part`, drawn
    /// before the part so that the part stays sharp on top of it.
    fn halo(&mut self, part: Part, points: Vec<Vec2>) {
        if self.overlay.highlights(part) {
            let stroke = self.stroke(13.0, self.palette.highlight, Dash::Solid);
            self.shapes.push(Figure::Line { points, stroke });
        }
    }

    /// [`DiagramBuilder::ray`] for a part a walk-through step may highlight.
    fn part_ray(&mut self, part: Part, d: DVec2, length: f64, stroke: Stroke, text: &str) {
        let size = match part {
            Part::T => 1.1,
            Part::Candidate(_) => 0.8,
            _ => 1.0,
        };
        self.halo(part, vec![self.at(DVec2::ZERO), self.at(d * length)]);
        let role = match part {
            Part::W | Part::N | Part::T => ArrowRole::Vector,
            _ => ArrowRole::Ray,
        };
        self.ray(d, (length, role), stroke, text, size);
    }

    /// The student's T, with its own length and dash, labelled with what it is.
    fn student(&mut self) {
        let Some(student) = self
            .overlay
            .student
            .as_ref()
            .filter(|_| !self.overlay.hide_answer)
        else {
            return;
        };
        let flat = self.state.plane().project(student.t);
        let length = flat.length();
        // NaN, zero or perpendicular to the plane: nothing to draw; the verdict says why.
        if !(length > 1e-9 && length.is_finite()) {
            return;
        }
        let drawn = student.t.length().clamp(0.25, 1.6);
        let stroke = self.stroke(2.6, self.palette.student, Dash::LongDash);
        let text = student.label.clone();
        self.ray(flat / length, (drawn, ArrowRole::Ray), stroke, &text, 0.95);
    }

    /// A straight line between world points, clipped to the drawing area.
    fn segment(&mut self, a: DVec2, b: DVec2, stroke: Stroke) {
        if let Some((a, b)) = clip_segment(self.at(a), self.at(b), &self.layout.drawing) {
            self.shapes.push(Figure::Line {
                points: vec![a, b],
                stroke,
            });
        }
    }

    /// Asks the labels to keep off the line between world points `a` and `b` where they can.
    fn keep_clear_of(&mut self, a: DVec2, b: DVec2) {
        if let Some(clipped) = clip_segment(self.at(a), self.at(b), &self.layout.drawing) {
            self.keep_clear.push(clipped);
        }
    }

    /// The two media, shaded by index and labelled in the drawing area's farthest corners.
    fn media(&mut self, normal: DVec2) {
        let drawing = self.layout.drawing;
        let origin = self.at(DVec2::ZERO);
        let facing = self.layout.view.direction(normal);
        let inset = self.font() * 0.6;
        for (side, symbol, index) in [
            (1.0, "μi", self.state.mu_i()),
            (-1.0, "μt", self.state.mu_t()),
        ] {
            let points = clip_rect_to_half_plane(&drawing, origin, facing * side);
            self.shapes.push(Figure::Fill {
                points,
                colour: medium_colour(&self.palette, index),
            });
            let corners = drawing.corners();
            let corner = corners
                .into_iter()
                .max_by(|a, b| {
                    let depth = |p: &Vec2| (*p - origin).dot(facing * side) - p.y * 1e-3;
                    depth(a).total_cmp(&depth(b))
                })
                .unwrap_or(drawing.min);
            let inward = (drawing.center() - corner).signum();
            let anchor = (Align::away(inward.x), Align::away(inward.y));
            let text = medium_text(symbol, index);
            let which = if side > 0.0 {
                t!("diagram-medium-of-ray")
            } else {
                t!("diagram-medium-entered")
            };
            let text = format!("{text}\n{which}");
            self.label(text, corner + inward * inset, anchor, 1.0);
        }
    }

    /// The surface line, the normal's axis and, when there is one, the critical angle.
    ///
    /// While an answer is hidden the axis stops at the surface (past it, it runs exactly where
    /// an unbent ray would go, and is the only line there) and the critical angle is left out
    /// (a question may ask for it, or for whether the ray is past it).
    fn guides(&mut self, normal: DVec2, toward_source: DVec2) {
        let along = normal.perp() * 10.0;
        let surface = self.stroke(2.5, self.palette.ink, Dash::Solid);
        self.segment(-along, along, surface);
        self.keep_clear_of(-along, along);
        let axis = self.stroke(1.0, self.palette.guide, Dash::Dashed);
        let far = if self.overlay.hide_answer {
            DVec2::ZERO
        } else {
            -normal * 1.15
        };
        self.segment(far, normal * 1.15, axis);
        // A label on the axis reads as if it named the normal.
        self.keep_clear_of(far, normal * 1.15);
        if let Some(critical) = self
            .state
            .critical_angle()
            .filter(|_| !self.overlay.hide_answer)
        {
            let side = if normal.perp_dot(toward_source) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let direction = DVec2::from_angle(side * critical).rotate(normal);
            let stroke = self.stroke(1.8, self.palette.critical, Dash::DashDot);
            self.segment(DVec2::ZERO, direction * 1.15, stroke);
            self.keep_clear_of(DVec2::ZERO, direction * 1.15);
            let at = self.at(direction * 1.15);
            let away = self.layout.view.direction(direction);
            let angle = number(critical.to_degrees(), 1);
            let text = t!("diagram-critical-angle", angle = angle);
            let anchor = (Align::away(away.x), Align::away(away.y));
            self.label_coloured(
                text,
                at,
                anchor,
                0.85,
                self.palette.text_shade(self.palette.critical),
            );
        }
    }

    /// At normal incidence W, N and T lie on one line and hide one another: a note beside the
    /// hit point says so (only W and N while the answer is hidden).
    fn normal_incidence(&mut self, r: &Refraction<f64>, normal: DVec2) {
        // θi under 0.05°: what the readouts show as 0.0°.
        if r.cos_i < 0.05_f64.to_radians().cos() {
            return;
        }
        let text = if self.overlay.hide_answer {
            t!("diagram-normal-incidence-asked")
        } else {
            t!("diagram-normal-incidence")
        };
        let at = self.at((normal.perp() + normal) * 0.3);
        let away = self.layout.view.direction(normal.perp());
        let anchor = (Align::away(away.x), Align::Center);
        self.label(text, at, anchor, 0.85);
    }

    /// An angle arc between two unit diagram directions, labelled `text`.
    fn angle(&mut self, part: Part, (from, to): (DVec2, DVec2), text: String, colour: Colour) {
        let view = self.layout.view;
        let radius = ARC_RADIUS as f32 * view.scale;
        let points = arc(
            self.at(DVec2::ZERO),
            radius,
            view.direction(from),
            view.direction(to),
        );
        self.halo(part, points.clone());
        let stroke = self.stroke(1.5, colour, Dash::Solid);
        self.shapes.push(Figure::Line { points, stroke });
        let middle = (from + to).normalize_or(from);
        let away = view.direction(middle);
        let at = self.at(middle * ARC_RADIUS) + away * (self.font() * 0.5);
        let anchor = (Align::away(away.x), Align::away(away.y));
        self.label_coloured(text, at, anchor, 0.9, self.palette.text_shade(colour));
    }

    /// The three rejected candidates as ghosts, labelled with (a, b) and the rule they break.
    fn candidates(&mut self, r: &Refraction<f64>) {
        for c in &r.candidates {
            let Some(rejection) = c.rejection else {
                continue;
            };
            let dash = match rejection {
                Rejection::WrongSide => Dash::Dashed,
                Rejection::WrongBend => Dash::Dotted,
                Rejection::Reversed => Dash::DashDot,
            };
            let stroke = self.stroke(1.8, self.palette.rejected, dash);
            // With a flipped normal the bug's ghost lies on the wrong-side root and says so.
            let text = if r.normal_flipped && rejection == Rejection::WrongSide {
                String::new()
            } else {
                // Semicolons between the numbers where the decimal separator is a comma.
                let separator = refraction_i18n::locale().list_separator();
                format!(
                    "{}\n(a, b) = ({}{separator}{})",
                    short_rule(rejection),
                    number(c.a, 3),
                    number(c.b, 3)
                )
            };
            let part = Part::Candidate(rejection);
            self.part_ray(part, self.flat(c.t), GHOST_LENGTH, stroke, &text);
        }
    }

    /// What the paper's formula gives with N as given when the kernel had to flip it: the
    /// wrong T of a ray tracer that forgets to flip an outward normal.
    fn outward_normal_bug(&mut self, r: &Refraction<f64>) {
        if !r.normal_flipped {
            return;
        }
        let facing = self.flat(r.facing_normal);
        let stroke = self.stroke(1.6, self.palette.n, Dash::Dashed);
        let kernel_normal = t!("diagram-kernel-normal");
        self.ray(facing, (0.75, ArrowRole::Ray), stroke, &kernel_normal, 0.8);
        // The wrong T is the wrong-side candidate: the simple view leaves it out with them.
        if self.overlay.simple {
            return;
        }
        if let Some(wrong) = seed::refract(r.w, r.n, r.mu, r.convention) {
            let stroke = self.stroke(3.0, self.palette.warning, Dash::Dashed);
            self.ray(
                self.flat(wrong),
                (1.0, ArrowRole::Ray),
                stroke,
                &t!("diagram-outward-normal-bug"),
                0.85,
            );
        }
    }

    /// T = a·W + b·N drawn as its two parts, head to tail.
    fn decomposition(&mut self, r: &Refraction<f64>) {
        let Some(tr) = r.transmission else {
            return;
        };
        let a_w = self.state.plane().project(r.w * tr.a);
        let t = self.state.plane().project(tr.t);
        let path = [DVec2::ZERO, a_w, t].map(|p| self.at(p)).to_vec();
        self.halo(Part::Decomposition, path);
        let w_part = self.stroke(1.3, self.palette.w, Dash::Dotted);
        self.segment(DVec2::ZERO, a_w, w_part);
        let n_part = self.stroke(1.3, self.palette.n, Dash::Dotted);
        self.segment(a_w, t, n_part);
        if self.layout.drawing.contains(self.at(a_w)) {
            let at = self.at(a_w);
            let text = format!("a·W (a = {})", number(tr.a, 3));
            self.label_coloured(
                text,
                at,
                (Align::Center, Align::End),
                0.75,
                self.palette.ink,
            );
        }
    }

    /// The status strip, its text wrapped to fit by [`Diagram::with_overlay`].
    fn banner(&mut self, r: &Refraction<f64>, text: String) {
        let rect = self.layout.banner;
        // A hidden answer keeps the calm colour: the alarm's would give total reflection away.
        let (fill, ink) = if r.is_tir() && !self.overlay.hide_answer {
            (self.palette.alarm, self.palette.on_alarm)
        } else {
            (self.palette.calm, self.palette.ink)
        };
        self.shapes.push(Figure::Fill {
            points: rect.corners().to_vec(),
            colour: fill,
        });
        let at = Vec2::new(rect.min.x + self.font() * BANNER_MARGIN, rect.center().y);
        self.shapes.push(Figure::Text(Label {
            text,
            at,
            h: Align::Start,
            v: Align::Center,
            size: self.font(),
            colour: ink,
            background: None,
        }));
    }

    /// The index scale with the presets and the two μ markers, and the markers' handles;
    /// nothing when the scale is folded away.
    fn index_scale(&mut self) -> Vec<Handle> {
        let Some(scale) = self.layout.scale else {
            return Vec::new();
        };
        let font = self.font();
        let line = self.stroke(1.5, self.palette.guide, Dash::Solid);
        self.shapes.push(Figure::Line {
            points: vec![
                Vec2::new(scale.x, scale.top),
                Vec2::new(scale.x, scale.bottom),
            ],
            stroke: line,
        });
        self.label(
            t!("diagram-index-scale"),
            Vec2::new(scale.x, scale.top - font * 1.2),
            (Align::Center, Align::End),
            0.85,
        );
        for tenth in 10..=26 {
            let y = scale.y_of(f64::from(tenth) / 10.0);
            let long = tenth % 5 == 0;
            let half = if long { 0.5 } else { 0.25 } * font;
            self.shapes.push(Figure::Line {
                points: vec![Vec2::new(scale.x - half, y), Vec2::new(scale.x + half, y)],
                stroke: line,
            });
            if long {
                let at = Vec2::new(scale.x + font * 2.2, y);
                let text = number(f64::from(tenth) / 10.0, 1);
                self.label(text, at, (Align::Start, Align::Center), 0.75);
            }
        }
        for m in MATERIALS.iter().filter(|m| m.name != "air") {
            let at = Vec2::new(scale.x - font * 2.0, scale.y_of(m.index));
            self.label(m.label(), at, (Align::End, Align::Center), 0.75);
        }
        [
            (HandleId::MuI, -1.0, self.state.mu_i(), "μi"),
            (HandleId::MuT, 1.0, self.state.mu_t(), "μt"),
        ]
        .map(|(id, side, index, text)| {
            let radius = self.handle_radius(font * 0.75);
            // For a finger, apart by their grab areas' width, so that it takes the one it is on.
            let apart = if self.overlay.touch {
                (font * 0.8).max(radius * GRAB_SCALE)
            } else {
                font * 0.8
            };
            let center = Vec2::new(scale.x + side * apart, scale.y_of(index));
            let fill = medium_colour(&self.palette, index);
            self.shapes.push(Figure::Disc {
                center,
                radius,
                fill,
                outline: self.stroke(2.0, self.palette.ink, Dash::Solid),
            });
            // The ink or the background, whichever reads better on the medium's shade.
            let (ink, paper) = (self.palette.ink, self.palette.background);
            let colour = if ink.contrast(fill) >= paper.contrast(fill) {
                ink
            } else {
                paper
            };
            self.shapes.push(Figure::Text(Label {
                text: text.into(),
                at: center,
                h: Align::Center,
                v: Align::Center,
                size: self.layout.text_size(0.75),
                colour,
                background: None,
            }));
            Handle { id, center, radius }
        })
        .to_vec()
    }

    /// The angle of incidence and the incoming ray from the source to the hit point, with an
    /// arrowhead on the way.
    fn incoming(&mut self, r: &Refraction<f64>, normal: DVec2, toward_source: DVec2) {
        let palette = self.palette;
        self.angle(
            Part::AngleI,
            (normal, toward_source),
            format!("θi = {}°", number(r.cos_i.acos().to_degrees(), 1)),
            palette.incoming,
        );
        let incoming = self.stroke(2.0, palette.incoming, palette.incoming_dash);
        let source = toward_source * INCOMING_LENGTH;
        self.halo(Part::Incoming, vec![self.at(source), self.at(DVec2::ZERO)]);
        self.segment(source, DVec2::ZERO, incoming);
        self.keep_clear_of(source, DVec2::ZERO);
        let at = self.at(source);
        let away = self.layout.view.direction(toward_source);
        let anchor = (Align::away(away.x), Align::away(away.y));
        let colour = palette.text_shade(palette.incoming);
        self.label_coloured(t!("diagram-incoming-ray"), at, anchor, 0.8, colour);
        self.shapes.push(Figure::Arrow {
            from: self.at(source),
            to: self.at(source * 0.45),
            stroke: incoming,
            role: ArrowRole::Ray,
        });
    }

    /// The angle of refraction and a thin reflected ray, or under total internal reflection
    /// a bold one that carries all the light.
    fn outgoing(&mut self, r: &Refraction<f64>, normal: DVec2) {
        let palette = self.palette;
        let reflected = self.flat(r.reflected);
        if let Some(shares) = self.overlay.intensities.map(|p| Shares::of(r, p)) {
            if let Some(tr) = r.transmission {
                let theta_t = number(tr.cos_t.clamp(-1.0, 1.0).acos().to_degrees(), 1);
                let text = format!("θt = {theta_t}°");
                self.angle(Part::AngleT, (-normal, self.flat(tr.t)), text, palette.t);
            }
            let full = self.stroke(3.0, palette.reflected, palette.reflected_dash);
            let light = shares.polarisation.label();
            let name = t!("diagram-reflected-light", light = light);
            self.shared_ray(reflected, full, &name, shares.reflected);
            return;
        }
        if let Some(tr) = r.transmission {
            let t = self.flat(tr.t);
            let theta_t = number(tr.cos_t.clamp(-1.0, 1.0).acos().to_degrees(), 1);
            let text = format!("θt = {theta_t}°");
            self.angle(Part::AngleT, (-normal, t), text, palette.t);
            let thin = self.stroke(1.6, palette.reflected, palette.reflected_dash);
            let words = t!("diagram-reflected");
            self.ray(reflected, (0.7, ArrowRole::Ray), thin, &words, 0.8);
        } else {
            let bold = self.stroke(4.5, palette.reflected, palette.reflected_dash);
            let words = t!("diagram-reflected-all");
            self.ray(reflected, (1.0, ArrowRole::Ray), bold, &words, 1.0);
        }
    }

    /// W, N and (unless totally reflected) T; returns the diagram directions of W's and N's
    /// handles from the hit point, and whether W is drawn arriving.
    ///
    /// While a step's answer is hidden, a W that points past the interface (a direction of
    /// travel, Section 2) would run on unbent into the second medium, which *is* the answer
    /// the class is asked to predict: it is drawn arriving at the hit point instead, the
    /// same direction on the incoming side, with its handle at its tail.
    fn vectors(&mut self, r: &Refraction<f64>, normal: DVec2) -> ([DVec2; 2], bool) {
        let palette = self.palette;
        let own = match self.state.convention() {
            Convention::AlongRay => t!("diagram-w-along-ray"),
            Convention::TowardOrigin => t!("diagram-w-toward-origin"),
        };
        // A student's API names the vectors its own way while their call is shown.
        let names = self.overlay.student.as_ref().and_then(|s| s.names.clone());
        let (w_text, n_text) =
            names.map_or_else(|| (own, "N".to_owned()), |n| (n.incident, n.normal));
        let w_dir = self.state.direction(HandleId::W);
        let n_dir = self.state.direction(HandleId::N);
        let past_surface = w_dir.dot(normal) < 0.0;
        // Under total internal reflection no light goes past the surface: a solid W there
        // would be the only solid line in the second medium and read as a refracted ray, so
        // it is dotted (no candidate nor the construction, the other dotted lines, is drawn).
        let dash = if past_surface && r.is_tir() && !self.overlay.hide_answer {
            Dash::Dotted
        } else {
            Dash::Solid
        };
        let w_stroke = self.stroke(3.0, palette.w, dash);
        let arriving = self.overlay.hide_answer && past_surface;
        if arriving {
            self.arriving(Part::W, w_dir, w_stroke, &w_text);
        } else {
            self.part_ray(Part::W, w_dir, 1.0, w_stroke, &w_text);
        }
        let n_stroke = self.stroke(3.0, palette.n, Dash::Solid);
        self.part_ray(Part::N, n_dir, 1.0, n_stroke, &n_text);
        if let Some(tr) = r.transmission.filter(|_| !self.overlay.hide_answer) {
            let t_stroke = self.stroke(4.5, palette.t, Dash::Solid);
            let shares = self.overlay.intensities.map(|p| Shares::of(r, p));
            // Under the *Intensities* switch T is as wide as its share, and says it.
            let (t_stroke, text) = match shares {
                Some(s) => (
                    stroke_for(self.stroke(3.0, palette.t, Dash::Solid), s.transmitted)
                        .unwrap_or(t_stroke),
                    Shares::label(&t!("diagram-transmitted"), s.transmitted),
                ),
                None => (t_stroke, "T".to_owned()),
            };
            self.part_ray(Part::T, self.flat(tr.t), 1.0, t_stroke, &text);
        }
        let w_handle = if arriving {
            -w_dir * ARRIVING_LENGTH
        } else {
            w_dir
        };
        ([w_handle, n_dir], arriving)
    }

    /// An arrow of [`ARRIVING_LENGTH`] along `d` that ends at the hit point, labelled at its
    /// tail.
    fn arriving(&mut self, part: Part, d: DVec2, stroke: Stroke, text: &str) {
        let (tail, head) = (self.at(-d * ARRIVING_LENGTH), self.at(DVec2::ZERO));
        self.halo(part, vec![tail, head]);
        self.shapes.push(Figure::Arrow {
            from: tail,
            to: head,
            stroke,
            role: ArrowRole::Vector,
        });
        let away = self.layout.view.direction(-d);
        let at = tail + away * (self.font() * 0.9);
        let colour = self.palette.text_shade(stroke.colour);
        let anchor = (Align::away(away.x), Align::away(away.y));
        self.label_coloured(text, at, anchor, 1.0, colour);
    }

    /// A ray drawn by its share of the light (the *Intensities* switch), labelled `name` and
    /// its percentage; a share too small to see is not drawn, and its label says so where
    /// the ray's tip would be (p light at Brewster's angle).
    fn shared_ray(&mut self, d: DVec2, full: Stroke, name: &str, share: f64) {
        let text = Shares::label(name, share);
        if let Some(stroke) = stroke_for(full, share) {
            self.ray(d, (1.0, ArrowRole::Ray), stroke, &text, 0.9);
        } else {
            let away = self.layout.view.direction(d);
            let at = self.at(d * 0.7);
            let anchor = (Align::away(away.x), Align::away(away.y));
            let colour = self.palette.text_shade(full.colour);
            let text = t!("diagram-no-reflected-ray", label = text);
            self.label_coloured(text, at, anchor, 0.9, colour);
        }
    }

    /// The *Wavefronts* layer over the media: the fronts and the construction under the rays,
    /// their labels placed with the diagram's own.
    fn waves(&mut self, options: &wavefronts::WaveOptions) {
        let layer = wavefronts::layer(self.state, self.layout, &self.palette, options);
        self.shapes.extend(layer.shapes);
        let rank = self.rank;
        self.labels
            .extend(layer.labels.into_iter().map(|l| (rank, l)));
    }

    /// A round handle at a tip (on paper, none is drawn: nothing there can be dragged).
    fn tip_handle(&mut self, id: HandleId, d: DVec2, colour: Colour) -> Handle {
        let center = self.at(d);
        let radius = self.handle_radius(self.font() * 0.6);
        if self.overlay.paper {
            return Handle { id, center, radius };
        }
        self.shapes.push(Figure::Disc {
            center,
            radius,
            fill: self.palette.background,
            outline: self.stroke(2.5, colour, Dash::Solid),
        });
        Handle { id, center, radius }
    }
}

impl Diagram {
    /// The diagram of `state` on a canvas `size` pixels wide and high, in the standard
    /// palette and nothing over it.
    #[must_use]
    pub fn new(state: &ExplorerState, size: Vec2) -> Self {
        Self::with_overlay(state, size, &Overlay::default())
    }

    /// The diagram of `state` on a canvas `size` pixels wide and high, drawn in the overlay's
    /// palette and view, with its student's T and highlights.
    #[must_use]
    pub fn with_overlay(state: &ExplorerState, size: Vec2, overlay: &Overlay) -> Self {
        let r = state.refraction();
        let face = Typeface::egui_default();
        let summary = banner_words(state, overlay);
        let scale = overlay.index_scale && !overlay.paper;
        let (layout, banner) = layout_with_banner(size, &summary, &face, scale);
        let layout = layout.panned(overlay.pan_zoom);
        let palette = overlay.palette;
        let mut b = DiagramBuilder {
            layout: &layout,
            state,
            overlay,
            palette,
            labels: Vec::new(),
            rank: Rank::Media,
            shapes: vec![Figure::Fill {
                points: layout.canvas.corners().to_vec(),
                colour: palette.background,
            }],
            keep_clear: Vec::new(),
        };
        let normal = b.flat(r.facing_normal);
        let toward_source = b.flat(-r.travel);
        b.media(normal);
        // The wavefronts' names and the critical angle: what the lessons about them teach.
        b.rank = Rank::Landmark;
        // The fronts beyond the surface would show the bend of a hidden answer.
        if let Some(options) = overlay.waves.filter(|_| !overlay.hide_answer) {
            b.waves(&options);
        }
        b.guides(normal, toward_source);
        b.normal_incidence(r, normal);
        b.rank = Rank::Rays;
        b.incoming(r, normal, toward_source);
        if !overlay.hide_answer {
            b.rank = Rank::Candidates;
            if !overlay.simple {
                b.candidates(r);
            }
            b.rank = Rank::Bug;
            b.outward_normal_bug(r);
            b.rank = Rank::Construction;
            b.decomposition(r);
            b.rank = Rank::Rays;
            b.outgoing(r, normal);
        }
        b.rank = Rank::Vectors;
        let ([w_dir, n_dir], w_arriving) = b.vectors(r, normal);
        b.student();
        b.banner(r, banner);
        let markers = b.index_scale();
        let w = b.tip_handle(HandleId::W, w_dir, palette.w);
        let n = b.tip_handle(HandleId::N, n_dir, palette.n);
        let mut handles = vec![w, n];
        handles.extend(markers);
        if overlay.paper {
            handles.clear();
        }
        let (shapes, left_out) = b.finish(&handles);
        Self {
            layout,
            shapes,
            handles,
            summary,
            left_out,
            w_arriving,
        }
    }

    /// The primitives to draw, back to front.
    #[must_use]
    pub fn primitives(&self) -> Vec<Primitive> {
        lower_all(&self.shapes)
    }

    /// A handle's grab area on the canvas.
    #[must_use]
    pub fn grab_area(handle: &Handle) -> Rect {
        Rect::around(handle.center, handle.radius * GRAB_SCALE)
    }

    /// Moves `handle` to the canvas point `p`: W and N point at it, a μ marker takes the index
    /// at its height.
    pub fn drag(&self, state: &mut ExplorerState, handle: HandleId, p: Vec2) {
        match handle {
            HandleId::W if self.w_arriving => {
                state.point(handle, -self.layout.view.to_world(p));
            }
            HandleId::W | HandleId::N => state.point(handle, self.layout.view.to_world(p)),
            HandleId::MuI | HandleId::MuT => {
                // The scale only gives indices in INDEX_RANGE; the kernel refuses one only when
                // the other, typed, index puts the ratio out of range, and then the marker
                // stays at the last good state, as every refused edit does.
                let other = match handle {
                    HandleId::MuI => HandleId::MuT,
                    _ => HandleId::MuI,
                };
                // Within the scale's step of the other medium's index is the other medium
                // (air's 1.000293, not vacuum's 1.000 beside it): the ray goes straight on.
                let Some(scale) = self.layout.scale else {
                    return;
                };
                let mut index = scale.index_at(p.y);
                if (index - state.index(other)).abs() < 0.001 {
                    index = state.index(other);
                }
                state.set_index(handle, index).ok();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette;

    fn arrows(diagram: &Diagram) -> Vec<(Vec2, Stroke)> {
        diagram
            .shapes
            .iter()
            .filter_map(|s| match s {
                Figure::Arrow { to, stroke, .. } => Some((*to, *stroke)),
                _ => None,
            })
            .collect()
    }

    fn texts(diagram: &Diagram) -> Vec<&str> {
        diagram
            .shapes
            .iter()
            .filter_map(|s| match s {
                Figure::Text(l) => Some(l.text.as_str()),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn t_is_bold_and_the_rejected_candidates_are_ghosts_with_distinct_dashes() {
        let diagram = Diagram::new(&ExplorerState::default(), Vec2::new(1000.0, 700.0));
        let all = arrows(&diagram);
        let t = all.iter().find(|(_, s)| s.colour == palette::T).unwrap();
        assert_eq!(t.1.dash, Dash::Solid);
        let ghosts: Vec<_> = all
            .iter()
            .filter(|(_, s)| s.colour == palette::REJECTED)
            .collect();
        assert_eq!(ghosts.len(), 3);
        assert!(ghosts.iter().all(|(_, s)| s.width < t.1.width));
        let mut dashes: Vec<_> = ghosts.iter().map(|(_, s)| s.dash.pattern(2.0)).collect();
        dashes.dedup();
        assert_eq!(dashes.len(), 3);
        let labels = texts(&diagram);
        assert!(
            labels
                .iter()
                .any(|l| l.starts_with("other b root: wrong side\n(a, b) = ("))
        );
        assert!(labels.iter().any(|l| l.starts_with("Section 2")));
        assert_eq!(diagram.handles.len(), 4);
    }

    #[test]
    fn a_hidden_answer_leaves_out_t_the_reflection_and_the_verdict() {
        let beyond = refraction_model::Lesson::BeyondCritical.state();
        let state = ExplorerState::default();
        let hidden = Overlay {
            hide_answer: true,
            ..Overlay::default()
        };
        let size = Vec2::new(1000.0, 700.0);
        let shown = Diagram::new(&state, size);
        let asked = Diagram::with_overlay(&state, size, &hidden);
        assert!(texts(&shown).contains(&"T"));
        assert!(!texts(&asked).contains(&"T"), "no T");
        assert!(!texts(&asked).iter().any(|t| t.starts_with("reflected")));
        assert!(!texts(&asked).iter().any(|t| t.contains("θt")));
        assert!(arrows(&asked).len() < arrows(&shown).len());
        let tir = Diagram::with_overlay(&beyond, size, &hidden);
        assert!(tir.summary.contains("hidden"), "{}", tir.summary);
        assert!(!texts(&tir).iter().any(|t| t.contains("otal internal")));
        assert_eq!(asked.handles.len(), 4, "the handles stay");
    }

    #[test]
    fn a_hidden_answer_draws_nothing_past_the_interface_but_n() {
        // Issue 32: W's arrow ran on unbent into the glass and gave the answer away.
        let size = Vec2::new(1000.0, 700.0);
        let hidden = Overlay {
            hide_answer: true,
            ..Overlay::default()
        };
        for degrees in [0.0_f64, 40.0, 60.0] {
            for convention in [Convention::AlongRay, Convention::TowardOrigin] {
                let a = degrees.to_radians();
                let w = DVec3::new(a.sin(), -a.cos(), 0.0);
                let w = if convention == Convention::AlongRay {
                    w
                } else {
                    -w
                };
                let state = ExplorerState::new(w, DVec3::Y, 1.0, 1.5, convention).unwrap();
                let asked = Diagram::with_overlay(&state, size, &hidden);
                let surface = asked.layout.view.to_canvas(DVec2::ZERO).y;
                let n_colour = Overlay::default().palette.n;
                for shape in &asked.shapes {
                    if let Figure::Arrow {
                        from, to, stroke, ..
                    } = shape
                        && stroke.colour != n_colour
                    {
                        assert!(
                            from.y <= surface + 0.5 && to.y <= surface + 0.5,
                            "{degrees}° {convention:?}: an arrow past the interface"
                        );
                    }
                }
                let w_handle = asked.handles[0].center;
                assert!(w_handle.y < surface, "W's handle on the incoming side");
                // A drag of the handle still points W where the pointer says.
                let mut dragged = state.clone();
                let p = asked.layout.view.to_canvas(DVec2::new(-0.5, 0.8));
                asked.drag(&mut dragged, HandleId::W, p);
                let travel = dragged.refraction().travel;
                assert!(
                    travel.y < 0.0 && travel.x > 0.0,
                    "{travel}: still toward the surface"
                );
            }
        }
    }

    #[test]
    fn a_hidden_answer_draws_no_line_past_the_surface_nor_the_critical_angle() {
        // Snell's step 2: the dashed normal past the surface was the only line there, exactly
        // where the unbent ray goes; the critical angle's line and label answer "at what angle
        // does T lie along the surface?".
        let size = Vec2::new(1000.0, 700.0);
        let hidden = Overlay {
            hide_answer: true,
            ..Overlay::default()
        };
        let normal = refraction_model::Lesson::NormalIncidence.state();
        let glass_to_air = {
            let a = 41_f64.to_radians();
            let w = DVec3::new(a.sin(), -a.cos(), 0.0);
            ExplorerState::new(w, DVec3::Y, 1.5, 1.0, Convention::AlongRay).unwrap()
        };
        for state in [normal, glass_to_air] {
            let shown = Diagram::new(&state, size);
            let asked = Diagram::with_overlay(&state, size, &hidden);
            let surface = asked.layout.view.to_canvas(DVec2::ZERO).y;
            // In the drawing area (the index scale's lines cross the surface's height).
            let past = |d: &Diagram| {
                d.shapes.iter().any(|shape| {
                    matches!(shape, Figure::Line { points, .. }
                        if points.iter().any(|p| p.y > surface + 0.5
                            && p.x < d.layout.drawing.max.x))
                })
            };
            assert!(past(&shown) && !past(&asked), "{:?}", state.mu_i());
            let critical = |d: &Diagram| texts(d).iter().any(|t| t.contains("θc"));
            assert_eq!(critical(&shown), state.critical_angle().is_some());
            assert!(!critical(&asked));
        }
    }

    #[test]
    fn under_total_internal_reflection_w_past_the_surface_is_dotted_not_a_ray() {
        let beyond = refraction_model::Lesson::BeyondCritical.state();
        let diagram = Diagram::new(&beyond, Vec2::new(1000.0, 700.0));
        let w = arrows(&diagram)
            .into_iter()
            .find(|(_, s)| s.colour == palette::W)
            .unwrap();
        assert_eq!(w.1.dash, Dash::Dotted);
        let refracting = Diagram::new(&ExplorerState::default(), Vec2::new(1000.0, 700.0));
        let w = arrows(&refracting)
            .into_iter()
            .find(|(_, s)| s.colour == palette::W)
            .unwrap();
        assert_eq!(w.1.dash, Dash::Solid);
    }

    #[test]
    fn on_paper_nothing_is_drawn_to_drag_and_a_hidden_answer_names_the_convention() {
        let size = Vec2::new(700.0, 520.0);
        let paper = Overlay {
            paper: true,
            hide_answer: true,
            ..Overlay::default()
        };
        let state = ExplorerState::default();
        let screen = Diagram::with_overlay(
            &state,
            size,
            &Overlay {
                hide_answer: true,
                ..Overlay::default()
            },
        );
        let sheet = Diagram::with_overlay(&state, size, &paper);
        assert!(sheet.handles.is_empty() && sheet.layout.scale.is_none());
        let discs = |d: &Diagram| {
            d.shapes
                .iter()
                .filter(|s| matches!(s, Figure::Disc { .. }))
                .count()
        };
        assert_eq!(discs(&screen), 4, "W, N and the two μ markers");
        assert_eq!(discs(&sheet), 0);
        assert!(screen.summary.contains("reveal"), "{}", screen.summary);
        assert!(sheet.summary.starts_with("Section 2"), "{}", sheet.summary);
        assert!(!texts(&sheet).iter().any(|t| t.contains("reveal")));
    }

    #[test]
    fn the_simple_view_leaves_out_the_bug_s_wrong_t_with_the_candidates() {
        let droplet = refraction_model::Lesson::DropletExit.state();
        assert!(droplet.refraction().normal_flipped);
        let size = Vec2::new(1000.0, 700.0);
        let bug = t!("diagram-outward-normal-bug");
        let full = Diagram::new(&droplet, size);
        let simple = Diagram::with_overlay(
            &droplet,
            size,
            &Overlay {
                simple: true,
                ..Overlay::default()
            },
        );
        assert!(texts(&full).contains(&bug.as_str()));
        assert!(!texts(&simple).contains(&bug.as_str()));
    }

    #[test]
    fn total_internal_reflection_has_a_banner_and_no_candidates() {
        let mut state = ExplorerState::default();
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.rotate(HandleId::W, 30.0);
        assert!(state.refraction().is_tir());
        let diagram = Diagram::new(&state, Vec2::new(1000.0, 700.0));
        let all = arrows(&diagram);
        assert!(!all.iter().any(|(_, s)| s.colour == palette::REJECTED));
        assert!(!all.iter().any(|(_, s)| s.colour == palette::T));
        assert!(all.iter().any(|(_, s)| s.colour == palette::REFLECTED));
        let labels = texts(&diagram);
        assert!(
            labels
                .iter()
                .any(|l| l.starts_with("TOTAL INTERNAL REFLECTION"))
        );
        assert!(
            labels
                .iter()
                .any(|l| l.starts_with("critical angle θc = 41.8°"))
        );
    }

    #[test]
    fn a_flipped_normal_shows_the_bug_as_a_warning_ghost() {
        let mut state = ExplorerState::default();
        state.flip_normal();
        let diagram = Diagram::new(&state, Vec2::new(1000.0, 700.0));
        let (tip, _) = arrows(&diagram)
            .into_iter()
            .find(|(_, s)| s.colour == palette::WARNING)
            .unwrap();
        // The bug's T goes back up into the ray's medium (above the surface on screen).
        assert!(tip.y < diagram.layout.view.origin.y);
    }

    #[test]
    fn the_students_t_and_the_walk_through_highlights_are_part_of_the_picture() {
        use crate::overlay::{Focus, Overlay, StudentRay};
        let state = ExplorerState::default();
        let wrong = state.refraction().candidates[1].t;
        let overlay = Overlay {
            student: Some(StudentRay {
                t: wrong * 1.3,
                label: "your T: wrong side".to_owned(),
                names: None,
            }),
            focus: Some(Focus::SquaredConstraints),
            ..Overlay::default()
        };
        let size = Vec2::new(1000.0, 700.0);
        let diagram = Diagram::with_overlay(&state, size, &overlay);
        let plain = Diagram::new(&state, size);
        let student: Vec<_> = arrows(&diagram)
            .into_iter()
            .filter(|(_, s)| s.colour == palette::STUDENT)
            .collect();
        assert_eq!(student.len(), 1);
        assert_eq!(student[0].1.dash, Dash::LongDash);
        let origin = diagram.layout.view.origin;
        let length = (student[0].0 - origin).length() / diagram.layout.view.scale;
        assert!(
            (length - 1.3).abs() < 1e-3,
            "drawn with its own length: {length}"
        );
        assert!(texts(&diagram).contains(&"your T: wrong side"));
        let halos = |d: &Diagram| {
            d.shapes
                .iter()
                .filter(|s| matches!(s, Figure::Line { stroke, .. } if stroke.colour == palette::HIGHLIGHT))
                .count()
        };
        assert_eq!(halos(&diagram), 4, "T and the three ghosts");
        assert_eq!(halos(&plain), 0);
        let nan = Overlay {
            student: Some(StudentRay {
                t: glam::DVec3::NAN,
                label: "your T".to_owned(),
                names: None,
            }),
            ..Overlay::default()
        };
        assert_eq!(
            Diagram::with_overlay(&state, size, &nan).shapes.len(),
            plain.shapes.len()
        );
    }

    #[test]
    fn a_students_api_names_the_incident_vector_and_the_normal() {
        use crate::overlay::{Overlay, StudentRay, VectorNames};
        let state = ExplorerState::default();
        let overlay = Overlay {
            student: Some(StudentRay {
                t: state.refraction().t().unwrap(),
                label: "your wt".to_owned(),
                names: Some(VectorNames {
                    incident: "wi (back toward the origin)".to_owned(),
                    normal: "n".to_owned(),
                }),
            }),
            ..Overlay::default()
        };
        let size = Vec2::new(1000.0, 700.0);
        let named = Diagram::with_overlay(&state, size, &overlay);
        let named = texts(&named);
        assert!(named.contains(&"wi (back toward the origin)"), "{named:?}");
        assert!(named.contains(&"n") && !named.contains(&"N"), "{named:?}");
        let plain = Diagram::new(&state, size);
        assert!(texts(&plain).contains(&"W (along the ray)"));
    }

    #[test]
    fn every_palette_draws_the_same_picture_in_its_own_colours() {
        use crate::overlay::Overlay;
        use crate::palette::{Palette, Theme};
        let state = ExplorerState::default();
        let size = Vec2::new(1000.0, 700.0);
        let dark = Overlay {
            palette: Palette::new(Theme::HighContrastDark, true),
            ..Overlay::default()
        };
        let diagram = Diagram::with_overlay(&state, size, &dark);
        assert!(
            matches!(&diagram.shapes[0], Figure::Fill { colour, .. } if *colour == dark.palette.background)
        );
        assert!(texts(&diagram).contains(&"incoming ray"));
        let reflected = arrows(&diagram)
            .into_iter()
            .find(|(_, s)| s.colour == dark.palette.reflected)
            .unwrap();
        assert_eq!(reflected.1.dash, Dash::DashDotDot);
    }

    #[test]
    fn no_two_rays_differ_by_colour_alone_in_any_palette() {
        use crate::overlay::{Overlay, StudentRay};
        use crate::palette::{Palette, Theme};
        let mut state = ExplorerState::default();
        state.flip_normal();
        let wrong = state.refraction().candidates[1].t;
        for theme in Theme::ALL {
            for safe in [false, true] {
                let palette = Palette::new(theme, safe);
                let overlay = Overlay {
                    palette,
                    student: Some(StudentRay {
                        t: wrong,
                        label: "your T".to_owned(),
                        names: None,
                    }),
                    ..Overlay::default()
                };
                let diagram = Diagram::with_overlay(&state, Vec2::new(1000.0, 700.0), &overlay);
                // The rays: every arrow but the vectors W and N (and the bug's −N beside N),
                // which are told apart by their labels and handles.
                let rays: Vec<(Dash, u32)> = arrows(&diagram)
                    .into_iter()
                    .filter(|(_, s)| s.colour != palette.w && s.colour != palette.n)
                    .map(|(_, s)| (s.dash, s.width.to_bits()))
                    .collect();
                assert!(rays.len() >= 7, "{rays:?}");
                for (i, a) in rays.iter().enumerate() {
                    assert!(!rays[i + 1..].contains(a), "{theme:?} {safe}: {a:?} twice");
                }
                assert!(texts(&diagram).contains(&"incoming ray"));
            }
        }
    }

    #[test]
    fn dragging_handles_moves_w_and_the_indices() {
        let mut state = ExplorerState::default();
        let diagram = Diagram::new(&state, Vec2::new(1000.0, 700.0));
        let origin = diagram.layout.view.origin;
        diagram.drag(&mut state, HandleId::W, origin + Vec2::new(0.0, 100.0));
        assert!(state.refraction().cos_i > 1.0 - 1e-12);
        let scale = diagram.layout.scale.unwrap();
        let y = scale.y_of(2.0);
        diagram.drag(&mut state, HandleId::MuT, Vec2::new(0.0, y));
        assert_eq!(state.mu_t(), 2.0);
        // μt dragged to the bottom beside air: air, not vacuum (no θc of 88.6°).
        diagram.drag(&mut state, HandleId::MuT, Vec2::new(0.0, scale.bottom));
        assert_eq!(state.mu_t(), state.mu_i());
        assert!(state.critical_angle().is_none());
        let rect = Diagram::grab_area(&diagram.handles[0]);
        assert!(rect.contains(diagram.handles[0].center));
    }

    #[test]
    fn every_label_fits_on_small_and_large_canvases() {
        let face = Typeface::egui_default();
        let mut tir = ExplorerState::default();
        tir.set_mu_i(1.5).unwrap();
        tir.set_mu_t(1.0).unwrap();
        tir.rotate(HandleId::W, 45.0);
        for state in [ExplorerState::default(), tir] {
            for size in [Vec2::new(500.0, 560.0), Vec2::new(1920.0, 1080.0)] {
                let diagram = Diagram::new(&state, size);
                let canvas = diagram.layout.canvas;
                for shape in &diagram.shapes {
                    if let Figure::Text(l) = shape {
                        let extent = face.measure(&l.text, l.size);
                        let min = l.at - extent * Vec2::new(l.h.fraction(), l.v.fraction());
                        let inside = canvas.contains(min) && canvas.contains(min + extent);
                        assert!(inside, "{l:?} is cut off at {size}");
                        assert!(l.text.chars().all(|c| c == '\n' || face.covers(c)), "{l:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn no_label_lies_on_a_ray_and_none_a_lesson_teaches_is_left_out() {
        // Issue 22: "θt" and "a·W" washed out T and W; in the normal-incidence lesson three
        // labels hid T.
        use refraction_model::Lesson;
        let face = Typeface::egui_default();
        let sizes = [
            Vec2::new(500.0, 560.0),
            Vec2::new(760.0, 520.0),
            Vec2::new(1920.0, 1080.0),
        ];
        let mut flipped = ExplorerState::default();
        flipped.flip_normal();
        let states = Lesson::ALL.map(Lesson::state).into_iter().chain([flipped]);
        for state in states {
            for size in sizes {
                let diagram = Diagram::new(&state, size);
                let shafts: Vec<Obstacle> = diagram
                    .shapes
                    .iter()
                    .filter_map(|shape| match shape {
                        Figure::Arrow {
                            from, to, stroke, ..
                        } => Some(Obstacle::Shaft {
                            a: *from,
                            b: *to,
                            half_width: stroke.width * 0.5,
                            firm: false,
                        }),
                        _ => None,
                    })
                    .collect();
                let labels = diagram.shapes.iter().filter_map(|shape| match shape {
                    Figure::Text(l) if l.background.is_some() => Some(l),
                    _ => None,
                });
                for l in labels {
                    let extent = face.measure(&l.text, l.size);
                    let min = l.at - extent * Vec2::new(l.h.fraction(), l.v.fraction());
                    let text_box = Rect::from_min_size(min, extent);
                    for shaft in &shafts {
                        assert!(!shaft.touches(&text_box), "{:?} on a ray at {size}", l.text);
                    }
                }
                let taught = ["T", "W", "N", "θi", "θt", "θc"];
                for l in &diagram.left_out {
                    assert!(
                        !taught.iter().any(|t| l.text.starts_with(t)),
                        "{:?} left out at {size}",
                        l.text
                    );
                }
            }
        }
    }
}
