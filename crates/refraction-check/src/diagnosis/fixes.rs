//! The fix of a finding in the student's own words: which part of T is wrong and which
//! variable that implicates, then, for a renderer the docs name (`--renderer`, or the API's),
//! the line of its code to change, and otherwise the fix in the formula's terms.
//!
//! The quoted lines are the renderers' own, as written at the commits `docs/check.md` names
//! (one line each, to say where to look): Mitsuba 3 `include/mitsuba/render/fresnel.h`
//! `fresnel`/`refract` and `src/bsdfs/dielectric.cpp`; Tungsten
//! `src/core/bsdfs/DielectricBsdf.cpp` `DielectricBsdf::sample` and `Fresnel.hpp`; Cycles
//! `src/kernel/svm/closure.h`, `closure/bsdf_util.h`, `closure/bsdf_microfacet.h`; three.js
//! `transmission_pars_fragment.glsl.js` `getVolumeTransmissionRay`; smallpt `radiance()`;
//! pbrt-v4 `src/pbrt/util/scattering.h` `Refract`; the book's `vec3.h`, `material.h`,
//! `hittable.h`; GLSL's built-in `refract`; glam's `Vec3::refract` (`src/f32/vec3.rs`); the
//! Python calls of Mitsuba 3's `mi.fresnel` and `mi.refract`.

use refraction_i18n::t;
use refraction_kernel::api::Api;

use super::hypotheses::{Sides, Slip};
use super::{Code, Renderer};

/// Where the mistake shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Location {
    /// In the arguments the code passed (the logged eta, normal or incident vector).
    Arguments,
    /// In what the code computed from right arguments.
    Code,
}

/// What a fix is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Fix {
    /// The finding's code.
    pub code: Code,
    /// The formula's mistake, for a hypothesis of the formula.
    pub slip: Option<Slip>,
    /// The rays it touches.
    pub sides: Sides,
    /// Where it shows.
    pub location: Location,
}

/// The fix, in `renderer`'s code where it has a line for it, else `api`'s, else in the
/// formula's terms; led by which part of T is wrong.
pub(super) fn fix(renderer: Option<Renderer>, api: Option<Api>, fix: &Fix) -> String {
    let renderer = renderer.or_else(|| api.map(Renderer::of_api));
    let line = renderer
        .and_then(|r| renderer_line(r, fix))
        .map(|(verb, code, place)| {
            let said = verb_sentence(verb, code);
            t!("check-fix-in", fix = said, place = place)
        })
        .unwrap_or_else(|| generic(fix));
    match part(fix) {
        Some(part) => t!("check-fix-part", part = part, fix = line),
        None => line,
    }
}

/// The rays a mistake touches, in words to follow a sentence ("" for all of them).
fn sides_words(sides: Sides) -> String {
    match sides {
        Sides::Both => String::new(),
        Sides::Entering => t!("check-sides-entering"),
        Sides::Leaving => t!("check-sides-leaving"),
    }
}

/// Which part of T is wrong, for a mistake of the formula.
fn part(fix: &Fix) -> Option<String> {
    let sides = sides_words(fix.sides);
    Some(match fix.slip? {
        Slip::Ratio => t!("check-part-ratio", sides = sides),
        Slip::RatioAcross => t!("check-part-across", sides = sides),
        Slip::RatioAlong => t!("check-part-along", sides = sides),
        Slip::Normal => t!("check-part-normal", sides = sides),
        Slip::Incident => t!("check-part-incident"),
        Slip::AcrossSign => t!("check-part-across-sign"),
        Slip::Root => t!("check-part-root"),
        Slip::Term => t!("check-part-term", sides = sides),
        Slip::NoFlip => t!("check-part-no-flip"),
    })
}

/// `verb` (`pass`, `write`, `restore`) with the code to pass or write.
fn verb_sentence(verb: &str, code: &str) -> String {
    match verb {
        "pass" => t!("check-fix-pass", code = code),
        "restore" => t!("check-fix-restore", code = code),
        _ => t!("check-fix-write", code = code),
    }
}

