//! The one label placer of every view (the interface diagram, a traced scene, the accuracy
//! plot): it keeps each label inside its bounds and off the obstacles it is told about
//! (arrowheads, handles, hit markers, plot markers) and off every label placed before it, and
//! leaves a label out rather than let it cover anything. A label left out is handed back, so
//! that the window can show its text on hover.
//!
//! Labels are placed in the order they are given: an earlier label keeps its spot, a later one
//! moves aside (a step at a time, around its anchor) or is left out. Views give the labels that
//! matter most first.

use glam::Vec2;

use super::font::Typeface;
use super::geometry::{Colour, Rect};
use super::lattice::{Shape, Squares};
use super::obstacle::Obstacle;
use super::obstacle_grid::{Crossable, ObstacleGrid};
use super::shapes::Label;

/// The opacity of a leader line, of 255.
const LEADER_ALPHA: u8 = 120;

/// What is wrong with the texts among `primitives`, drawn in `face` on `canvas`: each text that
/// covers another or reaches outside the canvas, in words (empty when nothing is). The views'
/// tests ask it of every figure they draw.
#[cfg(test)]
pub(crate) fn text_problems(
    primitives: &[crate::Primitive],
    face: &Typeface,
    canvas: &Rect,
) -> Vec<String> {
    let boxes: Vec<(&str, Rect)> = primitives
        .iter()
        .filter_map(|p| match p {
            crate::Primitive::Text(label) if !label.text.trim().is_empty() => {
                let extent = face.measure(&label.text, label.size);
                let fraction = Vec2::new(label.h.fraction(), label.v.fraction());
                let min = label.at - extent * fraction;
                Some((
                    label.text.as_str(),
                    Rect {
                        min,
                        max: min + extent,
                    },
                ))
            }
            _ => None,
        })
        .collect();
    let mut problems = Vec::new();
    for (i, (text, a)) in boxes.iter().enumerate() {
        if !(canvas.contains(a.min) && canvas.contains(a.max)) {
            // untranslated: a test's report to developers
            problems.push(format!("{text:?} reaches outside the canvas"));
        }
        for (other, b) in &boxes[i + 1..] {
            if a.overlaps(b) {
                // untranslated: a test's report to developers
                problems.push(format!("{text:?} covers {other:?}"));
            }
        }
    }
    problems
}

/// How far, in steps of 0.6 of the label's size, a label may move from its anchor without a
/// leader line.
const MOST_STEPS: usize = 12;

/// How far it may move with one.
const MOST_STEPS_WITH_LEADER: usize = 40;

/// The directions a label tries at each distance from its anchor, nearest first.
const DIRECTIONS: [Vec2; 8] = [
    Vec2::new(0.0, 1.0),
    Vec2::new(0.0, -1.0),
    Vec2::new(1.0, 0.0),
    Vec2::new(-1.0, 0.0),
    Vec2::new(0.7, 0.7),
    Vec2::new(-0.7, 0.7),
    Vec2::new(0.7, -0.7),
    Vec2::new(-0.7, -0.7),
];

/// Places labels one after another on one canvas.
pub struct Placer<'f> {
    face: &'f Typeface,
    obstacles: Vec<Obstacle>,
    /// The obstacles by where they are, built again when more have arrived since.
    grid: ObstacleGrid,
    /// The firm shafts' ends, which no leader line may cross.
    firm_shafts: Vec<(Vec2, Vec2)>,
    placed: Vec<Rect>,
}

/// What became of the labels given to a [`Placer`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Placement {
    /// The labels drawn, moved where they cover nothing.
    pub placed: Vec<Label>,
    /// The leader lines of the labels placed far from their anchors: from the anchor to the
    /// nearest point of the label's box, in the label's colour.
    pub leaders: Vec<(Vec2, Vec2, super::geometry::Colour)>,
    /// The labels left out, at their anchors, for a hover to show.
    pub left_out: Vec<Label>,
}

