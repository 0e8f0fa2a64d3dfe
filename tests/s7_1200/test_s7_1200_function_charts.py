"""The function charts of S7-1200 Motion Control V6 §11.1, replayed cycle by cycle against golden traces.

Each chart of the manual (MC_Power §11.1.1.2, MC_Halt §11.1.4.2, MC_MoveAbsolute §11.1.5.2,
MC_MoveRelative §11.1.6.2, MC_MoveVelocity §11.1.7.2, MC_MoveJog §11.1.8.2; catalog
shared/spec/s7-1200.md §4.1-§4.8, scenarios S-PWR-*, S-HALT-*, S-MABS-*, S-MREL-*, S-MVEL-*, S-JOG-*) is a
user program registered with ``@ctl.program``: it calls the chart's instances once per application cycle
(4 ms, servo cycle 1 ms) in the chart's order (instance 1 before instance 2) and records one row per
cycle: the virtual time of the calls, the chart's inputs and outputs right after the calls and the axis
tags Position and Velocity (setpoints) at that moment.  The charts are drawn for a PTO axis (Actor.Type 2,
MaxVelocity 100.0, start/stop velocity 1.0, no jerk limit: trapezoids) with the acceleration and
deceleration the chart states; every chart also runs on a PROFIdrive axis (Actor.Type 1, start/stop
velocity 0, drive "ready" after 20 ms).

Every test does two things:

1. It checks the facts the manual states for the chart explicitly (who shows Done/CommandAborted/
   InVelocity at which call, at which position and velocity; ramp durations from the configured
   dynamics within one application cycle).  A failing check names the manual's text.
2. It compares the run with its golden trace ``tests/golden/<chart>-<drive>.csv`` exactly, character
   for character (floats are written with ``repr``, so bit for bit; the runtime is deterministic).
   Traces longer than 1500 rows are thinned: within stretches where every input/output column is
   unchanged and the velocity changes at a constant rate (standstill, cruise, a ramp), only every 25th
   row (0.1 s) is kept; rows next to any change (an output edge, the start or end of a ramp) are always
   kept.  The header lines starting with ``#`` describe the scenario and the thinning.

Regenerate the golden traces after an intended change of behaviour with::

    PLCMOTION_UPDATE_GOLDEN=1 PYTHONPATH=src python -m pytest tests/s7_1200/test_s7_1200_function_charts.py

A golden file is (re)written only when the explicit checks of its test pass, so a trace that contradicts
the manual is never frozen; review the diff of tests/golden/ against the manual's description before
committing it.

Ramp durations: on a PTO axis a motion from standstill starts with a step to the start/stop velocity
and a stop ends with a step from it (§5.4.4.4 "ramp-up time = (maximum velocity - start/stop velocity) /
acceleration"), so a ramp from 0 to 50.0 at 10.0 takes (50.0 - 1.0) / 10.0 = 4.9 s on the PTO axis and
5.0 s on the PROFIdrive axis.
"""
from __future__ import annotations

import difflib
import os
from collections.abc import Callable
from itertools import pairwise
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative,
                               MC_MoveVelocity, MC_Power, MC_Reset)

SERVO = 0.001                      # servo cycle [s]
APP = 0.004                        # application cycle [s]: one program call = one row
GOLDEN = Path(__file__).resolve().parents[1] / "golden"
UPDATE = os.environ.get("PLCMOTION_UPDATE_GOLDEN") == "1"
MAX_ROWS = 1500                    # longer traces are thinned ...
KEEP_EVERY = 25                    # ... to every 25th row (0.1 s) inside constant stretches
READY_DELAY = 0.02                 # PROFIdrive: "Drive ready" 20 ms after the enable
EMERGENCY = 50.0                   # emergency stop deceleration (MC_Power StopMode 0)
ANALOG = ("time", "Position", "Velocity")    # the other columns are the chart's inputs and outputs

DRIVES = {"pto": 2, "profidrive": 1}
DRIVE_IDS = list(DRIVES)


# ----------------------------------------------------------------------------------------------------------
# the chart harness
class Chart:
    """One function chart: a controller with Axis_1, the chart's program and the rows it records."""

    def __init__(self, name: str, drive: str, *, acc: float, dec: float, max_v: float = 100.0,
                 description: str = ""):
        self.name = f"{name}-{drive}"
        self.drive = drive
        self.pto = drive == "pto"
        self.vss = 1.0 if self.pto else 0.0          # start/stop velocity (§5.4.4.4: 0 for PROFIdrive)
        self.acc, self.dec, self.max_v = acc, dec, max_v
        self.description = description
        actor: dict[str, Any] = {"Type": DRIVES[drive]}
        if self.pto:
            # enable output and "Drive ready" input of the stepper drive (§5.4.3.2)
            actor["Interface"] = {"EnableDriveOutput": "Q0.1", "DriveReadyInput": "I0.3"}
        params = {
            "Actor": actor,
            "DynamicLimits": {"MaxVelocity": max_v, "MinVelocity": self.vss},
            "DynamicDefaults": {"Acceleration": acc, "Deceleration": dec, "EmergencyDeceleration": EMERGENCY,
                                "Jerk": 0.0},
            "Plant": {"ReadyDelay": READY_DELAY},
        }
        self.ctl = Controller(servo_cycle=SERVO, app_cycle=APP)
        self.axis = self.ctl.add_positioning_axis("Axis_1", params)
        self.inp = SimpleNamespace()                 # the chart's inputs, changed by the test between cycles
        self.rows: list[dict[str, Any]] = []
        self._columns: list[tuple[str, Callable[[], Any]]] = []
        self._calls: Callable[[], None] | None = None
        self._recording = False
        self.ctl.program(self._cycle, name=name)

    # --- set-up --------------------------------------------------------------------------------------
    def program(self, calls: Callable[[], None], columns: list[tuple[str, Callable[[], Any]]]) -> None:
        """The chart's instance calls and the columns recorded after them (besides time/Position/Velocity)."""
        self._calls = calls
        self._columns = columns

    def start(self) -> None:
        """Start recording (after the set-up cycles that enable and home the axis)."""
        self._recording = True

    def _cycle(self) -> None:
        assert self._calls is not None
        self._calls()
        if self._recording:
            row: dict[str, Any] = {"time": self.ctl.time}
            for name, get in self._columns:
                row[name] = get()
            row["Position"] = self.axis.Position
            row["Velocity"] = self.axis.Velocity
            self.rows.append(row)

    # --- running -------------------------------------------------------------------------------------
    def step(self) -> dict[str, Any]:
        self.ctl.step()
        assert self.ctl.mode == "RUN", self.ctl.stop_reason
        return self.rows[-1] if self.rows else {}

    def run(self, seconds: float) -> None:
        for _ in range(round(seconds / APP)):
            self.step()

    def until(self, pred: Callable[[dict[str, Any]], bool], timeout: float, what: str) -> int:
        """Step until the last row satisfies ``pred``; returns its index."""
        for _ in range(round(timeout / APP)):
            row = self.step()
            if pred(row):
                return len(self.rows) - 1
        raise AssertionError(f"{self.name}: {what} not reached within {timeout} s (t = {self.ctl.time:.3f} s, "
                             f"last row {self.rows[-1]})")

    @property
    def last(self) -> int:
        """Index of the last recorded row."""
        return len(self.rows) - 1

    def col(self, name: str, lo: int = 0, hi: int | None = None) -> list[Any]:
        return [r[name] for r in self.rows[lo:hi]]

    # --- golden trace --------------------------------------------------------------------------------
    def csv(self) -> str:
        names = list(self.rows[0])
        kept = thin(self.rows)
        head = [f"# {self.name}: {self.description}",
                (f"# S7-1200 Motion Control V6; axis Actor.Type {DRIVES[self.drive]} ({self.drive}), MaxVelocity "
                 f"{self.max_v!r}, MinVelocity {self.vss!r}, Acceleration {self.acc!r}, Deceleration {self.dec!r}, "
                 f"EmergencyDeceleration {EMERGENCY!r}, Jerk 0.0; servo cycle {SERVO!r} s, application cycle "
                 f"{APP!r} s"),
                ("# one row per program call: time of the calls, then the chart's inputs and outputs and the "
                 "axis tags Position and Velocity right after the calls"),
                (f"# rows: {len(kept)} of {len(self.rows)} (stretches with constant inputs/outputs and constant "
                 f"acceleration thinned to every {KEEP_EVERY}th row)" if len(kept) < len(self.rows)
                 else f"# rows: all {len(self.rows)}"),
                ",".join(names)]
        body = [",".join(fmt(name, self.rows[i][name]) for name in names) for i in kept]
        return "\n".join(head + body) + "\n"

    def check_golden(self) -> None:
        """Compare with tests/golden/<name>.csv (or write it with PLCMOTION_UPDATE_GOLDEN=1)."""
        text = self.csv()
        path = GOLDEN / f"{self.name}.csv"
        if UPDATE:
            GOLDEN.mkdir(exist_ok=True)
            path.write_text(text)
            return
        if not path.exists():
            pytest.fail(f"golden trace {path} is missing; generate it with PLCMOTION_UPDATE_GOLDEN=1 and review it")
        expected = path.read_text()
        if text == expected:
            return
        exp_lines, got_lines = expected.splitlines(), text.splitlines()
        names = next((ln for ln in exp_lines if not ln.startswith("#")), "").split(",")
        for k, (e, g) in enumerate(zip(exp_lines, got_lines)):
            if e != g:
                if e.startswith("#") or g.startswith("#"):
                    detail = f"\n  golden: {e}\n  run:    {g}"
                else:
                    ev, gv = e.split(","), g.split(",")
                    diffs = [f"{n}: golden {a} / run {b}" for n, a, b in zip(names, ev, gv) if a != b]
                    detail = f" (time {gv[0]}): " + "; ".join(diffs)
                break
        else:
            detail = f": golden has {len(exp_lines)} lines, the run {len(got_lines)}"
        diff = "\n".join(list(difflib.unified_diff(exp_lines, got_lines, "golden", "run", n=1, lineterm=""))[:40])
        pytest.fail(f"{self.name}: trace differs from {path.name} at line {k + 1}{detail}\n{diff}")


