//! What the explorer shows: W, N, the two indices and the convention, kept valid at all times,
//! with the kernel's answer for them; and the edits a user makes by dragging, nudging and typing.

use glam::{DVec2, DVec3};

use refraction_i18n::t;
use refraction_kernel::{Convention, Incidence, InputError, Refraction, refract};

/// The range of the index scale beside the diagram (dragging stays inside it; typed values
/// may go beyond).
pub const INDEX_RANGE: (f64, f64) = (1.0, 2.6);

/// A named medium for the index presets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Its name, the same in every language (shown in the language's words by
    /// [`Material::label`]).
    pub name: &'static str,
    /// Its index of refraction.
    pub index: f64,
}

/// The presets: vacuum, air, water, glass and diamond.
pub const MATERIALS: [Material; 5] = [
    Material {
        name: "vacuum",
        index: 1.0,
    },
    Material {
        name: "air",
        index: 1.000293,
    },
    Material {
        name: "water",
        index: 1.333,
    },
    Material {
        name: "glass",
        index: 1.5,
    },
    Material {
        name: "diamond",
        index: 2.417,
    },
];

impl Material {
    /// Its name as shown, in the current language.
    #[must_use]
    pub fn label(&self) -> String {
        match self.name {
            "vacuum" => t!("diagram-material-vacuum"),
            "air" => t!("diagram-material-air"),
            "water" => t!("diagram-material-water"),
            "glass" => t!("diagram-material-glass"),
            "diamond" => t!("diagram-material-diamond"),
            other => other.to_owned(),
        }
    }
}

/// The preset with exactly this index, if any.
#[must_use]
pub fn material_of(index: f64) -> Option<Material> {
    MATERIALS.into_iter().find(|m| m.index == index)
}

/// A typed angle of incidence the explorer cannot show.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum AngleError {
    /// Not a number in [0°, 90°).
    #[error("{}", out_of_range(*.0))]
    OutOfRange(f64),
}

/// [`AngleError::OutOfRange`]'s message, in the current language.
fn out_of_range(degrees: f64) -> String {
    let angle = refraction_i18n::decimal(&degrees.to_string());
    t!("diagram-angle-out-of-range", angle = angle)
}

/// The lessons a teacher starts from, each one click away.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lesson {
    /// From air into glass at 40°: the ordinary case.
    AirToGlass,
    /// From glass into air at 45°, beyond the critical angle (41.8°): total internal reflection.
    BeyondCritical,
    /// Straight down the normal: nothing bends.
    NormalIncidence,
    /// From air into glass at Brewster's angle (tan θB = μt/μi): reflected and refracted rays
    /// at right angles.
    Brewster,
    /// A ray leaving a water droplet at 40°, with the droplet's outward normal: the normal the
    /// kernel must turn round, and the wrong T of the paper's formula beside it.
    DropletExit,
}

impl Lesson {
    /// Every lesson, in the order of the menu.
    pub const ALL: [Self; 5] = [
        Self::AirToGlass,
        Self::BeyondCritical,
        Self::NormalIncidence,
        Self::Brewster,
        Self::DropletExit,
    ];

    /// Its name in the menu (also its accessible name), in the current language.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::AirToGlass => t!("diagram-lesson-air-to-glass"),
            Self::BeyondCritical => t!("diagram-lesson-beyond-critical"),
            Self::NormalIncidence => t!("diagram-lesson-normal-incidence"),
            Self::Brewster => t!("diagram-lesson-brewster"),
            Self::DropletExit => t!("diagram-lesson-droplet-exit"),
        }
    }

    /// The state the lesson starts from, in Section 2's convention.
    #[must_use]
    pub fn state(self) -> ExplorerState {
        let (mu_i, mu_t, degrees, n) = match self {
            Self::AirToGlass => return ExplorerState::default(),
            Self::BeyondCritical => (GLASS, AIR, 45.0, DVec3::Y),
            Self::NormalIncidence => (AIR, GLASS, 0.0, DVec3::Y),
            Self::Brewster => (AIR, GLASS, (GLASS / AIR).atan().to_degrees(), DVec3::Y),
            Self::DropletExit => (WATER, AIR, 40.0, DVec3::NEG_Y),
        };
        let angle = f64::to_radians(degrees);
        let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
        ExplorerState::new(w, n, mu_i, mu_t, Convention::AlongRay)
            // untranslated: a panic message for developers, never shown to a user.
            .unwrap_or_else(|_| unreachable!("every lesson's incidence is valid (tested)"))
    }
}

