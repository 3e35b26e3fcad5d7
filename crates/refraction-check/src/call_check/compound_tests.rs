//! Compound bugs (issue 43, item 4) in logs printed the way their ecosystems print them:
//! refracting twice at one crossing, and the side decided with the geometric normal while
//! `refract` gets the shading one. Each emulates the call from the API's public definition,
//! injects the bug, and checks that the diagnosis names the cause and no other, and that the
//! right log of the same kind is clean. (The cosine's sign lost in the Fresnel code is tried on
//! Mitsuba 3's `fresnel` among the integration tests' renderer families.)

use glam::{DVec3, Vec3};
use refraction_kernel::api::Api;
use serde_json::Value;

use super::ecosystem_tests::{Hit, Rng, check_log};
use super::{Dialect, Format, Options, Pattern};
use crate::diagnosis::{Renderer, Summary};

/// A vector as `debugPrintfEXT("(%f, %f, %f)", v.x, v.y, v.z)` prints it: C's `%f`, six
/// decimals, `nan` for a NaN.
fn printf_vector(v: Vec3) -> String {
    let c_fixed = |c: f32| {
        if c.is_nan() {
            "nan".to_owned()
        } else {
            format!("{c:.6}")
        }
    };
    let [x, y, z] = v.to_array().map(c_fixed);
    format!("({x}, {y}, {z})")
}

/// One call as the shader prints it: `debugPrintfEXT("refract I=(%f, %f, %f) N=(%f, %f, %f)
/// eta=%f entering=%d -> (%f, %f, %f)", ...)`, or without `entering` when `sided` is false.
fn shader_line(hit: &Hit, t: Vec3, sided: bool) -> String {
    let (i, n) = (printf_vector(hit.incident), printf_vector(hit.normal));
    let side = if sided {
        format!(" entering={}", u8::from(hit.entering))
    } else {
        String::new()
    };
    let eta = hit.eta;
    format!(
        "refract I={i} N={n} eta={eta:.6}{side} -> {}\n",
        printf_vector(t)
    )
}

/// The answers and summary of a shader's log, read as `check --api glsl --inside 1.5 --outside
/// 1 --pattern ...` (with `entering` in the pattern when `sided`), fixes in `renderer`'s words.
fn check_shader(log: &str, sided: bool, renderer: Option<Renderer>) -> (Vec<Value>, Summary) {
    let pattern = if sided {
        "refract I={I} N={N} eta={eta} entering={entering} -> {result}"
    } else {
        "refract I={I} N={N} eta={eta} -> {result}"
    };
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        renderer,
        ..Options::new(Api::Glsl)
    };
    let pattern = Pattern::parse(Api::Glsl, pattern).unwrap();
    check_log(options, Format::Pattern(pattern), log)
}

/// A shader's log of `count` hits of a glass (n = 1.5) object. GLSL's `refract(I, N, eta)`
/// (the GLSL 4.60 specification, 8.5 Geometric Functions) is called once per crossing, as
/// three.js's transmission shader does (`getVolumeTransmissionRay`,
/// `transmission_pars_fragment.glsl.js`: `refract( - v, normalize( n ), 1.0 / ior )`); with
/// `twice`, the result is refracted again through the same normal (`T = refract(T, N, eta)`
/// left in after the code that called it moved).
fn twice_log(count: usize, twice: bool) -> String {
    let mut rng = Rng(4304);
    (0..count)
        .map(|_| {
            let hit = Hit::random(&mut rng);
            let mut t = hit.refracted(hit.eta);
            if twice {
                let again = Hit {
                    incident: t,
                    normal: hit.normal,
                    eta: hit.eta,
                    entering: hit.entering,
                };
                t = again.refracted(hit.eta);
            }
            shader_line(&hit, t, true)
        })
        .collect()
}

fn wrong(answers: &[Value]) -> usize {
    answers.iter().filter(|a| a["ok"] == false).count()
}

