//! For each API and each mistake code, calls whose verdict must name it; and the two defects of
//! the old `check` that issue 11 reports.

use glam::{DVec3, Vec3};
use refraction_kernel::api::{Api, Args, Returned};
use serde_json::{Value, json};

use super::fields::names;
use super::{Code, Format, Options, Pattern, Session};

fn wide(v: Vec3) -> [f64; 3] {
    v.as_dvec3().to_array()
}

/// What the API returns for `args` in the student's usual precision, as the line's result
/// fields.
fn returned(api: Api, args: Args<f64>) -> Vec<(&'static str, Value)> {
    let args32 = Args {
        incident: args.incident.as_vec3(),
        normal: args.normal.as_vec3(),
        eta: args.eta as f32,
    };
    match api {
        Api::Rtiow => match api.call(args) {
            Returned::Rtiow(a) => vec![("refracted", json!(a.refracted.to_array()))],
            _ => unreachable!(),
        },
        _ => match api.call(args32) {
            Returned::Glsl(v) => vec![("result", json!(wide(v)))],
            Returned::Pbrt(r) => vec![
                ("returned", json!(r.is_some())),
                ("wt", r.map_or(Value::Null, |r| json!(wide(r.wt)))),
            ],
            Returned::Mitsuba(a) => vec![("wo", json!(wide(a.wo)))],
            Returned::Rtiow(_) => unreachable!(),
        },
    }
}

fn line(api: Api, args: Args<f64>, result: Vec<(&'static str, Value)>, truth: Value) -> String {
    let n = names(api);
    let mut object = json!({
        n.incident: args.incident.to_array(),
        n.normal: args.normal.to_array(),
        n.eta: args.eta,
    });
    for (name, value) in result {
        object[name] = value;
    }
    if let Value::Object(truth) = truth {
        for (name, value) in truth {
            object[name] = value;
        }
    }
    object.to_string()
}

fn options(api: Api) -> Options {
    Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(api)
    }
}

fn answer(api: Api, text: &str) -> Value {
    let reply = Session::new(options(api), Format::JsonLines, false, false)
        .answer(1, text)
        .unwrap();
    serde_json::from_str(&reply).unwrap()
}

