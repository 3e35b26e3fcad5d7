"""Mitsuba 3's own `fresnel` and `refract` (scalar_rgb, on the CPU), called over many angles
from both sides of the surface, right and with a student's bug injected in the Python that
calls them: the right calls pass, and each bug is named with its code and its fix."""

import math

import mitsuba as mi
import numpy as np
import pytest

import refraction_check as rc

mi.set_variant("scalar_rgb")

import mitsuba_calls as calls  # noqa: E402 (needs the variant set)

SIDES = dict(inside=calls.INSIDE, outside=calls.OUTSIDE)


def check(wi, wo, **fields):
    """The calls as a student logs them: wi, the BSDF's eta and wo (None where it reflected)."""
    return rc.check(api="mitsuba", wi=wi, eta=calls.ETA, wo=wo, **SIDES, **fields)


def entering(wi):
    return [mi.Frame3f.cos_theta(w) > 0 for w in wi]


def test_mitsubas_own_calls_are_right_at_every_angle_from_both_sides():
    wi, wo = calls.calls(calls.right)
    assert len(wi) == 288
    assert any(w is None for w in wo), "rays from inside past the critical angle reflect"
    r = check(wi, wo)
    assert r.ok.all(), r
    assert r.verdict == "none"
    assert set(r.codes) == {"ok"}
    assert r.summary["diagnosis"][0]["code"] == "none"
    assert r.summary["judged"] == 288


def test_mitsubas_own_calls_pass_with_entering_and_travel_logged_too():
    wi, wo = calls.calls(calls.right)
    travel = [-w for w in wi]
    r = check(wi, wo, entering=entering(wi), travel=travel)
    assert r.ok.all() and r.verdict == "none", r


def test_the_smooth_dielectric_bsdf_sampled_is_right():
    wi, wo = calls.sampled({"type": "dielectric", "int_ior": calls.INSIDE, "ext_ior": calls.OUTSIDE})
    r = check(wi, wo)
    assert r.verdict == "none", r
    assert r.ok.all(), r
    assert r.summary["sampled"] > 0, "it sampled reflections, read as such"
    assert r.tally.get("reflected (sampled)", 0) == r.summary["sampled"]


BOTH, INSIDE = ("outside", "inside"), ("inside",)

#: Each student's bug, the code that names it, words its fix must say, and the sides of the
#: surface whose rays it makes wrong (a bug in the ratio's choice is only seen from inside).
BUGS = [
    (calls.ratio_inverted, "eta_inverted", ["upside down", "fresnel"], BOTH),
    (calls.eta_it_for_eta_ti, "eta_inverted", ["across N", "refract"], BOTH),
    (calls.other_root, "other_root", ["other root", "fresnel"], BOTH),
    (calls.across_sign_lost, "across_sign", ["across N", "refract"], BOTH),
    (calls.side_lost, "no_flip_inside", ["inside", "invert the ratio"], INSIDE),
    (calls.no_reflection_test, "missed_tir", ["critical angle", "fresnel"], INSIDE),
]


@pytest.mark.parametrize("student, code, fix, sides", BUGS, ids=[b[0].__name__ for b in BUGS])
def test_each_bug_in_the_calling_code_is_named_with_its_fix(student, code, fix, sides):
    wi, wo = calls.calls(student)
    r = check(wi, wo)
    verdict = r.summary["diagnosis"][0]
    assert verdict["code"] == code, r
    assert r.verdict == code
    for words in fix:
        assert words in verdict["fix"], verdict["fix"]
    # In the Python call's words, not Mitsuba's C++ (fresnel.h, Dr.Jit's C++ functions).
    for cpp in ("dr::", "Float ", "fresnel.h", "si.wi"):
        assert cpp not in verdict["fix"], verdict["fix"]
    assert not r.ok.all()
    assert verdict["lines"] == (~r.ok).sum(), "the one bug explains every wrong call"
    assert len(r.summary["diagnosis"]) == 1, r
    inside = np.array([mi.Frame3f.cos_theta(w) < 0 for w in wi])
    for side, rays in (("outside", ~inside), ("inside", inside)):
        wrong = (~r.ok[rays]).sum()
        assert (wrong > 0) == (side in sides), f"{wrong} wrong calls from {side}"


def test_a_bug_confined_to_rays_from_inside_says_so():
    wi, wo = calls.calls(calls.normal_turned_to_the_ray)
    r = check(wi, wo, n=[0, 0, 1])
    verdict = r.summary["diagnosis"][0]
    assert verdict["code"] == "eta_inverted", r
    assert "from inside" in verdict["where"] and "none from outside" in verdict["where"], verdict
    inside = np.array([mi.Frame3f.cos_theta(w) < 0 for w in wi])
    assert r.ok[~inside].all(), "rays from outside are right"
    assert not r.ok[inside].any(), "every ray from inside is wrong"


