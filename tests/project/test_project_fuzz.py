"""Config fuzz (issue 8): malformed project files always give clear messages, never a traceback.

Generated files: random documents over the project's own keys (wrong types, missing and extra keys,
NaN/inf, huge numbers, deep nesting, unicode), valid projects with one value replaced, and valid
projects with random edits (broken TOML).  For each: ``check_project`` returns messages that start
with the file name, ``load_project`` returns a controller or raises ProjectError, and ``plcmotion
check`` exits 0 or 1 with every line on stderr naming the file.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import os
import tempfile
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion.cli import main
from plcmotion.kernel.runtime import Controller
from plcmotion.project import ProjectError, check_project, load_project

KEYS = ["controller", "axes", "trace", "inputs", "command_tables", "cams", "servo_cycle", "app_cycle", "family",
        "technology_version", "state_file", "input_filter", "type", "leading_values", "name", "coupling",
        "Actor", "Type", "Actor.Type", "DynamicLimits", "MaxVelocity", "DynamicLimits.MaxVelocity", "Sensor[1]",
        "ActiveHoming", "Mode", "Plant", "InitialPosition", "Modulo.Enable", "points", "segments", "csv",
        "interpolation_mode", "boundary_conditions", "xmin", "xmax", "a1", "Command", "Position", "Velocity",
        "Duration", "NextStep", "StepCode", "signals", "every", "filter", "A", "B", "Axis_1", "I0.3", "Q0.1",
        "ä", "", " ", "1st", "a.b",
        # [[switches]], [[faults]] and the cycle watchdog (issue 8 defects 6 and 11)
        "switches", "faults", "cycle_watchdog", "cycle_watchdog_stop", "input", "low", "high", "active_high",
        "period", "at", "inject", "detail", "persistent", "load", "clear", "switch", "jump", "force", "blocked"]
WORDS = ["S7-1200", "S7-1500", "S7-1500T", "positioning", "synchronous", "external_encoder",
         "leading_axis_proxy", "setpoint", "actual", "A.Position", "Axis_1.Position", "I0.3", "../x", "/etc/passwd",
         "knife.csv", "x\x00y", "\u202e", "😀", "A", "B",
         "drive", "encoder", "drive_not_ready", "encoder_loss", "communication_loss", "station", "hardware",
         "stuck_actuated", "stuck_released", "chatter", "repair", "all", "load", "I0.2", "I0.5", "M", "S", "E"]

scalars = st.one_of(
    st.integers(-3, 200), st.integers(-2**63, 2**63 - 1), st.sampled_from([0, 1, 2, 5, 7, 151, 10**30, -10**30, 10**400, -10**400]),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([0.0, 1.0, 7.0, 1e-300, 5e-324, 1e300, 1e12]),
    st.booleans(), st.sampled_from(WORDS), st.text(max_size=6),
)
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=4)
                      | st.dictionaries(st.sampled_from(KEYS), inner, max_size=4), max_leaves=24)
documents = st.dictionaries(st.sampled_from(KEYS), values, max_size=6)


def toml(value: Any) -> str:
    """A value as inline TOML (strings as JSON: a few are no valid TOML, which is part of the test)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf") if math.isinf(value) else repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, list):
        return "[" + ", ".join(toml(v) for v in value) + "]"
    return "{ " + ", ".join(f"{json.dumps(k, ensure_ascii=False)} = {toml(v)}" for k, v in value.items()) + " }"


def document(doc: dict[str, Any]) -> str:
    return "".join(f"{json.dumps(k, ensure_ascii=False)} = {toml(v)}\n" for k, v in doc.items())


