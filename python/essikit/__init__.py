"""essikit: check, trace and convert ESSI (ISO 6582) and EIA cutting tapes from Python.

    import essikit
    report = essikit.check("part.esi", profile="woyda")      # the report of `essi check --format json`, as a dict
    lines = essikit.trace("part.esi", kerf=True)             # the motion records of `essi trace`, one a string
    gcode = essikit.convert("part.esi", to="gcode")          # the text of `essi convert`

A tape is a path (str or os.PathLike) or its bytes. `profile` is a built-in name (essikit.profiles()), "auto", or a
path to a JSON profile file; `input` is "essi", "eia" or None (from the content); `lang` "en", "de" or "zh".
A profile or argument that cannot be used, and a conversion of a tape with errors, raise essikit.Error with the
diagnostics (dicts, as in the report).
"""
import json
import os

from . import _essikit

__all__ = ["Error", "check", "trace", "convert", "profiles"]


class Error(Exception):
    """What went wrong, and the diagnostics (a list of dicts as in the JSON report) when there are some."""

    def __init__(self, message, diagnostics=None):
        super().__init__(message)
        self.diagnostics = diagnostics or []


def _tape(path_or_bytes):
    if isinstance(path_or_bytes, (bytes, bytearray, memoryview)):
        return bytes(path_or_bytes), "-"
    path = os.fspath(path_or_bytes)
    with open(path, "rb") as f:
        return f.read(), path


def _profile(profile):
    """(built-in name or "auto" or "", a profile file's text or "")"""
    if profile is None:
        return "", ""
    if profile == "auto" or profile in _essikit.profiles():
        return profile, ""
    try:
        with open(os.fspath(profile), "r", encoding="utf-8") as f:
            return "", f.read()
    except OSError as e:
        raise Error(f"unknown profile {profile!r}: not a built-in profile ({', '.join(_essikit.profiles())}, auto) "
                    f"and not a readable profile file ({e.strerror})") from None


def _call(fn, *args):
    try:
        return fn(*args)
    except _essikit.SetupError as e:
        message, diagnostics = e.args
        raise Error(message, json.loads(diagnostics)) from None


def check(path_or_bytes, profile=None, lang=None, input=None):
    """The report of `essi check --format json` for one tape, as a dict: {"files": [...], "summary", "profile"}."""
    data, name = _tape(path_or_bytes)
    name_, text = _profile(profile)
    return json.loads(_call(_essikit.check, data, name, name_, text, input or "", lang or ""))


def trace(path_or_bytes, profile=None, input=None, decimals=3, kerf=False, machine=False):
    """The motion records of `essi trace` (with kerf: the compensated path; machine: on the machine), one a string."""
    data, _ = _tape(path_or_bytes)
    name_, text = _profile(profile)
    return _call(_essikit.trace, data, name_, text, input or "", decimals, kerf, machine)


def convert(path_or_bytes, to="gcode", profile=None, input=None, absolute=False, force=False, lang=None):
    """The tape written as `to` ("essi", "eia" or "gcode"), as `essi convert` writes it. A tape with an error raises
    Error with the diagnostics, unless force."""
    data, _ = _tape(path_or_bytes)
    name_, text = _profile(profile)
    out, diagnostics, refused = _call(_essikit.convert, data, to, name_, text, input or "", absolute, force, lang or "")
    if refused:
        raise Error("the tape has errors; nothing was converted (force=True converts it)", json.loads(diagnostics))
    return out


def profiles():
    """The built-in profiles' names."""
    return list(_essikit.profiles())