def test_the_normal_turned_to_the_ray_and_logged_is_named_with_entering():
    wi = list(calls.directions())
    wo = [calls.normal_turned_to_the_ray(w) for w in wi]
    n = [calls.facing(w) for w in wi]
    r = check(wi, wo, n=n, entering=entering(wi))
    verdict = r.summary["diagnosis"][0]
    named = [verdict["code"]] + verdict.get("alike", [])
    assert "normal_not_facing" in named, verdict
    assert verdict["code"] != "none"


def test_the_rays_direction_passed_for_wi_is_named_with_travel_and_entering():
    wi = [-w for w in calls.directions()]  # ray.d, where wi points back along the ray
    wo = [calls.right(d) for d in wi]
    r = check(wi, wo, travel=wi, entering=[mi.Frame3f.cos_theta(d) < 0 for d in wi])
    assert r.verdict == "incident_reversed", r
    assert not r.ok.any()


def test_a_scene_with_the_indices_swapped_is_named_from_the_bsdfs_samples():
    wi, wo = calls.sampled({"type": "dielectric", "int_ior": calls.OUTSIDE, "ext_ior": calls.INSIDE})
    r = check(wi, wo)
    assert r.verdict == "eta_inverted", r
    assert not r.ok.all()


def test_a_fresnel_that_never_transmits_is_not_passed_as_sampled_reflections():
    # Every call reflects (wo None), also where F is 4 %: each is a sampled reflection on its
    # own, but not all of them together.
    wi = list(calls.directions())
    r = check(wi, [None] * len(wi))
    # Never, at any angle: the cosine's sign in the Fresnel term, not the test for total
    # internal reflection.
    assert r.verdict == "fresnel_cos_sign", r
    assert not r.ok.all()


def test_numpy_arrays_from_mitsubas_vectors_are_read_as_the_lists_are():
    wi, wo = calls.calls(calls.other_root)
    as_lists = check(wi, wo)
    wi_array = np.array(wi, dtype=np.float32)
    wo_array = np.array([w if w is not None else [math.nan] * 3 for w in wo], dtype=np.float32)
    as_arrays = check(wi_array, wo_array)
    assert as_arrays.summary == as_lists.summary
    assert list(as_arrays.codes) == list(as_lists.codes)


def llvm_variant():
    """Mitsuba's vectorised CPU variant, where the machine has the LLVM library it needs."""
    try:
        mi.set_variant("llvm_ad_rgb")
    except Exception as e:  # noqa: BLE001 (Mitsuba says why in its own exception types)
        pytest.skip(f"Mitsuba's llvm_ad_rgb variant cannot start here: {e}")


def test_drjit_arrays_of_a_vectorised_variant_are_read_lane_by_lane():
    wi_rows = np.array(list(calls.directions()), dtype=np.float32)
    llvm_variant()
    try:
        import drjit as dr

        wi = mi.Vector3f(wi_rows[:, 0], wi_rows[:, 1], wi_rows[:, 2])
        F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), calls.ETA)
        nothing = mi.Vector3f(dr.nan, dr.nan, dr.nan)
        wo = dr.select(F < 1, mi.refract(wi, cos_theta_t, eta_ti), nothing)
        assert np.asarray(wi).shape == (3, len(wi_rows)), "Dr.Jit's vectors come components first"
        r = check(wi, wo)
        assert r.verdict == "none" and r.ok.all(), r
        assert len(r) == len(wi_rows)
        F, cos_theta_t, eta_it, eta_ti = mi.fresnel(mi.Frame3f.cos_theta(wi), 1 / calls.ETA)
        wo = dr.select(F < 1, mi.refract(wi, cos_theta_t, eta_ti), nothing)
        assert check(wi, wo).verdict == "eta_inverted"
    finally:
        mi.set_variant("scalar_rgb")


def test_a_fix_is_in_the_script_s_words_unless_mitsuba_s_cpp_is_asked_for():
    wi, wo = calls.calls(calls.other_root)
    script = check(wi, wo).summary["diagnosis"][0]["fix"]
    assert "mi.refract(wi, cos_theta_t, eta_ti)" in script, script
    cpp = check(wi, wo, renderer="mitsuba").summary["diagnosis"][0]["fix"]
    assert "dr::mulsign_neg(cos_theta_t_abs, cos_theta_i)" in cpp, cpp
