//! The placer's search for a label's spot anywhere in its bounds, the fallback of a label that
//! must be shown when no ring around its anchor is free: a lattice of anchors a step apart
//! over the bounds (a step is 0.6 of the label's size), tried nearest the label's anchor first,
//! for each shape of its text ([`Shape`]). A drawing holds some thousands of them, and where no
//! spot is free every one would be tried, for each shape and each kind of spot. So the squares
//! between the lattice's points are asked first whether an obstacle touches them
//! ([`Squares`]): a spot whose box holds a touched square is not free, and only the others
//! are sorted and tried.

use glam::Vec2;

use super::buckets;
use super::geometry::Rect;
use super::shapes::{LABEL_PAD, Label};

/// The lattice over `bounds` for a label of `size`: its step and how many steps it spans
/// along each side.
fn lattice(bounds: &Rect, size: f32) -> (f32, usize, usize) {
    let step = size * 0.6;
    let span = bounds.max - bounds.min;
    (step, (span.x / step) as usize, (span.y / step) as usize)
}

/// A label in one shape of its text, and where it may go anywhere in its bounds.
pub(crate) struct Shape {
    /// The label in this shape.
    pub(crate) label: Label,
    /// The text's extent.
    extent: Vec2,
}

impl Shape {
    /// `label`, whose text measures `extent`.
    pub(crate) fn new(label: Label, extent: Vec2) -> Self {
        Self { label, extent }
    }

    /// The anchors of the lattice over `bounds` whose boxes lie inside `bounds` and hold no
    /// square `squares` knows to be touched, nearest the label's anchor first (ties in the
    /// lattice's order, row after row), each with its box. The anchors are placed so that
    /// each box's corner lies on a lattice point.
    pub(crate) fn spots(&self, bounds: &Rect, squares: &Squares) -> Vec<(Vec2, Rect)> {
        let label = &self.label;
        let (step, columns, rows) = lattice(bounds, label.size);
        let side = self.extent + Vec2::splat(2.0 * label.size * LABEL_PAD);
        let whole = ((side - Vec2::splat(0.01)) / step).max(Vec2::ZERO);
        let whole = (whole.x as usize, whole.y as usize);
        let offset = Vec2::splat(label.size * LABEL_PAD)
            + self.extent * Vec2::new(label.h.fraction(), label.v.fraction());
        let anchor = |(column, row): (usize, usize)| {
            bounds.min + Vec2::new(column as f32, row as f32) * step + offset
        };
        // The key is the distance's bits (ordered as the distance is, for what is not
        // negative) above the index.
        let mut keys: Vec<u64> = (0..=rows)
            .flat_map(|row| (0..=columns).map(move |column| (column, row)))
            .enumerate()
            .filter(|&(_, corner)| !squares.covered(corner, whole))
            .filter_map(|(i, corner)| {
                let at = anchor(corner);
                // Measured from the anchor, so that what is checked is exactly what a
                // reader of the label's anchor computes.
                let r = label.boxed(self.extent, at);
                let inside = r.min.cmpge(bounds.min).all() && r.max.cmple(bounds.max).all();
                let distance = at.distance(label.at);
                inside.then_some((u64::from(distance.to_bits()) << 32) | i as u64)
            })
            .collect();
        sort_keys_by_steps(&mut keys, step / 16.0, (columns + rows + 2) * 16);
        keys.into_iter()
            .map(|key| {
                let i = key as u32 as usize;
                let at = anchor((i % (columns + 1), i / (columns + 1)));
                (at, label.boxed(self.extent, at))
            })
            .collect()
    }
}

