//! Logs of four more renderers' glass code, beyond the four APIs `check --api` names: Mitsuba
//! 3, Tungsten, Blender Cycles and three.js, each re-written in Rust from its public source
//! (read at the commits below; none of their code is copied here), called the way its
//! integrator calls it on the scene of [`crate::renderers`] (a glass sphere of index 1.5 in
//! air, rays from both sides, a little over half of those from inside past the critical
//! angle), with one-line bugs students make injected, and printed the way each ecosystem
//! prints: Dr.Jit's `[x, y, z]` and Python's `None` and float reprs, a C++ stream's `(x,y,z)`,
//! Cycles' `print_float3` (`%.8f`, one vector a line), Node's `Float32Array(3) [ … ]` with
//! 17-digit float32 values, `-0` and arrays broken over several lines.
//!
//! | renderer | source read | what is called and printed |
//! | --- | --- | --- |
//! | [`Family::Mitsuba`] | mitsuba-renderer/mitsuba3 b45b0a9, `include/mitsuba/render/fresnel.h` `fresnel` and `refract`, `src/bsdfs/dielectric.cpp` `SmoothDielectric::sample` | `scalar_rgb` (float, no FMA), local frame; the Python script prints `wi`, the ratio and `bs.wo`, `None` when it sampled reflection |
//! | [`Family::Tungsten`] | tunabrain/tungsten 88ea020, `src/core/bsdfs/DielectricBsdf.cpp` `DielectricBsdf::sample`, `src/core/bsdfs/Fresnel.hpp` `dielectricReflectance` | float, local frame; `std::cout` in the transmission branch |
//! | [`Family::Cycles`] | blender/cycles 97dbe6f, `src/kernel/closure/bsdf_util.h` `fresnel_dielectric`, `refract_angle`; `src/kernel/svm/closure.h` (Glass BSDF); `src/kernel/closure/bsdf_microfacet.h` `bsdf_microfacet_sample` | float, world frame, N turned to face `wi`; `print_float3` of the refraction before the choice |
//! | [`Family::ThreeJs`] | mrdoob/three.js 08e1c55, `transmission_pars_fragment.glsl.js` `getVolumeTransmissionRay` | the shader's `refract(-v, normalize(n), 1.0 / ior)` ported to JavaScript with `Float32Array`s, front faces only; `console.log` |
//!
//! Each line (a record: Cycles' takes four lines, Node's as many as its arrays need) carries
//! its ground truth, as [`crate::renderers::Line`] does: whether the call differs from the
//! bug-free code's for the same ray and the same random number.

use glam::{DVec3, Vec3};

use crate::renderers::{Hit, Rng, angle, c_fixed, c_general};

/// A call's outcome counts as wrong beyond this angle (radians) from the bug-free one.
const WRONG_ANGLE: f64 = 1e-4;

/// The renderers emulated here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Family {
    /// Mitsuba 3's smooth dielectric, printed from Python.
    Mitsuba,
    /// Tungsten's dielectric BSDF, printed from C++.
    Tungsten,
    /// Cycles' glass closure, printed with `print_float3`.
    Cycles,
    /// three.js's transmission shader, ported to JavaScript and printed by Node.
    ThreeJs,
}

impl Family {
    /// Every family.
    pub(crate) const ALL: [Self; 4] = [Self::Mitsuba, Self::Tungsten, Self::Cycles, Self::ThreeJs];

    /// The bugs that can be injected ([`Bug::None`] not included).
    #[must_use]
    pub(crate) fn bugs(self) -> &'static [Bug] {
        match self {
            Self::Mitsuba => &[
                Bug::MitsubaRatioInverted,
                Bug::MitsubaTernarySwapped,
                Bug::MitsubaMulsign,
                Bug::MitsubaRefractSign,
                Bug::MitsubaAbsDropped,
            ],
            Self::Tungsten => &[
                Bug::TungstenTernarySwapped,
                Bug::TungstenAbsDropped,
                Bug::TungstenCopysign,
                Bug::TungstenHelperInverted,
            ],
            Self::Cycles => &[
                Bug::CyclesTernarySwapped,
                Bug::CyclesRefractEta,
                Bug::CyclesCosSign,
            ],
            Self::ThreeJs => &[Bug::ThreeIncidentReversed, Bug::ThreeEtaInverted],
        }
    }

    /// The options `check` needs for this family's log, before `--pattern`.
    #[must_use]
    pub(crate) fn options(self) -> &'static str {
        match self {
            Self::Mitsuba => "--api mitsuba --inside 1.5 --outside 1",
            Self::Tungsten => {
                "--renderer tungsten --normal +z --convention toward-origin --inside 1.5 --outside 1"
            }
            Self::Cycles => "--renderer cycles --convention toward-origin --inside 1.5 --outside 1",
            Self::ThreeJs => "--api glsl --renderer threejs --inside 1.5 --outside 1",
        }
    }

    /// The `--pattern` that reads the log.
    #[must_use]
    pub(crate) fn pattern(self) -> &'static str {
        match self {
            Self::Mitsuba => "wi={wi} inside={!entering} eta={eta} wo={wo}",
            Self::Tungsten => "wi={w} eta={ratio} wo={t_yours}",
            Self::Cycles => "wi: {w}\\nN: {n}\\nbackfacing: {!entering}\\nwo: {t_yours}",
            Self::ThreeJs => "I {I} N {N} eta {eta} frontFacing {entering} -> {result}",
        }
    }
}