/// The presets' indices, by name.
const AIR: f64 = MATERIALS[1].index;
const WATER: f64 = MATERIALS[2].index;
const GLASS: f64 = MATERIALS[3].index;

/// The draggable things on the canvas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HandleId {
    /// The tip of W: sets the incoming direction.
    W,
    /// The tip of N: rotates the surface.
    N,
    /// `μ_i`'s marker on the index scale.
    MuI,
    /// `μ_t`'s marker on the index scale.
    MuT,
}

impl HandleId {
    /// All handles, in keyboard (Tab) order.
    pub const ALL: [Self; 4] = [Self::W, Self::N, Self::MuI, Self::MuT];

    /// The accessible name (what a screen reader says and what tests look for), in the
    /// current language: the control the handle is, the same on the desktop and in a browser
    /// (W is the angle of incidence θi, N the direction of the normal, μi and μt the indices).
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::W => t!("diagram-handle-w"),
            Self::N => t!("diagram-handle-n"),
            Self::MuI => t!("diagram-handle-mu-i"),
            Self::MuT => t!("diagram-handle-mu-t"),
        }
    }
}

/// The plane of incidence, in which the diagram is drawn: an orthonormal pair of 3D directions
/// that become the diagram's x (right) and y (up) axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// The diagram's x axis.
    pub u: DVec3,
    /// The diagram's y axis.
    pub v: DVec3,
}

impl Plane {
    /// The plane z = 0, drawn with x right and y up.
    pub const XY: Self = Self {
        u: DVec3::X,
        v: DVec3::Y,
    };

    /// The plane containing `w` and `n` (non-zero). Its orientation is chosen from the axes
    /// alone, so that vectors in the xy plane are drawn exactly as in [`Plane::XY`]. When W is
    /// parallel to N any plane through N would do; the one closest to the xy plane is used.
    #[must_use]
    pub fn containing(w: DVec3, n: DVec3) -> Self {
        let (w, n) = (scaled(w), scaled(n));
        let normal = n
            .cross(w)
            .try_normalize()
            .or_else(|| n.cross(n.cross(DVec3::Z)).try_normalize())
            .or_else(|| n.cross(n.cross(DVec3::X)).try_normalize())
            .unwrap_or(DVec3::Z);
        let largest = normal.abs().max_position();
        let normal = if normal[largest] < 0.0 {
            -normal
        } else {
            normal
        };
        let [x, y, z] = [DVec3::X, DVec3::Y, DVec3::Z].map(|a| a.dot(normal).abs());
        let axis = if x <= y && x <= z {
            DVec3::X
        } else if y <= z {
            DVec3::Y
        } else {
            DVec3::Z
        };
        let u = (axis - normal * axis.dot(normal)).normalize_or(DVec3::X);
        Self {
            u,
            v: normal.cross(u),
        }
    }

    /// The diagram coordinates of a 3D vector (its part in the plane).
    #[must_use]
    pub fn project(&self, v: DVec3) -> DVec2 {
        DVec2::new(v.dot(self.u), v.dot(self.v))
    }

    /// The 3D vector at diagram coordinates `p`.
    #[must_use]
    pub fn lift(&self, p: DVec2) -> DVec3 {
        self.u * p.x + self.v * p.y
    }
}

/// The explorer's state: one refraction problem, always valid, with the kernel's answer.
///
/// Every edit goes through the kernel first and is refused (with the kernel's message) when the
/// kernel refuses it, so the state shown is always the last good one.
#[derive(Clone, Debug, PartialEq)]
pub struct ExplorerState {
    w: DVec3,
    n: DVec3,
    mu_i: f64,
    mu_t: f64,
    convention: Convention,
    plane: Plane,
    refraction: Refraction<f64>,
}