BASE_1200 = {
    "controller": {"servo_cycle": 0.001, "app_cycle": 0.004, "technology_version": 6, "cycle_watchdog": 50,
                   "cycle_watchdog_stop": False},
    "axes": {"A": {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 100.0}, "Mechanics.LeadScrew": 10.0},
             "B": {"Actor.Type": 2, "Sensor[1]": {"ActiveHoming": {"Mode": 2}}}},
    "command_tables": {"T": {"Command": [{"Type": 5, "Position": 10.0, "Velocity": 5.0},
                                         {"Type": 151, "Duration": 0.5}]}},
    "inputs": {"I0.3": {"filter": 0.0008}},
    "trace": {"signals": ["A.Position", "B.Velocity"], "every": 2},
    "switches": [{"input": "I0.2", "axis": "A", "low": 500.0},
                 {"input": "I0.5", "axis": "B", "low": 100.0, "high": 110.0, "period": 360.0, "active_high": False,
                  "name": "cam"}],
    # at most RUN_TIME, so that every action runs in assert_clear
    "faults": [{"at": 0.0, "axis": "A", "inject": "communication_loss", "persistent": True},
               {"at": 0.004, "axis": "B", "load": {"jump": 2.0}},
               {"at": 0.008, "input": "I0.2", "switch": "chatter", "period": 0.02},
               {"at": 0.012, "axis": "A", "inject": "drive", "detail": "station"},
               {"at": 0.016, "axis": "A", "clear": "all"},
               {"at": 0.02, "input": "I0.5", "switch": "stuck_actuated"}],
}
BASE_1500 = {
    "controller": {"family": "S7-1500T", "servo_cycle": 0.002, "app_cycle": 0.004},
    "axes": {"M": {"type": "positioning", "Modulo.Enable": True},
             "S": {"type": "synchronous", "leading_values": ["M", {"name": "E", "coupling": "actual"}]},
             "E": {"type": "external_encoder"}},
    "cams": {"C": {"points": [[0.0, 0.0], [180.0, 50.0], [360.0, 0.0]], "interpolation_mode": 1,
                   "segments": [{"xmin": 400.0, "xmax": 500.0, "a1": 0.5}]}},
    "trace": {"signals": ["S.Position"]},
    "switches": [{"input": "I0.2", "axis": "M", "high": -10.0}, {"input": "I0.3", "axis": "S", "low": 1.0,
                                                                  "high": 2.0}],
    "faults": [{"at": 0.002, "axis": "M", "load": {"force": 5.0, "blocked": False}},
               {"at": 0.004, "axis": "S", "inject": "encoder_loss", "persistent": True},
               {"at": 0.01, "input": "I0.2", "switch": "repair"},
               {"at": 0.02, "axis": "S", "clear": "encoder_loss"}],
}