/// One-line bugs, each as a student makes it in one renderer's code; each names the line it
/// alters, what the log then shows, and what `check` must name ([`Bug::expected`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bug {
    /// The code as published.
    None,
    /// Mitsuba, `SmoothDielectric`'s constructor: `m_eta = int_ior / ext_ior` written
    /// `ext_ior / int_ior`. The script prints the ratio it passes, 0.6666666666666666.
    MitsubaRatioInverted,
    /// Mitsuba, `fresnel`: `eta_it = select(outside_mask, eta, rcp_eta)` and `eta_ti =
    /// select(outside_mask, rcp_eta, eta)` both swapped: the ratio inverted inside the code.
    /// False total internal reflection entering past sinθ = 1/1.5 (F = 1: `None`), missed
    /// total internal reflection leaving, wrong directions elsewhere: one cause.
    MitsubaTernarySwapped,
    /// Mitsuba, `fresnel`: `mulsign_neg(cos_theta_t_abs, cos_theta_i)` written `mulsign`:
    /// `wo.z` on the side `wi` is on, the other root.
    MitsubaMulsign,
    /// Mitsuba, `refract`: `-eta_ti * wi.x(), -eta_ti * wi.y()` written without the minus:
    /// the part across the normal mirrored.
    MitsubaRefractSign,
    /// Mitsuba, `fresnel`: `cos_theta_i_abs = dr::abs(cos_theta_i)` written without `abs`:
    /// F > 1 for every ray from inside, which then always reflects (`None` on every line
    /// from inside, at every angle: the cosine's sign in the Fresnel code, not its test for
    /// total internal reflection).
    MitsubaAbsDropped,
    /// Tungsten, `DielectricBsdf::sample`: `eta = wi.z() < 0.0f ? _ior : _invIor` swapped.
    TungstenTernarySwapped,
    /// Tungsten, `DielectricBsdf::sample`: `dielectricReflectance(eta, std::abs(wi.z()),
    /// cosThetaT)` without `std::abs`: for rays from inside the helper inverts the ratio
    /// again, so cosθt comes from 1/μ while `wo`'s x and y use μ.
    TungstenAbsDropped,
    /// Tungsten, `DielectricBsdf::sample`: `-std::copysign(cosThetaT, wi.z())` without the
    /// minus: the other root.
    TungstenCopysign,
    /// Tungsten, `Fresnel::dielectricReflectance`: `sinThetaTSq = eta*eta*(1 - cos²)` written
    /// `(1 - cos²)/(eta*eta)`: cosθt from 1/μ on every ray.
    TungstenHelperInverted,
    /// Cycles, the Glass BSDF in `svm/closure.h`: `bsdf->ior = backfacing ? 1.0f / ior : ior`
    /// swapped.
    CyclesTernarySwapped,
    /// Cycles, `bsdf_microfacet_sample`: `refract_angle(wi, H, cos_HO, m_inv_eta)` passed
    /// `m_eta`: the part across N scaled by 1/μ.
    CyclesRefractEta,
    /// Cycles, `fresnel_dielectric_polarized`: `cos_theta_t = -safe_sqrtf(...) / eta` without
    /// the minus: the refraction printed is the other root, and F > 1 so the code never
    /// transmits.
    CyclesCosSign,
    /// three.js: `refract( - v, ...)` written `refract( v, ...)`.
    ThreeIncidentReversed,
    /// three.js: `refract( - v, normalize( n ), 1.0 / ior )` written with `ior`.
    ThreeEtaInverted,
}