/// The fix in the formula's terms, naming the variable.
fn generic(fix: &Fix) -> String {
    match (fix.slip, fix.code) {
        (Some(Slip::RatioAcross), _) => t!("check-fix-generic-ratio-across"),
        (Some(Slip::RatioAlong), _) => t!("check-fix-generic-ratio-along"),
        (Some(Slip::AcrossSign), _) => t!("check-fix-generic-across-sign"),
        (_, Code::FalseTir) if fix.sides != Sides::Both => t!("check-fix-generic-never-transmits"),
        (_, code) => generic_code(code),
    }
}

/// The fix for `code` in any renderer's own refraction.
fn generic_code(code: Code) -> String {
    match code {
        Code::EtaInverted => t!("check-fix-generic-eta-inverted"),
        Code::IncidentReversed => t!("check-fix-generic-incident-reversed"),
        Code::NormalNotFacing => t!("check-fix-generic-normal-not-facing"),
        Code::NoFlipInside => t!("check-fix-generic-no-flip-inside"),
        Code::NormalTermSign => t!("check-fix-generic-normal-term-sign"),
        Code::OtherRoot => t!("check-fix-generic-other-root"),
        Code::MissedTir => t!("check-fix-generic-missed-tir"),
        Code::FalseTir => t!("check-fix-generic-false-tir"),
        Code::NotUnitInput => t!("check-fix-generic-not-unit-input"),
        Code::NotTheApiResult => t!("check-fix-generic-not-the-api-result"),
        Code::AcrossSign => t!("check-fix-generic-across-sign"),
        Code::RefractedTwice => t!("check-fix-generic-refracted-twice"),
        Code::FresnelCosSign => t!("check-fix-generic-fresnel-cos-sign"),
        Code::NormalsMixed => t!("check-fix-generic-normals-mixed"),
    }
}

/// What a fix is about, as the renderers' tables look it up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum About {
    /// The ratio passed (the caller's).
    RatioPassed,
    /// The ratio chosen by the side inside the code.
    RatioChosen,
    /// The ratio in the part across N.
    Across,
    /// The ratio in cosθt, for rays from one side (a cosine passed without its sign taken
    /// off) or both.
    Along(Sides),
    /// The normal.
    Normal,
    /// The incident vector passed.
    IncidentPassed,
    /// The sign of the part across N in the code.
    AcrossSign,
    /// The root's sign.
    Root,
    /// The term along N.
    Term,
    /// pbrt's flip.
    NoFlip,
    /// A direction where it must reflect.
    MissedTir,
    /// Reflected where it refracts, on one side or all.
    FalseTir,
    /// Refracted twice at one crossing.
    Twice,
    /// The cosine's sign lost where F (or the choice to transmit) is computed.
    CosSign,
    /// The side decided with one normal, `refract` given another.
    NormalsMixed,
    /// Anything else.
    Other,
}

fn about(fix: &Fix) -> About {
    match (fix.slip, fix.code, fix.location) {
        (_, Code::RefractedTwice, _) => About::Twice,
        (_, Code::FresnelCosSign, _) => About::CosSign,
        (_, Code::NormalsMixed, _) => About::NormalsMixed,
        (Some(Slip::Ratio), _, Location::Arguments)
        | (None, Code::EtaInverted, Location::Arguments) => About::RatioPassed,
        (Some(Slip::Ratio), ..) | (None, Code::EtaInverted, _) => About::RatioChosen,
        (Some(Slip::RatioAcross), ..) => About::Across,
        (Some(Slip::RatioAlong), ..) => About::Along(fix.sides),
        (Some(Slip::Normal), ..) | (None, Code::NormalNotFacing, _) => About::Normal,
        (Some(Slip::Incident), ..) | (None, Code::IncidentReversed, _) => About::IncidentPassed,
        (Some(Slip::AcrossSign), ..) | (None, Code::AcrossSign, _) => About::AcrossSign,
        (Some(Slip::Root), ..) | (None, Code::OtherRoot, _) => About::Root,
        (Some(Slip::Term), ..) | (None, Code::NormalTermSign, _) => About::Term,
        (Some(Slip::NoFlip), ..) | (None, Code::NoFlipInside, _) => About::NoFlip,
        (None, Code::MissedTir, _) => About::MissedTir,
        (None, Code::FalseTir, _) => About::FalseTir,
        (None, ..) => About::Other,
    }
}