impl Placement {
    /// The placed labels and their leader lines as figures, the leaders first (thin, under
    /// the words).
    #[must_use]
    pub fn figures(self) -> Vec<super::shapes::Figure> {
        use super::shapes::{Dash, Figure, Stroke};
        let leaders = self
            .leaders
            .into_iter()
            // Thin, dotted and faint beside the text: a long leader must not read as a ray
            // (the outward-normal bug's, at 170 of 255, crossed the upper medium like one).
            .map(|(from, to, colour)| Figure::Line {
                points: vec![from, to],
                stroke: Stroke {
                    width: 1.0,
                    colour: Colour {
                        a: LEADER_ALPHA,
                        ..colour
                    },
                    dash: Dash::Dotted,
                },
            });
        leaders
            .chain(self.placed.into_iter().map(Figure::Text))
            .collect()
    }
}

/// How a label is placed: where it may go and what happens when no free spot is near.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Need {
    /// Near its anchor, else farther with a leader line, else left out.
    Optional,
    /// A label a lesson teaches: as [`Need::Optional`], but with no free spot even far away
    /// it may cross a shaft that is not firm, and failing that a firm one (never a handle,
    /// an arrowhead, a marked point or another label); left out only where the canvas has no
    /// room at all. Such labels are placed first, so that lesser ones give way.
    Shown,
}

impl<'f> Placer<'f> {
    /// A placer measuring text with `face`, with nothing on the canvas yet.
    #[must_use]
    pub fn new(face: &'f Typeface) -> Self {
        Self {
            face,
            obstacles: Vec::new(),
            grid: ObstacleGrid::default(),
            firm_shafts: Vec::new(),
            placed: Vec::new(),
        }
    }

    /// Adds something no later label may cover.
    pub fn avoid(&mut self, obstacle: Obstacle) {
        if let Obstacle::Shaft {
            a, b, firm: true, ..
        } = obstacle
        {
            self.firm_shafts.push((a, b));
        }
        self.obstacles.push(obstacle);
    }

    /// The box a label covers with its anchor at `at`: its text and the background's margin.
    #[must_use]
    pub fn text_box(&self, label: &Label, at: Vec2) -> Rect {
        label.boxed(self.face.measure(&label.text, label.size), at)
    }

    /// Free of every obstacle and every label placed so far.
    fn free(&self, r: &Rect) -> bool {
        self.clear_of(r, Crossable::Nothing)
    }

    /// Free of everything but the shafts that are not firm: what a label that must be shown
    /// settles for first (it may cross a lesser ray, never a handle, an arrowhead, a marked
    /// point or another label).
    fn free_but_lesser_shafts(&self, r: &Rect) -> bool {
        self.clear_of(r, Crossable::LesserShafts)
    }

    /// Free of everything but the rays' shafts: a shown label's last resort where the canvas
    /// is so small that only crossing W, N or T would keep it.
    fn free_but_shafts(&self, r: &Rect) -> bool {
        self.clear_of(r, Crossable::Shafts)
    }

    /// Whether `r` covers no placed label and no obstacle but those it may `cross`.
    fn clear_of(&self, r: &Rect, cross: Crossable) -> bool {
        // `place` builds the grid of every obstacle before it looks for a spot.
        // untranslated: a panic message for the engineer, never shown to a user.
        debug_assert_eq!(self.grid.count, self.obstacles.len(), "a stale grid");
        let touched = |i: usize| self.obstacles[i].touches(r);
        !self.grid.any_near(r, cross, touched) && !self.placed.iter().any(|p| p.overlaps(r))
    }

