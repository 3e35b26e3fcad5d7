//! Other people's `refract`: what four graphics APIs return for given arguments, bit for bit,
//! and what those arguments mean in this project's terms (the direction of travel d, the normal
//! facing it, μ = `n_from/n_to`), so that a student's call can be checked in their own API.
//!
//! - [`glsl`]: GLSL's `refract(I, N, eta)`, the same in HLSL, WGSL, glm and glam.
//! - [`pbrt`]: pbrt-v4's `Refract(wi, n, eta, &etap, &wt)`.
//! - [`rtiow`]: Ray Tracing in One Weekend's `refract(uv, n, etai_over_etat)` and the
//!   `cannot_refract` test of its `dielectric::scatter`.
//! - [`mitsuba`]: Mitsuba 3's `fresnel(cos_theta_i, eta)` and `refract`.
//!
//! Every function is generic over `f32` and `f64` and keeps its API's order of operations
//! (fused where the API fuses), so a student's logged bits can be reproduced.
//!
//! ```
//! use glam::Vec3;
//! use refraction_kernel::api::{Api, Args};
//! let d = Vec3::new(0.6, -0.8, 0.0);
//! // The same physical call, air into glass, in two APIs' conventions.
//! let glsl = Api::Glsl.arguments::<f32>(d, Vec3::Y, 1.0 / 1.5);
//! let pbrt = Api::Pbrt.arguments::<f32>(d, Vec3::Y, 1.0 / 1.5);
//! assert_eq!((pbrt.incident, pbrt.eta), (-d, 1.5));
//! let (a, b) = (Api::Glsl.call(glsl).transmitted(), Api::Pbrt.call(pbrt).transmitted());
//! assert!((a.unwrap() - b.unwrap()).length() < 1e-6);
//! ```

pub mod glsl;
pub mod mitsuba;
pub mod pbrt;
pub mod rtiow;

use crate::real::{Real, Vector3 as _};

/// A graphics API whose refraction call a student makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Api {
    /// GLSL `refract(I, N, eta)` (also HLSL, WGSL, glm, glam).
    Glsl,
    /// pbrt-v4 `Refract(wi, n, eta, &etap, &wt)`.
    Pbrt,
    /// Ray Tracing in One Weekend `refract(uv, n, etai_over_etat)`.
    Rtiow,
    /// Mitsuba 3 `fresnel(cos_theta_i, eta)` with `refract`.
    Mitsuba,
}

/// The three arguments every API's refraction takes, each in that API's own convention
/// (GLSL's `I, N, eta`, pbrt's `wi, n, eta`, the book's `uv, n, etai_over_etat`, Mitsuba's
/// `wi, n, eta` with `n` = +z in the local frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Args<S: Real> {
    /// The incident vector: GLSL's I and the book's uv (along the ray), pbrt's and Mitsuba's
    /// wi (back along the ray).
    pub incident: S::Vec3,
    /// The surface normal.
    pub normal: S::Vec3,
    /// The index ratio in the API's own sense.
    pub eta: S,
}

/// What a call means in this project's terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Meaning<S: Real> {
    /// d: the direction the ray travels in, toward the surface.
    pub travel: S::Vec3,
    /// The normal the API refracts about, on the side d comes from when the call is within
    /// the contract.
    pub normal: S::Vec3,
    /// μ = `n_from/n_to`, as the API understands the arguments.
    pub mu: S,
    /// Whether the normal as passed is on the side the ray comes from.
    pub normal_on_incident_side: bool,
    /// Whether the API means anything physical by these arguments: GLSL's and the book's
    /// `refract` need the normal against the ray; pbrt's and Mitsuba's accept either side.
    pub within_contract: bool,
}

/// What an API returned for one call, in its own shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Returned<S: Real> {
    /// GLSL's vector: the zero vector on total internal reflection.
    Glsl(S::Vec3),
    /// pbrt's `Refract`: `None` when it returns `false`.
    Pbrt(Option<pbrt::Refracted<S>>),
    /// The book's `refract` and `dielectric::scatter`'s `cannot_refract`.
    Rtiow(rtiow::Answer<S>),
    /// Mitsuba's `fresnel` and `refract`.
    Mitsuba(mitsuba::Answer<S>),
}

