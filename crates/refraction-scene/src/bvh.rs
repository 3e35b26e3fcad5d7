//! The acceleration structure the tracer finds crossings and media with: a bounding volume
//! hierarchy over the pieces of a scene's shapes (a polygon's edges, every other shape whole),
//! so that a ray's nearest crossing costs about log(pieces) box tests instead of one test per
//! piece.
//!
//! It finds exactly what testing every shape finds ([`Scene::first_crossing`] and
//! [`Scene::medium_where`], kept as the oracle of its tests), bit for bit: it calls the same
//! piece tests, breaks ties the same way (the lower shape, then the lower edge), and skips only
//! boxes that cannot hold an accepted crossing. That last part is exact, not approximate: a
//! piece accepts a crossing only within its box grown by a margin ([`Bounds::admits`]), a node's
//! box holds its pieces' boxes, and the entry and exit parameters of nested boxes nest in
//! floating point too, because rounding is monotonic.

use glam::DVec2;

use super::Scene;
use super::bounds::{Bounds, padding};
use super::shape::{Crossing, Shape, T_MIN, crosses_rightward};

/// The most intersection tests one trace makes (a ray or a point against a bounding box or a
/// shape's piece, in finding crossings and the media at hits); past it the trace stops and
/// says so ([`crate::Counts::truncated`]), so that no scene can keep the tracer busy for long (about
/// a second at this many on one core).
pub const MAX_TESTS: u64 = 100_000_000;

/// The most pieces in a leaf.
const LEAF: usize = 4;

/// One piece: a shape's edge, or a shape whole.
#[derive(Clone, Copy, Debug)]
struct Item {
    shape: usize,
    piece: usize,
    bounds: Bounds,
}

/// A node: its box and either its pieces (a leaf) or its two children.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Bounds,
    /// The box's largest absolute coordinate, for its margin.
    reach: f64,
    /// A leaf's items: `items[first..first + count]`; `count == 0` for an inner node.
    first: usize,
    count: usize,
    /// An inner node's second child (the first follows the node itself).
    second: usize,
    /// The axis an inner node's children are split along.
    axis: usize,
}

/// The nearest crossing found so far: (t, shape, piece) compared in that order.
#[derive(Clone, Copy, Debug)]
struct Best {
    shape: usize,
    piece: usize,
    crossing: Crossing,
}

impl Best {
    fn beaten_by(self, t: f64, shape: usize, piece: usize) -> bool {
        t.total_cmp(&self.crossing.t)
            .then(shape.cmp(&self.shape))
            .then(piece.cmp(&self.piece))
            .is_lt()
    }
}

/// Keeps the crossing `c` of `shape`'s piece `piece` if it beats `best`.
fn consider(best: &mut Option<Best>, shape: usize, piece: usize, c: Crossing) {
    if best.is_none_or(|b| b.beaten_by(c.t, shape, piece)) {
        *best = Some(Best {
            shape,
            piece,
            crossing: c,
        });
    }
}

/// A hierarchy over a list of boxed items.
#[derive(Debug, Default)]
struct Tree {
    items: Vec<Item>,
    nodes: Vec<Node>,
}

impl Tree {
    fn new(mut items: Vec<Item>) -> Self {
        let mut tree = Self {
            items: Vec::new(),
            nodes: Vec::with_capacity(2 * items.len() / LEAF + 1),
        };
        if !items.is_empty() {
            let count = items.len();
            tree.build(&mut items, 0, count);
        }
        tree.items = items;
        tree
    }

    /// Builds the subtree of `items[first..first + count]` (reordering them) and returns its
    /// position in `nodes`: split at the median of the centres along the wider axis, so that
    /// the depth stays log₂ of the count.
    fn build(&mut self, items: &mut [Item], first: usize, count: usize) -> usize {
        let slice = &mut items[first..first + count];
        let bounds = slice
            .iter()
            .map(|i| i.bounds)
            .reduce(Bounds::union)
            .unwrap_or_else(|| Bounds::point(DVec2::ZERO));
        let at = self.nodes.len();
        self.nodes.push(Node {
            bounds,
            reach: bounds.reach(),
            first,
            count,
            second: 0,
            axis: 0,
        });
        if count <= LEAF {
            return at;
        }
        let centre = |i: &Item, axis: usize| i.bounds.min[axis] + i.bounds.max[axis];
        let spread = slice
            .iter()
            .map(|i| Bounds::point(DVec2::new(centre(i, 0), centre(i, 1))))
            .reduce(Bounds::union)
            .map_or(DVec2::ZERO, |b| b.max - b.min);
        let axis = usize::from(spread.y > spread.x);
        let half = count / 2;
        slice.select_nth_unstable_by(half, |a, b| centre(a, axis).total_cmp(&centre(b, axis)));
        self.build(items, first, half);
        let second = self.build(items, first + half, count - half);
        self.nodes[at] = Node {
            count: 0,
            second,
            axis,
            ..self.nodes[at]
        };
        at
    }

