//! The *Intensities* switch: how much of the light each ray of the interface diagram carries,
//! from the kernel's Fresnel fractions for s, p or unpolarised light, shown by the rays' width
//! and opacity and by percentages beside them.

use super::fresnel_plot::percent;
use super::geometry::Colour;
use super::shapes::Stroke;
use refraction_kernel::{Fresnel, Refraction};

/// A share below this is not drawn at all: the ray has vanished (p light at Brewster's angle).
pub const VANISHED: f64 = 1e-4;

/// The light the shares are computed for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Polarisation {
    /// Polarised perpendicular to the plane of incidence.
    S,
    /// Polarised in the plane of incidence: not reflected at all at Brewster's angle.
    P,
    /// The mean of s and p, as from a lamp or the sun.
    #[default]
    Unpolarised,
}

impl Polarisation {
    /// Every choice, in the order of the menu.
    pub const ALL: [Self; 3] = [Self::Unpolarised, Self::S, Self::P];

    /// The name in the menu and in the labels.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::S => "s light",
            Self::P => "p light",
            Self::Unpolarised => "unpolarised light",
        }
    }
}

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
pub fn stroke_for(full: Stroke, share: f64) -> Option<Stroke> {
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
}
