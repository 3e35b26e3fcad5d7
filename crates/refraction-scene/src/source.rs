//! Light sources: a single ray, a parallel beam or a fan, of one wavelength or white.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::medium::{REFERENCE_WAVELENGTH_NM, WHITE_WAVELENGTHS_NM};

/// The arrangement of a source's rays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SourceKind {
    /// One ray from the origin.
    Ray,
    /// Parallel rays spread evenly across `width`, centred on the origin.
    Beam,
    /// Rays from the origin spread evenly over `spread_deg`, centred on the direction.
    Fan,
}

/// The colour of a source.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Light {
    /// Monochromatic light of this vacuum wavelength in nm.
    Wavelength(f64),
    /// White light: [`WHITE_WAVELENGTHS_NM`] when dispersion is traced, else the reference
    /// wavelength alone.
    White,
}

/// Where the rays of a scene start, which way they go and their colour.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Source {
    /// The arrangement.
    pub kind: SourceKind,
    /// The start of the ray, the centre of the beam, the apex of the fan.
    pub origin: DVec2,
    /// The unit direction of the ray, the beam, the fan's middle ray.
    pub direction: DVec2,
    /// How many rays a beam or fan has (≥ 1; 1 for a single ray).
    pub rays: usize,
    /// The width of a beam in world units (0 otherwise).
    pub width: f64,
    /// The full angle of a fan in degrees (0 otherwise).
    pub spread_deg: f64,
    /// The colour.
    pub light: Light,
}

impl Light {
    /// The wavelength in nm, or `None` for white light.
    #[must_use]
    pub fn wavelength_nm(self) -> Option<f64> {
        match self {
            Self::Wavelength(nm) => Some(nm),
            Self::White => None,
        }
    }
}

/// The vacuum wavelength in nm at which light is traced: white light traced once is traced
/// at [`REFERENCE_WAVELENGTH_NM`].
#[must_use]
pub fn traced_wavelength(light: Light) -> f64 {
    light.wavelength_nm().unwrap_or(REFERENCE_WAVELENGTH_NM)
}

/// Serializes traced light as its wavelength in nm, or `null` for white light traced once: the
/// `wavelength_nm` of the `trace` command's JSON.
///
/// # Errors
/// The serializer's.
pub(crate) fn serialize_wavelength<S: serde::Serializer>(
    light: &Light,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    light.wavelength_nm().serialize(serializer)
}

impl Source {
    /// The most rays a source may have.
    pub const MAX_RAYS: usize = 100_000;

    /// The colours to trace: one unless the light is white and dispersion is asked for.
    #[must_use]
    pub fn colours(&self, dispersion: bool) -> Vec<Light> {
        match self.light {
            Light::White if dispersion => WHITE_WAVELENGTHS_NM
                .iter()
                .copied()
                .map(Light::Wavelength)
                .collect(),
            light => vec![light],
        }
    }

    /// Every wavelength in nm the source may be traced at, with or without dispersion.
    #[must_use]
    pub fn wavelengths(&self) -> Vec<f64> {
        let mut all: Vec<f64> = self
            .colours(true)
            .into_iter()
            .map(traced_wavelength)
            .collect();
        all.push(REFERENCE_WAVELENGTH_NM);
        all
    }

    /// The start and unit direction of each ray. A full circle (a fan of 360°) has its rays
    /// 360°/n apart, so that its first and last rays do not coincide.
    pub fn rays(&self) -> impl Iterator<Item = (DVec2, DVec2)> + '_ {
        let full_circle = self.kind == SourceKind::Fan && self.spread_deg >= 360.0;
        let steps = if full_circle {
            self.rays.max(1)
        } else {
            self.rays.saturating_sub(1).max(1)
        } as f64;
        (0..self.rays).map(move |i| {
            // −½ … +½ across the beam or fan; the middle for a single ray.
            let spread = if self.rays == 1 {
                0.0
            } else {
                i as f64 / steps - 0.5
            };
            match self.kind {
                SourceKind::Ray => (self.origin, self.direction),
                SourceKind::Beam => (
                    self.origin + self.direction.perp() * (spread * self.width),
                    self.direction,
                ),
                SourceKind::Fan => (
                    self.origin,
                    DVec2::from_angle((spread * self.spread_deg).to_radians())
                        .rotate(self.direction),
                ),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn source(kind: SourceKind, rays: usize) -> Source {
        Source {
            kind,
            origin: DVec2::ZERO,
            direction: DVec2::X,
            rays,
            width: 2.0,
            spread_deg: 90.0,
            light: Light::White,
        }
    }

    #[test]
    fn a_beam_spreads_its_rays_across_its_width() {
        let rays: Vec<_> = source(SourceKind::Beam, 3).rays().collect();
        assert_eq!(
            rays,
            vec![
                (DVec2::new(0.0, -1.0), DVec2::X),
                (DVec2::ZERO, DVec2::X),
                (DVec2::new(0.0, 1.0), DVec2::X)
            ]
        );
    }

    #[test]
    fn a_fan_spreads_its_rays_over_its_angle() {
        let rays: Vec<_> = source(SourceKind::Fan, 2).rays().collect();
        let h = 0.5_f64.sqrt();
        assert!((rays[0].1 - DVec2::new(h, -h)).length() < 1e-15);
        assert!((rays[1].1 - DVec2::new(h, h)).length() < 1e-15);
        assert_eq!(
            source(SourceKind::Fan, 1).rays().next().unwrap().1,
            DVec2::X
        );
    }

    #[test]
    fn a_full_circle_fan_traces_each_direction_once() {
        let mut fan = source(SourceKind::Fan, 4);
        fan.spread_deg = 360.0;
        let directions: Vec<DVec2> = fan.rays().map(|(_, d)| d).collect();
        assert_eq!(directions.len(), 4);
        for (i, a) in directions.iter().enumerate() {
            let next = directions[(i + 1) % 4];
            assert!((a.dot(next)).abs() < 1e-12, "90° apart: {directions:?}");
        }
    }

    #[test]
    fn white_light_is_one_colour_unless_dispersion_is_asked_for() {
        let s = source(SourceKind::Ray, 1);
        assert_eq!(s.colours(false), vec![Light::White]);
        assert_eq!(s.colours(true).len(), WHITE_WAVELENGTHS_NM.len());
    }
}