def fmt(name: str, value: Any) -> str:
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    if name.startswith("ErrorID"):
        return f"16#{int(value):04X}"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return repr(float(value))


def thin(rows: list[dict[str, Any]]) -> list[int]:
    """Indices of the rows written to the golden file (all of them up to MAX_ROWS)."""
    n = len(rows)
    if n <= MAX_ROWS:
        return list(range(n))
    discrete = [k for k in rows[0] if k not in ANALOG]
    state = [tuple(r[k] for k in discrete) for r in rows]
    v = [r["Velocity"] for r in rows]
    keep = []
    for i in range(n):
        if i in (0, n - 1) or i % KEEP_EVERY == 0 or state[i] != state[i - 1] or state[i] != state[i + 1]:
            keep.append(i)
        elif i >= 2 and abs((v[i] - v[i - 1]) - (v[i - 1] - v[i - 2])) > 1e-7:
            keep.append(i)        # the velocity changed its rate between rows i-1 and i (kept: i-1 and i)
        elif i + 2 < n and abs((v[i + 2] - v[i + 1]) - (v[i + 1] - v[i])) > 1e-7:
            keep.append(i)
    return keep


def outputs(fb: Any, suffix: str, names: tuple[str, ...]) -> list[tuple[str, Callable[[], Any]]]:
    """Chart columns of an instance: its outputs with the chart's labels (Abort_1, InVel_1, ...)."""
    label = {"CommandAborted": "Abort", "InVelocity": "InVel"}
    return [(f"{label.get(n, n)}_{suffix}", (lambda n=n: getattr(fb, n))) for n in names]


def enable(chart: Chart, power: MC_Power) -> None:
    """Set-up: enable the axis (MC_Power called by the chart's program) before recording starts."""
    chart.inp.Enable = True
    for _ in range(100):
        chart.step()
        if power.Status:
            break
    assert power.Status, "set-up: axis not enabled"
    chart.run(0.02)
    chart.start()


def ramp_time(chart: Chart, v_from: float, v_to: float) -> float:
    """Expected duration of a velocity ramp ``v_from`` -> ``v_to`` of the chart's axis (§5.4.4.4)."""
    a = chart.acc if abs(v_to) > abs(v_from) else chart.dec
    lo, hi = sorted((abs(v_from), abs(v_to)))
    if lo == 0.0:
        lo = chart.vss            # PTO: step between 0 and the start/stop velocity (§5.4.4.4)
    return (hi - lo) / a


def first(chart: Chart, pred: Callable[[dict[str, Any]], bool], lo: int = 0, hi: int | None = None) -> int:
    for i in range(lo, len(chart.rows) if hi is None else hi):
        if pred(chart.rows[i]):
            return i
    raise AssertionError(f"{chart.name}: no row from {lo} satisfies the condition")


def check_ramp(chart: Chart, start: int, end: int, v_from: float, v_to: float, what: str) -> None:
    """The ramp from row ``start`` (the call that started it) to row ``end`` (first row at ``v_to``) lasts
    as long as the configured acceleration/deceleration gives, within one application cycle, and is
    linear in between (constant acceleration: no jerk limit)."""
    rows = chart.rows
    measured = rows[end]["time"] - rows[start]["time"]
    expected = ramp_time(chart, v_from, v_to)
    assert abs(measured - expected) <= APP + 1e-9, (
        f"{what}: ramp {v_from} -> {v_to} took {measured:.4f} s, expected {expected:.4f} s from the configured "
        f"{'acceleration' if abs(v_to) > abs(v_from) else 'deceleration'} (§5.4.4.4)")
    a = chart.acc if abs(v_to) > abs(v_from) else chart.dec
    slope = [abs(rows[i + 1]["Velocity"] - rows[i]["Velocity"]) / APP for i in range(start + 2, end - 2)]
    assert all(abs(s - a) < 1e-6 for s in slope), f"{what}: velocity does not change at {a} per second"


def check_stop_distance(ch: Chart, start: int, stop: int, dec: float, what: str) -> None:
    """Braking from the velocity at row ``start`` (the call that starts it) to standstill at row ``stop``
    covers (v^2 - vss^2) / (2 dec): the axis brakes from the moment of the call at exactly ``dec``."""
    v0 = ch.rows[start]["Velocity"]
    travelled = ch.rows[stop]["Position"] - ch.rows[start]["Position"]
    expected = (v0 * v0 - ch.vss * ch.vss) / (2 * dec) * (1.0 if v0 > 0 else -1.0)
    assert travelled == pytest.approx(expected, rel=1e-12, abs=1e-9), \
        f"{what}: braking distance {travelled!r}, expected {expected!r} at deceleration {dec}"