impl Default for ExplorerState {
    /// W at 40° from the normal, from air into glass, in Section 2's convention
    /// ([`Lesson::AirToGlass`]).
    fn default() -> Self {
        let angle = 40_f64.to_radians();
        let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
        Self::new(w, DVec3::Y, AIR, GLASS, Convention::AlongRay)
            // untranslated: a panic message for developers, never shown to a user.
            .unwrap_or_else(|_| unreachable!("the default incidence is valid"))
    }
}

impl ExplorerState {
    /// A state for these inputs (W and N need not be unit length); the diagram is drawn in
    /// their plane of incidence.
    ///
    /// # Errors
    /// The kernel's [`InputError`] naming the bad input.
    pub fn new(
        w: DVec3,
        n: DVec3,
        mu_i: f64,
        mu_t: f64,
        convention: Convention,
    ) -> Result<Self, InputError> {
        let refraction = refract(&Incidence {
            w,
            n,
            mu_i,
            mu_t,
            convention,
        })?;
        Ok(Self {
            w,
            n,
            mu_i,
            mu_t,
            convention,
            plane: Plane::containing(w, n),
            refraction,
        })
    }

    /// W as given.
    #[must_use]
    pub fn w(&self) -> DVec3 {
        self.w
    }

    /// N as given.
    #[must_use]
    pub fn n(&self) -> DVec3 {
        self.n
    }

    /// `μ_i`, the index of the medium the ray travels in.
    #[must_use]
    pub fn mu_i(&self) -> f64 {
        self.mu_i
    }

    /// `μ_t`, the index of the medium the ray enters.
    #[must_use]
    pub fn mu_t(&self) -> f64 {
        self.mu_t
    }

    /// Which way W points.
    #[must_use]
    pub fn convention(&self) -> Convention {
        self.convention
    }

    /// The plane the diagram is drawn in.
    #[must_use]
    pub fn plane(&self) -> &Plane {
        &self.plane
    }

    /// The kernel's answer for the current inputs.
    #[must_use]
    pub fn refraction(&self) -> &Refraction<f64> {
        &self.refraction
    }

    /// Replaces the inputs, keeping the plane of the diagram, if the kernel accepts them.
    fn update(
        &mut self,
        w: DVec3,
        n: DVec3,
        mu_i: f64,
        mu_t: f64,
        convention: Convention,
    ) -> Result<(), InputError> {
        let plane = self.plane;
        *self = Self::new(w, n, mu_i, mu_t, convention)?;
        self.plane = plane;
        Ok(())
    }

    /// Sets W and N as typed (3D, any non-zero length); the diagram moves to their plane.
    ///
    /// # Errors
    /// The kernel's message for a non-finite or zero vector; the state is unchanged.
    pub fn set_vectors(&mut self, w: DVec3, n: DVec3) -> Result<(), InputError> {
        *self = Self::new(w, n, self.mu_i, self.mu_t, self.convention)?;
        Ok(())
    }

    /// Sets `μ_i`.
    ///
    /// # Errors
    /// The kernel's message for an index that is not a finite number > 0; the state is unchanged.
    pub fn set_mu_i(&mut self, mu_i: f64) -> Result<(), InputError> {
        self.update(self.w, self.n, mu_i, self.mu_t, self.convention)
    }

    /// Sets `μ_t`.
    ///
    /// # Errors
    /// As [`ExplorerState::set_mu_i`].
    pub fn set_mu_t(&mut self, mu_t: f64) -> Result<(), InputError> {
        self.update(self.w, self.n, self.mu_i, mu_t, self.convention)
    }

    /// Sets the index a μ handle stands for ([`HandleId::MuI`] or [`HandleId::MuT`]; other
    /// handles are ignored).
    ///
    /// # Errors
    /// As [`ExplorerState::set_mu_i`].
    pub fn set_index(&mut self, handle: HandleId, index: f64) -> Result<(), InputError> {
        match handle {
            HandleId::MuI => self.set_mu_i(index),
            HandleId::MuT => self.set_mu_t(index),
            HandleId::W | HandleId::N => Ok(()),
        }
    }

    /// The index a μ handle stands for (`μ_t` for the others).
    #[must_use]
    pub fn index(&self, handle: HandleId) -> f64 {
        if handle == HandleId::MuI {
            self.mu_i
        } else {
            self.mu_t
        }
    }

