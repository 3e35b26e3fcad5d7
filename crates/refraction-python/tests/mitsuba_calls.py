"""Students' calls of Mitsuba 3's own `fresnel` and `refract`, right and with one bug each.

Mitsuba's conventions, read in its source (include/mitsuba/render/fresnel.h, functions
`fresnel` and `refract`; their caller `SmoothDielectric::sample` in src/bsdfs/dielectric.cpp):

- the local frame's z axis is the shading normal, the shape's outward one (never turned toward
  the ray), so `wi.z < 0` for a ray arriving from inside;
- `wi` points away from the surface, back where the ray came from;
- `eta = int_ior / ext_ior`, the index behind the normal over the one in front;
- `fresnel(cos_theta_i, eta)` returns `(F, cos_theta_t, eta_it, eta_ti)`: it picks the side
  from the sign of `cos_theta_i` (`eta_ti = 1/eta` outside, `eta` inside); `cos_theta_t`
  carries the side the ray goes to (negative for a ray entering); past the critical angle
  `cos_theta_t = 0` and F = 1;
- `refract(wi, cos_theta_t, eta_ti) = (-eta_ti*wi.x, -eta_ti*wi.y, cos_theta_t)`, and
  `refract(wi, m, cos_theta_t, eta_ti)` refracts about a normal `m`;
- the BSDF reflects with probability F, so a log says `None` where it reflected.
"""

import math

import drjit as dr
import mitsuba as mi

#: The glass's int_ior / ext_ior: glass of 1.5 in air.
INSIDE, OUTSIDE = 1.5, 1.0
ETA = INSIDE / OUTSIDE


def directions(angles=48, azimuths=(0.3, 2.0, 4.4)):
    """`wi` at `angles` angles of incidence from 0 to 90 degrees (never exactly either), at
    each azimuth, from outside (z > 0) and from inside (z < 0): 2 * angles * len(azimuths)
    unit vectors of Mitsuba's local frame."""
    for side in (1.0, -1.0):
        for i in range(angles):
            theta = (i + 0.5) / angles * math.pi / 2
            for phi in azimuths:
                s = math.sin(theta)
                yield mi.Vector3f(s * math.cos(phi), s * math.sin(phi), side * math.cos(theta))


def right(wi):
    """A right call, as SmoothDielectric::sample makes it: the refracted direction, or None
    where F = 1 (total internal reflection) and it can only reflect."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), ETA)
    return mi.refract(wi, cos_theta_t, eta_ti) if F < 1 else None


def ratio_inverted(wi):
    """The ratio upside down: the exterior index over the interior one."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), 1 / ETA)
    return mi.refract(wi, cos_theta_t, eta_ti) if F < 1 else None


def eta_it_for_eta_ti(wi):
    """fresnel's third value passed where refract takes its fourth."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), ETA)
    return mi.refract(wi, cos_theta_t, eta_it) if F < 1 else None


def other_root(wi):
    """cos_theta_t with its sign turned: the other root, T left in its medium."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), ETA)
    return mi.refract(wi, -cos_theta_t, eta_ti) if F < 1 else None


def across_sign_lost(wi):
    """refract written out by hand without the minus before eta_ti * wi."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), ETA)
    return mi.Vector3f(eta_ti * wi.x, eta_ti * wi.y, cos_theta_t) if F < 1 else None


def side_lost(wi):
    """The cosine's sign dropped (abs), so fresnel takes every ray for one from outside."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(abs(mi.Frame3f.cos_theta(wi)), ETA)
    return mi.refract(wi, cos_theta_t, eta_ti) if F < 1 else None


def no_reflection_test(wi):
    """The refracted direction used past the critical angle too (F = 1 not tested)."""
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), ETA)
    return mi.refract(wi, cos_theta_t, eta_ti)


OUTWARD = mi.Vector3f(0, 0, 1)


def facing(wi):
    """The normal turned toward the ray, as GLSL code does: the outward one, or its opposite
    for a ray from inside."""
    return OUTWARD if mi.Frame3f.cos_theta(wi) > 0 else -OUTWARD


def normal_turned_to_the_ray(wi):
    """refract about the normal turned toward the ray: fresnel never sees a ray from
    inside, so those rays refract with the ratio upside down."""
    m = facing(wi)
    F, cos_theta_t, eta_it, eta_ti = mi.fresnel(dr.dot(wi, m), ETA)
    return mi.refract(wi, m, cos_theta_t, eta_ti) if F < 1 else None


def calls(student, **fields):
    """`wi` and what `student` gave for each direction, as lists (None where it gave none)."""
    wi = list(directions(**fields))
    return wi, [student(w) for w in wi]


def sampled(bsdf_dict, seed=7):
    """The smooth dielectric BSDF's own samples (`bsdf.sample`) for each direction, with a
    fixed sequence of random numbers: `wi` and `wo`, None where it sampled reflection."""
    import numpy as np

    bsdf = mi.load_dict(bsdf_dict)
    ctx = mi.BSDFContext()
    numbers = np.random.default_rng(seed)
    wi, wo = [], []
    for w in directions():
        si = mi.SurfaceInteraction3f()
        si.wi = w
        bs, _ = bsdf.sample(ctx, si, float(numbers.random()), mi.Point2f(0.5, 0.5))
        transmitted = mi.has_flag(bs.sampled_type, mi.BSDFFlags.DeltaTransmission)
        wi.append(w)
        wo.append(bs.wo if transmitted else None)
    return wi, wo
