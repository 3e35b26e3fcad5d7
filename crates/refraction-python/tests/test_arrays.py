"""What `check` takes and gives in Python: NumPy arrays, lists, objects numpy reads (as torch
tensors on the CPU are), rows that logged nothing, bad shapes and types refused by name, and
the same answers and summary as the `check` command on the same calls."""

import json
import math
import os
import subprocess

import numpy as np
import pytest

import refraction_check as rc

NAN = math.nan


def glsl_refract(I, N, eta):
    """GLSL's refract(I, N, eta) row by row (the GLSL spec's formula), zero past the critical
    angle."""
    cos = np.sum(N * I, axis=-1, keepdims=True)
    k = 1.0 - eta**2 * (1.0 - cos**2)
    t = eta * I - (eta * cos + np.sqrt(np.maximum(k, 0.0))) * N
    return np.where(k < 0.0, 0.0, t)


def entering_glass(count=50, dtype=np.float64):
    """GLSL calls for rays entering glass of 1.5 from air at `count` angles: I, N, eta."""
    theta = (np.arange(count) + 0.5) / count * (np.pi / 2)
    I = np.stack([np.sin(theta), -np.cos(theta), np.zeros(count)], axis=1).astype(dtype)
    N = np.tile(np.array([0.0, 1.0, 0.0], dtype=dtype), (count, 1))
    return I, N, dtype(1.0 / 1.5)


def test_numpy_arrays_and_one_value_for_every_call():
    I, N, eta = entering_glass()
    result = glsl_refract(I, N, eta)
    r = rc.check(api="glsl", I=I, N=[0, 1, 0], eta=eta, result=result, entering=True, inside=1.5, outside=1.0)
    assert len(r) == 50
    assert r.ok.dtype == np.bool_ and r.ok.shape == (50,)
    assert r.ok.all() and r.verdict == "none", r
    wrong = glsl_refract(I, N, 1.5)  # eta upside down
    r = rc.check(api="glsl", I=I, N=N, eta=1.5, result=wrong, entering=np.ones(50, bool), inside=1.5, outside=1.0)
    assert r.verdict == "eta_inverted", r
    assert r.summary["diagnosis"][0]["code"] == "eta_inverted"
    assert "upside down" in r.summary["diagnosis"][0]["fix"]
    assert set(r.codes) <= {"eta_inverted", "missed_tir"}, r.codes
    assert all("eta_inverted" in m for m in r.mistakes if m)


def test_lists_and_tuples_are_read_as_arrays_and_a_single_call_as_one():
    I, N, eta = entering_glass(4)
    result = glsl_refract(I, N, eta)
    as_lists = rc.check(api="glsl", I=I.tolist(), N=tuple(N[0]), eta=float(eta), result=[tuple(t) for t in result], entering=[1, 1, 1, 1], inside=1.5, outside=1.0)
    as_arrays = rc.check(api="glsl", I=I, N=N, eta=eta, result=result, entering=True, inside=1.5, outside=1.0)
    assert as_lists.summary == as_arrays.summary
    one = rc.check(api="glsl", I=list(I[0]), N=[0, 1, 0], eta=eta, result=list(result[0]), entering=True, inside=1.5, outside=1.0)
    assert len(one) == 1 and one.ok[0], one


def test_none_and_nan_rows_logged_nothing_as_null_does():
    wi = [[0.6, 0.0, 0.8], [0.0, 0.0, 1.0], [0.8, 0.0, -0.6]]
    right = [[-0.4, 0.0, -math.sqrt(0.84)], [0.0, 0.0, -1.0], None]  # past the critical angle
    with_none = rc.check(api="mitsuba", wi=wi, eta=1.5, wo=right, inside=1.5, outside=1.0)
    with_nan = rc.check(api="mitsuba", wi=np.array(wi), eta=1.5, wo=np.array([r or [NAN] * 3 for r in right]), inside=1.5, outside=1.0)
    assert with_none.summary == with_nan.summary
    assert with_none.ok.all(), with_none
    assert with_none.answers[2]["t"] is None, "total internal reflection: no T"
    # GLSL's result cannot be null: a row of NaN there is a call without its result.
    I, N, eta = entering_glass(3)
    result = glsl_refract(I, N, eta)
    result[1] = NAN
    r = rc.check(api="glsl", I=I, N=N, eta=eta, result=result, entering=True, inside=1.5, outside=1.0)
    assert list(r.codes) == ["ok", "unreadable", "ok"]
    assert r.answers[1] is None and "result" in r.errors[1], r.errors
    assert r.errors[0] is None and not r.ok[1]
    # A vector with one NaN component is a vector that is not finite, as [0.1, null, 0] is.
    I[2, 1] = NAN
    r = rc.check(api="glsl", I=I, N=N, eta=eta, result=glsl_refract(I, N, eta), entering=True, inside=1.5, outside=1.0)
    assert r.codes[2] == "unreadable" and "I" in r.errors[2], r.errors