/// Whether the summary names `code` as its verdict, explaining (almost) every wrong line, and
/// no other cause.
fn assert_named(answers: &[Value], summary: &Summary, code: &str) {
    let verdict = &summary.diagnosis[0];
    assert_eq!(verdict.code, code, "{:?}", summary.diagnosis);
    let wrong = wrong(answers);
    assert!(wrong > 20, "only {wrong} wrong lines");
    assert!(
        verdict.lines * 100 >= wrong * 99,
        "{} of {wrong}: {:?}",
        verdict.lines,
        summary.diagnosis
    );
    let others: Vec<&str> = summary.diagnosis[1..].iter().map(|f| f.code).collect();
    assert!(others.iter().all(|c| *c == "too_few_digits"), "{others:?}");
}

/// Whether a right log's every line is right and its verdict `none`.
fn assert_clean(answers: &[Value], summary: &Summary) {
    assert_eq!(wrong(answers), 0, "{:?}", summary.diagnosis);
    assert_eq!(summary.diagnosis[0].code, "none", "{:?}", summary.diagnosis);
}

#[test]
fn a_shader_that_refracts_twice_is_named_with_its_cause() {
    let (answers, summary) = check_shader(&twice_log(1000, true), true, None);
    assert_named(&answers, &summary, "refracted_twice");
    let fix = &summary.diagnosis[0].fix;
    assert!(
        fix.contains("refract(I, N, eta); // once per crossing"),
        "{fix}"
    );
    // A glam user (Rust) is given the line in glam's words, not GLSL's.
    let (_, glam) = check_shader(&twice_log(1000, true), true, Some(Renderer::Glam));
    let fix = &glam.diagnosis[0].fix;
    assert!(fix.contains("incident.refract(normal, eta)"), "{fix}");
    assert!(!fix.contains("vec3"), "{fix}");
    let (answers, summary) = check_shader(&twice_log(1000, false), true, None);
    assert_clean(&answers, &summary);
}

/// A teaching renderer's own `refract` on `Eigen::Vector3d`, the textbook form (as Ray Tracing
/// in One Weekend's `refract` in `vec3.h`, written with Eigen's `dot`), returning `false` on
/// total internal reflection: `d` along the ray, `n` facing it, `mu` = `n_from / n_to`.
fn eigen_refract(d: DVec3, n: DVec3, mu: f64) -> Option<DVec3> {
    let c = -d.dot(n);
    let k = 1.0 - mu * mu * (1.0 - c * c);
    (k >= 0.0).then(|| mu * d + (mu * c - k.sqrt()) * n)
}

/// An Eigen vector as `v.transpose().format(IOFormat(FullPrecision, DontAlignCols, ", ", ",
/// ", "", "", "[", "]"))` prints it: every digit that tells the double, in brackets.
fn eigen_vector(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

/// The Eigen renderer's log of `count` hits, a JSON line each (`w`, `n`, `entering`,
/// `t_yours`, `null` where it reflects), its ratio chosen by `ratio` (`n_from / n_to` when
/// right) and, with `twice`, its result refracted again.
fn eigen_log(count: usize, twice: bool, ratio: impl Fn(bool) -> f64) -> String {
    let mut rng = Rng(4306);
    let mut log = String::new();
    for _ in 0..count {
        let hit = Hit::random(&mut rng);
        let (d, n) = (hit.incident.as_dvec3(), hit.normal.as_dvec3());
        let mu = ratio(hit.entering);
        let mut t = eigen_refract(d, n, mu);
        if twice {
            t = t.and_then(|t| eigen_refract(t, n, mu));
        }
        let t = t.map_or_else(|| "null".to_owned(), eigen_vector);
        log.push_str(&format!(
            "{{\"w\": {}, \"n\": {}, \"entering\": {}, \"t_yours\": {t}}}\n",
            eigen_vector(d),
            eigen_vector(n),
            hit.entering
        ));
    }
    log
}

fn check_eigen(log: &str) -> (Vec<Value>, Summary) {
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Dialect::Physics)
    };
    check_log(options, Format::JsonLines, log)
}

/// `n_from / n_to` for glass of 1.5 in air.
fn right_ratio(entering: bool) -> f64 {
    if entering { 1.0 / 1.5 } else { 1.5 }
}

