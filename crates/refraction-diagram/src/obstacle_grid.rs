//! A uniform grid over the placer's obstacles, so that the test of a label's box looks only at
//! the obstacles near it. A scene drawn with a thousand rays gives the placer thousands of
//! obstacles (ray segments, curved faces, hit markers) and a label hunting for a free spot
//! tests hundreds of boxes: scanning every obstacle for every box made the label placement
//! most of a frame's time.
//!
//! Each cell lists its obstacles by [`Crossable`] rank: the solid ones (boxes, discs,
//! arrowheads) first, then the firm shafts, then the lesser ones. A test that may cross some
//! shafts reads only the part of a cell's list it may not cross, and a solid obstacle, large
//! and few, is met before the many rays. The lists sit in one array (a cell's share found by
//! its start), built by a counting sort.

use core::ops::Range;

use glam::Vec2;

use super::buckets;
use super::geometry::Rect;
use super::obstacle::Obstacle;

/// The side of a cell in pixels: about a line of label text, so that a label's box spans a
/// handful of cells.
const CELL: f32 = 32.0;

/// The most cells along either side (a larger drawing gets larger cells).
const MOST_CELLS: usize = 256;

/// What a label's box may cross: each looser than the one before.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Crossable {
    /// No obstacle at all.
    Nothing,
    /// The shafts that are not firm (lesser rays).
    LesserShafts,
    /// Every shaft.
    Shafts,
}

/// The ranks of the obstacles in a cell's list: solid, firm shafts, lesser shafts.
const RANKS: usize = 3;

/// An obstacle's rank: 0 solid, 1 a firm shaft, 2 a lesser one. A box that may cross
/// `Crossable` tests the ranks below [`tested_ranks`] only.
fn rank(obstacle: &Obstacle) -> usize {
    match obstacle {
        Obstacle::Shaft { firm: true, .. } => 1,
        Obstacle::Shaft { firm: false, .. } => 2,
        Obstacle::Box(_) | Obstacle::Disc { .. } | Obstacle::Polygon(_) => 0,
    }
}

/// How many ranks, from the first, a box that may cross `crossable` must stay off.
fn tested_ranks(crossable: Crossable) -> usize {
    match crossable {
        Crossable::Nothing => 3,
        Crossable::LesserShafts => 2,
        Crossable::Shafts => 1,
    }
}

/// The obstacles' indices by the cells their bounding boxes cover.
#[derive(Debug, Default)]
pub(crate) struct ObstacleGrid {
    /// How many obstacles it was built from (the placer rebuilds it when more arrive).
    pub(crate) count: usize,
    origin: Vec2,
    cell: f32,
    columns: usize,
    rows: usize,
    /// Where each (cell, rank) list starts in `entries`, cell by cell, rank by rank, and
    /// one past the last list's end.
    starts: Vec<usize>,
    /// The obstacles, list after list.
    entries: Vec<Entry>,
}

/// An obstacle in a cell's list: its index and a box it lies within there (for a shaft, the
/// box of its part in the cell's row), so that most obstacles far from a label's box are
/// passed over without reading them.
#[derive(Clone, Copy, Debug)]
struct Entry {
    index: u32,
    within: Rect,
}

