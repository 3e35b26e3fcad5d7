//! The Ray Tracing in One Weekend flow end to end: a glass sphere traced the book's way
//! (`hit_record::set_face_normal`, `dielectric::scatter`, `refract`) with the book's adapter,
//! three injected bugs, a printf log of every refract call, and `check --api rtiow --pattern`
//! naming each bug on every line it touches.

use crate::cli;

use cli::{answers, run};
use glam::DVec3;
use refraction_kernel::api::rtiow;
use serde_json::Value;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Bug {
    None,
    /// `ri = rec.front_face ? refraction_index : 1.0/refraction_index`.
    EtaInverted,
    /// `set_face_normal` keeps the outward normal (`front_face` still right).
    OutwardNormal,
    /// `r_out_parallel = +sqrt(...) * n` in the student's own refract.
    FlippedSqrt,
}

const CENTRE: DVec3 = DVec3::new(0.0, 0.0, -1.0);
const RADIUS: f64 = 0.5;
const PATTERN: &str = "LOG ray {path}: {uv} | {n} | {etai_over_etat} | {refracted} | {entering}";

fn flipped_refract(uv: DVec3, n: DVec3, e: f64) -> DVec3 {
    let right = rtiow::refract::<f64>(uv, n, e);
    let cos_theta = (-uv).dot(n).min(1.0);
    let perp = (uv + n * cos_theta) * e;
    right + n * (2.0 * (1.0 - perp.length_squared()).abs().sqrt())
}

/// The far side of the sphere's surface along the ray, if it meets it.
fn hit(origin: DVec3, direction: DVec3) -> Option<DVec3> {
    let oc = CENTRE - origin;
    let a = direction.length_squared();
    let h = direction.dot(oc);
    let discriminant = h * h - a * (oc.length_squared() - RADIUS * RADIUS);
    if discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt();
    [(h - root) / a, (h + root) / a]
        .into_iter()
        .find(|&t| t > 1e-6)
        .map(|t| origin + direction * t)
}

fn v(x: DVec3) -> String {
    format!("{:.6} {:.6} {:.6}", x.x, x.y, x.z)
}

/// Traces one camera ray through the sphere, logging each refract call.
fn trace(ray: usize, mut direction: DVec3, bug: Bug, log: &mut String) {
    let mut origin = DVec3::ZERO;
    for _ in 0..6 {
        let Some(p) = hit(origin, direction) else {
            log.push_str(&format!("ray {ray} escaped\n"));
            return;
        };
        let outward = (p - CENTRE) / RADIUS;
        let front_face = direction.dot(outward) < 0.0;
        let normal = match (bug, front_face) {
            (Bug::OutwardNormal, _) | (_, true) => outward,
            (_, false) => -outward,
        };
        let ri = match (bug, front_face) {
            (Bug::EtaInverted, true)
            | (Bug::None | Bug::OutwardNormal | Bug::FlippedSqrt, false) => 1.5,
            _ => 1.0 / 1.5,
        };
        let unit = rtiow::unit_vector::<f64>(direction);
        direction = if rtiow::cannot_refract::<f64>(unit, normal, ri) {
            rtiow::reflect::<f64>(unit, normal)
        } else {
            let refracted = if bug == Bug::FlippedSqrt {
                flipped_refract(unit, normal, ri)
            } else {
                rtiow::refract::<f64>(unit, normal, ri)
            };
            log.push_str(&format!(
                "LOG ray {ray}: {} | {} | {ri:.6} | {} | {}\n",
                v(unit),
                v(normal),
                v(refracted),
                u8::from(front_face)
            ));
            refracted
        };
        origin = p;
    }
}

fn check(bug: Bug) -> (Vec<Value>, String, Option<i32>) {
    let mut log = String::from("render 40x40 samples=1\n");
    let mut ray = 0;
    for i in -3..=3 {
        for j in -3..=3 {
            ray += 1;
            let aim = DVec3::new(f64::from(i) * 0.06, f64::from(j) * 0.06, -1.0);
            trace(ray, aim, bug, &mut log);
        }
    }
    let output = run(
        &[
            "check",
            "--api",
            "rtiow",
            "--inside",
            "1.5",
            "--outside",
            "1",
            "--paths",
            "--pattern",
            PATTERN,
        ],
        &log,
    );
    let tally = String::from_utf8(output.stderr.clone()).unwrap();
    (answers(&output), tally, output.status.code())
}

fn calls(answers: &[Value]) -> Vec<&Value> {
    answers
        .iter()
        .filter(|a| a.get("mistakes").is_some())
        .collect()
}

#[test]
fn the_right_flow_is_right_on_every_line() {
    let (answers, tally, status) = check(Bug::None);
    let calls = calls(&answers);
    assert!(calls.len() > 40, "{}", calls.len());
    for call in &calls {
        assert_eq!(call["ok"], true, "{call}");
    }
    let says = |what: &str| {
        calls
            .iter()
            .any(|c| c["explanation"].as_str().unwrap().contains(what))
    };
    assert!(says("entering the object") && says("leaving the object"));
    let summaries: Vec<&Value> = answers
        .iter()
        .filter(|a| a.get("exit_ok").is_some())
        .collect();
    assert_eq!(summaries.len(), 49);
    assert!(
        summaries
            .iter()
            .all(|s| s["exit_ok"] == true && s["first_wrong"].is_null())
    );
    assert_eq!(status, Some(0), "{tally}");
    assert!(
        tally.contains("skipped (not matching the pattern)"),
        "{tally}"
    );
}

#[test]
fn an_inverted_eta_is_named_on_every_line() {
    let (answers, tally, status) = check(Bug::EtaInverted);
    for call in calls(&answers) {
        assert_eq!(call["mistakes"][0], "eta_inverted", "{call}");
        assert!(
            call["explanation"]
                .as_str()
                .unwrap()
                .contains("The book's etai_over_etat is")
        );
    }
    assert!(tally.contains("eta_inverted"), "{tally}");
    assert_eq!(status, Some(1));
}

#[test]
fn an_outward_normal_is_named_where_the_ray_leaves() {
    let (answers, _, _) = check(Bug::OutwardNormal);
    let calls = calls(&answers);
    let leaving: Vec<&&Value> = calls
        .iter()
        .filter(|c| {
            c["explanation"]
                .as_str()
                .unwrap()
                .contains("needs n against uv")
        })
        .collect();
    assert!(!leaving.is_empty() && leaving.len() < calls.len());
    for call in &calls {
        let entering_right = call["ok"] == true;
        let named =
            call["mistakes"].as_array().unwrap().first() == Some(&"normal_not_facing".into());
        assert!(entering_right || named, "{call}");
    }
}

#[test]
fn a_flipped_square_root_is_named_as_the_student_s_own_refract() {
    let (answers, _, _) = check(Bug::FlippedSqrt);
    for call in calls(&answers) {
        assert_eq!(
            call["mistakes"],
            serde_json::json!(["other_root"]),
            "{call}"
        );
        let explanation = call["explanation"].as_str().unwrap();
        assert!(
            explanation.contains("square root's sign flipped"),
            "{explanation}"
        );
        assert!(!explanation.contains("outward"), "{explanation}");
    }
}
