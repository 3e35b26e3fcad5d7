//! Logs of `refract` calls as four real renderers make them, with one-line bugs injected: test
//! material for `check`'s whole-log diagnosis (which single bug explains a log).
//!
//! Each renderer's call path is re-written in Rust from its source (read at the commits named
//! below; no code text copied): the same order of operations, in the precision the original
//! uses (pbrt-v4's `Float` is `float` unless built with `PBRT_FLOAT_AS_DOUBLE`; smallpt and
//! Ray Tracing in One Weekend use `double`; a GLSL shader uses `float`). Every call prints one
//! line in the form a student would plausibly `printf` from that code, and every line carries
//! its ground truth: whether it is wrong, whether the ray arrives from inside the glass, and
//! whether it is past the critical angle.
//!
//! The scene is a glass sphere (index [`INSIDE`] = 1.5) in air ([`OUTSIDE`] = 1): each ray
//! meets its surface either from outside (entering) or from inside (leaving), half each, at an
//! angle of incidence drawn uniformly in [0°, 88°], so a little over half of the rays from
//! inside are past the critical angle (41.8°).
//!
//! | renderer | source read | precision | where the line is printed |
//! | --- | --- | --- | --- |
//! | [`Renderer::Pbrt`] | mmp/pbrt-v4 5f7a606 `src/pbrt/util/scattering.h` `Refract`, `src/pbrt/bxdfs.cpp` `DielectricBxDF::Sample_f` | f32 | after every `Refract` call, `ok=0` included |
//! | [`Renderer::Smallpt`] | Kevin Beason's `smallpt.cpp` (2008), `radiance()`, the REFR branch (copies: ldm5180/smallpt and others, identical there) | f64 | after `tdir`: a ray that `return`s on total internal reflection prints nothing |
//! | [`Renderer::Rtiow`] | RayTracing/raytracing.github.io (`release` 94b510c = v4.0.0, `dev` d3e5bf9) `src/InOneWeekend/vec3.h`, `hittable.h`, `sphere.h`, `material.h` and the book's listing `dielectric-with-refraction` | f64 | after `dielectric::scatter` chose `direction` (a reflection where `cannot_refract`) |
//! | [`Renderer::Glsl`] | GLSL 4.60 built-in `refract(I, N, eta)` (glam 0.34 `Vec3::refract` computes the same) | f32 | after the `refract` call, via `debugPrintfEXT`, with the ray's `rd` |
//!
//! A line is [`Line::wrong`] when the call differs from the one the same renderer's bug-free
//! code makes for the same ray: an argument (the incident vector or the normal more than 1e-4
//! rad away, the index ratio more than 1e-4 relative) or the outcome (a direction more than
//! 1e-4 rad away, a transmission where it signals total internal reflection or the reverse),
//! or a line printed where the bug-free code prints none (smallpt); smallpt's ratio `nnt`
//! counts only where the line prints it (mixed precision). A call with a wrong
//! argument is wrong even where its outcome happens to be right, as `check` judges calls: an
//! outward normal past the critical angle (GLSL, the book: still the zero vector or the
//! reflection), GLSL's reversed `I` past it (still zero), pbrt's `1 / eta` at normal
//! incidence. The bug-free code itself agrees with Snell's law (the tests check it).
//!
//! `count` in [`log`] is the number of lines; rays that print nothing are drawn past.

use glam::{DVec3, Vec3};

/// The index of refraction of the glass (`check --inside`).
pub(crate) const INSIDE: f64 = 1.5;

/// The index of refraction around the glass (`check --outside`).
pub(crate) const OUTSIDE: f64 = 1.0;

/// Largest angle of incidence drawn, in degrees (grazing rays are left out).
const MAX_INCIDENCE_DEG: f64 = 88.0;

/// A call's direction (or argument) counts as wrong beyond this angle from the bug-free one
/// (radians; a ratio beyond this relative difference): far above rounding (f32 rounding is
/// ~1e-7 except within ~1e-6 rad of the critical angle) and visible in 6 printed digits.
const WRONG_ANGLE: f64 = 1e-4;

/// The renderers whose `refract` call paths are emulated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Renderer {
    /// pbrt-v4's `Refract(wi, n, eta, &etap, &wt)`, called the way `DielectricBxDF::Sample_f`
    /// calls it, from a student's tracer in render space (see [`Bug::PbrtEtaInverted`]).
    Pbrt,
    /// smallpt's own refraction formula in `radiance()` (no API: generic `check`).
    Smallpt,
    /// Ray Tracing in One Weekend's `refract(uv, n, etai_over_etat)` and `dielectric::scatter`.
    Rtiow,
    /// GLSL's built-in `refract(I, N, eta)` called from a path-tracing shader.
    Glsl,
}

impl Renderer {
    /// Every renderer.
    pub(crate) const ALL: [Self; 4] = [Self::Pbrt, Self::Smallpt, Self::Rtiow, Self::Glsl];

    /// The bugs that can be injected into this renderer's code ([`Bug::None`] not included).
    #[must_use]
    pub(crate) fn bugs(self) -> &'static [Bug] {
        match self {
            Self::Pbrt => &[
                Bug::PbrtEtaInverted,
                Bug::PbrtNoFlipInside,
                Bug::PbrtNormalTermSign,
            ],
            Self::Smallpt => &[Bug::SmallptNormalsSwapped, Bug::SmallptNntInverted],
            Self::Rtiow => &[Bug::RtiowRatioNotInverted, Bug::RtiowOutwardNormal],
            Self::Glsl => &[
                Bug::GlslOutwardNormal,
                Bug::GlslEtaInverted,
                Bug::GlslIncidentReversed,
            ],
        }
    }

    /// `check --api NAME` for this renderer's log; `None` for smallpt (generic `check`).
    #[must_use]
    pub(crate) fn api(self) -> Option<&'static str> {
        match self {
            Self::Pbrt => Some("pbrt"),
            Self::Smallpt => None,
            Self::Rtiow => Some("rtiow"),
            Self::Glsl => Some("glsl"),
        }
    }
}