    /// Switches the convention. The ray stays where it is, so W turns around: that is the
    /// whole difference between the paper's two sections.
    pub fn set_convention(&mut self, convention: Convention) {
        if convention != self.convention {
            let turned = self.update(-self.w, self.n, self.mu_i, self.mu_t, convention);
            debug_assert!(
                turned.is_ok(),
                "−W is as valid as W: the kernel cannot refuse it"
            );
        }
    }

    /// Turns N around (an outward normal where the ray leaves the medium: the classic bug).
    pub fn flip_normal(&mut self) {
        let flipped = self.update(self.w, -self.n, self.mu_i, self.mu_t, self.convention);
        // The kernel checks finiteness and length, which a sign keeps.
        debug_assert!(
            flipped.is_ok(),
            "−N is as valid as N: the kernel cannot refuse it"
        );
    }

    /// Points W (for [`HandleId::W`]) or N (for [`HandleId::N`]) along the diagram direction
    /// `direction`, keeping its length; a zero direction is ignored.
    pub fn point(&mut self, handle: HandleId, direction: DVec2) {
        let Some(direction) = direction.try_normalize() else {
            return;
        };
        let lifted = |v: DVec3| self.plane.lift(direction) * length(v);
        let (w, n) = match handle {
            HandleId::W => (lifted(self.w), self.n),
            HandleId::N => (self.w, lifted(self.n)),
            HandleId::MuI | HandleId::MuT => return,
        };
        // A turned vector the kernel refuses (one so long or short that its length overflows
        // or vanishes on the way) leaves the last good state, as every refused edit does: the
        // handle does not follow the pointer there.
        self.update(w, n, self.mu_i, self.mu_t, self.convention)
            .ok();
    }

    /// The diagram direction of W or N (the in-plane part of the vector, unit length; μ handles
    /// give the diagram's x axis).
    #[must_use]
    pub fn direction(&self, handle: HandleId) -> DVec2 {
        let v = match handle {
            HandleId::W => self.w,
            HandleId::N => self.n,
            HandleId::MuI | HandleId::MuT => return DVec2::X,
        };
        self.plane.project(scaled(v)).normalize_or(DVec2::X)
    }

    /// Turns W or N counter-clockwise in the diagram by `degrees`.
    pub fn rotate(&mut self, handle: HandleId, degrees: f64) {
        let direction = DVec2::from_angle(degrees.to_radians()).rotate(self.direction(handle));
        self.point(handle, direction);
    }

    /// How far N leans from straight up in the diagram, in degrees: positive to the right
    /// (clockwise), in (−180°, 180°].
    #[must_use]
    pub fn normal_tilt_degrees(&self) -> f64 {
        let n = self.direction(HandleId::N);
        n.x.atan2(n.y).to_degrees()
    }

    /// Turns N in the diagram to lean `degrees` from straight up, clockwise (what
    /// [`ExplorerState::normal_tilt_degrees`] then gives, modulo 360°); a value that is not
    /// finite is ignored.
    pub fn set_normal_tilt_degrees(&mut self, degrees: f64) {
        if degrees.is_finite() {
            let (sin, cos) = degrees.to_radians().sin_cos();
            self.point(HandleId::N, DVec2::new(sin, cos));
        }
    }

    /// The critical angle θc in radians (sin θc = `μ_t/μ_i`), when there is one (`μ_i` > `μ_t`).
    #[must_use]
    pub fn critical_angle(&self) -> Option<f64> {
        (self.mu_i > self.mu_t).then(|| (self.mu_t / self.mu_i).asin())
    }

    /// The angle of incidence θi in degrees, between the ray coming in and the normal facing it.
    #[must_use]
    pub fn incidence_degrees(&self) -> f64 {
        self.refraction.cos_i.clamp(-1.0, 1.0).acos().to_degrees()
    }

    /// Turns W so that the ray meets the surface at `degrees` from the normal, coming from the
    /// side it comes from now; N, the indices and the convention stay.
    ///
    /// # Errors
    /// [`AngleError::OutOfRange`] unless 0 ≤ `degrees` < 90; the state is unchanged.
    pub fn set_incidence_degrees(&mut self, degrees: f64) -> Result<(), AngleError> {
        if !(0.0..90.0).contains(&degrees) {
            return Err(AngleError::OutOfRange(degrees));
        }
        self.set_incidence(degrees.to_radians());
        Ok(())
    }

