"""Command table technology object and MC_CommandTable, derived from the S7-1200 Motion Control V6 manual.

Sections: §6.4.3.2 (step types, limits, "Next step"), §6.4.3.6 ("Complete command" / "Blend motion"),
§6.4.3.7 (runtime editing of ``Command[1..32].*``), §11.1.9.1 (MC_CommandTable: requirements, override
response, StartStep/EndStep, CurrentStep/StepCode/Done), §9.5.2 (status outputs), §9.6 (command table
errors: motion continues, shown at MC_CommandTable only), §12.8 (16#8700-16#8704, 16#8409, 16#840A,
16#840B, 16#8207/16#0019).  Project decisions respected: docs/decisions.md rows 40-46.

Axis used throughout: PTO, 1 pulse = 0.01 mm, MaxVelocity 100 mm/s, start/stop velocity 1 mm/s,
acceleration = deceleration = 100 mm/s^2, no jerk limit.
"""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (
    MC_CommandTable,
    MC_Halt,
    MC_Home,
    MC_MoveAbsolute,
    MC_MoveJog,
    MC_MoveRelative,
    MC_MoveVelocity,
    MC_Power,
)

SERVO, APP = 0.001, 0.004
VMAX, VMIN, ACC, DEC = 100.0, 1.0, 100.0, 100.0
EMPTY, HALT, REL, ABS, VEL, WAIT = 0, 2, 5, 6, 7, 151
COMPLETE, BLEND = 0, 1


def axis_params(actor: int = 2, extra: dict | None = None) -> dict:
    params = {"Actor": {"Type": actor},
              "DynamicLimits": {"MaxVelocity": VMAX, "MinVelocity": VMIN if actor == 2 else 0.0},
              "DynamicDefaults": {"Acceleration": ACC, "Deceleration": DEC, "EmergencyDeceleration": 1000.0,
                                  "Jerk": 0.0}}
    if actor != 2:
        params["Actor"]["DriveParameter"] = {"ReferenceSpeed": 3000.0, "MaxSpeed": 3000.0}
    params.update(extra or {})
    return params


class Bench:
    """One controller, one axis, its MC_Power (called every scan) and a setpoint trace per servo cycle."""

    def __init__(self, steps=(), *, actor: int = 2, extra: dict | None = None, enable: bool = True):
        self.ctl = Controller(servo_cycle=SERVO, app_cycle=APP)
        self.axis = self.ctl.add_positioning_axis("Axis_1", axis_params(actor, extra))
        self.table = self.ctl.add_command_table("Table_1", list(steps))
        self.power = MC_Power(Axis=self.axis, Enable=enable)
        self.fbs: list = [self.power]
        self.trace: list[tuple[float, float, float]] = []        # (t, Position, Velocity) every servo cycle
        self.ctl.on_post_servo(lambda t: self.trace.append((t, self.axis.Position, self.axis.Velocity)))
        if enable:
            self.scan_until(lambda: self.power.Status, 50)

    def add(self, fb):
        if getattr(fb, "Axis", None) is None:
            fb.Axis = self.axis
        self.fbs.append(fb)
        return fb

    def table_fb(self, **inputs) -> MC_CommandTable:
        fb = MC_CommandTable(Axis=self.axis, CommandTable=self.table)
        for k, v in inputs.items():
            setattr(fb, k, v)
        return self.add(fb)

    def scan(self) -> dict[int, dict]:
        """Call every instance once (like OB1), then one application cycle; returns outputs by instance."""
        out = {}
        for fb in self.fbs:
            fb()
            out[id(fb)] = dict(fb.outputs)
        self.ctl.step()
        return out

    def scan_until(self, cond, max_scans: int, what: str = "condition") -> int:
        for n in range(max_scans):
            self.scan()
            if cond():
                return n + 1
        raise AssertionError(f"{what} not reached within {max_scans} scans (t = {self.ctl.time:.3f} s)")

    def run_table(self, fb: MC_CommandTable, max_scans: int = 3000) -> list[dict]:
        """Scan until the table instance ends; returns the outputs of the table instance per scan."""
        seen = []
        for _ in range(max_scans):
            out = self.scan()[id(fb)]
            seen.append(out)
            if out["Done"] or out["Error"] or out["CommandAborted"]:
                return seen
        raise AssertionError(f"command table still busy after {max_scans} scans: {seen[-1]}")

    def home(self, position: float = 0.0):
        home = MC_Home(Axis=self.axis, Mode=0, Position=position, Execute=True)
        home()
        assert home.Done and self.axis.StatusBits.HomingDone


def steps_seen(outs: list[dict]) -> list[tuple[int, int]]:
    """(CurrentStep, StepCode) in the order they were shown while the table was Busy, without repeats."""
    seq: list[tuple[int, int]] = []
    for o in outs:
        if o["Busy"]:
            pair = (o["CurrentStep"], o["StepCode"])
            if not seq or seq[-1] != pair:
                seq.append(pair)
    return seq


def error_of(out: dict) -> tuple[int, int]:
    assert out["Error"], f"no error: {out}"
    return out["ErrorID"], out["ErrorInfo"]


