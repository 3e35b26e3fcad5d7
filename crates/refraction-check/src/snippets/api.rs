//! A call checked in the student's own API, copied back as a unit test in their language: GLSL,
//! C++ with pbrt-v4's `Refract` (a `GoogleTest` case, as pbrt's own tests are), C++ with the
//! book's `refract` and `cannot_refract`, or Python (pytest: the student's own `refract` with
//! the API's signature, or Mitsuba's Python bindings). Each passes the arguments as they were
//! logged and asserts what the API returns for them (the `api_result` of `check --api`), so the
//! test holds against the real API and fails against an implementation of it that differs;
//! when the call's arguments were wrong, a comment gives the right call and the right T.

use refraction_kernel::api::{Api, Args};
use serde_json::Value as Json;

use super::{literal, vector};
use crate::call_check::fields::names;
use crate::call_check::{Call, CallVerdict, Code};
use refraction_tools::Precision;

/// The language a test is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Language {
    /// A GLSL function returning whether the built-in `refract` gives the expected vector.
    Glsl,
    /// C++ with pbrt-v4's `Refract(wi, n, eta, &etap, &wt)`, as a `GoogleTest` case.
    CppPbrt,
    /// C++ with the book's `refract(uv, n, etai_over_etat)` and `cannot_refract`.
    CppBook,
    /// Python (pytest).
    Python,
}

impl Language {
    /// The copy button's label.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Glsl => "GLSL test",
            Self::CppPbrt => "C++ test (pbrt's Refract)",
            Self::CppBook => "C++ test (the book's refract)",
            Self::Python => "Python test",
        }
    }

    /// The languages a student of `api` writes tests in: the API's own, then Python.
    #[must_use]
    pub fn of(api: Api) -> &'static [Self] {
        match api {
            Api::Glsl => &[Self::Glsl, Self::Python],
            Api::Pbrt => &[Self::CppPbrt, Self::Python],
            Api::Rtiow => &[Self::CppBook, Self::Python],
            Api::Mitsuba => &[Self::Python],
        }
    }
}

/// A checked call, as the test needs it.
#[derive(Clone, Copy, Debug)]
pub struct ApiCase<'a> {
    /// The API called.
    pub api: Api,
    /// The arguments as logged.
    pub args: Args<f64>,
    /// What the API returns for them, in its own shape (`check --api`'s `api_result`).
    pub returned: &'a Json,
    /// The precision the student's code computes in: the test's tolerance.
    pub precision: Precision,
    /// The mistakes found in the call.
    pub mistakes: &'a [Code],
    /// The right arguments for the ray, in the API's convention.
    pub right: Args<f64>,
    /// The physically right T (`None` on total internal reflection).
    pub t: Option<[f64; 3]>,
}

impl<'a> ApiCase<'a> {
    /// The case of a judged call: its arguments and what the API returns for them, and the
    /// right call for its ray ([`right_args`]).
    #[must_use]
    pub fn of(call: &'a Call, verdict: &'a CallVerdict) -> Self {
        Self {
            api: call.api,
            args: call.args,
            returned: &verdict.api_result,
            precision: call.precision,
            mistakes: &verdict.mistakes,
            right: right_args(call, verdict),
            t: verdict.t,
        }
    }
}

/// The right arguments for a judged call's ray in its API's convention: the normal facing the
/// ray, and the ratio the ray's media give.
#[must_use]
pub fn right_args(call: &Call, verdict: &CallVerdict) -> Args<f64> {
    let m = verdict.right;
    let facing = if m.travel.dot(m.normal) > 0.0 {
        -m.normal
    } else {
        m.normal
    };
    call.api.arguments::<f64>(m.travel, facing, m.mu)
}

/// Field `key` of the API's answer as a finite vector (`None`: absent, null or NaN).
fn vector_at(json: &Json, key: Option<&str>) -> Option<[f64; 3]> {
    let value = key.map_or(Some(json), |k| json.get(k))?;
    let items = value.as_array().filter(|a| a.len() == 3)?;
    let mut out = [0.0; 3];
    for (slot, item) in out.iter_mut().zip(items) {
        *slot = item.as_f64().filter(|x| x.is_finite())?;
    }
    Some(out)
}