    /// Turns W to `angle` radians from the facing normal, on the side the ray comes from.
    fn set_incidence(&mut self, angle: f64) {
        let r = &self.refraction;
        let toward_source = self.plane.project(-r.travel);
        let normal = self.plane.project(r.facing_normal).normalize_or(DVec2::Y);
        let side = if normal.perp_dot(toward_source) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let toward_source = DVec2::from_angle(side * angle).rotate(normal);
        let sign = self.convention.travel_sign::<f64>();
        self.point(HandleId::W, -toward_source * sign);
    }

    /// Turns W so that the ray meets the surface at the critical angle, on the side it comes
    /// from now. Does nothing without a critical angle.
    ///
    /// The angle is a nanoradian short of θc: exactly at θc rounding decides between total
    /// reflection and a grazing T, and the class should see T lying along the surface.
    pub fn snap_to_critical_angle(&mut self) {
        if let Some(critical) = self.critical_angle() {
            self.set_incidence(critical - 1e-9);
        }
    }
}

/// What `v` is divided by before its components are squared (for a cross product or a
/// length): its largest component's magnitude when that lies outside 1e−100..1e100, where the
/// squares would overflow or underflow (|v| above about 1e154 or below about 1e−154), else 1,
/// so that ordinary vectors keep their bits. The kernel scales the same way before it
/// normalises.
fn scale_of(v: DVec3) -> f64 {
    let largest = v.abs().max_element();
    if largest.is_finite() && largest > 0.0 && !(1e-100..=1e100).contains(&largest) {
        largest
    } else {
        1.0
    }
}

/// `v` in the same direction with components safe to square (see [`scale_of`]).
fn scaled(v: DVec3) -> DVec3 {
    v / scale_of(v)
}