/// One-line bugs, each as a student makes it in one renderer's code.
///
/// Each variant's doc names the line of the original it alters (file, function, the line as
/// the original has it), the altered line, what the bug does to the log, and the diagnosis
/// code the whole-log verdict should name ([`Bug::expected_code`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Bug {
    /// The code as published: every line right.
    None,
    /// pbrt: the caller passes `1 / eta`. Original (`src/pbrt/bxdfs.cpp`,
    /// `DielectricBxDF::Sample_f`): `bool valid = Refract(wo, Normal3f(0, 0, 1), eta, &etap,
    /// &wi);` (in the local frame; the emulated tracer calls it in render space with the
    /// outward normal, which is what the local frame's z axis is); altered: `Refract(wo, n, 1 /
    /// eta, &etap, &wt)`.
    ///
    /// Every line is wrong (its `eta`; its result too but at normal incidence): rays entering
    /// are bent as if leaving the glass, those past sinθ = 1/1.5 get `ok=0` (a false total internal reflection); rays
    /// leaving get `etap` = 1.5 after the flip and refract even past the critical angle. The
    /// logged `eta` is 0.666667 on every line. Code `eta_inverted`. Fix: pass the material's
    /// `eta` (`n_inside/n_outside` for the outward `n`); `Refract` inverts it itself when `wi` is
    /// below `n`.
    ///
    /// The line has no `travel`, so each line is explained as well by `n` pointing inward
    /// (which in `Refract` equals an inverted eta) or by `wi` reversed with `n` inward and
    /// this eta right: each line alone ties `incident_reversed`, `eta_inverted` and
    /// `normal_not_facing`. Only what holds across lines separates them for the whole log: a shape's normal is outward (then `entering` says `n` is outward on every
    /// line) and the caller's `eta` is the same 0.666667 on every line, entering or not.
    PbrtEtaInverted,
    /// pbrt: the orientation flip removed from `Refract` (`src/pbrt/util/scattering.h`):
    /// original `if (cosTheta_i < 0) { eta = 1 / eta; cosTheta_i = -cosTheta_i; n = -n; }`;
    /// altered: the block deleted.
    ///
    /// Lines from outside are untouched (bit for bit); every line from inside is wrong: `etap`
    /// stays 1.5 (never inverted, as logged), `cosTheta_i` stays negative so `wt` =
    /// `d_tan/1.5 − cosθt·n_out` goes back into the glass, and `ok=1` even past the critical
    /// angle. Code `no_flip_inside`. Fix: restore the flip at the top of `Refract`.
    PbrtNoFlipInside,
    /// pbrt: the term along `n` negated in `Refract` (`src/pbrt/util/scattering.h`): original
    /// `*wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);`; altered: the `+`
    /// before the term made a `-`.
    ///
    /// Every line that refracts is wrong, from either side; `wt`'s part across `n` is right
    /// (that of `-wi / eta`), only its part along `n` is wrong: −cosθi/η − (cosθi/η − cosθt) =
    /// cosθt − 2·cosθi/η instead of −cosθt (η after the flip), so `wt` is not unit length and,
    /// entering at grazing angles (where cosθi < η·cosθt/2 = 0.75·cosθt), points back into
    /// the air. `ok`, `etap` and total internal reflection are right. Code `normal_term_sign`.
    /// Fix: add the `(cosTheta_i / eta - cosTheta_t) * Vector3f(n)` term.
    PbrtNormalTermSign,
    /// smallpt: `nl` in place of `n` in `tdir` (`radiance()`, REFR branch): original
    /// `Vec tdir = (r.d*nnt - n*((into?1:-1)*(ddn*nnt+sqrt(cos2t)))).norm();`; altered: `nl*`
    /// in place of `n*`.
    ///
    /// `(into?1:-1)` already turns the outward `n` into the facing normal, so with `nl` the
    /// term along the normal points the wrong way on rays leaving the glass: there the normal
    /// used is in effect the outward one, which does not face the ray. Lines from outside are
    /// untouched (`nl` = `n` there); every line from inside is wrong: before `.norm()` the part
    /// across the normal is right (nnt·d's), the part along it is cosθt − 2·nnt·cosθi instead
    /// of −cosθt, so `tdir` still leaves the glass but bent toward the normal. It is *not* the
    /// mirror across the surface (the other root) an un-flipped normal gives in GLSL or the
    /// book, because `ddn` keeps using the facing `nl`. Code `normal_not_facing` (per line it
    /// looks like `normal_term_sign`, but only on lines from inside: a facing mistake). Fix:
    /// `n` in `tdir`, as published.
    SmallptNormalsSwapped,
    /// smallpt: `nnt` inverted (`radiance()`, REFR branch): original `double nc=1, nt=1.5,
    /// nnt=into?nc/nt:nt/nc, ...`; altered: `nnt=into?nt/nc:nc/nt`.
    ///
    /// Every printed line is wrong: its `tdir` (but within ~1e-4 rad of normal incidence) and,
    /// in the mixed-precision line, its `nnt`. Rays entering past sinθ = 1/1.5 take the
    /// total-internal-reflection `return` and print nothing; rays leaving past the critical
    /// angle now print a `tdir` (they should have returned). Code `eta_inverted`.
    /// Fix: `nnt` is `nc/nt` when `into`, `nt/nc` otherwise.
    SmallptNntInverted,
    /// The book: the ratio not chosen by `front_face` (`src/InOneWeekend/material.h`,
    /// `dielectric::scatter`): original `double ri = rec.front_face ? (1.0/refraction_index) :
    /// refraction_index;` (v4.0.0: `double refraction_ratio = rec.front_face ? (1.0/ir) :
    /// ir;`); altered: `double ri = 1.0/refraction_index;`.
    ///
    /// Lines from outside are untouched; every line from inside is wrong (its result too but
    /// at normal incidence), with `ratio` 0.666667 and `front_face=0`: `cannot_refract` never
    /// holds, so rays past the critical angle refract too. Code `eta_inverted`. Fix: `ri =
    /// rec.front_face ? (1.0/refraction_index) : refraction_index`.
    RtiowRatioNotInverted,
    /// The book: the outward normal kept in the hit record (`src/InOneWeekend/hittable.h`,
    /// `hit_record::set_face_normal`): original `normal = front_face ? outward_normal :
    /// -outward_normal;`; altered: `normal = outward_normal;` (`front_face` still computed).
    ///
    /// Lines from outside are untouched. From inside below the critical angle `refract` gets
    /// `cos_theta` < 0, `r_out_perp` comes out the same and `r_out_parallel` flips: the mirror
    /// across the surface (the other root), back into the glass. Past the critical angle
    /// `cannot_refract` is unchanged (it squares `cos_theta`) and `reflect` does not care
    /// about the normal's sign: a right outcome from a wrong call (`n` shows it). Lines from
    /// inside are wrong, and only they. Code `normal_not_facing`. Fix: keep
    /// `normal = front_face ? outward_normal : -outward_normal`.
    ///
    /// The emulated `scatter` is the book's listing `dielectric-with-refraction` (section
    /// "Total Internal Reflection"), before Schlick's reflectance is added. With the final
    /// `material.h`, this bug makes `reflectance(cos_theta, ri)` ≥ 1 on every ray from inside
    /// (`pow(1 - cosine, 5)` with `cosine` < 0), so `refract` is never called for rays
    /// leaving the sphere and a log printed in the refract branch shows no inside lines at all.
    RtiowOutwardNormal,
    /// GLSL: the outward normal passed (`vec3 t = refract(rd, Nf, eta);` altered to
    /// `refract(rd, N, eta)`, where `Nf = entering ? N : -N`).
    ///
    /// Lines from outside are untouched; from inside below the critical angle the result is
    /// the mirror across the surface (the other root), back into the glass; past it k < 0 as
    /// before: the zero vector, a right outcome from a wrong call (`N` shows it). Code
    /// `normal_not_facing`. Fix: pass the normal facing `I`; GLSL's `refract` does not flip
    /// `N`.
    GlslOutwardNormal,
    /// GLSL: eta inverted (`float eta = entering ? 1.0 / 1.5 : 1.5;` altered to `entering ?
    /// 1.5 : 1.0 / 1.5`).
    ///
    /// Every line is wrong (its `eta`; its result too but at normal incidence): entering rays
    /// past sinθ = 1/1.5 get the zero vector (a false total internal reflection), leaving rays past the critical angle
    /// refract. Code `eta_inverted`. Fix: `eta = n_from/n_to`, the index the ray leaves over the
    /// one it enters.
    GlslEtaInverted,
    /// GLSL: the incident vector reversed (`refract(rd, Nf, eta)` altered to `refract(-rd, Nf,
    /// eta)`: the direction back toward the eye, as shading code holds it).
    ///
    /// Every line is wrong: the logged `I` is −`rd`, with dot(N, I) > 0 on every line, entering
    /// or not. Where it refracts, the result is the mirror across the normal (the part across
    /// the normal negated, "bends the wrong way"; unchanged only at normal incidence); past the
    /// critical angle it is still the zero vector (k only depends on dot(N, I)²): a right
    /// outcome from a wrong call. Code `incident_reversed` (without `rd` in the line, `N`
    /// negated on every line would explain the log equally). Fix: `I` is the direction of
    /// travel, `rd`.
    GlslIncidentReversed,
}

impl Bug {
    /// Every bug, [`Bug::None`] first.
    pub(crate) const ALL: [Self; 11] = [
        Self::None,
        Self::PbrtEtaInverted,
        Self::PbrtNoFlipInside,
        Self::PbrtNormalTermSign,
        Self::SmallptNormalsSwapped,
        Self::SmallptNntInverted,
        Self::RtiowRatioNotInverted,
        Self::RtiowOutwardNormal,
        Self::GlslOutwardNormal,
        Self::GlslEtaInverted,
        Self::GlslIncidentReversed,
    ];

    /// The renderer whose code this bug is in; `None` for [`Bug::None`] (any renderer).
    #[must_use]
    pub(crate) fn renderer(self) -> Option<Renderer> {
        match self {
            Self::None => None,
            Self::PbrtEtaInverted | Self::PbrtNoFlipInside | Self::PbrtNormalTermSign => {
                Some(Renderer::Pbrt)
            }
            Self::SmallptNormalsSwapped | Self::SmallptNntInverted => Some(Renderer::Smallpt),
            Self::RtiowRatioNotInverted | Self::RtiowOutwardNormal => Some(Renderer::Rtiow),
            Self::GlslOutwardNormal | Self::GlslEtaInverted | Self::GlslIncidentReversed => {
                Some(Renderer::Glsl)
            }
        }
    }