# ==========================================================================================================
# §6.4.3.2 step types
def test_s7_1200_6_4_3_2_steps_run_in_sequence_with_current_step_step_code_and_done():
    """§6.4.3.2 "The commands will be processed in sequence"; §11.1.9.1 CurrentStep = "step currently being
    executed", StepCode = the step code "output ... while the command is being processed", Busy while the
    table is executed, Done = "command table has been successfully executed"; §9.5.2 Done means the axis is
    at standstill; StatusBits.CommandTableActive while the axis is controlled by MC_CommandTable."""
    b = Bench([
        {"Type": REL, "Position": 20.0, "Velocity": 40.0, "StepCode": 11},
        {"Type": VEL, "Velocity": 30.0, "Duration": 0.5, "StepCode": 22},
        {"Type": WAIT, "Duration": 0.2, "StepCode": 33},
        {"Type": HALT, "StepCode": 44},
        {"Type": REL, "Position": 5.0, "Velocity": 10.0, "StepCode": 65535},
    ])
    ct = b.table_fb(Execute=True, StartStep=1, EndStep=5)
    active = []
    outs = []
    for _ in range(3000):
        o = b.scan()[id(ct)]
        outs.append(o)
        active.append(b.axis.StatusBits.CommandTableActive)
        if o["Done"] or o["Error"]:
            break
    assert outs[-1]["Done"] and not outs[-1]["Error"], outs[-1]
    assert steps_seen(outs) == [(1, 11), (2, 22), (3, 33), (4, 44), (5, 65535)]
    assert all(o["Busy"] for o in outs[:-1])
    assert all(active[:-2]), "StatusBits.CommandTableActive while the table runs"
    assert not b.axis.StatusBits.CommandTableActive
    assert b.axis.Velocity == 0.0 and b.axis.StatusBits.StandStill
    # Done latched while Execute stays TRUE (§9.5.2), drops with Execute
    assert all(b.scan()[id(ct)]["Done"] for _ in range(3))
    ct.Execute = False
    assert not b.scan()[id(ct)]["Done"]


def test_s7_1200_9_5_2_done_for_one_call_when_execute_already_false():
    """§9.5.2: if Execute is already FALSE when the table ends, Done is TRUE for exactly one call."""
    b = Bench([{"Type": REL, "Position": 5.0, "Velocity": 50.0}])
    ct = b.table_fb(Execute=True)
    b.scan()
    ct.Execute = False
    outs = [b.scan()[id(ct)] for _ in range(200)]
    done = [i for i, o in enumerate(outs) if o["Done"]]
    assert len(done) == 1 and all(o["Busy"] for o in outs[:done[0]])
    assert b.axis.Position == pytest.approx(5.0)


def test_s7_1200_6_4_3_2_empty_steps_are_ignored():
    """§6.4.3.2 Empty: "The empty entry is ignored when the command table is processed." """
    b = Bench([
        {"Type": EMPTY, "StepCode": 1},
        {"Type": REL, "Position": 10.0, "Velocity": 40.0, "StepCode": 2},
        {"Type": EMPTY, "Position": 99.0, "Velocity": 1e9, "Duration": -5.0, "NextStep": 7, "StepCode": 3},
        {"Type": REL, "Position": 10.0, "Velocity": 40.0, "StepCode": 4},
    ])
    ct = b.table_fb(Execute=True, StartStep=1, EndStep=32)
    outs = b.run_table(ct)
    assert outs[-1]["Done"], outs[-1]
    assert [s for s, _ in steps_seen(outs)] == [2, 4]
    assert b.axis.Position == pytest.approx(20.0)


def test_s7_1200_6_4_3_2_positioning_relative_moves_by_the_travel_path_at_the_velocity():
    """§6.4.3.2 Positioning Relative: "The command will move the axis by the given travel path" "at the given
    velocity"; "The given velocity will not be reached if the travel path selected is not large enough."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 40.0},
               {"Type": REL, "Position": -1.0, "Velocity": 100.0}])
    ct = b.table_fb(Execute=True, EndStep=1)
    assert b.run_table(ct)[-1]["Done"]
    vs = [v for _, _, v in b.trace]
    assert max(vs) == pytest.approx(40.0) and b.axis.Position == pytest.approx(30.0)
    b.trace.clear()
    ct2 = b.table_fb(Execute=True, StartStep=2, EndStep=2)
    assert b.run_table(ct2)[-1]["Done"]
    assert b.axis.Position == pytest.approx(29.0)
    peak = max(abs(v) for _, _, v in b.trace)
    assert peak < 15.0, "1 mm at 100 mm/s^2 cannot reach 100 mm/s"


def test_s7_1200_6_4_3_2_positioning_absolute_needs_homing():
    """§6.4.3.2 Positioning Absolute: "the axis must be homed for this" -> 16#8204 "Axis is not homed"
    (§12.8); after MC_Home the step moves the axis to the position."""
    b = Bench([{"Type": ABS, "Position": 120.0, "Velocity": 40.0}])
    ct = b.table_fb(Execute=True, EndStep=1)
    out = b.run_table(ct)[-1]
    assert error_of(out) == (0x8204, 0x0001)
    assert b.axis.Position == 0.0
    b.home(100.0)
    ct.Execute = False
    b.scan()
    ct.Execute = True
    assert b.run_table(ct)[-1]["Done"]
    assert b.axis.Position == pytest.approx(120.0)


def test_s7_1200_6_4_3_2_velocity_set_point_duration_includes_acceleration():
    """§6.4.3.2 Velocity set point: "The duration includes both the acceleration phase and the constant travel
    phase. The next command will be processed once the duration is over."  Acceleration to 50 mm/s takes
    0.49 s, so the following Halt starts 1.0 s (not 1.49 s) after the step started."""
    b = Bench([{"Type": VEL, "Velocity": 50.0, "Duration": 1.0}, {"Type": HALT}])
    ct = b.table_fb(Execute=True, EndStep=2)
    b.trace.clear()
    t0 = b.ctl.time                      # the table starts at this call
    outs = b.run_table(ct)
    assert outs[-1]["Done"]
    tr = b.trace
    v_at = {round(t, 6): v for t, _, v in tr}
    assert max(v for _, _, v in tr) == pytest.approx(50.0)
    # first servo cycle after t0 + 1.0 in which the velocity drops below 50
    t_dec = next(t for t, _, v in tr if t > t0 + 0.6 and v < 50.0 - 1e-9)
    assert t_dec - t0 == pytest.approx(1.0, abs=2 * SERVO), (t0, t_dec)
    assert v_at[round(t0 + 0.9, 6)] == pytest.approx(50.0)


def test_s7_1200_6_4_3_2_velocity_set_point_not_reached_when_duration_too_short():
    """§6.4.3.2: "The given velocity will not be reached during the command if too short a runtime is
    selected" -- 0.2 s at 100 mm/s^2 from the start/stop velocity 1 mm/s reaches about 21 mm/s."""
    b = Bench([{"Type": VEL, "Velocity": 100.0, "Duration": 0.2}, {"Type": HALT}])
    ct = b.table_fb(Execute=True, EndStep=2)
    assert b.run_table(ct)[-1]["Done"]
    peak = max(v for _, _, v in b.trace)
    assert peak == pytest.approx(VMIN + ACC * 0.2, abs=0.5)


