"""Project files: loading, reading back the configured tags, and the problem messages."""
from __future__ import annotations

import textwrap
import time
from pathlib import Path

import pytest

import plcmotion
from plcmotion.project import ProjectError, check_project, load_project

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

VALID = """
[controller]
servo_cycle = 0.002
app_cycle = 0.006

[axes.Axis_1]
type = "positioning"
"Actor.Type" = 2
"Mechanics.LeadScrew" = 5.0
[axes.Axis_1.Actor.DriveParameter]
PulsesPerDriveRevolution = 1600
[axes.Axis_1.DynamicLimits]
MaxVelocity = 100.0
MinVelocity = 2.5
[axes.Axis_1."Sensor[1]".ActiveHoming]
Mode = 2
HomePositionOffset = 1.5
[axes.Axis_1.PositionLimitsSW]          # spelling of an older manual
Active = true
MaxPosition = 400.0

[axes.Axis_2]
"Actor.Type" = 1
"Mechanics.LeadScrew" = 10.0
"DynamicLimits.MaxVelocity" = 400.0
"Sensor.Sensor[1].System" = 1
[axes.Axis_2.PositionControl]
Kv = 25.0
[axes.Axis_2.Plant]
InitialPosition = 12.5

[trace]
signals = ["Axis_1.Position", "Axis_2.ActualPosition", "Axis_2.StatusBits.Enable"]
every = 2
"""


def write(tmp_path: Path, text: str, name: str = "project.toml") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def only_problem(path: Path) -> str:
    problems = check_project(path)
    assert len(problems) == 1, problems
    return problems[0]


# --- a valid file ---------------------------------------------------------------------------------------

def test_project_valid_file_loads_with_the_configured_values(tmp_path):
    path = write(tmp_path, VALID)
    assert check_project(path) == []
    ctl = load_project(path)
    assert ctl.servo_cycle == 0.002 and ctl.app_cycle == pytest.approx(0.006)
    assert list(ctl.axes) == ["Axis_1", "Axis_2"]                    # file order
    a1, a2 = ctl.axes["Axis_1"], ctl.axes["Axis_2"]
    assert a1.Actor.Type == 2 and a2.Actor.Type == 1
    assert a1.DynamicLimits.MaxVelocity == 100.0
    assert a1.DynamicLimits.MinVelocity == 2.5
    assert a1.Actor.DriveParameter.PulsesPerDriveRevolution == 1600
    assert a1.Mechanics.LeadScrew == 5.0
    assert a1.Sensor[1].ActiveHoming.Mode == 2
    assert a1.Sensor[1].ActiveHoming.HomePositionOffset == 1.5
    assert a1.PositionLimits_SW.Active is True
    assert a1.PositionLimits_SW.MaxPosition == 400.0
    assert a1.PositionLimits_SW.MinPosition == -10000.0            # start value, not in the file
    assert a2.DynamicLimits.MaxVelocity == 400.0
    assert a2.DynamicLimits.MinVelocity == 0.0                     # fixed for PROFIdrive
    assert a2.PositionControl.Kv == 25.0
    assert a2.tag("Sensor[1].System") == 1
    assert a2.ActualPosition == 12.5                               # Plant.InitialPosition
    assert ctl.project == {"path": str(path), "trace": {
        "signals": ["Axis_1.Position", "Axis_2.ActualPosition", "Axis_2.StatusBits.Enable"], "every": 2}}


def test_project_defaults_without_controller_and_trace_sections(tmp_path):
    path = write(tmp_path, '[axes.X]\n"Actor.Type" = 2\n')
    ctl = load_project(str(path))
    assert (ctl.servo_cycle, ctl.app_cycle) == (0.001, 0.004)
    assert ctl.project["trace"] == {"signals": [], "every": 1}
    assert ctl.axes["X"].DynamicLimits.MaxVelocity == 250.0


def test_project_empty_tables_of_tag_groups_are_allowed(tmp_path):
    path = write(tmp_path, '[axes.A]\n[axes.A.Homing]\n[axes.A."Sensor[1]".PassiveHoming]\n[axes.B]\n')
    assert list(load_project(path).axes) == ["A", "B"]


def test_project_empty_file_gives_a_controller_without_axes(tmp_path):
    ctl = load_project(write(tmp_path, ""))
    assert ctl.axes == {}


def test_project_package_level_load_project(tmp_path):
    ctl = plcmotion.load_project(write(tmp_path, VALID))
    assert isinstance(ctl, plcmotion.Controller)


def test_project_loaded_controller_runs(tmp_path):
    ctl = load_project(write(tmp_path, VALID))
    ctl.run(0.1)
    assert ctl.mode == "RUN" and ctl.time == pytest.approx(0.102)


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_project_example_projects_are_valid(name):
    assert check_project(EXAMPLES / name) == []
    ctl = load_project(EXAMPLES / name)
    assert ctl.axes and ctl.project["trace"]["signals"]


def test_project_examples_exist():
    names = {p.name for p in EXAMPLES.glob("*.toml")}
    assert {"pto_stepper.toml", "profidrive_servo.toml"} <= names