def check_position_continuity(ch: Chart) -> None:
    """Position moves by the velocity between two calls: between v_i * APP and v_(i+1) * APP (the velocity is
    monotonic within one cycle in these charts), in the direction of travel; no jumps."""
    rows = ch.rows
    for a, b in pairwise(rows):
        dp = b["Position"] - a["Position"]
        lo, hi = sorted((a["Velocity"] * APP, b["Velocity"] * APP))
        assert lo - 1e-9 <= dp <= hi + 1e-9, \
            f"{ch.name}: Position jumps by {dp!r} between t = {a['time']} and {b['time']} " \
            f"(velocity {a['Velocity']!r} -> {b['Velocity']!r})"


def true_rows(chart: Chart, name: str) -> list[int]:
    """Indices of the rows in which column ``name`` is TRUE."""
    return [i for i, r in enumerate(chart.rows) if r[name]]


def runs(idx: list[int]) -> bool:
    """``idx`` is one contiguous run of rows."""
    return bool(idx) and idx == list(range(idx[0], idx[-1] + 1))


# ----------------------------------------------------------------------------------------------------------
# MC_Power §11.1.1.2
def power_chart(name: str, drive: str, description: str):
    ch = Chart(name, drive, acc=10.0, dec=10.0, description=description)
    power, reset, move = MC_Power(), MC_Reset(), MC_MoveVelocity()
    ch.inp.Enable, ch.inp.Execute_2, ch.inp.Execute_3 = False, False, False
    ax = ch.axis

    def calls():
        power(Axis=ax, Enable=ch.inp.Enable, StartMode=1, StopMode=0)
        reset(Axis=ax, Execute=ch.inp.Execute_2, Restart=False)
        move(Axis=ax, Execute=ch.inp.Execute_3, Velocity=20.0)

    cols = [("Enable_1", lambda: power.Enable)] + outputs(power, "1", ("Status", "Busy", "Error", "ErrorID"))
    cols += [("Execute_2", lambda: reset.Execute)] + outputs(reset, "2", ("Done", "Busy", "Error", "ErrorID"))
    cols += [("Execute_3", lambda: move.Execute)] + outputs(move, "3", ("InVelocity", "Busy", "CommandAborted",
                                                                        "Error", "ErrorID"))
    cols += [("StatusBits.Enable", lambda: ax.StatusBits.Enable), ("StatusBits.Error", lambda: ax.StatusBits.Error)]
    if ch.pto:
        cols += [("EnableOutput", lambda: ch.ctl.outputs["Q0.1"]), ("ReadyInput", lambda: ch.ctl.inputs["I0.3"])]
    ch.program(calls, cols)
    ch.start()
    return ch


def check_enable(ch: Chart, e: int) -> int:
    """Enable_1 rose at row ``e``: Busy_1 at once, Status_1 once the drive is ready; returns that row."""
    rows = ch.rows
    assert all(not r["Status_1"] and not r["Busy_1"] and not r["StatusBits.Enable"] for r in rows[:e]), \
        "§11.1.1: Status/Busy before the enable"
    assert rows[e]["Busy_1"], "§11.1.1 Busy: 'MC_Power is active' from the enable on"
    assert not rows[e]["Status_1"], "§11.1.1.1: Status only once 'Drive ready' is reported"
    s = first(ch, lambda r: r["Status_1"], e)
    assert all(r["Busy_1"] and not r["Error_1"] for r in rows[e:s + 1])
    if ch.pto:
        assert rows[e]["EnableOutput"], "§11.1.1.1: the enable output is set with Enable = TRUE"
        assert all(not r["ReadyInput"] for r in rows[e:s]) and rows[s]["ReadyInput"], \
            "§11.1.1.1 / chart ①: Status_1 TRUE once the drive has signaled 'Drive ready'"
    else:
        waited = rows[s]["time"] - rows[e]["time"]
        assert READY_DELAY - 1e-9 <= waited <= READY_DELAY + APP + 1e-9, \
            f"chart ①: Status_1 after 'Drive ready' ({READY_DELAY} s), got {waited:.3f} s"
    return s


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_power_chart_1_enable_then_disable(drive):
    """S-PWR-1, §11.1.1.2 ①/③: 'An axis is enabled and then disabled again. When the drive has signaled
    "Drive ready" back to the CPU, the successful enable can be read out via "Status_1".'  The axis moves
    at 20.0 when Enable_1 goes FALSE: StopMode 0 brakes with the emergency deceleration and Status_1 goes
    FALSE only at standstill (§11.1.1 Status; ③ 'the exact end of the signals depends on the drive and the
    StopMode').

    tests/golden/S-PWR-1-pto.csv was corrected by hand: from t = 2.784 on, Position is the end of the
    planned emergency ramp, 24.03 + (20.0^2 - 1.0^2) / (2 * 50.0) = 28.020000000000003 (the value the
    planner computes for the stop point); the implementation freezes the setpoint one servo cycle early
    at 28.018975 (see check_stop_distance)."""
    ch = power_chart("S-PWR-1", drive, "MC_Power chart (1): enable, move at 20.0, disable (StopMode 0)")
    ch.run(0.1)
    ch.inp.Enable = True
    e = ch.last + 1
    ch.run(0.2)
    s = check_enable(ch, e)
    ch.inp.Execute_3 = True
    ch.until(lambda r: r["InVel_3"], 5.0, "velocity 20.0")
    ch.run(0.2)
    ch.inp.Enable = False
    d = ch.last + 1
    end = ch.until(lambda r: not r["Busy_1"], 5.0, "disabling complete")
    ch.run(0.2)
    ch.inp.Execute_3 = False
    x = ch.last + 1
    ch.run(0.1)
    rows = ch.rows

    assert all(r["Status_1"] == r["StatusBits.Enable"] for r in rows), "Status_1 and StatusBits.Enable differ"
    assert not any(r["Error_1"] or r["Error_2"] or r["Error_3"] for r in rows)
    # disabling: Status_1 and Busy_1 stay TRUE while the axis brakes, FALSE together at standstill
    stop = first(ch, lambda r: r["Velocity"] == 0.0, d)
    assert end == stop, "§11.1.1.1: disabling is complete (Busy, Status FALSE) when the axis stands still"
    assert all(r["Status_1"] and r["Busy_1"] and r["Velocity"] > 0.0 for r in rows[d:stop]), \
        "§11.1.1 Status: 'when disabling, Status goes FALSE only after standstill'"
    assert not rows[stop]["Status_1"] and not rows[stop]["StatusBits.Enable"]
    assert all(not r["Status_1"] and not r["Busy_1"] for r in rows[stop:])
    v0 = rows[d]["Velocity"]
    assert v0 == 20.0
    measured = rows[stop]["time"] - rows[d]["time"]
    expected = (v0 - ch.vss) / EMERGENCY
    assert abs(measured - expected) <= APP + 1e-9, \
        f"StopMode 0: emergency stop ramp {expected:.3f} s expected, took {measured:.3f} s"
    if ch.pto:
        assert all(r["EnableOutput"] for r in rows[e:stop]) and not any(r["EnableOutput"] for r in rows[stop:])
    # Enable = FALSE aborts the running command (§11.1.1 Override); Execute_3 held: latched (§9.5.3)
    ca = true_rows(ch, "Abort_3")
    assert ca == list(range(d, x)), "MC_MoveVelocity aborted at the disable, latched while Execute TRUE"
    assert not rows[d]["Busy_3"] and not rows[d]["InVel_3"]
    assert s < d
    if ch.pto:
        # braked with the emergency deceleration down to the start/stop velocity, then stopped: the axis
        # stands where the braking ramp ends (PROFIdrive: the Position tag shows the actual value once the
        # axis is disabled, which lags by the following error)
        check_stop_distance(ch, d, stop, EMERGENCY, "StopMode 0 (emergency stop deceleration)")
    ch.check_golden()


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_power_chart_2_error_reset_reenable(drive):
    """S-PWR-2, §11.1.1.2 ②: 'Following an axis enable, an error has occurred that caused the axis to be
    disabled. The error is eliminated and acknowledged with "MC_Reset". The axis is then enabled again.'
    (§11.1.1.1: re-enabled automatically because Enable stayed TRUE).  The error: PTO 'Drive ready' lost
    (16#8000), PROFIdrive drive fault (16#800C); the axis moves at 20.0 when it occurs."""
    ch = power_chart("S-PWR-2", drive, "MC_Power chart (2): enable, move, error disables the axis, cause "
                     "removed, MC_Reset, automatic re-enable")
    error_id = 0x8000 if ch.pto else 0x800C
    ch.run(0.1)
    ch.inp.Enable = True
    e = ch.last + 1
    ch.run(0.2)
    check_enable(ch, e)
    ch.inp.Execute_3 = True
    ch.until(lambda r: r["InVel_3"], 5.0, "velocity 20.0")
    ch.run(0.2)
    ch.axis.inject_fault("drive_not_ready" if ch.pto else "drive", persistent=True)
    f = ch.last + 1
    ch.run(0.2)
    ch.axis.clear_fault()                 # the cause is eliminated ...
    c = ch.last + 1
    ch.run(0.1)
    ch.inp.Execute_2 = True               # ... and acknowledged with MC_Reset
    r_ = ch.last + 1
    again = ch.until(lambda r: r["Status_1"], 1.0, "re-enable")
    ch.run(0.2)
    ch.inp.Execute_2 = False
    x = ch.last + 1
    ch.run(0.1)
    ch.inp.Execute_3 = False
    ch.run(0.1)
    rows = ch.rows

    assert all(r["Enable_1"] for r in rows[e:]), "Enable_1 stays TRUE throughout ②"
    assert all(r["Status_1"] == r["StatusBits.Enable"] for r in rows)
    # the error disables the axis
    fr = rows[f]
    assert fr["Error_1"] and fr["ErrorID_1"] == error_id, f"Error_1 with 16#{error_id:04X} at the error"
    assert not fr["Status_1"] and fr["Busy_1"], "the error disables the axis (Status_1 FALSE), MC_Power stays Busy"
    assert fr["StatusBits.Error"] and fr["Velocity"] == 0.0
    assert all(r["Error_1"] and r["ErrorID_1"] == error_id and not r["Status_1"] for r in rows[f:r_]), \
        "the error stays until it is acknowledged (also after its cause is gone)"
    assert not any(r["Busy_2"] or r["Done_2"] for r in rows[:r_])
    # the running MC_MoveVelocity is ended by the error (Execute_3 held: latched, §9.5.3)
    assert fr["Error_3"] and fr["ErrorID_3"] == error_id and not fr["Busy_3"]
    if ch.pto:
        assert not fr["EnableOutput"], "the enable output is reset when the axis is disabled"
    # acknowledgement: Done_2 and StatusBits.Error FALSE (§11.1.2.1)
    done = true_rows(ch, "Done_2")
    assert done and done[0] <= r_ + 1 and done == list(range(done[0], x)), \
        "MC_Reset Done_2 at the acknowledgement, latched while Execute_2 is TRUE (§9.5.2)"
    assert not rows[done[0]]["StatusBits.Error"], "§11.1.2.1: acknowledged = Done TRUE and StatusBits.Error FALSE"
    # MC_Power is called before MC_Reset: its next call shows the error gone
    after = done[0] + 1
    assert not rows[after]["Error_1"] and rows[after]["ErrorID_1"] == 0
    assert again > done[0] and all(not r["Status_1"] for r in rows[f:again]), \
        "chart ②: the axis is enabled again after the acknowledgement"
    if ch.pto:
        assert rows[after]["EnableOutput"], "auto re-enable sets the enable output again"
        s2 = first(ch, lambda r: r["ReadyInput"], after)
        assert again == s2, "re-enabled once 'Drive ready' is reported again"
    else:
        waited = rows[again]["time"] - rows[done[0]]["time"]
        assert READY_DELAY - 1e-9 <= waited <= READY_DELAY + 2 * APP + 1e-9, f"re-enable after the drive is ready ({waited})"
    assert all(r["Status_1"] and r["Busy_1"] and not r["Error_1"] for r in rows[again:])
    assert c > f
    ch.check_golden()