def test_s7_1200_6_4_3_2_wait_does_not_stop_active_travel():
    """§6.4.3.2 Wait: "Waits until the given period is over. Wait does not stop active travel." """
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.5, "StepCode": 1},
               {"Type": WAIT, "Duration": 0.5, "StepCode": 2},
               {"Type": HALT, "StepCode": 3}])
    ct = b.table_fb(Execute=True, EndStep=3)
    waiting_velocities = []
    for _ in range(1000):
        o = b.scan()[id(ct)]
        if o["Busy"] and o["CurrentStep"] == 2:
            waiting_velocities.append(b.axis.Velocity)
        if o["Done"] or o["Error"]:
            break
    assert o["Done"]
    assert len(waiting_velocities) >= int(0.5 / APP) - 1
    assert all(v == pytest.approx(40.0) for v in waiting_velocities)


def test_s7_1200_6_4_3_2_halt_after_velocity_set_point_brakes_with_configured_deceleration():
    """§6.4.3.2 Halt: "Stop axis (the command only takes effect after a 'Velocity set point' command)";
    braking with the configured deceleration (DynamicDefaults.Deceleration = 100 mm/s^2); the table is Done
    once the axis stands still (§9.5.2)."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.6}, {"Type": HALT, "StepCode": 9}])
    ct = b.table_fb(Execute=True, EndStep=2)
    outs = b.run_table(ct)
    assert outs[-1]["Done"] and b.axis.Velocity == 0.0
    t_top = max(t for t, _, v in b.trace if v == pytest.approx(40.0))
    decel = [(t, v) for t, _, v in b.trace if t > t_top and 1.0 < v < 39.0]
    assert len(decel) > 100
    (t1, v1), (t2, v2) = decel[0], decel[-1]
    assert (v1 - v2) / (t2 - t1) == pytest.approx(DEC, rel=0.02)


def test_s7_1200_6_4_3_2_halt_after_completed_positioning_has_no_effect():
    """§6.4.3.2 Halt "only takes effect after a 'Velocity set point' command" (decision 44: after a completed
    positioning the axis is at standstill): the table goes on with the next step."""
    b = Bench([{"Type": REL, "Position": 20.0, "Velocity": 40.0},
               {"Type": HALT},
               {"Type": REL, "Position": 10.0, "Velocity": 40.0}])
    ct = b.table_fb(Execute=True, EndStep=3)
    outs = b.run_table(ct)
    assert outs[-1]["Done"], outs[-1]
    assert b.axis.Position == pytest.approx(30.0)


def test_s7_1200_decision_43_relative_step_after_velocity_set_point_counts_from_where_it_starts():
    """Decision 43 (§6.4.3.2 "move the axis by the given travel path"): after a Velocity set point the
    relative step counts from the position where it starts.  Velocity 40 mm/s for 0.6 s from the start/stop
    velocity 1 mm/s at 100 mm/s^2 covers (40^2 - 1^2)/200 + 40 x 0.21 = 16.395 mm, so the table ends at
    26.395 mm; while the axis runs at constant velocity its setpoint advances 40 mm/s x 1 ms every servo
    cycle (no hold at the step change)."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.6, "StepCode": 1},
               {"Type": REL, "Position": 10.0, "Velocity": 40.0, "StepCode": 2}])
    ct = b.table_fb(Execute=True, EndStep=2)
    assert b.run_table(ct)[-1]["Done"]
    assert b.axis.Position == pytest.approx(16.395 + 10.0, abs=0.006)
    pairs = list(zip(b.trace, b.trace[1:]))
    cruise = [(s1, s2) for s1, s2 in pairs if s1[2] == pytest.approx(40.0) and s2[2] == pytest.approx(40.0)]
    assert len(cruise) > 200
    stalls = [(s1, s2) for s1, s2 in cruise if abs((s2[1] - s1[1]) - 40.0 * SERVO) > 1e-6]
    assert not stalls, f"setpoint does not advance with the velocity: {stalls[:2]}"


def test_s7_1200_decision_41_end_of_table_with_moving_axis_brakes_then_done():
    """Decision 41 (§9.5.2 Done = axis at standstill): a table that ends with a velocity set point brakes the
    axis with the configured deceleration, then shows Done."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.5}])
    ct = b.table_fb(Execute=True, EndStep=1)
    outs = b.run_table(ct)
    assert outs[-1]["Done"] and b.axis.Velocity == 0.0
    # Busy while the axis was still braking
    assert b.trace[-1][2] == 0.0 and max(v for _, _, v in b.trace) == pytest.approx(40.0)


# ==========================================================================================================
# §6.4.3.2 "Next step", §6.4.3.6 transitions
def _velocity_near(trace, lo, hi):
    return [v for _, p, v in trace if lo <= p <= hi]


def test_s7_1200_6_4_3_6_complete_command_stops_between_positioning_steps():
    """§6.4.3.2 "Complete command: The command will be completed. The next command will be processed
    immediately." -- the first positioning ends at its target (the PTO velocity falls to the start/stop
    velocity) before the second starts."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 40.0, "NextStep": COMPLETE},
               {"Type": REL, "Position": 30.0, "Velocity": 20.0, "NextStep": COMPLETE}])
    ct = b.table_fb(Execute=True, EndStep=2)
    assert b.run_table(ct)[-1]["Done"]
    assert b.axis.Position == pytest.approx(60.0)
    # the velocity falls to the start/stop velocity at the first target (within one servo cycle of
    # acceleration, wherever in the servo cycle the next step starts)
    assert min(abs(v) for v in _velocity_near(b.trace, 29.0, 31.0)) <= VMIN + ACC * SERVO + 1e-9