    /// Calls `leaf` on every item under the nodes that `enter` lets in, counting each node and
    /// item in `tests`. `enter` says whether to go into a node and, for an inner node, whether
    /// its second child is to be searched first; it sees the state `leaf` updates.
    fn visit<S>(
        &self,
        stack: &mut Vec<usize>,
        tests: &mut u64,
        state: &mut S,
        enter: impl Fn(&S, &Node) -> Option<bool>,
        mut leaf: impl FnMut(&mut S, Item),
    ) {
        stack.clear();
        if !self.nodes.is_empty() {
            stack.push(0);
        }
        while let Some(at) = stack.pop() {
            let node = &self.nodes[at];
            *tests += 1;
            let Some(second_first) = enter(state, node) else {
                continue;
            };
            if node.count == 0 {
                // Popped last, searched first.
                if second_first {
                    stack.extend([at + 1, node.second]);
                } else {
                    stack.extend([node.second, at + 1]);
                }
                continue;
            }
            for &item in &self.items[node.first..node.first + node.count] {
                *tests += 1;
                leaf(state, item);
            }
        }
    }
}

/// The hierarchies over one scene's shapes, with the scratch space their queries reuse and the
/// count of tests they made (the tracer's measure of work).
pub(crate) struct Bvh<'a> {
    shapes: &'a [Shape],
    /// Every piece with a box: what rays are tested against.
    pieces: Tree,
    /// Every region shape with a box, whole: where a point may be inside.
    regions: Tree,
    /// Shapes without a box (lines), tested by every query.
    unbounded: Vec<usize>,
    stack: Vec<usize>,
    /// The polygons whose box holds the point of a [`Self::medium_where`].
    polygons: Vec<Item>,
    tests: u64,
}

impl<'a> Bvh<'a> {
    /// The hierarchies over `scene`'s shapes.
    pub(crate) fn new(scene: &'a Scene) -> Self {
        let shapes = scene.shapes();
        let mut pieces = Vec::new();
        let mut regions = Vec::new();
        let mut unbounded = Vec::new();
        for (shape, s) in shapes.iter().enumerate() {
            let first = pieces.len();
            for piece in 0..s.piece_count() {
                match s.piece_bounds(piece) {
                    Some(bounds) => pieces.push(Item {
                        shape,
                        piece,
                        bounds,
                    }),
                    None => unbounded.push(shape),
                }
            }
            let whole = pieces[first..]
                .iter()
                .map(|i| i.bounds)
                .reduce(Bounds::union);
            if let Some(bounds) = whole.filter(|_| s.medium().is_some()) {
                regions.push(Item {
                    shape,
                    piece: 0,
                    bounds,
                });
            }
        }
        Self {
            shapes,
            pieces: Tree::new(pieces),
            regions: Tree::new(regions),
            unbounded,
            stack: Vec::new(),
            polygons: Vec::new(),
            tests: 0,
        }
    }

    /// The box and piece tests made so far.
    pub(crate) fn tests(&self) -> u64 {
        self.tests
    }

    /// The first boundary the ray `origin + t·direction` (unit `direction`) crosses at
    /// t > [`T_MIN`]: exactly [`Scene::first_crossing`].
    pub(crate) fn first_crossing(
        &mut self,
        origin: DVec2,
        direction: DVec2,
    ) -> Option<(usize, Crossing)> {
        let mut best: Option<Best> = None;
        for &shape in &self.unbounded {
            self.tests += 1;
            if let Some(c) = self.shapes[shape].piece_crossing(0, origin, direction) {
                consider(&mut best, shape, 0, c);
            }
        }
        let enter = |best: &Option<Best>, node: &Node| {
            let pad = padding(node.reach, origin);
            let (entry, exit) = node.bounds.slab(pad, origin, direction);
            // A tie at `entry` may still be won by a lower shape: skip only what is farther.
            let skip = entry > exit || exit <= T_MIN || best.is_some_and(|b| entry > b.crossing.t);
            (!skip).then_some(direction[node.axis] < 0.0)
        };
        let shapes = self.shapes;
        self.pieces.visit(
            &mut self.stack,
            &mut self.tests,
            &mut best,
            enter,
            |best, item| {
                let shape = &shapes[item.shape];
                if let Some(c) = shape.piece_crossing(item.piece, origin, direction) {
                    consider(best, item.shape, item.piece, c);
                }
            },
        );
        best.map(|b| (b.shape, b.crossing))
    }