def test_project_example_servo_velocity_is_reachable_with_max_speed():
    axis = load_project(EXAMPLES / "profidrive_servo.toml").axes["Spindle"]
    drive = axis.Actor.DriveParameter
    assert axis.Actor.Type == 1 and drive.ReferenceSpeed == 3000.0
    assert axis.DynamicLimits.MaxVelocity <= drive.MaxSpeed / 60.0 * axis.Mechanics.LeadScrew
    assert axis.Sensor[1].System == 1                               # rotary encoder


def test_project_example_stepper_mechanics():
    axis = load_project(EXAMPLES / "pto_stepper.toml").axes["Shuttle"]
    assert axis.Actor.Type == 2
    assert axis.Mechanics.LeadScrew == 5.0
    assert axis.Actor.DriveParameter.PulsesPerDriveRevolution == 200 * 8
    assert axis.DynamicLimits.MinVelocity > 0.0
    assert axis.PositionLimits_SW.Active is True


# --- reading the file -----------------------------------------------------------------------------------

def test_project_missing_file(tmp_path):
    path = tmp_path / "nowhere.toml"
    assert check_project(path) == [f"{path}: file not found"]
    with pytest.raises(ProjectError) as err:
        load_project(path)
    assert err.value.problems == [f"{path}: file not found"]


def test_project_directory_instead_of_file(tmp_path):
    assert check_project(tmp_path) == [f"{tmp_path}: is a directory, not a project file"]


def test_project_file_that_is_not_utf8(tmp_path):
    path = tmp_path / "latin1.toml"
    path.write_bytes('[axes.Achse_1]\n# Stra\xdfe\n'.encode("latin-1"))
    message = only_problem(path)
    assert message.startswith(f"{path}: not UTF-8 text")


def test_project_toml_syntax_error_names_line_and_column(tmp_path):
    path = write(tmp_path, """
        [axes.Axis_1]
        "Actor.Type" = 2
        "DynamicLimits.MaxVelocity" = fast
    """)
    message = only_problem(path)
    assert message.startswith(f"{path}: TOML syntax error: ")
    assert "line 4, column" in message
    assert '"DynamicLimits.MaxVelocity" = fast' in message


# --- single problems: (file text, key path and value, allowed) -------------------------------------------

