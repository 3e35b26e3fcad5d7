//! Logs printed the way other ecosystems print them (issue 43), each emulated from the
//! ecosystem's public documentation or source: the diagnosis must read them, call no right
//! line wrong at their printed precision, and still name a student's mistake.

use glam::{DVec3, Vec3};
use refraction_kernel::api::{Api, Args, Returned};
use serde_json::Value;

use super::{Format, Options, Pattern, Session};
use crate::diagnosis::Summary;

/// A small deterministic generator (`SplitMix64`), so that every run sees the same log.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    pub(super) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        #[expect(clippy::cast_precision_loss)]
        let unit = (z >> 11) as f64 / (1_u64 << 53) as f64;
        unit
    }

    /// A direction uniformly on the sphere.
    pub(super) fn direction(&mut self) -> DVec3 {
        let z = 2.0 * self.next() - 1.0;
        let phi = core::f64::consts::TAU * self.next();
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

/// One hit of a glass (n = 1.5) object in the student's right code: the incident direction,
/// the normal turned to face it, the ratio `n_from / n_to`, and whether the ray enters.
pub(super) struct Hit {
    pub(super) incident: Vec3,
    pub(super) normal: Vec3,
    pub(super) eta: f32,
    pub(super) entering: bool,
}

impl Hit {
    pub(super) fn random(rng: &mut Rng) -> Self {
        let incident = rng.direction();
        let outward = rng.direction();
        let entering = outward.dot(incident) < 0.0;
        let normal = if entering { outward } else { -outward };
        Self {
            incident: incident.as_vec3(),
            normal: normal.as_vec3(),
            eta: if entering { 1.0 / 1.5 } else { 1.5 },
            entering,
        }
    }

    /// GLSL's `refract` of these arguments in single precision, as the student's shader or
    /// C# port computes it.
    pub(super) fn refracted(&self, eta: f32) -> Vec3 {
        let args = Args {
            incident: self.incident,
            normal: self.normal,
            eta,
        };
        match Api::Glsl.call(args) {
            Returned::Glsl(v) => v,
            _ => unreachable!("GLSL returns a vector"),
        }
    }
}

/// A vector as Unity's `Vector3.ToString(format)` prints it: "(x, y, z)", each C# `float`
/// with the "F<decimals>" format. `ToString()` with no format is "F2", two digits after the
/// point (Unity's `ScriptReference`, `Vector3.ToString`: "Defaults to two digits displayed
/// (format="F2")"; `UnityCsReference`, Runtime/Export/Math/Vector3.cs,
/// `ToString(string format, IFormatProvider formatProvider)`). .NET rounds the value to that
/// many decimals and keeps the sign of a negative that rounds to zero ("-0.00").
fn unity_vector(v: Vec3, decimals: usize) -> String {
    let [x, y, z] = v.to_array().map(|x| format!("{x:.decimals$}"));
    format!("({x}, {y}, {z})")
}

/// A log of `count` hits, each printed by `Debug.Log` as a Unity script writes it: the
/// vectors with `Vector3.ToString()`, the float ratio with `float.ToString()` (the shortest
/// text that reads back as the float), the flag as C#'s `bool.ToString()` ("True", "False").
/// `eta_of` is the ratio the student's code passes; `decimals` those of the vectors' format.
fn unity_log(count: usize, decimals: usize, eta_of: impl Fn(&Hit) -> f32) -> String {
    let mut rng = Rng(43);
    let mut log = String::new();
    for _ in 0..count {
        let hit = Hit::random(&mut rng);
        let eta = eta_of(&hit);
        let entering = if hit.entering { "True" } else { "False" };
        log.push_str(&format!(
            "refract I={} N={} eta={eta} entering={entering} -> {}\n",
            unity_vector(hit.incident, decimals),
            unity_vector(hit.normal, decimals),
            unity_vector(hit.refracted(eta), decimals),
        ));
    }
    log
}

/// The answers and the summary of `log` read with `pattern` as `check --api glsl --inside 1.5
/// --outside 1` reads it.
fn check_glsl(pattern: &str, log: &str) -> (Vec<Value>, Summary) {
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Api::Glsl)
    };
    let pattern = Pattern::parse(Api::Glsl, pattern).unwrap();
    check_log(options, Format::Pattern(pattern), log)
}

/// The answers and the summary of `log` read in `format` with `options`.
pub(super) fn check_log(options: Options, format: Format, log: &str) -> (Vec<Value>, Summary) {
    let mut session = Session::new(options, format, false, false);
    let mut out = Vec::new();
    session.run(log.as_bytes(), &mut out, 1).unwrap();
    let answers = String::from_utf8(out)
        .unwrap()
        .lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect();
    (answers, session.summary())
}