    /// Whether `p` is inside the polygon `region` (a [`Self::regions`] item): the even-odd
    /// count of its edges crossing the half-line from `p` towards +x, searched only where that
    /// half-line runs through the polygon's box.
    fn in_polygon(&mut self, region: Item, points: &[DVec2], p: DVec2) -> bool {
        let end = region.bounds.max.x;
        let enter = |_: &bool, node: &Node| {
            let pad = padding(node.reach, p);
            (node.bounds.meets_rightward(pad, p) && node.bounds.min.x - pad <= end).then_some(false)
        };
        let mut inside = false;
        self.pieces.visit(
            &mut self.stack,
            &mut self.tests,
            &mut inside,
            enter,
            |inside, item| {
                if item.shape == region.shape {
                    let (a, b) = (points[item.piece], points[(item.piece + 1) % points.len()]);
                    *inside ^= crosses_rightward(a, b, p);
                }
            },
        );
        inside
    }

    /// The medium at `p`: exactly [`Scene::medium_where`] of `scene` (the scene this was built
    /// for), with `on_boundary` = (shape, inside) deciding that shape's side.
    pub(crate) fn medium_where(
        &mut self,
        scene: &Scene,
        p: DVec2,
        on_boundary: Option<(usize, bool)>,
    ) -> usize {
        let mut top = on_boundary
            .filter(|&(shape, inside)| inside && self.shapes[shape].medium().is_some())
            .map(|(shape, _)| shape);
        let decided = on_boundary.map(|(shape, _)| shape);
        for &shape in &self.unbounded {
            self.tests += 1;
            if Some(shape) != decided && top < Some(shape) && self.shapes[shape].contains(p) {
                top = Some(shape);
            }
        }
        // Discs and lenses are decided as they are found; polygons, whose test is a search of
        // its own, afterwards, topmost first, and only while they could still be on top.
        let mut polygons = core::mem::take(&mut self.polygons);
        polygons.clear();
        let shapes = self.shapes;
        let enter = |_: &(Option<usize>, Vec<Item>), node: &Node| {
            node.bounds
                .holds(padding(node.reach, p), p)
                .then_some(false)
        };
        let mut state = (top, polygons);
        self.regions.visit(
            &mut self.stack,
            &mut self.tests,
            &mut state,
            enter,
            |(top, polygons), item| {
                let holds = item.bounds.holds(padding(item.bounds.reach(), p), p);
                if !holds || Some(item.shape) == decided || *top > Some(item.shape) {
                    return;
                }
                match &shapes[item.shape] {
                    Shape::Polygon { .. } => polygons.push(item),
                    shape if shape.contains(p) => *top = Some(item.shape),
                    _ => {}
                }
            },
        );
        let (mut top, mut polygons) = state;
        polygons.sort_unstable_by_key(|item| core::cmp::Reverse(item.shape));
        for &region in &polygons {
            if top > Some(region.shape) {
                break;
            }
            let Shape::Polygon { points, .. } = &shapes[region.shape] else {
                continue;
            };
            if self.in_polygon(region, points, p) {
                top = Some(region.shape);
                break;
            }
        }
        self.polygons = polygons;
        top.and_then(|s| self.shapes[s].medium())
            .unwrap_or_else(|| scene.background())
    }
}