fn mistakes(answer: &Value) -> Vec<String> {
    answer["mistakes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m.as_str().unwrap().to_owned())
        .collect()
}

/// A ray entering glass from air at 40° (leaving at 20° when `entering` is false).
fn situation(entering: bool) -> (DVec3, DVec3, f64) {
    let (angle, mu) = if entering {
        (40_f64, 1.0 / 1.5)
    } else {
        (20.0, 1.5)
    };
    let a = angle.to_radians();
    let d = DVec3::new(a.sin(), -a.cos(), 0.3).normalize();
    (d, DVec3::Y, mu)
}

/// The usual right call: for pbrt and Mitsuba the outward normal with the material's eta.
fn usual(api: Api, entering: bool) -> Args<f64> {
    let (d, n, mu) = situation(entering);
    let args = api.arguments(d, n, mu);
    match api {
        Api::Pbrt | Api::Mitsuba if !entering => Args {
            normal: -n,
            eta: 1.5,
            ..args
        },
        _ => args,
    }
}

/// The line carrying the usual right call with `mistake` made, and what the API returns for it.
fn injected(api: Api, entering: bool, mistake: impl Fn(Args<f64>) -> Args<f64>) -> String {
    let (d, _, _) = situation(entering);
    let args = mistake(usual(api, entering));
    let truth = json!({"entering": entering, "travel": d.to_array()});
    line(api, args, returned(api, args), truth)
}

#[test]
fn right_calls_are_ok_in_every_api() {
    for api in Api::ALL {
        for entering in [true, false] {
            let a = answer(api, &injected(api, entering, |args| args));
            assert_eq!(a["ok"], true, "{api:?} {a}");
            assert_eq!(a["mistakes"], json!([]), "{api:?}");
            assert_eq!(a["matches"], "chosen", "{api:?}");
        }
    }
}

#[test]
fn each_argument_mistake_is_named_in_every_api() {
    type Inject = fn(Args<f64>) -> Args<f64>;
    let cases: [(Code, Inject); 4] = [
        (Code::EtaInverted, |a| Args {
            eta: 1.0 / a.eta,
            ..a
        }),
        (Code::IncidentReversed, |a| Args {
            incident: -a.incident,
            ..a
        }),
        (Code::NormalNotFacing, |a| Args {
            normal: -a.normal,
            ..a
        }),
        (Code::NotUnitInput, |a| Args {
            incident: a.incident * 1.2,
            ..a
        }),
    ];
    for api in Api::ALL {
        for (code, inject) in cases {
            for entering in [true, false] {
                let a = answer(api, &injected(api, entering, inject));
                assert_eq!(a["ok"], false, "{api:?} {code:?} {a}");
                assert_eq!(mistakes(&a)[0], code.name(), "{api:?} {code:?} {a}");
            }
        }
    }
}

#[test]
fn a_wrong_result_and_a_missed_tir_are_named_in_every_api() {
    for api in Api::ALL {
        let (d, n, mu) = situation(true);
        let args = api.arguments(d, n, mu);
        let right = api.call(args).transmitted().unwrap();
        let other_root = right - n * (2.0 * right.dot(n));
        let result = match api {
            Api::Pbrt => vec![
                ("returned", json!(true)),
                ("wt", json!(other_root.to_array())),
            ],
            _ => vec![(names(api).result, json!(other_root.to_array()))],
        };
        let a = answer(api, &line(api, args, result, json!({"entering": true})));
        assert_eq!(mistakes(&a), ["other_root"], "{api:?} {a}");
        assert!(
            a["explanation"]
                .as_str()
                .unwrap()
                .contains("the other root"),
            "{a}"
        );

        // Glass to air at 60°: past the critical angle.
        let up = DVec3::new(60_f64.to_radians().sin(), 60_f64.to_radians().cos(), 0.0);
        let args = api.arguments(up, -DVec3::Y, 1.5);
        let formula = api.call(args).formula().unwrap_or(up);
        let result = match api {
            Api::Glsl => vec![("result", json!([null, null, null]))],
            Api::Pbrt => vec![("returned", json!(true)), ("wt", json!(up.to_array()))],
            _ => vec![(names(api).result, json!(formula.to_array()))],
        };
        let a = answer(api, &line(api, args, result, json!({"entering": false})));
        assert_eq!(mistakes(&a), ["missed_tir"], "{api:?} {a}");
        assert_eq!(a["t"], Value::Null);
        // Saying so is right.
        let a = answer(api, &injected_tir(api, args));
        assert_eq!(a["ok"], true, "{api:?} {a}");
    }
}

/// A call past the critical angle answered as the API answers it: the book's caller reflects,
/// Mitsuba samples no transmission.
fn injected_tir(api: Api, args: Args<f64>) -> String {
    let result = match api {
        Api::Rtiow => {
            let reflected =
                refraction_kernel::api::rtiow::reflect::<f64>(args.incident, args.normal);
            vec![("refracted", json!(reflected.to_array()))]
        }
        Api::Mitsuba => vec![("wo", Value::Null)],
        Api::Glsl | Api::Pbrt => returned(api, args),
    };
    line(api, args, result, json!({"entering": false}))
}

/// A GLSL call entering glass with eta inverted (1.5 passed for 1/1.5).
fn glsl_eta_inverted() -> String {
    let (d, n, _) = situation(true);
    let args = Api::Glsl.arguments(d, n, 1.5);
    line(
        Api::Glsl,
        args,
        returned(Api::Glsl, args),
        json!({"entering": true}),
    )
}

#[test]
fn glsl_explains_eta_in_its_own_words() {
    let text = glsl_eta_inverted();
    let a = answer(Api::Glsl, &text);
    assert_eq!(mistakes(&a), ["eta_inverted"]);
    let explanation = a["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("GLSL's eta is n_from/n_to")
            && explanation.contains("you passed 1.5 for a ray entering the object")
            && explanation.contains("pass 1/1.5 = 0.666667"),
        "{explanation}"
    );
}

#[test]
fn ties_are_listed_with_the_field_that_tells_them_apart() {
    let (d, n, mu) = situation(true);
    let args = Args {
        incident: -d,
        ..Api::Glsl.arguments(d, n, mu)
    };
    let a = answer(
        Api::Glsl,
        &line(Api::Glsl, args, returned(Api::Glsl, args), json!({})),
    );
    assert_eq!(
        mistakes(&a),
        ["normal_not_facing", "incident_reversed"],
        "{a}"
    );
    assert_eq!(
        a["alternatives"],
        json!([["normal_not_facing"], ["incident_reversed"]])
    );
    assert!(
        a["explanation"]
            .as_str()
            .unwrap()
            .contains("Give travel to tell them apart")
    );
    // pbrt: an inward normal and an inverted eta give the same call; entering says which.
    let args = Args {
        normal: -n,
        ..Api::Pbrt.arguments(d, n, mu)
    };
    let text = line(
        Api::Pbrt,
        args,
        returned(Api::Pbrt, args),
        json!({"from": 1, "to": 1.5}),
    );
    let a = answer(Api::Pbrt, &text);
    assert_eq!(
        a["alternatives"],
        json!([
            ["incident_reversed"],
            ["eta_inverted"],
            ["normal_not_facing"]
        ]),
        "{a}"
    );
    let explanation = a["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("Give travel and entering to tell them apart"),
        "{a}"
    );
}

/// Issue 11: a flipped square-root sign was blamed on "an outward normal" although the normal
/// faced the ray.
#[test]
fn a_flipped_square_root_is_not_blamed_on_the_normal() {
    let (d, n, mu) = situation(false);
    let args = Api::Rtiow.arguments(d, n, mu);
    let right = refraction_kernel::api::rtiow::refract::<f64>(args.incident, args.normal, args.eta);
    let flipped = right - n * (2.0 * right.dot(n));
    let result = vec![("refracted", json!(flipped.to_array()))];
    let a = answer(
        Api::Rtiow,
        &line(Api::Rtiow, args, result, json!({"entering": false})),
    );
    assert_eq!(mistakes(&a), ["other_root"], "{a}");
    let explanation = a["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("square root's sign flipped"),
        "{explanation}"
    );
    assert!(!explanation.contains("outward"), "{explanation}");
}

/// Issue 11: an inverted-ratio build (`ri = front_face ? ir : 1/ir`) was judged half right
/// when fed the ratio the code passed; with `entering` every such call is named.
#[test]
fn an_inverted_ratio_build_is_wrong_on_every_hit() {
    for entering in [true, false] {
        for degrees in [5.0, 25.0, 40.0, 70.0] {
            let a = degrees_f64(degrees);
            let d = DVec3::new(a.sin(), -a.cos(), 0.0);
            let ri = if entering { 1.5 } else { 1.0 / 1.5 };
            let args = Args {
                incident: d,
                normal: DVec3::Y,
                eta: ri,
            };
            let answer = refraction_kernel::api::rtiow::answer::<f64>(d, DVec3::Y, ri);
            let result = if answer.cannot_refract {
                refraction_kernel::api::rtiow::reflect::<f64>(d, DVec3::Y)
            } else {
                answer.refracted
            };
            let text = line(
                Api::Rtiow,
                args,
                vec![("refracted", json!(result.to_array()))],
                json!({"entering": entering}),
            );
            let verdict = self::answer(Api::Rtiow, &text);
            assert_eq!(verdict["ok"], false, "{entering} {degrees} {verdict}");
            assert_eq!(mistakes(&verdict)[0], "eta_inverted", "{verdict}");
        }
    }
}

fn degrees_f64(degrees: f64) -> f64 {
    degrees.to_radians()
}

#[test]
fn six_logged_digits_are_compared_at_that_precision() {
    let text = r#"{"uv":[0.642788,-0.766044,0],"n":[0,1,0],"etai_over_etat":0.666667,"refracted":[0.428525,-0.90353,0],"entering":1}"#;
    let a = answer(Api::Rtiow, text);
    assert_eq!(a["ok"], true, "{a}");
    // Off in the fourth digit: not what refract returns.
    let text = text.replace("0.428525", "0.4287");
    assert_eq!(mistakes(&answer(Api::Rtiow, &text)), ["not_the_api_result"]);
}

/// One GLSL call of a traced path: what a tracer logs at a hit.
fn path_line(hit: (DVec3, DVec3, f64, DVec3), entering: bool, point: DVec3) -> String {
    let (i, n, eta, result) = hit;
    json!({"I": i.to_array(), "N": n.to_array(), "eta": eta, "result": result.to_array(),
           "entering": entering, "path": "ray", "point": point.to_array(), "precision": "f64"})
    .to_string()
}

fn summaries(lines: &[String]) -> Vec<Value> {
    let mut session = Session::new(options(Api::Glsl), Format::JsonLines, false, true);
    let mut out: Vec<Value> = Vec::new();
    for line in lines {
        let reply = session.answer(1, line).unwrap();
        out.extend(
            reply
                .lines()
                .map(|l| serde_json::from_str::<Value>(l).unwrap()),
        );
    }
    out.extend(session.finish().map(|l| serde_json::from_str(&l).unwrap()));
    out.into_iter()
        .filter(|v| v.get("exit_ok").is_some())
        .collect()
}

fn glsl(i: DVec3, n: DVec3, eta: f64) -> (DVec3, DVec3, f64, DVec3) {
    (
        i,
        n,
        eta,
        refraction_kernel::api::glsl::refract::<f64>(i, n, eta),
    )
}

#[test]
fn an_inverted_eta_at_both_faces_of_a_slab_cancels() {
    let a = 30_f64.to_radians();
    let d = DVec3::new(a.sin(), -a.cos(), 0.0);
    let first = glsl(d, DVec3::Y, 1.5);
    let inside = first.3;
    let second = glsl(inside, DVec3::Y, 1.0 / 1.5);
    let lines = [
        path_line(first, true, DVec3::ZERO),
        path_line(second, false, inside * (-1.0 / inside.y)),
    ];
    let s = &summaries(&lines)[0];
    assert_eq!(
        (s["hits"].clone(), s["first_wrong"].clone()),
        (json!(2), json!(1)),
        "{s}"
    );
    assert_eq!(s["exit_ok"], true, "{s}");
    let explanation = s["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("cancel") && explanation.contains("logged surfaces"),
        "{s}"
    );
}

/// A unit sphere at the origin entered at its top, (0, 1, 0), at `degrees` from the normal:
/// the right first call, an outward normal where the ray first tries to leave (so it stays
/// inside, mirrored), and eta upside down where it finally leaves. Returns the logged hits and
/// the signed angle between where the ray leaves and where it should.
fn sphere_path(degrees: f64) -> (Vec<String>, f64) {
    let a = degrees.to_radians();
    let d = DVec3::new(a.sin(), -a.cos(), 0.0);
    let next = |p: DVec3, t: DVec3| p + t * (-2.0 * p.dot(t) / t.length_squared());
    let p1 = DVec3::Y;
    let h1 = glsl(d, p1, 1.0 / 1.5);
    let p2 = next(p1, h1.3);
    let h2 = glsl(h1.3, p2, 1.5);
    let p3 = next(p2, h2.3);
    let h3 = glsl(h2.3, -p3, 1.0 / 1.5);
    let right_inside = h1.3;
    let right = refraction_kernel::api::glsl::refract::<f64>(right_inside, -p2, 1.5);
    let off = right.x * h3.3.y - right.y * h3.3.x;
    let lines = vec![
        path_line(h1, true, p1),
        path_line(h2, false, p2),
        path_line(h3, false, p3),
    ];
    (lines, off.atan2(right.dot(h3.3)))
}

#[test]
fn two_wrong_calls_can_cancel_on_a_sphere() {
    // Where the mistakes cancel exactly, found by bisection between 70 and 76 degrees.
    let (mut low, mut high) = (70.0, 76.0);
    assert!(sphere_path(low).1 * sphere_path(high).1 < 0.0);
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if sphere_path(mid).1 * sphere_path(low).1 > 0.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    let s = &summaries(&sphere_path(low).0)[0];
    assert_eq!(
        (s["hits"].clone(), s["first_wrong"].clone()),
        (json!(3), json!(2)),
        "{s}"
    );
    assert_eq!(s["exit_ok"], true, "{s}");
    let explanation = s["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("Hits 2, 3 are wrong") && explanation.contains("sphere"),
        "{s}"
    );
    // The same mistakes elsewhere on the sphere do not cancel.
    let s = &summaries(&sphere_path(50.0).0)[0];
    assert_eq!(s["exit_ok"], false, "{s}");
    assert!(
        s["explanation"]
            .as_str()
            .unwrap()
            .contains("The first wrong call is hit 2")
    );
}

#[test]
fn each_path_gets_its_summary_and_a_hit_without_path_is_refused() {
    let (d, n, mu) = situation(true);
    let args = Api::Glsl.arguments(d, n, mu);
    let hit = |path: &str| {
        let mut result = returned(Api::Glsl, args);
        result.push(("path", json!(path)));
        line(Api::Glsl, args, result, json!({"precision": "f32"}))
    };
    let all = summaries(&[hit("a"), hit("b"), hit("b")]);
    assert_eq!(all.len(), 2);
    assert_eq!(
        (all[0]["path"].clone(), all[1]["hits"].clone()),
        (json!("a"), json!(2))
    );
    assert_eq!(all[1]["first_wrong"], Value::Null);
    let mut session = Session::new(options(Api::Glsl), Format::JsonLines, false, true);
    let lone = line(Api::Glsl, args, returned(Api::Glsl, args), json!({}));
    assert!(
        session
            .answer(1, &lone)
            .unwrap_err()
            .to_string()
            .contains("missing field `path`")
    );
}

#[test]
fn a_long_csv_log_judged_on_many_threads_answers_as_one_thread_does() {
    let rows = [
        "0.642788,-0.766044,0,\"0, 1, 0\",0.666667,\"0.428525, -0.90353, 0\",1,1.5",
        "0.642788,-0.766044,0,\"0, -1, 0\",0.666667,\"0.428525, 0.90353, 0\",1,1.5",
        "not, a, row",
    ];
    let mut text = String::from("I.x,I.y,I.z,N,eta,result,from,to\n");
    // Past one chunk of lines, so that later chunks are judged in parallel with the header.
    for k in 0..9000 {
        text.push_str(rows[k % rows.len()]);
        text.push('\n');
    }
    let run = |threads: usize| {
        let mut session = Session::new(options(Api::Glsl), Format::Csv, false, false);
        let mut out = Vec::new();
        let answered = session.run(text.as_bytes(), &mut out, threads).unwrap();
        (
            answered,
            String::from_utf8(out).unwrap(),
            session.tally().summary(),
        )
    };
    let (one, many) = (run(1), run(4));
    assert_eq!(one, many);
    let (answered, out, tally) = one;
    assert!(!answered);
    assert_eq!(out.lines().count(), 9000);
    // A tie counts each of its mistakes.
    assert_eq!(
        tally,
        "3000 normal_not_facing|incident_reversed, 3000 ok, 3000 unreadable"
    );
    let last_error: Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
    assert_eq!(
        last_error["line"], 9001,
        "line numbers count the header too"
    );
}

#[test]
fn an_api_result_that_overflows_is_told_in_words_not_as_nan() {
    let line = r#"{"uv":[4e240,-1,0],"n":[0,1,0],"etai_over_etat":1.5,"refracted":[1,0,0]}"#;
    let a = answer(Api::Rtiow, line);
    let explanation = a["explanation"].as_str().unwrap();
    assert!(
        explanation.contains("not finite (NaN or infinite components)"),
        "{explanation}"
    );
    let cleaned = explanation.replace("NaN or infinite", "");
    assert!(
        !cleaned.contains("NaN") && !cleaned.contains("inf"),
        "{explanation}"
    );
    assert!(
        a["mistakes"]
            .as_array()
            .unwrap()
            .contains(&json!("not_unit_input"))
    );
}

#[test]
fn explanations_come_in_the_threads_language_with_its_decimal_comma() {
    let text = glsl_eta_inverted();
    refraction_i18n::set_locale(refraction_i18n::Locale::De);
    let a = answer(Api::Glsl, &text);
    refraction_i18n::set_locale(refraction_i18n::Locale::En);
    assert_eq!(mistakes(&a), ["eta_inverted"], "the codes stay the JSON's");
    let explanation = a["explanation"].as_str().unwrap();
    assert!(
        explanation.starts_with("In GLSL ist eta n_from/n_to")
            && explanation.contains("beim Eintritt in das Objekt (von n = 1 nach n = 1,5)")
            && explanation.contains("übergib 1/1,5 = 0,666667"),
        "{explanation}"
    );
    let english = answer(Api::Glsl, &text);
    assert!(
        english["explanation"]
            .as_str()
            .unwrap()
            .contains("pass 1/1.5 = 0.666667"),
        "English again once the language is set back"
    );
}

#[test]
fn lines_judged_on_other_threads_speak_the_callers_language() {
    // Issue 35: the workers judged in the default language whatever the caller spoke.
    use refraction_i18n::{Locale, set_locale, t};
    let wrong = glsl_eta_inverted();
    let zero = r#"{"I":[0,0,0],"N":[0,1,0],"eta":1,"result":[0,0,0]}"#;
    let text: String = (0..400)
        .flat_map(|k| [if k % 2 == 0 { wrong.as_str() } else { zero }, "\n"])
        .collect();
    set_locale(Locale::De);
    let explained = answer(Api::Glsl, &wrong)["explanation"].clone();
    let refused = t!("check-field-zero-vector", field = "I");
    let mut session = Session::new(options(Api::Glsl), Format::JsonLines, false, false);
    let mut out = Vec::new();
    let answered = session.run(text.as_bytes(), &mut out, 4);
    set_locale(Locale::En);
    assert!(!answered.unwrap());
    assert!(refused.ends_with("ist der Nullvektor"), "{refused}");
    assert!(
        explained.as_str().unwrap().starts_with("In GLSL ist eta"),
        "{explained}"
    );
    let answers: Vec<Value> = String::from_utf8(out)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), 400);
    for (k, a) in answers.iter().enumerate() {
        if k % 2 == 0 {
            assert_eq!(a["explanation"], explained, "line {}", k + 1);
        } else {
            assert_eq!(a["error"], refused.as_str(), "line {}", k + 1);
        }
    }
}

