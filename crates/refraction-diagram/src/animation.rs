//! Animations for a slide: the frames of the μ → 1 morph, of a sweep of the angle of incidence
//! through the critical angle, and of the moving wavefronts, each as the state (and the
//! wavefront phase) of one frame, drawn like any other diagram.

use glam::{DVec2, Vec2};

use refraction_i18n::t;

use super::overlay::Overlay;
use super::picture::Diagram;
use super::shapes::Primitive;
use super::wavefronts::WaveOptions;
use refraction_model::{ExplorerState, HandleId};

/// The frames an animation has when none are asked for.
pub const ANIMATION_FRAMES: usize = 36;
/// The frames per second when none are asked for.
pub const ANIMATION_FPS: u32 = 12;

/// The largest angle of incidence the sweep reaches, in degrees: grazing, but not so exactly
/// that rounding decides which side the ray is on.
const SWEEP_END_DEG: f64 = 89.5;

/// Smoothstep: starts and ends gently, so the class sees both ends of a morph.
#[must_use]
pub(crate) fn ease(s: f32) -> f32 {
    let s = if s.is_nan() { 0.0 } else { s.clamp(0.0, 1.0) };
    s * s * (3.0 - 2.0 * s)
}

/// An animation the `render --animate` command and *Export animation* write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Animation {
    /// `μ_t` moves to `μ_i`, so that μ → 1 and T turns into W: why the paper picks its signs.
    Mu,
    /// W swings from normal incidence to grazing; from the denser medium, so that total
    /// internal reflection appears on the way, at the critical angle.
    Sweep,
    /// The wavefronts move at c/μ in each medium, one period, looping.
    Wavefronts,
}

impl Animation {
    /// Every animation, in the order of the menus.
    pub const ALL: [Self; 3] = [Self::Mu, Self::Sweep, Self::Wavefronts];

    /// The name used on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Mu => "mu",
            Self::Sweep => "sweep",
            Self::Wavefronts => "wavefronts",
        }
    }

    /// The animation of a command-line name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|a| a.name() == name)
    }

    /// What it shows, for a menu, in the current language.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::Mu => t!("diagram-animation-mu"),
            Self::Sweep => t!("diagram-animation-sweep"),
            Self::Wavefronts => t!("diagram-animation-wavefronts"),
        }
    }

    /// Frame `index` of `count` (at least 1) starting from `start`.
    #[must_use]
    pub fn frame(self, start: &ExplorerState, index: usize, count: usize) -> AnimationFrame {
        let last = count.max(2) - 1;
        let s = index.min(last) as f64 / last as f64;
        match self {
            Self::Mu => {
                let mut state = start.clone();
                let eased = f64::from(ease(s as f32));
                let mu_t = start.mu_t() + (start.mu_i() - start.mu_t()) * eased;
                // Between two accepted indices every index is accepted.
                state
                    .set_mu_t(if index >= last { start.mu_i() } else { mu_t })
                    .ok();
                AnimationFrame { state, waves: None }
            }
            Self::Sweep => AnimationFrame {
                state: swept(start, s * SWEEP_END_DEG),
                waves: None,
            },
            Self::Wavefronts => AnimationFrame {
                state: start.clone(),
                waves: Some(WaveOptions {
                    // `count` frames over one period: the frame after the last is the first.
                    phase: index as f64 / count.max(1) as f64,
                    huygens: false,
                }),
            },
        }
    }
}

/// `start` with the ray from the denser of its two media, meeting the surface at `degrees`
/// from the normal on the side it comes from now.
fn swept(start: &ExplorerState, degrees: f64) -> ExplorerState {
    let mut state = start.clone();
    let (dense, thin) = if start.mu_i() >= start.mu_t() {
        (start.mu_i(), start.mu_t())
    } else {
        (start.mu_t(), start.mu_i())
    };
    // Both were accepted as they are; swapping them keeps them acceptable.
    state.set_mu_i(dense).ok();
    state.set_mu_t(thin).ok();
    let r = state.refraction();
    let toward_source = state.plane().project(-r.travel);
    let normal = state
        .plane()
        .project(r.facing_normal)
        .normalize_or(DVec2::Y);
    let side = if normal.perp_dot(toward_source) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let toward_source = DVec2::from_angle(side * degrees.to_radians()).rotate(normal);
    let sign = state.convention().travel_sign::<f64>();
    state.point(HandleId::W, -toward_source * sign);
    state
}

/// One frame: the state drawn and, for the wavefronts, where they are.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimationFrame {
    /// The state of this frame.
    pub state: ExplorerState,
    /// The wavefronts drawn, if any.
    pub waves: Option<WaveOptions>,
}