fn number_at(json: &Json, key: &str) -> Option<f64> {
    json.get(key).and_then(Json::as_f64)
}

/// What the API returns, reduced to what a test asserts: the transmitted vector or `None`
/// where the API says nothing is transmitted.
fn transmitted(case: &ApiCase<'_>) -> Option<[f64; 3]> {
    let r = case.returned;
    match case.api {
        Api::Glsl => vector_at(r, None).filter(|v| *v != [0.0; 3]),
        Api::Pbrt => vector_at(r, Some("wt")),
        Api::Rtiow => {
            let cannot = r.get("cannot_refract").and_then(Json::as_bool) != Some(false);
            vector_at(r, Some("refracted")).filter(|_| !cannot)
        }
        Api::Mitsuba => vector_at(r, Some("wo")).filter(|_| number_at(r, "F") < Some(1.0)),
    }
}

/// The tolerance of the comparison: a few units in the last place of the student's precision.
fn tolerance(precision: Precision) -> &'static str {
    match precision {
        Precision::F32 => "1e-5",
        Precision::F64 => "1e-12",
    }
}

/// The comment lines that open every test: where it comes from and, for a wrong call, the
/// right one.
fn header(case: &ApiCase<'_>, comment: &str) -> String {
    let mut lines = vec![format!(
        "{comment} {} as logged, checked by refraction-explorer: the expected value is what the \
         API returns for these arguments.",
        case.api.signature()
    )];
    let wrong: Vec<&str> = case.mistakes.iter().map(|c| c.name()).collect();
    if !wrong.is_empty() {
        let n = names(case.api);
        let t = case.t.map_or_else(
            || "no refracted ray (total internal reflection)".to_owned(),
            |t| format!("T = ({})", vector(t)),
        );
        lines.push(format!("{comment} Mistakes found: {}.", wrong.join(", ")));
        lines.push(format!(
            "{comment} The right call for this ray: {} = ({}), {} = ({}), {} = {}; it gives {t}.",
            n.incident,
            vector(case.right.incident),
            n.normal,
            vector(case.right.normal),
            n.eta,
            literal(case.right.eta),
        ));
    }
    format!("{}\n", lines.join("\n"))
}

/// A test's name: the one checked call's, or a logged line's in a file of many.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Name {
    /// The call checked in the panel.
    Checked,
    /// The call on this line of a log (from 1).
    Line(usize),
}

impl Name {
    /// The name in `snake_case` after `prefix` (`test_refract`, `test_refract_line_42`).
    fn snake(self, prefix: &str) -> String {
        match self {
            Self::Checked => prefix.to_owned(),
            Self::Line(line) => format!("{prefix}_line_{line}"),
        }
    }

    /// The name in `CamelCase` (`CheckedCall`, `Line42`), as `GoogleTest` names its cases.
    fn camel(self) -> String {
        match self {
            Self::Checked => "CheckedCall".to_owned(),
            Self::Line(line) => format!("Line{line}"),
        }
    }
}

fn glsl(case: &ApiCase<'_>, name: Name) -> String {
    let Args {
        incident,
        normal,
        eta,
    } = case.args;
    let expected = transmitted(case).map_or_else(
        || "vec3(0.0)  /* the zero vector: total internal reflection */".to_owned(),
        |v| format!("vec3({})", vector(v)),
    );
    format!(
        "{}bool {}() {{\n    vec3 I = vec3({});\n    vec3 N = vec3({});\n    \
         float eta = {};\n    vec3 expected = {expected};\n    vec3 result = refract(I, N, eta);\n    \
         return all(lessThanEqual(abs(result - expected), vec3({})));\n}}\n",
        header(case, "//"),
        name.snake("test_refract"),
        vector(incident),
        vector(normal),
        literal(eta),
        tolerance(case.precision),
    )
}

/// What a C++ file of pbrt tests includes once.
const PBRT_PREAMBLE: &str =
    "#include <gtest/gtest.h>\n#include <pbrt/util/scattering.h>\n\nusing namespace pbrt;\n\n";

