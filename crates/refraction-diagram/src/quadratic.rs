//! The paper's quadratic in b (eq. 20), whose roots merge and vanish at the critical angle.

use glam::Vec2;
use refraction_kernel::Refraction;

use super::geometry::Rect;
use super::palette::Palette;
use super::plot::{Axis, Chart};
use super::shapes::{Dash, Figure, Primitive, Stroke, lower_all};

/// b² + 2·a·wn·b + a² − 1 = 0 for the convention's chosen a = ±μ (Section 1:
/// μ² − 2μ·b·wn + b² = 1; Section 2: μ² + 2μ·b·wn + b² = 1).
#[derive(Clone, Debug, PartialEq)]
pub struct Quadratic {
    /// The chosen weight of W (−μ in Section 1, +μ in Section 2).
    pub a: f64,
    /// wn = Ŵ·N̂.
    pub wn: f64,
    /// The kernel's roots: the chosen b and the other root, or none on total internal
    /// reflection.
    pub roots: Vec<f64>,
}

impl Quadratic {
    /// The quadratic of a refraction, with the kernel's roots.
    #[must_use]
    pub fn of(r: &Refraction<f64>) -> Self {
        let a = r.convention.travel_sign::<f64>() * r.mu;
        Self {
            a,
            wn: r.wn(),
            roots: r
                .candidates
                .iter()
                .filter(|c| c.a == a)
                .map(|c| c.b)
                .collect(),
        }
    }

    /// The left-hand side at `b`.
    #[must_use]
    pub fn value(&self, b: f64) -> f64 {
        b * b + 2.0 * self.a * self.wn * b + self.a * self.a - 1.0
    }

    /// The b of the vertex, halfway between the roots.
    #[must_use]
    pub fn vertex(&self) -> f64 {
        -self.a * self.wn
    }

    /// The b and value ranges to plot: both roots (or, with none, the vertex) and the
    /// parabola's minimum with room around them, and the zero line always in view.
    #[must_use]
    pub fn window(&self) -> ((f64, f64), (f64, f64)) {
        let vertex = self.vertex();
        let (low, high) = self
            .roots
            .iter()
            .fold((vertex, vertex), |(lo, hi), b| (lo.min(*b), hi.max(*b)));
        let half = ((high - low) * 0.5 + 0.6).max(1.0);
        let middle = (low + high) * 0.5;
        let bottom = self.value(vertex).min(0.0);
        let top = self.value(middle + half).max(0.5);
        let room = (top - bottom) * 0.08;
        ((middle - half, middle + half), (bottom - room, top + room))
    }

    /// `count` points (b, value) evenly over vertex ± `half_width`.
    #[must_use]
    pub fn samples(&self, half_width: f64, count: usize) -> Vec<[f64; 2]> {
        let count = count.max(2);
        (0..count)
            .map(|i| {
                let b =
                    self.vertex() - half_width + 2.0 * half_width * i as f64 / (count - 1) as f64;
                [b, self.value(b)]
            })
            .collect()
    }
}

/// The parabola of `q` on a canvas of `size` with text `text` pixels high, in `palette`'s
/// colours: the zero line, the curve over its window and the kernel's roots on it.
#[must_use]
pub fn quadratic_plot(q: &Quadratic, size: Vec2, text: f32, palette: &Palette) -> Vec<Primitive> {
    let ((x0, x1), (y0, y1)) = q.window();
    let rows = (size.y / (text * 2.2)).floor().clamp(1.0, 5.0) as usize;
    let chart = Chart {
        area: Rect {
            min: Vec2::new(text * 3.0, text * 0.7),
            max: Vec2::new(size.x - text * 0.8, size.y - text * 1.6),
        },
        x: Axis::covering(x0, x1, 5),
        y: Axis::covering(y0, y1, rows),
        text,
    };
    let mut figures = vec![Figure::Fill {
        points: Rect::from_min_size(Vec2::ZERO, size).corners().to_vec(),
        colour: palette.background,
    }];
    figures.extend(chart.axes(("", ""), palette));
    let stroke = |width, colour| Stroke {
        width,
        colour,
        dash: Dash::Solid,
    };
    let zero = vec![chart.at(chart.x.min, 0.0), chart.at(chart.x.max, 0.0)];
    figures.push(Figure::Line {
        points: zero,
        stroke: stroke(1.5, palette.guide),
    });
    let (left, right) = (chart.x.min, chart.x.max);
    let curve = q
        .samples((right - left) * 0.5, 161)
        .into_iter()
        .filter(|[b, v]| (left..=right).contains(b) && (chart.y.min..=chart.y.max).contains(v))
        .map(|[b, v]| chart.at(b, v))
        .collect();
    figures.push(Figure::Line {
        points: curve,
        stroke: stroke(2.0, palette.t),
    });
    for b in &q.roots {
        figures.push(Figure::Disc {
            center: chart.at(*b, 0.0),
            radius: text * 0.35,
            fill: palette.warning,
            outline: stroke(1.0, palette.background),
        });
    }
    lower_all(&figures)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_window_shows_both_roots_or_the_vertex() {
        use glam::DVec3;
        use refraction_kernel::{Convention, Incidence, refract};
        for (n, mu_i, mu_t) in [
            (DVec3::Y, 1.0, 1.5),
            (DVec3::NEG_Y, 1.0, 1.5),
            (DVec3::Y, 1.5, 1.0),
            (DVec3::Y, 1.0, 2.417),
        ] {
            let w = DVec3::new(0.7, -0.7, 0.0);
            let r = refract(&Incidence {
                w,
                n,
                mu_i,
                mu_t,
                convention: Convention::AlongRay,
            })
            .unwrap();
            let q = Quadratic::of(&r);
            let ((x0, x1), (y0, y1)) = q.window();
            for b in q.roots.iter().chain([&q.vertex()]) {
                assert!(x0 < *b && *b < x1, "{b} outside {x0}..{x1}");
            }
            let v = q.value(q.vertex());
            assert!(y0 < v.min(0.0) && y1 > 0.0, "{y0}..{y1}");
        }
    }
    use refraction_kernel::Convention;
    use refraction_model::{ExplorerState, HandleId};

    #[test]
    fn the_kernel_roots_are_roots_and_vanish_past_the_critical_angle() {
        let mut state = ExplorerState::default();
        for convention in [Convention::AlongRay, Convention::TowardOrigin] {
            state.set_convention(convention);
            let q = Quadratic::of(state.refraction());
            assert_eq!(q.roots.len(), 2);
            for b in &q.roots {
                assert!(q.value(*b).abs() < 1e-12);
            }
            assert!((q.value(q.vertex()) + state.refraction().k).abs() < 1e-12);
        }
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.rotate(HandleId::W, 30.0);
        let q = Quadratic::of(state.refraction());
        assert!(q.roots.is_empty() && q.value(q.vertex()) > 0.0);
        assert_eq!(q.samples(1.0, 5).len(), 5);
    }
}