    /// The diagnosis code the whole-log verdict should name (see each variant for why).
    #[must_use]
    pub(crate) fn expected_code(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::PbrtEtaInverted
            | Self::SmallptNntInverted
            | Self::RtiowRatioNotInverted
            | Self::GlslEtaInverted => "eta_inverted",
            Self::PbrtNoFlipInside => "no_flip_inside",
            Self::PbrtNormalTermSign => "normal_term_sign",
            Self::SmallptNormalsSwapped | Self::RtiowOutwardNormal | Self::GlslOutwardNormal => {
                "normal_not_facing"
            }
            Self::GlslIncidentReversed => "incident_reversed",
        }
    }

    /// The fix, in the renderer's own code words (empty for [`Bug::None`]).
    #[must_use]
    pub(crate) fn fix(self) -> &'static str {
        match self {
            Self::None => "",
            Self::PbrtEtaInverted => {
                "Pass the material's eta to Refract as it is, not 1 / eta: eta is the index \
                 inside over the index outside for the outward n, and Refract inverts it (and \
                 flips n) itself when wi is below n."
            }
            Self::PbrtNoFlipInside => {
                "Restore the flip at the top of Refract: when cosTheta_i < 0, set eta = 1 / \
                 eta, cosTheta_i = -cosTheta_i and n = -n before computing sin2Theta_i."
            }
            Self::PbrtNormalTermSign => {
                "In Refract, *wt is -wi / eta plus (cosTheta_i / eta - cosTheta_t) * \
                 Vector3f(n): add the term along n, do not subtract it."
            }
            Self::SmallptNormalsSwapped => {
                "tdir's normal term must use n, the outward normal, not nl: (into?1:-1) \
                 already turns n to face the ray, so nl there points the term the wrong way \
                 when the ray leaves the glass."
            }
            Self::SmallptNntInverted => {
                "nnt is nc/nt when into (the ray enters the glass) and nt/nc when it leaves \
                 (nnt=into?nc/nt:nt/nc)."
            }
            Self::RtiowRatioNotInverted => {
                "Choose the ratio by the face: ri = rec.front_face ? (1.0/refraction_index) : \
                 refraction_index (in v4.0.0: refraction_ratio = rec.front_face ? (1.0/ir) : ir)."
            }
            Self::RtiowOutwardNormal => {
                "In hit_record::set_face_normal keep normal = front_face ? outward_normal : \
                 -outward_normal, so rec.normal faces a ray that leaves the sphere."
            }
            Self::GlslOutwardNormal => {
                "Pass the normal facing the ray: refract(rd, entering ? N : -N, eta); GLSL's \
                 refract does not flip N."
            }
            Self::GlslEtaInverted => {
                "eta is the index the ray leaves over the one it enters: entering ? 1.0 / 1.5 \
                 : 1.5."
            }
            Self::GlslIncidentReversed => {
                "I is the direction of travel: refract(rd, Nf, eta), not the direction back \
                 toward the eye (-rd)."
            }
        }
    }
}

/// One printed line and its ground truth.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Line {
    /// The line as the student's code printed it (no newline).
    pub text: String,
    /// The call differs from the bug-free code's for the same ray: an argument or the outcome
    /// (see the module docs).
    pub wrong: bool,
    /// The ray arrives from inside the glass (it is leaving the sphere).
    pub from_inside: bool,
    /// The ray arrives from inside past the critical angle: physically totally reflected.
    pub past_critical: bool,
}

/// A whole log with what `check` needs to read it and what its verdict should be.
#[derive(Clone, Debug)]
pub(crate) struct Log {
    /// One line per call, in order.
    pub lines: Vec<Line>,
    /// The `--pattern` that reads the lines (see [`pattern`]).
    pub pattern: &'static str,
    /// `check --api NAME`; `None` for smallpt: `check` without `--api`.
    pub api: Option<&'static str>,
    /// `--inside`: the glass's index.
    pub inside: f64,
    /// `--outside`: the air's index.
    pub outside: f64,
    /// The diagnosis code the whole-log verdict should name ("none" for a right log).
    pub expected_code: &'static str,
    /// The fix in the renderer's own code words (empty for a right log).
    pub fix: &'static str,
}

/// The log `renderer`'s code with `bug` prints for `count` calls on rays drawn from `seed`;
/// `mixed_precision` prints the index ratio with `%.17g` and the vectors with 6 digits.
///
/// # Panics
/// When `bug` belongs to another renderer ([`Bug::None`] fits every renderer).
#[must_use]
pub(crate) fn log(
    renderer: Renderer,
    bug: Bug,
    count: usize,
    seed: u64,
    mixed_precision: bool,
) -> Log {
    if let Some(owner) = bug.renderer() {
        assert!(
            owner == renderer,
            "Bug::{bug:?} is a bug in {owner:?}'s code, not in {renderer:?}'s"
        );
    }
    let mut rng = Rng::new(seed);
    let mut lines = Vec::with_capacity(count);
    while lines.len() < count {
        let hit = Hit::draw(&mut rng);
        let Some(printed) = emulate(renderer, bug, &hit) else {
            continue;
        };
        let right = emulate(renderer, Bug::None, &hit);
        // smallpt's plain line does not print nnt.
        let shown = if renderer == Renderer::Smallpt && !mixed_precision {
            Shown::Vectors
        } else {
            Shown::All
        };
        lines.push(Line {
            wrong: differs(&printed, right.as_ref(), shown),
            text: if mixed_precision {
                printed.mixed
            } else {
                printed.plain
            },
            from_inside: hit.from_inside,
            past_critical: hit.past_critical(),
        });
    }
    Log {
        lines,
        pattern: pattern(renderer, mixed_precision),
        api: renderer.api(),
        inside: INSIDE,
        outside: OUTSIDE,
        expected_code: bug.expected_code(),
        fix: bug.fix(),
    }
}

/// The `--pattern` that reads `renderer`'s log, every field the line has: pbrt's `{etap}`,
/// the book's `{front_face}`, smallpt through `check` without `--api` (`{w}`, `{n}`,
/// `{entering}`, `{ratio}`, `{t_yours}`).
#[must_use]
pub(crate) fn pattern(renderer: Renderer, mixed_precision: bool) -> &'static str {
    match (renderer, mixed_precision) {
        (Renderer::Pbrt, _) => {
            "Refract wi={wi} n={n} eta={eta} -> wt={wt} etap={etap} ok={returned} entering={entering}"
        }
        (Renderer::Smallpt, false) => "REFR d={w} nl={n} into={entering} tdir={t_yours}",
        (Renderer::Smallpt, true) => "REFR d={w} nl={n} into={entering} nnt={ratio} tdir={t_yours}",
        (Renderer::Rtiow, _) => {
            "uv={uv} n={n} ratio={etai_over_etat} front_face={front_face} refracted={refracted}"
        }
        (Renderer::Glsl, _) => "rd={travel} I={I} N={N} eta={eta} entering={entering} -> {result}",
    }
}

// ---------------------------------------------------------------------------------------------
// Rays

/// A small seeded generator: splitmix64 to spread the seed, then xorshift64*.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Self {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        Self(if z == 0 { 0x2545_F491_4F6C_DD1D } else { z })
    }

    fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1).
    #[expect(clippy::cast_precision_loss)] // 53 bits fit exactly
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1_u64 << 53) as f64
    }
}

/// One ray meeting the sphere's surface, in exact-ish f64 geometry.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Hit {
    /// The unit direction of travel.
    pub(crate) travel: DVec3,
    /// The sphere's unit outward normal at the hit (also the hit point on a unit sphere).
    pub(crate) outward: DVec3,
    /// The ray travels inside the glass.
    pub(crate) from_inside: bool,
    /// The length of the ray's direction as the book's camera leaves it (not unit).
    pub(crate) length: f64,
}

impl Hit {
    pub(crate) fn draw(rng: &mut Rng) -> Self {
        let z = 2.0 * rng.unit() - 1.0;
        let phi = core::f64::consts::TAU * rng.unit();
        let r = (1.0 - z * z).max(0.0).sqrt();
        let outward = DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let helper = if outward.x.abs() < 0.9 {
            DVec3::X
        } else {
            DVec3::Y
        };
        let a = outward.cross(helper).normalize();
        let b = outward.cross(a);
        let psi = core::f64::consts::TAU * rng.unit();
        let tangent = a * psi.cos() + b * psi.sin();
        let from_inside = rng.unit() < 0.5;
        let theta = rng.unit() * MAX_INCIDENCE_DEG.to_radians();
        let along = if from_inside {
            theta.cos()
        } else {
            -theta.cos()
        };
        let travel = (tangent * theta.sin() + outward * along).normalize();
        let length = 0.5 + 1.5 * rng.unit();
        Self {
            travel,
            outward,
            from_inside,
            length,
        }
    }

    /// sinθi.
    pub(crate) fn sin_i(&self) -> f64 {
        self.travel.cross(self.outward).length()
    }

    /// From inside, past the critical angle.
    pub(crate) fn past_critical(&self) -> bool {
        self.from_inside && INSIDE / OUTSIDE * self.sin_i() > 1.0
    }
}

/// What a call did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Outcome {
    /// It transmitted along this direction (as computed, widened to f64; not normalised).
    Transmitted(DVec3),
    /// It signalled total internal reflection: pbrt's `false`, GLSL's zero vector, the book's
    /// `cannot_refract` (its `direction` is then the reflection).
    Refused,
}

/// A call's arguments in the renderer's own terms, widened to f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Args {
    /// pbrt's `wi`, smallpt's `r.d`, the book's `uv`, GLSL's `I`.
    pub(crate) incident: DVec3,
    /// pbrt's `n`, smallpt's `nl`, the book's `n`, GLSL's `N`.
    pub(crate) normal: DVec3,
    /// pbrt's `eta`, smallpt's `nnt`, the book's `ri`, GLSL's `eta`.
    pub(crate) ratio: f64,
}

/// One call's printed line, plain and with mixed precision, its arguments and its outcome.
#[derive(Clone, Debug)]
pub(crate) struct Printed {
    pub(crate) plain: String,
    pub(crate) mixed: String,
    pub(crate) args: Args,
    pub(crate) outcome: Outcome,
}

