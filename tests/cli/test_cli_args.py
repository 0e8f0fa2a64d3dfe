"""Issue 8 defect 10: every bad CLI argument gets a one-line error before the run starts, exit code 2;
defect 6 at the CLI: a program that stops the controller (sys.exit, Ctrl-C) is reported, exit code != 0."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from plcmotion.cli import main

MARK = "PROGRAM-RAN"


@pytest.fixture
def project(tmp_path: Path) -> tuple[str, str]:
    toml = tmp_path / "p.toml"
    toml.write_text('[controller]\nservo_cycle = 0.001\napp_cycle = 0.004\nstate_file = "p.state.json"\n'
                    '[axes.Axis_1]\n"Actor.Type" = 1\n')
    program = tmp_path / "prog.py"
    program.write_text("import sys\n"
                       "@ctl.program\n"
                       "def main():\n"
                       f"    print({MARK!r}, flush=True)\n")
    return str(toml), str(program)


def _one_line_error(capsys, *needles: str) -> str:
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert MARK not in captured.out, "the run started before the argument was rejected"
    assert len(err.splitlines()) == 1, err
    for needle in needles:
        assert needle in err, err
    return err


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "-1", "0", "-0.0", "1e300"])
def test_cli_defect10_run_duration_rejected(project, capsys, value):
    """Defect 10: --duration nan|inf|-1|0 gave a traceback or one silent cycle; 1e300 would never end."""
    code = main(["run", *project, "--duration", value, "--quiet"])
    assert code == 2
    _one_line_error(capsys, "--duration")


@pytest.mark.parametrize("args", [["--duration", "abc"], ["--every", "1.5"], ["--bogus"], []],
                         ids=["duration-text", "every-float", "unknown-option", "no-duration"])
def test_cli_defect10_argparse_errors_are_one_line_exit_2(project, capsys, args):
    assert main(["run", *project, *args, "--quiet"] if args != [] else ["run", *project]) == 2
    _one_line_error(capsys, "plcmotion run: error:")


@pytest.mark.parametrize("value", ["0", "-3"])
def test_cli_defect10_run_every_rejected(project, capsys, tmp_path, value):
    code = main(["run", *project, "--duration", "0.1", "--every", value, "--trace", str(tmp_path / "t.csv"),
                 "--quiet"])
    assert code == 2
    _one_line_error(capsys, "--every")
    assert not (tmp_path / "t.csv").exists()


@pytest.mark.parametrize("option, name", [("--trace", "t.csv"), ("--plot", "t.png")])
def test_cli_defect10_output_into_missing_folder_rejected_before_the_run(project, capsys, tmp_path, option, name):
    """Defect 10: --plot/--trace into a missing folder raised a traceback after the whole run."""
    target = tmp_path / "missing" / "deeper" / name
    assert main(["run", *project, "--duration", "0.1", option, str(target), "--quiet"]) == 2
    _one_line_error(capsys, option, "missing")


@pytest.mark.parametrize("option", ["--trace", "--plot"])
def test_cli_defect10_output_is_a_folder_or_under_a_file(project, capsys, tmp_path, option):
    assert main(["run", *project, "--duration", "0.1", option, str(tmp_path), "--quiet"]) == 2
    _one_line_error(capsys, option)
    a_file = tmp_path / "file.txt"
    a_file.write_text("x")
    assert main(["run", *project, "--duration", "0.1", option, str(a_file / "t.out"), "--quiet"]) == 2
    _one_line_error(capsys, option)


def test_cli_defect10_plot_format_and_same_file(project, capsys, tmp_path):
    assert main(["run", *project, "--duration", "0.1", "--plot", str(tmp_path / "t.xyz"), "--quiet"]) == 2
    _one_line_error(capsys, "--plot", "png")
    same = str(tmp_path / "t.png")
    assert main(["run", *project, "--duration", "0.1", "--trace", same, "--plot", same, "--quiet"]) == 2
    _one_line_error(capsys, "--trace", "--plot")


@pytest.mark.parametrize("args", [["--signal", "Axis_1.Position"], ["--every", "2"]])
def test_cli_defect10_trace_options_without_trace_or_plot(project, capsys, args):
    """--signal/--every without --trace or --plot were ignored silently."""
    assert main(["run", *project, "--duration", "0.1", *args, "--quiet"]) == 2
    _one_line_error(capsys, "--trace", "--plot")


def test_cli_defect10_valid_run_still_works(project, capsys, tmp_path):
    csv, png = tmp_path / "out" / "t.csv", tmp_path / "out" / "t.png"
    csv.parent.mkdir()
    assert main(["run", *project, "--duration", "0.1", "--trace", str(csv), "--plot", str(png), "--every", "2",
                 "--quiet"]) == 0
    out = capsys.readouterr().out
    assert MARK in out and "mode RUN" in out
    assert csv.exists() and png.exists()


@pytest.mark.parametrize("where", ["under-a-file", "dev-null"])
def test_cli_defect10_demo_out_unwritable(capsys, tmp_path, where):
    """Defect 10: demo --out to a place that cannot be written: one line, exit 2, before the demo runs."""
    if where == "under-a-file":
        a_file = tmp_path / "file.txt"
        a_file.write_text("x")
        out = a_file / "demo"
    else:
        out = Path(os.devnull) / "demo"
    assert main(["demo", "--out", str(out)]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert len(captured.err.strip().splitlines()) == 1 and "--out" in captured.err


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write anywhere")
def test_cli_defect10_demo_out_read_only_folder(capsys, tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        assert main(["demo", "--out", str(ro)]) == 2
    finally:
        ro.chmod(0o700)
    assert "--out" in capsys.readouterr().err


def test_cli_defect10_check_missing_project(capsys, tmp_path):
    assert main(["check", str(tmp_path / "nope.toml")]) != 0
    err = capsys.readouterr().err
    assert "nope.toml" in err and "Traceback" not in err


# --- defect 6 at the command line -------------------------------------------------------------------------
def test_cli_defect6_run_reports_sys_exit_in_a_program(project, capsys, tmp_path):
    """Defect 6: `plcmotion run` exited 0 silently when a program called sys.exit(0).  Now the controller goes
    to STOP (a PLC program cannot end the controller) and the CLI reports it with exit code 1."""
    toml, _ = project
    program = tmp_path / "exits.py"
    program.write_text("import sys\n@ctl.program\ndef main():\n    if ctl.time > 0.05:\n        sys.exit(0)\n")
    code = main(["run", toml, str(program), "--duration", "0.2", "--quiet"])
    captured = capsys.readouterr()
    assert code == 1
    assert "mode STOP" in captured.out
    assert "controller in STOP" in captured.err and "SystemExit" in captured.err


def test_cli_defect6_run_sys_exit_while_loading_the_program(project, capsys, tmp_path):
    toml, _ = project
    program = tmp_path / "exits.py"
    program.write_text("import sys\nsys.exit(0)\n")
    assert main(["run", toml, str(program), "--duration", "0.2", "--quiet"]) == 2
    assert "sys.exit(0)" in capsys.readouterr().err


def test_cli_defect6_run_keyboard_interrupt(project, capsys, tmp_path):
    """Ctrl-C in a program: the controller goes to STOP, the trace written so far is kept, exit 130."""
    toml, _ = project
    program = tmp_path / "ctrl_c.py"
    program.write_text("@ctl.program\ndef main():\n    if ctl.time > 0.05:\n        raise KeyboardInterrupt\n")
    csv = tmp_path / "t.csv"
    assert main(["run", toml, str(program), "--duration", "1", "--trace", str(csv), "--quiet"]) == 130
    captured = capsys.readouterr()
    assert "interrupted" in captured.err and "STOP" in captured.err
    assert csv.exists() and len(csv.read_text().splitlines()) > 10


def test_cli_defect6_run_reports_cycle_overruns(project, capsys, tmp_path):
    """The cycle watchdog at the CLI: overruns are summed up after the run (not one warning per cycle)."""
    toml, _ = project
    program = tmp_path / "slow.py"
    program.write_text("@ctl.program\ndef main():\n    if ctl.app_cycles == 3:\n"
                       "        ctl.inject_cycle_overrun(cycles=4)\n")
    assert main(["run", toml, str(program), "--duration", "0.1", "--quiet"]) == 0
    captured = capsys.readouterr()
    assert "4 cycle time overruns" in captured.out
    assert "Warning" not in captured.err


# --- review of issue 8 (found by trying the CLI as a user) -----------------------------------------------
@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux /proc")
def test_cli_defect10_demo_out_into_a_folder_nobody_can_write(capsys):
    """Defect 10 (review): `demo --out /proc` passed the permission check as root (os.access says yes) and
    ended in a FileNotFoundError traceback after the whole demo; it is rejected before the demo runs."""
    assert main(["demo", "--out", "/proc"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert len(captured.err.strip().splitlines()) == 1 and "--out /proc" in captured.err


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full (a disk that is always full)")
def test_cli_defect10_trace_write_error_during_the_run_is_reported_in_one_line(project, capsys):
    """Defect 10 (review): a trace file that cannot be written during the run (disk full) gave an OSError
    traceback at the end; now the run completes, the controller stays in RUN and one line says why, exit 1."""
    code = main(["run", *project, "--duration", "0.05", "--trace", "/dev/full", "--quiet"])
    captured = capsys.readouterr()
    assert code == 1
    assert "Traceback" not in captured.err and "mode RUN" in captured.out
    lines = [line for line in captured.err.splitlines() if line.strip()]
    assert len(lines) == 1 and "--trace /dev/full" in lines[0] and "No space left" in lines[0], captured.err


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero (an endless file)")
def test_cli_defect7_check_of_an_endless_file_ends_with_the_size_limit(capsys):
    """Defect 7 (review): `plcmotion check /dev/zero` read forever (the size limit looked at st_size only, which
    is 0 for a device); the file is read up to the limit and rejected."""
    import threading

    result: list[int] = []
    worker = threading.Thread(target=lambda: result.append(main(["check", "/dev/zero"])), daemon=True)
    worker.start()
    worker.join(10.0)
    assert result == [1], "check did not end within 10 s"
    assert "allowed: at most" in capsys.readouterr().err


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux /proc")
@pytest.mark.parametrize("option, name", [("--plot", "p.png"), ("--trace", "t.csv")])
def test_cli_defect10_output_into_a_folder_nobody_can_write_rejected_before_the_run(project, capsys, option, name):
    """Defect 10 (review): as root os.access says any folder is writable, so --plot /proc/p.png ran the whole
    project and then failed; both options are refused before the run with one line and exit code 2."""
    code = main(["run", *project, "--duration", "0.05", option, f"/proc/{name}", "--quiet"])
    assert code == 2
    err = _one_line_error(capsys, f"{option} /proc/{name}")
    assert err.startswith("plcmotion run: ")
