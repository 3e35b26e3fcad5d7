//! What the explorer shows: W, N, the two indices and the convention, kept valid at all times,
//! with the kernel's answer for them; and the edits a user makes by dragging, nudging and typing.

use glam::{DVec2, DVec3};

use refraction_kernel::{Convention, Incidence, InputError, Refraction, refract};

/// The range of the index scale beside the diagram (dragging stays inside it; typed values
/// may go beyond).
pub const INDEX_RANGE: (f64, f64) = (1.0, 2.6);

/// A named medium for the index presets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Its name as shown.
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

/// The preset with exactly this index, if any.
#[must_use]
pub fn material_of(index: f64) -> Option<Material> {
    MATERIALS.into_iter().find(|m| m.index == index)
}

/// The draggable things on the canvas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HandleId {
    /// The tip of W: sets the incoming direction.
    W,
    /// The tip of N: rotates the surface.
    N,
    /// μ_i's marker on the index scale.
    MuI,
    /// μ_t's marker on the index scale.
    MuT,
}

impl HandleId {
    /// All handles, in keyboard (Tab) order.
    pub const ALL: [Self; 4] = [Self::W, Self::N, Self::MuI, Self::MuT];

    /// The accessible name (what a screen reader says and what tests look for).
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::W => "W handle",
            Self::N => "N handle",
            Self::MuI => "μi handle",
            Self::MuT => "μt handle",
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
    /// W at 40° from the normal, from air into glass, in Section 2's convention.
    fn default() -> Self {
        let angle = 40_f64.to_radians();
        let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
        Self::new(w, DVec3::Y, 1.000293, 1.5, Convention::AlongRay)
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

    /// μ_i, the index of the medium the ray travels in.
    #[must_use]
    pub fn mu_i(&self) -> f64 {
        self.mu_i
    }

    /// μ_t, the index of the medium the ray enters.
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

    /// Sets μ_i.
    ///
    /// # Errors
    /// The kernel's message for an index that is not a finite number > 0; the state is unchanged.
    pub fn set_mu_i(&mut self, mu_i: f64) -> Result<(), InputError> {
        self.update(self.w, self.n, mu_i, self.mu_t, self.convention)
    }

    /// Sets μ_t.
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

    /// The index a μ handle stands for (μ_t for the others).
    #[must_use]
    pub fn index(&self, handle: HandleId) -> f64 {
        if handle == HandleId::MuI {
            self.mu_i
        } else {
            self.mu_t
        }
    }

    /// Switches the convention. The ray stays where it is, so W turns around: that is the
    /// whole difference between the source's two sections.
    pub fn set_convention(&mut self, convention: Convention) {
        if convention != self.convention {
            // −W is as valid as W, so the kernel cannot refuse this.
            let _ = self.update(-self.w, self.n, self.mu_i, self.mu_t, convention);
        }
    }

    /// Turns N around (an outward normal where the ray leaves the medium: the classic bug).
    pub fn flip_normal(&mut self) {
        // −N is as valid as N (the kernel checks finiteness and length, which a sign keeps),
        // so the kernel cannot refuse this.
        let _ = self.update(self.w, -self.n, self.mu_i, self.mu_t, self.convention);
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
        let _ = self.update(w, n, self.mu_i, self.mu_t, self.convention);
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

    /// The critical angle θc in radians (sin θc = μ_t/μ_i), when there is one (μ_i > μ_t).
    #[must_use]
    pub fn critical_angle(&self) -> Option<f64> {
        (self.mu_i > self.mu_t).then(|| (self.mu_t / self.mu_i).asin())
    }

    /// Turns W so that the ray meets the surface at the critical angle, on the side it comes
    /// from now. Does nothing without a critical angle.
    ///
    /// The angle is a nanoradian short of θc: exactly at θc rounding decides between total
    /// reflection and a grazing T, and the class should see T lying along the surface.
    pub fn snap_to_critical_angle(&mut self) {
        let Some(critical) = self.critical_angle() else {
            return;
        };
        let r = &self.refraction;
        let toward_source = self.plane.project(-r.travel);
        let normal = self.plane.project(r.facing_normal).normalize_or(DVec2::Y);
        let side = if normal.perp_dot(toward_source) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let angle = side * (critical - 1e-9);
        let toward_source = DVec2::from_angle(angle).rotate(normal);
        let sign = self.convention.travel_sign::<f64>();
        self.point(HandleId::W, -toward_source * sign);
    }
}

/// `v` divided by its largest component's magnitude (`v` itself when that is 0 or not finite):
/// the same direction with components in [−1, 1], so that squaring them for a cross product or
/// a length neither overflows (|v| above about 1e154) nor underflows (below about 1e−154), as
/// the kernel does before it normalises.
fn scaled(v: DVec3) -> DVec3 {
    let largest = v.abs().max_element();
    // Only outside a safe range, so that ordinary vectors keep their bits.
    if largest.is_finite() && !(1e-100..=1e100).contains(&largest) && largest > 0.0 {
        v / largest
    } else {
        v
    }
}

/// |v| without overflow or underflow in the squares (see [`scaled`]).
fn length(v: DVec3) -> f64 {
    let largest = v.abs().max_element();
    if largest > 0.0 && largest.is_finite() {
        (v / largest).length() * largest
    } else {
        v.length()
    }
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