    /// The first anchor from `steps` (in steps of 0.6 of the label's size around its anchor)
    /// whose box, moved inside `bounds`, is `free`; the anchor and its box.
    fn spot(
        &self,
        label: &Label,
        bounds: &Rect,
        steps: core::ops::RangeInclusive<usize>,
        free: impl Fn(&Self, &Rect) -> bool,
    ) -> Option<(Vec2, Rect)> {
        let step = label.size * 0.6;
        // Measured once: the text's extent does not depend on where it goes.
        let extent = self.face.measure(&label.text, label.size);
        let offsets = steps.flat_map(|k| {
            let ring: Vec<Vec2> = if k == 0 {
                vec![Vec2::ZERO]
            } else {
                DIRECTIONS.map(|d| d * step * k as f32).to_vec()
            };
            ring
        });
        offsets.map(|offset| label.at + offset).find_map(|at| {
            let r = label.boxed(extent, at);
            let shift = (bounds.min - r.min).max(Vec2::ZERO) + (bounds.max - r.max).min(Vec2::ZERO);
            // The box is measured again at the moved anchor, so that what is checked is
            // exactly what a reader of the label's anchor computes.
            let at = at + shift;
            let moved = label.boxed(extent, at);
            let inside = moved.min.cmpge(bounds.min).all() && moved.max.cmple(bounds.max).all();
            (inside && free(self, &moved)).then_some((at, moved))
        })
    }

    /// Whether a leader line from `anchor` to the box `r` would cross no firm shaft (W, N or
    /// T): a leader across them would read as one more ray.
    fn leader_clear(&self, anchor: Vec2, r: &Rect) -> bool {
        let end = anchor.clamp(r.min, r.max);
        if end.distance(anchor) < 1.0 {
            return true;
        }
        // The first pixels leave the anchor, which may lie on a ray's tip.
        let start = anchor + (end - anchor).normalize() * 3.0;
        !self
            .firm_shafts
            .iter()
            .any(|(a, b)| segments_cross(start, end, *a, *b))
    }

    /// `label` in each shape a label that must be shown tries anywhere in `bounds`: as it is,
    /// then broken into narrower lines (a long label that fits nowhere whole often fits
    /// between the rays in more lines), each shape once.
    fn shapes(&self, label: &Label) -> Vec<Shape> {
        let widest = self.face.measure(&label.text, label.size).x;
        let mut texts = vec![label.text.clone()];
        for share in [0.7, 0.5, 0.35] {
            let text = wrap(self.face, &label.text, label.size, widest * share);
            if !texts.contains(&text) {
                texts.push(text);
            }
        }
        texts
            .into_iter()
            .map(|text| {
                let extent = self.face.measure(&text, label.size);
                Shape::new(
                    Label {
                        text,
                        ..label.clone()
                    },
                    extent,
                )
            })
            .collect()
    }

    /// Where a label that must be shown goes when no ring around its anchor is free: the spot
    /// in `bounds` nearest its anchor that is free and reached by a leader crossing no firm
    /// shaft, else one that is free, else one free but for lesser shafts; each tried with
    /// every one of the label's [`Self::shapes`] in turn. The label keeps the text of the
    /// shape that found its spot.
    fn anywhere(&self, label: &mut Label, bounds: &Rect) -> Option<(Vec2, Rect)> {
        let shapes = self.shapes(label);
        let anchor = label.at;
        let touched = |cross| {
            move |r: &Rect| {
                self.grid
                    .any_near(r, cross, |i| self.obstacles[i].touches(r))
            }
        };
        let all = Squares::new(bounds, label.size, touched(Crossable::Nothing));
        // One pass over a shape's spots finds its nearest spot with a clear leader and, on the
        // way, its nearest free one, kept for when no shape has a clear leader.
        let mut nearest_free = Vec::new();
        let found = shapes
            .iter()
            .find_map(|shape| {
                let mut free = None;
                let clear = shape.spots(bounds, &all).into_iter().find(|&(at, r)| {
                    let ok = self.free(&r);
                    if ok && free.is_none() {
                        free = Some((at, r));
                    }
                    ok && self.leader_clear(anchor, &r)
                });
                nearest_free.push(free);
                clear.map(|spot| (shape, spot))
            })
            .or_else(|| {
                let mut free = shapes.iter().zip(nearest_free);
                free.find_map(|(shape, spot)| spot.map(|spot| (shape, spot)))
            })
            .or_else(|| {
                let solid = Squares::new(bounds, label.size, touched(Crossable::LesserShafts));
                shapes.iter().find_map(|shape| {
                    let mut spots = shape.spots(bounds, &solid).into_iter();
                    let spot = spots.find(|(_, r)| self.free_but_lesser_shafts(r))?;
                    Some((shape, spot))
                })
            });
        let (shape, spot) = found?;
        label.text.clone_from(&shape.label.text);
        Some(spot)
    }