impl Bug {
    /// The code the first finding must have, and a piece of its fix: the line to change in
    /// the renderer's own code.
    #[must_use]
    pub(crate) fn expected(self) -> (&'static str, &'static str) {
        match self {
            Self::None => ("none", ""),
            Self::MitsubaRatioInverted => ("eta_inverted", "m_eta = int_ior / ext_ior"),
            Self::MitsubaTernarySwapped => {
                ("eta_inverted", "dr::select(outside_mask, eta, rcp_eta)")
            }
            Self::MitsubaMulsign => (
                "other_root",
                "dr::mulsign_neg(cos_theta_t_abs, cos_theta_i)",
            ),
            Self::MitsubaRefractSign => ("across_sign", "-eta_ti * wi.x()"),
            Self::MitsubaAbsDropped => ("fresnel_cos_sign", "dr::abs(cos_theta_i)"),
            Self::TungstenTernarySwapped => {
                ("eta_inverted", "event.wi.z() < 0.0f ? _ior : _invIor")
            }
            Self::TungstenAbsDropped => ("eta_inverted", "std::abs(event.wi.z())"),
            Self::TungstenCopysign => ("other_root", "-std::copysign(cosThetaT, event.wi.z())"),
            Self::TungstenHelperInverted => ("eta_inverted", "float sinThetaTSq = eta*eta*"),
            Self::CyclesTernarySwapped => (
                "eta_inverted",
                "(sd->flag & SD_BACKFACING) ? 1.0f / ior : ior",
            ),
            Self::CyclesRefractEta => ("eta_inverted", "refract_angle(wi, H, cos_HO, m_inv_eta)"),
            Self::CyclesCosSign => ("other_root", "-safe_sqrtf(eta_cos_theta_t_sq) / eta"),
            Self::ThreeIncidentReversed => (
                "incident_reversed",
                "refract( - v, normalize( n ), 1.0 / ior )",
            ),
            Self::ThreeEtaInverted => ("eta_inverted", "1.0 / ior"),
        }
    }
}

/// One record and its ground truth.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Line {
    /// The record as printed (several lines for Cycles and for Node's long arrays).
    pub text: String,
    /// The call differs from the bug-free code's for the same ray and random number.
    pub wrong: bool,
    /// The ray arrives from inside the glass.
    pub from_inside: bool,
}

/// What a call did, widened to f64.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Outcome {
    Transmitted(DVec3),
    /// It reflected (sampled, or total internal reflection).
    Reflected,
}

/// One call's record, what it was given and what it did.
#[derive(Clone, Debug)]
struct Printed {
    text: String,
    /// The incident vector, normal and ratio it was given (as printed).
    args: (DVec3, DVec3, f64),
    outcome: Outcome,
}

/// The log `family`'s code with `bug` prints for `count` records on rays drawn from `seed`,
/// with `noise` lines of the renderer's other output between some of them.
#[must_use]
pub(crate) fn log(family: Family, bug: Bug, count: usize, seed: u64) -> Vec<Line> {
    assert!(
        bug == Bug::None || family.bugs().contains(&bug),
        "{bug:?} is not a bug of {family:?}"
    );
    let mut rng = Rng::new(seed);
    let mut lines = Vec::with_capacity(count);
    while lines.len() < count {
        let hit = Hit::draw(&mut rng);
        let sample = rng.unit();
        if family == Family::ThreeJs && hit.from_inside {
            continue; // three.js refracts at front faces only
        }
        let Some(printed) = emulate(family, bug, &hit, sample) else {
            continue;
        };
        let right = emulate(family, Bug::None, &hit, sample);
        lines.push(Line {
            wrong: right.is_none_or(|r| differs(&printed, &r)),
            text: printed.text,
            from_inside: hit.from_inside,
        });
    }
    lines
}

/// The log as a file: records in order, a line of the renderer's other output before every
/// seventh (Cycles' progress, a Python warning, Node's timing).
#[must_use]
pub(crate) fn text(family: Family, lines: &[Line]) -> String {
    let noise = match family {
        Family::Mitsuba => "2024-05-01 12:00:01 INFO  [SamplingIntegrator] Rendering 64 spp",
        Family::Tungsten => "Rendering pass 3/16",
        Family::Cycles => "Path Tracing Sample 12/64, Tile 3/16",
        Family::ThreeJs => "frame 1: 16.7 ms",
    };
    let mut out = String::new();
    for (i, line) in lines.iter().enumerate() {
        if i % 7 == 3 {
            out.push_str(noise);
            out.push('\n');
        }
        out.push_str(&line.text);
        out.push('\n');
    }
    out
}