impl<S: Real> Returned<S> {
    /// The transmitted direction, or `None` where the API says nothing is transmitted: GLSL's
    /// zero vector, pbrt's `false`, the book's `cannot_refract`, Mitsuba's F = 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::api::Api;
    /// // Leaving glass at 45°, past the critical angle, in every API's convention.
    /// let up = DVec3::new(0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0);
    /// for api in Api::ALL {
    ///     let returned = api.call(api.arguments::<f64>(up, -DVec3::Y, 1.5));
    ///     assert_eq!(returned.transmitted(), None, "{api:?}");
    /// }
    /// ```
    #[must_use]
    pub fn transmitted(&self) -> Option<S::Vec3> {
        match *self {
            Self::Glsl(v) => (v.to_array() != [S::ZERO; 3]).then_some(v),
            Self::Pbrt(r) => r.map(|r| r.wt),
            Self::Rtiow(a) => (!a.cannot_refract).then_some(a.refracted),
            Self::Mitsuba(a) => (a.fresnel.f < S::ONE).then_some(a.wo),
        }
    }

    /// The vector the refraction formula produced, even where the API says not to use it (the
    /// book's `refract` and Mitsuba's `refract` past the critical angle); `None` for pbrt's
    /// `false`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::api::Api;
    /// let up = DVec3::new(0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0);
    /// let call = |api: Api| api.call(api.arguments::<f64>(up, -DVec3::Y, 1.5));
    /// // Past the critical angle GLSL's formula gives zero, the book's a vector longer than 1.
    /// assert_eq!(call(Api::Glsl).formula(), Some(DVec3::ZERO));
    /// assert!(call(Api::Rtiow).formula().unwrap().length() > 1.0);
    /// assert_eq!(call(Api::Pbrt).formula(), None);
    /// ```
    #[must_use]
    pub fn formula(&self) -> Option<S::Vec3> {
        match *self {
            Self::Glsl(v) => Some(v),
            Self::Pbrt(r) => r.map(|r| r.wt),
            Self::Rtiow(a) => Some(a.refracted),
            Self::Mitsuba(a) => Some(a.wo),
        }
    }
}

impl Api {
    /// Every API, in the order the command line lists them.
    pub const ALL: [Self; 4] = [Self::Glsl, Self::Pbrt, Self::Rtiow, Self::Mitsuba];