# ----------------------------------------------------------------------------------------------------------
# MC_Halt §11.1.4.2 (Acceleration 10.0, Deceleration 5.0)
def halt_chart(name: str, drive: str, description: str):
    ch = Chart(name, drive, acc=10.0, dec=5.0, description=description)
    power, move, halt = MC_Power(), MC_MoveVelocity(), MC_Halt()
    ch.inp.Enable, ch.inp.Execute_1, ch.inp.Execute_2 = False, False, False
    ax = ch.axis

    def calls():
        power(Axis=ax, Enable=ch.inp.Enable)
        move(Axis=ax, Execute=ch.inp.Execute_1, Velocity=20.0)
        halt(Axis=ax, Execute=ch.inp.Execute_2)

    cols = [("Execute_1", lambda: move.Execute)] + outputs(move, "1", ("InVelocity", "Busy", "CommandAborted", "Error"))
    cols += [("Execute_2", lambda: halt.Execute)] + outputs(halt, "2", ("Done", "Busy", "CommandAborted", "Error"))
    ch.program(calls, cols)
    enable(ch, power)
    return ch


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_halt_chart_1_halt_with_done(drive):
    """S-HALT-1, §11.1.4.2 ①: 'The axis is braked by an MC_Halt command until it comes to a standstill. The
    axis standstill is signaled via "Done_2".'  MC_Halt brakes 'with the configured deceleration'
    (§11.1.4.1) 5.0.  The moving command is MC_MoveVelocity_1 at 20.0 whose Execute_1 is already FALSE:
    Busy_1/InVel_1 stay TRUE until the halt (§11.1.7.1 PLCopen V2.0) and no Abort_1 is shown (§9.5.3)."""
    ch = halt_chart("S-HALT-1", drive, "MC_Halt chart (1): MC_MoveVelocity_1 at 20.0, MC_Halt_2 brakes to "
                    "standstill, Done_2")
    ch.run(0.1)
    ch.inp.Execute_1 = True
    m = ch.last + 1
    iv = ch.until(lambda r: r["InVel_1"], 5.0, "InVel_1")
    ch.run(0.5)
    ch.inp.Execute_1 = False
    ch.run(0.5)
    ch.inp.Execute_2 = True
    h = ch.last + 1
    done = ch.until(lambda r: r["Done_2"], 10.0, "Done_2")
    ch.run(0.5)
    ch.inp.Execute_2 = False
    x = ch.last + 1
    ch.run(0.2)
    rows = ch.rows

    assert rows[iv]["Velocity"] == 20.0 and rows[iv - 1]["Velocity"] != 20.0, "InVel_1 when 20.0 is reached"
    check_ramp(ch, m, iv, 0.0, 20.0, "MC_MoveVelocity_1")
    assert all(r["Busy_1"] and r["InVel_1"] for r in rows[iv:h + 1]), "§11.1.7.1: Busy/InVelocity stay TRUE"
    assert rows[h]["Busy_2"], "Busy_2 from the start of the halt"
    assert all(not r["Busy_1"] and not r["InVel_1"] for r in rows[h + 1:]), "MC_MoveVelocity_1 ended by the halt"
    assert not true_rows(ch, "Abort_1"), "§9.5.3: velocity reached and Execute FALSE -> no CommandAborted"
    stop = first(ch, lambda r: r["Velocity"] == 0.0, h)
    check_ramp(ch, h, stop, 20.0, 0.0, "MC_Halt (configured deceleration 5.0)")
    assert all(r["Velocity"] > 0.0 for r in rows[h:stop])
    if ch.pto:
        assert done == stop, "Done_2: 'zero velocity reached' at the call that sees the standstill"
    else:
        check_dwell(ch, stop, done, "Done_2")
    assert all(r["Busy_2"] and not r["Done_2"] for r in rows[h:done])
    assert true_rows(ch, "Done_2") == list(range(done, x)), "Done_2 latched while Execute_2 TRUE (§9.5.2)"
    assert all(not r["Busy_2"] for r in rows[done:])
    assert not any(r["Abort_2"] or r["Error_1"] or r["Error_2"] for r in rows)
    check_stop_distance(ch, h, stop, ch.dec, "MC_Halt")
    check_position_continuity(ch)
    ch.check_golden()


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_halt_chart_2_halt_aborted(drive):
    """S-HALT-2, §11.1.4.2 ②: 'While an MC_Halt command is braking the axis, this command is aborted by
    another motion command. The abort is signaled via "Abort_2".'  The other command: a new
    MC_MoveVelocity_1 (20.0) 1.0 s into the braking; the axis follows it without stopping."""
    ch = halt_chart("S-HALT-2", drive, "MC_Halt chart (2): MC_Halt_2 braking is aborted by a new "
                    "MC_MoveVelocity_1 command")
    ch.run(0.1)
    ch.inp.Execute_1 = True
    ch.until(lambda r: r["InVel_1"], 5.0, "InVel_1")
    ch.run(0.5)
    ch.inp.Execute_1 = False
    ch.run(0.5)
    ch.inp.Execute_2 = True
    h = ch.last + 1
    ch.run(1.0)
    ch.inp.Execute_1 = True               # another motion command while MC_Halt is braking
    o = ch.last + 1
    iv = ch.until(lambda r: r["InVel_1"], 5.0, "InVel_1 of the new command")
    ch.run(0.5)
    ch.inp.Execute_2 = False
    x = ch.last + 1
    ch.run(0.1)
    ch.inp.Execute_1 = False
    ch.run(0.1)
    rows = ch.rows

    v_o = rows[o]["Velocity"]
    assert abs(v_o - (20.0 - ch.dec * (rows[o]["time"] - rows[h]["time"]))) <= ch.dec * APP + 1e-9, \
        "MC_Halt brakes with the configured deceleration 5.0"
    assert all(r["Busy_2"] and not r["Done_2"] for r in rows[h:o]), "Busy_2 while braking"
    # MC_MoveVelocity_1 is called before MC_Halt_2: the halt sees the abort in the same cycle
    assert rows[o]["Busy_1"]
    assert true_rows(ch, "Abort_2") == list(range(o, x)), \
        "Abort_2 at the override, latched while Execute_2 TRUE, FALSE with Execute_2 (§9.5.2)"
    assert all(not r["Busy_2"] for r in rows[o:])
    assert not true_rows(ch, "Done_2"), "an aborted halt never shows Done_2"
    assert min(r["Velocity"] for r in rows[h:]) > 0.0, "the axis follows the new command without stopping"
    assert rows[iv]["Velocity"] == 20.0 and rows[iv - 1]["Velocity"] != 20.0
    check_ramp(ch, o, iv, v_o, 20.0, "new MC_MoveVelocity_1 after the aborted halt")
    assert not any(r["Error_1"] or r["Error_2"] for r in rows)
    check_position_continuity(ch)
    ch.check_golden()