fn differs(a: &Printed, b: &Printed) -> bool {
    let ((ai, an, ar), (bi, bn, br)) = (a.args, b.args);
    angle(ai, bi) > WRONG_ANGLE
        || angle(an, bn) > WRONG_ANGLE
        || (ar / br - 1.0).abs() > WRONG_ANGLE
        || match (a.outcome, b.outcome) {
            (Outcome::Transmitted(x), Outcome::Transmitted(y)) => {
                angle(x, y) > WRONG_ANGLE || (x.length() - y.length()).abs() > 1e-3
            }
            (Outcome::Reflected, Outcome::Reflected) => false,
            _ => true,
        }
}

fn emulate(family: Family, bug: Bug, hit: &Hit, sample: f64) -> Option<Printed> {
    match family {
        Family::Mitsuba => Some(mitsuba::call(bug, hit, sample)),
        Family::Tungsten => tungsten::call(bug, hit, sample),
        Family::Cycles => cycles::call(bug, hit),
        Family::ThreeJs => Some(three::call(bug, hit)),
    }
}

/// The ray in a local shading frame whose z axis is the outward normal: `wi = -d`.
fn local_wi(hit: &Hit) -> Vec3 {
    let (s, t) = hit.outward.any_orthonormal_pair();
    let wi = -hit.travel;
    Vec3::new(
        wi.dot(s) as f32,
        wi.dot(t) as f32,
        wi.dot(hit.outward) as f32,
    )
}

// ---------------------------------------------------------------------------------------------
// How each ecosystem prints a number

/// The decimal digits and exponent of `x`'s shortest round-trip form (`1.5` → ("15", 0)).
fn shortest(x: f64) -> (String, i32) {
    let text = format!("{:e}", x.abs());
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    (mantissa.replace('.', ""), exponent.parse().unwrap_or(0))
}

/// `digits` (a shortest form's) with the point after digit `point` (may be ≤ 0 or past them).
fn positional(digits: &str, point: i32) -> String {
    let n = i32::try_from(digits.len()).unwrap_or(i32::MAX);
    if point <= 0 {
        format!(
            "0.{}{digits}",
            "0".repeat(usize::try_from(-point).unwrap_or(0))
        )
    } else if point >= n {
        format!(
            "{digits}{}",
            "0".repeat(usize::try_from(point - n).unwrap_or(0))
        )
    } else {
        let (a, b) = digits.split_at(usize::try_from(point).unwrap_or(0));
        format!("{a}.{b}")
    }
}

/// `x` in its shortest round-trip digits, positional for decimal exponents in `positional`
/// and in scientific notation otherwise, its exponent written by `exponent` (from its
/// magnitude), `-0` and a `nan` word as each language writes them.
fn shortest_text(
    x: f64,
    positions: core::ops::Range<i32>,
    zero: &str,
    nan: &str,
    exponent_text: impl Fn(u32) -> String,
) -> (String, bool) {
    if x.is_nan() {
        return (nan.to_owned(), false);
    }
    let sign = if x.is_sign_negative() { "-" } else { "" };
    if x == 0.0 {
        return (format!("{sign}{zero}"), false);
    }
    let (digits, exponent) = shortest(x);
    if positions.contains(&exponent) {
        return (format!("{sign}{}", positional(&digits, exponent + 1)), true);
    }
    let mantissa = positional(&digits, 1);
    let esign = if exponent < 0 { '-' } else { '+' };
    let e = exponent_text(exponent.unsigned_abs());
    (
        format!("{sign}{}e{esign}{e}", mantissa.trim_end_matches('.')),
        false,
    )
}

/// Python's `repr` of a float: the shortest round-trip digits, positional from 1e-4 to 1e16,
/// always with a point (`1.0`, `-0.0`), `1e-05` below.
pub(crate) fn python_float(x: f64) -> String {
    let (text, positional) = shortest_text(x, -4..16, "0.0", "nan", |e| format!("{e:02}"));
    if positional && !text.contains('.') {
        format!("{text}.0")
    } else {
        text
    }
}

/// JavaScript's `Number#toString` as Node's `console.log` prints an array element: shortest
/// round-trip digits, positional from 1e-6 up to 1e21, `-0` kept.
pub(crate) fn js_number(x: f64) -> String {
    shortest_text(x, -6..21, "0", "NaN", |e| e.to_string()).0
}