impl AnimationFrame {
    /// The frame drawn on a canvas of `size` with `overlay`, back to front: the diagram with
    /// this frame's wavefronts (if any, else the overlay's) over the media and under
    /// everything else; Huygens's construction is drawn when the overlay asks for it.
    #[must_use]
    pub fn primitives(&self, size: Vec2, overlay: &Overlay) -> Vec<Primitive> {
        let huygens = overlay.waves.is_some_and(|w| w.huygens);
        let waves = self.waves.map(|w| WaveOptions {
            huygens: w.huygens || huygens,
            ..w
        });
        let overlay = Overlay {
            waves: waves.or(overlay.waves),
            ..overlay.clone()
        };
        Diagram::with_overlay(&self.state, size, &overlay).primitives()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_ones_are_refused() {
        for a in Animation::ALL {
            assert_eq!(Animation::from_name(a.name()), Some(a));
        }
        assert_eq!(Animation::from_name("spin"), None);
    }

    #[test]
    fn the_mu_morph_ends_at_mu_one_with_t_equal_to_w() {
        let start = ExplorerState::default();
        assert_ne!(start.mu_i(), start.mu_t());
        let last = Animation::Mu.frame(&start, 23, 24).state;
        assert_eq!(last.refraction().mu, 1.0);
        assert_eq!(last.refraction().t(), Some(last.refraction().travel));
        let first = Animation::Mu.frame(&start, 0, 24).state;
        assert_eq!(first.mu_t(), start.mu_t());
    }

    #[test]
    fn the_sweep_goes_from_normal_incidence_through_the_critical_angle_to_grazing() {
        let start = ExplorerState::default();
        let frames: Vec<_> = (0..24)
            .map(|i| Animation::Sweep.frame(&start, i, 24).state)
            .collect();
        let cos_i: Vec<f64> = frames.iter().map(|s| s.refraction().cos_i).collect();
        assert!((cos_i[0] - 1.0).abs() < 1e-12);
        assert!(cos_i[23] < 0.01);
        assert!(cos_i.windows(2).all(|w| w[1] < w[0]), "{cos_i:?}");
        assert!(!frames[0].refraction().is_tir() && frames[23].refraction().is_tir());
        assert!(frames.iter().all(|s| s.mu_i() > s.mu_t()));
    }

    #[test]
    fn wavefront_frames_loop_over_one_period_and_draw_more_than_the_diagram() {
        let start = ExplorerState::default();
        let phases: Vec<f64> = (0..4)
            .map(|i| {
                Animation::Wavefronts
                    .frame(&start, i, 4)
                    .waves
                    .unwrap()
                    .phase
            })
            .collect();
        assert_eq!(phases, [0.0, 0.25, 0.5, 0.75]);
        let frame = Animation::Wavefronts.frame(&start, 1, 4);
        let size = Vec2::new(800.0, 600.0);
        let plain = Diagram::new(&frame.state, size).primitives();
        let with_waves = frame.primitives(size, &Overlay::default());
        assert!(with_waves.len() > plain.len() + 10);
        // The background still comes first, the handles (the diagram's last discs) stay last
        // but for the labels (and the leader lines of those placed far from their anchors).
        assert_eq!(with_waves[0], plain[0]);
        let last_disc =
            |p: &[Primitive]| p.iter().rposition(|x| matches!(x, Primitive::Disc { .. }));
        let (plain_disc, waves_disc) =
            (last_disc(&plain).unwrap(), last_disc(&with_waves).unwrap());
        assert_eq!(with_waves[waves_disc], plain[plain_disc]);
        assert!(
            with_waves[waves_disc + 1..]
                .iter()
                .all(|p| matches!(p, Primitive::Text(_) | Primitive::Polyline { .. }))
        );
    }

    #[test]
    fn a_wavefront_frame_draws_huygens_when_the_overlay_asks_and_not_otherwise() {
        let frame = Animation::Wavefronts.frame(&ExplorerState::default(), 0, 4);
        let size = Vec2::new(800.0, 600.0);
        let huygens = |overlay: &Overlay| {
            frame
                .primitives(size, overlay)
                .iter()
                .filter(|p| matches!(p, Primitive::Text(l) if l.text.starts_with("Huygens")))
                .count()
        };
        assert_eq!(huygens(&Overlay::default()), 0);
        let asked = Overlay {
            waves: Some(WaveOptions {
                phase: 0.5,
                huygens: true,
            }),
            ..Overlay::default()
        };
        assert_eq!(huygens(&asked), 1);
    }
}
