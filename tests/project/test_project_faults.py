"""``[[switches]]`` and ``[[faults]]`` of a project file (issue 8, defect 11): the same public API as a Python
program, checked at load time with one clear message per problem (file, key path, what is allowed)."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion import s7_1200 as S12
from plcmotion.project import ProjectError, check_project, load_project

AXIS = '''
[axes.Axis_1]
"Actor.Type" = 1
"Actor.Interface.EnableDriveOutput" = "Q0.0"
"Sensor[1].Interface.Type" = 2
"PositionLimits_HW.Active" = true
"PositionLimits_HW.MinSwitchAddress" = "I0.1"
"PositionLimits_HW.MaxSwitchAddress" = "I0.2"
"PositionLimits_HW.MinSwitchLevel" = true
"PositionLimits_HW.MaxSwitchLevel" = true
"Plant.HWLimitMinPosition" = -500.0
"Plant.HWLimitMaxPosition" = 500.0
'''


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "project.toml"
    path.write_text(text, encoding="utf-8")
    return path


def enabled(ctl):
    axis = ctl["Axis_1"]
    power = S12.MC_Power(Axis=axis, Enable=True)
    ctl.program(lambda: power())
    ctl.run_until(lambda: power.Status, timeout=1.0)
    return axis, power


def test_project_defect11_project_switch_is_placed_with_the_public_api(tmp_path):
    """A ``[[switches]]`` entry places a switch at machine positions of an axis (Controller.plant.place_switch):
    a program reads it as the load passes."""
    ctl = load_project(write(tmp_path, AXIS + '''
[[switches]]
input = "I0.5"
axis = "Axis_1"
low = 10.0
high = 20.0
name = "part present"
'''))
    sw = ctl.plant.switch("I0.5")
    assert (sw.low, sw.high, sw.name, sw.active_high) == (10.0, 20.0, "part present", True)
    axis, power = enabled(ctl)
    mv = S12.MC_MoveAbsolute(Axis=axis)
    home = S12.MC_Home(Axis=axis, Execute=True, Mode=0, Position=0.0)
    seen = []
    ctl.program(lambda: (home(), mv(Execute=home.Done, Position=30.0, Velocity=50.0),
                         seen.append((axis.ActualPosition, ctl.inputs["I0.5"]))))
    ctl.run_until(lambda: mv.Done, timeout=3.0)
    inside = [p for p, on in seen if on]
    assert inside and min(inside) >= 10.0 and max(inside) <= 20.0 + 50.0 * 0.0074


def test_project_defect11_project_faults_play_at_their_time(tmp_path):
    """``[[faults]]``: the bus of Axis_1 fails at 0.3 s (16#800C/16#003E, S7-1200 V6 §12.8, remove enable) and is
    back at 0.6 s; a stuck limit switch at 1.0 s (16#8004); the entries run through the public API."""
    ctl = load_project(write(tmp_path, AXIS + '''
[[faults]]
at = 0.3
axis = "Axis_1"
inject = "communication_loss"
persistent = true

[[faults]]
at = 0.6
axis = "Axis_1"
clear = "all"

[[faults]]
at = 1.0
input = "I0.2"
switch = "stuck_actuated"
'''))
    axis, power = enabled(ctl)
    ctl.run(0.3 - ctl.time - 0.002)
    assert power.Status
    ctl.run(0.01)
    assert not power.Status and (power.ErrorID, power.ErrorInfo) == (0x800C, 0x003E)
    assert axis.ErrorBits.CommunicationFault
    ctl.run(0.35)
    reset = S12.MC_Reset(Axis=axis, Execute=True)
    ctl.program(lambda: reset())
    ctl.run_until(lambda: power.Status, timeout=0.5)
    ctl.run(1.1 - ctl.time)
    assert not power.Status and (power.ErrorID, power.ErrorInfo) == (0x8004, 0x000E)
    assert [w.split(":")[0] for _, w in ctl.plant.scenario.done] == ["faults[0]", "faults[1]", "faults[2]"]


@pytest.mark.parametrize("text,expected", [
    ('[[faults]]\nat = -1\naxis = "Axis_1"\ninject = "drive"', "faults[0].at = -1: allowed"),
    ('[[faults]]\nat = 1\naxis = "Nope"\ninject = "drive"', "faults[0].axis = \"Nope\": allowed"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\ninject = "bus"', "faults[0].inject = \"bus\": allowed"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\ninject = "drive"\ndetail = "smoke"', "detail 'smoke' is not one of"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"', "give exactly one action"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\ninject = "drive"\nclear = "all"', "give exactly one action"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\nload = { jump = nan }', "faults[0].load: jump must be a finite"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\nload = { push = 1 }', "faults[0].load = { push = 1 }: allowed"),
    ('[[faults]]\nat = 1\ninput = "I0.7"\nswitch = "stuck_actuated"', "faults[0].input = \"I0.7\": allowed"),
    ('[[faults]]\nat = 1\ninput = "I0.2"\nswitch = "chatter"', "faults[0].period = "),
    ('[[faults]]\nat = 1\ninput = "I0.2"\nswitch = "bent"', "faults[0].switch = \"bent\": allowed"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\ninject = "drive"\nwhen = 2', "faults[0].when: unknown key"),
    ('faults = 3', "faults = 3: allowed: an array of tables [[faults]]"),
    ('[[switches]]\naxis = "Axis_1"\nlow = 1.0', "switches[0]: the input is missing"),
    ('[[switches]]\ninput = "I0.5"\naxis = "Axis_1"\nlow = 5.0\nhigh = 1.0', "switches[0]: switch at I0.5: low"),
    ('[[switches]]\ninput = "I0.1"\naxis = "Axis_1"\nlow = 5.0', "switches[0]: input I0.1 is already wired"),
    ('[[switches]]\ninput = "I0.5"\naxis = "Axis_1"\nlow = inf', "switches[0].low = inf: allowed"),
    ('[[switches]]\ninput = "Q0.5"\naxis = "Axis_1"\nlow = 1.0', "is not an input"),
])
def test_project_defect11_project_fault_entries_are_checked_with_clear_messages(tmp_path, text, expected):
    # a top-level key must come before the first table
    path = write(tmp_path, AXIS + "\n" + text + "\n" if text.startswith("[[") else text + "\n" + AXIS)
    problems = check_project(path)
    assert any(expected in p for p in problems), problems
    assert all(p.startswith(str(path)) for p in problems)
    with pytest.raises(ProjectError):
        load_project(path)


def test_project_defect11_project_rejects_a_communication_loss_on_an_analog_axis(tmp_path):
    path = write(tmp_path, '[axes.Axis_1]\n"Actor.Type" = 0\n[[faults]]\nat = 1\naxis = "Axis_1"\n'
                           'inject = "communication_loss"\n')
    assert any("faults[0]: axis Axis_1: communication_loss needs a PROFIdrive axis" in p
               for p in check_project(path))


_VALUES = [0, -1, 1.5, 1e300, float("inf"), float("nan"), True, "", "I0.2", "Axis_1", "all", "load", "chatter",
           "stuck_actuated", "communication_loss", "drive", [], [1], {}, {"jump": 1.0}, {"force": "x"}]


def _toml(value) -> str:
    from plcmotion.project import toml_value
    return toml_value(value)


@settings(max_examples=60, deadline=None)
@given(entries=st.lists(st.dictionaries(st.sampled_from(["at", "axis", "input", "inject", "detail", "persistent",
                                                          "load", "clear", "switch", "period", "low", "high",
                                                          "active_high", "name", "x"]),
                                         st.sampled_from(_VALUES), max_size=6), max_size=3),
       section=st.sampled_from(["faults", "switches"]))
def test_project_defect11_random_fault_and_switch_entries_never_raise(tmp_path_factory, entries, section):
    """Config fuzz: whatever the entries hold, checking the file gives messages (or none), never a traceback."""
    body = "".join(f"\n[[{section}]]\n" + "".join(f"{k} = {_toml(v)}\n" for k, v in e.items()) for e in entries)
    path = write(tmp_path_factory.mktemp("p"), AXIS + body)
    problems = check_project(path)
    assert all(isinstance(p, str) and p.startswith(str(path)) for p in problems)


def test_project_defect11_docs_project_example_loads(tmp_path):
    """The ``[[switches]]``/``[[faults]]`` example of docs/fault_injection.md is a valid project (with an axis)."""
    import re

    page = (Path(__file__).resolve().parents[2] / "docs" / "fault_injection.md").read_text(encoding="utf-8")
    (block,) = re.findall(r"```toml\n(.*?)```", page, re.DOTALL)
    ctl = load_project(write(tmp_path, AXIS + "\n" + block))
    assert len(ctl.plant.scenario.pending) == 4 and ctl.plant.switch("I0.5").name == "part present"
    ctl.run(2.5)
    assert [w.split(":")[0] for _, w in ctl.plant.scenario.done] == [f"faults[{i}]" for i in range(4)]


def test_project_defect11_project_faults_on_an_encoder_or_proxy_are_refused(tmp_path):
    """Only axes have a simulated drive and load: an external encoder or a leading axis proxy named in
    ``[[faults]]`` or ``[[switches]]`` gives a message, not a silently ignored entry."""
    path = write(tmp_path, '''[controller]
family = "S7-1500T"
[axes.Enc]
type = "external_encoder"
[axes.Proxy]
type = "leading_axis_proxy"
[[faults]]
at = 1
axis = "Enc"
inject = "encoder_loss"
[[switches]]
input = "I0.2"
axis = "Proxy"
low = 1.0
''')
    problems = check_project(path)
    assert any("faults[0].axis = \"Enc\": allowed" in p and "ExternalEncoder" in p for p in problems), problems
    assert any("switches[0].axis = \"Proxy\": allowed" in p and "LeadingAxisProxy" in p for p in problems), problems


HUGE = "1" + "0" * 400          # a TOML integer beyond float range


@pytest.mark.parametrize("text,expected", [
    ('[[faults]]\nat = 1e13\naxis = "Axis_1"\ninject = "drive"', "faults[0].at = 10000000000000.0: allowed"),
    (f'[[faults]]\nat = {HUGE}\naxis = "Axis_1"\ninject = "drive"', "faults[0].at = 1000"),
    (f'[[switches]]\ninput = "I0.5"\naxis = "Axis_1"\nlow = {HUGE}', "switches[0].low = 1000"),
    (f'[[faults]]\nat = 1\ninput = "I0.2"\nswitch = "chatter"\nperiod = {HUGE}', "faults[0].period = 1000"),
    (f'[controller]\ncycle_watchdog = {HUGE}', "controller.cycle_watchdog = 1000"),
    ('[[faults]]\nat = 1\ninput = "I0.2"\naxis = "Axis_1"\nswitch = "repair"', "faults[0].axis: not used"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\nclear = "all"\npersistent = true', "faults[0].persistent: not used"),
    ('[[faults]]\nat = 1\naxis = "Axis_1"\ninject = "drive"\nperiod = 5', "faults[0].period: not used"),
    ('[[faults]]\nat = 1\ninput = "I0.2"\nswitch = "repair"\nperiod = 5', "faults[0].period: not used"),
    ('[controller]\ncycle_watchdog = 0\ncycle_watchdog_stop = true', "controller.cycle_watchdog_stop = true: allowed"),
], ids=["at-beyond-the-scenario-range", "at-huge-int", "switch-low-huge-int", "chatter-period-huge-int",
        "watchdog-huge-int", "axis-with-a-switch-action", "persistent-with-clear", "period-with-inject",
        "period-without-chatter", "watchdog-stop-without-watchdog"])
def test_project_defect11_project_fault_values_found_in_review(tmp_path, text, expected):
    """Review of issue 8 (found by the config fuzz once it covered [[faults]]/[[switches]]/cycle_watchdog):
    ``at`` beyond 1e12 s gave a ValueError traceback, an integer beyond float range an OverflowError; a key the
    entry's action does not use (``axis`` of a switch action, ``persistent`` of a clear, ``period`` of an
    inject) was ignored silently.  Each is one message with the key path."""
    path = write(tmp_path, text + "\n" + AXIS)
    problems = check_project(path)
    assert any(expected in p for p in problems), problems
    assert all(p.startswith(str(path)) and len(p) < 400 for p in problems), problems
    with pytest.raises(ProjectError):
        load_project(path)