/// Node's `util.inspect` of a `Float32Array` of three: on one line when it fits in 80
/// columns (its rule: 33 columns and the elements' widths), else one element a line.
pub(crate) fn node_f32_array(v: Vec3) -> String {
    let items: Vec<String> = v
        .to_array()
        .iter()
        .map(|&c| js_number(f64::from(c)))
        .collect();
    let width: usize = items.iter().map(String::len).sum();
    if 33 + width <= 80 {
        format!("Float32Array(3) [ {} ]", items.join(", "))
    } else {
        format!("Float32Array(3) [\n  {}\n]", items.join(",\n  "))
    }
}

/// Dr.Jit's `repr` of a 3-vector: `[x, y, z]`, each `%g`.
pub(crate) fn drjit_vector(v: Vec3) -> String {
    let items: Vec<String> = v
        .to_array()
        .iter()
        .map(|&c| c_general(f64::from(c), 6))
        .collect();
    format!("[{}]", items.join(", "))
}

// ---------------------------------------------------------------------------------------------
// Mitsuba 3

/// Mitsuba 3, b45b0a9: `include/mitsuba/render/fresnel.h`, `fresnel(cos_theta_i, eta)`
/// (`outside_mask = cos_theta_i >= 0`; `eta_it`, `eta_ti` selected by it; `cos_theta_t_sqr =
/// fnmadd(fnmadd(cos_theta_i, cos_theta_i, 1), eta_ti * eta_ti, 1)`; `safe_sqrt`; the
/// amplitudes `a_s`, `a_p` and `r = 0.5·(a_s² + a_p²)`, 0 when index-matched and 1 at
/// `cos_theta_i_abs == 0`; `cos_theta_t = mulsign_neg(cos_theta_t_abs, cos_theta_i)`) and
/// `refract(wi, cos_theta_t, eta_ti)`; `src/bsdfs/dielectric.cpp`, `SmoothDielectric::sample`
/// (`m_eta = int_ior / ext_ior`; reflection when `sample1 <= r_i`). Dr.Jit's `fnmadd(a, b, c)`
/// is `-a*b + c` unfused in the `scalar_rgb` variant built without FMA.
///
/// The student's Python script, in that variant, prints after `bsdf.sample`: `print(f"wi={si.wi}
/// inside={si.wi.z < 0} eta={eta} wo={bs.wo if transmitted else None}")`, `eta` being the
/// Python float it built the BSDF with (`int_ior / ext_ior`); Python prints `True`/`False`.
mod mitsuba {
    use super::{Bug, DVec3, Hit, Outcome, Printed, Vec3, drjit_vector, local_wi, python_float};

    /// `fresnel`'s `r`, `cos_theta_t` and `eta_ti`.
    fn fresnel(cos_i: f32, eta: f32, bug: Bug) -> (f32, f32, f32) {
        let outside = cos_i >= 0.0;
        let rcp = 1.0 / eta;
        let (eta_it, eta_ti) = match (outside, bug == Bug::MitsubaTernarySwapped) {
            (true, false) | (false, true) => (eta, rcp),
            (false, false) | (true, true) => (rcp, eta),
        };
        let cos_t_sqr = -(-cos_i * cos_i + 1.0) * (eta_ti * eta_ti) + 1.0;
        let cos_i_abs = if bug == Bug::MitsubaAbsDropped {
            cos_i
        } else {
            cos_i.abs()
        };
        let cos_t_abs = if cos_t_sqr > 0.0 {
            cos_t_sqr.sqrt()
        } else {
            0.0
        };
        let a_s = (-eta_it * cos_t_abs + cos_i_abs) / (eta_it * cos_t_abs + cos_i_abs);
        let a_p = (-eta_it * cos_i_abs + cos_t_abs) / (eta_it * cos_i_abs + cos_t_abs);
        let r = if eta == 1.0 {
            0.0
        } else if cos_i_abs == 0.0 {
            1.0
        } else {
            0.5 * (a_s * a_s + a_p * a_p)
        };
        // mulsign_neg(v, s): v negated unless s's sign bit is set; mulsign: the other way.
        let negative = cos_i.is_sign_negative() != (bug == Bug::MitsubaMulsign);
        let cos_t = if negative { cos_t_abs } else { -cos_t_abs };
        (r, cos_t, eta_ti)
    }

