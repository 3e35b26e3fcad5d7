//! The current case as text to paste elsewhere: a `solve` line, code calling a reference
//! function (Rust, GLSL, C++ with glm) and a unit-test vector, each with the expected T; and a
//! student's checked call as a unit test in their own language ([`api`]). The window copies
//! them and writes a log's failing lines as a file of tests with them.

pub mod api;
pub mod tests_file;

use crate::error::{JsonError, RequestError};
use crate::solve::Request;
use refraction_kernel::{Convention, refract};

/// A number as a float literal that Rust, GLSL and C++ all read back exactly (`1.0`, `0.1`,
/// `1e-7`; never `1`).
fn literal(x: f64) -> String {
    format!("{x:?}")
}

fn vector(v: [f64; 3]) -> String {
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

/// The language a test of any renderer's own refraction is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnyLanguage {
    /// C++ with `assert`, calling a `refract` the student points at their own.
    Cpp,
    /// Python (pytest), calling a `refract` imported from the student's module.
    Python,
}

/// A failing line of any renderer's log: its number, the problem and what the code sent.
#[derive(Clone, Copy, Debug)]
pub struct AnyCase<'a> {
    /// The log's line number, from 1.
    pub line: usize,
    /// The problem: W, N, the indices, the convention.
    pub request: &'a Request,
    /// What the student's code gave (`None`: it reported total internal reflection).
    pub yours: Option<[f64; 3]>,
}

/// The tolerance of a test in `precision`.
fn any_tolerance(precision: crate::solve::Precision) -> &'static str {
    match precision {
        crate::solve::Precision::F32 => "1e-5",
        crate::solve::Precision::F64 => "1e-12",
    }
}

/// One case's test body in `language`: the call with the log's arguments and the expected T
/// (the kernel's) or total internal reflection, after a comment saying what the code gave.
fn any_test(language: AnyLanguage, case: &AnyCase<'_>) -> Result<String, RequestError> {
    let r = case.request;
    let t = expected(r)?.t;
    let gave = case.yours.map_or_else(
        || "total internal reflection".to_owned(),
        |y| format!("({})", vector(y)),
    );
    let tol = any_tolerance(r.precision);
    let (w, n, mu_i, mu_t) = (vector(r.w), vector(r.n), literal(r.mu_i), literal(r.mu_t));
    let line = case.line;
    Ok(match (language, t) {
        (AnyLanguage::Cpp, Some(t)) => format!(
            "// Line {line}: the code gave {gave}.\nstatic void test_refract_line_{line}() {{\n    \
             V t;\n    assert(refract(V{{{w}}}, V{{{n}}}, {mu_i}, {mu_t}, &t));\n    \
             assert(near(t, V{{{}}}, {tol}));\n}}\n",
            vector(t)
        ),
        (AnyLanguage::Cpp, None) => format!(
            "// Line {line}: the code gave {gave}; the right answer is total internal reflection.\n\
             static void test_refract_line_{line}() {{\n    V t;\n    \
             assert(!refract(V{{{w}}}, V{{{n}}}, {mu_i}, {mu_t}, &t));\n}}\n"
        ),
        (AnyLanguage::Python, Some(t)) => format!(
            "\n\n# Line {line}: the code gave {gave}.\ndef test_refract_line_{line}():\n    \
             t = refract(({w}), ({n}), {mu_i}, {mu_t})\n    assert t is not None\n    \
             assert close(t, ({}), {tol})\n",
            vector(t)
        ),
        (AnyLanguage::Python, None) => format!(
            "\n\n# Line {line}: the code gave {gave}; the right answer is total internal reflection.\n\
             def test_refract_line_{line}():\n    assert refract(({w}), ({n}), {mu_i}, {mu_t}) is None\n"
        ),
    })
}

/// What a file of any renderer's tests starts with: how to point it at the renderer's own
/// refraction, and the helpers the tests share.
fn any_preamble(language: AnyLanguage, convention: Convention) -> String {
    let w = match convention {
        Convention::AlongRay => "W, the direction the ray travels in",
        Convention::TowardOrigin => "W, pointing back toward the ray's origin",
    };
    match language {
        AnyLanguage::Cpp => format!(
            "// Each test calls your renderer's refraction with the logged {w}, N and the\n\
             // indices: define `refract` to call it (true and the direction in t, or false on\n\
             // total internal reflection).\n#include <cassert>\n#include <cmath>\n\n\
             struct V {{ double x, y, z; }};\nbool refract(V w, V n, double mu_i, double mu_t, V* t);\n\n\
             static bool near(V a, V b, double tolerance) {{\n    \
             return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance &&\n           \
             std::fabs(a.z - b.z) <= tolerance;\n}}\n\n"
        ),
        AnyLanguage::Python => format!(
            "# Each test calls your renderer's refraction with the logged {w}, N and the\n\
             # indices: refract(w, n, mu_i, mu_t) gives the direction, or None on total internal\n\
             # reflection.\nfrom renderer import refract  # change the module to your renderer's\n\n\n\
             def close(a, b, tolerance):\n    return all(abs(x - y) <= tolerance for x, y in zip(a, b))\n"
        ),
    }
}

/// A C++ `main` that calls each of the test functions `names` and returns 0.
fn cpp_main(names: impl Iterator<Item = String>) -> String {
    let mut text = "int main() {\n".to_owned();
    for name in names {
        text.push_str(&format!("    {name}();\n"));
    }
    text.push_str("    return 0;\n}\n");
    text
}

/// A file of tests in `language` of any renderer's own refraction, one per failing line, with
/// a `main` that runs them in C++.
///
/// # Errors
/// A line's problem cannot be refracted (it was judged, so it can).
pub fn any_renderer_tests(
    language: AnyLanguage,
    cases: &[AnyCase<'_>],
) -> Result<String, RequestError> {
    let convention = cases
        .first()
        .map_or_else(Convention::default, |c| c.request.convention);
    let mut text = any_preamble(language, convention);
    for case in cases {
        text.push_str(&any_test(language, case)?);
        if language == AnyLanguage::Cpp {
            text.push('\n');
        }
    }
    if language == AnyLanguage::Cpp {
        text.push_str(&cpp_main(
            cases
                .iter()
                .map(|c| format!("test_refract_line_{}", c.line)),
        ));
    }
    Ok(text)
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