/// Whether `fix` borrows another ecosystem's code: smallpt's variables, GLSL's or Mitsuba's
/// functions, pbrt's names.
fn borrows(fix: &str) -> bool {
    [
        "nnt",
        "nc / nt",
        "into",
        "faceforward",
        "dr::",
        "cosTheta",
        "vec3(",
    ]
    .iter()
    .any(|word| fix.contains(word))
}

#[test]
fn an_eigen_renderer_that_refracts_twice_is_named_in_its_own_words() {
    let (answers, summary) = check_eigen(&eigen_log(1000, true, right_ratio));
    assert_named(&answers, &summary, "refracted_twice");
    let fix = &summary.diagnosis[0].fix;
    assert!(
        fix.contains("once per surface crossing") && !borrows(fix),
        "{fix}"
    );
    let (answers, summary) = check_eigen(&eigen_log(1000, false, right_ratio));
    assert_clean(&answers, &summary);
    // Its ratio upside down: the fix says which ratio, without smallpt's variables.
    let (_, summary) = check_eigen(&eigen_log(1000, false, |e| 1.0 / right_ratio(e)));
    let verdict = &summary.diagnosis[0];
    assert_eq!(verdict.code, "eta_inverted", "{:?}", summary.diagnosis);
    assert!(
        verdict.fix.contains("n_from / n_to") && !borrows(&verdict.fix),
        "{}",
        verdict.fix
    );
}

/// A shader with a normal map's log of `count` hits of a glass object: the geometric normal
/// `Ng` (outward) and the shading one `Ns` tilted from it by up to about 20°. The shader turns
/// `Ns` to face the ray and chooses the ratio by the side: right, `bool entering = dot(I, Ns) <
/// 0.0;`; with `mixed`, `bool entering = dot(I, Ng) < 0.0;` (the geometric normal decides),
/// then `vec3 N = entering ? Ns : -Ns; float eta = entering ? 1.0 / 1.5 : 1.5; refract(I, N,
/// eta)` either way.
fn normal_mapped_log(count: usize, mixed: bool, sided: bool) -> String {
    let mut rng = Rng(4305);
    (0..count)
        .map(|_| {
            let incident = rng.direction();
            let ng = rng.direction();
            let ns = (ng + 0.35 * rng.direction()).normalize();
            let decides = if mixed { ng } else { ns };
            let entering = incident.dot(decides) < 0.0;
            let hit = Hit {
                incident: incident.as_vec3(),
                normal: if entering { ns } else { -ns }.as_vec3(),
                eta: right_ratio(entering) as f32,
                entering,
            };
            shader_line(&hit, hit.refracted(hit.eta), sided)
        })
        .collect()
}

#[test]
fn a_side_decided_with_the_geometric_normal_is_named_where_entering_is_logged() {
    let (answers, summary) = check_shader(&normal_mapped_log(1000, true, true), true, None);
    assert_named(&answers, &summary, "normals_mixed");
    let fix = &summary.diagnosis[0].fix;
    assert!(fix.contains("same normal"), "{fix}");
    let (answers, summary) = check_shader(&normal_mapped_log(1000, false, true), true, None);
    assert_clean(&answers, &summary);
}

#[test]
fn without_entering_a_normal_that_faces_the_ray_on_most_lines_says_what_to_log() {
    let (_, summary) = check_shader(&normal_mapped_log(1000, true, false), false, None);
    let finding = summary
        .diagnosis
        .iter()
        .find(|f| f.code == "normal_not_facing")
        .unwrap_or_else(|| panic!("{:?}", summary.diagnosis));
    assert!(finding.fix.contains("`entering`"), "{}", finding.fix);
}

// Item 5 of issue 43: the fix in the words of the user's own ecosystem.

/// A Rust tracer's log of `count` hits, glam's `Vec3::refract(self, normal, eta)` (glam 0.30,
/// `src/f32/vec3.rs`: GLSL's formula, `Vec3::ZERO` past the critical angle) called with the
/// normal turned to face the ray, or, with `outward`, with the shape's outward normal on every
/// hit; each call printed with `println!("refract I={:?} N={:?} eta={:?} entering={} -> {:?}",
/// ...)` (glam's `Debug`: `Vec3(x, y, z)`).
fn glam_log(count: usize, outward: bool) -> String {
    let mut rng = Rng(4307);
    let mut log = String::new();
    for _ in 0..count {
        let mut hit = Hit::random(&mut rng);
        if outward && !hit.entering {
            hit.normal = -hit.normal;
        }
        let t = hit.refracted(hit.eta);
        let (i, n, eta, entering) = (hit.incident, hit.normal, hit.eta, hit.entering);
        log.push_str(&format!(
            "refract I={i:?} N={n:?} eta={eta:?} entering={entering} -> {t:?}\n"
        ));
    }
    log
}