/// The line `renderer`'s code with `bug` prints for `hit`, or `None` when it prints none.
pub(crate) fn emulate(renderer: Renderer, bug: Bug, hit: &Hit) -> Option<Printed> {
    match renderer {
        Renderer::Pbrt => Some(pbrt::call(bug, hit)),
        Renderer::Smallpt => smallpt::call(bug, hit),
        Renderer::Rtiow => Some(rtiow::call(bug, hit)),
        Renderer::Glsl => Some(glsl::call(bug, hit)),
    }
}

/// Which arguments a line prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shown {
    /// The incident vector, the normal and the ratio.
    All,
    /// The vectors only (smallpt's plain line has no `nnt`).
    Vectors,
}

/// Whether `printed` differs from the call the bug-free code made (`right`, `None` when it
/// printed nothing): an argument the line shows, or the outcome.
fn differs(printed: &Printed, right: Option<&Printed>, shown: Shown) -> bool {
    let Some(right) = right else {
        return true;
    };
    let (a, b) = (printed.args, right.args);
    angle(a.incident, b.incident) > WRONG_ANGLE
        || angle(a.normal, b.normal) > WRONG_ANGLE
        || (shown == Shown::All && (a.ratio / b.ratio - 1.0).abs() > WRONG_ANGLE)
        || outcomes_differ(printed.outcome, right.outcome)
}

/// Whether two outcomes differ: directions beyond [`WRONG_ANGLE`], or only one refused.
fn outcomes_differ(a: Outcome, b: Outcome) -> bool {
    match (a, b) {
        (Outcome::Transmitted(a), Outcome::Transmitted(b)) => angle(a, b) > WRONG_ANGLE,
        (Outcome::Refused, Outcome::Refused) => false,
        _ => true,
    }
}

/// The angle between two non-zero vectors, accurate for small angles.
pub(crate) fn angle(a: DVec3, b: DVec3) -> f64 {
    let (a, b) = (a.normalize(), b.normalize());
    a.cross(b).length().atan2(a.dot(b))
}

// ---------------------------------------------------------------------------------------------
// Printing as C and C++ print

/// C's `%.{decimals}f` (a `float` argument is promoted to `double` first).
pub(crate) fn c_fixed(x: f64, decimals: usize) -> String {
    if x.is_nan() {
        return if x.is_sign_negative() { "-nan" } else { "nan" }.to_owned();
    }
    if x.is_infinite() {
        return if x < 0.0 { "-inf" } else { "inf" }.to_owned();
    }
    format!("{x:.decimals$}")
}

