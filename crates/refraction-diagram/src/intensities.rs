//! The *Intensities* switch: how much of the light each ray of the interface diagram carries,
//! from the kernel's Fresnel fractions for s, p or unpolarised light, shown by the rays' width
//! and opacity and by percentages beside them.

use super::geometry::Colour;
use super::numbers::percent;
use super::shapes::Stroke;
use refraction_kernel::{Fresnel, Refraction};
use refraction_model::Polarisation;

/// A share below this is not drawn at all: the ray has vanished (p light at Brewster's angle).
pub(crate) const VANISHED: f64 = 1e-4;

/// The fractions of the incoming power that leave by the reflected and the transmitted ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shares {
    /// Reflected, 0 to 1 (1 on total internal reflection).
    pub reflected: f64,
    /// Transmitted, 0 to 1 (0 on total internal reflection).
    pub transmitted: f64,
    /// For which light.
    pub polarisation: Polarisation,
}

impl Shares {
    /// The shares of the kernel's refraction `r` for `polarisation`.
    #[must_use]
    pub fn of(r: &Refraction<f64>, polarisation: Polarisation) -> Self {
        let f = Fresnel::of(r);
        let (reflected, transmitted) = match polarisation {
            Polarisation::S => (f.rs, f.ts),
            Polarisation::P => (f.rp, f.tp),
            Polarisation::Unpolarised => (f.reflectance(), f.transmittance()),
        };
        Self {
            reflected,
            transmitted,
            polarisation,
        }
    }

    /// The label beside a ray carrying `share`, e.g. `reflected 4.0 %`.
    #[must_use]
    pub fn label(name: &str, share: f64) -> String {
        format!("{name} {}", percent(share))
    }
}

/// The stroke of a ray carrying `share` of the light, from the stroke it has at full
/// strength: width and opacity grow with √share (so that 4 % is still seen), and a share below
/// [`VANISHED`] is not drawn (`None`).
#[must_use]
pub(crate) fn stroke_for(full: Stroke, share: f64) -> Option<Stroke> {
    if share.is_nan() || share < VANISHED {
        return None;
    }
    let strength = share.min(1.0).sqrt() as f32;
    let alpha = f32::from(full.colour.a) * (0.35 + 0.65 * strength);
    Some(Stroke {
        width: full.width * (0.25 + 0.75 * strength) * 1.6,
        colour: Colour {
            a: alpha.round() as u8,
            ..full.colour
        },
        ..full
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::Dash;
    use glam::DVec3;
    use refraction_kernel::{Convention, Incidence, refract};

    fn refraction(w: DVec3, mu_i: f64, mu_t: f64) -> Refraction<f64> {
        refract(&Incidence {
            w,
            n: DVec3::Y,
            mu_i,
            mu_t,
            convention: Convention::AlongRay,
        })
        .unwrap()
    }

    #[test]
    fn at_brewsters_angle_p_light_is_not_reflected_and_its_ray_vanishes() {
        // tanθB = 1.5 from air into glass.
        let r = refraction(DVec3::new(1.5, -1.0, 0.0), 1.0, 1.5);
        let p = Shares::of(&r, Polarisation::P);
        assert!(p.reflected < 1e-20 && (p.transmitted - 1.0).abs() < 1e-15);
        let full = Stroke {
            width: 2.0,
            colour: Colour::hex(0xCC79A7),
            dash: Dash::Solid,
        };
        assert_eq!(stroke_for(full, p.reflected), None);
        let s = Shares::of(&r, Polarisation::S);
        assert!(s.reflected > 0.1);
        assert!(stroke_for(full, s.reflected).is_some());
        assert_eq!(Shares::label("reflected", p.reflected), "reflected 0.0 %");
    }

    #[test]
    fn more_light_draws_a_wider_more_opaque_ray_and_tir_reflects_it_all() {
        let full = Stroke {
            width: 2.0,
            colour: Colour::hex(0x0072B2),
            dash: Dash::Solid,
        };
        let weak = stroke_for(full, 0.04).unwrap();
        let strong = stroke_for(full, 0.96).unwrap();
        assert!(weak.width < strong.width && weak.colour.a < strong.colour.a);
        let r = refraction(DVec3::new(0.8, -0.6, 0.0), 1.5, 1.0);
        for polarisation in Polarisation::ALL {
            let shares = Shares::of(&r, polarisation);
            assert_eq!((shares.reflected, shares.transmitted), (1.0, 0.0));
        }
        let normal = refraction(DVec3::new(0.0, -1.0, 0.0), 1.0, 1.5);
        let unpolarised = Shares::of(&normal, Polarisation::Unpolarised);
        assert_eq!(
            Shares::label("reflected", unpolarised.reflected),
            "reflected 4.0 %"
        );
        assert_eq!(stroke_for(full, f64::NAN), None);
    }

    fn reflected_arrows(diagram: &crate::Diagram, colour: Colour) -> Vec<Stroke> {
        diagram
            .shapes
            .iter()
            .filter_map(|s| match s {
                crate::shapes::Figure::Arrow { stroke, .. }
                    if stroke.colour.r == colour.r
                        && stroke.colour.g == colour.g
                        && stroke.colour.b == colour.b =>
                {
                    Some(*stroke)
                }
                _ => None,
            })
            .collect()
    }

    fn texts(diagram: &crate::Diagram) -> Vec<String> {
        diagram
            .shapes
            .iter()
            .filter_map(|s| match s {
                crate::shapes::Figure::Text(l) => Some(l.text.clone()),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn the_diagram_draws_the_shares_only_when_switched_on_and_p_light_vanishes_at_brewster() {
        use crate::{Diagram, Overlay};
        use refraction_model::ExplorerState;
        let mut state = ExplorerState::default();
        state
            .set_vectors(DVec3::new(1.5, -1.0, 0.0), DVec3::Y)
            .unwrap();
        state.set_mu_i(1.0).unwrap();
        let size = glam::Vec2::new(1000.0, 700.0);
        let plain = Diagram::new(&state, size);
        let colour = Overlay::default().palette.reflected;
        assert_eq!(reflected_arrows(&plain, colour).len(), 1);
        assert!(!texts(&plain).iter().any(|t| t.contains('%')));
        let with = |polarisation| Overlay {
            intensities: Some(polarisation),
            ..Overlay::default()
        };
        let p = Diagram::with_overlay(&state, size, &with(Polarisation::P));
        assert!(reflected_arrows(&p, colour).is_empty(), "no reflected ray");
        let texts_p = texts(&p);
        assert!(
            texts_p
                .iter()
                .any(|t| t.contains("reflected (p light) 0.0 %")),
            "{texts_p:?}"
        );
        assert!(texts_p.iter().any(|t| t.contains("T: transmitted 100.0 %")));
        let s = Diagram::with_overlay(&state, size, &with(Polarisation::S));
        let unpolarised = Diagram::with_overlay(&state, size, &with(Polarisation::Unpolarised));
        let (rs, ru) = (
            reflected_arrows(&s, colour)[0],
            reflected_arrows(&unpolarised, colour)[0],
        );
        assert!(rs.width > ru.width && rs.colour.a >= ru.colour.a);
        assert!(
            texts(&s)
                .iter()
                .any(|t| t.contains("reflected (s light) 14.8 %"))
        );
    }
}