# ----------------------------------------------------------------------------------------------------------
# MC_MoveAbsolute §11.1.5.2 and MC_MoveRelative §11.1.6.2 (Acceleration 10.0, Deceleration 10.0)
def positioning_chart(name: str, drive: str, cls: type, description: str, *, second: dict[str, float],
                      chained: bool):
    """Instance 1 (1000.0 at 50.0) and instance 2 (``second``); ``chained``: Execute_2 := Done_1."""
    ch = Chart(name, drive, acc=10.0, dec=10.0, description=description)
    power, home = MC_Power(), MC_Home()
    m1, m2 = cls(), cls()
    ch.inp.Enable, ch.inp.Home, ch.inp.Execute_1, ch.inp.Execute_2 = False, False, False, False
    ax = ch.axis
    key = "Position" if cls is MC_MoveAbsolute else "Distance"

    def calls():
        power(Axis=ax, Enable=ch.inp.Enable)
        home(Axis=ax, Execute=ch.inp.Home, Mode=0, Position=0.0)
        m1(Axis=ax, Execute=ch.inp.Execute_1, **{key: 1000.0}, Velocity=50.0)
        m2(Axis=ax, Execute=m1.Done if chained else ch.inp.Execute_2, **second)

    cols = [("Execute_1", lambda: m1.Execute)] + outputs(m1, "1", ("Done", "Busy", "CommandAborted", "Error"))
    cols += [("Execute_2", lambda: m2.Execute)] + outputs(m2, "2", ("Done", "Busy", "CommandAborted", "Error"))
    ch.program(calls, cols)
    ch.inp.Enable = True
    for _ in range(100):
        ch.step()
        if power.Status:
            break
    if cls is MC_MoveAbsolute:             # §11.1.5.1: the axis must be homed
        ch.inp.Home = True
        ch.step()
        ch.inp.Home = False
        ch.step()
        assert ax.StatusBits.HomingDone and ax.Position == 0.0, "set-up: MC_Home Mode 0"
    ch.run(0.02)
    ch.start()
    return ch


def check_arrival(ch: Chart, done: str, busy: str, start: int, target: float) -> int:
    """Done shown exactly at the call that sees the axis at standstill at the target; returns that row."""
    rows = ch.rows
    d = first(ch, lambda r: r[done], start)
    assert rows[d]["Position"] == target and rows[d]["Velocity"] == 0.0, \
        f"{done}: 'target position reached' (Position {target}, Velocity 0), got {rows[d]['Position']!r}, " \
        f"{rows[d]['Velocity']!r}"
    assert all(r[busy] and not r[done] for r in rows[start:d]), f"{busy} TRUE until {done}"
    arrived = first(ch, lambda r: r["Position"] == target and r["Velocity"] == 0.0, start)
    if ch.pto:
        assert d == arrived, f"{done} at the call that sees the axis at the target"
    else:
        check_dwell(ch, arrived, d, done)
    return d


def check_dwell(ch: Chart, arrived: int, done: int, what: str) -> None:
    """PROFIdrive: the end of the setpoint interpolation (target reached, MC_Halt) is followed by positioning
    monitoring (§5.4.4.6): Done once the actual position has stayed in the window for MinDwellTime (0.1 s
    by default) after the setpoint arrived; the setpoint stands still meanwhile."""
    rows = ch.rows
    dwell = rows[done]["time"] - rows[arrived]["time"]
    assert 0.1 - 1e-9 <= dwell <= 0.1 + 0.05, f"{what}: positioning monitoring (MinDwellTime 0.1 s), got {dwell:.3f} s"
    assert all(r["Velocity"] == 0.0 for r in rows[arrived:done + 1])