/// Issue 23: a line that is not UTF-8 was left out of the tally of a pattern run.
#[test]
fn a_line_that_is_not_utf8_is_counted_as_unreadable() {
    let pattern =
        Pattern::parse(Api::Rtiow, "uv={uv} n={n} r={etai_over_etat} t={refracted}").unwrap();
    let mut session = Session::new(options(Api::Rtiow), Format::Pattern(pattern), false, false);
    let mut input = b"uv=0 -1 0 n=0 1 0 r=1 t=0 -1 0\n".to_vec();
    input.extend_from_slice(b"uv=\xFF\xFE\n");
    let mut out = Vec::new();
    let answered = session.run(&input[..], &mut out, 1).unwrap();
    assert!(!answered && !session.all_ok());
    assert_eq!(session.tally().summary(), "1 ok, 1 unreadable");
    assert_eq!(session.summary().skipped, 1, "not judged");
}

/// Issue 23: a path of 100,000 right hits was said to leave wrong ("a hit missing?"): the
/// retrace through the logged surfaces drifted from the student's f32 ray by rounding over so
/// many steps, and a right path must stay right however long it is.
#[test]
fn a_long_path_of_right_hits_leaves_right() {
    let mut d = Vec3::new(0.3, -0.95, 0.1).normalize();
    let mut lines = Vec::new();
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    for k in 0..100_000 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        // A surface facing the ray at up to 80° into glass and up to 39° out of it (just short
        // of the critical angle, where rounding grows most), turned about the ray at random.
        #[expect(clippy::cast_precision_loss)]
        let (u, v) = (
            (seed >> 11) as f32 / (1_u64 << 53) as f32,
            (seed & 0xffff) as f32 / 65536.0,
        );
        let most: f32 = if k % 2 == 0 { 80.0 } else { 39.0 };
        let angle = (u * most).to_radians();
        let (a, b) = d.any_orthonormal_pair();
        let turn = v * core::f32::consts::TAU;
        let n = -(d * angle.cos() + (a * turn.cos() + b * turn.sin()) * angle.sin());
        let eta: f32 = if k % 2 == 0 { 1.0 / 1.5 } else { 1.5 };
        // The student's f32 ray, as GLSL refracts it.
        let t = d.refract(n, eta);
        lines.push(
            json!({"I": d.to_array(), "N": n.to_array(), "eta": eta, "result": t.to_array(),
                   "entering": k % 2 == 0, "path": "long", "precision": "f32"})
            .to_string(),
        );
        d = t.normalize();
    }
    let s = &summaries(&lines)[0];
    assert_eq!(s["hits"], 100_000, "{s}");
    assert_eq!(s["exit_ok"], true, "{s}");
}