    pub(super) fn call(bug: Bug, hit: &Hit, sample: f64) -> Printed {
        let eta64 = if bug == Bug::MitsubaRatioInverted {
            1.0 / 1.5
        } else {
            1.5
        };
        let eta = eta64 as f32;
        let wi = local_wi(hit);
        let (r, cos_t, eta_ti) = fresnel(wi.z, eta, bug);
        let reflected = (sample as f32) <= r;
        let sign = if bug == Bug::MitsubaRefractSign {
            1.0
        } else {
            -1.0
        };
        let wo = Vec3::new(sign * eta_ti * wi.x, sign * eta_ti * wi.y, cos_t);
        let shown = if reflected {
            "None".to_owned()
        } else {
            drjit_vector(wo)
        };
        let inside = if wi.z < 0.0 { "True" } else { "False" };
        Printed {
            text: format!(
                "wi={} inside={inside} eta={} wo={shown}",
                drjit_vector(wi),
                python_float(eta64)
            ),
            args: (wi.as_dvec3(), DVec3::Z, eta64),
            outcome: if reflected {
                Outcome::Reflected
            } else {
                Outcome::Transmitted(wo.as_dvec3())
            },
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Tungsten

/// Tungsten, 88ea020: `src/core/bsdfs/DielectricBsdf.cpp`, `DielectricBsdf::sample` (`eta =
/// event.wi.z() < 0.0f ? _ior : _invIor`; `F = Fresnel::dielectricReflectance(eta,
/// std::abs(event.wi.z()), cosThetaT)`; reflection when `nextBoolean(F)`, i.e. the sample `<
/// F`; otherwise `false` if `F == 1`, else `wo = Vec3f(-wi.x()*eta, -wi.y()*eta,
/// -std::copysign(cosThetaT, wi.z()))`), `src/core/bsdfs/Fresnel.hpp`,
/// `dielectricReflectance` (a negative cosine inverts eta; `sinThetaTSq = eta*eta*(1 -
/// cosThetaI²)`; above 1: `cosThetaT = 0`, F = 1; `Rs`, `Rp`). The frame's z is the outward
/// normal (never turned for a transmissive BSDF, `TraceBase::makeLocalScatterEvent`).
///
/// The student prints in the transmission branch: `std::cout << "wi=" << event.wi << " eta="
/// << eta << " wo=" << event.wo << std::endl;` (`Vec3f` as `(x,y,z)`, default precision 6).
mod tungsten {
    use super::{Bug, DVec3, Hit, Outcome, Printed, Vec3, c_general, local_wi};

    const IOR: f32 = 1.5;

    fn dielectric_reflectance(eta: f32, cos_i: f32, bug: Bug) -> (f32, f32) {
        let (mut eta, mut cos_i) = (eta, cos_i);
        if cos_i < 0.0 {
            eta = 1.0 / eta;
            cos_i = -cos_i;
        }
        let sin2_t = if bug == Bug::TungstenHelperInverted {
            (1.0 - cos_i * cos_i) / (eta * eta)
        } else {
            eta * eta * (1.0 - cos_i * cos_i)
        };
        if sin2_t > 1.0 {
            return (1.0, 0.0);
        }
        let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
        let rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
        let rp = (eta * cos_t - cos_i) / (eta * cos_t + cos_i);
        ((rs * rs + rp * rp) * 0.5, cos_t)
    }

    fn vector(v: Vec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_general(f64::from(c), 6));
        format!("({x},{y},{z})")
    }

    pub(super) fn call(bug: Bug, hit: &Hit, sample: f64) -> Option<Printed> {
        let wi = local_wi(hit);
        let inside = wi.z < 0.0;
        let eta = if inside == (bug == Bug::TungstenTernarySwapped) {
            1.0 / IOR
        } else {
            IOR
        };
        let cos_i = if bug == Bug::TungstenAbsDropped {
            wi.z
        } else {
            wi.z.abs()
        };
        let (f, cos_t) = dielectric_reflectance(eta, cos_i, bug);
        if (sample as f32) < f || f == 1.0 {
            return None; // reflected: printed only where it transmits
        }
        let z = if bug == Bug::TungstenCopysign {
            cos_t.copysign(wi.z)
        } else {
            -cos_t.copysign(wi.z)
        };
        let wo = Vec3::new(-wi.x * eta, -wi.y * eta, z);
        Some(Printed {
            text: format!(
                "wi={} eta={} wo={}",
                vector(wi),
                c_general(f64::from(eta), 6),
                vector(wo)
            ),
            args: (wi.as_dvec3(), DVec3::Z, f64::from(eta)),
            outcome: Outcome::Transmitted(wo.as_dvec3()),
        })
    }
}

// ---------------------------------------------------------------------------------------------
// Cycles

/// Blender Cycles, 97dbe6f: `src/kernel/geom/shader_data.h` (`sd->wi = -ray->D`; backfacing
/// when `dot(Ng, wi) < 0`, then N turned round); `src/kernel/svm/closure.h`, the Glass BSDF
/// (`bsdf->ior = backfacing ? 1.0f / ior : ior`); `src/kernel/closure/bsdf_microfacet.h`,
/// `bsdf_microfacet_sample` for a smooth surface (`H = N`, `cos_HI = dot(H, wi)`, the Fresnel
/// of `fresnel_dielectric(cos_HI, m_eta, &cos_HO)`, refraction when `rand >= F`, `wo =
/// refract_angle(wi, H, cos_HO, m_inv_eta)`); `src/kernel/closure/bsdf_util.h`,
/// `fresnel_dielectric_polarized` (`eta_cos_theta_t_sq = sqr(eta) - (1 - sqr(cos_theta_i))`,
/// total internal reflection when it is `<= 0`; `cos_theta_t = -safe_sqrtf(...) / eta`;
/// `r_s`, `r_p`) and `refract_angle` (`(inv_eta * dot(normal, incident) + cos_theta_t) *
/// normal - inv_eta * incident`).
///
/// The student prints the refraction before the choice, where there is one, with Cycles'
/// `print_float3` (`"%s: %.8f %.8f %.8f\n"`): `print_float3("wi", wi); print_float3("N", N);
/// printf("backfacing: %d\n", backfacing); print_float3("wo", refract_angle(...));`.
mod cycles {
    use super::{Bug, Hit, Outcome, Printed, Vec3, c_fixed};

    const IOR: f32 = 1.5;

    fn print_float3(label: &str, v: Vec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_fixed(f64::from(c), 8));
        format!("{label}: {x} {y} {z}")
    }

    /// `fresnel_dielectric`'s `cos_theta_t`, `None` on total internal reflection (Cycles
    /// reflects then).
    fn cos_theta_t(cos_i: f32, eta: f32, bug: Bug) -> Option<f32> {
        let eta_cos_t_sq = eta * eta - (1.0 - cos_i * cos_i);
        if eta_cos_t_sq <= 0.0 {
            return None;
        }
        let root = eta_cos_t_sq.max(0.0).sqrt() / eta;
        Some(if bug == Bug::CyclesCosSign {
            root
        } else {
            -root
        })
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Option<Printed> {
        let wi = (-hit.travel).as_vec3().normalize();
        let ng = hit.outward.as_vec3().normalize();
        let backfacing = ng.dot(wi) < 0.0;
        let n = if backfacing { -ng } else { ng };
        let swapped = bug == Bug::CyclesTernarySwapped;
        let m_eta = if backfacing == swapped {
            IOR
        } else {
            1.0 / IOR
        };
        let m_inv_eta = 1.0 / m_eta;
        let cos_ho = cos_theta_t(n.dot(wi), m_eta, bug)?;
        let inv_eta = if bug == Bug::CyclesRefractEta {
            m_eta
        } else {
            m_inv_eta
        };
        let wo = (inv_eta * n.dot(wi) + cos_ho) * n - inv_eta * wi;
        let text = [
            print_float3("wi", wi),
            print_float3("N", n),
            format!("backfacing: {}", u8::from(backfacing)),
            print_float3("wo", wo),
        ]
        .join("\n");
        Some(Printed {
            text,
            args: (wi.as_dvec3(), n.as_dvec3(), f64::from(m_eta)),
            outcome: Outcome::Transmitted(wo.as_dvec3()),
        })
    }
}

// ---------------------------------------------------------------------------------------------
// three.js

/// three.js, 08e1c55: `src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js`,
/// `getVolumeTransmissionRay`: `refract( - v, normalize( n ), 1.0 / ior )`, `v` the unit
/// vector from the surface to the camera, `n` the normal turned toward the viewer
/// (`normal_fragment_begin.glsl.js`); GLSL's `refract(I, N, eta)` (`k = 1 - eta² (1 -
/// dot(N, I)²)`, zero when `k < 0`, else `eta I - (eta dot(N, I) + sqrt(k)) N`). Only front
/// faces refract: the rays drawn from inside are left out.
///
/// The student's JavaScript port computes in `Float32Array`s (`1.0 / ior` a JavaScript
/// number) and logs `console.log("I", I, "N", N, "eta", eta, "frontFacing", true, "->", r)`.
mod three {
    use super::{Bug, Hit, Outcome, Printed, Vec3, js_number, node_f32_array};

    const IOR: f64 = 1.5;

    fn refract(i: Vec3, n: Vec3, eta: f32) -> Vec3 {
        let d = n.x * i.x + n.y * i.y + n.z * i.z;
        let k = 1.0 - eta * eta * (1.0 - d * d);
        if k < 0.0 {
            Vec3::ZERO
        } else {
            eta * i - (eta * d + k.sqrt()) * n
        }
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Printed {
        let v = (-hit.travel).as_vec3().normalize();
        let n = hit.outward.as_vec3().normalize();
        let eta = if bug == Bug::ThreeEtaInverted {
            IOR
        } else {
            1.0 / IOR
        };
        let i = if bug == Bug::ThreeIncidentReversed {
            v
        } else {
            -v
        };
        let r = refract(i, n, eta as f32);
        Printed {
            text: format!(
                "I {} N {} eta {} frontFacing true -> {}",
                node_f32_array(i),
                node_f32_array(n),
                js_number(eta),
                node_f32_array(r)
            ),
            args: (i.as_dvec3(), n.as_dvec3(), eta),
            outcome: if r == Vec3::ZERO {
                Outcome::Reflected
            } else {
                Outcome::Transmitted(r.as_dvec3())
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_as_python_node_and_drjit_print_them() {
        assert_eq!(python_float(1.5), "1.5");
        assert_eq!(python_float(1.0 / 1.5), "0.6666666666666666");
        assert_eq!(python_float(f64::from(0.1_f32)), "0.10000000149011612");
        assert_eq!(python_float(-0.0), "-0.0");
        assert_eq!(python_float(1.0), "1.0");
        assert_eq!(python_float(1e-5), "1e-05");
        assert_eq!(js_number(-0.0), "-0");
        assert_eq!(js_number(f64::from(0.1_f32)), "0.10000000149011612");
        assert_eq!(js_number(1e-7), "1e-7");
        assert_eq!(js_number(f64::from(1e-7_f32)), "1.0000000116860974e-7");
        assert_eq!(js_number(123_456_792.0), "123456792");
        assert_eq!(
            node_f32_array(Vec3::new(0.5, -0.25, -0.8)),
            "Float32Array(3) [ 0.5, -0.25, -0.800000011920929 ]"
        );
        assert_eq!(
            node_f32_array(Vec3::new(0.391_630_2, -0.587_445_3, -0.708_039_9)),
            "Float32Array(3) [\n  0.3916302025318146,\n  -0.5874453186988831,\n  -0.7080398797988892\n]"
        );
        assert_eq!(drjit_vector(Vec3::new(0.1, -0.0, 1e-7)), "[0.1, -0, 1e-07]");
    }

    #[test]
    fn bug_free_calls_refract_by_snell_s_law() {
        for family in Family::ALL {
            let lines = log(family, Bug::None, 400, 3);
            assert!(lines.iter().all(|l| !l.wrong), "{family:?}");
            let inside = lines.iter().filter(|l| l.from_inside).count();
            assert_eq!(
                inside == 0,
                family == Family::ThreeJs,
                "{family:?}: {inside}"
            );
        }
        // Mitsuba's reflections where the ray refracts: sampled, printed as None.
        let mitsuba = log(Family::Mitsuba, Bug::None, 400, 3);
        let none = mitsuba
            .iter()
            .filter(|l| l.text.ends_with("wo=None"))
            .count();
        assert!(none > 40, "{none} reflections");
    }

    #[test]
    fn each_bug_makes_some_lines_wrong_and_records_print_as_their_ecosystem_does() {
        for family in Family::ALL {
            for &bug in family.bugs() {
                let lines = log(family, bug, 300, 5);
                let wrong = lines.iter().filter(|l| l.wrong).count();
                assert!(wrong > 20, "{family:?} {bug:?}: {wrong} wrong");
            }
        }
        let cycles = log(Family::Cycles, Bug::None, 1, 1)[0].text.clone();
        assert_eq!(cycles.lines().count(), 4, "{cycles}");
        assert!(
            cycles.starts_with("wi: ") && cycles.contains("\nbackfacing: "),
            "{cycles}"
        );
        let node = log(Family::ThreeJs, Bug::None, 30, 1);
        assert!(
            node.iter()
                .any(|l| l.text.contains("Float32Array(3) [\n  "))
        );
        assert!(
            node.iter()
                .all(|l| l.text.contains(" eta 0.6666666666666666 "))
        );
        let tungsten = log(Family::Tungsten, Bug::None, 1, 1)[0].text.clone();
        assert!(
            tungsten.starts_with("wi=(") && !tungsten.contains(", "),
            "{tungsten}"
        );
        let abs = log(Family::Mitsuba, Bug::MitsubaAbsDropped, 200, 2);
        assert!(
            abs.iter()
                .filter(|l| l.from_inside)
                .all(|l| l.text.ends_with("wo=None"))
        );
    }
}
