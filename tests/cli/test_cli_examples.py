"""Smoke tests of what a user runs first: the README commands, the demo, the CLI and every example."""
from __future__ import annotations

import re
import runpy
from pathlib import Path

import pytest

from plcmotion.cli import main
from plcmotion.trace import read_csv

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
PNG = b"\x89PNG\r\n\x1a\n"


def test_cli_readme_has_two_setup_commands_and_ci_runs_the_test_command():
    readme = (ROOT / "README.md").read_text()
    setup = readme.split("## Set up", 1)[1].split("\n## ", 1)[0]
    commands = re.findall(r"```sh\n(.+?)\n```", setup, re.S)
    assert len(commands) == 2
    demo, tests = commands
    assert "plcmotion demo" in demo and "pytest" in tests
    ci = (ROOT / ".ci" / "run").read_text()
    assert tests in ci.splitlines()                 # .ci/run runs exactly the README's test command


def test_cli_demo_writes_trace_plot_and_summary(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "16#8402/16#0008" in out                  # the invalid command and its ErrorID (§12.8)
    assert "CommandAborted" in out and "16#8002/16#000E" in out
    columns, rows = read_csv(tmp_path / "trace.csv")
    assert columns[0] == "time" and "Axis_1.Position" in columns
    assert len(rows) > 10000
    assert (tmp_path / "trace.png").read_bytes()[:8] == PNG


@pytest.mark.parametrize("project, program, duration", [
    ("pto_stepper.toml", "pto_stepper_program.py", 8.0),
    ("profidrive_servo.toml", "profidrive_servo_program.py", 12.0),
    ("flying_saw.toml", "flying_saw_program.py", 8.0),
    ("rotary_knife.toml", "rotary_knife_program.py", 4.0),
])
def test_cli_examples_run_without_errors(tmp_path, capsys, project, program, duration):
    csv, png = tmp_path / "t.csv", tmp_path / "t.png"
    code = main(["run", str(EXAMPLES / project), str(EXAMPLES / program), "--duration", str(duration),
                 "--trace", str(csv), "--plot", str(png), "--quiet"])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "no error" in out and "mode RUN" in out
    columns, rows = read_csv(csv)
    assert len(rows) == round(duration / 0.001)
    assert png.read_bytes()[:8] == PNG


@pytest.mark.parametrize("project", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_cli_example_projects_check_ok(project, capsys):
    assert main(["check", str(EXAMPLES / project)]) == 0
    assert "OK" in capsys.readouterr().out


def test_cli_check_reports_problems(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[axes.A.DynamicLimits]\nMaxVelocity = -1.0\n")
    assert main(["check", str(bad)]) == 1
    err = capsys.readouterr().err
    assert "axes.A.DynamicLimits.MaxVelocity = -1.0" in err and "allowed" in err


def test_cli_run_reports_a_broken_program_without_traceback(tmp_path, capsys):
    prog = tmp_path / "prog.py"
    prog.write_text("def setup(ctl):\n    pass\n")
    code = main(["run", str(EXAMPLES / "pto_stepper.toml"), str(prog), "--duration", "0.1", "--quiet"])
    assert code == 2
    assert "registers no program" in capsys.readouterr().err


def test_cli_run_reports_controller_stop(tmp_path, capsys):
    prog = tmp_path / "prog.py"
    prog.write_text("def setup(ctl):\n    @ctl.program\n    def main():\n        raise RuntimeError('sensor wiring')\n")
    code = main(["run", str(EXAMPLES / "pto_stepper.toml"), str(prog), "--duration", "0.1", "--quiet"])
    assert code == 1
    assert "sensor wiring" in capsys.readouterr().err


def test_cli_quickstart_example_runs(capsys):
    runpy.run_path(str(EXAMPLES / "quickstart.py"), run_name="__main__")
    out = capsys.readouterr().out
    assert "ActualPosition = 100.0" in out or "ActualPosition = 99.99" in out
    assert "ErrorID = 16#0000" in out


def test_cli_readme_project_example_is_valid(tmp_path):
    """The project file shown in the README loads."""
    from plcmotion.project import check_project

    readme = (ROOT / "README.md").read_text()
    block = re.search(r"```toml\n(.+?)\n```", readme, re.S).group(1)
    path = tmp_path / "readme.toml"
    path.write_text(block)
    assert check_project(path) == []


def test_cli_readme_python_example_runs():
    """The Python API example of the README runs as shown."""
    readme = (ROOT / "README.md").read_text()
    block = re.search(r"## Python API\n\n```python\n(.+?)\n```", readme, re.S).group(1)
    exec(compile(block, "README.md", "exec"), {})


def test_cli_readme_synchronous_operation_example_runs(capsys):
    """The S7-1500T example of the README runs as shown and reaches synchronism at the positions."""
    readme = (ROOT / "README.md").read_text()
    block = re.search(r"## Synchronous operation \(S7-1500T\)\n\n```python\n(.+?)\n```", readme, re.S).group(1)
    exec(compile(block, "README.md", "exec"), {})
    flag, deviation = capsys.readouterr().out.split()
    assert flag == "True" and abs(float(deviation)) < 1e-9