fn cpp_pbrt(case: &ApiCase<'_>, name: Name) -> String {
    let Args {
        incident,
        normal,
        eta,
    } = case.args;
    let tol = format!("{}f", tolerance(case.precision));
    let call = "Refract(wi, n, eta, &etap, &wt)";
    let checks = match (transmitted(case), number_at(case.returned, "etap")) {
        (Some(wt), Some(etap)) => format!(
            "    ASSERT_TRUE({call});\n    EXPECT_NEAR(wt.x, {}, {tol});\n    \
             EXPECT_NEAR(wt.y, {}, {tol});\n    EXPECT_NEAR(wt.z, {}, {tol});\n    \
             EXPECT_NEAR(etap, {}, {tol});\n",
            literal(wt[0]),
            literal(wt[1]),
            literal(wt[2]),
            literal(etap)
        ),
        _ => format!(
            "    // Total internal reflection: Refract returns false.\n    EXPECT_FALSE({call});\n"
        ),
    };
    format!(
        "{}TEST(Refract, {}) {{\n    Vector3f wi({});\n    Normal3f n({});\n    \
         Float eta = {};\n    Float etap;\n    Vector3f wt;\n{checks}}}\n",
        header(case, "//"),
        name.camel(),
        vector(incident),
        vector(normal),
        literal(eta),
    )
}

/// What a C++ file of the book's tests includes once.
const BOOK_PREAMBLE: &str = "#include <cassert>\n#include <cmath>\n#include \"vec3.h\"\n\n";

fn cpp_book(case: &ApiCase<'_>, name: Name) -> String {
    let Args {
        incident,
        normal,
        eta,
    } = case.args;
    let checks = transmitted(case).map_or_else(
        || "    // Past the critical angle: dielectric::scatter reflects instead.\n    assert(cannot_refract);\n".to_owned(),
        |v| {
            format!(
                "    assert(!cannot_refract);\n    vec3 refracted = refract(uv, n, etai_over_etat);\n    \
                 vec3 expected({});\n    assert((refracted - expected).length() < {});\n",
                vector(v),
                tolerance(case.precision)
            )
        },
    );
    format!(
        "{}static void {}() {{\n    \
         vec3 uv({});\n    vec3 n({});\n    double etai_over_etat = {};\n    \
         // dielectric::scatter's test (material.h).\n    \
         double cos_theta = std::fmin(dot(-uv, n), 1.0);\n    \
         double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);\n    \
         bool cannot_refract = etai_over_etat * sin_theta > 1.0;\n{checks}}}\n",
        header(case, "//"),
        name.snake("test_refract"),
        vector(incident),
        vector(normal),
        literal(eta),
    )
}
/// The Python lines that call and assert, per API: the student's own `refract` with the
/// API's signature, or Mitsuba's bindings.
fn python_body(case: &ApiCase<'_>, close: &str) -> String {
    let expected = transmitted(case);
    let near = |name: &str, v: [f64; 3]| format!("    assert {close}({name}, ({}))\n", vector(v));
    match (case.api, expected) {
        (Api::Glsl, Some(v)) => format!("    result = refract(I, N, eta)\n{}", near("result", v)),
        (Api::Glsl, None) => "    # Total internal reflection: the zero vector.\n    result = refract(I, N, eta)\n    assert close(result, (0.0, 0.0, 0.0))\n".replace("close", close),
        (Api::Pbrt, Some(v)) => format!("    result = refract(wi, n, eta)  # (wt, etap), None on TIR\n    assert result is not None\n    wt, etap = result\n{}", near("wt", v)),
        (Api::Pbrt, None) => "    # Total internal reflection: pbrt's Refract returns false.\n    assert refract(wi, n, eta) is None\n".to_owned(),
        (Api::Rtiow, v) => {
            let tail = v.map_or_else(
                || "    assert cannot_refract\n".to_owned(),
                |v| format!("    assert not cannot_refract\n    refracted = refract(uv, n, etai_over_etat)\n{}", near("refracted", v)),
            );
            format!(
                "    cos_theta = min(-sum(a * b for a, b in zip(uv, n)), 1.0)\n    \
                 cannot_refract = etai_over_etat * math.sqrt(1.0 - cos_theta * cos_theta) > 1.0\n{tail}"
            )
        }
        (Api::Mitsuba, v) => {
            let local = case.args.normal.to_array() == [0.0, 0.0, 1.0];
            let (cos, refract) = if local {
                ("mi.Frame3f.cos_theta(wi)", "mi.refract(wi, cos_theta_t, eta_ti)")
            } else {
                ("dr.dot(wi, n)", "mi.refract(wi, n, cos_theta_t, eta_ti)")
            };
            let f = number_at(case.returned, "F").unwrap_or(1.0);
            let tail = v.map_or_else(
                || "    assert F == 1.0  # total internal reflection: it never transmits\n".to_owned(),
                |v| format!("    assert abs(F - {}) < {}\n    wo = {refract}\n{}", literal(f), tolerance(case.precision), near("wo", v)),
            );
            format!("    F, cos_theta_t, eta_it, eta_ti = mi.fresnel({cos}, eta)\n{tail}")
        }
    }
}

