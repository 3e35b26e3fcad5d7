//! The API adapters against their APIs: glam's own `refract` bit for bit, the worked 3D example
//! computed independently (exact arithmetic, rounded once per operation) for every API, and
//! every adapter against the default kernel on random rays.

use glam::{DVec3, Vec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use refraction_kernel::api::{Api, mitsuba, pbrt, rtiow};
use refraction_kernel::{Real, Vector3 as _, condition_number, refract_facing, transmit_pbrt};

fn unit_vector() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(-1.0..1.0_f64)
        .prop_map(DVec3::from_array)
        .prop_filter("not too short", |v| v.length() > 0.1)
        .prop_map(DVec3::normalize)
}

/// Any vector: unit, long, short, tiny, huge.
fn any_vector() -> impl Strategy<Value = DVec3> {
    (unit_vector(), -40.0..40.0_f64).prop_map(|(v, e)| v * 2f64.powf(e))
}

fn to_s<S: Real>(v: DVec3) -> S::Vec3 {
    S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z))
}

fn wide<S: Real>(v: S::Vec3) -> DVec3 {
    DVec3::from_array(v.to_array().map(Real::to_f64))
}

fn bits<S: Real>(v: S::Vec3) -> [u64; 3] {
    v.to_array().map(|c| c.to_f64().to_bits())
}

/// glam's own `refract` for `Vec3` and `DVec3`, called by one name in code generic over the
/// precision (the kernel's `Vector3` leaves it out: only tests and the glam variant need it).
trait GlamRefract: Sized {
    type Scalar;
    fn glam_refract(self, normal: Self, eta: Self::Scalar) -> Self;
}

impl GlamRefract for Vec3 {
    type Scalar = f32;
    fn glam_refract(self, normal: Self, eta: f32) -> Self {
        self.refract(normal, eta)
    }
}

impl GlamRefract for DVec3 {
    type Scalar = f64;
    fn glam_refract(self, normal: Self, eta: f64) -> Self {
        self.refract(normal, eta)
    }
}

fn glam_agrees<S>(i: DVec3, n: DVec3, eta: f64) -> Result<(), TestCaseError>
where
    S: Real<Vec3: GlamRefract<Scalar = S>>,
{
    let (i, n, eta) = (to_s::<S>(i), to_s::<S>(n), S::from_f64(eta));
    let ours = refraction_kernel::api::glsl::refract::<S>(i, n, eta);
    prop_assert_eq!(bits::<S>(ours), bits::<S>(i.glam_refract(n, eta)));
    Ok(())
}

/// Inputs where an order-of-operations slip would show: grazing, normal, critical, TIR, zero,
/// subnormal, huge, infinite and NaN components, eta at its limits.
fn hard_cases() -> Vec<(DVec3, DVec3, f64)> {
    let d = DVec3::new(0.6, -0.8, 0.0);
    let critical = DVec3::new(1.0 / 1.5, -(1.0 - 1.0 / 2.25_f64).sqrt(), 0.0);
    let mut cases = vec![
        (DVec3::X, DVec3::Y, 1.0),
        (DVec3::X, DVec3::Y, 1.5),
        (-DVec3::Y, DVec3::Y, 1.5),
        (critical, DVec3::Y, 1.5),
        (d, DVec3::Y, 1.0 / 1.5),
        (d, -DVec3::Y, 1.0 / 1.5),
        (d, DVec3::Y, 1e-300),
        (d, DVec3::Y, 1e300),
        (d * 1e-310, DVec3::Y, 1.5),
        (d * 1e200, DVec3::Y, 1.5),
        (DVec3::ZERO, DVec3::Y, 1.5),
        (d, DVec3::ZERO, 1.5),
        (d, DVec3::Y, 0.0),
        (d, DVec3::Y, f64::NAN),
        (d, DVec3::Y, f64::INFINITY),
        (DVec3::new(f64::INFINITY, -1.0, 0.0), DVec3::Y, 1.5),
        (DVec3::new(f64::NAN, -1.0, 0.0), DVec3::Y, 1.5),
        (d, DVec3::new(0.0, f64::NAN, 0.0), 1.5),
    ];
    for k in 0..200 {
        let angle = f64::from(k) * 0.45_f64.to_radians();
        let incident = DVec3::new(angle.sin(), -angle.cos(), 0.0);
        cases.push((incident, DVec3::Y, 1.5));
        cases.push((incident, DVec3::Y, 1.0 / 1.5));
    }
    cases
}