class ArrayLike:
    """An object numpy reads through `__array__`, as it reads torch's CPU tensors."""

    def __init__(self, values):
        self.values = np.asarray(values)

    def __array__(self, dtype=None, copy=None):
        return self.values if dtype is None else self.values.astype(dtype)


def test_objects_numpy_reads_are_taken_as_their_arrays():
    I, N, eta = entering_glass(5)
    result = glsl_refract(I, N, eta)
    r = rc.check(api="glsl", I=ArrayLike(I), N=ArrayLike(N), eta=eta, result=ArrayLike(result), entering=True, inside=1.5, outside=1.0)
    assert r.ok.all() and len(r) == 5, r


def test_torch_tensors_on_the_cpu():
    torch = pytest.importorskip("torch", reason="torch is not installed (it is not on the CI's list)")
    I, N, eta = entering_glass(5, np.float32)
    result = glsl_refract(I, N, eta)
    r = rc.check(api="glsl", I=torch.from_numpy(I), N=torch.from_numpy(N), eta=torch.tensor(eta), result=torch.from_numpy(result), entering=True, inside=1.5, outside=1.0)
    assert r.ok.all(), r


def rtiow_refract_f32(count=300):
    """Ray Tracing in One Weekend's refract(uv, n, etai_over_etat) ported to float32 (as a
    Rust or shader port runs it), for random rays entering glass: uv, n, ratio, refracted."""
    d = np.random.default_rng(1).normal(size=(count, 3)).astype(np.float32)
    d[:, 1] = -np.abs(d[:, 1])
    uv = d / np.linalg.norm(d, axis=1, keepdims=True)
    n = np.tile(np.float32([0, 1, 0]), (count, 1))
    ratio = np.float32(1 / 1.5)
    cos = np.minimum(np.sum(-uv * n, axis=1, keepdims=True), np.float32(1))
    perp = ratio * (uv + cos * n)
    parallel = -np.sqrt(np.abs(np.float32(1) - np.sum(perp * perp, axis=1, keepdims=True))) * n
    return uv, n, ratio, perp + parallel


def test_float32_arrays_are_judged_at_float32():
    # The book's code is double; a float32 port judged at f64 is wrong on every line (the
    # inputs are unit length only to float32's precision). The arrays' dtype says float32.
    uv, n, ratio, refracted = rtiow_refract_f32()
    book = dict(api="rtiow", uv=uv, n=n, etai_over_etat=ratio, refracted=refracted, entering=True, inside=1.5, outside=1.0)
    r = rc.check(**book)
    assert r.ok.all() and r.verdict == "none", r
    assert not rc.check(**book, precision="f64").ok.any()
    wide = {k: v.astype(np.float64) if isinstance(v, np.ndarray) else v for k, v in book.items()}
    assert rc.check(**wide, precision="f32").summary == r.summary


@pytest.mark.parametrize(
    "arguments, named, said",
    [
        (dict(wi=np.zeros((4, 2))), "wi", "(4, 2)"),
        (dict(wi=np.zeros((2, 3, 1))), "wi", "(2, 3, 1)"),
        (dict(wi=1.0), "wi", "()"),
        (dict(eta=np.ones((4, 3))), "eta", "(4, 3)"),
        (dict(wi=np.zeros((4, 3)), wo=np.zeros((5, 3))), "wo", "5 rows"),
        (dict(wi=np.zeros((0, 3))), "wi", "no rows"),
        (dict(wi="0 0 1"), "wi", "numbers"),
        (dict(wi=np.zeros((4, 3), complex)), "wi", "numbers"),
        (dict(wi=[[0, 0, 1], "up"]), "wi", "numbers"),
        (dict(wi={"x": 1}), "wi", "numbers"),
        (dict(entering=[1, 0, 2]), "entering", "row 2"),
        (dict(wt=np.zeros((4, 3))), "wt", "wi, n, eta, wo"),
        (dict(inside=1.5), "outside", "both"),
        (dict(inside=-1.0, outside=1.0), "inside", "-1"),
        (dict(inside="glass", outside=1.0), "inside", "glass"),
        (dict(normal="+z"), "normal", "api=None"),
        (dict(renderer="blender3"), "renderer", "tungsten"),
        (dict(precision="half"), "precision", "f32"),
    ],
)
def test_bad_arguments_raise_value_error_naming_them(arguments, named, said):
    calls = dict(wi=np.tile([0.6, 0.0, 0.8], (4, 1)), eta=1.5, wo=np.tile([-0.4, 0.0, -0.9165], (4, 1)))
    calls.update(arguments)
    with pytest.raises(ValueError) as refused:
        rc.check(api="mitsuba", **calls)
    message = str(refused.value)
    assert named in message and said in message, message