/// What a Python file of `api`'s tests imports and defines once, for `precision`.
fn python_preamble(api: Api, precision: Precision) -> String {
    let imports = match api {
        Api::Mitsuba => {
            "import drjit as dr\nimport mitsuba as mi\n\nmi.set_variant(\"scalar_rgb\")\n"
                .to_owned()
        }
        _ => format!(
            "import math\n\nfrom renderer import refract  # your {}: change the module\n",
            api.signature()
        ),
    };
    let tol = tolerance(precision);
    format!(
        "{imports}\n\ndef close(a, b):\n    return all(abs(x - y) <= {tol} for x, y in zip(a, b))\n"
    )
}

fn python(case: &ApiCase<'_>, name: Name) -> String {
    let n = names(case.api);
    let Args {
        incident,
        normal,
        eta,
    } = case.args;
    let vec = if case.api == Api::Mitsuba {
        "mi.Vector3f"
    } else {
        ""
    };
    format!(
        "\n\n{}def {}():\n    {} = {vec}({})\n    {} = {vec}({})\n    {} = {}\n{}",
        header(case, "#"),
        name.snake("test_refract"),
        n.incident,
        vector(incident),
        n.normal,
        vector(normal),
        n.eta,
        literal(eta),
        python_body(case, "close"),
    )
}

/// The test of one case in `language`, named `name` (without what its file includes once).
fn one(language: Language, case: &ApiCase<'_>, name: Name) -> String {
    match language {
        Language::Glsl => glsl(case, name),
        Language::CppPbrt => cpp_pbrt(case, name),
        Language::CppBook => cpp_book(case, name),
        Language::Python => python(case, name),
    }
}