CASES = {
    "unknown section": (
        "[controler]\nservo_cycle = 0.001\n",
        "controler: unknown section", "did you mean controller?"),
    "unknown controller key": (
        "[controller]\nservo_cycel = 0.001\n",
        "controller.servo_cycel: unknown key (value 0.001)", "did you mean servo_cycle?"),
    "servo_cycle text": (
        '[controller]\nservo_cycle = "1ms"\n',
        'controller.servo_cycle = "1ms"', "allowed: a positive number of seconds"),
    "servo_cycle negative": (
        "[controller]\nservo_cycle = -0.001\n",
        "controller.servo_cycle = -0.001", "allowed: a positive number of seconds"),
    "app_cycle zero": (
        "[controller]\napp_cycle = 0\n",
        "controller.app_cycle = 0", "allowed: a positive number of seconds"),
    "app_cycle bool": (
        "[controller]\napp_cycle = true\n",
        "controller.app_cycle = true", "allowed: a positive number of seconds"),
    "app_cycle not a multiple": (
        "[controller]\nservo_cycle = 0.001\napp_cycle = 0.0025\n",
        "controller.app_cycle = 0.0025",
        "allowed: a whole multiple of servo_cycle = 0.001 s, e.g. 0.002 or 0.003"),
    "app_cycle shorter than servo_cycle": (
        "[controller]\nservo_cycle = 0.002\napp_cycle = 0.001\n",
        "controller.app_cycle = 0.001", "allowed: a whole multiple of servo_cycle = 0.002 s"),
    "default app_cycle not a multiple": (
        "[controller]\nservo_cycle = 0.003\n",
        "controller.app_cycle = 0.004 (default)", "allowed: a whole multiple of servo_cycle = 0.003 s"),
    "controller not a table": (
        "controller = 0.001\n",
        "controller = 0.001", "allowed: a table [controller]"),
    "axis name not an identifier": (
        '[axes."Axis 1"]\n"Actor.Type" = 2\n',
        'axes."Axis 1": the axis name "Axis 1" is not an identifier',
        "allowed: letters, digits and underscores"),
    "axis name starting with a digit": (
        '[axes.1st]\n"Actor.Type" = 2\n',
        'axes.1st: the axis name "1st" is not an identifier', "allowed: letters, digits and underscores"),
    "axis not a table": (
        "[axes]\nAxis_1 = 5\n",
        "axes.Axis_1 = 5", "allowed: a table of axis tags"),
    "axes not a table": (
        'axes = ["Axis_1"]\n',
        'axes = ["Axis_1"]', "allowed: one table [axes.<name>] per axis"),
    "unknown axis type": (
        '[axes.Axis_1]\ntype = "rotary"\n',
        'axes.Axis_1.type = "rotary"', 'allowed: one of "positioning"'),
    "misspelled status word bit": (
        '[controller]\nfamily = "S7-1500T"\n[axes.Axis_1]\ntype = "synchronous"\nleading_values = []\n'
        '[trace]\nsignals = ["Axis_1.StatusWord.Synchronus"]\n',
        'trace.signals[0] = "Axis_1.StatusWord.Synchronus": Axis_1.StatusWord.Synchronus: StatusWord has no bit',
        "did you mean StatusWord.Synchronous?"),
    "family in other case": (
        '[controller]\nfamily = "s7-1500t"\n',
        'controller.family = "s7-1500t"', 'did you mean "S7-1500T"?'),
    "S7-1500 object without family": (
        '[axes.Axis_1]\ntype = "synchronous"\n',
        "controller.family is not set, so S7-1200 is assumed, but the file has synchronous axes",
        'set family = "S7-1500T"'),
    "unknown tag": (
        "[axes.Axis_1.DynamicLimits]\nMaxVelocty = 100.0\n",
        "axes.Axis_1.DynamicLimits.MaxVelocty: unknown parameter (value 100.0)",
        "did you mean DynamicLimits.MaxVelocity or"),
    "unknown tag group": (
        "[axes.Axis_1.Nonsense]\nFoo = 1\n",
        "axes.Axis_1.Nonsense.Foo: unknown parameter (value 1)", "not a tag of the positioning axis"),
    "wrong type of a real": (
        '[axes.Axis_1.DynamicDefaults]\nJerk = "high"\n',
        'axes.Axis_1.DynamicDefaults.Jerk = "high"', "allowed: real in [0.0, 1000000000000.0]"),
    "wrong type of a bool": (
        '[axes.Axis_1]\n"PositionLimits_SW.Active" = "yes"\n',
        'axes.Axis_1.PositionLimits_SW.Active = "yes"', "allowed: true or false"),
    "wrong type of an integer": (
        '[axes.Axis_1."Sensor[1]".ActiveHoming]\nMode = 1.5\n',
        'axes.Axis_1.Sensor[1].ActiveHoming.Mode = 1.5', "allowed: one of 0, 1, 2"),
    "a table where a value belongs": (
        "[axes.Axis_1]\nPlant = [1, 2]\n",
        "axes.Axis_1.Plant: unknown parameter (value [1, 2])", "not a tag of the positioning axis"),
    "not one of the choices": (
        '[axes.Axis_1]\n"Actor.Type" = 3\n',
        "axes.Axis_1.Actor.Type = 3", "allowed: one of 0, 1, 2"),
    "out of range, integer": (
        "[axes.Axis_1.Actor.DriveParameter]\nPulsesPerDriveRevolution = 0\n",
        "axes.Axis_1.Actor.DriveParameter.PulsesPerDriveRevolution = 0", "allowed: integer in [1, 2147483647]"),
    "out of range, plant": (
        "[axes.Axis_1.Plant]\nSpeedTimeConstant = 11.0\n",
        "axes.Axis_1.Plant.SpeedTimeConstant = 11.0", "allowed: real in [0.0, 10.0]"),
    "rule: MinVelocity above MaxVelocity": (
        "[axes.Axis_1.DynamicLimits]\nMaxVelocity = 50.0\nMinVelocity = 60.0\n",
        "axes.Axis_1.DynamicLimits.MinVelocity = 60.0", "at most DynamicLimits.MaxVelocity = 50"),
    "rule on a tag the file does not set": (
        "[axes.Axis_1.DynamicLimits]\nMaxVelocity = 5.0\n",
        "axes.Axis_1.DynamicLimits.MinVelocity = 10.0: at most DynamicLimits.MaxVelocity = 5",
        "(start value; the file does not set this tag)"),
    "rule: SW limits in the wrong order": (
        "[axes.Axis_1.PositionLimits_SW]\nMinPosition = 10.0\nMaxPosition = -10.0\n",
        "axes.Axis_1.PositionLimits_SW.MinPosition = 10.0", "at most PositionLimits_SW.MaxPosition = -10"),
    "rule: PTO frequency": (
        ('[axes.Axis_1]\n"Actor.DriveParameter.PulsesPerDriveRevolution" = 1600\n'
         '"Mechanics.LeadScrew" = 5.0\n"DynamicLimits.MaxVelocity" = 500.0\n'),
        "axes.Axis_1.DynamicLimits.MaxVelocity = 500.0", "at most 100000 pulses/s = 312.5 user units/s"),
    "rule: servo velocity above MaxSpeed": (
        ('[axes.Axis_1]\n"Actor.Type" = 1\n"Mechanics.LeadScrew" = 10.0\n'
         '"DynamicLimits.MaxVelocity" = 600.0\n'),
        "axes.Axis_1.DynamicLimits.MaxVelocity = 600.0", "at most 500 user units/s with MaxSpeed 3000 1/min"),
    "rule: MaxSpeed above twice the reference speed": (
        '[axes.Axis_1]\n"Actor.Type" = 1\n"Actor.DriveParameter.MaxSpeed" = 7000.0\n',
        "axes.Axis_1.Actor.DriveParameter.MaxSpeed = 7000.0", "at most 2 x ReferenceSpeed = 6000 1/min"),
    "rule: start/stop velocity of a servo": (
        '[axes.Axis_1]\n"Actor.Type" = 1\n"DynamicLimits.MinVelocity" = 5.0\n',
        "axes.Axis_1.DynamicLimits.MinVelocity = 5.0", "fixed at 0.0 for PROFIdrive/analog drives"),
    "same tag twice": (
        '[axes.Axis_1]\n"PositionLimits_SW.Active" = true\n[axes.Axis_1.PositionLimitsSW]\nActive = false\n',
        "axes.Axis_1.PositionLimitsSW.Active = false",
        "already set by axes.Axis_1.PositionLimits_SW.Active = true; set each tag once"),
    "trace not a table": (
        'trace = ["Axis_1.Position"]\n',
        'trace = ["Axis_1.Position"]', "allowed: a table [trace]"),
    "unknown trace key": (
        "[trace]\nsignal = []\n",
        "trace.signal: unknown key (value [])", "did you mean signals?"),
    "signals not a list": (
        '[axes.Axis_1]\n[trace]\nsignals = "Axis_1.Position"\n',
        'trace.signals = "Axis_1.Position"', "allowed: a list of strings"),
    "signal not a string": (
        '[axes.Axis_1]\n[trace]\nsignals = ["Axis_1.Position", 3]\n',
        "trace.signals[1] = 3", 'allowed: a string "<axis>.<tag>"'),
    "signal without a tag": (
        '[axes.Axis_1]\n[trace]\nsignals = ["Axis_1"]\n',
        'trace.signals[0] = "Axis_1"', 'allowed: "<axis>.<tag>"'),
    "signal of an unknown axis": (
        '[axes.Axis_1]\n[trace]\nsignals = ["Axis_2.Position"]\n',
        'trace.signals[0] = "Axis_2.Position": unknown axis Axis_2 (did you mean Axis_1?)',
        "allowed: \"<axis>.<tag>\" with an axis of this file: Axis_1"),
    "signal of an unknown tag": (
        '[axes.Axis_1]\n[trace]\nsignals = ["Axis_1.Posiiton"]\n',
        'trace.signals[0] = "Axis_1.Posiiton": Axis_1.Posiiton is not a tag', "did you mean Position"),
    "every zero": (
        "[trace]\nevery = 0\n",
        "trace.every = 0", "allowed: an integer >= 1"),
    "every real": (
        "[trace]\nevery = 2.0\n",
        "trace.every = 2.0", "allowed: an integer >= 1"),
    "empty table that is no group of tags": (
        "[axes.Axis_1.DynamicLimit]\n",
        "axes.Axis_1.DynamicLimit: unknown parameter (value {})", "did you mean DynamicLimits."),
}