def test_s7_1200_6_4_3_6_blend_motion_no_standstill_between_positioning_steps():
    """§6.4.3.2 "Blend motion: The motion of the current command will be blended with the motion of the
    following command"; §6.4.3.6 chart / decision 42: the first target is passed at the velocity of the
    following step, without standstill; a relative step counts from the previous target (decision 43)."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 40.0, "NextStep": BLEND, "StepCode": 1},
               {"Type": REL, "Position": 30.0, "Velocity": 20.0, "NextStep": COMPLETE, "StepCode": 2}])
    ct = b.table_fb(Execute=True, EndStep=2)
    assert b.run_table(ct)[-1]["Done"]
    assert b.axis.Position == pytest.approx(60.0)
    near = _velocity_near(b.trace, 25.0, 35.0)
    assert near and min(near) >= 20.0 - 1e-6, "no standstill between blended steps"
    v_at_30 = min(b.trace, key=lambda s: abs(s[1] - 30.0))[2]
    assert v_at_30 == pytest.approx(20.0, abs=0.5)


def test_s7_1200_6_4_3_6_blend_positioning_into_velocity_set_point():
    """§6.4.3.2: positioning steps are blended with a following "Velocity set point" step (§6.4.3.6 chart:
    no standstill)."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 40.0, "NextStep": BLEND},
               {"Type": VEL, "Velocity": 20.0, "Duration": 0.5},
               {"Type": HALT}])
    ct = b.table_fb(Execute=True, EndStep=3)
    assert b.run_table(ct)[-1]["Done"]
    near = _velocity_near(b.trace, 25.0, 35.0)
    assert near and min(near) >= 20.0 - 1e-6


def test_s7_1200_6_4_3_6_velocity_set_point_followed_by_velocity_set_point_without_stop():
    """§6.4.3.6 (velocity job followed by velocity job): the duration of the first ends, the next command
    takes over the moving axis (no standstill in between)."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.5},
               {"Type": VEL, "Velocity": 20.0, "Duration": 0.5},
               {"Type": HALT}])
    ct = b.table_fb(Execute=True, EndStep=3)
    assert b.run_table(ct)[-1]["Done"]
    moving = [v for t, _, v in b.trace if v != 0.0]
    first = next(i for i, s in enumerate(b.trace) if s[2] != 0.0)
    last = max(i for i, s in enumerate(b.trace) if s[2] != 0.0)
    assert all(s[2] >= VMIN - 1e-9 for s in b.trace[first:last + 1])
    assert max(moving) == pytest.approx(40.0) and any(v == pytest.approx(20.0) for v in moving)


def test_s7_1200_6_4_3_2_no_blending_with_other_command_types():
    """§6.4.3.2: "No blending occurs with other command types" -- Blend motion followed by a Wait is not an
    error; the positioning completes (stops) at its target."""
    b = Bench([{"Type": REL, "Position": 10.0, "Velocity": 40.0, "NextStep": BLEND},
               {"Type": WAIT, "Duration": 0.1},
               {"Type": REL, "Position": 10.0, "Velocity": 40.0}])
    ct = b.table_fb(Execute=True, EndStep=3)
    assert b.run_table(ct)[-1]["Done"]
    assert b.axis.Position == pytest.approx(20.0)
    assert min(abs(v) for v in _velocity_near(b.trace, 9.5, 10.5)) <= VMIN + ACC * SERVO + 1e-9


def test_s7_1200_decision_42_blend_into_opposite_direction_stops_at_target():
    """Decision 42: a blended step whose successor moves back stops at its target, then reverses."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 40.0, "NextStep": BLEND},
               {"Type": REL, "Position": -10.0, "Velocity": 40.0}])
    ct = b.table_fb(Execute=True, EndStep=2)
    assert b.run_table(ct)[-1]["Done"]
    assert max(p for _, p, _ in b.trace) == pytest.approx(30.0, abs=0.011)
    assert b.axis.Position == pytest.approx(20.0)


# ==========================================================================================================
# §11.1.9.1 StartStep / EndStep
def _binary_table():
    return [{"Type": REL, "Position": float(2 ** k), "Velocity": 50.0, "StepCode": 100 + k} for k in range(5)]


@pytest.mark.parametrize("start, end, visited", [(2, 4, [2, 3, 4]), (1, 32, [1, 2, 3, 4, 5]), (5, 5, [5]),
                                                 (3, 32, [3, 4, 5])])
def test_s7_1200_11_1_9_1_start_step_to_end_step(start, end, visited):
    """§11.1.9.1 StartStep "step at which the execution ... should begin", EndStep "step up to which the
    execution ... should take place"; steps outside the range are not executed."""
    b = Bench(_binary_table())
    ct = b.table_fb(Execute=True, StartStep=start, EndStep=end)
    outs = b.run_table(ct)
    assert outs[-1]["Done"], outs[-1]
    assert steps_seen(outs) == [(n, 100 + n - 1) for n in visited]
    assert b.axis.Position == pytest.approx(sum(2 ** (n - 1) for n in visited))