/// A file of tests in `language`, one per case and named by it, with what they include once
/// before them and, for the book's C++, a `main` that runs them.
#[must_use]
pub(crate) fn file(language: Language, cases: &[(Name, ApiCase<'_>)]) -> String {
    let Some((_, first)) = cases.first() else {
        return String::new();
    };
    let mut text = match language {
        Language::Glsl => String::new(),
        Language::CppPbrt => PBRT_PREAMBLE.to_owned(),
        Language::CppBook => BOOK_PREAMBLE.to_owned(),
        Language::Python => {
            // One tolerance for the file: the loosest precision's, so no f32 line fails by
            // its rounding.
            let loosest = cases
                .iter()
                .map(|(_, c)| c.precision)
                .find(|p| *p == Precision::F32)
                .unwrap_or(first.precision);
            python_preamble(first.api, loosest)
        }
    };
    let tests: Vec<String> = cases
        .iter()
        .map(|(name, case)| one(language, case, *name))
        .collect();
    let between = if language == Language::Python {
        ""
    } else {
        "\n"
    };
    text.push_str(&tests.join(between));
    if language == Language::CppBook {
        text.push('\n');
        text.push_str(&super::cpp_main(
            cases.iter().map(|(name, _)| name.snake("test_refract")),
        ));
    }
    text
}

/// The checked call as a unit test in `language`.
#[must_use]
pub fn test(language: Language, case: &ApiCase<'_>) -> String {
    file(language, &[(Name::Checked, *case)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call_check::{Options, Record, check_record};

    /// The test of a logged line, with the verdict's own fields.
    fn snippet(api: Api, line: &str, language: Language) -> String {
        let record = Record::from_json_line(api, line).unwrap();
        let (call, d) = check_record(&record, &Options::new(api)).unwrap();
        let right = api.arguments::<f64>(d.right.travel, d.right.normal, d.right.mu);
        test(
            language,
            &ApiCase {
                api,
                args: call.args,
                returned: &d.api_result,
                precision: call.precision,
                mistakes: &d.mistakes,
                right,
                t: d.t,
            },
        )
    }

    #[test]
    fn a_glsl_test_carries_the_arguments_the_api_result_and_the_right_call() {
        let line = r#"{"I":[0.3,-0.953939,0],"N":[0,1,0],"eta":1.5,"result":[0.45,-0.893029,0],"from":1,"to":1.5}"#;
        let glsl = snippet(Api::Glsl, line, Language::Glsl);
        assert!(
            glsl.contains("vec3 I = vec3(0.3, -0.953939, 0.0);"),
            "{glsl}"
        );
        assert!(glsl.contains("float eta = 1.5;"), "{glsl}");
        // GLSL's own answer for eta = 1.5 in f32, widened exactly.
        assert!(
            glsl.contains("vec3 expected = vec3(0.45000001788139343, -0.8930281400680542, 0.0);"),
            "{glsl}"
        );
        assert!(glsl.contains("Mistakes found: eta_inverted."), "{glsl}");
        assert!(glsl.contains("eta = 0.666666"), "{glsl}");
        assert!(glsl.contains("vec3(1e-5)"), "{glsl}");
        let python = snippet(Api::Glsl, line, Language::Python);
        assert!(python.contains("    eta = 1.5\n"), "{python}");
        assert!(
            python
                .contains("assert close(result, (0.45000001788139343, -0.8930281400680542, 0.0))"),
            "{python}"
        );
    }

    #[test]
    fn pbrt_and_the_book_assert_their_own_tir_signals() {
        let tir = r#"{"wi":[-0.9,0.43588989435406733,0],"n":[0,1,0],"eta":0.6666666666666666,"returned":false}"#;
        let cpp = snippet(Api::Pbrt, tir, Language::CppPbrt);
        assert!(
            cpp.contains("Vector3f wi(-0.9, 0.43588989435406733, 0.0);"),
            "{cpp}"
        );
        assert!(
            cpp.contains("EXPECT_FALSE(Refract(wi, n, eta, &etap, &wt));"),
            "{cpp}"
        );
        let right =
            r#"{"wi":[-0.6,0.8,0],"n":[0,1,0],"eta":1.5,"returned":true,"wt":[0.4,-0.916515,0]}"#;
        let cpp = snippet(Api::Pbrt, right, Language::CppPbrt);
        assert!(cpp.contains("ASSERT_TRUE(Refract("), "{cpp}");
        assert!(cpp.contains("EXPECT_NEAR(etap, 1.5, 1e-5f);"), "{cpp}");
        assert!(!cpp.contains("Mistakes found"), "{cpp}");
        let book = r#"{"uv":[0.9,-0.43588989435406733,0],"n":[0,1,0],"etai_over_etat":1.5,"refracted":[1,0,0]}"#;
        let cpp = snippet(Api::Rtiow, book, Language::CppBook);
        assert!(cpp.contains("double etai_over_etat = 1.5;"), "{cpp}");
        assert!(cpp.contains("    assert(cannot_refract);"), "{cpp}");
        let python = snippet(Api::Rtiow, book, Language::Python);
        assert!(python.contains("    assert cannot_refract\n"), "{python}");
    }

    #[test]
    fn mitsuba_uses_its_python_bindings_in_the_local_frame() {
        let line = r#"{"wi":[-0.6,0,0.8],"eta":1.5,"wo":[0.4,0,-0.916515]}"#;
        let python = snippet(Api::Mitsuba, line, Language::Python);
        assert!(
            python.contains("wi = mi.Vector3f(-0.6, 0.0, 0.8)"),
            "{python}"
        );
        assert!(
            python.contains("mi.fresnel(mi.Frame3f.cos_theta(wi), eta)"),
            "{python}"
        );
        assert!(
            python.contains("wo = mi.refract(wi, cos_theta_t, eta_ti)"),
            "{python}"
        );
        assert!(python.contains("assert close(wo, (0.4"), "{python}");
        assert_eq!(Language::of(Api::Mitsuba), &[Language::Python]);
    }
}
