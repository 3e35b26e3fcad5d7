"""The bug in a renderer's refraction, named from its calls held in arrays.

``check`` judges each call of a renderer's refraction (Mitsuba 3's ``fresnel`` and
``refract``, GLSL's ``refract``, pbrt-v4's ``Refract``, Ray Tracing in One Weekend's
``refract``, or any renderer's own formula) and diagnoses all of them as one log: the one
mistake in the code that explains the wrong calls, and its fix in the code's own terms. It
is refraction-explorer's ``check`` command, the same code, without a log in between::

    import refraction_check as rc
    r = rc.check(api="mitsuba", wi=wi, eta=1.5, wo=wo, inside=1.5, outside=1.0)
    r.ok        # numpy bool array, one per call
    r.codes     # one code per call, as `check` prints them
    r.summary   # the dict `check --summary` writes; r.summary["diagnosis"][0]["fix"]
"""

from ._native import Checked, __version__, check

__all__ = ["Checked", "check", "__version__"]
