"""``plcmotion serve``: the flags, --virtual equal to ``plcmotion run``, a short paced run on the real
clock, the pacing tags in the program, and the controlled shutdown on SIGINT/SIGTERM in a subprocess.

Real-clock checks only bound what holds on a loaded machine: a paced run never ends before its time."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from plcmotion.cli import _load, load_program, main
from plcmotion.project import load_project
from plcmotion.services import make_loop
from plcmotion.trace import Trace

from ._fixtures import PROGRAM, PROJECT

SRC = Path(__file__).resolve().parents[2] / "src"


@pytest.fixture
def project(tmp_path):
    (tmp_path / "p.toml").write_text(PROJECT)
    (tmp_path / "prog.py").write_text(PROGRAM)
    return tmp_path


def _axis_lines(out: str) -> list[str]:
    return [line for line in out.splitlines() if line.startswith("  ")]


@pytest.mark.parametrize("argv, text", [
    (["--speed", "0"], "--speed 0.0: allowed: a factor in (0, 1000]"),
    (["--speed", "nan"], "--speed nan"),
    (["--virtual", "--speed", "2"], "--speed and --virtual"),
    (["--duration", "-1"], "--duration -1.0: allowed: a finite time > 0 s"),
    (["--tolerate", "-1"], "--tolerate -1"),
    (["--overrun", "halt"], "invalid choice: 'halt'"),
    (["--realtime", "0"], "--realtime 0: allowed: a SCHED_FIFO priority in [1, 99]"),
    (["--realtime", "5", "--virtual"], "--realtime and --virtual"),
])
def test_services_serve_rejects_bad_flags_with_one_line(project, capsys, argv, text):
    assert main(["serve", str(project / "p.toml"), str(project / "prog.py"), *argv]) == 2
    err = capsys.readouterr().err
    assert text in err and len(err.strip().splitlines()) == 1


def test_services_serve_virtual_prints_what_run_prints(project, capsys):
    args = [str(project / "p.toml"), str(project / "prog.py"), "--duration", "0.5"]
    assert main(["run", *args, "--quiet"]) == 0
    run_out = capsys.readouterr().out
    assert main(["serve", *args, "--virtual"]) == 0
    serve_out = capsys.readouterr().out
    assert _axis_lines(serve_out) == _axis_lines(run_out) and len(_axis_lines(run_out)) == 1
    assert "ended by duration" in serve_out and "pacing:" not in serve_out


def test_services_serve_virtual_gives_the_trace_of_run_bit_for_bit(project):
    """The servo-cycle trace of every tag of the axis: ``serve --virtual`` and the loop of ``run``."""
    def controller():
        ctl = load_project(str(project / "p.toml"))
        load_program(ctl, str(project / "prog.py"))
        signals = [f"Axis_1.{t}" for t in ("Position", "Velocity", "Acceleration", "ActualPosition",
                                           "ActualVelocity", "StatusBits.Enable", "StatusBits.ConstantVelocity")]
        return ctl, Trace(ctl, signals).start()

    served, t1 = controller()
    make_loop(served, virtual=True).run(0.6)
    ran, t2 = controller()
    for _ in range(round(0.6 / ran.app_cycle)):          # the loop of cmd_run
        ran.step()
    assert np.array_equal(t1.stop().rows, t2.stop().rows) and len(t1.rows) == 600
    assert t1.rows[-1, 2] == 200.0                       # the axis reached its velocity


def test_services_serve_paced_takes_at_least_the_wall_clock_time(project, capsys):
    """0.3 s of virtual time at real time, then 0.4 s at twice real time: never faster than planned."""
    for duration, speed, least in (("0.3", "1", 0.3), ("0.4", "2", 0.2)):
        t0 = time.monotonic()
        assert main(["serve", str(project / "p.toml"), str(project / "prog.py"), "--duration", duration,
                     "--speed", speed]) == 0
        assert time.monotonic() - t0 >= least
        out = capsys.readouterr().out
        cycles = round(float(duration) * 1000)
        assert f"pacing: {cycles} servo cycles at x{speed}" in out and "ended by duration" in out
    assert not (project / "p.state.json").exists()        # nothing retentive: no state file left behind


def test_services_program_reads_the_pacing_tags(project, capsys):
    (project / "prog.py").write_text(PROGRAM + '''

@ctl.program
def report():
    if abs(ctl.time - 0.1) < 1e-9:
        print(f"Pacing.Cycles {pacing.Cycles} Overruns {pacing.tag('Overruns')} Speed {pacing.Speed}")
''')
    assert main(["serve", str(project / "p.toml"), str(project / "prog.py"), "--duration", "0.12",
                 "--speed", "4"]) == 0
    out = capsys.readouterr().out
    assert "Pacing.Cycles 100 Overruns " in out and "Speed 4.0" in out


def test_services_load_without_program_globals_is_as_run(project):
    ctl = _load(type("A", (), {"project": str(project / "p.toml"), "program": str(project / "prog.py")})())
    assert not isinstance(ctl, int) and ctl.axes["Axis_1"].state == "disabled"


ABSOLUTE_ENCODER = """
[axes.Axis_1."Sensor[1]"]
Type = 1
Parameter.DeterminableRevolutions = 4096
"""

SHUTDOWN_PROGRAM = '''
import atexit
from plcmotion.s7_1200 import MC_Home, MC_MoveVelocity, MC_Power
import json
import os

MARK = os.environ["SERVE_MARK"]


def watch(ctl):
    axis = ctl.axes["Axis_1"]
    samples = []
    ctl.on_post_servo(lambda t: samples.append((t, axis.Velocity, axis.StatusBits.Enable)))

    @ctl.program
    def mark():
        if axis.StatusBits.ConstantVelocity and not os.path.exists(MARK):
            open(MARK, "w").close()

    atexit.register(lambda: Path(MARK + ".json").write_text(json.dumps(samples[-1500:])))


from pathlib import Path


def setup(ctl):
    axis = ctl.axes["Axis_1"]
    power, home, run = MC_Power(), MC_Home(), MC_MoveVelocity()

    @ctl.program
    def main():
        power(Axis=axis, Enable=True, StopMode=0)
        home(Axis=axis, Execute=power.Status, Mode=7, Position=1000.0)     # absolute encoder adjustment
        run(Axis=axis, Execute=home.Done, Velocity=200.0)
    watch(ctl)
'''


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_services_signal_stops_axes_on_their_ramp_saves_retain_and_exits_0(project, sig):
    """SIGINT/SIGTERM: the axis running at 200 mm/s is disabled with the StopMode its MC_Power gave (0:
    emergency stop with the configured EmergencyDeceleration 2000 mm/s^2, S7-1200 V6 §11.1.1), so it
    brakes over 0.1 s instead of losing its enable at speed; then the enable goes off, the state file is
    written and the process exits 0.  The retentive data (S7-1200 V6 §11.1.3: the absolute encoder offset
    of MC_Home mode 7) is in the state file after the exit even where the file was lost during the run."""
    (project / "p.toml").write_text(PROJECT + ABSOLUTE_ENCODER)
    (project / "prog.py").write_text(SHUTDOWN_PROGRAM)
    mark = project / "running"
    state = project / "p.state.json"
    env = {**os.environ, "PYTHONPATH": str(SRC), "SERVE_MARK": str(mark)}
    proc = subprocess.Popen([sys.executable, "-m", "plcmotion", "serve", str(project / "p.toml"),
                             str(project / "prog.py"), "--speed", "2"], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while not mark.exists() and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.02)
        assert mark.exists(), proc.communicate(timeout=10)
        state.unlink()                              # written at the adjustment; the shutdown writes it again
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, err
    assert "ended by shutdown" in out and "Axis_1: disabled" in out
    assert json.loads(state.read_text()) == {"format": "plcmotion-retain-1",
                                             "axes": {"Axis_1": {"AbsEncoderOffset": 1000.0, "HomingDone": True}}}
    samples = json.loads(Path(str(mark) + ".json").read_text())
    last_full = max(i for i, s in enumerate(samples) if s[1] >= 200.0)
    v = np.array([s[1] for s in samples[last_full:]])
    t = np.array([s[0] for s in samples[last_full:]])
    braking = (v > 0) & (v < 200.0)
    assert samples[-1][2] is False and v[-1] == 0.0
    assert 0.095 <= braking.sum() * 0.001 <= 0.101              # 200 mm/s / 2000 mm/s^2 = 0.1 s
    assert np.max(-np.diff(v) / np.diff(t)) <= 2000.0 * (1 + 1e-9)


@pytest.mark.parametrize("refuse", [False, True])
def test_services_serve_realtime_asks_for_sched_fifo_and_runs_on_without_it(project, capsys, monkeypatch, refuse):
    calls = []

    def setscheduler(pid, policy, param):
        calls.append((pid, policy, param.sched_priority))
        if refuse:
            raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(os, "sched_setscheduler", setscheduler)
    assert main(["serve", str(project / "p.toml"), str(project / "prog.py"), "--duration", "0.05", "--speed", "5",
                 "--realtime", "10"]) == 0
    assert calls == [(0, os.SCHED_FIFO, 10)]
    err = capsys.readouterr().err
    assert ("SCHED_FIFO priority 10 refused (Operation not permitted" in err) == refuse