    /// Places `label` inside `bounds`: at its anchor if that covers nothing, else at the
    /// nearest free spot around it, moved inside `bounds` as needed; farther, with a leader
    /// line from the anchor (the second value), when nothing near is free; a label that is
    /// [`Need::Shown`] may then cross a shaft.
    ///
    /// # Errors
    /// No free spot, or the label is larger than `bounds`: it is given back unchanged.
    pub fn place(
        &mut self,
        mut label: Label,
        bounds: &Rect,
        need: Need,
    ) -> Result<(Label, Option<Vec2>), Label> {
        if self.grid.count != self.obstacles.len() {
            self.grid = ObstacleGrid::new(&self.obstacles);
        }
        let near = self.spot(&label, bounds, 0..=MOST_STEPS, Self::free);
        let far = || {
            self.spot(
                &label,
                bounds,
                MOST_STEPS + 1..=MOST_STEPS_WITH_LEADER,
                |placer: &Self, r: &Rect| placer.free(r) && placer.leader_clear(label.at, r),
            )
        };
        let found = match near {
            Some(spot) => Some((spot, false)),
            None => far().map(|spot| (spot, true)),
        };
        let found = match (found, need) {
            (Some(found), _) => Some(found),
            (None, Need::Optional) => None,
            (None, Need::Shown) => {
                let steps = 0..=MOST_STEPS_WITH_LEADER;
                // A leader across W, N or T is avoided where it can be, then settled for
                // before the label itself crosses a ray.
                self.anywhere(&mut label, bounds)
                    .or_else(|| self.spot(&label, bounds, steps, Self::free_but_shafts))
                    .map(|spot| {
                        let far = spot.0.distance(label.at) > label.size * 0.6 * MOST_STEPS as f32;
                        (spot, far)
                    })
            }
        };
        let Some(((at, r), leader)) = found else {
            return Err(label);
        };
        self.placed.push(r);
        let anchor = label.at;
        label.at = at;
        Ok((label, leader.then_some(anchor)))
    }

    /// Places every label of `labels` in order, each inside the bounds given with it, as
    /// its need says.
    #[must_use]
    pub(crate) fn place_all(
        &mut self,
        labels: impl IntoIterator<Item = (Label, Rect, Need)>,
    ) -> Placement {
        let mut placement = Placement::default();
        for (label, bounds, need) in labels {
            match self.place(label, &bounds, need) {
                Ok((l, leader)) => {
                    if let Some(anchor) = leader {
                        let extent = self.face.measure(&l.text, l.size);
                        let r = l.boxed(extent, l.at);
                        placement
                            .leaders
                            .push((anchor, anchor.clamp(r.min, r.max), l.colour));
                    }
                    placement.placed.push(l);
                }
                Err(l) => placement.left_out.push(l),
            }
        }
        placement
    }
}

/// Whether the segments `p0`–`p1` and `q0`–`q1` cross (touching ends count).
fn segments_cross(p0: Vec2, p1: Vec2, q0: Vec2, q1: Vec2) -> bool {
    let side = |a: Vec2, b: Vec2, c: Vec2| (b - a).perp_dot(c - a);
    let (d1, d2) = (side(q0, q1, p0), side(q0, q1, p1));
    let (d3, d4) = (side(p0, p1, q0), side(p0, p1, q1));
    d1 * d2 <= 0.0 && d3 * d4 <= 0.0 && (d1 != 0.0 || d2 != 0.0 || d3 != 0.0 || d4 != 0.0)
}