def paths(tree: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix] if prefix else []
    if isinstance(tree, dict):
        for k, v in tree.items():
            out += paths(v, prefix + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            out += paths(v, prefix + (i,))
    return out


@st.composite
def one_value_replaced(draw) -> str:
    base = json.loads(json.dumps(draw(st.sampled_from([BASE_1200, BASE_1500]))))
    where = draw(st.sampled_from(paths(base)))
    node = base
    for k in where[:-1]:
        node = node[k]
    if draw(st.booleans()) and isinstance(node, dict):
        del node[where[-1]]                                   # a missing key
    else:
        node[where[-1]] = draw(values)
    if draw(st.booleans()):                                   # an extra key somewhere
        extra = draw(st.sampled_from([p for p in paths(base) if isinstance(_at(base, p), dict)] or [()]))
        _at(base, extra)[draw(st.sampled_from(KEYS))] = draw(values)
    return document(base)


def _at(tree: Any, path: tuple) -> Any:
    for k in path:
        tree = tree[k]
    return tree


@st.composite
def edited_text(draw) -> str:
    text = document(draw(st.sampled_from([BASE_1200, BASE_1500])))
    for _ in range(draw(st.integers(1, 3))):
        i = draw(st.integers(0, len(text)))
        j = draw(st.integers(i, min(len(text), i + 12)))
        text = text[:i] + draw(st.sampled_from(["", "[", "]", "=", '"', "\n", "{", "}", ",", ".", "\x00", "é",
                                                "[[axes.A]]\n", "nan", "1e999", "\\u"])) + text[j:]
    return text


FAULT_VALUES = st.one_of(
    scalars, st.sampled_from([0.0, 0.004, 0.01, 0.02, 1e12, 1e13, 10**30, 10**400, -0.0, -1.0]),
    st.dictionaries(st.sampled_from(["jump", "force", "blocked", "x"]), scalars, max_size=3))
FAULT_ENTRY_KEYS = ["at", "axis", "input", "inject", "detail", "persistent", "load", "clear", "switch", "period",
                    "low", "high", "active_high", "name", "bogus"]


@st.composite
def fault_sections(draw) -> str:
    """A valid base with its [[switches]] or [[faults]] entries (or [controller] watchdog keys) edited:
    keys dropped, added or given values from a pool aimed at these sections."""
    base = json.loads(json.dumps(draw(st.sampled_from([BASE_1200, BASE_1500]))))
    section = draw(st.sampled_from(["switches", "faults", "controller"]))
    if section == "controller":
        for key in ("cycle_watchdog", "cycle_watchdog_stop"):
            if draw(st.booleans()):
                base["controller"][key] = draw(FAULT_VALUES)
        return document(base)
    entries = base[section]
    for _ in range(draw(st.integers(1, 4))):
        entry = draw(st.sampled_from(entries)) if entries and draw(st.integers(0, 4)) else {}
        if entry is not None and entry not in entries:
            entries.append(entry)
        key = draw(st.sampled_from(FAULT_ENTRY_KEYS))
        if key in entry and draw(st.booleans()):
            del entry[key]
        else:
            entry[key] = draw(FAULT_VALUES)
    return document(base)


def assert_clear(text: str) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "fuzz.toml"
        path.write_text(text, encoding="utf-8", errors="surrogatepass")
        problems = check_project(path)
        assert isinstance(problems, list)
        assert all(isinstance(p, str) and p.startswith(f"{path}: ") for p in problems), problems
        try:
            ctl = load_project(path)
        except ProjectError as exc:
            assert exc.problems == problems
        else:
            assert problems == [] and isinstance(ctl, Controller)
            # a loaded project runs, and the faults it plays until then do not stop it: [[faults]] entries
            # are checked at load time (plcmotion.project_faults)
            ctl.run(RUN_TIME)
            assert ctl.mode == "RUN", ctl.stop_reason
        err = io.StringIO()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = main(["check", str(path)])
        assert code == (1 if problems else 0)
        assert all(line.startswith(str(path)) for line in err.getvalue().splitlines()), err.getvalue()


#: virtual time a loaded project runs in assert_clear [s] (the faults of the bases happen before)
RUN_TIME = 0.024

#: examples per test; PLCMOTION_CONFIG_FUZZ=2000 for a long (random instead of fixed) run
EXAMPLES = int(os.environ.get("PLCMOTION_CONFIG_FUZZ", "80"))
FUZZ = settings(max_examples=EXAMPLES, deadline=None, derandomize="PLCMOTION_CONFIG_FUZZ" not in os.environ,
                database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@FUZZ
@given(documents)
def test_project_random_documents_give_clear_messages(doc):
    assert_clear(document(doc))


@FUZZ
@given(one_value_replaced())
def test_project_valid_projects_with_one_value_replaced_give_clear_messages(text):
    assert_clear(text)


@FUZZ
@given(edited_text())
def test_project_edited_projects_give_clear_messages(text):
    assert_clear(text)


@FUZZ
@given(fault_sections())
def test_project_switch_fault_and_watchdog_sections_give_clear_messages(text):
    """[[switches]], [[faults]] and the cycle watchdog keys (issue 8 defects 6 and 11, added in review)."""
    assert_clear(text)


@settings(max_examples=40, deadline=None, derandomize=True, database=None)
@given(st.binary(max_size=200))
def test_project_random_bytes_give_clear_messages(data):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "fuzz.toml"
        path.write_bytes(data)
        problems = check_project(path)
        assert all(p.startswith(f"{path}: ") for p in problems)


def test_project_the_bases_are_valid_projects():
    for base in (BASE_1200, BASE_1500):
        assert_clear(document(base))
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / "base.toml"
            path.write_text(document(base), encoding="utf-8")
            assert check_project(path) == []
