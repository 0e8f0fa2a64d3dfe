"""The timing examples of MC_MoveAbsolute (S7-Technology V4.1 §6.2.6): override, append, overlay 1, 2, 3.

Each example runs as the manual draws it: FB1 moves to 1000 with Velocity 50, Acceleration and
Deceleration 10 (trapezoidal, Jerk 0); FB2 starts while FB1 cruises.  The expected instants are the
kinematics of those values (a virtual axis: its actual value is its setpoint), recorded OB1 cycle by OB1
cycle (4 ms).
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_MoveAbsolute

from _s7t_rig import enabled

DYN = dict(Velocity=50.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
CYCLE = 0.004


class Scenario:
    """OB1 calls FB2 then FB1 every cycle (so FB1 shows an abort in the cycle FB2 starts)."""

    def __init__(self):
        self.ctl, self.axis, _ = enabled()
        self.fb1, self.fb2 = MC_MoveAbsolute(), MC_MoveAbsolute()
        self.exe1 = self.exe2 = False
        self.in1: dict = dict(Position=1000.0, **DYN)
        self.in2: dict = {}
        self.log: list[dict] = []
        b, i = self.ctl.bank, self.axis.index

        @self.ctl.program
        def ob1():
            self.fb2(Axis=self.axis, Execute=self.exe2, **self.in2)
            self.fb1(Axis=self.axis, Execute=self.exe1, **self.in1)
            self.log.append(dict(t=self.ctl.time, p=float(b.sp_p[i]), v=float(b.sp_v[i]),
                                 done1=self.fb1.Done, busy1=self.fb1.Busy, abort1=self.fb1.CommandAborted,
                                 done2=self.fb2.Done, busy2=self.fb2.Busy, abort2=self.fb2.CommandAborted,
                                 err=self.fb1.Error or self.fb2.Error))
        self.t0 = self.ctl.time

    def run(self, until: float, **set_inputs) -> None:
        for k, v in set_inputs.items():
            setattr(self, k, v)
        self.ctl.run(self.t0 + until - self.ctl.time)

    def first(self, key: str) -> dict:
        return next(r for r in self.log if r[key])

    def at(self, t: float) -> dict:
        return min(self.log, key=lambda r: abs(r["t"] - self.t0 - t))


def test_s7t_override_phase_a():
    """S7-Technology V4.1 §6.2.6 "override motion" phase a: FB1 reaches 1000 (5 s to 50, 750 at 50, 5 s
    braking: Done_1 at 25 s, standing still); Exe_2 is set in the OB1 cycle that shows Done_1, so FB2
    (1500, Velocity 30, Acceleration/Deceleration 10) starts one OB1 cycle later after a brief standstill:
    3 s to 30 (45), 410 at 30, 3 s braking = 19.667 s, Done_2 at 1500.  Nothing is aborted."""
    s = Scenario()
    s.in2 = dict(Position=1500.0, Velocity=30.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
    s.run(0.0, exe1=True)
    s.ctl.run_until(lambda: s.fb1.Done, 30.0)
    done1 = s.log[-1]
    assert done1["t"] - s.t0 == pytest.approx(25.0, abs=0.005)
    assert done1["p"] == pytest.approx(1000.0, abs=1e-6) and done1["v"] == 0.0 and not done1["busy1"]
    s.exe2 = True
    s.ctl.step()
    start = s.log[-1]                               # the next OB1 cycle: FB2 takes the axis at rest
    assert start["busy2"] and start["done1"] and not start["abort1"]
    assert start["t"] - done1["t"] == pytest.approx(CYCLE, abs=1e-9)
    assert start["p"] == pytest.approx(1000.0, abs=1e-6)
    t2 = start["t"] - s.t0
    s.run(t2 + 21.0)
    assert s.at(t2 + 1.5)["v"] == pytest.approx(15.0, abs=0.05)     # accelerating with 10
    assert s.at(t2 + 10.0)["v"] == pytest.approx(30.0, abs=1e-6)
    done2 = s.first("done2")
    assert done2["t"] - s.t0 == pytest.approx(t2 + 19.667, abs=0.01)
    assert done2["p"] == pytest.approx(1500.0, abs=1e-6) and not done2["busy2"]
    assert not any(r["abort1"] or r["abort2"] or r["err"] for r in s.log)


def test_s7t_override_phase_b():
    """S7-Technology V4.1 §6.2.6 "override motion" phase b: FB2 (1500, Velocity 30, Deceleration 10) while
    FB1 cruises at 50: Abort_1 in the same OB1 cycle, the axis brakes with 10 to 30 (2 s) and is Done_2 at
    1500: 8 s start + 2 s to 30 (80 travelled, at 355) + 1100 at 30 + 3 s braking = 49.667 s."""
    s = Scenario()
    s.run(0.0, exe1=True)
    s.run(8.0)
    s.in2 = dict(Position=1500.0, Velocity=30.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
    s.run(8.0 + CYCLE, exe2=True)
    start = s.log[-1]
    assert start["abort1"] and start["busy2"] and not start["busy1"]
    assert start["p"] == pytest.approx(275.0, abs=1e-6)
    s.run(52.0)
    assert s.at(9.0)["v"] == pytest.approx(40.0, abs=1e-6)       # braking with Deceleration 10
    assert s.at(11.0)["v"] == pytest.approx(30.0, abs=1e-6)
    done = s.first("done2")
    assert done["t"] - s.t0 == pytest.approx(49.667, abs=0.005)
    assert done["p"] == pytest.approx(1500.0, abs=1e-6)
    assert all(r["abort1"] for r in s.log if r["t"] >= start["t"])   # held while Exe_1 stays TRUE
    assert not any(r["err"] for r in s.log)


def test_s7t_append():
    """S7-Technology V4.1 §6.2.6 "append motion" (Mode 1): Busy_2 at once; FB1 goes on to 1000 and stops
    (Done_1 at 5 + 15 + 5 = 25 s), FB2 starts from standstill without a gap and is Done_2 at 1500 after
    5 + 5 + 5 = 15 s more."""
    s = Scenario()
    s.run(0.0, exe1=True)
    s.run(8.0)
    s.in2 = dict(Position=1500.0, Mode=1, **DYN)
    s.run(8.0 + CYCLE, exe2=True)
    assert s.log[-1]["busy2"] and s.log[-1]["busy1"] and not s.log[-1]["abort1"]
    s.run(42.0)
    done1 = s.first("done1")
    assert done1["t"] - s.t0 == pytest.approx(25.0, abs=0.005)
    assert done1["p"] == pytest.approx(1000.0, abs=1e-6) and done1["v"] == 0.0
    k = s.log.index(done1)
    assert s.log[k + 2]["v"] > 0.0 and s.log[k]["busy2"]            # no gap: FB2 moves at once
    done2 = s.first("done2")
    assert done2["t"] - s.t0 == pytest.approx(40.0, abs=0.005)
    assert done2["p"] == pytest.approx(1500.0, abs=1e-6) and not done2["busy2"]


def test_s7t_overlay_1():
    """S7-Technology V4.1 §6.2.6 "overlay motion 1" (Mode 2, new velocity 30 < 50): the axis brakes so that
    it passes 1000 at 30 (Done_1 at 5 + 795/50 + 2 = 22.9 s) and goes on at 30 to 1500 (Done_2 at
    22.9 + 455/30 + 3 = 41.067 s)."""
    s = Scenario()
    s.run(0.0, exe1=True)
    s.run(8.0)
    s.in2 = dict(Position=1500.0, Mode=2, Velocity=30.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
    s.run(8.0 + CYCLE, exe2=True)
    s.run(43.0)
    done1 = s.first("done1")
    assert done1["t"] - s.t0 == pytest.approx(22.9, abs=0.005)
    assert done1["v"] == pytest.approx(30.0, abs=1e-6) and done1["p"] == pytest.approx(1000.0, abs=0.2)
    assert s.at(30.0)["v"] == pytest.approx(30.0, abs=1e-6)
    done2 = s.first("done2")
    assert done2["t"] - s.t0 == pytest.approx(41.067, abs=0.005)
    assert min(r["v"] for r in s.log if s.t0 + 5.1 < r["t"] < done2["t"] - 3.1) > 29.99   # never slower


def test_s7t_overlay_2():
    """S7-Technology V4.1 §6.2.6 "overlay motion 2" (new velocity 70 > 50): 1000 is passed at 50 (Done_1 at
    5 + 875/50 = 22.5 s), then the axis accelerates with 10 to 70 and brakes to 1500 (Done_2 at
    22.5 + 2 + 135/70 + 7 = 33.429 s)."""
    s = Scenario()
    s.run(0.0, exe1=True)
    s.run(8.0)
    s.in2 = dict(Position=1500.0, Mode=2, Velocity=70.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
    s.run(8.0 + CYCLE, exe2=True)
    s.run(35.0)
    done1 = s.first("done1")
    assert done1["t"] - s.t0 == pytest.approx(22.5, abs=0.005)
    assert done1["v"] == pytest.approx(50.0, abs=0.05)
    assert s.at(25.5)["v"] == pytest.approx(70.0, abs=1e-6)
    done2 = s.first("done2")
    assert done2["t"] - s.t0 == pytest.approx(33.429, abs=0.005)
    assert done2["p"] == pytest.approx(1500.0, abs=1e-6)


def test_s7t_overlay_3_reversal():
    """S7-Technology V4.1 §6.2.6 "overlay motion 3" (target 700 behind 1000): the axis stops exactly at 1000
    (Done_1 at 25 s) and moves to -30 without a gap, Done_2 at 700 after 3 + 7 + 3 = 13 s more."""
    s = Scenario()
    s.run(0.0, exe1=True)
    s.run(8.0)
    s.in2 = dict(Position=700.0, Mode=2, Velocity=30.0, Acceleration=10.0, Deceleration=10.0, Jerk=0.0)
    s.run(8.0 + CYCLE, exe2=True)
    s.run(40.0)
    done1 = s.first("done1")
    assert done1["t"] - s.t0 == pytest.approx(25.0, abs=0.005)
    assert max(r["p"] for r in s.log) == pytest.approx(1000.0, abs=1e-6)
    k = s.log.index(done1)
    assert s.log[k + 2]["v"] < 0.0                                   # no gap at the reversal
    assert s.at(30.0)["v"] == pytest.approx(-30.0, abs=1e-6)
    done2 = s.first("done2")
    assert done2["t"] - s.t0 == pytest.approx(38.0, abs=0.005)
    assert done2["p"] == pytest.approx(700.0, abs=1e-6)