/// `text` broken into lines no wider than `width` pixels at font size `size`, between words
/// only (a word wider than `width` gets a line of its own). Existing line breaks are kept.
/// Linear in the text's length.
#[must_use]
pub(crate) fn wrap(face: &Typeface, text: &str, size: f32, width: f32) -> String {
    wrap_lines(face, text, size, width, false)
}

/// `text` broken into lines no wider than `width` pixels at font size `size`, as the labels
/// wrap, but a word wider than a line is cut into pieces that fit (a page's text, where one
/// unbroken word must not run off the paper). Linear in the text's length: each character
/// is measured once or twice.
#[must_use]
pub fn wrap_breaking_words(face: &Typeface, text: &str, size: f32, width: f32) -> String {
    wrap_lines(face, text, size, width, true)
}

fn wrap_lines(face: &Typeface, text: &str, size: f32, width: f32, break_words: bool) -> String {
    // Widths add up (the font is measured without kerning).
    let space = face.width(" ", size);
    let mut lines: Vec<String> = Vec::new();
    for paragraph in text.lines() {
        let mut line = String::new();
        let mut line_width = 0.0;
        for word in paragraph.split(' ') {
            let whole = face.width(word, size);
            let pieces = if break_words && whole > width {
                pieces(face, word, size, width)
            } else {
                vec![(word, whole)]
            };
            for (piece, piece_width) in pieces {
                if !line.is_empty() && line_width + space + piece_width > width {
                    lines.push(core::mem::replace(&mut line, piece.to_owned()));
                    line_width = piece_width;
                } else {
                    if !line.is_empty() {
                        line.push(' ');
                        line_width += space;
                    }
                    line.push_str(piece);
                    line_width += piece_width;
                }
            }
        }
        lines.push(line);
    }
    lines.join("\n")
}