/// |v| without overflow or underflow in the squares (see [`scale_of`]).
fn length(v: DVec3) -> f64 {
    scaled(v).length() * scale_of(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_refracts_from_air_into_glass() {
        let state = ExplorerState::default();
        let r = state.refraction();
        assert!(!r.is_tir() && !r.normal_flipped);
        assert!((r.cos_i - 40_f64.to_radians().cos()).abs() < 1e-12);
        assert_eq!(state.plane(), &Plane::XY);
    }

    #[test]
    fn planes_of_3d_vectors_contain_them_and_keep_xy_as_drawn() {
        let (w, n) = (DVec3::new(0.3, -0.5, 0.8), DVec3::new(0.0, 0.6, 0.8));
        let plane = Plane::containing(w, n);
        for v in [w, n] {
            assert!((plane.lift(plane.project(v)) - v).length() < 1e-12);
        }
        assert!(plane.u.dot(plane.v).abs() < 1e-15);
        let xy = Plane::containing(DVec3::new(1.0, -1.0, 0.0), DVec3::new(0.2, 1.0, 0.0));
        assert!((xy.u - DVec3::X).length() < 1e-15 && (xy.v - DVec3::Y).length() < 1e-15);
        let parallel = Plane::containing(DVec3::NEG_Y, DVec3::Y);
        assert!(parallel.project(DVec3::Y).length() > 0.999);
    }

    #[test]
    fn bad_indices_are_refused_and_the_last_good_state_kept() {
        let mut state = ExplorerState::default();
        let before = state.clone();
        for bad in [f64::NAN, 0.0, -1.5, f64::INFINITY] {
            assert!(state.set_mu_t(bad).is_err());
            assert_eq!(state, before);
        }
        let err = state
            .set_vectors(DVec3::ZERO, DVec3::Y)
            .unwrap_err()
            .to_string();
        assert_eq!(err, "w is the zero vector, which has no direction");
        assert_eq!(state, before);
    }

    #[test]
    fn switching_convention_turns_w_around_but_keeps_t() {
        let mut state = ExplorerState::default();
        let t = state.refraction().t().unwrap();
        let w = state.w();
        state.set_convention(Convention::TowardOrigin);
        assert_eq!(state.w(), -w);
        assert!((state.refraction().t().unwrap() - t).length() < 1e-15);
    }

    #[test]
    fn rotating_and_pointing_move_w_in_the_plane() {
        let mut state = ExplorerState::default();
        state.point(HandleId::W, DVec2::new(0.0, -1.0));
        assert!(state.refraction().cos_i > 1.0 - 1e-15);
        state.rotate(HandleId::W, 30.0);
        assert!((state.refraction().cos_i - 30_f64.to_radians().cos()).abs() < 1e-12);
        state.rotate(HandleId::N, 90.0);
        assert!(state.n().dot(DVec3::NEG_X) > 1.0 - 1e-12);
        let before = state.clone();
        state.point(HandleId::W, DVec2::ZERO);
        assert_eq!(state, before);
    }

    #[test]
    fn snapping_to_the_critical_angle_gives_a_grazing_ray() {
        let mut state = ExplorerState::default();
        assert!(state.critical_angle().is_none());
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.snap_to_critical_angle();
        let r = state.refraction();
        assert!(!r.is_tir(), "{r:?}");
        assert!(r.transmission.unwrap().cos_t < 1e-4);
        assert!((r.cos_i - (1.0 - 1.0 / 2.25_f64).sqrt()).abs() < 1e-8);
        let tir_after = |degrees| {
            let mut turned = state.clone();
            turned.rotate(HandleId::W, degrees);
            turned.refraction().is_tir()
        };
        assert_ne!(tir_after(1.0), tir_after(-1.0));
    }

    #[test]
    fn every_lesson_shows_what_it_is_named_for() {
        let states = Lesson::ALL.map(Lesson::state);
        let [glass, beyond, normal, brewster, droplet] = &states;
        assert_eq!(glass, &ExplorerState::default());
        assert!(beyond.refraction().is_tir());
        assert!(beyond.critical_angle().unwrap().to_degrees() < 45.0);
        assert!((normal.refraction().cos_i - 1.0).abs() < 1e-15);
        let t = normal.refraction().t().unwrap();
        assert!((t - normal.w()).length() < 1e-12, "nothing bends");
        // At Brewster's angle the reflected and refracted rays are perpendicular.
        let r = brewster.refraction();
        assert!(r.reflected.dot(r.t().unwrap()).abs() < 1e-12);
        assert!(droplet.refraction().normal_flipped && !droplet.refraction().is_tir());
        assert_eq!(droplet.mu_i(), 1.333);
        for (lesson, state) in Lesson::ALL.iter().zip(&states) {
            assert!(!lesson.label().is_empty() && state.refraction().warnings.len() <= 1);
        }
    }

    #[test]
    fn typed_incidence_turns_w_on_its_side_and_bad_angles_change_nothing() {
        let mut state = ExplorerState::default();
        state.set_incidence_degrees(25.0).unwrap();
        assert!((state.incidence_degrees() - 25.0).abs() < 1e-9);
        assert!(state.w().x > 0.0, "still coming from the left");
        state.set_convention(Convention::TowardOrigin);
        state.set_incidence_degrees(60.0).unwrap();
        assert!((state.incidence_degrees() - 60.0).abs() < 1e-9);
        let before = state.clone();
        for bad in [-1.0, 90.0, f64::NAN, 400.0] {
            assert!(state.set_incidence_degrees(bad).is_err());
            assert_eq!(state, before);
        }
        let mut flipped = Lesson::DropletExit.state();
        flipped.set_incidence_degrees(10.0).unwrap();
        assert!((flipped.incidence_degrees() - 10.0).abs() < 1e-9);
    }

    #[test]
    fn huge_and_tiny_vectors_are_drawn_in_their_own_direction() {
        for scale in [1e300, 1e-300, 1e160, 1e-160] {
            let w = DVec3::new(0.6, -0.8, 0.0) * scale;
            let state = ExplorerState::new(w, DVec3::Y * scale, 1.0, 1.5, Convention::AlongRay)
                .expect("a valid state");
            let drawn = state.direction(HandleId::W);
            assert!(
                (drawn - DVec2::new(0.6, -0.8)).length() < 1e-12,
                "{scale:e}: {drawn}"
            );
            assert!(
                (state.direction(HandleId::N) - DVec2::Y).length() < 1e-12,
                "{scale:e}"
            );
        }
    }
}