@pytest.mark.parametrize("case", list(CASES))
def test_project_each_problem_gives_one_clear_message(tmp_path, case):
    text, key_and_value, allowed = CASES[case]
    path = write(tmp_path, text, name="case.toml")
    message = only_problem(path)
    assert message.startswith(f"{path}: {key_and_value}"), message
    assert allowed in message, message
    with pytest.raises(ProjectError) as err:
        load_project(path)
    assert err.value.problems == [message]
    assert message in str(err.value)


def test_project_message_for_a_value_out_of_range(tmp_path):
    path = write(tmp_path, "[axes.Axis_1.DynamicLimits]\nMaxVelocity = -5.0\n", name="x.toml")
    assert check_project(path) == [
        f"{path}: axes.Axis_1.DynamicLimits.MaxVelocity = -5.0: allowed: real in (0.0, 1000000000000.0]"]


def test_project_relative_path_is_named_as_given(tmp_path, monkeypatch):
    write(tmp_path, "[axes.Axis_1.DynamicLimits]\nMaxVelocity = -5.0\n", name="x.toml")
    monkeypatch.chdir(tmp_path)
    assert check_project("x.toml")[0].startswith("x.toml: axes.Axis_1.DynamicLimits.MaxVelocity = -5.0")


# --- several problems -------------------------------------------------------------------------------------

MANY = """
[controller]
servo_cycle = 0.001
app_cycle = 0.0015
cycle = 1

[axis.Axis_0]

[axes.Axis_1]
"Actor.Type" = 7
[axes.Axis_1.DynamicLimits]
MaxVelocity = -5.0
MaxVelcity = 1.0

[axes."Bad name"]
"DynamicDefaults.Jerk" = "none"

[axes.Axis_2]
"Actor.Type" = 1
[axes.Axis_2.FollowingError]
MaxValue = -1.0

[axes.Axis_3]
"Plant.InitialPosition" = 1.0

[trace]
signals = ["Axis_3.Position", "Axis_9.Position", "Axis_3.Nothing"]
every = -1
"""


