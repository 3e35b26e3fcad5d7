//! `--renderer NAME`: whose code a log comes from, so that the diagnosis of the whole log can
//! name the line to change in that renderer's own code. It changes no verdict: the search for
//! the mistake is the same for every log; only the words of the fix differ.

use refraction_kernel::api::Api;

/// A renderer whose glass code the fixes quote (see `docs/check.md`, one section a family).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Renderer {
    /// Mitsuba 3: `fresnel` and `refract` (`include/mitsuba/render/fresnel.h`), called by
    /// `SmoothDielectric::sample`.
    Mitsuba,
    /// Tungsten: `DielectricBsdf::sample` and `Fresnel::dielectricReflectance`.
    Tungsten,
    /// Blender Cycles: `fresnel_dielectric`, `refract_angle` and the glass closure's
    /// `backfacing ? 1/ior : ior`.
    Cycles,
    /// three.js: the transmission shader's `refract(-v, normalize(n), 1.0 / ior)`.
    ThreeJs,
    /// pbrt-v4: `Refract` and `DielectricBxDF::Sample_f`.
    Pbrt,
    /// smallpt: the REFR branch of `radiance()`.
    Smallpt,
    /// Ray Tracing in One Weekend: `refract` and `dielectric::scatter`.
    Rtiow,
    /// A GLSL (HLSL, WGSL, glm) shader calling the built-in `refract`.
    Glsl,
    /// Rust code calling glam's `Vec3::refract` (GLSL's formula, `Vec3::ZERO` past the
    /// critical angle).
    Glam,
    /// Python calling Mitsuba 3's `mi.fresnel` and `mi.refract` itself (the Python package's
    /// `api="mitsuba"`): the fix is in the script's call, not in Mitsuba's C++.
    MitsubaPython,
}

impl Renderer {
    /// Every renderer, in the order the docs list them.
    pub const ALL: [Self; 10] = [
        Self::Mitsuba,
        Self::Tungsten,
        Self::Cycles,
        Self::ThreeJs,
        Self::Pbrt,
        Self::Smallpt,
        Self::Rtiow,
        Self::Glsl,
        Self::Glam,
        Self::MitsubaPython,
    ];

    /// The name on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Mitsuba => "mitsuba",
            Self::Tungsten => "tungsten",
            Self::Cycles => "cycles",
            Self::ThreeJs => "threejs",
            Self::Pbrt => "pbrt",
            Self::Smallpt => "smallpt",
            Self::Rtiow => "rtiow",
            Self::Glsl => "glsl",
            Self::Glam => "glam",
            Self::MitsubaPython => "mitsuba-python",
        }
    }

    /// The renderer for a command-line name (any case; `three.js` and `blender` too).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        let name = name.to_ascii_lowercase();
        match name.as_str() {
            "three.js" | "three" => Some(Self::ThreeJs),
            "blender" => Some(Self::Cycles),
            "mitsuba_python" | "mi" => Some(Self::MitsubaPython),
            _ => Self::ALL.into_iter().find(|r| r.name() == name),
        }
    }

    /// The renderer a named API's calls come from, when none is named.
    #[must_use]
    pub fn of_api(api: Api) -> Self {
        match api {
            Api::Glsl => Self::Glsl,
            Api::Pbrt => Self::Pbrt,
            Api::Rtiow => Self::Rtiow,
            Api::Mitsuba => Self::Mitsuba,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_back() {
        for renderer in Renderer::ALL {
            assert_eq!(Renderer::from_name(renderer.name()), Some(renderer));
        }
        assert_eq!(Renderer::from_name("Three.js"), Some(Renderer::ThreeJs));
        assert_eq!(Renderer::from_name("luxcore"), None);
    }
}