def check_trapezoid(ch: Chart, start: int, done: int, v: float, what: str) -> None:
    """Positioning from standstill at ``start`` with cruise velocity ``v``, standstill at ``done``."""
    rows = ch.rows
    top = first(ch, lambda r: r["Velocity"] == v, start)
    check_ramp(ch, start, top, 0.0, v, f"{what} acceleration")
    last_top = max(i for i in range(start, done) if rows[i]["Velocity"] == v)
    stop = first(ch, lambda r: r["Velocity"] == 0.0, last_top)
    check_ramp(ch, last_top, stop, v, 0.0, f"{what} deceleration")
    assert all(r["Velocity"] == v for r in rows[top:last_top + 1]), f"{what}: constant velocity {v}"


def pulse_or_hold(ch: Chart, name: str, pulse: bool) -> int:
    """Set the chart input ``name``; with ``pulse`` reset it after one call.  Returns the row of the edge."""
    setattr(ch.inp, name, True)
    row = ch.last + 1
    if pulse:
        ch.step()
        setattr(ch.inp, name, False)
    return row


def sequential_positioning(ch: Chart, first_target: float, second_target: float, pulse: bool) -> None:
    """①: instance 2 started by Done_1 = TRUE; brief standstill; Done_2 at the second target.  ``pulse``:
    Execute_1 is TRUE for one call only, so Done_1 (and with it Execute_2 := Done_1, and Done_2) is TRUE for
    exactly one call (§9.5.2); otherwise Execute_1 is held and both Done outputs are latched."""
    ch.run(0.1)
    s = pulse_or_hold(ch, "Execute_1", pulse)
    ch.until(lambda r: r["Done_2"], 60.0, "Done_2")
    ch.run(0.5)
    ch.inp.Execute_1 = False
    x = ch.last + 1
    ch.run(0.2)
    rows = ch.rows

    d1 = check_arrival(ch, "Done_1", "Busy_1", s, first_target)
    check_trapezoid(ch, s, d1, 50.0, "instance 1")
    if pulse:
        assert true_rows(ch, "Done_1") == [d1], "Done_1 for one call (Execute_1 already FALSE, §9.5.2)"
    else:
        assert true_rows(ch, "Done_1") == list(range(d1, x)), "Done_1 latched while Execute_1 TRUE (§9.5.2)"
    # 'When "Done_1" = TRUE, another command is started' (Execute_2 := Done_1, same cycle)
    assert rows[d1]["Execute_2"] and not rows[d1 - 1]["Execute_2"] and rows[d1]["Busy_2"]
    assert all(not r["Busy_2"] for r in rows[:d1])
    # 'the axis comes to a standstill briefly'
    still = [i for i in range(d1 - 40, d1 + 40) if rows[i]["Velocity"] == 0.0]
    assert d1 in still and runs(still), "the axis stands still between the two commands"
    assert rows[still[-1] + 1]["Velocity"] > 0.0
    if ch.pto:
        assert len(still) == 1, "PTO: standstill only for the program's response time (one cycle)"
    d2 = check_arrival(ch, "Done_2", "Busy_2", d1, second_target)
    check_trapezoid(ch, d1, d2, 50.0, "instance 2")
    if pulse:
        assert true_rows(ch, "Done_2") == [d2], "Done_2 for one call (Execute_2 = Done_1 already FALSE)"
    else:
        assert true_rows(ch, "Done_2") == list(range(d2, x)), "Done_2 latched while Execute_2 (= Done_1) is TRUE"
    assert not any(r["Abort_1"] or r["Abort_2"] or r["Error_1"] or r["Error_2"] for r in rows)
    check_position_continuity(ch)
    ch.check_golden()


def override_positioning(ch: Chart, v2: float, target_of: Callable[[float], float], pulse: bool) -> None:
    """②: instance 2 overrides instance 1 while it cruises at 50.0; no stop; Done_2 at the new target.
    ``pulse``: both Execute inputs TRUE for one call only (Abort_1 and Done_2 then shown for one call)."""
    ch.run(0.1)
    s = pulse_or_hold(ch, "Execute_1", pulse)
    ch.run(15.0)
    o = pulse_or_hold(ch, "Execute_2", pulse)
    ch.until(lambda r: r["Done_2"], 60.0, "Done_2")
    ch.run(0.5)
    ch.inp.Execute_1 = ch.inp.Execute_2 = False
    x = ch.last + 1
    ch.run(0.2)
    rows = ch.rows
    p_o = rows[o]["Position"]
    assert rows[o]["Velocity"] == 50.0, "set-up: instance 1 cruises at 50.0 at the override"

    # instance 1 is called before instance 2: it shows the abort at its first call after the override
    assert rows[o]["Busy_2"] and all(r["Busy_1"] for r in rows[s:o + 1])
    assert true_rows(ch, "Abort_1") == ([o + 1] if pulse else list(range(o + 1, x))), \
        "Abort_1 exactly at the override (first call of instance 1 after it), " + \
        ("one call (Execute_1 FALSE)" if pulse else "latched while Execute_1 TRUE") + " (§9.5.2)"
    assert all(not r["Busy_1"] for r in rows[o + 1:]) and not true_rows(ch, "Done_1")
    target = target_of(p_o)
    d2 = check_arrival(ch, "Done_2", "Busy_2", o, target)
    if pulse:
        assert true_rows(ch, "Done_2") == [d2]
    else:
        assert true_rows(ch, "Done_2") == list(range(d2, x))
    arrived = first(ch, lambda r: r["Position"] == target and r["Velocity"] == 0.0, o)
    assert all(r["Velocity"] > 0.0 for r in rows[o:arrived]), \
        "the axis moves to the new target without stopping (the velocity never drops to zero)"
    top = first(ch, lambda r: r["Velocity"] == v2, o)
    check_ramp(ch, o, top, 50.0, v2, "change to the new velocity")
    assert all(min(50.0, v2) - 1e-9 <= r["Velocity"] <= max(50.0, v2) + 1e-9 for r in rows[o:top]), \
        "the velocity goes straight from 50.0 to the new velocity"
    last_top = max(i for i in range(o, d2) if rows[i]["Velocity"] == v2)
    stop = first(ch, lambda r: r["Velocity"] == 0.0, last_top)
    check_ramp(ch, last_top, stop, v2, 0.0, "deceleration at the new target")
    assert not any(r["Error_1"] or r["Error_2"] or r["Abort_2"] for r in rows)
    check_position_continuity(ch)
    ch.check_golden()


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_absolute_chart_1_sequential(drive):
    """S-MABS-1, §11.1.5.2 ①: 'An axis is moved to absolute position 1000.0 ... signaled via "Done_1". When
    "Done_1" = TRUE, another MC_MoveAbsolute command, with target position 1500.0, is started. Because of
    the response times ... the axis comes to a standstill briefly. When the axis reaches the new target
    position, this is signaled via "Done_2".'  Both at Velocity 50.0."""
    ch = positioning_chart("S-MABS-1", drive, MC_MoveAbsolute, "MC_MoveAbsolute chart (1): 1000.0, then 1500.0 "
                           "started by Done_1", second={"Position": 1500.0, "Velocity": 50.0}, chained=True)
    sequential_positioning(ch, 1000.0, 1500.0, pulse=False)


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_absolute_chart_2_override(drive):
    """S-MABS-2, §11.1.5.2 ②: 'An active MC_MoveAbsolute command is aborted by another MC_MoveAbsolute
    command. The abort is signaled via "Abort_1". The axis is then moved at the new velocity to the new
    target position 1500.0.'  Instance 1: 1000.0 at 50.0; instance 2: 1500.0 at 80.0, started at
    t + 15 s while instance 1 cruises; the velocity never drops to zero."""
    ch = positioning_chart("S-MABS-2", drive, MC_MoveAbsolute, "MC_MoveAbsolute chart (2): 1000.0 at 50.0 "
                           "overridden by 1500.0 at 80.0", second={"Position": 1500.0, "Velocity": 80.0},
                           chained=False)
    override_positioning(ch, 80.0, lambda p_o: 1500.0, pulse=False)


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_relative_chart_1_sequential(drive):
    """S-MREL-1, §11.1.6.2 ①: 'The axis is moved by an MC_MoveRelative command by the distance 1000.0 ...
    "Done_1". When "Done_1" = TRUE, another MC_MoveRelative command, with travel distance 500.0, is
    started ... the axis comes to a standstill briefly ... "Done_2".'  From Position 0.0: 1000.0, 1500.0."""
    ch = positioning_chart("S-MREL-1", drive, MC_MoveRelative, "MC_MoveRelative chart (1): 1000.0, then 500.0 "
                           "started by Done_1", second={"Distance": 500.0, "Velocity": 50.0}, chained=True)
    assert ch.axis.Position == 0.0
    sequential_positioning(ch, 1000.0, 1500.0, pulse=True)


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_relative_chart_2_override(drive):
    """S-MREL-2, §11.1.6.2 ②: 'An active MC_MoveRelative command is aborted by another MC_MoveRelative
    command. The abort is signaled via "Abort_1". The axis is then moved at the new velocity by the new
    distance 500.0.'  The distance counts from the position at the override (§11.1.6.1 'relative to the
    start position'); instance 2 at 30.0, started while instance 1 (1000.0 at 50.0) cruises."""
    ch = positioning_chart("S-MREL-2", drive, MC_MoveRelative, "MC_MoveRelative chart (2): 1000.0 at 50.0 "
                           "overridden by 500.0 at 30.0", second={"Distance": 500.0, "Velocity": 30.0},
                           chained=False)
    override_positioning(ch, 30.0, lambda p_o: p_o + 500.0, pulse=True)