@pytest.mark.parametrize("start, end, codes", [
    (0, 32, (0x840A, 0x000A)), (-3, 5, (0x840A, 0x000A)),
    (5, 3, (0x840A, 0x001D)),
    (33, 32, (0x840A, 0x001E)),
    (1, 0, (0x840B, 0x000A)), (1, -1, (0x840B, 0x000A)),
    (1, 33, (0x840B, 0x001E)),
])
def test_s7_1200_12_8_840A_840B_invalid_start_end_step(start, end, codes):
    """§12.8 16#840A StartStep (16#000A <= 0, 16#001D > EndStep, 16#001E > 32), 16#840B EndStep (16#000A
    <= 0, 16#001E > 32); block parameter errors: the axis does not move, nothing else is affected.  Where
    two limits are violated the specific code is expected (EndStep <= 0 is 16#840B/16#000A, StartStep > 32
    with a valid EndStep is 16#840A/16#001E), otherwise those codes could never occur."""
    b = Bench(_binary_table())
    ct = b.table_fb(Execute=True, StartStep=start, EndStep=end)
    out = b.scan()[id(ct)]
    assert error_of(out) == codes and not out["Busy"]
    assert not b.power.Error and not b.axis.StatusBits.Error
    b.scan()
    assert b.axis.Position == 0.0 and b.axis.Velocity == 0.0


# ==========================================================================================================
# §12.8 16#8700-16#8704 (command table configuration errors)
def _vel(**kw):
    row = {"Type": VEL, "Velocity": 20.0, "Duration": 0.1}
    row.update(kw)
    return row


def _rel(**kw):
    row = {"Type": REL, "Position": 5.0, "Velocity": 20.0}
    row.update(kw)
    return row


NAN = math.nan


@pytest.mark.parametrize("row, codes", [
    ({"Type": 1}, (0x8700, 0x0001)), ({"Type": 3}, (0x8700, 0x0001)), ({"Type": 152}, (0x8700, 0x0001)),
    (_rel(Position=NAN), (0x8701, 0x0002)), (_rel(Position=2.0e12), (0x8701, 0x0005)),
    (_rel(Position=-2.0e12), (0x8701, 0x0006)),
    (_rel(Velocity=150.0), (0x8702, 0x0008)), (_rel(Velocity=0.5), (0x8702, 0x0009)),
    (_rel(Velocity=NAN), (0x8702, 0x0002)), (_rel(Velocity=0.0), (0x8702, 0x0009)),
    (_vel(Velocity=-150.0), (0x8702, 0x0008)), (_vel(Velocity=0.5), (0x8702, 0x0009)),
    (_vel(Velocity=-0.5), (0x8702, 0x0009)), (_vel(Velocity=NAN), (0x8702, 0x0002)),
    (_vel(Duration=64800.5), (0x8703, 0x0021)), (_vel(Duration=0.0005), (0x8703, 0x0022)),
    (_vel(Duration=0.0), (0x8703, 0x0022)), (_vel(Duration=NAN), (0x8703, 0x0002)),
    ({"Type": WAIT, "Duration": 1.0e5}, (0x8703, 0x0021)), ({"Type": WAIT, "Duration": 0.0}, (0x8703, 0x0022)),
    (_rel(NextStep=2), (0x8704, 0x0011)), (_rel(NextStep=-1), (0x8704, 0x0011)),
    (_vel(NextStep=BLEND), (0x8704, 0x0023)),
    ({"Type": WAIT, "Duration": 0.1, "NextStep": BLEND}, (0x8704, 0x0023)),
    ({"Type": HALT, "NextStep": BLEND}, (0x8704, 0x0023)),
], ids=lambda x: repr(x) if isinstance(x, dict) else None)
def test_s7_1200_12_8_8700_8704_invalid_step(row, codes):
    """§12.8 16#8700 command type, 16#8701 position (format, > 1E+12, < -1E+12), 16#8702 velocity (format,
    > maximum velocity, < start/stop velocity; positioning needs 1.0e-12 <= v), 16#8703 duration (format,
    > 64800 s, < 0.001 s), 16#8704 next step (invalid selection; "Blend motion" only for Positioning
    Relative/Absolute, §6.4.3.2).  §9.6: shown only at MC_CommandTable, not at MC_Power."""
    b = Bench([row])
    ct = b.table_fb(Execute=True, EndStep=1)
    out = b.run_table(ct, 10)[-1]
    assert error_of(out) == codes
    assert not b.power.Error and not b.axis.StatusBits.Error and b.power.Status


@pytest.mark.parametrize("row", [_vel(Velocity=0.0), _vel(Velocity=-100.0), _vel(Duration=0.001),
                                 _rel(Position=0.0), _rel(Position=1.0e-12, Velocity=100.0),
                                 {"Type": WAIT, "Duration": 64800.0}, _rel(NextStep=BLEND)],
                         ids=["vel0", "vel-max", "dur-min", "pos0", "pos-tiny", "wait-max", "blend-last"])
def test_s7_1200_6_4_3_2_limit_values_accepted(row):
    """§6.4.3.2 limit values: velocity set point 0.0 and -1.0e12..-1.0e-12 allowed, duration 0.001 s .. 64800 s,
    position exactly 0.0 or >= 1.0e-12, Blend motion on a positioning step."""
    b = Bench([row])
    ct = b.table_fb(Execute=True, EndStep=1)
    outs = [b.scan()[id(ct)] for _ in range(5)]
    assert not any(o["Error"] for o in outs), outs[-1]
    assert outs[0]["Busy"] or outs[0]["Done"]