#[test]
fn a_judged_line_counts_as_the_command_counts_it_and_lands_on_the_failure_map() {
    // The explorer's opened logs: judge_line counts each line in the tally and the diagnosis,
    // and its point says where it lands on the failure map.
    let mut session = Session::new(options(Api::Glsl), Format::JsonLines, false, false);
    let right = injected(Api::Glsl, true, |args| args);
    let inverted = injected(Api::Glsl, false, |args| Args {
        eta: 1.0 / args.eta,
        ..args
    });
    let (_, judged) = session.judge_line(&right).unwrap().unwrap();
    let point = judged.point();
    assert!(point.ok && point.error_deg < 1e-3, "{point:?}");
    let (d, n, _) = situation(true);
    let expected = refraction_model::log_map::incidence_deg(d, n);
    assert!((point.incidence_deg - expected).abs() < 1e-9, "{point:?}");
    let (_, judged) = session.judge_line(&inverted).unwrap().unwrap();
    let point = judged.point();
    assert!(!point.ok && point.error_deg > 5.0, "{point:?}");
    assert_eq!(point.side, Some(crate::diagnosis::Side::Inside));
    assert!(session.judge_line("{\"I\": 1}").is_err());
    assert_eq!(
        session.tally().summary(),
        "1 eta_inverted, 1 ok, 1 unreadable"
    );
    let summary = session.summary();
    assert_eq!((summary.lines, summary.judged, summary.ok), (3, 2, 1));
    assert_eq!(summary.diagnosis[0].code, "eta_inverted");
}

#[test]
fn a_reported_total_internal_reflection_lands_where_its_reflection_goes() {
    // Past the critical angle the right direction is the reflected ray; GLSL's zero vector is
    // reflected by the caller, so a right TIR line is off by nothing.
    let (a, mu) = (60_f64.to_radians(), 1.5);
    let d = DVec3::new(a.sin(), -a.cos(), 0.0);
    let args = Api::Glsl.arguments(d, DVec3::Y, mu);
    let text = line(
        Api::Glsl,
        args,
        returned(Api::Glsl, args),
        json!({"entering": false}),
    );
    let mut session = Session::new(options(Api::Glsl), Format::JsonLines, false, false);
    let (_, judged) = session.judge_line(&text).unwrap().unwrap();
    let point = judged.point();
    assert!(point.ok && point.past_critical, "{point:?}");
    assert!(point.error_deg < 1e-3, "{point:?}");
    assert!((point.incidence_deg - 60.0).abs() < 1e-9, "{point:?}");
}