/// The box an obstacle lies within, a pixel larger all round (a box that touches the obstacle
/// then always shares a cell with it).
fn bounding_box(obstacle: &Obstacle) -> Rect {
    let (min, max) = match obstacle {
        Obstacle::Box(r) => (r.min, r.max),
        Obstacle::Disc { center, radius } => (
            *center - Vec2::splat(*radius),
            *center + Vec2::splat(*radius),
        ),
        Obstacle::Polygon(points) => points.iter().fold(
            (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        ),
        Obstacle::Shaft {
            a, b, half_width, ..
        } => (
            a.min(*b) - Vec2::splat(*half_width),
            a.max(*b) + Vec2::splat(*half_width),
        ),
    };
    Rect {
        min: min - Vec2::ONE,
        max: max + Vec2::ONE,
    }
}

/// Whether both corners of `r` are finite numbers.
fn finite(r: &Rect) -> bool {
    r.min.is_finite() && r.max.is_finite()
}

impl ObstacleGrid {
    /// The grid of `obstacles`: cells of [`CELL`] pixels (larger where the obstacles spread
    /// over more than [`MOST_CELLS`] of them) over the box they lie within.
    pub(crate) fn new(obstacles: &[Obstacle]) -> Self {
        let boxes: Vec<Rect> = obstacles.iter().map(bounding_box).collect();
        let Some((origin, end)) = boxes
            .iter()
            .filter(|r| finite(r))
            .map(|r| (r.min, r.max))
            .reduce(|(lo, hi), (min, max)| (lo.min(min), hi.max(max)))
        else {
            return Self {
                count: obstacles.len(),
                ..Self::default()
            };
        };
        let span = (end - origin).max_element();
        let cell = CELL.max(span / MOST_CELLS as f32);
        let count_along = |length: f32| ((length / cell).floor() as usize + 1).min(MOST_CELLS);
        let (columns, rows) = (count_along(end.x - origin.x), count_along(end.y - origin.y));
        let mut grid = Self {
            count: obstacles.len(),
            origin,
            cell,
            columns,
            rows,
            starts: Vec::new(),
            entries: Vec::new(),
        };
        // Each (list, obstacle) pair in the obstacles' order, then sorted by list (counting,
        // so that a list keeps that order).
        let mut pairs: Vec<(u32, Entry)> = Vec::new();
        for (index, (obstacle, r)) in obstacles.iter().zip(&boxes).enumerate() {
            if !finite(r) {
                continue;
            }
            let index = u32::try_from(index).unwrap_or(u32::MAX);
            let rank = rank(obstacle);
            grid.for_each_cell_of(obstacle, r, |column, row, within| {
                let list = (row * columns + column) * RANKS + rank;
                let list = u32::try_from(list).unwrap_or(u32::MAX);
                pairs.push((list, Entry { index, within }));
            });
        }
        grid.sort_into_lists(&pairs);
        grid
    }

    /// Calls `cell` with each cell (column, row) `obstacle` (within `r`, its bounding box)
    /// may touch, and a box the obstacle lies within there: every cell under `r` with `r`,
    /// but for a shaft only the columns its line passes in each row (a long diagonal ray's
    /// box covers many cells it never crosses), with the box of its part in that row.
    fn for_each_cell_of(
        &self,
        obstacle: &Obstacle,
        r: &Rect,
        mut cell: impl FnMut(usize, usize, Rect),
    ) {
        let Obstacle::Shaft {
            a, b, half_width, ..
        } = obstacle
        else {
            self.cells_under(r)
                .for_each(|(column, row)| cell(column, row, *r));
            return;
        };
        let (a, b, reach) = (*a, *b, *half_width + 1.0);
        for row in self.along(r.min.y, r.max.y, self.origin.y, self.rows) {
            let slab = self.cell_rect(0, row);
            let (y0, y1) = (slab.min.y - reach, slab.max.y + reach);
            // Where along a–b the line is within the row's reach, and the x it spans there.
            let dy = b.y - a.y;
            let (t0, t1) = if dy.abs() < f32::EPSILON {
                (0.0, 1.0)
            } else {
                let (s0, s1) = ((y0 - a.y) / dy, (y1 - a.y) / dy);
                (s0.min(s1).max(0.0), s0.max(s1).min(1.0))
            };
            if t0 > t1 {
                continue;
            }
            let (x0, x1) = (a.x + (b.x - a.x) * t0, a.x + (b.x - a.x) * t1);
            let (lo, hi) = (x0.min(x1) - reach, x0.max(x1) + reach);
            let within = Rect {
                min: Vec2::new(lo, y0),
                max: Vec2::new(hi, y1),
            };
            for column in self.along(lo, hi, self.origin.x, self.columns) {
                cell(column, row, within);
            }
        }
    }

    /// Fills `starts` and `entries` from (list, obstacle) pairs, keeping each list's
    /// obstacles in the order given.
    fn sort_into_lists(&mut self, pairs: &[(u32, Entry)]) {
        let lists = self.columns * self.rows * RANKS;
        (self.entries, self.starts) = buckets::sorted(
            pairs,
            lists,
            |&(list, _)| list as usize,
            |&(_, entry)| entry,
        );
    }

    /// The cell's own box, grown by a pixel (so that an obstacle on its border is in it).
    fn cell_rect(&self, column: usize, row: usize) -> Rect {
        let min = self.origin + Vec2::new(column as f32, row as f32) * self.cell;
        Rect {
            min: min - Vec2::ONE,
            max: min + Vec2::splat(self.cell) + Vec2::ONE,
        }
    }

    /// The cells along one axis (of `count` cells from `origin`) that `lo..=hi` overlaps,
    /// clamped to the grid: an interval beyond its edge gets the edge's cell, which is more
    /// than it needs and never less.
    fn along(&self, lo: f32, hi: f32, origin: f32, count: usize) -> Range<usize> {
        if count == 0 {
            return 0..0;
        }
        // The cast truncates, which is the floor for what is not negative (and 0 for NaN).
        let cell_of = |v: f32| (((v - origin) / self.cell).max(0.0) as usize).min(count - 1);
        cell_of(lo)..cell_of(hi) + 1
    }

    /// The cells (column, row) that `r` overlaps, clamped to the grid.
    fn cells_under(&self, r: &Rect) -> impl Iterator<Item = (usize, usize)> + use<> {
        let columns = self.along(r.min.x, r.max.x, self.origin.x, self.columns);
        let rows = self.along(r.min.y, r.max.y, self.origin.y, self.rows);
        rows.flat_map(move |row| columns.clone().map(move |column| (column, row)))
    }

    /// Whether `touched` holds for any obstacle that may touch `r` and that a box which may
    /// cross `crossable` must stay off. Every such one that does touch it is asked about (some
    /// more than once), the solid ones of each cell first; most that do not are not asked.
    pub(crate) fn any_near(
        &self,
        r: &Rect,
        crossable: Crossable,
        mut touched: impl FnMut(usize) -> bool,
    ) -> bool {
        let ranks = tested_ranks(crossable);
        let columns = self.along(r.min.x, r.max.x, self.origin.x, self.columns);
        for row in self.along(r.min.y, r.max.y, self.origin.y, self.rows) {
            for column in columns.clone() {
                let list = (row * self.columns + column) * RANKS;
                let (from, to) = (self.starts[list], self.starts[list + ranks]);
                for entry in &self.entries[from..to] {
                    let within = &entry.within;
                    let apart = within.max.cmplt(r.min).any() || r.max.cmplt(within.min).any();
                    if !apart && touched(entry.index as usize) {
                        return true;
                    }
                }
            }
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn obstacle() -> impl Strategy<Value = Obstacle> {
        let point = || (-50.0_f32..1300.0, -50.0_f32..800.0).prop_map(|(x, y)| Vec2::new(x, y));
        prop_oneof![
            (point(), 1.0_f32..80.0).prop_map(|(c, h)| Obstacle::Box(Rect::around(c, h))),
            (point(), 0.5_f32..20.0).prop_map(|(center, radius)| Obstacle::Disc { center, radius }),
            (point(), point(), 0.5_f32..4.0, any::<bool>()).prop_map(|(a, b, half_width, firm)| {
                Obstacle::Shaft {
                    a,
                    b,
                    half_width,
                    firm,
                }
            }),
            (point(), 2.0_f32..30.0).prop_map(|(c, s)| Obstacle::Polygon(vec![
                c,
                c + Vec2::new(s, 0.0),
                c + Vec2::new(0.0, s)
            ])),
        ]
    }

    /// The obstacles [`ObstacleGrid::any_near`] asks about, in the order it asks.
    fn near(grid: &ObstacleGrid, r: &Rect, crossable: Crossable) -> Vec<usize> {
        let mut asked = Vec::new();
        grid.any_near(r, crossable, |i| {
            asked.push(i);
            false
        });
        asked
    }

    proptest! {
        #[test]
        fn every_obstacle_a_box_touches_is_near_it(
            obstacles in prop::collection::vec(obstacle(), 0..300),
            boxes in prop::collection::vec((-100.0_f32..1400.0, -100.0_f32..900.0, 1.0_f32..200.0, 1.0_f32..60.0), 1..40),
        ) {
            let grid = ObstacleGrid::new(&obstacles);
            for (x, y, w, h) in boxes {
                let r = Rect::from_min_size(Vec2::new(x, y), Vec2::new(w, h));
                for crossable in [Crossable::Nothing, Crossable::LesserShafts, Crossable::Shafts] {
                    let near = near(&grid, &r, crossable);
                    for (i, o) in obstacles.iter().enumerate() {
                        let crossed = match o {
                            Obstacle::Shaft { firm, .. } => {
                                crossable == Crossable::Shafts
                                    || (crossable == Crossable::LesserShafts && !firm)
                            }
                            _ => false,
                        };
                        if crossed {
                            prop_assert!(!near.contains(&i), "{o:?} may be crossed");
                        } else if o.touches(&r) {
                            prop_assert!(near.contains(&i), "{o:?} touches {r:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn a_box_far_from_an_obstacle_has_few_near_and_a_vast_drawing_keeps_few_cells() {
        let shaft = Obstacle::Shaft {
            a: Vec2::ZERO,
            b: Vec2::new(1.0e6, 1.0e6),
            half_width: 1.0,
            firm: true,
        };
        let grid = ObstacleGrid::new(&[shaft]);
        assert!(grid.columns <= MOST_CELLS && grid.rows <= MOST_CELLS);
        let far = Rect::from_min_size(Vec2::new(9.0e5, 0.0), Vec2::splat(50.0));
        assert_eq!(
            near(&grid, &far, Crossable::Nothing).len(),
            0,
            "a cell the diagonal never crosses"
        );
        let on = Rect::from_min_size(Vec2::splat(5.0e5), Vec2::splat(50.0));
        assert!(!near(&grid, &on, Crossable::Nothing).is_empty());
        assert_eq!(
            near(&ObstacleGrid::new(&[]), &on, Crossable::Nothing).len(),
            0
        );
    }

    #[test]
    fn a_cell_lists_its_solid_obstacles_before_its_rays() {
        let ray = |firm| Obstacle::Shaft {
            a: Vec2::new(0.0, 10.0),
            b: Vec2::new(100.0, 10.0),
            half_width: 1.0,
            firm,
        };
        let banner = Obstacle::Box(Rect::from_min_size(Vec2::ZERO, Vec2::splat(100.0)));
        let grid = ObstacleGrid::new(&[ray(false), ray(true), banner]);
        let r = Rect::from_min_size(Vec2::new(5.0, 5.0), Vec2::splat(10.0));
        assert_eq!(near(&grid, &r, Crossable::Nothing), [2, 1, 0]);
        assert_eq!(near(&grid, &r, Crossable::LesserShafts), [2, 1]);
        assert_eq!(near(&grid, &r, Crossable::Shafts), [2]);
    }
}