/// `word`, wider than `width`, cut into pieces no wider than it (each at least one
/// character), with their widths.
fn pieces<'a>(face: &Typeface, word: &'a str, size: f32, width: f32) -> Vec<(&'a str, f32)> {
    let (mut out, mut start, mut used) = (Vec::new(), 0, 0.0);
    for (i, ch) in word.char_indices() {
        let advance = face.width(ch.encode_utf8(&mut [0; 4]), size);
        if used + advance > width && i > start {
            out.push((&word[start..i], used));
            (start, used) = (i, 0.0);
        }
        used += advance;
    }
    out.push((&word[start..], used));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette;
    use crate::shapes::Align;
    use proptest::prelude::*;

    #[test]
    fn a_label_breaks_between_words_and_a_page_inside_a_word_too_long() {
        // Issue 32: a diagram's label read "преломляет/ся", broken inside the word.
        let face = Typeface::egui_default();
        let narrow = face.width("преломля", 14.0);
        let wrapped = wrap(&face, "знак преломляется", 14.0, narrow);
        assert_eq!(wrapped, "знак\nпреломляется");
        let broken = wrap_breaking_words(&face, "знак преломляется", 14.0, narrow);
        assert!(broken.lines().count() >= 3, "{broken}");
        assert!(
            broken.lines().all(|l| face.width(l, 14.0) <= narrow),
            "{broken}"
        );
    }

    fn label(text: &str, at: Vec2) -> Label {
        Label {
            text: text.to_owned(),
            at,
            h: Align::Start,
            v: Align::Start,
            size: 14.0,
            colour: palette::INK,
            background: Some(palette::LABEL_BACKGROUND),
        }
    }

    fn canvas() -> Rect {
        Rect::from_min_size(Vec2::ZERO, Vec2::new(400.0, 300.0))
    }

    #[test]
    fn segments_cross_where_they_meet_and_not_beside_each_other() {
        let (a, b) = (Vec2::new(0.0, 0.0), Vec2::new(10.0, 10.0));
        assert!(segments_cross(
            a,
            b,
            Vec2::new(0.0, 10.0),
            Vec2::new(10.0, 0.0)
        ));
        assert!(!segments_cross(
            a,
            b,
            Vec2::new(5.0, 0.0),
            Vec2::new(15.0, 10.0)
        ));
        assert!(!segments_cross(
            a,
            b,
            Vec2::new(20.0, 0.0),
            Vec2::new(20.0, 10.0)
        ));
    }

    #[test]
    fn a_label_with_room_stays_at_its_anchor() {
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        let placed = placer.place(label("T", Vec2::new(50.0, 50.0)), &canvas(), Need::Optional);
        assert_eq!(placed.unwrap(), (label("T", Vec2::new(50.0, 50.0)), None));
    }

    #[test]
    fn a_label_moves_off_an_arrowhead_and_into_the_canvas() {
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        let head = vec![
            Vec2::new(45.0, 45.0),
            Vec2::new(70.0, 55.0),
            Vec2::new(45.0, 65.0),
        ];
        placer.avoid(Obstacle::Polygon(head.clone()));
        let (placed, _) = placer
            .place(
                label("your T", Vec2::new(50.0, 50.0)),
                &canvas(),
                Need::Optional,
            )
            .unwrap();
        let r = placer.text_box(&placed, placed.at);
        assert!(!Obstacle::Polygon(head).touches(&r));
        let (edge, _) = placer
            .place(
                label("at the edge", Vec2::new(390.0, 290.0)),
                &canvas(),
                Need::Optional,
            )
            .unwrap();
        let r = placer.text_box(&edge, edge.at);
        assert!(r.max.x <= 400.0 && r.max.y <= 300.0);
    }

    #[test]
    fn a_label_with_no_room_is_left_out_not_overlapped() {
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        placer.avoid(Obstacle::Box(canvas()));
        let placement = placer.place_all([(
            label("θi = 40°", Vec2::new(50.0, 50.0)),
            canvas(),
            Need::Optional,
        )]);
        assert!(placement.placed.is_empty());
        assert_eq!(placement.left_out[0].text, "θi = 40°");
        let tiny = Rect::from_min_size(Vec2::ZERO, Vec2::splat(5.0));
        assert!(
            Placer::new(&face)
                .place(label("wide", Vec2::ZERO), &tiny, Need::Optional)
                .is_err()
        );
        // A label a lesson teaches is shown all the same, over what is not a handle.
        let mut placer = Placer::new(&face);
        let shaft = Obstacle::Shaft {
            a: Vec2::ZERO,
            b: Vec2::new(400.0, 300.0),
            half_width: 300.0,
            firm: false,
        };
        placer.avoid(shaft);
        let placement =
            placer.place_all([(label("T", Vec2::new(50.0, 50.0)), canvas(), Need::Shown)]);
        assert_eq!(placement.placed.len(), 1);
    }

    #[test]
    fn a_label_stays_off_a_shaft_and_goes_farther_with_a_leader_when_nothing_near_is_free() {
        let face = Typeface::egui_default();
        let mut placer = Placer::new(&face);
        // A thick ray across the canvas through the anchor.
        let shaft = Obstacle::Shaft {
            a: Vec2::new(0.0, 50.0),
            b: Vec2::new(400.0, 50.0),
            half_width: 3.0,
            firm: false,
        };
        placer.avoid(shaft.clone());
        let (near, leader) = placer
            .place(
                label("θt", Vec2::new(100.0, 45.0)),
                &canvas(),
                Need::Optional,
            )
            .unwrap();
        assert!(!shaft.touches(&placer.text_box(&near, near.at)));
        assert_eq!(leader, None, "a free spot is near");
        // Everything near the anchor taken: the label goes farther, with a leader.
        let mut placer = Placer::new(&face);
        placer.avoid(Obstacle::Box(Rect::from_min_size(
            Vec2::ZERO,
            Vec2::new(300.0, 165.0),
        )));
        let placement = placer.place_all([(
            label("a·W", Vec2::new(100.0, 50.0)),
            canvas(),
            Need::Optional,
        )]);
        assert_eq!(placement.placed.len(), 1, "{placement:?}");
        assert_eq!(placement.leaders.len(), 1, "{placement:?}");
        assert_eq!(placement.leaders[0].0, Vec2::new(100.0, 50.0));
    }

    #[test]
    fn wrapping_keeps_every_line_inside_the_width() {
        let face = Typeface::egui_default();
        let text = "k = -0.25 < 0: no real root for b, no refracted ray; all light is reflected";
        let wrapped = wrap(&face, text, 14.0, 200.0);
        assert!(wrapped.lines().count() > 1);
        assert!(wrapped.lines().all(|l| face.width(l, 14.0) <= 200.0));
        assert_eq!(wrapped.replace('\n', " "), text);
        assert_eq!(wrap(&face, "one\ntwo", 14.0, 1000.0), "one\ntwo");
    }

    fn obstacle() -> impl Strategy<Value = Obstacle> {
        let point = || (0.0f32..400.0, 0.0f32..300.0).prop_map(|(x, y)| Vec2::new(x, y));
        prop_oneof![
            (point(), 2.0f32..40.0, 2.0f32..40.0)
                .prop_map(|(p, w, h)| Obstacle::Box(Rect::from_min_size(p, Vec2::new(w, h)))),
            (point(), 1.0f32..15.0).prop_map(|(center, radius)| Obstacle::Disc { center, radius }),
            (point(), point(), 0.5f32..4.0).prop_map(|(a, b, half_width)| Obstacle::Shaft {
                a,
                b,
                half_width,
                firm: false,
            }),
            (point(), 0.0f32..6.3, 5.0f32..20.0).prop_map(|(tip, turn, length)| {
                let d = Vec2::from_angle(turn) * length;
                Obstacle::Polygon(vec![
                    tip,
                    tip - d + d.perp() * 0.4,
                    tip - d - d.perp() * 0.4,
                ])
            }),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn placed_labels_cover_no_obstacle_no_other_label_and_stay_inside(
            obstacles in prop::collection::vec(obstacle(), 0..25),
            anchors in prop::collection::vec(
                (-20.0f32..420.0, -20.0f32..320.0, 0usize..3, 0usize..3, 13.0f32..30.0, 1usize..20),
                1..25,
            ),
        ) {
            let face = Typeface::egui_default();
            let mut placer = Placer::new(&face);
            for o in &obstacles {
                placer.avoid(o.clone());
            }
            let aligns = [Align::Start, Align::Center, Align::End];
            let labels: Vec<(Label, Rect, Need)> = anchors
                .iter()
                .map(|&(x, y, h, v, size, length)| {
                    let mut l = label(&"μ".repeat(length), Vec2::new(x, y));
                    (l.h, l.v, l.size) = (aligns[h], aligns[v], size);
                    (l, canvas(), Need::Optional)
                })
                .collect();
            let count = labels.len();
            let placement = placer.place_all(labels);
            prop_assert_eq!(placement.placed.len() + placement.left_out.len(), count);
            let boxes: Vec<Rect> =
                placement.placed.iter().map(|l| placer.text_box(l, l.at)).collect();
            for (i, b) in boxes.iter().enumerate() {
                prop_assert!(b.min.cmpge(Vec2::ZERO).all() && b.max.cmple(Vec2::new(400.0, 300.0)).all());
                for o in &obstacles {
                    prop_assert!(!o.touches(b), "{:?} covers {:?}", b, o);
                }
                for other in &boxes[i + 1..] {
                    prop_assert!(!b.overlaps(other));
                }
            }
        }
    }
}