const UNITY_PATTERN: &str = "refract I={I} N={N} eta={eta} entering={entering} -> {result}";

fn named(answer: &Value) -> bool {
    answer["mistakes"].as_array().is_some_and(|m| !m.is_empty())
}

/// Whether a line is neither right nor given a mistake: its digits cannot tell.
fn undecided(answer: &Value) -> bool {
    answer["ok"] == false && !named(answer)
}

#[test]
fn unity_two_decimals_never_call_a_right_line_wrong() {
    let (answers, summary) = check_glsl(UNITY_PATTERN, &unity_log(3300, 2, |hit| hit.eta));
    assert_eq!(answers.len(), 3300);
    let wrong: Vec<&Value> = answers.iter().filter(|a| named(a)).collect();
    assert!(wrong.is_empty(), "right lines called wrong: {wrong:#?}");
    let undecided = answers.iter().filter(|a| undecided(a)).count();
    // The log has grazing and near-critical hits whose signs two decimals cannot decide.
    assert!(undecided > 0, "no line exercised the printed precision");
    assert!(undecided < 330, "{undecided} of 3300 lines left undecided");
    let verdict = &summary.diagnosis[0];
    assert_eq!(verdict.code, "too_few_digits", "{summary:#?}");
    assert_eq!(verdict.lines, undecided);
    assert_eq!(summary.ok + undecided, 3300);
    assert!(verdict.fix.contains("ToString(\"F6\")"), "{}", verdict.fix);
    assert_eq!(summary.verdict(), crate::Verdict::Unchecked);
}

#[test]
fn unity_two_decimals_still_name_an_inverted_ratio() {
    let (answers, summary) = check_glsl(UNITY_PATTERN, &unity_log(3300, 2, |hit| 1.0 / hit.eta));
    assert_eq!(summary.diagnosis[0].code, "eta_inverted", "{summary:#?}");
    let named_lines = answers.iter().filter(|a| named(a)).count();
    assert!(named_lines > 3000, "only {named_lines} lines named");
}

#[test]
fn no_printed_precision_calls_a_right_line_wrong() {
    for decimals in 1..=6 {
        let (answers, summary) =
            check_glsl(UNITY_PATTERN, &unity_log(1000, decimals, |hit| hit.eta));
        let wrong = answers.iter().filter(|a| named(a)).count();
        assert_eq!(
            wrong, 0,
            "{decimals} decimals: {wrong} right lines called wrong"
        );
        assert_ne!(
            summary.verdict(),
            crate::Verdict::Mistake,
            "{decimals} decimals"
        );
        let undecided = answers.iter().filter(|a| undecided(a)).count();
        // From one decimal, where almost nothing can be told, to six, where everything can.
        match decimals {
            1 => assert!(undecided > 900, "{undecided} undecided at one decimal"),
            6 => assert_eq!(undecided, 0, "six decimals decide every line"),
            _ => assert!(
                undecided < 20,
                "{undecided} undecided at {decimals} decimals"
            ),
        }
    }
}

/// A log of `count` hits of a Rust port of the book's `refract` on `f32` (glam's `Vec3`),
/// each line printed with `println!("{} {} {}", ...)` per vector: Rust prints an `f32` as the
/// shortest text that reads back as it (`core::fmt::float`, `float_to_decimal_display`), eight
/// or nine digits where a double shows sixteen. Only calls of `refract` are logged.
fn rust_f32_log(count: usize) -> String {
    let mut rng = Rng(1718);
    let mut log = String::new();
    let v = |v: Vec3| format!("{} {} {}", v.x, v.y, v.z);
    while log.lines().count() < count {
        let hit = Hit::random(&mut rng);
        // The book normalises in the renderer's own precision: its lengths are off by an ulp.
        let (uv, n) = (hit.incident.normalize(), hit.normal.normalize());
        let args = Args {
            incident: uv,
            normal: n,
            eta: hit.eta,
        };
        let Returned::Rtiow(answer) = Api::Rtiow.call(args) else {
            unreachable!("the book's refract")
        };
        // dielectric::scatter reflects where it cannot refract, and logs only refract's calls.
        if answer.cannot_refract {
            continue;
        }
        log.push_str(&format!(
            "uv={} n={} ratio={} front_face={} refracted={}\n",
            v(uv),
            v(n),
            hit.eta,
            hit.entering,
            v(answer.refracted),
        ));
    }
    log
}