/// C's `%.{precision}g`, which is also what a C++ stream prints for a `double` with that
/// precision (6 by default).
pub(crate) fn c_general(x: f64, precision: usize) -> String {
    if !x.is_finite() {
        return c_fixed(x, 0);
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.to_owned();
    }
    let precision = precision.max(1);
    let scientific = format!("{:.*e}", precision - 1, x);
    let (mantissa, exponent) = scientific
        .split_once('e')
        .unwrap_or((scientific.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let limit = i32::try_from(precision).unwrap_or(i32::MAX);
    if exponent < -4 || exponent >= limit {
        let sign = if exponent < 0 { '-' } else { '+' };
        let mantissa = strip_zeros(mantissa);
        format!("{mantissa}e{sign}{:02}", exponent.unsigned_abs())
    } else {
        let decimals = usize::try_from(limit - 1 - exponent).unwrap_or(0);
        strip_zeros(&format!("{x:.decimals$}")).to_owned()
    }
}

/// `%g`'s removal of trailing zeros (and of a trailing point).
fn strip_zeros(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

pub(crate) fn flag(b: bool) -> &'static str {
    if b { "1" } else { "0" }
}

// ---------------------------------------------------------------------------------------------
// pbrt-v4

/// pbrt-v4, commit 5f7a606 (mmp/pbrt-v4).
///
/// - `src/pbrt/util/scattering.h`, `Refract(Vector3f wi, Normal3f n, Float eta, Float *etap,
///   Vector3f *wt)`: `cosTheta_i = Dot(n, wi)`; when it is negative, eta is inverted,
///   `cosTheta_i` negated and `n` negated; `sin2Theta_i = std::max<Float>(0, 1 - Sqr(cosTheta_i))`,
///   `sin2Theta_t = sin2Theta_i / Sqr(eta)`; `false` when `sin2Theta_t >= 1`; otherwise
///   `cosTheta_t = std::sqrt(1 - sin2Theta_t)`, `*wt = -wi / eta + (cosTheta_i / eta -
///   cosTheta_t) * Vector3f(n)` and `*etap = eta`. On `false` neither `*wt` nor `*etap` is
///   written.
/// - `src/pbrt/util/vecmath.h`: `Dot(Normal3, Vector3)` is `FMA(n.x, v.x, SumOfProducts(n.y,
///   v.y, n.z, v.z))`; `Tuple3::operator/` divides each component; scalar times vector
///   multiplies each; `Normalize(v)` is `v / Length(v)`, `Length` the `std::sqrt` of
///   `Sqr(x) + Sqr(y) + Sqr(z)`. `src/pbrt/util/math.h`: `SumOfProducts(a, b, c, d)` is
///   `FMA(a, b, c*d) + FMA(c, d, -(c*d))`; `src/pbrt/util/float.h`: `FMA` is `std::fma`.
/// - `src/pbrt/bxdfs.cpp`, `DielectricBxDF::Sample_f`: calls `Refract(wo, Normal3f(0, 0, 1),
///   eta, &etap, &wi)` in the local shading frame, `wo` pointing back along the ray (−ray.d
///   for a camera path), the material's `eta` (inside over outside), and only after
///   `FrDielectric` chose transmission, so at total internal reflection (R = 1) its smooth
///   branch never reaches `Refract`; the rough branch does, as `tir = !Refract(...)`.
///
/// Emulated: a student's tracer calling `Refract` on every hit the way `Sample_f` does (its
/// `wo`, the material's eta, the surface normal: outward on a sphere, which is the local
/// frame's z axis) but in render space, reflecting when it returns `false` like the rough
/// branch. `Float wt`'s default is zero and the caller starts `etap` at 0, so an `ok=0` line
/// prints `wt=(0.000000, 0.000000, 0.000000) etap=0.000000`. `entering` is the caller's
/// `Dot(n, wo) > 0`. Line: `printf("Refract wi=(%f, %f, %f) n=(%f, %f, %f) eta=%f -> wt=(%f,
/// %f, %f) etap=%f ok=%d entering=%d\n", ...)`; with mixed precision `eta=%.17g` and
/// `etap=%.17g`.
mod pbrt {
    use super::{Args, Bug, Hit, Outcome, Printed, Vec3, c_fixed, c_general, flag};

    /// pbrt's `Float` without `PBRT_FLOAT_AS_DOUBLE`.
    type Float = f32;

    /// The material's `eta` (glass inside, air outside).
    const ETA: Float = 1.5;

    fn fma(a: Float, b: Float, c: Float) -> Float {
        a.mul_add(b, c)
    }

    fn sum_of_products(a: Float, b: Float, c: Float, d: Float) -> Float {
        let cd = c * d;
        fma(a, b, cd) + fma(c, d, -cd)
    }

    /// `Dot(Normal3f n, Vector3f v)`.
    pub(super) fn dot(n: Vec3, v: Vec3) -> Float {
        fma(n.x, v.x, sum_of_products(n.y, v.y, n.z, v.z))
    }

    /// `Normalize(v)`: each component divided by the length.
    fn normalize(v: Vec3) -> Vec3 {
        let length = (v.x * v.x + v.y * v.y + v.z * v.z).sqrt();
        Vec3::new(v.x / length, v.y / length, v.z / length)
    }

    /// `Refract(wi, n, eta, &etap, &wt)`: `Some((wt, etap))` for `true`, `None` for `false`.
    pub(super) fn refract(wi: Vec3, n: Vec3, eta: Float, bug: Bug) -> Option<(Vec3, Float)> {
        let (mut n, mut eta) = (n, eta);
        let mut cos_i = dot(n, wi);
        // Bug::PbrtNoFlipInside deletes this block.
        if cos_i < 0.0 && bug != Bug::PbrtNoFlipInside {
            eta = 1.0 / eta;
            cos_i = -cos_i;
            n = -n;
        }
        let one_minus = 1.0 - cos_i * cos_i;
        // std::max<Float>(0, x) is x only when 0 < x.
        let sin2_i = if 0.0 < one_minus { one_minus } else { 0.0 };
        let sin2_t = sin2_i / (eta * eta);
        if sin2_t >= 1.0 {
            return None;
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        let along_n = cos_i / eta - cos_t;
        let wt = if bug == Bug::PbrtNormalTermSign {
            -wi / eta - along_n * n
        } else {
            -wi / eta + along_n * n
        };
        Some((wt, eta))
    }

    fn vector(v: Vec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_fixed(f64::from(c), 6));
        format!("({x}, {y}, {z})")
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Printed {
        let ray_d = normalize(hit.travel.as_vec3());
        let n = normalize(hit.outward.as_vec3());
        let wo = -ray_d;
        let entering = dot(n, wo) > 0.0;
        let eta = if bug == Bug::PbrtEtaInverted {
            1.0 / ETA
        } else {
            ETA
        };
        let (mut wt, mut etap) = (Vec3::ZERO, 0.0);
        let ok = match refract(wo, n, eta, bug) {
            Some((w, e)) => {
                (wt, etap) = (w, e);
                true
            }
            None => false,
        };
        let line = |ratio: &dyn Fn(Float) -> String| {
            format!(
                "Refract wi={} n={} eta={} -> wt={} etap={} ok={} entering={}",
                vector(wo),
                vector(n),
                ratio(eta),
                vector(wt),
                ratio(etap),
                flag(ok),
                flag(entering)
            )
        };
        Printed {
            plain: line(&|x| c_fixed(f64::from(x), 6)),
            mixed: line(&|x| c_general(f64::from(x), 17)),
            args: Args {
                incident: wo.as_dvec3(),
                normal: n.as_dvec3(),
                ratio: f64::from(eta),
            },
            outcome: if ok {
                Outcome::Transmitted(wt.as_dvec3())
            } else {
                Outcome::Refused
            },
        }
    }
}

// ---------------------------------------------------------------------------------------------
// smallpt

/// smallpt, Kevin Beason (2008), `smallpt.cpp`, `radiance()`: the REFR branch (read in
/// ldm5180/smallpt `smallpt.cpp` and in several unmodified copies of the 99-line original).
///
/// `n` is the outward normal `(x - obj.p).norm()`; `nl` is `n` when `n.dot(r.d) < 0`, else
/// `n*-1` (the normal facing the ray); `into = n.dot(nl) > 0`; `nc = 1`, `nt = 1.5`, `nnt =
/// into ? nc/nt : nt/nc`, `ddn = r.d.dot(nl)`, `cos2t = 1 - nnt*nnt*(1 - ddn*ddn)`; when
/// `cos2t < 0` it returns the reflected ray's radiance (total internal reflection);
/// otherwise `tdir = (r.d*nnt - n*((into?1:-1)*(ddn*nnt + sqrt(cos2t)))).norm()`. `Vec`'s
/// `operator*(double)` multiplies each component, `dot` sums x, y, z products left to right,
/// `norm()` multiplies by `1/sqrt(x*x + y*y + z*z)`. All `double`.
///
/// Emulated on the scene's glass sphere (`Sphere(16.5, Vec(73,16.5,78), ..., REFR)`), the
/// hit point placed on it. Line, printed right after `tdir`: `printf("REFR d=(%.6f %.6f
/// %.6f) nl=(%.6f %.6f %.6f) into=%d tdir=(%.6f %.6f %.6f)\n", ...)`; with mixed precision
/// ` nnt=%.17g` before ` tdir=`. A ray that returns on total internal reflection prints
/// nothing.
mod smallpt {
    use super::{Args, Bug, DVec3, Hit, Outcome, Printed, c_fixed, c_general, flag};

    const CENTER: DVec3 = DVec3::new(73.0, 16.5, 78.0);
    const RADIUS: f64 = 16.5;

    fn dot(a: DVec3, b: DVec3) -> f64 {
        a.x * b.x + a.y * b.y + a.z * b.z
    }

    fn times(v: DVec3, s: f64) -> DVec3 {
        DVec3::new(v.x * s, v.y * s, v.z * s)
    }

    fn norm(v: DVec3) -> DVec3 {
        times(v, 1.0 / (v.x * v.x + v.y * v.y + v.z * v.z).sqrt())
    }

    fn vector(v: DVec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_fixed(c, 6));
        format!("({x} {y} {z})")
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Option<Printed> {
        let d = hit.travel;
        let x = CENTER + times(hit.outward, RADIUS);
        let n = norm(x - CENTER);
        let nl = if dot(n, d) < 0.0 { n } else { times(n, -1.0) };
        let into = dot(n, nl) > 0.0;
        let (nc, nt) = (1.0, 1.5);
        // Bug::SmallptNntInverted swaps the two ratios.
        let enters = if bug == Bug::SmallptNntInverted {
            !into
        } else {
            into
        };
        let nnt = if enters { nc / nt } else { nt / nc };
        let ddn = dot(d, nl);
        let cos2t = 1.0 - nnt * nnt * (1.0 - ddn * ddn);
        if cos2t < 0.0 {
            return None;
        }
        let side = if into { 1.0 } else { -1.0 };
        // Bug::SmallptNormalsSwapped uses nl here.
        let normal = if bug == Bug::SmallptNormalsSwapped {
            nl
        } else {
            n
        };
        let tdir = norm(times(d, nnt) - times(normal, side * (ddn * nnt + cos2t.sqrt())));
        let head = format!("REFR d={} nl={} into={}", vector(d), vector(nl), flag(into));
        Some(Printed {
            plain: format!("{head} tdir={}", vector(tdir)),
            mixed: format!("{head} nnt={} tdir={}", c_general(nnt, 17), vector(tdir)),
            args: Args {
                incident: d,
                normal: nl,
                ratio: nnt,
            },
            outcome: Outcome::Transmitted(tdir),
        })
    }
}

// ---------------------------------------------------------------------------------------------
// Ray Tracing in One Weekend

/// Ray Tracing in One Weekend (RayTracing/raytracing.github.io: `dev` d3e5bf9; `release`
/// 94b510c is v4.0.0, the same code with `ir` and `refraction_ratio` for
/// `refraction_index` and `ri`).
///
/// - `src/InOneWeekend/vec3.h`: `refract(uv, n, etai_over_etat)`: `cos_theta = fmin(dot(-uv,
///   n), 1.0)`, `r_out_perp = etai_over_etat * (uv + cos_theta*n)`, `r_out_parallel =
///   -sqrt(fabs(1.0 - r_out_perp.length_squared())) * n`, their sum; `reflect(v, n) = v -
///   2*dot(v,n)*n`; `unit_vector(v) = v / v.length()` where `v / t` is `(1/t) * v`; `dot` sums
///   left to right; `operator<<` prints the three components separated by spaces.
/// - `hittable.h`, `hit_record::set_face_normal`: `front_face = dot(r.direction(),
///   outward_normal) < 0`, `normal = front_face ? outward_normal : -outward_normal`;
///   `sphere.h`, `sphere::hit`: `outward_normal = (rec.p - center) / radius`.
/// - `material.h` / the book's listing `dielectric-with-refraction` ("Total Internal
///   Reflection"): `ri = rec.front_face ? (1.0/refraction_index) : refraction_index`,
///   `unit_direction = unit_vector(r_in.direction())`, `cos_theta = fmin(dot(-unit_direction,
///   rec.normal), 1.0)`, `sin_theta = sqrt(1.0 - cos_theta*cos_theta)`, `cannot_refract = ri *
///   sin_theta > 1.0`, `direction` the reflection if so, else the refraction. The final
///   `material.h` also reflects when Schlick's `reflectance(cos_theta, ri) > random_double()`;
///   that random choice is left out here (see [`super::Bug::RtiowOutwardNormal`]).
///
/// Emulated on the book's glass sphere of that section (`point3(-1.0, 0.0, -1.0)`, 0.5,
/// `dielectric(1.50)`), with a ray direction that is not unit (as the book's camera makes
/// it). Line, after `direction` is chosen: `std::clog << "uv=" << unit_direction << " n=" <<
/// rec.normal << " ratio=" << ri << " front_face=" << rec.front_face << " refracted=" <<
/// direction << '\n';` (default stream precision 6, `bool` as 1/0); with mixed precision
/// `std::setprecision(17)` around `ri`.
mod rtiow {
    use super::{Args, Bug, DVec3, Hit, Outcome, Printed, c_general, flag};

    const CENTER: DVec3 = DVec3::new(-1.0, 0.0, -1.0);
    const RADIUS: f64 = 0.5;
    const REFRACTION_INDEX: f64 = 1.5;

    fn dot(u: DVec3, v: DVec3) -> f64 {
        u.x * v.x + u.y * v.y + u.z * v.z
    }

    fn times(t: f64, v: DVec3) -> DVec3 {
        DVec3::new(t * v.x, t * v.y, t * v.z)
    }

    fn over(v: DVec3, t: f64) -> DVec3 {
        times(1.0 / t, v)
    }

    fn unit_vector(v: DVec3) -> DVec3 {
        over(v, dot(v, v).sqrt())
    }

    fn reflect(v: DVec3, n: DVec3) -> DVec3 {
        v - times(2.0 * dot(v, n), n)
    }

    fn refract(uv: DVec3, n: DVec3, etai_over_etat: f64) -> DVec3 {
        let cos_theta = dot(-uv, n).min(1.0);
        let perp = times(etai_over_etat, uv + times(cos_theta, n));
        let parallel = times(-(1.0 - dot(perp, perp)).abs().sqrt(), n);
        perp + parallel
    }

    fn vector(v: DVec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_general(c, 6));
        format!("{x} {y} {z}")
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Printed {
        let direction_in = hit.travel * hit.length;
        let p = CENTER + hit.outward * RADIUS;
        let outward_normal = over(p - CENTER, RADIUS);
        let front_face = dot(direction_in, outward_normal) < 0.0;
        // Bug::RtiowOutwardNormal keeps the outward normal.
        let normal = if front_face || bug == Bug::RtiowOutwardNormal {
            outward_normal
        } else {
            -outward_normal
        };
        // Bug::RtiowRatioNotInverted ignores front_face.
        let ri = if front_face || bug == Bug::RtiowRatioNotInverted {
            1.0 / REFRACTION_INDEX
        } else {
            REFRACTION_INDEX
        };
        let unit_direction = unit_vector(direction_in);
        let cos_theta = dot(-unit_direction, normal).min(1.0);
        let sin_theta = (1.0 - cos_theta * cos_theta).sqrt();
        let cannot_refract = ri * sin_theta > 1.0;
        let direction = if cannot_refract {
            reflect(unit_direction, normal)
        } else {
            refract(unit_direction, normal, ri)
        };
        let line = |ratio: String| {
            format!(
                "uv={} n={} ratio={ratio} front_face={} refracted={}",
                vector(unit_direction),
                vector(normal),
                flag(front_face),
                vector(direction)
            )
        };
        Printed {
            plain: line(c_general(ri, 6)),
            mixed: line(c_general(ri, 17)),
            args: Args {
                incident: unit_direction,
                normal,
                ratio: ri,
            },
            outcome: if cannot_refract {
                Outcome::Refused
            } else {
                Outcome::Transmitted(direction)
            },
        }
    }

    /// The book's reflection for `hit` with the bug-free code, for the tests.
    #[cfg(test)]
    pub(super) fn reflection(hit: &Hit) -> DVec3 {
        let outward_normal = over(CENTER + hit.outward * RADIUS - CENTER, RADIUS);
        let unit_direction = unit_vector(hit.travel * hit.length);
        let facing = if dot(unit_direction, outward_normal) < 0.0 {
            outward_normal
        } else {
            -outward_normal
        };
        reflect(unit_direction, facing)
    }
}

// ---------------------------------------------------------------------------------------------
// GLSL

/// GLSL's built-in `refract(I, N, eta)` (GLSL 4.60 specification, built-in geometric
/// functions; the OpenGL reference page says the same): `k = 1.0 - eta * eta * (1.0 -
/// dot(N, I) * dot(N, I))`; the zero vector when `k < 0.0`, otherwise `eta * I - (eta *
/// dot(N, I) + sqrt(k)) * N`; I and N "should be normalized". glam 0.34's `Vec3::refract` is
/// the same with the test turned round (`k >= 0.0` refracts). A GPU compiler may fuse or
/// reorder these; emulated as written, in `float`, with glam's `normalize` (times the
/// reciprocal length) for GLSL's implementation-defined one.
///
/// The emulated shader meets a sphere (`center = vec3(0.0, 0.5, -2.0)`, radius 0.5):
/// `vec3 N = normalize(p - center); bool entering = dot(rd, N) < 0.0; vec3 Nf = entering ? N :
/// -N; float eta = entering ? 1.0 / 1.5 : 1.5; vec3 t = refract(rd, Nf, eta);` and reflects
/// when `t` is zero. Line: `debugPrintfEXT("rd=(%f, %f, %f) I=(%f, %f, %f) N=(%f, %f, %f)
/// eta=%f entering=%d -> (%f, %f, %f)", ...)`: the ray's direction, then the arguments as
/// passed; with mixed precision `eta=%.17g`. `rd` is `check`'s truth field `travel`: without
/// it, a reversed `I` ([`super::Bug::GlslIncidentReversed`]) and a normal negated on every
/// line explain the log equally (and `check` ties them).
mod glsl {
    use super::{Args, Bug, DVec3, Hit, Outcome, Printed, Vec3, c_fixed, c_general, flag};

    const CENTER: DVec3 = DVec3::new(0.0, 0.5, -2.0);
    const RADIUS: f64 = 0.5;

    fn dot(a: Vec3, b: Vec3) -> f32 {
        a.x * b.x + a.y * b.y + a.z * b.z
    }

    /// GLSL's `refract(I, N, eta)`.
    pub(super) fn refract(i: Vec3, n: Vec3, eta: f32) -> Vec3 {
        let n_dot_i = dot(n, i);
        let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
        if k < 0.0 {
            Vec3::ZERO
        } else {
            eta * i - (eta * n_dot_i + k.sqrt()) * n
        }
    }

    fn vector(v: Vec3) -> String {
        let [x, y, z] = v.to_array().map(|c| c_fixed(f64::from(c), 6));
        format!("({x}, {y}, {z})")
    }

    pub(super) fn call(bug: Bug, hit: &Hit) -> Printed {
        let rd = hit.travel.as_vec3().normalize();
        let center = CENTER.as_vec3();
        let p = (CENTER + hit.outward * RADIUS).as_vec3();
        let n = (p - center).normalize();
        let entering = dot(rd, n) < 0.0;
        let nf = if entering { n } else { -n };
        // Bug::GlslEtaInverted swaps the two ratios.
        let enters = if bug == Bug::GlslEtaInverted {
            !entering
        } else {
            entering
        };
        let eta: f32 = if enters { 1.0 / 1.5 } else { 1.5 };
        let i_arg = if bug == Bug::GlslIncidentReversed {
            -rd
        } else {
            rd
        };
        let n_arg = if bug == Bug::GlslOutwardNormal { n } else { nf };
        let t = refract(i_arg, n_arg, eta);
        let line = |ratio: String| {
            format!(
                "rd={} I={} N={} eta={ratio} entering={} -> {}",
                vector(rd),
                vector(i_arg),
                vector(n_arg),
                flag(entering),
                vector(t)
            )
        };
        Printed {
            plain: line(c_fixed(f64::from(eta), 6)),
            mixed: line(c_general(f64::from(eta), 17)),
            args: Args {
                incident: i_arg.as_dvec3(),
                normal: n_arg.as_dvec3(),
                ratio: f64::from(eta),
            },
            outcome: if t == Vec3::ZERO {
                Outcome::Refused
            } else {
                Outcome::Transmitted(t.as_dvec3())
            },
        }
    }
}

// ---------------------------------------------------------------------------------------------

#[cfg(test)]
mod tests {
    use super::*;

    /// Snell's law in f64, through angles: the facing normal, sinθt = μ·sinθi, T along the
    /// tangential direction and against the facing normal; `None` past the critical angle.
    fn snell(hit: &Hit) -> Option<DVec3> {
        let facing = if hit.from_inside {
            -hit.outward
        } else {
            hit.outward
        };
        let mu = if hit.from_inside {
            INSIDE / OUTSIDE
        } else {
            OUTSIDE / INSIDE
        };
        let cos_i = -hit.travel.dot(facing);
        let across = hit.travel + facing * cos_i;
        let sin_i = across.length();
        let sin_t = mu * sin_i;
        if sin_t > 1.0 {
            return None;
        }
        if sin_i == 0.0 {
            return Some(hit.travel);
        }
        let cos_t = (1.0 - sin_t * sin_t).sqrt();
        Some(across / sin_i * sin_t - facing * cos_t)
    }

    /// cosθt of Snell's law, negative past the critical angle (as −√(−k)).
    fn cos_t(hit: &Hit) -> f64 {
        let mu = if hit.from_inside {
            INSIDE / OUTSIDE
        } else {
            OUTSIDE / INSIDE
        };
        let sin_i = hit.sin_i();
        let k = 1.0 - mu * mu * sin_i * sin_i;
        k.abs().sqrt().copysign(k)
    }

    fn hits(seed: u64, count: usize) -> Vec<Hit> {
        let mut rng = Rng::new(seed);
        (0..count).map(|_| Hit::draw(&mut rng)).collect()
    }

    /// The rounding unit a renderer computes with.
    fn epsilon(renderer: Renderer) -> f64 {
        match renderer {
            Renderer::Pbrt | Renderer::Glsl => f64::from(f32::EPSILON),
            Renderer::Smallpt | Renderer::Rtiow => f64::EPSILON,
        }
    }

    #[test]
    fn bug_free_calls_agree_with_snell_s_law() {
        for renderer in Renderer::ALL {
            let eps = epsilon(renderer);
            let (mut transmitted, mut refused) = (0, 0);
            for hit in hits(7, 20_000) {
                let c = cos_t(&hit);
                if c.abs() < 1e3 * eps {
                    continue; // within rounding of the critical angle: either answer
                }
                let printed = emulate(renderer, Bug::None, &hit);
                match (snell(&hit), printed.map(|p| p.outcome)) {
                    (Some(t), Some(Outcome::Transmitted(got))) => {
                        let tolerance = 16.0 * eps * (1.0 + 1.0 / c);
                        let off = angle(got, t);
                        assert!(
                            off <= tolerance,
                            "{renderer:?} {hit:?}: {off} > {tolerance}"
                        );
                        let length_off = (got.length() - 1.0).abs();
                        assert!(
                            length_off < 64.0 * eps,
                            "{renderer:?}: |T| = {}",
                            got.length()
                        );
                        transmitted += 1;
                    }
                    (None, Some(Outcome::Refused) | None) => refused += 1,
                    (expected, got) => panic!("{renderer:?} {hit:?}: {expected:?} vs {got:?}"),
                }
            }
            assert!(transmitted > 10_000 && refused > 4_000, "{renderer:?}");
        }
    }

    #[test]
    fn the_book_reflects_where_it_cannot_refract_and_glsl_returns_zero() {
        for hit in hits(11, 4_000).iter().filter(|h| h.past_critical()) {
            if cos_t(hit).abs() < 1e-6 {
                continue;
            }
            let line = rtiow::call(Bug::None, hit);
            assert_eq!(line.outcome, Outcome::Refused);
            let reflected = hit.travel - 2.0 * hit.travel.dot(hit.outward) * hit.outward;
            assert!(angle(rtiow::reflection(hit), reflected) < 1e-12);
            assert!(line.plain.ends_with(&{
                let [x, y, z] = rtiow::reflection(hit).to_array().map(|c| c_general(c, 6));
                format!("refracted={x} {y} {z}")
            }));
            assert!(
                glsl::call(Bug::None, hit)
                    .plain
                    .ends_with("-> (0.000000, 0.000000, 0.000000)")
            );
            let pbrt = pbrt::call(Bug::None, hit).plain;
            assert!(pbrt.ends_with("etap=0.000000 ok=0 entering=0"), "{pbrt}");
            assert!(smallpt::call(Bug::None, hit).is_none());
        }
    }

    #[test]
    fn glsl_is_glam_s_refract_bit_for_bit() {
        for hit in hits(3, 5_000) {
            let i = hit.travel.as_vec3().normalize();
            let n = hit.outward.as_vec3().normalize();
            let n = if i.dot(n) < 0.0 { n } else { -n };
            for eta in [1.0_f32 / 1.5, 1.5] {
                let (ours, glam) = (glsl::refract(i, n, eta), i.refract(n, eta));
                assert_eq!(
                    ours.to_array().map(f32::to_bits),
                    glam.to_array().map(f32::to_bits)
                );
            }
        }
    }

    /// The worked examples of refraction-explorer's pbrt adapter (`refraction_kernel::api::pbrt`
    /// tests), bit for bit.
    #[test]
    fn pbrt_matches_the_project_s_worked_examples() {
        let wi = Vec3::new(
            f32::from_bits(0xbf24_8dbb),
            f32::from_bits(0x3f44_1b7d),
            0.0,
        );
        let (wt, etap) = pbrt::refract(wi, Vec3::Y, 1.5, Bug::None).unwrap();
        assert_eq!((wt.x.to_bits(), wt.y.to_bits()), (0x3edb_67a4, 0xbf67_4dbc));
        assert_eq!(etap.to_bits(), 1.5_f32.to_bits());
        let angle = 20_f64.to_radians();
        let wi = -DVec3::new(angle.sin(), angle.cos(), 0.0).as_vec3();
        let (wt, etap) = pbrt::refract(wi, Vec3::Y, 1.5, Bug::None).unwrap();
        assert_eq!(etap.to_bits(), 0x3f2a_aaab);
        assert_eq!((wt.x.to_bits(), wt.y.to_bits()), (0x3f03_55f3, 0x3f5b_be2c));
        let wi = -DVec3::new(0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0).as_vec3();
        assert_eq!(pbrt::refract(wi, Vec3::Y, 1.5, Bug::None), None);
    }

    /// What a bug must do to one ray's line.
    #[derive(Debug, PartialEq)]
    enum Touch {
        /// The same text as the bug-free code's.
        Identical,
        /// A wrong call.
        Wrong,
        /// No line, with or without the bug.
        Absent,
    }

    /// What `bug` must do to `hit`'s line (see each variant's docs).
    #[expect(clippy::match_same_arms)] // one arm per case, as the docs read
    fn touch(bug: Bug, hit: &Hit) -> Touch {
        let (inside, past) = (hit.from_inside, hit.past_critical());
        let grazing_out = !inside && hit.sin_i() * INSIDE / OUTSIDE > 1.0;
        match bug {
            Bug::None => Touch::Identical,
            Bug::PbrtEtaInverted | Bug::GlslEtaInverted | Bug::GlslIncidentReversed => Touch::Wrong,
            Bug::PbrtNoFlipInside
            | Bug::RtiowRatioNotInverted
            | Bug::RtiowOutwardNormal
            | Bug::GlslOutwardNormal => {
                if inside {
                    Touch::Wrong
                } else {
                    Touch::Identical
                }
            }
            Bug::PbrtNormalTermSign if past => Touch::Identical,
            Bug::PbrtNormalTermSign => Touch::Wrong,
            Bug::SmallptNormalsSwapped if past => Touch::Absent,
            Bug::SmallptNormalsSwapped if inside => Touch::Wrong,
            Bug::SmallptNormalsSwapped => Touch::Identical,
            Bug::SmallptNntInverted if grazing_out => Touch::Absent,
            Bug::SmallptNntInverted => Touch::Wrong,
        }
    }

    /// Whether `bug` must change the outcome of `hit`'s call (`None`: either, near normal
    /// incidence, where a wrong ratio or a reversed incident vector changes nothing).
    #[expect(clippy::match_same_arms)] // one arm per case, as the docs read
    fn outcome_changes(bug: Bug, hit: &Hit) -> Option<bool> {
        let (inside, past) = (hit.from_inside, hit.past_critical());
        let normal = hit.sin_i() < 1e-3;
        match bug {
            Bug::None => Some(false),
            Bug::PbrtEtaInverted | Bug::SmallptNntInverted | Bug::GlslEtaInverted if normal => None,
            Bug::PbrtEtaInverted | Bug::SmallptNntInverted | Bug::GlslEtaInverted => Some(true),
            Bug::RtiowRatioNotInverted if inside && normal => None,
            Bug::RtiowRatioNotInverted | Bug::PbrtNoFlipInside => Some(inside),
            Bug::PbrtNormalTermSign => Some(!past),
            Bug::SmallptNormalsSwapped | Bug::RtiowOutwardNormal | Bug::GlslOutwardNormal => {
                Some(inside && !past)
            }
            Bug::GlslIncidentReversed if normal => None,
            Bug::GlslIncidentReversed => Some(!past),
        }
    }

    #[test]
    fn each_bug_changes_the_lines_it_should_and_only_those() {
        let all = hits(5, 20_000);
        for renderer in Renderer::ALL {
            for &bug in core::iter::once(&Bug::None).chain(renderer.bugs()) {
                let (mut wrong, mut right_outcome_wrong_call) = (0, 0);
                for hit in &all {
                    if cos_t(hit).abs() < 1e-3 {
                        continue; // within rounding of the critical angle
                    }
                    let right = emulate(renderer, Bug::None, hit);
                    let got = emulate(renderer, bug, hit);
                    let is_wrong = got.as_ref().map(|g| differs(g, right.as_ref(), Shown::All));
                    let expected = touch(bug, hit);
                    let context = || format!("{bug:?} {hit:?} {expected:?} {got:?} {right:?}");
                    match expected {
                        Touch::Identical => match (&got, &right) {
                            (Some(g), Some(r)) => {
                                assert_eq!(
                                    (&g.plain, &g.mixed),
                                    (&r.plain, &r.mixed),
                                    "{}",
                                    context()
                                );
                            }
                            (None, None) => {}
                            _ => panic!("{}", context()),
                        },
                        Touch::Wrong => assert_eq!(is_wrong, Some(true), "{}", context()),
                        Touch::Absent => assert!(got.is_none(), "{}", context()),
                    }
                    let changed = match (&got, &right) {
                        (Some(g), Some(r)) => Some(outcomes_differ(g.outcome, r.outcome)),
                        (Some(_), None) => Some(true),
                        (None, _) => None,
                    };
                    if let (Some(changed), Some(expected)) = (changed, outcome_changes(bug, hit)) {
                        assert_eq!(changed, expected, "outcome: {}", context());
                    }
                    wrong += usize::from(is_wrong == Some(true));
                    right_outcome_wrong_call +=
                        usize::from(is_wrong == Some(true) && changed == Some(false));
                }
                assert_eq!(wrong > 0, bug != Bug::None, "{bug:?}: {wrong} wrong lines");
                let shows_only_in_arguments = matches!(
                    bug,
                    Bug::RtiowOutwardNormal | Bug::GlslOutwardNormal | Bug::GlslIncidentReversed
                );
                assert_eq!(
                    right_outcome_wrong_call > 1_000,
                    shows_only_in_arguments,
                    "{bug:?}"
                );
            }
        }
    }

    #[test]
    fn normal_term_sign_keeps_the_part_across_n() {
        for hit in hits(13, 5_000).iter().filter(|h| !h.past_critical()) {
            let right = pbrt::call(Bug::None, hit).outcome;
            let got = pbrt::call(Bug::PbrtNormalTermSign, hit).outcome;
            let (Outcome::Transmitted(right), Outcome::Transmitted(got)) = (right, got) else {
                panic!("{hit:?}");
            };
            let n = hit.outward;
            let across = |v: DVec3| v - n * v.dot(n);
            assert!((across(right) - across(got)).length() < 1e-6);
            assert!((right.dot(n) - got.dot(n)).abs() > 0.1);
        }
    }

    #[test]
    fn smallpt_swapped_normals_flip_the_n_term_only_from_inside() {
        for hit in hits(17, 5_000)
            .iter()
            .filter(|h| h.from_inside && !h.past_critical())
        {
            let (Some(right), Some(got)) = (
                smallpt::call(Bug::None, hit),
                smallpt::call(Bug::SmallptNormalsSwapped, hit),
            ) else {
                panic!("{hit:?}");
            };
            let (Outcome::Transmitted(right), Outcome::Transmitted(got)) =
                (right.outcome, got.outcome)
            else {
                panic!("{hit:?}");
            };
            // Still leaves the glass (not the other root), bent toward the normal.
            let n = hit.outward;
            assert!(got.dot(n) > 0.0 && right.dot(n) > 0.0);
            assert!(got.dot(n) >= right.dot(n) - 1e-12);
            let reflected_across = right - 2.0 * right.dot(n) * n;
            assert!(angle(got, reflected_across) > 1e-3 || hit.sin_i() < 1e-3);
        }
    }

    #[test]
    fn pbrt_without_the_flip_logs_etap_never_inverted() {
        let log = log(Renderer::Pbrt, Bug::PbrtNoFlipInside, 2_000, 1, false);
        for line in &log.lines {
            let etap = line
                .text
                .split("etap=")
                .nth(1)
                .unwrap()
                .split(' ')
                .next()
                .unwrap();
            assert_eq!(etap, "1.500000", "{}", line.text);
            assert_eq!(line.wrong, line.from_inside, "{}", line.text);
            assert!(line.text.contains("ok=1"));
        }
        let right = super::log(Renderer::Pbrt, Bug::None, 2_000, 1, false);
        assert!(
            right
                .lines
                .iter()
                .any(|l| l.text.contains("etap=0.666667 ok=1"))
        );
    }

    #[test]
    fn logs_mix_sides_and_past_critical_lines_and_name_the_verdict() {
        for renderer in Renderer::ALL {
            for &bug in core::iter::once(&Bug::None).chain(renderer.bugs()) {
                let log = log(renderer, bug, 1_000, 42, false);
                assert_eq!(log.lines.len(), 1_000);
                let inside = log.lines.iter().filter(|l| l.from_inside).count();
                let past = log.lines.iter().filter(|l| l.past_critical).count();
                let wrong = log.lines.iter().filter(|l| l.wrong).count();
                assert!(
                    inside > 150 && inside < 850,
                    "{bug:?}: {inside} from inside"
                );
                // smallpt prints nothing past the critical angle unless nnt is inverted.
                let prints_past = renderer != Renderer::Smallpt || bug == Bug::SmallptNntInverted;
                assert_eq!(past > 100, prints_past, "{bug:?}: {past} past critical");
                assert_eq!(wrong == 0, bug == Bug::None, "{bug:?}: {wrong} wrong");
                assert!(log.lines.iter().all(|l| !l.past_critical || l.from_inside));
                assert_eq!((log.inside, log.outside), (1.5, 1.0));
                assert_eq!(log.expected_code, bug.expected_code());
                assert_eq!(log.fix.is_empty(), bug == Bug::None);
                assert_eq!(log.api, renderer.api());
            }
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_log() {
        let a = log(Renderer::Glsl, Bug::GlslEtaInverted, 50, 9, true);
        let b = log(Renderer::Glsl, Bug::GlslEtaInverted, 50, 9, true);
        let c = log(Renderer::Glsl, Bug::GlslEtaInverted, 50, 10, true);
        assert_eq!(a.lines, b.lines);
        assert_ne!(a.lines, c.lines);
    }

    #[test]
    #[should_panic(expected = "is a bug in Pbrt's code, not in Glsl's")]
    fn a_bug_of_another_renderer_panics() {
        let _ = log(Renderer::Glsl, Bug::PbrtEtaInverted, 1, 0, false);
    }

    #[test]
    fn every_bug_belongs_to_one_renderer_and_is_listed_there() {
        for bug in Bug::ALL {
            match bug.renderer() {
                None => assert_eq!(bug, Bug::None),
                Some(r) => assert!(r.bugs().contains(&bug)),
            }
        }
        let listed: usize = Renderer::ALL.iter().map(|r| r.bugs().len()).sum();
        assert_eq!(listed + 1, Bug::ALL.len());
    }

    #[test]
    fn lines_print_as_the_student_s_code_prints_them() {
        let first = |renderer, mixed| log(renderer, Bug::None, 1, 4, mixed).lines[0].text.clone();
        let pbrt = first(Renderer::Pbrt, false);
        assert!(pbrt.starts_with("Refract wi=(") && pbrt.contains(") eta=1.500000 -> wt=("));
        let pbrt_mixed = first(Renderer::Pbrt, true);
        assert!(pbrt_mixed.contains(" eta=1.5 -> "), "{pbrt_mixed}");
        let smallpt = first(Renderer::Smallpt, false);
        assert!(
            smallpt.starts_with("REFR d=(") && smallpt.contains(" tdir=("),
            "{smallpt}"
        );
        assert!(first(Renderer::Smallpt, true).contains(" nnt="));
        let rtiow = first(Renderer::Rtiow, true);
        assert!(
            rtiow.starts_with("uv=") && rtiow.contains(" front_face="),
            "{rtiow}"
        );
        let glsl = first(Renderer::Glsl, false);
        assert!(
            glsl.starts_with("rd=(") && glsl.contains(") I=(") && glsl.contains(" -> ("),
            "{glsl}"
        );
        // The mixed-precision ratios: 17 significant digits of the f32 or f64 value.
        let pbrt_inside = log(Renderer::Pbrt, Bug::None, 200, 4, true);
        assert!(
            pbrt_inside
                .lines
                .iter()
                .any(|l| l.text.contains("etap=0.66666668653488159 "))
        );
        let rtiow_inside = log(Renderer::Rtiow, Bug::None, 200, 4, true);
        assert!(
            rtiow_inside
                .lines
                .iter()
                .any(|l| l.text.contains("ratio=0.66666666666666663 "))
        );
        let smallpt_log = log(Renderer::Smallpt, Bug::None, 200, 4, true);
        assert!(
            smallpt_log
                .lines
                .iter()
                .any(|l| l.text.contains("nnt=0.66666666666666663 "))
        );
    }

    #[test]
    fn c_formatting() {
        assert_eq!(c_general(2.0 / 3.0, 6), "0.666667");
        assert_eq!(c_general(1.5, 6), "1.5");
        assert_eq!(c_general(1e-5, 6), "1e-05");
        assert_eq!(c_general(0.0001, 6), "0.0001");
        assert_eq!(c_general(-0.903_529_6, 6), "-0.90353");
        assert_eq!(c_general(123_456.7, 6), "123457");
        assert_eq!(c_general(1_234_567.0, 6), "1.23457e+06");
        assert_eq!(c_general(2.0 / 3.0, 17), "0.66666666666666663");
        assert_eq!(
            c_general(f64::from(1.0_f32 / 1.5), 17),
            "0.66666668653488159"
        );
        assert_eq!(c_general(0.0, 6), "0");
        assert_eq!(c_general(-0.0, 6), "-0");
        assert_eq!(c_fixed(-0.0, 6), "-0.000000");
        assert_eq!(c_fixed(-1e-9, 6), "-0.000000");
        assert_eq!(c_fixed(f64::NAN, 6), "nan");
    }

    #[test]
    fn patterns_name_only_fields_of_their_api() {
        for renderer in Renderer::ALL {
            for mixed in [false, true] {
                let log = log(renderer, Bug::None, 1, 0, mixed);
                let fields = |p: &str| -> Vec<String> {
                    p.split('{')
                        .skip(1)
                        .map(|s| s.split('}').next().unwrap().to_owned())
                        .collect()
                };
                let named = fields(log.pattern);
                let allowed: &[&str] = match renderer {
                    Renderer::Pbrt => &["wi", "n", "eta", "wt", "etap", "returned", "entering"],
                    Renderer::Smallpt => &["w", "n", "entering", "ratio", "t_yours"],
                    Renderer::Rtiow => &["uv", "n", "etai_over_etat", "front_face", "refracted"],
                    Renderer::Glsl => &["travel", "I", "N", "eta", "entering", "result"],
                };
                assert!(
                    named.iter().all(|f| allowed.contains(&f.as_str())),
                    "{named:?}"
                );
                assert_eq!(log.pattern, pattern(renderer, mixed));
            }
        }
    }
}