# ----------------------------------------------------------------------------------------------------------
# MC_MoveVelocity §11.1.7.2 (Acceleration 10.0, Deceleration 10.0)
def velocity_chart(name: str, drive: str, description: str):
    ch = Chart(name, drive, acc=10.0, dec=10.0, description=description)
    power, v1, v2 = MC_Power(), MC_MoveVelocity(), MC_MoveVelocity()
    ch.inp.Enable, ch.inp.Execute_1, ch.inp.Execute_2 = False, False, False
    ax = ch.axis

    def calls():
        power(Axis=ax, Enable=ch.inp.Enable)
        v1(Axis=ax, Execute=ch.inp.Execute_1, Velocity=30.0)
        v2(Axis=ax, Execute=ch.inp.Execute_2, Velocity=15.0)

    cols = [("Execute_1", lambda: v1.Execute)] + outputs(v1, "1", ("InVelocity", "Busy", "CommandAborted", "Error"))
    cols += [("Execute_2", lambda: v2.Execute)] + outputs(v2, "2", ("InVelocity", "Busy", "CommandAborted", "Error"))
    ch.program(calls, cols)
    enable(ch, power)
    return ch


def check_second_velocity(ch: Chart, o: int, x2: int) -> int:
    """Instance 2 (15.0) from row ``o``: InVel_2 when 15.0 is reached, then continuous motion at 15.0."""
    rows = ch.rows
    iv2 = first(ch, lambda r: r["InVel_2"], o)
    assert rows[iv2]["Velocity"] == 15.0 and rows[iv2 - 1]["Velocity"] != 15.0, \
        "InVel_2 exactly when the new target velocity 15.0 is reached"
    assert all(r["Busy_2"] and not r["InVel_2"] for r in rows[o:iv2])
    assert all(r["Busy_2"] and r["InVel_2"] and r["Velocity"] == 15.0 for r in rows[iv2:]), \
        "'The axis then continues moving at the new constant velocity' (Busy_2/InVel_2 stay TRUE, also after " \
        "Execute_2 = FALSE: §11.1.7.1 PLCopen V2.0)"
    assert any(not r["Execute_2"] for r in rows[x2:]) and x2 < len(rows)
    assert not any(r["Abort_2"] or r["Error_1"] or r["Error_2"] for r in rows)
    return iv2


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_velocity_chart_1_reached_then_overridden(drive):
    """S-MVEL-1, §11.1.7.2 ①: 'An active MC_MoveVelocity command signals via "InVel_1" that its target
    velocity has been reached. It is then aborted by another MC_MoveVelocity command. The abort is
    signaled via "Abort_1". When the new target velocity 15.0 is reached, this is signaled via "InVel_2".
    The axis then continues moving at the new constant velocity.'  Instance 1 at 30.0, Execute_1 held."""
    ch = velocity_chart("S-MVEL-1", drive, "MC_MoveVelocity chart (1): 30.0 reached, overridden by 15.0")
    ch.run(0.1)
    ch.inp.Execute_1 = True
    s = ch.last + 1
    iv1 = ch.until(lambda r: r["InVel_1"], 5.0, "InVel_1")
    ch.run(1.0)
    ch.inp.Execute_2 = True
    o = ch.last + 1
    ch.until(lambda r: r["InVel_2"], 5.0, "InVel_2")
    ch.run(0.5)
    ch.inp.Execute_2 = False
    x2 = ch.last + 1
    ch.run(0.5)
    ch.inp.Execute_1 = False
    x1 = ch.last + 1
    ch.run(0.2)
    rows = ch.rows

    assert rows[iv1]["Velocity"] == 30.0 and rows[iv1 - 1]["Velocity"] != 30.0, "InVel_1 when 30.0 is reached"
    check_ramp(ch, s, iv1, 0.0, 30.0, "instance 1")
    assert all(r["InVel_1"] and r["Busy_1"] for r in rows[iv1:o + 1])
    assert true_rows(ch, "Abort_1") == list(range(o + 1, x1)), \
        "Abort_1 at the first call of instance 1 after the override, latched while Execute_1 TRUE"
    assert all(not r["InVel_1"] and not r["Busy_1"] for r in rows[o + 1:]), "InVel_1 FALSE after the abort"
    iv2 = check_second_velocity(ch, o, x2)
    check_ramp(ch, o, iv2, 30.0, 15.0, "30.0 -> 15.0")
    check_position_continuity(ch)
    ch.check_golden()


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_velocity_chart_2_overridden_before_reached(drive):
    """S-MVEL-2, §11.1.7.2 ②: 'An active MC_MoveVelocity command is aborted by another MC_MoveVelocity
    command prior to reaching its target velocity. The abort is signaled via "Abort_1". When the new
    target velocity 15.0 is reached, this is signaled via "InVel_2".'  Instance 1 (30.0) is started with
    a one-cycle Execute_1 pulse and overridden 1.0 s later (velocity about 11): as the velocity was not
    reached, Abort_1 is shown although Execute_1 is FALSE, for exactly one call (§9.5.3)."""
    ch = velocity_chart("S-MVEL-2", drive, "MC_MoveVelocity chart (2): 30.0 overridden by 15.0 before reaching "
                        "it (Execute_1 pulsed)")
    ch.run(0.1)
    ch.inp.Execute_1 = True
    s = ch.last + 1
    ch.step()
    ch.inp.Execute_1 = False
    ch.run(1.0)
    ch.inp.Execute_2 = True
    o = ch.last + 1
    ch.until(lambda r: r["InVel_2"], 5.0, "InVel_2")
    ch.run(0.5)
    ch.inp.Execute_2 = False
    x2 = ch.last + 1
    ch.run(0.5)
    rows = ch.rows

    assert 0.0 < rows[o]["Velocity"] < 15.0
    assert not true_rows(ch, "InVel_1"), "instance 1 never reached its velocity"
    assert all(r["Busy_1"] for r in rows[s:o + 1])
    assert true_rows(ch, "Abort_1") == [o + 1], \
        "Abort_1 at the first call after the override, one call only (Execute_1 FALSE, §9.5.3)"
    assert all(not r["Busy_1"] for r in rows[o + 1:])
    iv2 = check_second_velocity(ch, o, x2)
    v = ch.col("Velocity", s, iv2 + 1)
    assert all(b >= a for a, b in pairwise(v)), "the axis keeps accelerating to 15.0"
    check_ramp(ch, s, iv2, 0.0, 15.0, "0 -> 15.0 (same acceleration before and after the override)")
    check_position_continuity(ch)
    ch.check_golden()