def test_s7_1200_9_6_table_error_in_later_step_motion_continues():
    """§9.6 "Configuration error of command table TO": the axis motion continues, the error is only shown at
    MC_CommandTable (not at MC_Power, no axis error); the remedy needs no MC_Reset: correct the value
    online and restart the command (§12.8)."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 0.6}, {"Type": 3}])
    ct = b.table_fb(Execute=True, EndStep=2)
    out = b.run_table(ct)[-1]
    assert error_of(out) == (0x8700, 0x0001)
    for _ in range(25):
        b.scan()
        assert b.axis.Velocity == pytest.approx(40.0), "motion continues"
    assert not b.power.Error and not b.axis.StatusBits.Error
    b.table.Command[2].Type = HALT                                   # correct online, restart
    ct.Execute = False
    b.scan()
    ct.Execute = True
    ct.StartStep = 2
    out = b.run_table(ct)[-1]
    assert out["Done"] and b.axis.Velocity == 0.0


# ==========================================================================================================
# §6.4.3.7 runtime editing
def test_s7_1200_6_4_3_7_step_values_changed_by_user_program_while_table_runs():
    """§6.4.3.7: Command[n].Type/Position/Velocity/Duration/NextStep/StepCode can be changed during runtime;
    decision 45: a step is checked (and taken) when it is about to run."""
    b = Bench([{"Type": REL, "Position": 10.0, "Velocity": 20.0, "StepCode": 1},
               {"Type": REL, "Position": 10.0, "Velocity": 20.0, "StepCode": 2}])
    ct = b.table_fb(Execute=True, EndStep=2)
    b.scan()
    b.scan()
    assert ct.CurrentStep == 1
    b.table.Command[2].Position = 30.0
    b.table.Command[2].Velocity = 50.0
    b.table.set_tag("Command[2].StepCode", 77)
    assert b.table.tag("Command[2].Velocity") == 50.0
    outs = b.run_table(ct)
    assert outs[-1]["Done"]
    assert (2, 77) in steps_seen(outs)
    assert b.axis.Position == pytest.approx(40.0)
    assert max(v for _, _, v in b.trace) == pytest.approx(50.0)


def test_s7_1200_12_10_8_1_table_has_32_steps():
    """§6.4.3.2 "Up to 32 commands"; tags Command[1..32]."""
    b = Bench()
    assert b.table.Command[32].Type == 0 and b.table.Command[1].Velocity == 0.0
    for bad in (0, 33):
        with pytest.raises(IndexError):
            b.table.Command[bad]


# ==========================================================================================================
# §11.1.9.1 requirements
@pytest.mark.parametrize("actor", [1, 0], ids=["PROFIdrive", "analog"])
def test_s7_1200_11_1_9_1_only_for_pto_axes(actor):
    """§11.1.9.1: MC_CommandTable "is available for axes with drive connection via PTO"; requirement "The
    drive is connected via PTO" -> 16#8408/16#001B "Axis does not match the required TO type" (§12.8)."""
    b = Bench([{"Type": REL, "Position": 5.0, "Velocity": 20.0}], actor=actor)
    ct = b.table_fb(Execute=True, EndStep=1)
    out = b.scan()[id(ct)]
    assert error_of(out) == (0x8408, 0x001B)
    for _ in range(20):
        b.scan()
    assert b.axis.Position == pytest.approx(0.0, abs=1e-3)


@pytest.mark.parametrize("value, info", [("axis", 0x001B), (None, 0x001C), (42, 0x001C)])
def test_s7_1200_12_8_8409_invalid_command_table_input(value, info):
    """§12.8 16#8409: invalid CommandTable (16#001B wrong TO type, 16#001C not a technology DB)."""
    b = Bench()
    ct = b.table_fb(Execute=True)
    ct.CommandTable = b.axis if value == "axis" else value
    assert error_of(b.scan()[id(ct)]) == (0x8409, info)


def test_s7_1200_11_1_9_1_axis_must_be_enabled():
    """§11.1.9.1 requirement "The axis is enabled" -> 16#8200 "Axis is not enabled"."""
    b = Bench([{"Type": REL, "Position": 5.0, "Velocity": 20.0}], enable=False)
    ct = b.table_fb(Execute=True, EndStep=1)
    assert error_of(b.scan()[id(ct)]) == (0x8200, 0x0001)


# ==========================================================================================================
# §11.1.9.1 override response
def test_s7_1200_11_1_9_1_running_command_aborted_only_when_first_motion_step_starts():
    """§11.1.9.1: "The active Motion Control command is canceled by the start of the first 'Positioning
    Relative', 'Positioning Absolute', 'Velocity set point' or 'Halt' command" -- leading Wait steps leave
    the running MC_MoveVelocity alone (it keeps Busy and its velocity)."""
    b = Bench([{"Type": WAIT, "Duration": 0.3, "StepCode": 1},
               {"Type": WAIT, "Duration": 0.1, "StepCode": 2},
               {"Type": REL, "Position": 10.0, "Velocity": 20.0, "StepCode": 3}])
    mv = b.add(MC_MoveVelocity(Execute=True, Velocity=30.0))
    b.scan_until(lambda: mv.InVelocity, 200)
    ct = b.table_fb(Execute=True, EndStep=3)
    during_wait = []
    for _ in range(1000):
        out = b.scan()
        o = out[id(ct)]
        if o["Busy"] and o["CurrentStep"] in (1, 2):
            during_wait.append((out[id(mv)], b.axis.Velocity))
        if o["Busy"] and o["CurrentStep"] == 3:
            break
    assert len(during_wait) >= int(0.4 / APP) - 1
    assert all(m["Busy"] and not m["CommandAborted"] for m, _ in during_wait)
    assert all(v == pytest.approx(30.0) for _, v in during_wait)
    assert mv.CommandAborted and not mv.Busy
    start = b.axis.Position
    outs = b.run_table(ct)
    assert outs[-1]["Done"]
    assert b.axis.Position > start


def _aborters(b: Bench):
    return {
        "MC_Halt": lambda: MC_Halt(Axis=b.axis, Execute=True),
        "MC_MoveRelative": lambda: MC_MoveRelative(Axis=b.axis, Execute=True, Distance=5.0, Velocity=20.0),
        "MC_MoveAbsolute": lambda: MC_MoveAbsolute(Axis=b.axis, Execute=True, Position=500.0, Velocity=20.0),
        "MC_MoveVelocity": lambda: MC_MoveVelocity(Axis=b.axis, Execute=True, Velocity=10.0),
        "MC_MoveJog": lambda: MC_MoveJog(Axis=b.axis, JogForward=True, Velocity=10.0),
        "MC_CommandTable": lambda: MC_CommandTable(Axis=b.axis, CommandTable=b.table, Execute=True,
                                                   StartStep=2, EndStep=2),
    }