/// The line to change in `renderer`'s code: the verb, the line as it must read, and where.
fn renderer_line(
    renderer: Renderer,
    fix: &Fix,
) -> Option<(&'static str, &'static str, &'static str)> {
    let about = about(fix);
    match renderer {
        Renderer::Mitsuba => mitsuba(about),
        Renderer::Tungsten => tungsten(about),
        Renderer::Cycles => cycles(about),
        Renderer::ThreeJs => three_js(about),
        Renderer::Smallpt => smallpt(about),
        Renderer::Pbrt => pbrt(about),
        Renderer::Rtiow => rtiow(about),
        Renderer::Glsl => glsl(about),
        Renderer::Glam => glam(about),
        Renderer::MitsubaPython => mitsuba_python(about),
    }
}

type Line = Option<(&'static str, &'static str, &'static str)>;

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn mitsuba(about: About) -> Line {
    const FRESNEL: &str = "fresnel, include/mitsuba/render/fresnel.h";
    Some(match about {
        About::RatioPassed => ("write", "m_eta = int_ior / ext_ior;", "SmoothDielectric's constructor, src/bsdfs/dielectric.cpp"),
        About::RatioChosen => ("write", "eta_it = dr::select(outside_mask, eta, rcp_eta), eta_ti = dr::select(outside_mask, rcp_eta, eta);", FRESNEL),
        About::Along(Sides::Both) => ("write", "Float cos_theta_t_sqr = dr::fnmadd(dr::fnmadd(cos_theta_i, cos_theta_i, 1.f), eta_ti * eta_ti, 1.f);", FRESNEL),
        About::Along(_) => ("write", "Float cos_theta_i_abs = dr::abs(cos_theta_i);", FRESNEL),
        About::Across | About::AcrossSign => ("write", "return Vector<Float, 3>(-eta_ti * wi.x(), -eta_ti * wi.y(), cos_theta_t);", "refract, include/mitsuba/render/fresnel.h"),
        About::Root => ("write", "Float cos_theta_t = dr::mulsign_neg(cos_theta_t_abs, cos_theta_i);", FRESNEL),
        About::IncidentPassed => ("pass", "Frame3f::cos_theta(si.wi) // wi in the local frame, pointing away from the surface", "SmoothDielectric::sample"),
        About::Normal => ("pass", "refract(si.wi, cos_theta_t, eta_ti) // about the shading frame's z axis: fresnel turns it", "SmoothDielectric::sample"),
        About::MissedTir => ("write", "Float cos_theta_t_abs = dr::safe_sqrt(cos_theta_t_sqr); // F = 1 past the critical angle: it reflects", FRESNEL),
        About::FalseTir => ("write", "Float cos_theta_i_abs = dr::abs(cos_theta_i); // F, the probability of reflecting, at most 1", FRESNEL),
        About::Twice => ("write", "bs.wo = dr::select(selected_r, reflect(si.wi), refract(si.wi, cos_theta_t, eta_ti)); // one refract per crossing", "SmoothDielectric::sample, src/bsdfs/dielectric.cpp"),
        About::CosSign => ("write", "Float cos_theta_i_abs = dr::abs(cos_theta_i); // F from |cos θi|, below 1 where k > 0", FRESNEL),
        About::Term | About::NoFlip | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn tungsten(about: About) -> Line {
    const SAMPLE: &str = "DielectricBsdf::sample, src/core/bsdfs/DielectricBsdf.cpp";
    const FRESNEL: &str = "Fresnel::dielectricReflectance, src/core/bsdfs/Fresnel.hpp";
    Some(match about {
        About::RatioPassed | About::RatioChosen => ("write", "float eta = event.wi.z() < 0.0f ? _ior : _invIor;", SAMPLE),
        About::Along(Sides::Both) => ("write", "float sinThetaTSq = eta*eta*(1.0f - cosThetaI*cosThetaI);", FRESNEL),
        About::Along(_) => ("write", "float F = Fresnel::dielectricReflectance(eta, std::abs(event.wi.z()), cosThetaT);", SAMPLE),
        About::Across | About::AcrossSign | About::Root => ("write", "event.wo = Vec3f(-event.wi.x()*eta, -event.wi.y()*eta, -std::copysign(cosThetaT, event.wi.z()));", SAMPLE),
        About::MissedTir => ("write", "if (sinThetaTSq > 1.0f) { cosThetaT = 0.0f; return 1.0f; }", FRESNEL),
        About::FalseTir => ("write", "float F = Fresnel::dielectricReflectance(eta, std::abs(event.wi.z()), cosThetaT); // reflect with probability F, at most 1", SAMPLE),
        About::CosSign => ("write", "float F = Fresnel::dielectricReflectance(eta, std::abs(event.wi.z()), cosThetaT);", SAMPLE),
        About::IncidentPassed | About::Normal | About::Term | About::NoFlip | About::Twice | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn cycles(about: About) -> Line {
    const UTIL: &str = "fresnel_dielectric_polarized, src/kernel/closure/bsdf_util.h";
    const SAMPLE: &str = "bsdf_microfacet_sample, src/kernel/closure/bsdf_microfacet.h";
    Some(match about {
        About::RatioPassed | About::RatioChosen => ("write", "bsdf->ior = (sd->flag & SD_BACKFACING) ? 1.0f / ior : ior;", "the Glass BSDF, src/kernel/svm/closure.h"),
        About::Across => ("pass", "refract_angle(wi, H, cos_HO, m_inv_eta)", SAMPLE),
        About::Along(_) => ("write", "const float eta_cos_theta_t_sq = sqr(eta) - (1.0f - sqr(cos_theta_i));", UTIL),
        About::Root => ("write", "const float cos_theta_t = -safe_sqrtf(eta_cos_theta_t_sq) / eta;", UTIL),
        About::AcrossSign => ("write", "return (inv_eta * dot(normal, incident) + cos_theta_t) * normal - inv_eta * incident;", "refract_angle, src/kernel/closure/bsdf_util.h"),
        About::Normal => ("write", "if (backfacing) { sd->flag |= SD_BACKFACING; sd->Ng = -sd->Ng; sd->N = -sd->N; }", "src/kernel/geom/shader_data.h"),
        About::MissedTir => ("write", "if (eta_cos_theta_t_sq <= 0) { return one_float2(); } // total internal reflection", UTIL),
        About::FalseTir => ("write", "const bool do_refract = (rand.z >= pdf_reflect);", SAMPLE),
        About::IncidentPassed | About::Term | About::NoFlip | About::Twice | About::CosSign | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn three_js(about: About) -> Line {
    const SHADER: &str = "getVolumeTransmissionRay, src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js";
    Some(match about {
        About::RatioPassed | About::RatioChosen | About::IncidentPassed => ("write", "vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );", SHADER),
        About::Normal => ("write", "normal *= faceDirection;", "normal_fragment_begin.glsl.js"),
        _ => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn smallpt(about: About) -> Line {
    const RADIANCE: &str = "radiance(), smallpt.cpp";
    Some(match about {
        About::RatioPassed | About::RatioChosen | About::Along(_) | About::Across => ("write", "double nc=1, nt=1.5, nnt=into?nc/nt:nt/nc, ddn=r.d.dot(nl), cos2t;", RADIANCE),
        About::Normal | About::Root | About::Term | About::AcrossSign | About::IncidentPassed => ("write", "Vec tdir = (r.d*nnt - n*((into?1:-1)*(ddn*nnt+sqrt(cos2t)))).norm();", RADIANCE),
        About::MissedTir | About::FalseTir => ("write", "if ((cos2t=1-nnt*nnt*(1-ddn*ddn))<0) return obj.e + f.mult(radiance(reflRay,depth,Xi));", RADIANCE),
        About::CosSign => ("write", "double a=nt-nc, b=nt+nc, R0=a*a/(b*b), c = 1-(into?-ddn:tdir.dot(n));", RADIANCE),
        About::NoFlip | About::Twice | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn pbrt(about: About) -> Line {
    const REFRACT: &str = "Refract, src/pbrt/util/scattering.h";
    Some(match about {
        About::RatioPassed => ("pass", "Refract(wo, n, eta, &etap, &wi); // eta = n_inside / n_outside as the material gives it, not 1 / eta", "DielectricBxDF::Sample_f"),
        About::RatioChosen | About::NoFlip => ("restore", "if (cosTheta_i < 0) { eta = 1 / eta; cosTheta_i = -cosTheta_i; n = -n; }", REFRACT),
        About::Along(_) => ("write", "Float sin2Theta_t = sin2Theta_i / Sqr(eta);", REFRACT),
        About::Term | About::Across | About::AcrossSign => ("write", "*wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);", REFRACT),
        About::Root => ("write", "Float cosTheta_t = SafeSqrt(1 - sin2Theta_t); *wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);", REFRACT),
        About::IncidentPassed => ("pass", "Refract(-ray.d, n, eta, &etap, &wt); // wi points back where the ray came from", "the caller"),
        About::Normal => ("pass", "Refract(wo, n, eta, &etap, &wi); // n: the shape's outward normal, which Refract turns itself", "the caller"),
        About::MissedTir | About::FalseTir => ("write", "Float sin2Theta_t = sin2Theta_i / Sqr(eta); if (sin2Theta_t >= 1) return false;", REFRACT),
        About::CosSign => ("restore", "if (cosTheta_i < 0) { eta = 1 / eta; cosTheta_i = -cosTheta_i; }", "FrDielectric, src/pbrt/util/scattering.h"),
        About::Twice | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn rtiow(about: About) -> Line {
    const REFRACT: &str = "refract, vec3.h";
    Some(match about {
        About::RatioPassed | About::RatioChosen => ("write", "double ri = rec.front_face ? (1.0/refraction_index) : refraction_index;", "dielectric::scatter, material.h"),
        About::Normal => ("write", "normal = front_face ? outward_normal : -outward_normal;", "hit_record::set_face_normal, hittable.h"),
        About::IncidentPassed => ("pass", "vec3 unit_direction = unit_vector(r_in.direction());", "dielectric::scatter, material.h"),
        About::Root | About::Term => ("write", "vec3 r_out_parallel = -std::sqrt(std::fabs(1.0 - r_out_perp.length_squared())) * n;", REFRACT),
        About::Across | About::AcrossSign => ("write", "vec3 r_out_perp = etai_over_etat * (uv + cos_theta*n);", REFRACT),
        About::MissedTir | About::FalseTir => ("write", "bool cannot_refract = ri * sin_theta > 1.0; // then reflect", "dielectric::scatter, material.h"),
        About::CosSign => ("write", "double cos_theta = std::fmin(dot(-unit_direction, rec.normal), 1.0);", "dielectric::scatter, material.h"),
        About::Along(_) | About::NoFlip | About::Twice | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn glsl(about: About) -> Line {
    const OWN: &str = "your own refract: the built-in computes it so";
    Some(match about {
        About::RatioPassed | About::RatioChosen => ("pass", "refract(I, N, entering ? 1.0 / ior : ior)", "the call"),
        About::Normal => ("pass", "refract(I, faceforward(N, I, N), eta)", "the call"),
        About::IncidentPassed => ("pass", "refract(rd, N, eta)", "the call"),
        About::Root | About::Term | About::AcrossSign | About::Across => ("write", "eta * I - (eta * dot(N, I) + sqrt(k)) * N", OWN),
        About::MissedTir => ("write", "vec3 T = refract(I, N, eta); if (dot(T, T) == 0.0) { /* reflect */ } else { T = normalize(T); }", "the caller: refract returns vec3(0.0) past the critical angle, and normalize(vec3(0.0)) is NaN"),
        About::FalseTir | About::Along(_) => ("write", "float k = 1.0 - eta * eta * (1.0 - dot(N, I) * dot(N, I)); if (k < 0.0) return vec3(0.0);", OWN),
        About::Twice => ("write", "vec3 T = refract(I, N, eta); // once per crossing: trace T on, never refract(T, N, eta)", "the caller"),
        About::NoFlip | About::CosSign | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn glam(about: About) -> Line {
    const CALL: &str = "the call of Vec3::refract";
    const OWN: &str = "your own refract: glam's Vec3::refract computes it so";
    Some(match about {
        About::RatioPassed | About::RatioChosen => ("pass", "incident.refract(normal, if entering { 1.0 / ior } else { ior })", CALL),
        About::Normal => ("pass", "incident.refract(if incident.dot(normal) > 0.0 { -normal } else { normal }, eta)", CALL),
        About::IncidentPassed => ("pass", "ray.direction.normalize().refract(normal, eta)", CALL),
        About::Root | About::Term | About::AcrossSign | About::Across => ("write", "eta * self - (eta * normal.dot(self) + k.sqrt()) * normal", OWN),
        About::MissedTir => ("write", "let t = incident.refract(normal, eta); if t == Vec3::ZERO { /* reflect */ } else { t.normalize() }", "the caller: Vec3::refract returns Vec3::ZERO past the critical angle, and normalize() of it is NaN"),
        About::FalseTir | About::Along(_) => ("write", "let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i); if k < 0.0 { return Vec3::ZERO; }", OWN),
        About::Twice => ("write", "let t = incident.refract(normal, eta); // once per crossing: trace t on, never t.refract(normal, eta)", "the caller"),
        About::NoFlip | About::CosSign | About::NormalsMixed | About::Other => return None,
    })
}

// untranslated: each renderer's own code and the file and function it is in
#[rustfmt::skip]
fn mitsuba_python(about: About) -> Line {
    const FRESNEL: &str = "your call of mi.fresnel";
    const REFRACT: &str = "your call of mi.refract";
    Some(match about {
        About::RatioPassed | About::RatioChosen | About::Along(Sides::Both) => ("pass", "F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), int_ior / ext_ior)", FRESNEL),
        About::Along(_) | About::NoFlip => ("pass", "mi.fresnel(mi.Frame3f.cos_theta(wi), eta)  # the cosine with its sign, never abs(): for rays from inside fresnel must invert the ratio", FRESNEL),
        About::Across => ("pass", "mi.refract(wi, cos_theta_t, eta_ti)  # eta_ti, fresnel's fourth value, not eta_it", REFRACT),
        About::AcrossSign => ("write", "wo = mi.refract(wi, cos_theta_t, eta_ti)  # (-eta_ti * wi.x, -eta_ti * wi.y, cos_theta_t)", "your script, where it builds the vector by hand"),
        About::Root => ("pass", "mi.refract(wi, cos_theta_t, eta_ti)  # cos_theta_t as mi.fresnel returns it, its sign kept", REFRACT),
        About::IncidentPassed => ("pass", "mi.fresnel(mi.Frame3f.cos_theta(wi), eta)  # wi points away from the surface, back along the ray: -ray.d", FRESNEL),
        About::Normal => ("pass", "mi.refract(wi, cos_theta_t, eta_ti)  # about the local frame's z axis, the outward normal: fresnel turns the side itself", REFRACT),
        About::MissedTir => ("write", "wo = dr.select(F < 1, mi.refract(wi, cos_theta_t, eta_ti), mi.reflect(wi))  # past the critical angle mi.fresnel returns F = 1", "your script"),
        About::FalseTir => ("write", "selected_r = sample1 <= F  # reflect with probability F, below 1 wherever k > 0", "your script"),
        About::Twice => ("write", "wo = mi.refract(wi, cos_theta_t, eta_ti)  # once per crossing, never mi.refract of wo again", "your script"),
        About::Term | About::CosSign | About::NormalsMixed | About::Other => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(renderer: Option<Renderer>, slip: Slip, sides: Sides, location: Location) -> String {
        let code = slip.code(sides);
        fix(
            renderer,
            None,
            &Fix {
                code,
                slip: Some(slip),
                sides,
                location,
            },
        )
    }

    #[test]
    fn each_fix_says_the_part_and_the_renderer_s_line() {
        let across = of(
            Some(Renderer::Cycles),
            Slip::RatioAcross,
            Sides::Both,
            Location::Code,
        );
        assert!(
            across.contains("across N") && across.contains("m_inv_eta"),
            "{across}"
        );
        let along = of(
            Some(Renderer::Tungsten),
            Slip::RatioAlong,
            Sides::Leaving,
            Location::Code,
        );
        assert!(
            along.contains("std::abs(event.wi.z())") && along.contains("leaving"),
            "{along}"
        );
        let root = of(
            Some(Renderer::Mitsuba),
            Slip::Root,
            Sides::Both,
            Location::Code,
        );
        assert!(
            root.contains("mulsign_neg") && !root.contains("√k"),
            "{root}"
        );
        let passed = of(
            Some(Renderer::Mitsuba),
            Slip::Ratio,
            Sides::Both,
            Location::Arguments,
        );
        assert!(passed.contains("int_ior / ext_ior"), "{passed}");
        let chosen = of(
            Some(Renderer::Mitsuba),
            Slip::Ratio,
            Sides::Both,
            Location::Code,
        );
        assert!(chosen.contains("dr::select(outside_mask"), "{chosen}");
    }

    /// Every fix a finding can be given: each slip on each side it takes, in the arguments or
    /// the code, and each code a line names on its own.
    fn every_fix() -> Vec<Fix> {
        let mut all = Vec::new();
        for location in [Location::Arguments, Location::Code] {
            for slip in Slip::ALL {
                for sides in [Sides::Both, Sides::Entering, Sides::Leaving] {
                    let code = slip.code(sides);
                    all.push(Fix {
                        code,
                        slip: Some(slip),
                        sides,
                        location,
                    });
                }
            }
            for code in Code::ALL {
                all.push(Fix {
                    code,
                    slip: None,
                    sides: Sides::Both,
                    location,
                });
            }
        }
        all
    }

    #[test]
    fn each_ecosystem_s_fix_uses_its_own_names_and_no_other_s() {
        // Names only one ecosystem's code has (issue 43: a glam user was given GLSL's
        // faceforward, an Eigen renderer smallpt's variables, a Python script Mitsuba's C++).
        let ecosystems: [(Option<Renderer>, &[&str]); 6] = [
            (Some(Renderer::Glsl), &["faceforward", "vec3("]),
            (Some(Renderer::Glam), &["Vec3::", "incident.refract"]),
            (Some(Renderer::Pbrt), &["cosTheta", "Refract("]),
            (
                Some(Renderer::Mitsuba),
                &["dr::", "include/mitsuba", "si.wi"],
            ),
            (Some(Renderer::MitsubaPython), &["mi.fresnel", "mi.refract"]),
            // Any renderer's own code (an Eigen renderer): the formula's terms only.
            (None, &[]),
        ];
        let smallpt = ["nnt", "into?", "into ?", "nc/nt", "nc / nt"];
        for (renderer, own) in ecosystems {
            let mut quoted = 0;
            for f in every_fix() {
                let text = fix(renderer, None, &f);
                let foreign = ecosystems
                    .iter()
                    .filter(|(other, _)| *other != renderer)
                    .flat_map(|(_, names)| names.iter())
                    .chain(&smallpt)
                    .find(|name| text.contains(**name));
                assert!(
                    foreign.is_none(),
                    "{renderer:?} {f:?}: {foreign:?} in {text}"
                );
                quoted += usize::from(own.iter().any(|name| text.contains(name)));
            }
            assert!(renderer.is_none() || quoted > 10, "{renderer:?}: {quoted}");
        }
    }

    #[test]
    fn without_a_renderer_the_fix_names_the_variable() {
        let across = of(None, Slip::RatioAcross, Sides::Both, Location::Code);
        assert!(across.contains("1/μ²"), "{across}");
        let unexplained = fix(
            None,
            None,
            &Fix {
                code: Code::NotTheApiResult,
                slip: None,
                sides: Sides::Both,
                location: Location::Code,
            },
        );
        assert!(!unexplained.contains("compare"), "{unexplained}");
    }
}
