"""The Python module essikit, installed with pip from ./python (tests/python/run.sh), gives what `essi` gives:
the same report for every example, the same trace and conversion, and essikit.Error where essi refuses."""
import json
import os
import subprocess

import pytest

import essikit

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, "examples")
ESSI = os.environ["ESSI_BIN"]
TAPES = sorted(os.path.join(EXAMPLES, f) for f in os.listdir(EXAMPLES) if f.endswith((".esi", ".eia")))


def essi(*args):
    return subprocess.run([ESSI, *args], capture_output=True, text=True, env={**os.environ, "LANG": "C.UTF-8"})


@pytest.mark.parametrize("tape", TAPES, ids=os.path.basename)
def test_check_gives_the_report_of_essi_check(tape):
    want = json.loads(essi("check", "--format", "json", "--profile", "auto", tape).stdout)
    assert essikit.check(tape, profile="auto") == want  # (the JSON report has no timing fields)


def test_bytes_profiles_and_languages():
    tape = os.path.join(EXAMPLES, "bad_arc_off_circle.esi")
    data = open(tape, "rb").read()
    report = essikit.check(data, profile="woyda", lang="de")
    assert report["profile"] == "woyda" and report["files"][0]["path"] == "-"
    assert report["files"][0]["ok"] is False
    want = json.loads(subprocess.run([ESSI, "check", "--format", "json", "--profile", "woyda", "--lang", "de", "-"],
                                     input=data, capture_output=True).stdout)
    assert report == want
    assert set(essikit.profiles()) == {"iso6582", "woyda", "hypertherm", "din66025"}


def test_a_profile_file():
    profile = os.path.join(EXAMPLES, "plan_table.profile.json")
    tape = os.path.join(EXAMPLES, "plan_table.esi")
    want = json.loads(essi("check", "--format", "json", "--profile", profile, tape).stdout)
    assert essikit.check(tape, profile=profile) == want


def test_trace_and_convert_are_essis():
    tape = os.path.join(EXAMPLES, "kerf_parts.esi")
    assert essikit.trace(tape, kerf=True) == essi("trace", "--kerf", tape).stdout.splitlines()
    assert essikit.convert(tape, to="gcode", absolute=True) == essi("convert", "--to", "gcode", "--absolute", tape).stdout


def test_errors_raise_essikit_error_with_the_diagnostics():
    with pytest.raises(essikit.Error) as e:
        essikit.convert(os.path.join(EXAMPLES, "bad_kerf_gouge.esi"))
    assert [d["code"] for d in e.value.diagnostics if d["severity"] == "error"] == ["E307"]
    assert essikit.convert(os.path.join(EXAMPLES, "bad_kerf_gouge.esi"), force=True).startswith("G17")
    with pytest.raises(essikit.Error, match="unknown profile 'nope'"):
        essikit.check(b"+10+0\n64\n", profile="nope")
    with pytest.raises(essikit.Error, match="expected en, de or zh"):
        essikit.check(b"+10+0\n64\n", lang="fr")
    bad = os.path.join(os.environ.get("TMPDIR", "/tmp"), "essikit_bad_profile.json")
    with open(bad, "w") as f:
        f.write('{"unit_mm": "x"}')
    with pytest.raises(essikit.Error) as e:
        essikit.check(b"+10+0\n64\n", profile=bad)
    assert e.value.diagnostics[0]["code"] == "E402"
    assert "unit_mm" in e.value.diagnostics[0]["message"]