def test_project_all_problems_are_reported_at_once(tmp_path):
    path = write(tmp_path, MANY, name="many.toml")
    problems = check_project(path)
    expected = [
        "axis: unknown section",
        "controller.cycle: unknown key",
        "controller.app_cycle = 0.0015: allowed: a whole multiple of servo_cycle",
        "axes.Axis_1.Actor.Type = 7: allowed: one of 0, 1, 2",
        "axes.Axis_1.DynamicLimits.MaxVelocity = -5.0: allowed: real in (0.0, 1000000000000.0]",
        "axes.Axis_1.DynamicLimits.MaxVelcity: unknown parameter (value 1.0); did you mean",
        'axes."Bad name": the axis name "Bad name" is not an identifier',
        'axes."Bad name".DynamicDefaults.Jerk = "none": allowed: real in',
        "axes.Axis_2.FollowingError.MaxValue = -1.0: allowed: real in [0.0, 1000000000000.0]",
        'trace.signals[1] = "Axis_9.Position": unknown axis Axis_9',
        'trace.signals[2] = "Axis_3.Nothing": Axis_3.Nothing is not a tag of the positioning axis',
        "trace.every = -1: allowed: an integer >= 1",
    ]
    assert len(problems) == len(expected), "\n".join(problems)
    for problem, start in zip(problems, expected):
        assert problem.startswith(f"{path}: {start}"), (problem, start)

    with pytest.raises(ProjectError) as err:
        load_project(path)
    error = err.value
    assert isinstance(error, ValueError)
    assert error.problems == problems
    assert str(error).splitlines()[0] == f"{path}: {len(problems)} problems in the project file"
    assert all(p in str(error) for p in problems)


def test_project_valid_axes_of_a_bad_file_are_still_checked_against_a_bad_controller(tmp_path):
    path = write(tmp_path, """
        [controller]
        servo_cycle = "fast"
        [axes.A]
        "DynamicLimits.MaxVelocity" = 0.0
    """)
    problems = check_project(path)
    assert [p.split(" = ")[0] for p in problems] == [
        f"{path}: controller.servo_cycle", f"{path}: axes.A.DynamicLimits.MaxVelocity"]


@pytest.mark.parametrize("text", [
    "axes = 1", "trace = 1", "controller = []", "[axes.A]\n[axes.A.Sensor]\nx = {}\n",
    "[[axes.A]]\n", "[axes.A]\n\"Actor.Type\" = 1979-05-27\n", "[trace]\nsignals = [[1]]\n",
    "[axes.A]\n\"Actor.Type\" = nan\n", "[axes.A]\n\"DynamicLimits.MaxVelocity\" = inf\n",
])
def test_project_odd_files_give_messages_not_tracebacks(tmp_path, text):
    path = write(tmp_path, text)
    problems = check_project(path)
    assert problems and all(p.startswith(f"{path}: ") for p in problems)
    with pytest.raises(ProjectError):
        load_project(path)


@pytest.mark.parametrize("value", ['"500"', "true"])
def test_project_quoted_number_or_bool_for_a_real_tag_is_rejected(tmp_path, value):
    path = write(tmp_path, f"[axes.Axis_1.DynamicLimits]\nMaxVelocity = {value}\n")
    message = only_problem(path)
    assert message.startswith(f"{path}: axes.Axis_1.DynamicLimits.MaxVelocity = {value}: allowed: real")


# --- issue 8, defect 7: configuration that must not be accepted -------------------------------------------

T1500 = '[controller]\nfamily = "S7-1500T"\n'