#[test]
fn glsl_is_glam_bit_for_bit_on_hard_cases() {
    for (i, n, eta) in hard_cases() {
        glam_agrees::<f32>(i, n, eta).unwrap();
        glam_agrees::<f64>(i, n, eta).unwrap();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    #[test]
    fn glsl_is_glam_bit_for_bit(i in any_vector(), n in any_vector(), eta in 0.05..20.0_f64) {
        glam_agrees::<f32>(i, n, eta)?;
        glam_agrees::<f64>(i, n, eta)?;
    }

    /// Mitsuba's normal-based `refract` without FMA rounds exactly as GLSL's formula does:
    /// -(N·X) - (-(I·eta)) is I·eta - N·X exactly, and both sum the dot left to right.
    #[test]
    fn mitsuba_without_fma_is_glam_bit_for_bit(d in unit_vector(), n in unit_vector(), eta in 0.2..5.0_f64) {
        let n = if d.dot(n) > 0.0 { -n } else { n };
        for_precisions_mitsuba::<f32>(d, n, eta)?;
        for_precisions_mitsuba::<f64>(d, n, eta)?;
    }

    /// The kernel's pbrt-style call against pbrt's own `Refract`: the same etap, the same
    /// answer about total internal reflection, T within the kernel's bound.
    #[test]
    fn transmit_pbrt_answers_as_pbrt_does(
        wi in unit_vector(), n in unit_vector(), eta in 0.3..3.0_f64,
    ) {
        like_pbrt::<f32>(wi, n, eta)?;
        like_pbrt::<f64>(wi, n, eta)?;
    }

    #[test]
    fn every_adapter_refracts_like_the_kernel(d in unit_vector(), n in unit_vector(), mu in 0.3..3.0_f64) {
        let n = if d.dot(n) > 0.0 { -n } else { n };
        like_the_kernel::<f32>(d, n, mu)?;
        like_the_kernel::<f64>(d, n, mu)?;
    }
}

fn for_precisions_mitsuba<S>(d: DVec3, n: DVec3, eta: f64) -> Result<(), TestCaseError>
where
    S: Real<Vec3: GlamRefract<Scalar = S>>,
{
    let (d, n, eta_m) = (to_s::<S>(d), to_s::<S>(n), S::from_f64(eta));
    let eta_g = S::ONE / eta_m;
    let answer = mitsuba::answer::<S>(-d, n, eta_m, mitsuba::Fma::Unfused);
    let glam = d.glam_refract(n, eta_g);
    if answer.fresnel.f < S::ONE {
        prop_assert_eq!(bits::<S>(answer.wo), bits::<S>(glam));
    } else {
        prop_assert_eq!(glam.to_array(), [S::ZERO; 3]);
    }
    Ok(())
}

fn like_pbrt<S: Real>(wi: DVec3, n: DVec3, eta: f64) -> Result<(), TestCaseError> {
    let (wi_s, n_s, eta_s) = (to_s::<S>(wi), to_s::<S>(n), S::from_f64(eta));
    let (wi, n, eta) = (wide::<S>(wi_s), wide::<S>(n_s), eta_s.to_f64());
    let eps = S::EPSILON.to_f64();
    let cos_i = wi.dot(n);
    // pbrt's compensated dot product may see the other side within a few ε of grazing.
    if cos_i.abs() < 8.0 * eps {
        return Ok(());
    }
    let mu = if cos_i < 0.0 { eta } else { 1.0 / eta };
    let k = 1.0 - mu * mu * (1.0 - cos_i * cos_i);
    match (
        transmit_pbrt(wi_s, n_s, eta_s),
        pbrt::refract::<S>(wi_s, n_s, eta_s),
    ) {
        (Some(ours), Some(theirs)) => {
            prop_assert_eq!(ours.etap, theirs.etap);
            let kappa = condition_number(mu, cos_i.abs(), k.max(0.0).sqrt(), eps);
            let off = (wide::<S>(ours.t) - wide::<S>(theirs.wt)).length();
            prop_assert!(off <= 64.0 * eps * kappa, "{off:e}, κ = {kappa:e}");
        }
        (None, None) => {}
        // Rounding may decide differently within a few ulps of the critical angle, and pbrt's
        // 1 − cos²θi rounds to 1 within about √ε of grazing, `false` with eta near 1.
        (ours, theirs) => prop_assert!(
            k.abs() < 1e3 * eps || cos_i.abs() < 4.0 * eps.sqrt(),
            "{ours:?} {theirs:?} k = {k:e}"
        ),
    }
    Ok(())
}

fn like_the_kernel<S: Real>(d: DVec3, n: DVec3, mu: f64) -> Result<(), TestCaseError> {
    let (ds, ns, mus) = (to_s::<S>(d), to_s::<S>(n), S::from_f64(mu));
    let kernel = refract_facing(ds, ns, mus);
    let k = kernel.k.to_f64();
    for api in Api::ALL {
        let got = api.call(api.arguments::<S>(ds, ns, mus)).transmitted();
        match (kernel.transmitted, got) {
            (Some(right), Some(t)) => {
                let cos_t = right.cos_t.to_f64();
                let kappa = condition_number(mu, kernel.cos_i.to_f64(), cos_t, S::EPSILON.to_f64());
                let off = (wide::<S>(t) - wide::<S>(right.t)).length();
                prop_assert!(
                    off <= 64.0 * S::EPSILON.to_f64() * kappa,
                    "{api:?}: {off:e}"
                );
            }
            (None, None) => {}
            // Rounding may decide differently within a few ulps of the critical angle.
            _ => prop_assert!(k.abs() < 1e3 * S::EPSILON.to_f64(), "{api:?}: k = {k:e}"),
        }
    }
    Ok(())
}

/// The notes' generic 3D example: d = normalize(1, -2, 0.5), N = normalize(-0.2, 1, 0.3), air to
/// glass; the expected bits come from exact rational arithmetic rounded once per operation.
#[test]
fn the_worked_3d_example_in_every_api() {
    let d = DVec3::from_array(
        [
            0x3fdb_ee90_56fb_9c39,
            0xbfeb_ee90_56fb_9c39,
            0x3fcb_ee90_56fb_9c39,
        ]
        .map(f64::from_bits),
    );
    let n = DVec3::from_array(
        [
            0xbfc8_151b_b86f_ee1d,
            0x3fee_1a62_a68b_e9a4,
            0x3fd2_0fd4_ca53_f295,
        ]
        .map(f64::from_bits),
    );
    let d32 = Vec3::from_array([0x3edf_7483, 0xbf5f_7483, 0x3e5f_7483].map(f32::from_bits));
    let n32 = Vec3::from_array([0xbe40_a8de, 0x3f70_d315, 0x3e90_7ea6].map(f32::from_bits));
    let glsl = d.glam_refract(n, 1.0 / 1.5);
    assert_eq!(
        bits::<f64>(glsl),
        [
            0x3fd7_1945_fab6_be28,
            0xbfed_d09e_9bcd_3f2a,
            0x3fa4_c166_89ea_edd8
        ]
    );
    let glsl32 = d32.glam_refract(n32, 1.0 / 1.5);
    assert_eq!(
        glsl32.to_array().map(f32::to_bits),
        [0x3eb8_ca30, 0xbf6e_84f5, 0x3d26_0b3a]
    );
    let wt = pbrt::refract::<f64>(-d, n, 1.5).unwrap().wt;
    assert_eq!(
        bits::<f64>(wt),
        [
            0x3fd7_1945_fab6_be27,
            0xbfed_d09e_9bcd_3f29,
            0x3fa4_c166_89ea_edde
        ]
    );
    let wt32 = pbrt::refract::<f32>(-d32, n32, 1.5).unwrap().wt;
    assert_eq!(
        wt32.to_array().map(f32::to_bits),
        [0x3eb8_ca30, 0xbf6e_84f4, 0x3d26_0b36]
    );
    assert_eq!(
        bits::<f64>(rtiow::refract::<f64>(d, n, 1.0 / 1.5)),
        [
            0x3fd7_1945_fab6_be27,
            0xbfed_d09e_9bcd_3f2a,
            0x3fa4_c166_89ea_edd8
        ]
    );
    let fused = mitsuba::answer::<f32>(-d32, n32, 1.5, mitsuba::Fma::Fused).wo;
    assert_eq!(
        fused.to_array().map(f32::to_bits),
        [0x3eb8_ca31, 0xbf6e_84f5, 0x3d26_0b3b]
    );
    let unfused = mitsuba::answer::<f32>(-d32, n32, 1.5, mitsuba::Fma::Unfused).wo;
    assert_eq!(unfused, glsl32);
}

#[test]
fn total_internal_reflection_as_each_api_signals_it() {
    let angle = 45_f64.to_radians();
    let up = DVec3::new(angle.sin(), angle.cos(), 0.0);
    let facing = -DVec3::Y;
    for api in Api::ALL {
        let returned = api.call(api.arguments::<f64>(up, facing, 1.5));
        assert_eq!(returned.transmitted(), None, "{api:?}");
    }
    // The book's and Mitsuba's formulas still give a vector there; GLSL's is zero, pbrt's none.
    let formula = |api: Api| api.call(api.arguments::<f64>(up, facing, 1.5)).formula();
    assert_eq!(formula(Api::Glsl), Some(DVec3::ZERO));
    assert_eq!(formula(Api::Pbrt), None);
    assert!(formula(Api::Rtiow).unwrap().length() > 1.1);
    assert!(formula(Api::Mitsuba).unwrap().length() > 1.0);
}

/// pbrt's rounded 1 − cos²θi is 1 for a ray 1e-4 from grazing in f32, so with eta = 1 its
/// `Refract` returns `false`; the kernel's pbrt-style call transmits the ray unchanged.
#[test]
fn near_grazing_at_eta_one_pbrt_refuses_and_transmit_pbrt_transmits() {
    let d = Vec3::new(1.0, -1e-4, 0.0).normalize();
    assert_eq!(pbrt::refract::<f32>(-d, Vec3::Y, 1.0), None);
    let ours = transmit_pbrt(-d, Vec3::Y, 1.0).expect("the ray crosses the surface");
    assert_eq!((ours.t, ours.etap), (d, 1.0));
}