def test_other_keywords_and_apis_are_refused_by_name():
    with pytest.raises(ValueError, match="optix"):
        rc.check(api="optix", wi=[0, 0, 1])
    with pytest.raises(ValueError, match="unknown argument `wi` for api=None"):
        rc.check(wi=[0, 0, 1])
    with pytest.raises(ValueError, match="normal must be"):
        rc.check(normal=[0, 0, 0], w=[0, 0, 1])
    with pytest.raises(ValueError, match="wo"):
        rc.check(api="mitsuba", wi=[[0.6, 0.0, 0.8]] * 3, eta=1.5)  # wo left out


def test_from_is_from_underscore_and_the_books_front_face_is_entering():
    I, N, eta = entering_glass(3)
    t = glsl_refract(I, N, eta)
    spelt = rc.check(w=I, n=N, from_=1.0, to=1.5, t_yours=t)
    given = rc.check(w=I, n=N, **{"from": 1.0, "to": 1.5}, t_yours=t)
    assert spelt.summary == given.summary and spelt.ok.all()
    book = rc.check(api="rtiow", uv=I, n=N, etai_over_etat=eta, refracted=t, front_face=True, inside=1.5, outside=1.0)
    assert book.ok.all() and book.verdict == "none", book


def test_normal_and_convention_read_a_local_frames_log():
    # Tungsten's log: wi toward where the ray came from, the local frame's +z as the normal.
    wi = np.array([[0.6, 0.0, 0.8], [0.6, 0.0, -0.8]])
    right = [[-0.4, 0.0, -math.sqrt(0.84)], None]
    r = rc.check(normal="+z", convention="toward-origin", inside=1.5, outside=1.0, w=wi, t_yours=right)
    assert r.ok.all() and r.verdict == "none", r
    per_call = rc.check(normal=[0, 0, 1], convention=["toward_origin", "toward_origin"], inside=1.5, outside=1.0, w=wi, t_yours=right)
    assert per_call.summary == r.summary


def test_repr_and_the_notebook_table_show_the_tally_and_the_bug():
    I, N, eta = entering_glass(10)
    r = rc.check(api="glsl", I=I, N=N, eta=1.5, result=glsl_refract(I, N, 1.5), entering=True, inside=1.5, outside=1.0)
    text = repr(r)
    assert text.splitlines()[0] == "10 calls, 0 right", text
    assert "The bug: eta_inverted" in text
    assert r.diagnosis[0] in text
    html = r._repr_html_()
    assert html.startswith("<div>") and html.count("<table>") == 2, html
    assert "eta_inverted" in html and "The first 5 of 10 wrong calls" in html
    assert sum(r.tally.values()) == 10


def explorer():
    """The `check` command's program, when the environment names it (CI does)."""
    path = os.environ.get("REFRACTION_EXPLORER")
    if not path:
        pytest.skip("REFRACTION_EXPLORER (the built refraction-explorer) is not set")
    return path


def test_the_summary_and_answers_are_those_of_the_check_command(tmp_path):
    program = explorer()
    I, _, _ = entering_glass(30)
    leaving = np.arange(30) % 2 == 1
    I[leaving, 1] *= -1  # these travel up, out of the glass below y = 0
    N = np.tile([0.0, 1.0, 0.0], (30, 1))  # the student's bug: the outward normal for every ray
    eta = np.where(leaving, 1.5, 1 / 1.5)
    result = glsl_refract(I, N, eta[:, None])
    entering = ~leaving
    r = rc.check(api="glsl", I=I, N=N, eta=eta, result=result, entering=entering, inside=1.5, outside=1.0)
    lines = [
        json.dumps({"I": list(i), "N": list(n), "eta": e, "result": list(t), "entering": bool(g)})
        for i, n, e, t, g in zip(I.tolist(), N.tolist(), eta.tolist(), result.tolist(), entering)
    ]
    log = tmp_path / "calls.jsonl"
    log.write_text("\n".join(lines) + "\n")
    summary = tmp_path / "summary.json"
    done = subprocess.run(
        [program, "check", "--api", "glsl", "--inside", "1.5", "--outside", "1", "--summary", str(summary), str(log)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == (0 if r.ok.all() else 1), done.stderr
    assert json.loads(summary.read_text()) == r.summary
    assert [json.loads(a) for a in done.stdout.splitlines()] == r.answers
    assert r.verdict != "none", r