DEFECT_7 = {
    # servo cycle range [0.25 ms, 32 ms], application cycle up to 1 s (docs: robustness)
    "servo_cycle denormal": ("[controller]\nservo_cycle = 5e-324\n", "controller.servo_cycle = 5e-324",
                             "allowed: a positive number of seconds in [0.0001, 0.032]"),
    "servo_cycle tiny": ("[controller]\nservo_cycle = 1e-300\n", "controller.servo_cycle = 1e-300",
                         "in [0.0001, 0.032]"),
    "servo_cycle long": ("[controller]\nservo_cycle = 0.1\napp_cycle = 0.1\n", "controller.servo_cycle = 0.1",
                         "in [0.0001, 0.032]"),
    "app_cycle huge": ("[controller]\napp_cycle = 1e300\n", "controller.app_cycle = 1e+300",
                       "allowed: a positive number of seconds in [0.0001, 1]"),
    "app_cycle inf": ("[controller]\napp_cycle = inf\n", "controller.app_cycle = inf", "in [0.0001, 1]"),
    # integers beyond the float range (TOML readers accept them): a message, not OverflowError
    "input_filter huge int": ("[controller]\ninput_filter = 1" + "0" * 400 + "\n", "controller.input_filter = 1000",
                              "allowed: a time in [0, 20] s"),
    "servo_cycle huge int": ("[controller]\nservo_cycle = 1" + "0" * 400 + "\n", "controller.servo_cycle = 1000",
                             "allowed: a positive number of seconds in [0.0001, 0.032]"),
    "input filter huge int": ('[inputs]\n"I0.3" = { filter = 1' + "0" * 400 + " }\n", 'inputs."I0.3".filter = 1000',
                              "allowed: a time in [0, 20] s"),
    "trace every huge int": ("[trace]\nevery = 1" + "0" * 400 + "\n", "trace.every = 1000",
                             "allowed: an integer >= 1 (record every n-th servo cycle), at most 1000000000"),
    # integers are integers: TOML tells 1 from 1.0
    "Actor.Type real": ('[axes.A]\n"Actor.Type" = 1.0\n', "axes.A.Actor.Type = 1.0",
                        "allowed: one of 0, 1, 2 (an integer: write 1, not 1.0)"),
    "technology_version real": ("[controller]\ntechnology_version = 7.0\n",
                                "controller.technology_version = 7.0", "allowed: 6 or 7"),
    "interpolation_mode real": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [1.0, 1.0]]\ninterpolation_mode = 1.0\n",
                                "cams.C.interpolation_mode = 1.0", "allowed: the integer 0 or 1 or 2"),
    "boundary_conditions real": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [1.0, 1.0]]\nboundary_conditions = 1.0\n",
                                 "cams.C.boundary_conditions = 1.0", "allowed: the integer 0 or 1"),
    # cams (S7-1500T V5 §6.2.5.7): finite values, strictly increasing leading values, 1000 points, 50 segments
    "cam points not increasing": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [2.0, 1.0], [1.0, 2.0]]\n",
                                  "cams.C.points[2] = [1.0, 2.0]", "strictly increasing leading value"),
    "cam points duplicate": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [1.0, 1.0], [1.0, 2.0]]\n",
                             "cams.C.points[2] = [1.0, 2.0]", "each leading value once"),
    "cam point nan": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [1.0, nan]]\n",
                      "cams.C.points[1] = [1.0, nan]", "finite numbers within +-1e+12"),
    "cam point inf": (T1500 + "[cams.C]\npoints = [[-inf, 0.0], [1.0, 1.0]]\n",
                      "cams.C.points[0] = [-inf, 0.0]", "finite numbers"),
    "cam point huge": (T1500 + "[cams.C]\npoints = [[0.0, 0.0], [1.0, 2e12]]\n",
                       "cams.C.points[1] = [1.0, 2000000000000.0]", "within +-1e+12"),
    "cam point not a pair": (T1500 + "[cams.C]\npoints = [[0.0, 0.0, 1.0]]\n",
                             "cams.C.points[0] = [0.0, 0.0, 1.0]", "an [x, y] pair of numbers"),
    "cam segment nan": (T1500 + "[cams.C]\nsegments = [{ xmin = 0.0, xmax = 1.0, a1 = nan }]\n",
                        "cams.C.segments[0]", "finite numbers"),
    "cam segment empty range": (T1500 + "[cams.C]\nsegments = [{ xmin = 1.0, xmax = 1.0, a1 = 1.0 }]\n",
                                "cams.C.segments[0]", "xmax greater than xmin"),
    "cam too many points": (T1500 + "[cams.C]\npoints = [" + ", ".join(f"[{i}.0, 0.0]" for i in range(1001)) + "]\n",
                            "cams.C.points: 1001 points", "allowed: at most 1000 points"),
    "cam too many segments": (T1500 + "[cams.C]\nsegments = ["
                              + ", ".join(f"{{ xmin = {i}.0, xmax = {i + 1}.0 }}" for i in range(51)) + "]\n",
                              "cams.C.segments: 51 segments", "allowed: at most 50 segments"),
    # command tables (S7-1200 V6 §12.10.8.1)
    "step Type 99": ("[command_tables.T]\nCommand = [{ Type = 99 }]\n",
                     "command_tables.T.Command[1].Type = 99", "allowed: one of 0 (Empty), 2 (Halt)"),
    "step Type real": ("[command_tables.T]\nCommand = [{ Type = 5.0, Position = 1.0, Velocity = 1.0 }]\n",
                       "command_tables.T.Command[1].Type = 5.0", "allowed: an integer"),
    "step Position nan": ("[command_tables.T]\nCommand = [{ Type = 5, Position = nan, Velocity = 10.0 }]\n",
                          "command_tables.T.Command[1].Position = nan", "allowed: a finite number"),
    "step Position too far": ("[command_tables.T]\nCommand = [{ Type = 6, Position = 2e12, Velocity = 10.0 }]\n",
                              "command_tables.T.Command[1].Position = 2000000000000.0", "allowed: a finite number within +-1e+12"),
    "step Velocity inf": ("[command_tables.T]\nCommand = [{ Type = 7, Velocity = inf, Duration = 1.0 }]\n",
                          "command_tables.T.Command[1].Velocity = inf", "allowed: a finite number"),
    "step positioning without velocity": ("[command_tables.T]\nCommand = [{ Type = 5, Position = 10.0 }]\n",
                                          "command_tables.T.Command[1].Velocity = 0.0", "a velocity > 0"),
    "step Wait without duration": ("[command_tables.T]\nCommand = [{ Type = 151 }]\n",
                                   "command_tables.T.Command[1].Duration = 0.0", "a time in [0.001, 64800] s"),
    "step NextStep 2": ("[command_tables.T]\nCommand = [{ Type = 2, NextStep = 2 }]\n",
                        "command_tables.T.Command[1].NextStep = 2", "0 (complete the step) or 1 (blend)"),
    "step blend after velocity": ("[command_tables.T]\nCommand = [{ Type = 7, Velocity = 5.0, Duration = 1.0, "
                                  "NextStep = 1 }]\n",
                                  "command_tables.T.Command[1].NextStep = 1", "only positioning steps blend"),
    # a tag set twice: as a dotted key and in a nested table
    "dotted and nested key": ('[axes.A]\n"DynamicLimits.MaxVelocity" = 100.0\n[axes.A.DynamicLimits]\n'
                              "MaxVelocity = 200.0\n",
                              "axes.A.DynamicLimits.MaxVelocity = 200.0",
                              'already set by axes.A.DynamicLimits.MaxVelocity = 100.0'),
    # files named by the project stay in its folder unless allowed
    "state_file up": ('[controller]\nstate_file = "../elsewhere.state.json"\n',
                      'controller.state_file = "../elsewhere.state.json"', "allowed: a file in the project's folder"),
    "state_file absolute": ('[controller]\nstate_file = "/tmp/x.state.json"\n',
                            'controller.state_file = "/tmp/x.state.json"', "--allow-outside-paths"),
    "cam csv up": (T1500 + '[cams.C]\ncsv = "../../etc/passwd"\n', 'cams.C.csv = "../../etc/passwd"',
                   "allowed: a file in the project's folder or below it"),
}


