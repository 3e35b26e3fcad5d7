//! The current case as text to paste elsewhere: a `solve` line, code calling a reference
//! function (Rust, GLSL, C++ with glm) and a unit-test vector, each with the expected T. The
//! window copies them; the numbers are written as [`literal`]s, which the log diagnosis's test
//! files use too.

use crate::error::{JsonError, RequestError};
use crate::solve::Request;
use refraction_kernel::{Convention, refract};

/// A number as a float literal that Rust, GLSL and C++ all read back exactly (`1.0`, `0.1`,
/// `1e-7`; never `1`).
#[must_use]
pub fn literal(x: f64) -> String {
    format!("{x:?}")
}

/// A vector as three [`literal`]s separated by commas (`0.6, -0.8, 0.0`).
#[must_use]
pub fn vector(v: impl Into<[f64; 3]>) -> String {
    let v: [f64; 3] = v.into();
    v.map(literal).join(", ")
}

/// The kernel's answer for a request, at f64.
struct Expected {
    /// T, or `None` on total internal reflection.
    t: Option<[f64; 3]>,
    /// (a, b), or `None` on total internal reflection.
    weights: Option<(f64, f64)>,
    /// Whether the kernel turned N around to face the ray.
    normal_flipped: bool,
}

fn expected(request: &Request) -> Result<Expected, RequestError> {
    let r = refract(&request.incidence::<f64>()?)?;
    Ok(Expected {
        t: r.t().map(|t| t.to_array()),
        weights: r.transmission.map(|t| (t.a, t.b)),
        normal_flipped: r.normal_flipped,
    })
}

/// The case as Rust calling this crate's kernel, asserting the expected T.
///
/// # Errors
/// The request cannot be refracted.
pub fn rust(request: &Request) -> Result<String, RequestError> {
    let t = expected(request)?.t;
    let convention = match request.convention {
        Convention::AlongRay => "AlongRay",
        Convention::TowardOrigin => "TowardOrigin",
    };
    let check = t.map_or_else(
        || "assert!(r.is_tir(), \"expected total internal reflection\");".to_owned(),
        |t| {
            format!(
                "let expected = glam::DVec3::new({});\nassert!((r.t().unwrap() - expected).length() < 1e-12);",
                vector(t)
            )
        },
    );
    Ok(format!(
        "use refraction_kernel::{{Convention, Incidence, refract}};\n\n\
         let r = refract(&Incidence::<f64> {{\n    w: glam::DVec3::new({}),\n    n: glam::DVec3::new({}),\n    \
         mu_i: {},\n    mu_t: {},\n    convention: Convention::{convention},\n}})\n.unwrap();\n{check}\n",
        vector(request.w),
        vector(request.n),
        literal(request.mu_i),
        literal(request.mu_t),
    ))
}

/// The built-in `refract(I, N, eta)` call of GLSL and glm for this case: I is the travel
/// direction (−W for `toward_origin`), N is turned to face it, and eta = `μ_i/μ_t`.
fn shading_call(request: &Request, vec3: &str, refract_fn: &str) -> Result<String, RequestError> {
    let expected = expected(request)?;
    let incident = match request.convention {
        Convention::AlongRay => "normalize(W)",
        Convention::TowardOrigin => "-normalize(W)  /* W points back to the origin */",
    };
    let normal = if expected.normal_flipped {
        "-normalize(N)  /* N pointed along the ray: turn it to face the ray */"
    } else {
        "normalize(N)"
    };
    let t = expected.t.map_or_else(
        || "the zero vector: total internal reflection".to_owned(),
        |t| format!("{vec3}({})", vector(t)),
    );
    Ok(format!(
        "{vec3} W = {vec3}({});\n{vec3} N = {vec3}({});\n{vec3} T = {refract_fn}({incident}, {normal}, {} / {});\n// expected T = {t}\n",
        vector(request.w),
        vector(request.n),
        literal(request.mu_i),
        literal(request.mu_t),
    ))
}

/// The case as GLSL calling the built-in `refract`, with the expected T in a comment.
///
/// # Errors
/// The request cannot be refracted.
pub fn glsl(request: &Request) -> Result<String, RequestError> {
    shading_call(request, "vec3", "refract")
}

/// The case as C++ calling `glm::refract`, with the expected T in a comment.
///
/// # Errors
/// The request cannot be refracted.
pub fn cpp(request: &Request) -> Result<String, RequestError> {
    shading_call(request, "glm::vec3", "glm::refract")
        .map(|text| format!("#include <glm/glm.hpp>\nusing glm::normalize;\n{text}"))
}

/// The case as a language-neutral unit-test vector: the `solve` fields plus the expected
/// `t_expected` (null on TIR), `tir`, `a` and `b`, as one JSON line.
///
/// # Errors
/// The request cannot be refracted.
pub fn test_vector(request: &Request) -> Result<String, RequestError> {
    let Expected { t, weights, .. } = expected(request)?;
    let mut value: serde_json::Value = serde_json::from_str(&request.to_json_line())
        .map_err(|e| RequestError::from(JsonError::from(&e)))?;
    value["t_expected"] = serde_json::json!(t);
    value["tir"] = serde_json::json!(t.is_none());
    value["a"] = serde_json::json!(weights.map(|w| w.0));
    value["b"] = serde_json::json!(weights.map(|w| w.1));
    Ok(value.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::Precision;

    fn request(w: [f64; 3], n: [f64; 3], convention: Convention) -> Request {
        Request {
            w,
            n,
            mu_i: 1.0,
            mu_t: 1.5,
            convention,
            precision: Precision::F64,
        }
    }

    #[test]
    fn snippets_carry_the_inputs_and_the_expected_t() {
        let case = request([0.6, -0.8, 0.0], [0.0, 1.0, 0.0], Convention::AlongRay);
        let rust = rust(&case).unwrap();
        assert!(
            rust.contains("w: glam::DVec3::new(0.6, -0.8, 0.0)"),
            "{rust}"
        );
        assert!(
            rust.contains(
                "let expected = glam::DVec3::new(0.39999999999999997, -0.9165151389911681, 0.0)"
            ),
            "{rust}"
        );
        let glsl = glsl(&case).unwrap();
        assert!(
            glsl.contains("vec3 T = refract(normalize(W), normalize(N), 1.0 / 1.5);"),
            "{glsl}"
        );
        assert!(cpp(&case).unwrap().contains("glm::refract("));
        let vector: serde_json::Value = serde_json::from_str(&test_vector(&case).unwrap()).unwrap();
        assert_eq!(vector["tir"], false);
        assert_eq!(vector["t_expected"][0], 0.39999999999999997);
    }

    #[test]
    fn glsl_turns_the_incident_vector_and_the_normal_the_way_the_builtin_expects() {
        let leaving = request([-0.6, -0.8, 0.0], [0.0, 1.0, 0.0], Convention::TowardOrigin);
        let glsl = glsl(&leaving).unwrap();
        assert!(glsl.contains("-normalize(W)"), "{glsl}");
        assert!(glsl.contains("-normalize(N)"), "{glsl}");
    }
}