    /// The name on the command line: `glsl`, `pbrt`, `rtiow` or `mitsuba`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::api::Api;
    /// assert_eq!(Api::ALL.map(Api::name), ["glsl", "pbrt", "rtiow", "mitsuba"]);
    /// ```
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Glsl => "glsl",
            Self::Pbrt => "pbrt",
            Self::Rtiow => "rtiow",
            Self::Mitsuba => "mitsuba",
        }
    }

    /// The API for a command-line name (any case): its [`name`](Self::name), or for GLSL one of
    /// `hlsl`, `wgsl`, `glm`, `glam`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::api::Api;
    /// assert_eq!(Api::from_name("HLSL"), Some(Api::Glsl));
    /// assert_eq!(Api::from_name("pbrt"), Some(Api::Pbrt));
    /// assert_eq!(Api::from_name("optix"), None);
    /// ```
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        let name = name.to_ascii_lowercase();
        match name.as_str() {
            "glsl" | "hlsl" | "wgsl" | "glm" | "glam" => Some(Self::Glsl),
            _ => Self::ALL.into_iter().find(|api| api.name() == name),
        }
    }

    /// The call as a student writes it, for titles and messages.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::api::Api;
    /// assert_eq!(Api::Glsl.signature(), "GLSL refract(I, N, eta)");
    /// ```
    #[must_use]
    pub fn signature(self) -> &'static str {
        match self {
            Self::Glsl => "GLSL refract(I, N, eta)",
            Self::Pbrt => "pbrt-v4 Refract(wi, n, eta, &etap, &wt)",
            Self::Rtiow => "Ray Tracing in One Weekend refract(uv, n, etai_over_etat)",
            Self::Mitsuba => {
                "Mitsuba 3 fresnel(cos_theta_i, eta) + refract(wi, cos_theta_t, eta_ti)"
            }
        }
    }

    /// What this API returns for `args` (Mitsuba's in a scalar build without FMA, see
    /// [`mitsuba::Fma`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::api::{Api, Args, Returned};
    /// let (incident, normal) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// let args = Args::<f32> { incident, normal, eta: 1.0 / 1.5 };
    /// let Returned::Glsl(t) = Api::Glsl.call(args) else { unreachable!() };
    /// assert_eq!(t, args.incident.refract(args.normal, args.eta)); // glam's own, bit for bit
    /// ```
    #[must_use]
    pub fn call<S: Real>(self, args: Args<S>) -> Returned<S> {
        let Args {
            incident,
            normal,
            eta,
        } = args;
        match self {
            Self::Glsl => Returned::Glsl(glsl::refract(incident, normal, eta)),
            Self::Pbrt => Returned::Pbrt(pbrt::refract(incident, normal, eta)),
            Self::Rtiow => Returned::Rtiow(rtiow::answer(incident, normal, eta)),
            Self::Mitsuba => Returned::Mitsuba(mitsuba::answer(
                incident,
                normal,
                eta,
                mitsuba::Fma::Unfused,
            )),
        }
    }

    /// What `args` mean in this project's terms.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::api::{Api, Args};
    /// // pbrt's wi points back along the ray; its eta is inverted when the ray leaves.
    /// let args = Args { incident: DVec3::new(-0.6, 0.8, 0.0), normal: DVec3::Y, eta: 1.5 };
    /// let meaning = Api::Pbrt.meaning(args);
    /// assert_eq!(meaning.travel, DVec3::new(0.6, -0.8, 0.0));
    /// assert_eq!(meaning.mu, 1.0 / 1.5);
    /// assert!(meaning.within_contract);
    /// ```
    #[must_use]
    pub fn meaning<S: Real>(self, args: Args<S>) -> Meaning<S> {
        let Args {
            incident,
            normal,
            eta,
        } = args;
        match self {
            Self::Glsl => glsl::meaning(incident, normal, eta),
            Self::Pbrt => pbrt::meaning(incident, normal, eta),
            Self::Rtiow => rtiow::meaning(incident, normal, eta),
            Self::Mitsuba => mitsuba::meaning(incident, normal, eta),
        }
    }

    /// The right arguments, in this API's convention, for a ray travelling along `d` onto a
    /// surface whose normal `facing` is on d's side (d·facing ≤ 0) with μ = `n_from/n_to`. For
    /// pbrt and Mitsuba the normal passed is `facing` itself (either side would do with the
    /// matching eta).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::api::Api;
    /// let d = Vec3::new(0.6, -0.8, 0.0);
    /// let pbrt = Api::Pbrt.arguments::<f32>(d, Vec3::Y, 1.0 / 1.5);
    /// assert_eq!((pbrt.incident, pbrt.normal, pbrt.eta), (-d, Vec3::Y, 1.5));
    /// let glsl = Api::Glsl.arguments::<f32>(d, Vec3::Y, 1.0 / 1.5);
    /// assert_eq!(glsl.incident, d);
    /// ```
    #[must_use]
    pub fn arguments<S: Real>(self, d: S::Vec3, facing: S::Vec3, mu: S) -> Args<S> {
        match self {
            Self::Glsl | Self::Rtiow => Args {
                incident: d,
                normal: facing,
                eta: mu,
            },
            Self::Pbrt | Self::Mitsuba => Args {
                incident: -d,
                normal: facing,
                eta: S::ONE / mu,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn names_and_aliases() {
        for api in Api::ALL {
            assert_eq!(Api::from_name(api.name()), Some(api));
        }
        for alias in ["HLSL", "wgsl", "glm", "glam"] {
            assert_eq!(Api::from_name(alias), Some(Api::Glsl));
        }
        assert_eq!(Api::from_name("optix"), None);
    }

    #[test]
    fn the_right_arguments_mean_the_situation_in_every_api() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        for api in Api::ALL {
            let m = api.meaning(api.arguments::<f64>(d, DVec3::Y, 1.0 / 1.5));
            assert_eq!((m.travel, m.normal), (d, DVec3::Y), "{api:?}");
            assert!(
                (m.mu - 1.0 / 1.5).abs() < 1e-15 && m.within_contract,
                "{api:?}"
            );
        }
    }
}