#[test]
fn a_rust_tracer_on_glam_is_given_glam_s_words_not_glsl_s() {
    let log = glam_log(1000, true);
    assert!(log.starts_with("refract I=Vec3("), "{}", &log[..80]);
    let (answers, summary) = check_shader(&log, true, None);
    assert_named(&answers, &summary, "normal_not_facing");
    let fix = &summary.diagnosis[0].fix;
    assert!(fix.contains("incident.dot(normal) > 0.0"), "{fix}");
    assert!(
        !fix.contains("faceforward") && !fix.contains("vec3"),
        "{fix}"
    );
    // The per-line explanation borrows no API's function either.
    let first = answers.iter().find(|a| a["ok"] == false).unwrap();
    assert!(!first.to_string().contains("faceforward"), "{first}");
    let (answers, summary) = check_shader(&glam_log(1000, false), true, None);
    assert_clean(&answers, &summary);
    // A shader printing the same calls is still given GLSL's words.
    let (_, summary) = check_shader(&outward_shader_log(), true, None);
    assert!(summary.diagnosis[0].fix.contains("faceforward(N, I, N)"));
}

/// The glam log's calls printed by a shader (`debugPrintfEXT`) instead.
fn outward_shader_log() -> String {
    let mut rng = Rng(4307);
    (0..1000)
        .map(|_| {
            let mut hit = Hit::random(&mut rng);
            if !hit.entering {
                hit.normal = -hit.normal;
            }
            let t = hit.refracted(hit.eta);
            shader_line(&hit, t, true)
        })
        .collect()
}

#[test]
fn a_shader_whose_normalize_hides_total_internal_reflection_is_told_to_test_before_it() {
    // `vec3 T = normalize(refract(I, N, eta));`: normalize(vec3(0.0)) is NaN past the critical
    // angle, printed `nan` by debugPrintfEXT.
    let mut rng = Rng(4308);
    let log: String = (0..1000)
        .map(|_| {
            let hit = Hit::random(&mut rng);
            let t = hit.refracted(hit.eta);
            shader_line(&hit, t / t.length(), true)
        })
        .collect();
    let (answers, summary) = check_shader(&log, true, None);
    assert_named(&answers, &summary, "missed_tir");
    let fix = &summary.diagnosis[0].fix;
    assert!(fix.contains("normalize(vec3(0.0)) is NaN"), "{fix}");
    assert!(
        !fix.contains("return vec3(0.0)"),
        "not the built-in's code: {fix}"
    );
}

#[test]
fn an_own_fresnel_that_never_transmits_is_named_by_its_cosine_not_its_tir_test() {
    // The Eigen renderer's Fresnel term taken with the cosine's sign lost (`double cosi =
    // d.dot(n);` for `-d.dot(n)`): Schlick's F = R0 + (1 − R0)(1 − cosθi)⁵ ≥ 1, so every ray
    // reflects and the line logs `null`, also near normal incidence.
    let right = eigen_log(1000, false, right_ratio);
    let mut never = String::new();
    for line in right.lines() {
        never.push_str(&line[..line.find("\"t_yours\"").unwrap()]);
        never.push_str("\"t_yours\": null}\n");
    }
    let (_, summary) = check_eigen(&never);
    let verdict = &summary.diagnosis[0];
    assert_eq!(verdict.code, "fresnel_cos_sign", "{:?}", summary.diagnosis);
    assert!(
        verdict.fix.contains("|N·I|") && !borrows(&verdict.fix),
        "{}",
        verdict.fix
    );
    assert_eq!(summary.diagnosis.len(), 1, "{:?}", summary.diagnosis);
}