# ----------------------------------------------------------------------------------------------------------
# MC_MoveJog §11.1.8.2 (Acceleration 10.0, Deceleration 5.0)
def jog_chart(name: str, drive: str, description: str):
    ch = Chart(name, drive, acc=10.0, dec=5.0, description=description)
    power, jog = MC_Power(), MC_MoveJog()
    ch.inp.Enable, ch.inp.Jog_F, ch.inp.Jog_B, ch.inp.Velocity = False, False, False, 50.0
    ax = ch.axis

    def calls():
        power(Axis=ax, Enable=ch.inp.Enable)
        jog(Axis=ax, JogForward=ch.inp.Jog_F, JogBackward=ch.inp.Jog_B, Velocity=ch.inp.Velocity)

    cols = [("Jog_F", lambda: jog.JogForward), ("Jog_B", lambda: jog.JogBackward),
            ("Velocity_1", lambda: jog.Velocity)]
    cols += outputs(jog, "1", ("InVelocity", "Busy", "CommandAborted", "Error"))
    ch.program(calls, cols)
    enable(ch, power)
    return ch


def check_release(ch: Chart, r: int, v: float) -> None:
    """Jog input released at row ``r`` while jogging at ``v``: InVel_1 FALSE at once, braking with the
    configured deceleration, Busy_1 FALSE at standstill (§9.5.4)."""
    rows = ch.rows
    assert not rows[r]["InVel_1"] and rows[r]["Busy_1"], "InVel_1 FALSE as soon as the jog input is reset"
    stop = first(ch, lambda row: row["Velocity"] == 0.0, r)
    check_ramp(ch, r, stop, v, 0.0, "braking after the jog input is reset")
    assert all(row["Busy_1"] and not row["InVel_1"] for row in rows[r:stop]), "Busy_1 while braking"
    assert all(not row["Busy_1"] and not row["InVel_1"] for row in rows[stop:]), "Busy_1 FALSE at standstill"
    assert not any(row["Abort_1"] or row["Error_1"] for row in rows)
    check_stop_distance(ch, r, stop, ch.dec, "braking after the jog input is reset")
    check_position_continuity(ch)


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_jog_chart_1_forward(drive):
    """S-JOG-1, §11.1.8.2 ①: 'The axis is moved in the positive direction in jog mode via "Jog_F". When the
    target velocity 50.0 is reached, this is signaled via "InVel_1". After "Jog_F" is reset, the axis is
    braked to a standstill.'  Acceleration 10.0: 5 s (PTO 4.9 s from the start/stop velocity), deceleration
    5.0: 10 s (PTO 9.8 s)."""
    ch = jog_chart("S-JOG-1", drive, "MC_MoveJog chart (1): Jog_F at 50.0, released")
    ch.run(0.1)
    ch.inp.Jog_F = True
    s = ch.last + 1
    iv = ch.until(lambda r: r["InVel_1"], 10.0, "InVel_1")
    ch.run(1.0)
    ch.inp.Jog_F = False
    r = ch.last + 1
    ch.until(lambda row: not row["Busy_1"], 15.0, "standstill")
    ch.run(0.2)
    rows = ch.rows

    assert rows[s]["Busy_1"] and not rows[s]["InVel_1"]
    assert rows[iv]["Velocity"] == 50.0 and rows[iv - 1]["Velocity"] != 50.0, "InVel_1 when +50.0 is reached"
    check_ramp(ch, s, iv, 0.0, 50.0, "jog forward")
    assert all(row["InVel_1"] and row["Velocity"] == 50.0 for row in rows[iv:r])
    assert all(row["Velocity"] >= 0.0 for row in rows), "positive direction"
    check_release(ch, r, 50.0)
    ch.check_golden()


@pytest.mark.parametrize("drive", DRIVE_IDS)
def test_s7_1200_mc_move_jog_chart_2_backward_velocity_change(drive):
    """S-JOG-2, §11.1.8.2 ②: 'The axis is moved in the negative direction in jog mode via "Jog_B". When the
    target velocity -50.0 is reached, this is signaled via "InVel_1". When "Jog_B" is set, the value at
    parameter "Velocity" changes to 25.0. "InVel_1" is reset and the axis is braked. When the new target
    velocity -25.0 is reached, this is signaled via "InVel_1". After "Jog_B" is reset, the axis is braked
    to a standstill.'  (§9.3: MC_MoveJog takes Velocity over while a jog input is TRUE.)"""
    ch = jog_chart("S-JOG-2", drive, "MC_MoveJog chart (2): Jog_B at 50.0, Velocity changed to 25.0 while "
                   "jogging, released")
    ch.run(0.1)
    ch.inp.Jog_B = True
    s = ch.last + 1
    iv = ch.until(lambda r: r["InVel_1"], 10.0, "InVel_1 at -50.0")
    ch.run(1.0)
    ch.inp.Velocity = 25.0
    c = ch.last + 1
    iv2 = ch.until(lambda r: r["InVel_1"], 10.0, "InVel_1 at -25.0")
    ch.run(1.0)
    ch.inp.Jog_B = False
    r = ch.last + 1
    ch.until(lambda row: not row["Busy_1"], 15.0, "standstill")
    ch.run(0.2)
    rows = ch.rows

    assert rows[iv]["Velocity"] == -50.0 and rows[iv - 1]["Velocity"] != -50.0, "InVel_1 when -50.0 is reached"
    check_ramp(ch, s, iv, 0.0, -50.0, "jog backward")
    assert all(row["InVel_1"] and row["Velocity"] == -50.0 for row in rows[iv:c])
    # the velocity change: InVel_1 reset, braked from -50.0 to -25.0 with the deceleration 5.0
    assert not rows[c]["InVel_1"] and rows[c]["Busy_1"], "'InVel_1 is reset' when Velocity changes to 25.0"
    assert all(not row["InVel_1"] for row in rows[c:iv2])
    v = ch.col("Velocity", c, iv2 + 1)
    assert all(-50.0 <= a <= b <= -25.0 for a, b in pairwise(v)), "'the axis is braked' from -50.0 to -25.0"
    assert rows[iv2]["Velocity"] == -25.0 and rows[iv2 - 1]["Velocity"] != -25.0, "InVel_1 again at -25.0"
    check_ramp(ch, c, iv2, -50.0, -25.0, "velocity change 50.0 -> 25.0")
    assert all(row["InVel_1"] and row["Velocity"] == -25.0 for row in rows[iv2:r])
    assert all(row["Velocity"] <= 0.0 for row in rows), "negative direction"
    check_release(ch, r, -25.0)
    ch.check_golden()