#[test]
fn f32_code_printed_in_full_is_judged_in_f32() {
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Api::Rtiow)
    };
    let pattern = Pattern::parse(
        Api::Rtiow,
        "uv={uv} n={n} ratio={etai_over_etat} front_face={entering} refracted={refracted}",
    )
    .unwrap();
    let log = rust_f32_log(1718);
    // Its vectors' lengths are off by more than their printed digits allow a double.
    let lengths_off = log
        .lines()
        .filter(|line| {
            let uv: Vec<f64> = line[3..line.find(" n=").unwrap()]
                .split(' ')
                .map(|x| x.parse().unwrap())
                .collect();
            (DVec3::new(uv[0], uv[1], uv[2]).length() - 1.0).abs() > 2e-8
        })
        .count();
    assert!(lengths_off > 300, "only {lengths_off} lines exercise f32");
    let mut session = Session::new(options, Format::Pattern(pattern), false, false);
    let mut out = Vec::new();
    session.run(log.as_bytes(), &mut out, 1).unwrap();
    let out = String::from_utf8(out).unwrap();
    let wrong: Vec<&str> = out.lines().filter(|l| l.contains("\"ok\":false")).collect();
    assert!(
        wrong.is_empty(),
        "{} lines wrong: {:?}",
        wrong.len(),
        wrong.first()
    );
    assert_eq!(session.summary().diagnosis[0].code, "none");
}

/// A `Vector3d` as Eigen's `std::cout << v` prints it: one coefficient a row, each right-
/// aligned to the widest at the stream's precision, 6 significant digits (Eigen, Eigen/src/
/// Core/IO.h, `print_matrix` with the default `IOFormat`).
fn eigen_column(v: DVec3) -> String {
    let texts = v.to_array().map(|x| {
        let text = format!("{x:.6}");
        let text = text.trim_end_matches('0').trim_end_matches('.');
        if text == "-0" {
            "0".to_owned()
        } else {
            text.to_owned()
        }
    });
    let width = texts.iter().map(String::len).max().unwrap_or(0);
    texts.map(|t| format!("{t:>width$}")).join("\n")
}

#[test]
fn eigen_column_vectors_are_refused_with_what_to_print() {
    let (d, n, t) = (
        DVec3::new(0.642_788, -0.766_044, 0.0),
        DVec3::Y,
        DVec3::new(0.428_525, -0.903_53, 0.0),
    );
    let log = format!(
        "d =\n{}\nn =\n{}\ninto 1\nt =\n{}\n",
        eigen_column(d),
        eigen_column(n),
        eigen_column(t)
    );
    let lines: Vec<&str> = log.lines().collect();
    assert_eq!(
        super::suggest::suggest(super::Dialect::Physics, &lines),
        None
    );
    assert!(super::suggest::column_printed(&lines));
    // A vector a pattern reads over its column's lines is refused, never joined wrong.
    let column = eigen_column(d);
    let read = super::record::from_text(super::fields::Kind::Vector, "w", &column);
    let error = read.expect_err("a column vector was read");
    assert!(
        matches!(error, super::LineError::ColumnVector { .. }),
        "{error:?}"
    );
    assert!(error.to_string().contains("v.transpose()"), "{error}");
    // The same numbers on one line are read.
    let row = column.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(super::record::from_text(super::fields::Kind::Vector, "w", &row).is_ok());
}

const SMALLPT_PATTERN: &str = "REFR d=({w}) nl=({n}) into={entering} tdir=({t_yours})";

#[test]
fn any_renderer_s_two_decimal_log_calls_no_right_line_wrong() {
    // smallpt's own refraction printed with printf("%.2f"): read by `check` without --api.
    let mut rng = Rng(2);
    let v = |v: Vec3| format!("{:.2} {:.2} {:.2}", v.x, v.y, v.z);
    let mut log = String::new();
    for _ in 0..1000 {
        let hit = Hit::random(&mut rng);
        let t = hit.refracted(hit.eta);
        if t == Vec3::ZERO {
            continue; // smallpt reflects there and prints no refraction
        }
        let into = u8::from(hit.entering);
        let (d, n) = (v(hit.incident), v(hit.normal));
        log.push_str(&format!(
            "REFR d=({d}) nl=({n}) into={into} tdir=({})\n",
            v(t)
        ));
    }
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(super::Dialect::Physics)
    };
    let pattern = Pattern::parse(super::Dialect::Physics, SMALLPT_PATTERN).unwrap();
    let mut session = Session::new(options, Format::Pattern(pattern), false, false);
    let mut out = Vec::new();
    session.run(log.as_bytes(), &mut out, 1).unwrap();
    let answers: Vec<Value> = String::from_utf8(out)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let wrong: Vec<&Value> = answers.iter().filter(|a| named(a)).collect();
    assert!(
        wrong.is_empty(),
        "{} right lines called wrong: {:?}",
        wrong.len(),
        wrong.first()
    );
    assert_ne!(session.summary().verdict(), crate::Verdict::Mistake);
}
