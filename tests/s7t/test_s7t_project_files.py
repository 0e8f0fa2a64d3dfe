"""Project files of the S7-Technology family: configuration errors, traces and the example project.

The keys of an axis table are the expert-list names of S7-Technology V4.1 §9.4; technology DB numbers
§2.5.3 (DB1 is the MCDevice DB, §7.10); technology DB members §7.1/§7.2; DB update §7.11.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from plcmotion.cli import main
from plcmotion.project import check_project, load_project
from plcmotion.trace import Trace, read_csv

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
PNG = b"\x89PNG\r\n\x1a\n"

HEAD = '[controller]\nfamily = "S7-Technology"\nservo_cycle = 0.002\napp_cycle = 0.004\n\n'


def _problems(tmp_path, body: str) -> list[str]:
    path = tmp_path / "machine.toml"
    path.write_text(HEAD + body, encoding="utf-8")
    problems = check_project(path)
    assert all(p.startswith(f"{path}: ") for p in problems)          # every line names the file
    return [p.split(": ", 1)[1] for p in problems]


def test_s7t_project_unknown_tag_suggests_the_expert_list_name(tmp_path):
    """S7-Technology V4.1 §9.4: a misspelt parameter is named with its key path and the nearest names."""
    problems = _problems(tmp_path, '[axes.Table]\n"TypeOfAxis.MaxVelocity.maximun" = 500.0\n')
    assert len(problems) == 1
    assert problems[0].startswith("axes.Table.TypeOfAxis.MaxVelocity.maximun: unknown parameter (value 500.0)")
    assert "did you mean TypeOfAxis.MaxVelocity.maximum" in problems[0]


@pytest.mark.parametrize("key, value, allowed", [
    ("override.velocity", "250.0", "allowed: real in [0.0, 200.0]"),                   # number 4142: 0 ... 200 %
    ("TypeOfAxis.NumberOfDataSets.DataSet_1.Gear.numFactor", "0", "allowed: integer in [1, 2147483647]"),
    ("DBNumber", "70000", "allowed: integer in [1, 65535]"),
    ("userdefaultdynamics.profile", "1", "allowed: one of 66, 67"),                   # EnumProfile ValueDint
])
def test_s7t_project_value_out_of_range_names_the_range(tmp_path, key, value, allowed):
    """S7-Technology V4.1 §9.4 (ranges of the parameter list), §9.4.12 (ENUM ValueDint): the message names
    the full key path, the value and the allowed range."""
    problems = _problems(tmp_path, f'[axes.Table]\n"{key}" = {value}\n')
    assert problems == [f"axes.Table.{key} = {value}: {allowed}"]


def test_s7t_project_nested_table_gives_the_same_key_path(tmp_path):
    """S7-Technology V4.1 §9.4: a tag written as a nested table is reported under its dotted path."""
    problems = _problems(tmp_path, "[axes.Table.userdefaultdynamics]\npositiveaccel = -5.0\n")
    assert problems == ["axes.Table.userdefaultdynamics.positiveaccel = -5.0: allowed: real in (0.0, 1000000000000.0]"]


@pytest.mark.parametrize("key, value, hint", [
    ("swlimit.state", "1.0", "(an integer: write 1, not 1.0)"),                         # EnumActiveInactive
    ("override.velocity", '"fast"', "allowed: real in [0.0, 200.0]"),
])
def test_s7t_project_wrong_type_is_refused(tmp_path, key, value, hint):
    """S7-Technology V4.1 §9.4: ENUM parameters take their integer ValueDint, REAL parameters numbers."""
    problems = _problems(tmp_path, f'[axes.Table]\n"{key}" = {value}\n')
    assert len(problems) == 1 and problems[0].startswith(f"axes.Table.{key} = {value}: ") and hint in problems[0]


def test_s7t_project_duplicate_db_number_names_both_objects(tmp_path):
    """S7-Technology V4.1 §2.5.3: every technology object has its own technology DB; DB1 is the MCDevice DB
    (§7.10).  A number declared twice is found also when the first table has problems of its own."""
    problems = _problems(tmp_path, "[axes.Table]\nDBNumber = 10\n\n[axes.Feed]\nDBNumber = 10\n\n"
                                   "[axes.Spindle]\nDBNumber = 1\n")
    assert problems == [
        "axes.Feed.DBNumber = 10: allowed: a value no other object of the file has; axes.Table.DBNumber = 10",
        "axes.Spindle.DBNumber = 1: allowed: a DB number no other technology object has; DB1 is the MCDevice DB"]
    problems = _problems(tmp_path, '[axes.Table]\nDBNumber = 10\n"override.velocity" = 300.0\n\n'
                                   "[axes.Feed]\nDBNumber = 10\n")
    assert problems == ["axes.Table.override.velocity = 300.0: allowed: real in [0.0, 200.0]",
                        "axes.Feed.DBNumber = 10: allowed: a value no other object of the file has; "
                        "axes.Table.DBNumber = 10"]


def test_s7t_device_refuses_a_db_number_in_use():
    """S7-Technology V4.1 §2.5.3: through the Python API a taken DB number is a configuration error naming the
    owner."""
    from plcmotion import Controller
    from plcmotion.kernel.errors import ConfigurationError

    ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
    ctl.add_positioning_axis("Table", {"DBNumber": 10})
    with pytest.raises(ConfigurationError, match="DB10 is the technology DB of Table"):
        ctl.add_positioning_axis("Feed", {"DBNumber": 10})


def test_s7t_project_technology_must_fit_the_type(tmp_path):
    """S7-Technology V4.1 §3.1.1: a synchronization axis (technology 2) is declared as type = "synchronous"."""
    problems = _problems(tmp_path, "[axes.Table]\nWizard.Technology = 2\n")
    assert problems == ['axes.Table.Wizard.Technology = 2: allowed: 0 (speed-controlled) or 1 (positioning) for '
                        'type = "positioning"; a synchronization axis is type = "synchronous"']


def test_s7t_project_trace_signals_are_technology_db_members(tmp_path):
    """S7-Technology V4.1 §7.1, §7.2, §7.11: the trace columns of an axis are its technology DB members as the
    program reads them (the values of the last DB update); an unknown member is refused with examples."""
    body = ("[axes.Table]\nWizard.Virtual = 1\n\n[axes.Fan]\nWizard = { Technology = 0, Virtual = 1 }\n\n"
            '[trace]\nsignals = ["Table.ActualPosition", "Table.Statusword.Standstill", "Fan.CommandVelocity"]\n')
    assert _problems(tmp_path, body) == []
    bad = _problems(tmp_path, body.replace('"Fan.CommandVelocity"', '"Fan.ActualPosition"'))
    assert len(bad) == 1 and bad[0].startswith('trace.signals[2] = "Fan.ActualPosition": Fan.ActualPosition is not '
                                               "a tag of the S7-Technology axis")
    assert _problems(tmp_path, body) == []
    ctl = load_project(tmp_path / "machine.toml")
    table = ctl.axes["Table"]
    trace = Trace(ctl).start()                      # the default columns of the family
    ctl.run(0.02)
    trace.stop()
    assert "Table.CommandPosition" in trace.columns and "Table.Statusword.DriveEnabled" in trace.columns
    assert "Fan.CommandVelocity" in trace.columns and "Fan.CommandPosition" not in trace.columns
    assert table.tag("UpdateCounter") == table.db.UpdateCounter == 5    # every 2nd IPO cycle of 2 ms: 20 ms


def test_s7t_project_example_runs_through_the_cli(tmp_path, capsys):
    """S7-Technology V4.1 §6.2.6 (Mode 1 append, Mode 2 overlay), §6.2.10, §6.9.2 (DoneFlag), §7.11 (UpdateCounter,
    OB65): the example project checks, runs 7 s without error and writes its trace and plot."""
    project, program = EXAMPLES / "s7t_positioning.toml", EXAMPLES / "s7t_positioning_program.py"
    assert main(["check", str(project)]) == 0
    assert "Table (positioning axis, PROFIdrive), Conveyor (speed-controlled axis, PROFIdrive)" in \
        capsys.readouterr().out
    csv, png = tmp_path / "t.csv", tmp_path / "t.png"
    code = main(["run", str(project), str(program), "--duration", "7", "--trace", str(csv), "--plot", str(png),
                 "--quiet"])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "Table: enabled, CommandPosition 0, ActualPosition" in out and "no error" in out
    assert "Conveyor: enabled, CommandVelocity 400" in out
    columns, rows = read_csv(csv)
    data = dict(zip(columns, rows.T))
    assert len(rows) == 3500                                              # 7 s of 2 ms IPO cycles
    assert data["Table.CommandPosition"].max() == pytest.approx(550.0)
    assert data["Conveyor.CommandVelocity"].max() == pytest.approx(1000.0)
    assert png.read_bytes()[:8] == PNG


def test_s7t_project_run_reports_technology_db_errors(tmp_path, capsys):
    """S7-Technology V4.1 §5.12, §7.1, §7.12.1: an error that only the technology DB holds is in the summary
    of `plcmotion run`.  A hydraulic axis disabled with MC_Power StopMode 3 notes 8040 in its technology DB
    (§6.2.1) without any alarm of the axis; the summary names the ErrorID, its message and the ErrorBuffer."""
    project, program = tmp_path / "press.toml", tmp_path / "press.py"
    project.write_text(HEAD + '[axes.Press]\nWizard.DriveTechnology = 1\n"TypeOfAxis.Homing.referencingNecessary" = 0\n'
                       '[axes.Table]\nWizard.Virtual = 1\n', encoding="utf-8")
    program.write_text(
        "from plcmotion.s7t import MC_Power\n"
        "power, other = MC_Power(), MC_Power()\n\n"
        "@ctl.program\n"
        "def ob1():\n"
        "    power(Axis=axes['Press'], Enable=ctl.time < 0.5, StopMode=3)\n"
        "    other(Axis=axes['Table'], Enable=True)\n", encoding="utf-8")
    assert main(["run", str(project), str(program), "--duration", "1", "--quiet"]) == 0
    out = capsys.readouterr().out
    press = next(line for line in out.splitlines() if line.strip().startswith("Press:"))
    table = next(line for line in out.splitlines() if line.strip().startswith("Table:"))
    assert press.startswith("  Press: disabled,")
    assert press.endswith('technology DB error 16#8040 "The axis / external encoder are disabled, or the wrong mode '
                          'is set" (ErrorBuffer 16#8040)'), press
    assert table.endswith("no error")


def test_s7t_project_example_program_append_overlay_and_db_snapshots():
    """S7-Technology V4.1 §6.2.6: Mode 1 stops at the first target, Mode 2 passes it at the lower velocity;
    §6.9.2 DoneFlag[1] toggles; §7.11 the program sees a new snapshot per DB update; OB65 runs after each."""
    from plcmotion.cli import load_program

    ctl = load_project(EXAMPLES / "s7t_positioning.toml")
    load_program(ctl, str(EXAMPLES / "s7t_positioning_program.py"))
    ctl.run(7.0)
    state = ctl.s7t_example
    assert state["step"] == "done" and state["stopped_at_150"]
    assert state["passed_450"] == pytest.approx(100.0)                  # the overlaid command's velocity
    assert state["done_flag"] is True
    assert state["snapshots"] == 1750                                   # 7 s / (2 x 2 ms): one per OB1 cycle
    assert 0.0 < state["max_following_error"] < 1.0