@pytest.mark.parametrize("case", list(DEFECT_7))
def test_project_configuration_that_must_not_be_accepted_defect_7(tmp_path, case):
    """Issue 8 defect 7: each gives one clear problem naming the file, the key path and what is allowed."""
    text, key_and_value, allowed = DEFECT_7[case]
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    message = only_problem(path)
    assert message.startswith(f"{path}: {key_and_value}"), message
    assert allowed in message, message
    with pytest.raises(ProjectError):
        load_project(path)


def test_project_valid_cycles_at_the_ends_of_the_ranges_load_defect_7(tmp_path):
    path = write(tmp_path, "[controller]\nservo_cycle = 0.0001\napp_cycle = 1.0\n")
    ctl = load_project(path)
    assert ctl.servo_cycle == 0.0001 and ctl.app_cycle == pytest.approx(1.0)
    path = write(tmp_path, "[controller]\nservo_cycle = 0.032\napp_cycle = 0.064\n")
    assert load_project(path).servo_cycle == 0.032


def test_project_valid_cam_and_command_table_still_load_defect_7(tmp_path):
    path = write(tmp_path, T1500 + "[cams.C]\npoints = [[0.0, 0.0], [90, 1.0], [180.0, 0.0]]\n"
                 "segments = [{ xmin = 200.0, xmax = 300.0, a0 = 0.0, a1 = 0.01 }]\ninterpolation_mode = 1\n")
    assert check_project(path) == []
    path = write(tmp_path, "[command_tables.T]\nCommand = [{ Type = 5, Position = 1.0, Velocity = 10.0, NextStep = 1 },"
                           " { Type = 7, Velocity = -5.0, Duration = 0.5 }, { Type = 151, Duration = 64800 }, {}]\n")
    ctl = load_project(path)
    assert ctl.command_tables["T"].Command[3].Duration == 64800.0


def test_project_paths_outside_the_project_folder_need_the_option_defect_8(tmp_path):
    project = tmp_path / "project"
    project.mkdir()
    (tmp_path / "knife.csv").write_text("0,0\n180,50\n360,0\n")
    path = write(project, '[controller]\nfamily = "S7-1500T"\nstate_file = "../machine.state.json"\n'
                 '[cams.C]\ncsv = "../knife.csv"\n')
    problems = check_project(path)
    assert len(problems) == 2 and all("allowed: a file in the project's folder" in p for p in problems)
    ctl = load_project(path, allow_outside_paths=True)
    assert ctl.state_file == str(project / "../machine.state.json")
    assert ctl.cams["C"].Point[3].x == 360.0
    # inside the folder (also in a sub-folder) is fine without the option
    (project / "cams").mkdir()
    (project / "cams" / "knife.csv").write_text("0,0\n180,50\n360,0\n")
    path = write(project, '[controller]\nfamily = "S7-1500T"\nstate_file = "state/m.json"\n'
                          '[cams.C]\ncsv = "cams/knife.csv"\n')
    assert check_project(path) == []


def test_project_a_link_that_points_out_of_the_project_folder_is_refused_defect_8(tmp_path):
    project = tmp_path / "project"
    project.mkdir()
    (tmp_path / "secret.csv").write_text("0,0\n1,1\n")
    (project / "cam.csv").symlink_to(tmp_path / "secret.csv")
    path = write(project, T1500 + '[cams.C]\ncsv = "cam.csv"\n')
    assert "allowed: a file in the project's folder" in only_problem(path)


