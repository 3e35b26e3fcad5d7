//! A uniform grid over the placer's obstacles, so that the test of a label's box looks only at
//! the obstacles near it. A scene drawn with a thousand rays gives the placer thousands of
//! obstacles (ray segments, curved faces, hit markers) and a label hunting for a free spot
//! tests hundreds of boxes: scanning every obstacle for every box made the label placement
//! most of a frame's time.

use glam::Vec2;

use super::geometry::Rect;
use super::placer::Obstacle;

/// The side of a cell in pixels: about a line of label text, so that a label's box spans a
/// handful of cells.
const CELL: f32 = 32.0;

/// The most cells along either side (a larger drawing gets larger cells).
const MOST_CELLS: usize = 256;

/// The obstacles' indices by the cells their bounding boxes cover.
#[derive(Debug, Default)]
pub(crate) struct ObstacleGrid {
    /// How many obstacles it was built from (the placer rebuilds it when more arrive).
    pub(crate) count: usize,
    origin: Vec2,
    cell: f32,
    columns: usize,
    rows: usize,
    cells: Vec<Vec<u32>>,
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

impl ObstacleGrid {
    /// The grid of `obstacles`: cells of [`CELL`] pixels (larger where the obstacles spread
    /// over more than [`MOST_CELLS`] of them) over the box they lie within.
    pub(crate) fn new(obstacles: &[Obstacle]) -> Self {
        let boxes: Vec<Rect> = obstacles.iter().map(bounding_box).collect();
        let finite = |r: &&Rect| r.min.is_finite() && r.max.is_finite();
        let Some((origin, end)) = boxes
            .iter()
            .filter(finite)
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
            cells: vec![Vec::new(); columns * rows],
        };
        for (index, (obstacle, r)) in obstacles.iter().zip(&boxes).enumerate() {
            if !finite(&r) {
                continue;
            }
            let index = u32::try_from(index).unwrap_or(u32::MAX);
            let long_shaft = matches!(obstacle, Obstacle::Shaft { .. });
            for (column, row) in grid.cells_under(r) {
                // A long diagonal ray's box covers many cells it never crosses.
                if long_shaft && !obstacle.touches(&grid.cell_rect(column, row)) {
                    continue;
                }
                grid.cells[row * columns + column].push(index);
            }
        }
        grid
    }

    /// The cell's own box, grown by a pixel (so that an obstacle on its border is in it).
    fn cell_rect(&self, column: usize, row: usize) -> Rect {
        let min = self.origin + Vec2::new(column as f32, row as f32) * self.cell;
        Rect {
            min: min - Vec2::ONE,
            max: min + Vec2::splat(self.cell) + Vec2::ONE,
        }
    }

    /// The cells (column, row) that `r` overlaps, clamped to the grid: a box beyond its edge
    /// gets the edge's cells, which is more than it needs and never less.
    fn cells_under(&self, r: &Rect) -> impl Iterator<Item = (usize, usize)> + use<> {
        let last = Vec2::new(self.columns as f32 - 1.0, self.rows as f32 - 1.0);
        let cell_of = |p: Vec2| {
            ((p - self.origin) / self.cell)
                .floor()
                .clamp(Vec2::ZERO, last)
        };
        let (lo, hi) = (cell_of(r.min), cell_of(r.max));
        let (columns, rows) = if self.cells.is_empty() {
            (0..0, 0..0)
        } else {
            (
                lo.x as usize..hi.x as usize + 1,
                lo.y as usize..hi.y as usize + 1,
            )
        };
        rows.flat_map(move |row| columns.clone().map(move |column| (column, row)))
    }

    /// The indices of the obstacles that may touch `r` (some more than once): every one that
    /// does is among them.
    pub(crate) fn near<'g>(&'g self, r: &Rect) -> impl Iterator<Item = usize> + 'g {
        self.cells_under(r).flat_map(move |(column, row)| {
            self.cells[row * self.columns + column]
                .iter()
                .map(|&i| i as usize)
        })
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
            (point(), point(), 0.5_f32..4.0).prop_map(|(a, b, half_width)| Obstacle::Shaft {
                a,
                b,
                half_width,
                firm: false,
            }),
            (point(), 2.0_f32..30.0).prop_map(|(c, s)| Obstacle::Polygon(vec![
                c,
                c + Vec2::new(s, 0.0),
                c + Vec2::new(0.0, s)
            ])),
        ]
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
                let near: std::collections::BTreeSet<usize> = grid.near(&r).collect();
                for (i, o) in obstacles.iter().enumerate() {
                    if o.touches(&r) {
                        prop_assert!(near.contains(&i), "{o:?} touches {r:?}");
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
            grid.near(&far).count(),
            0,
            "a cell the diagonal never crosses"
        );
        let on = Rect::from_min_size(Vec2::splat(5.0e5), Vec2::splat(50.0));
        assert!(grid.near(&on).count() > 0);
        assert_eq!(ObstacleGrid::new(&[]).near(&on).count(), 0);
    }
}