@pytest.mark.parametrize("name", ["MC_Halt", "MC_MoveRelative", "MC_MoveAbsolute", "MC_MoveVelocity",
                                  "MC_MoveJog", "MC_CommandTable"])
def test_s7_1200_11_1_9_1_another_command_aborts_the_table(name):
    """§11.1.9.1: MC_CommandTable "can be aborted by" MC_Halt, MC_MoveAbsolute, MC_MoveRelative,
    MC_MoveVelocity, MC_MoveJog, MC_CommandTable -> CommandAborted (latched while Execute is TRUE),
    Busy FALSE; StatusBits.CommandTableActive FALSE afterwards."""
    b = Bench([{"Type": VEL, "Velocity": 40.0, "Duration": 5.0},
               {"Type": VEL, "Velocity": 15.0, "Duration": 5.0}])
    b.home(0.0)
    ct = b.table_fb(Execute=True, EndStep=1)
    b.scan_until(lambda: b.axis.Velocity == pytest.approx(40.0), 200)
    assert b.axis.StatusBits.CommandTableActive
    new = b.add(_aborters(b)[name]())
    first = b.scan()                     # the table instance is called before the new command
    assert first[id(ct)]["Busy"] and not first[id(new)].get("Error")
    out = b.scan()
    assert out[id(ct)]["CommandAborted"] and not out[id(ct)]["Busy"]
    for _ in range(3):
        assert b.scan()[id(ct)]["CommandAborted"]
    if name != "MC_CommandTable":
        assert not b.axis.StatusBits.CommandTableActive
    ct.Execute = False
    assert not b.scan()[id(ct)]["CommandAborted"]


def test_s7_1200_11_1_9_1_table_aborts_running_motion_command():
    """§11.1.9.1: the new MC_CommandTable aborts an active MC_MoveRelative (when its first motion step
    starts)."""
    b = Bench([{"Type": VEL, "Velocity": 20.0, "Duration": 0.2}])
    mr = b.add(MC_MoveRelative(Execute=True, Distance=500.0, Velocity=50.0))
    b.scan_until(lambda: b.axis.Velocity > 10.0, 100)
    ct = b.table_fb(Execute=True, EndStep=1)
    assert b.scan()[id(ct)]["Busy"]      # MC_MoveRelative is called before the table in each scan
    out = b.scan()
    assert out[id(mr)]["CommandAborted"] and not out[id(mr)]["Busy"] and out[id(ct)]["Busy"]
    assert b.run_table(ct)[-1]["Done"]


@pytest.mark.parametrize("mode", [0, 1])
def test_s7_1200_12_8_8207_0019_direct_homing_rejected_while_table_runs(mode):
    """§11.1.3 MC_Home requirement "no MC_CommandTable may be active upon start with Mode = 0, 1 or 2";
    §12.8 16#8207/16#0019; the table goes on (decision 46)."""
    b = Bench([{"Type": VEL, "Velocity": 20.0, "Duration": 1.0}])
    ct = b.table_fb(Execute=True, EndStep=1)
    b.scan()
    b.scan()
    home = b.add(MC_Home(Execute=True, Mode=mode, Position=0.0))
    out = b.scan()
    assert error_of(out[id(home)]) == (0x8207, 0x0019)
    assert out[id(ct)]["Busy"] and not b.axis.StatusBits.HomingDone


HOMING = {"Sensor[1].ActiveHoming.DigitalInputAddress": "I0.2",
          "Sensor[1].PassiveHoming.DigitalInputAddress": "I0.2", "Plant.HomingSwitchPosition": 200.0, "Homing": {"ApproachVelocity": 50.0, "ReferencingVelocity": 10.0}}


def test_s7_1200_12_8_8207_0018_table_rejected_while_passively_homed():
    """§12.8 16#8207/16#0018 "axis cannot be moved with a command table while being actively or passively
    homed"; decision 46: rejected while passive homing (MC_Home Mode 2) is armed; the homing goes on."""
    b = Bench([{"Type": VEL, "Velocity": 20.0, "Duration": 1.0}], extra=HOMING)
    home = b.add(MC_Home(Execute=True, Mode=2, Position=0.0))
    b.scan()
    assert home.Busy
    ct = b.table_fb(Execute=True, EndStep=1)
    out = b.scan()
    assert error_of(out[id(ct)]) == (0x8207, 0x0018)
    assert out[id(home)]["Busy"] and b.axis.Velocity == 0.0


def test_s7_1200_11_1_9_1_active_homing_aborts_table_and_table_aborts_active_homing():
    """§11.1.9.1 override response: MC_CommandTable is aborted by "MC_Home command Mode = 3" and aborts an
    active "MC_Home command Mode = 3" (decision 46)."""
    b = Bench([{"Type": VEL, "Velocity": 20.0, "Duration": 5.0}], extra=HOMING)
    ct = b.table_fb(Execute=True, EndStep=1)
    for _ in range(20):
        b.scan()
    home = b.add(MC_Home(Execute=True, Mode=3, Position=0.0))
    b.scan()
    b.scan()
    assert ct.CommandAborted and home.Busy and b.axis.StatusBits.HomingCommand
    assert not b.axis.StatusBits.CommandTableActive
    ct2 = b.table_fb(Execute=True, EndStep=1)
    b.scan()
    b.scan()
    assert home.CommandAborted and ct2.Busy and b.axis.StatusBits.CommandTableActive


