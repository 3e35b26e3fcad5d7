"""The Mitsuba 3 examples of docs/python.md run as they are written and print what the page
says they print: each script (a block that sets Mitsuba's variant, with the block after it
that continues it) runs in a Python of its own, as a reader pastes it into a file."""

import pathlib
import re
import subprocess
import sys

import pytest

PAGE = pathlib.Path(__file__).resolve().parents[3] / "docs" / "python.md"


def blocks():
    """The page's code blocks, in order: (language, text)."""
    return re.findall(r"```(\w+)\n(.*?)```", PAGE.read_text(encoding="utf-8"), re.S)


def scripts():
    """Each whole script of the page, with the text block that follows it (its output, where
    the page shows it)."""
    found = []
    for language, text in blocks():
        if language == "python" and "mi.set_variant(" in text:
            found.append([text, None])
        elif language == "python" and found and text.startswith("def "):
            found[-1][0] += "\n" + text  # the same session, continued
        elif language == "text" and found and found[-1][1] is None:
            found[-1][1] = text
    return found


def run(script):
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    if "llvm_ad_rgb" in script and done.returncode != 0 and "LLVM" in done.stderr:
        pytest.skip(f"Mitsuba's llvm_ad_rgb variant cannot start here: {done.stderr[-300:]}")
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_page_has_its_three_examples():
    assert len(scripts()) == 3, [s[:60] for s, _ in scripts()]


def test_the_right_calls_pass_and_the_students_other_root_is_named():
    script, shown = scripts()[0]
    printed = run(script).splitlines()
    assert printed[:2] == ["none True", "other_root"], printed
    # The page shows repr(r) of the student's calls, wrapped: the same words.
    assert " ".join(printed[2:]).split() == " ".join(shown.splitlines()).split()


def test_the_bsdfs_own_samples_print_what_the_page_shows():
    script, shown = scripts()[1]
    assert run(script) == shown


def test_drjit_lanes_of_a_vectorised_variant():
    script, _ = scripts()[2]
    assert run(script) == "100 none\n"