/// Sorts `keys` (a distance's bits above an index): by whole `step`s of distance first (a
/// counting sort, the steps from `most_steps` on as one), then each step's few by their keys.
/// The order of one sort of them all, in a fraction of the time for the thousands of spots of
/// a drawing.
fn sort_keys_by_steps(keys: &mut Vec<u64>, step: f32, most_steps: usize) {
    let steps_of = |key: u64| {
        let distance = f32::from_bits((key >> 32) as u32);
        // The cast truncates (NaN to 0): every key's bucket is no less than an earlier one's.
        ((distance / step) as usize).min(most_steps)
    };
    let (mut sorted, starts) =
        buckets::sorted(keys, most_steps + 1, |&key| steps_of(key), |&key| key);
    for bucket in starts.windows(2) {
        sorted[bucket[0]..bucket[1]].sort_unstable();
    }
    *keys = sorted;
}

/// The squares between the lattice's points over a label's bounds that an obstacle touches
/// (for one kind of spot), counted so that whether a box holds any is four looks: a box that
/// holds a touched square is not free.
pub(crate) struct Squares {
    columns: usize,
    rows: usize,
    /// How many touched squares lie above and left of each lattice point, row after row.
    sums: Vec<u32>,
}

impl Squares {
    /// The squares of the lattice over `bounds` for a label of `size`, each asked of
    /// `touched` (whether an obstacle touches a box), spared a hundredth of a pixel inside so
    /// that a square lies inside every box that holds it, rounding and all.
    pub(crate) fn new(bounds: &Rect, size: f32, touched: impl Fn(&Rect) -> bool) -> Self {
        let (step, columns, rows) = lattice(bounds, size);
        let width = columns + 1;
        let mut sums = vec![0_u32; width * (rows + 1)];
        for row in 0..rows {
            let mut across = 0;
            for column in 0..columns {
                let min = bounds.min + Vec2::new(column as f32, row as f32) * step;
                let square = Rect {
                    min: min + Vec2::splat(0.01),
                    max: min + Vec2::splat(step - 0.01),
                };
                across += u32::from(touched(&square));
                sums[(row + 1) * width + column + 1] = sums[row * width + column + 1] + across;
            }
        }
        Self {
            columns,
            rows,
            sums,
        }
    }

    /// Whether the box with its corner at the lattice point `corner` and holding `whole`
    /// squares along each side holds a touched square (false says nothing of the rest of it).
    pub(crate) fn covered(
        &self,
        (column, row): (usize, usize),
        (across, down): (usize, usize),
    ) -> bool {
        let (right, bottom) = (
            (column + across).min(self.columns),
            (row + down).min(self.rows),
        );
        if right <= column || bottom <= row {
            return false;
        }
        let width = self.columns + 1;
        let sum = |column: usize, row: usize| self.sums[row * width + column];
        sum(right, bottom) + sum(column, row) > sum(column, bottom) + sum(right, row)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_sorted_by_steps_are_in_the_order_of_one_sort() {
        let mut seed = 7_u64;
        let mut keys: Vec<u64> = (0..5000_u64)
            .map(|i| {
                seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                let distance = (seed >> 40) as f32 / 64.0;
                (u64::from(distance.to_bits()) << 32) | i
            })
            .chain([u64::from(f32::INFINITY.to_bits()) << 32])
            .collect();
        let mut once = keys.clone();
        once.sort_unstable();
        sort_keys_by_steps(&mut keys, 9.0, 40);
        assert_eq!(keys, once);
    }

    #[test]
    fn a_box_is_covered_where_it_holds_a_touched_square() {
        let bounds = Rect::from_min_size(Vec2::ZERO, Vec2::splat(100.0));
        // Steps of 6 pixels; one obstacle in the square from (30, 30) to (36, 36).
        let touched =
            |r: &Rect| r.min.x < 33.0 && r.max.x > 33.0 && r.min.y < 33.0 && r.max.y > 33.0;
        let squares = Squares::new(&bounds, 10.0, touched);
        assert!(squares.covered((5, 5), (1, 1)));
        assert!(squares.covered((3, 4), (3, 2)));
        assert!(!squares.covered((6, 5), (3, 3)), "it lies left of the box");
        assert!(
            !squares.covered((0, 0), (5, 5)),
            "it lies right of and below the box"
        );
        assert!(
            !squares.covered((5, 5), (0, 4)),
            "a box narrower than a square holds none"
        );
    }
}