# ==========================================================================================================
# the table moves the axis like a motion command: status tags, direction and SW limits
def test_s7_1200_10_2_target_position_during_table_positioning_step():
    """§10.2 "Target position ... indicates the current target position of an active positioning command or
    of the axis command table"; "Remaining travel distance ... for an active positioning command or the axis
    command table" (StatusPositioning.TargetPosition / .Distance)."""
    b = Bench([{"Type": REL, "Position": 30.0, "Velocity": 20.0}])
    ct = b.table_fb(Execute=True, EndStep=1)
    for _ in range(50):
        b.scan()
    assert ct.Busy
    assert b.axis.StatusPositioning.TargetPosition == pytest.approx(30.0)
    assert b.axis.StatusPositioning.Distance == pytest.approx(30.0 - b.axis.Position)


@pytest.mark.parametrize("row", [{"Type": REL, "Position": -10.0, "Velocity": 20.0},
                                 {"Type": VEL, "Velocity": -20.0, "Duration": 0.5}], ids=["rel", "vel"])
def test_s7_1200_12_8_8008_direction_mode_applies_to_table_steps(row):
    """§5.4.4.1 Actor.DirectionMode = 1 (positive only); §12.8 16#8008/16#002E "The selected motion direction
    is not allowed" (operating error with axis stop: at the instruction and MC_Power, §9.6) -- the axis
    never moves in the forbidden direction, whichever instruction commands it."""
    b = Bench([row], extra={"Actor.DirectionMode": 1})
    ct = b.table_fb(Execute=True, EndStep=1)
    outs = b.run_table(ct, 400)
    assert error_of(outs[-1]) == (0x8008, 0x002E)
    assert min(p for _, p, _ in b.trace) >= -1e-9
    b.scan()
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x8008, 0x002E)


def test_s7_1200_5_4_4_3_sw_limit_switch_stops_table_motion():
    """§6.4.3.2 note: the trend view does not show "movements in response to software limit switches being
    reached" -- the real axis does react: §5.4.4.3 the motion is stopped at the SW limit with the configured
    deceleration, 16#8002/16#000E at the triggering instruction and MC_Power."""
    b = Bench([{"Type": ABS, "Position": 80.0, "Velocity": 40.0}],
              extra={"PositionLimits_SW": {"Active": True, "MinPosition": -100.0, "MaxPosition": 50.0}})
    b.home(0.0)
    ct = b.table_fb(Execute=True, EndStep=1)
    outs = b.run_table(ct, 1000)
    assert error_of(outs[-1]) == (0x8002, 0x000E)
    for _ in range(100):
        b.scan()
    assert max(p for _, p, _ in b.trace) <= 50.0 + 1e-6
    assert b.axis.Position == pytest.approx(50.0)
    assert b.power.ErrorID == 0x8002 and b.axis.StatusBits.SWLimitMaxActive


def test_s7_1200_5_4_4_3_hw_limit_switch_stops_table_motion():
    """§5.4.4.3 "Response of the axis when position limits are triggered": a PTO axis that approaches a hardware
    limit switch brakes to standstill with the emergency deceleration; "HW limit switch approached" (16#8004/
    16#000E) is shown at the initiating instruction (here MC_CommandTable) and at MC_Power."""
    b = Bench([{"Type": VEL, "Velocity": 20.0, "Duration": 5.0}],
              extra={"PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.3", "MaxSwitchAddress": "I0.4"},
                     "Plant": {"HWLimitMaxPosition": 30.0, "HWLimitMinPosition": -30.0}})
    ct = b.table_fb(Execute=True, EndStep=1)
    outs = b.run_table(ct, 1000)
    assert error_of(outs[-1]) == (0x8004, 0x000E)
    for _ in range(20):
        b.scan()
    assert b.axis.Velocity == 0.0 and b.axis.StatusBits.HWLimitMaxActive
    assert (b.power.ErrorID, b.power.ErrorInfo) == (0x8004, 0x000E)
    # input filter 6.4 ms (§5.4.4.3) plus the emergency ramp 20^2 / (2 x 1000)
    assert 30.0 <= b.axis.Position <= 30.0 + 20.0 * (0.0064 + 2 * SERVO) + 20.0 ** 2 / (2 * 1000.0)


def test_s7_1200_11_1_1_power_disable_aborts_table():
    """§11.1.1 MC_Power Enable = FALSE "aborts all commands" of the axis: the running table shows
    CommandAborted and the axis is stopped and disabled."""
    b = Bench([{"Type": VEL, "Velocity": 30.0, "Duration": 5.0}])
    ct = b.table_fb(Execute=True, EndStep=1)
    for _ in range(30):
        b.scan()
    b.power.Enable = False
    outs = [b.scan()[id(ct)] for _ in range(2)]
    assert outs[-1]["CommandAborted"] and not outs[-1]["Busy"]
    b.scan_until(lambda: not b.power.Status and not b.axis.StatusBits.Enable, 200)
    assert b.axis.Velocity == 0.0 and not b.axis.StatusBits.CommandTableActive


def test_s7_1200_command_table_field_beyond_lreal_gives_16_8701_not_overflow_s12_8():
    """A Python int beyond the LREAL range in a command table REAL field is stored as an invalid value:
    the step gives the manual's configuration error 16#8701 (ErrorInfo 16#0002), it never raises."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("A", {"DynamicLimits": {"MaxVelocity": 100.0}})     # PTO (§11.1.9)
    table = ctl.add_command_table("T", [{"Type": 5, "Position": 10**400, "Velocity": 10.0}])
    table.Command[1].Velocity = -10**400             # a runtime write neither
    power, ct = MC_Power(Axis=axis, Enable=True), MC_CommandTable()
    ctl.run_until(lambda: power().Status, 1.0)
    ct(Axis=axis, CommandTable=table, Execute=True, StartStep=1, EndStep=1)
    ctl.run_until(lambda: ct().Error, 1.0)
    assert (ct.ErrorID, ct.ErrorInfo) == (0x8701, 0x0002)