def test_project_a_cam_csv_that_is_no_point_list_is_not_echoed_defect_8(tmp_path):
    """The error names the line and the reason, never the content of the file."""
    (tmp_path / "notes.csv").write_text("root:x:0:0:root:/root:/bin/bash\nhunter2:secret-token-1234\n")
    path = write(tmp_path, T1500 + '[cams.C]\ncsv = "notes.csv"\n')
    message = only_problem(path)
    assert message.endswith("notes.csv, line 2: field 1 is not a number"), message
    assert "hunter2" not in message and "secret-token" not in message and "/bin/bash" not in message


def test_project_toml_syntax_error_excerpt_is_bounded(tmp_path):
    path = write(tmp_path, '[axes.A]\n"Actor.Type" = ' + "x" * 5000 + "\n")
    message = only_problem(path)
    assert "line 2" in message and len(message) < 400


# --- size limits, checked before the expensive work ------------------------------------------------------

def test_project_a_too_large_project_file_is_refused_at_once_defect_7(tmp_path):
    from plcmotion.project_rules import MAX_FILE_BYTES
    path = tmp_path / "big.toml"
    path.write_bytes(b"# padding\n" * (MAX_FILE_BYTES // 10 + 1))
    started = time.perf_counter()
    message = only_problem(path)
    assert time.perf_counter() - started < 1.0
    assert message.startswith(f"{path}: the file has ") and f"at most {MAX_FILE_BYTES} bytes" in message


def test_project_a_project_file_of_too_many_lines_is_refused_before_parsing_defect_7(tmp_path):
    from plcmotion.project_rules import MAX_LINES
    path = write(tmp_path, "".join(f"[axes.A{i}]\n" for i in range(MAX_LINES + 1)))
    started = time.perf_counter()
    message = only_problem(path)
    assert time.perf_counter() - started < 1.0
    assert f"{MAX_LINES + 2} lines; allowed: at most {MAX_LINES} lines" in message


def test_project_too_many_technology_objects_are_refused_before_creating_any_defect_7(tmp_path):
    path = write(tmp_path, "".join(f"[axes.A{i}]\n" for i in range(1001)) + "[command_tables.T]\n")
    started = time.perf_counter()
    message = only_problem(path)
    assert time.perf_counter() - started < 2.0
    assert "1002 technology objects; allowed: at most 1000" in message


@pytest.mark.parametrize("text, expected", [
    ("a = " + "[" * 3000 + "]" * 3000 + "\n", "nested too deeply"),
    ("[axes.A]\nx = " + "{ y = " * 30 + "1" + " }" * 30 + "\n", "levels deep; allowed: at most 12"),
    ("[trace]\nsignals = [" + ", ".join(['"A.Position"'] * 5000) + "]\n", "a list of 5000 items; allowed: at most 4096"),
])
def test_project_deep_nesting_and_long_lists_are_refused_defect_7(tmp_path, text, expected):
    path = write(tmp_path, text)
    assert expected in only_problem(path)


def test_project_cli_check_needs_the_flag_for_outside_paths_defect_8(tmp_path, capsys):
    from plcmotion.cli import main
    project = tmp_path / "project"
    project.mkdir()
    path = write(project, '[controller]\nstate_file = "../machine.state.json"\n')
    assert main(["check", str(path)]) == 1
    assert "--allow-outside-paths" in capsys.readouterr().err
    assert main(["check", "--allow-outside-paths", str(path)]) == 0


def test_project_an_axis_is_not_its_own_leading_value_s6_1_3(tmp_path):
    """The leading values of a synchronous axis are other technology objects (S7-1500T V5 §6.1.3)."""
    path = write(tmp_path, T1500 + '[axes.M]\n[axes.S]\ntype = "synchronous"\nleading_values = ["S"]\n')
    assert only_problem(path).startswith(f'{path}: axes.S.leading_values: "S" is not a technology object of '
                                         f"this file; allowed: M")


@pytest.mark.parametrize("value", ["[]", "{}", "1", "[[1]]"])
def test_project_an_axis_type_of_the_wrong_kind_is_a_message_config_fuzz(tmp_path, value):
    """Found by the config fuzz: ``type = []`` raised TypeError (unhashable) before the checks."""
    path = write(tmp_path, f"[axes.A]\ntype = {value}\n")
    assert only_problem(path).startswith(f"{path}: axes.A.type = {value}: allowed: one of \"positioning\"")


@pytest.mark.parametrize("value", ["0", '"M"', "true"])
def test_project_leading_values_of_the_wrong_kind_are_a_message_config_fuzz(tmp_path, value):
    """Found by the config fuzz: ``leading_values = 0`` raised TypeError (int not iterable)."""
    path = write(tmp_path, T1500 + f'[axes.M]\n[axes.S]\ntype = "synchronous"\nleading_values = {value}\n')
    assert only_problem(path).startswith(f"{path}: axes.S.leading_values = {value}: allowed: a list of names")
