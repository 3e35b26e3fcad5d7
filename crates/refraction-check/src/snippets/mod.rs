//! A student's checked call, or a failing line of any renderer's log, as a unit test in their
//! own language: one call ([`api`]), or a file of tests for a log's failing lines
//! ([`tests_file`]), which `check --tests` and the window's *Save failing lines as tests* write.

pub(crate) mod api;
pub mod tests_file;

use refraction_kernel::{Convention, refract};
use refraction_tools::snippets::{literal, vector};
use refraction_tools::{Precision, Request, RequestError};

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
pub(crate) struct AnyCase<'a> {
    /// The log's line number, from 1.
    pub line: usize,
    /// The problem: W, N, the indices, the convention.
    pub request: &'a Request,
    /// What the student's code gave (`None`: it reported total internal reflection).
    pub yours: Option<[f64; 3]>,
}

/// The tolerance of a test in `precision`.
fn any_tolerance(precision: Precision) -> &'static str {
    match precision {
        Precision::F32 => "1e-5",
        Precision::F64 => "1e-12",
    }
}

/// One case's test body in `language`: the call with the log's arguments and the expected T
/// (the kernel's) or total internal reflection, after a comment saying what the code gave.
fn any_test(language: AnyLanguage, case: &AnyCase<'_>) -> Result<String, RequestError> {
    let r = case.request;
    let t = refract(&r.incidence::<f64>()?)?.t().map(|t| t.to_array());
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
pub(crate) fn any_renderer_tests(
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