/// The sign of the turn a → b → c: 1 counter-clockwise, −1 clockwise, 0 in a line.
fn turn(a: DVec2, b: DVec2, c: DVec2) -> i8 {
    let cross = (b - a).perp_dot(c - a);
    if cross > 0.0 {
        1
    } else if cross < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether `p`, in line with `a` and `b`, lies within their box (so on the segment).
fn on_segment(a: DVec2, b: DVec2, p: DVec2) -> bool {
    a.min(b).cmple(p).all() && p.cmple(a.max(b)).all()
}

/// Whether the segments a–b and c–d have a point in common.
fn segments_meet(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let (t1, t2) = (turn(a, b, c), turn(a, b, d));
    let (t3, t4) = (turn(c, d, a), turn(c, d, b));
    (t1 != t2 && t3 != t4)
        || (t1 == 0 && on_segment(a, b, c))
        || (t2 == 0 && on_segment(a, b, d))
        || (t3 == 0 && on_segment(c, d, a))
        || (t4 == 0 && on_segment(c, d, b))
}

/// Whether edges `i` < `j` of the closed polygon `points` meet anywhere but at the vertex that
/// neighbouring edges share (where they meet only if they fold back along each other).
fn edges_meet(points: &[DVec2], i: usize, j: usize) -> bool {
    let n = points.len();
    let edge = |k: usize| (points[k], points[(k + 1) % n]);
    let ((a, b), (c, d)) = (edge(i), edge(j));
    let fold = |shared: DVec2, one: DVec2, other: DVec2| {
        turn(shared, one, other) == 0 && (one - shared).dot(other - shared) > 0.0
    };
    if j == i + 1 {
        fold(b, a, d)
    } else if i == 0 && j == n - 1 {
        fold(a, b, c)
    } else {
        segments_meet(a, b, c, d)
    }
}

/// The first pair of edges (i, j), i < j, j as small as can be, at which the closed polygon
/// `points` crosses or touches itself, if it does: edge k runs from point k to the next. Each
/// edge is tested only against the edges whose boxes overlap its own.
///
/// # Errors
/// The number of tests made, when it passes [`MAX_TESTS`] before an answer (edges whose boxes
/// overlap by the thousand).
pub(crate) fn first_self_crossing(points: &[DVec2]) -> Result<Option<(usize, usize)>, u64> {
    let n = points.len();
    let items: Vec<Item> = (0..n)
        .map(|piece| {
            let (a, b) = (points[piece], points[(piece + 1) % n]);
            Item {
                shape: 0,
                piece,
                bounds: Bounds {
                    min: a.min(b),
                    max: a.max(b),
                },
            }
        })
        .collect();
    let tree = Tree::new(items.clone());
    let (mut stack, mut tests) = (Vec::new(), 0);
    for (j, edge) in items.iter().enumerate() {
        let overlaps =
            |b: &Bounds| b.min.cmple(edge.bounds.max).all() && edge.bounds.min.cmple(b.max).all();
        let mut found = None;
        tree.visit(
            &mut stack,
            &mut tests,
            &mut found,
            |found, node| (found.is_none() && overlaps(&node.bounds)).then_some(false),
            |found, item| {
                if found.is_none()
                    && item.piece < j
                    && overlaps(&item.bounds)
                    && edges_meet(points, item.piece, j)
                {
                    *found = Some((item.piece, j));
                }
            },
        );
        if found.is_some() {
            return Ok(found);
        }
        if tests > MAX_TESTS {
            return Err(MAX_TESTS);
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Effects, Light, Medium, Source, SourceKind};
    use proptest::prelude::*;

    /// A scene of `shapes` in vacuum and glass, with a ray source (only its shapes matter).
    fn scene(shapes: Vec<Shape>) -> Scene {
        let glass = Medium {
            name: "glass".to_owned(),
            dispersion: crate::Dispersion::Constant(1.5),
            absorption: 0.0,
        };
        Scene {
            name: "random".to_owned(),
            title: "random".to_owned(),
            description: String::new(),
            media: vec![Medium::vacuum(), glass],
            background: 0,
            shapes,
            source: Source {
                kind: SourceKind::Ray,
                origin: DVec2::ZERO,
                direction: DVec2::X,
                rays: 1,
                width: 0.0,
                spread_deg: 0.0,
                light: Light::White,
            },
            effects: Effects::default(),
            view: None,
        }
    }

    /// Coordinates on a coarse grid, so that shapes share edges and vertices, rays start on
    /// boundaries and run along axes: the ties and grazing cases where a search could differ.
    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![(-8_i32..=8).prop_map(|i| f64::from(i) * 0.5), -4.0_f64..4.0,]
    }

    fn point() -> impl Strategy<Value = DVec2> {
        (coordinate(), coordinate()).prop_map(|(x, y)| DVec2::new(x, y))
    }

    fn direction() -> impl Strategy<Value = DVec2> {
        prop_oneof![
            Just(DVec2::X),
            Just(-DVec2::Y),
            (0.0_f64..core::f64::consts::TAU).prop_map(DVec2::from_angle),
            (point(), point()).prop_filter_map("distinct", |(a, b)| (b - a).try_normalize()),
        ]
    }

    fn shape() -> impl Strategy<Value = Shape> {
        let medium = 0_usize..2;
        prop_oneof![
            (point(), 0.25_f64..3.0, medium.clone()).prop_map(|(center, radius, medium)| {
                Shape::Circle {
                    center,
                    radius,
                    medium,
                }
            }),
            (prop::collection::vec(point(), 3..40), medium.clone())
                .prop_map(|(points, medium)| Shape::Polygon { points, medium }),
            (point(), direction(), medium.clone()).prop_map(|(point, normal, medium)| {
                Shape::Line {
                    point,
                    normal,
                    medium,
                }
            }),
            (point(), point())
                .prop_filter("a segment has length", |(a, b)| a != b)
                .prop_map(|(from, to)| Shape::Segment { from, to }),
            (point(), 0.5_f64..3.0, 0.5_f64..3.0, 0.05_f64..0.95, medium).prop_map(
                |(center, r1, r2, f, medium)| Shape::Lens {
                    lens: crate::Lens {
                        center,
                        thickness: f * 2.0 * r1.min(r2),
                        radii: [r1, r2],
                    },
                    medium,
                }
            ),
        ]
    }

    fn same(a: Option<(usize, Crossing)>, b: Option<(usize, Crossing)>) -> bool {
        let bits = |c: Option<(usize, Crossing)>| {
            c.map(|(s, c)| (s, c.t.to_bits(), c.normal.x.to_bits(), c.normal.y.to_bits()))
        };
        bits(a) == bits(b)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// From a random start, a ray is followed from crossing to crossing (each next ray
        /// starting on the boundary it just met, turned a random way): at every step the
        /// hierarchy finds bit for bit the crossing and the media that testing every shape finds.
        #[test]
        fn the_hierarchy_finds_what_testing_every_shape_finds(
            mut shapes in prop::collection::vec(shape(), 1..24),
            copies in prop::collection::vec(any::<prop::sample::Index>(), 0..4),
            start in point(),
            turns in prop::collection::vec(direction(), 1..12),
            probes in prop::collection::vec(point(), 8),
        ) {
            // Copies on top tie with their originals everywhere: the lower shape must win.
            let copies: Vec<Shape> = copies.iter().map(|i| i.get(&shapes).clone()).collect();
            shapes.extend(copies);
            let scene = scene(shapes);
            let mut bvh = Bvh::new(&scene);
            for p in probes {
                prop_assert_eq!(bvh.medium_where(&scene, p, None), scene.medium_where(p, None));
            }
            let mut origin = start;
            for d in turns {
                let linear = scene.first_crossing(origin, d);
                let fast = bvh.first_crossing(origin, d);
                prop_assert!(same(linear, fast), "{origin} {d}: {linear:?} vs {fast:?}");
                let Some((shape, crossing)) = linear else { continue };
                origin += d * crossing.t;
                for inside in [false, true] {
                    let on = Some((shape, inside));
                    prop_assert_eq!(
                        bvh.medium_where(&scene, origin, on),
                        scene.medium_where(origin, on)
                    );
                }
            }
        }
    }

    #[test]
    fn a_polygon_that_crosses_or_folds_onto_itself_is_found() {
        let at = |xy: &[(f64, f64)]| {
            xy.iter()
                .map(|&(x, y)| DVec2::new(x, y))
                .collect::<Vec<_>>()
        };
        let square = at(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        assert_eq!(first_self_crossing(&square), Ok(None));
        let bow_tie = at(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        assert_eq!(first_self_crossing(&bow_tie), Ok(Some((0, 2))));
        // Two squares touching at a corner: a figure of eight through (1, 1).
        let touching = at(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (1.0, 1.0),
            (2.0, 1.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (1.0, 1.0),
            (0.0, 1.0),
        ]);
        assert!(first_self_crossing(&touching).unwrap().is_some());
        // A spike folding back along its own edge.
        let spike = at(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 1.0)]);
        assert_eq!(first_self_crossing(&spike), Ok(Some((0, 1))));
        let n = 20_000;
        let round: Vec<DVec2> = (0..n)
            .map(|k| DVec2::from_angle(core::f64::consts::TAU * f64::from(k) / f64::from(n)))
            .collect();
        assert_eq!(first_self_crossing(&round), Ok(None));
    }

    #[test]
    fn many_shapes_cost_few_tests_per_ray() {
        let shapes = (0..10_000)
            .map(|i| Shape::Circle {
                center: DVec2::new(f64::from(i % 100), f64::from(i / 100)),
                radius: 0.3,
                medium: 1,
            })
            .collect();
        let scene = scene(shapes);
        let mut bvh = Bvh::new(&scene);
        let origin = DVec2::new(-1.0, 50.2);
        let hit = bvh.first_crossing(origin, DVec2::X);
        assert!(same(hit, scene.first_crossing(origin, DVec2::X)));
        assert!(hit.is_some());
        assert!(bvh.tests() < 200, "{} tests", bvh.tests());
        let before = bvh.tests();
        assert_eq!(bvh.medium_where(&scene, DVec2::new(50.0, 50.0), None), 1);
        // The half-line to the right meets 50 circles of the row, not 10,000.
        assert!(bvh.tests() - before < 400, "{} tests", bvh.tests() - before);
    }
}
