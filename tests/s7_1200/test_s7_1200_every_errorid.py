"""Every ErrorID/ErrorInfo of S7-1200 Motion Control V6 §12.8, each provoked in the situation the manual
names, with where it is shown (§9.6: the instruction, and MC_Power for errors with axis stop and axis
configuration errors) and the axis reaction.  Codes that cannot arise in plcmotion are listed in
``NOT_PRODUCIBLE`` with the reason (also in docs/errorids.md)."""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_ChangeDynamic, MC_CommandTable, MC_Halt, MC_Home, MC_MoveAbsolute,
                               MC_MoveJog, MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_ReadParam, MC_Reset,
                               MC_WriteParam)
from plcmotion.s7_1200 import variables as V

PTO = {"Actor": {"Type": 2}, "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0},
       "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": 200.0, "Jerk": 0.0, "EmergencyDeceleration": 2000.0}}
SERVO = {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 100.0},
         "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": 200.0, "Jerk": 0.0, "EmergencyDeceleration": 2000.0}}


def merge(base: dict, extra: dict) -> dict:
    out = {k: (dict(v) if isinstance(v, dict) else v) for k, v in base.items()}
    for k, v in extra.items():
        out[k] = merge(out.get(k, {}), v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


class Rig:
    """One axis, MC_Power enabled, helpers to run instructions until they end."""

    def __init__(self, params: dict, *, enable: bool = True, home: bool = False, **ctl_kw):
        self.ctl = Controller(**ctl_kw)
        self.axis = self.ctl.add_positioning_axis("A", params)
        self.power = MC_Power()
        self.power(Axis=self.axis, Enable=enable)
        if enable:
            self.run_until(lambda: self.power().Status, 1.0)
        if home:
            h = MC_Home()
            h(Axis=self.axis, Execute=True, Mode=0, Position=0.0)

    def run_until(self, cond, timeout: float = 20.0) -> None:
        end = self.ctl.time + timeout
        while not cond() and self.ctl.time < end:
            self.ctl.step()
        assert cond(), "condition not reached"

    def finish(self, inst, timeout: float = 20.0):
        """Call ``inst`` every cycle until it shows Error/Done/CommandAborted."""
        self.run_until(lambda: inst().Error or getattr(inst, "Done", False) or getattr(inst, "CommandAborted", False),
                       timeout)
        self.power()
        return inst


def codes(inst) -> tuple[int, int]:
    return inst.ErrorID, inst.ErrorInfo


# --- scenarios: each returns (instruction showing the error, rig) --------------------------------------------
def s_drive_not_ready():
    r = Rig(merge(SERVO, {"Actor": {"Interface": {"DriveReadyInput": "I0.4"}}}), input_filter=0.0)
    r.axis.inject_fault("drive_not_ready")
    r.ctl.step()
    return r.power(), r


def s_sw_limit(side: str, info: int):
    r = Rig(merge(PTO, {"PositionLimits_SW": {"Active": True, "MinPosition": -50.0, "MaxPosition": 50.0}}), home=True)
    sign = 1.0 if side == "max" else -1.0
    mv = MC_MoveVelocity()
    if info == 0x000E:
        mv(Axis=r.axis, Execute=True, Velocity=sign * 40.0)
    else:
        mv(Axis=r.axis, Execute=True, Velocity=sign * 100.0)
        r.run_until(lambda: abs(r.axis.Position) < 30.0 and mv().InVelocity, 5.0)
        r.ctl.run(0.05)
        # §12.4: homing shifts the position toward the limit while moving at 100: braking with the
        # deceleration needs 25, with the emergency deceleration 2.5
        h = MC_Home()
        jump = 15.0 if info == 0x000F else 19.5
        h(Axis=r.axis, Execute=True, Mode=1, Position=sign * jump)
    return r.finish(mv), r


def s_hw_limit(side: str):
    r = Rig(merge(PTO, {"PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.1", "MaxSwitchAddress": "I0.2"},
                        "Plant": {"HWLimitMinPosition": -30.0, "HWLimitMaxPosition": 30.0}}))
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=50.0 if side == "max" else -50.0)
    return r.finish(mv), r


def s_hw_used():
    ctl = Controller()
    a = ctl.add_positioning_axis("A", merge(PTO, {"Actor": {"Interface": {"PTO": 1}}}))
    b = ctl.add_positioning_axis("B", merge(PTO, {"Actor": {"Interface": {"PTO": 1}}}))
    pa = MC_Power()
    pa(Axis=a, Enable=True)
    ctl.step()
    mv = MC_MoveRelative()
    mv(Axis=b, Execute=True, Distance=10.0, Velocity=10.0)
    return mv, None


def s_direction(info: int):
    r = Rig(merge(PTO, {"Actor": {"DirectionMode": 1}}))
    mv = MC_MoveRelative()
    if info == 0x002E:
        mv(Axis=r.axis, Execute=True, Distance=-10.0, Velocity=10.0)
        return r.finish(mv), r
    first = MC_MoveVelocity()
    first(Axis=r.axis, Execute=True, Velocity=80.0)
    r.run_until(lambda: first().InVelocity, 2.0)
    mv(Axis=r.axis, Execute=True, Distance=1.0, Velocity=10.0)   # needs a reversal: not permitted
    return r.finish(mv), r


def s_reference_not_found():
    r = Rig(merge(PTO, {"Homing": {"ApproachVelocity": 50.0, "ReferencingVelocity": 10.0, "AutoReversal": True},
                        "Sensor[1]": {"ActiveHoming": {"DigitalInputAddress": "I0.0"}},
                        "PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.1", "MaxSwitchAddress": "I0.2"},
                        "Plant": {"HWLimitMinPosition": -30.0, "HWLimitMaxPosition": 30.0}}),
            input_filter=0.0)
    h = MC_Home()
    h(Axis=r.axis, Execute=True, Mode=3, Position=0.0)    # no homing switch between the limit switches
    return r.finish(h), r


def s_device(kind: str, detail: str):
    r = Rig(SERVO)
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=20.0)
    r.ctl.run(0.1)
    r.axis.inject_fault(kind, detail)
    return r.finish(mv), r


def s_position_range(info: int):
    if info == 0x003B:
        r = Rig(merge(SERVO, {"Modulo": {"Enable": True, "Length": 0.5}, "DynamicLimits": {"MaxVelocity": 1000.0},
                              "Actor": {"DriveParameter": {"MaxSpeed": 6000.0}}}))
        mv = MC_MoveVelocity()
        mv(Axis=r.axis, Execute=True, Velocity=900.0)     # more than a modulo length per servo cycle
        return r.finish(mv), r
    r = Rig(merge(SERVO, {"Sensor[1]": {"Type": 1, "Parameter": {"DeterminableRevolutions": 2}},
                          "Plant": {"InitialPosition": 10.0}}))
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=50.0 if info == 0x0039 else -50.0)
    return r.finish(mv), r


def s_following_error():
    r = Rig(merge(SERVO, {"FollowingError": {"MinValue": 0.001, "MaxValue": 0.002},
                          "PositionControl": {"Kpc": 0.0}}))
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=50.0)
    return r.finish(mv), r


def s_hw_free(info: int):
    params = merge(SERVO, {"PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.1", "MaxSwitchAddress": "I0.2"},
                           "Plant": {"HWLimitMinPosition": -30.0, "HWLimitMaxPosition": 30.0}})
    r = Rig(params, input_filter=0.0)
    if info == 0x0044:
        r.ctl.inputs.force("I0.1", False)       # both switches actuated (low-active contacts)
        r.ctl.inputs.force("I0.2", False)
        r.ctl.step()
        return r.power(), r
    if info == 0x0043:
        mv = MC_MoveVelocity()
        mv(Axis=r.axis, Execute=True, Velocity=10.0)
        r.ctl.run(0.1)
        r.ctl.inputs.force("I0.1", False)      # the low switch while moving up: wiring swapped
        return r.finish(mv), r
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=50.0)
    r.finish(mv)
    reset = MC_Reset()
    reset(Axis=r.axis, Execute=True)
    r.run_until(lambda: r.power().Status, 2.0)
    again = MC_MoveRelative()
    again(Axis=r.axis, Execute=True, Distance=5.0, Velocity=10.0)      # further into the switch
    return r.finish(again), r


def s_positioning(info: int):
    extra = {"PositioningMonitoring": {"Window": 0.01, "ToleranceTime": 0.05, "MinDwellTime": 0.5},
             "PositionControl": {"Kv": 1.0}, "FollowingError": {"EnableMonitoring": False}}
    r = Rig(merge(SERVO, extra))
    mv = MC_MoveRelative()
    mv(Axis=r.axis, Execute=True, Distance=20.0, Velocity=50.0)
    if info == 0x0046:
        r.run_until(lambda: r.axis.job is None or r.ctl.bank.pm_on[r.axis.index] if r.axis.job else False, 5.0)
    return r.finish(mv), r


def s_sw_order():
    r = Rig(merge(SERVO, {"PositionLimits_SW": {"Active": True}}), home=True)
    r.axis.PositionLimits_SW.MinPosition = 20000.0          # written at runtime above the high limit
    r.ctl.step()
    return r.power(), r


def s_homing_zero(path: str):
    params = merge(PTO, {"Sensor[1]": {"ActiveHoming": {"DigitalInputAddress": "I0.0"}},
                         "Homing": {"ApproachVelocity": 0.0 if path == "approach" else 50.0,
                                    "ReferencingVelocity": 0.0 if path == "referencing" else 10.0}})
    r = Rig(params)
    h = MC_Home()
    h(Axis=r.axis, Execute=True, Mode=3)
    return r.finish(h), r


def s_rejection(code: str):
    r = Rig(PTO, enable=code not in ("not_enabled",))
    mv = MC_MoveAbsolute() if code == "not_homed" else MC_MoveRelative()
    if code == "already_enabled":
        second = MC_Power()
        second(Axis=r.axis, Enable=True)
        return second, r
    if code == "numeric_limit":
        mv(Axis=r.axis, Execute=True, Distance=1.0e12, Velocity=10.0)
        r.axis.ctl.step()
        mv2 = MC_MoveRelative()
        r.ctl.step()
        hm = MC_Home()
        hm(Axis=r.axis, Execute=True, Mode=0, Position=5.0e11)
        mv2(Axis=r.axis, Execute=True, Distance=6.0e11, Velocity=10.0)
        return mv2, r
    if code == "homing_active":
        params = merge(PTO, {"Sensor[1]": {"ActiveHoming": {"DigitalInputAddress": "I0.0"}},
                             "Homing": {"ApproachVelocity": 50.0, "ReferencingVelocity": 10.0}})
        r = Rig(params)
        h3 = MC_Home()
        h3(Axis=r.axis, Execute=True, Mode=3)
        r.ctl.step()
        h0 = MC_Home()
        h0(Axis=r.axis, Execute=True, Mode=0)
        return h0, r
    if code == "not_running":
        r.ctl.stop("test")
    if code == "actual_invalid":
        r = Rig(SERVO)
        r.axis.inject_fault("encoder", "dirty", persistent=True)
        reset = MC_Reset()
        reset(Axis=r.axis, Execute=True)
        r.power(Enable=True, StartMode=0)            # without position control (§12.7)
        r.run_until(lambda: r.power().Status, 1.0)
        h = MC_Home()
        h(Axis=r.axis, Execute=True, Mode=0)
        return h, r
    if code == "position_control":
        r = Rig(SERVO)
        r.axis.inject_fault("encoder", "dirty", persistent=True)
        MC_Reset()(Axis=r.axis, Execute=True)
        p2 = r.power
        p2(Enable=False)
        r.ctl.run(0.1)
        p2(Enable=True, StartMode=0)
        r.run_until(lambda: p2().Status, 1.0)
        mv(Axis=r.axis, Execute=True, Distance=1.0, Velocity=1.0)
        return mv, r
    if code == "too_many":
        r.axis.busy_commands.update(range(200))
    if code == "not_activated":
        ctl = Controller()
        a = ctl.add_positioning_axis("A", merge(PTO, {"Actor": {"Interface": {"PTO": 1}}}))
        mv(Axis=a, Execute=True, Distance=1.0, Velocity=10.0)
        return mv, None
    mv(Axis=r.axis, Execute=True, Distance=1.0, Velocity=10.0) if not isinstance(mv, MC_MoveAbsolute) else \
        mv(Axis=r.axis, Execute=True, Position=1.0, Velocity=10.0)
    return mv, r


def s_restart(info: int):
    r = Rig(PTO)
    if info == 0x002C:
        mv = MC_MoveVelocity()
        mv(Axis=r.axis, Execute=True, Velocity=80.0)
        r.ctl.run(0.5)
        r.power(Enable=False)
        r.ctl.step()
    reset = MC_Reset()
    reset(Axis=r.axis, Execute=True, Restart=True)
    return reset, r


def s_change_dynamic(kind: str):
    r = Rig(merge(PTO, {"DynamicLimits": {"MinVelocity": 100.0}}) if kind == "span" else PTO)
    cd = MC_ChangeDynamic()
    if kind == "span":
        cd(Axis=r.axis, Execute=True, ChangeRampUp=True, RampUpTime=1.0)
    else:
        cd(Axis=r.axis, Execute=True, ChangeJerkTime=True, JerkTime=0.1)
        r.axis.cfg["DynamicDefaults.Acceleration"] = float("nan")     # a broken acceleration tag
        cd(Execute=False)
        cd(Execute=True)
    return cd, r


def s_config(path: str, value, where: str = "pto"):
    r = Rig(PTO if where == "pto" else SERVO)
    mv = MC_MoveVelocity()
    r.axis.set_tag(path, value)        # direct assignment in the user program (RW tag)
    mv(Axis=r.axis, Execute=True, Velocity=20.0)
    r.ctl.step()
    return mv(), r


def s_write_param(path: str, value):
    r = Rig(PTO, enable=False)
    wp = MC_WriteParam()
    wp(Parameter=r.axis.ref(path), Value=value, Execute=True)
    power = MC_Power()
    power(Axis=r.axis, Enable=True)
    r.ctl.step()
    return power(), r


def s_table(field: str, value, extra: dict | None = None):
    r = Rig(PTO)
    step = {"Type": 5, "Position": 10.0, "Velocity": 10.0}
    step.update(extra or {})
    step[field] = value
    table = r.ctl.add_command_table("T", [step])
    ct = MC_CommandTable()
    ct(Axis=r.axis, CommandTable=table, Execute=True, StartStep=1, EndStep=1)
    return ct, r


def s_internal():
    r = Rig(PTO)
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=20.0)

    def broken(*args, **kw):
        raise RuntimeError("injected defect")
    r.axis._on_milestone = broken                      # a defect while the axis handles an event
    return r.finish(mv), r


# (ErrorID, ErrorInfo, scenario, also shown at MC_Power, axis disabled afterwards)
CASES = [
    (0x8000, 0x0001, s_drive_not_ready, True, True),
    (0x8001, 0x000E, lambda: s_sw_limit("min", 0x000E), True, False),
    (0x8001, 0x000F, lambda: s_sw_limit("min", 0x000F), True, False),
    (0x8001, 0x0010, lambda: s_sw_limit("min", 0x0010), True, None),
    (0x8002, 0x000E, lambda: s_sw_limit("max", 0x000E), True, False),
    (0x8002, 0x000F, lambda: s_sw_limit("max", 0x000F), True, False),
    (0x8002, 0x0010, lambda: s_sw_limit("max", 0x0010), True, None),
    (0x8003, 0x000E, lambda: s_hw_limit("min"), True, False),
    (0x8004, 0x000E, lambda: s_hw_limit("max"), True, False),
    (0x8005, 0x0001, s_hw_used, False, None),
    (0x8008, 0x002E, lambda: s_direction(0x002E), True, False),
    (0x8008, 0x002F, lambda: s_direction(0x002F), True, False),
    (0x8009, 0x0033, s_reference_not_found, True, False),
    *[(0x800A, info, (lambda d=detail: s_device("encoder", d)), True, True) for info, detail in
      [(0x0001, ""), (0x0034, "hardware"), (0x0035, "dirty"), (0x0036, "absolute_value"), (0x0037, "zero_mark"),
       (0x0038, "parking"), (0x0040, "station"), (0x0041, "sign_of_life")]],
    (0x800B, 0x0039, lambda: s_position_range(0x0039), True, True),
    (0x800B, 0x003A, lambda: s_position_range(0x003A), True, True),
    (0x800B, 0x003B, lambda: s_position_range(0x003B), True, True),
    *[(0x800C, info, (lambda d=detail: s_device("drive", d)), True, True) for info, detail in
      [(0x0001, ""), (0x003C, "control_requested"), (0x003D, "shutdown"), (0x003E, "station"),
       (0x003F, "sign_of_life")]],
    (0x800D, 0x0001, s_following_error, True, True),
    (0x800E, 0x0042, lambda: s_hw_free(0x0042), True, True),
    (0x800E, 0x0043, lambda: s_hw_free(0x0043), True, True),
    (0x800E, 0x0044, lambda: s_hw_free(0x0044), True, True),
    (0x800F, 0x0045, lambda: s_positioning(0x0045), True, True),
    (0x8010, 0x0001, s_sw_order, True, True),
    (0x8011, 0x000A, lambda: s_homing_zero("approach"), True, True),
    (0x8012, 0x000A, lambda: s_homing_zero("referencing"), True, True),
    (0x8200, 0x0001, lambda: s_rejection("not_enabled"), False, None),
    (0x8201, 0x0001, lambda: s_rejection("already_enabled"), False, None),
    (0x8202, 0x0001, lambda: s_rejection("too_many"), False, None),
    (0x8204, 0x0001, lambda: s_rejection("not_homed"), False, None),
    (0x8206, 0x0001, lambda: s_rejection("not_activated"), False, None),
    (0x8207, 0x0016, lambda: s_rejection("homing_active"), False, None),
    (0x8207, 0x0052, lambda: s_rejection("numeric_limit"), False, None),
    (0x8207, 0x0053, lambda: s_rejection("not_running"), None, None),
    (0x8207, 0x0054, lambda: s_rejection("actual_invalid"), False, None),
    (0x8207, 0x006B, lambda: s_rejection("position_control"), False, None),
    (0x8208, 0x000A, lambda: s_change_dynamic("span"), False, None),
    (0x8209, 0x0002, lambda: s_change_dynamic("acceleration"), False, None),
    (0x820A, 0x0013, lambda: s_restart(0x0013), False, None),
    (0x820A, 0x002C, lambda: s_restart(0x002C), False, None),
    (0x8608, 0x0004, lambda: s_config("DynamicDefaults.Acceleration", -1.0), True, None),
    (0x8609, 0x0002, lambda: s_config("DynamicDefaults.Deceleration", math.nan), True, None),
    (0x860A, 0x0004, lambda: s_config("DynamicDefaults.EmergencyDeceleration", 0.0), True, None),
    (0x8614, 0x0020, lambda: s_config("DynamicDefaults.Jerk", -1.0), True, None),
    (0x860B, 0x0006, lambda: s_config("PositionLimits_SW.MinPosition", -2.0e12), True, None),
    (0x860C, 0x0005, lambda: s_config("PositionLimits_SW.MaxPosition", 2.0e12), True, None),
    (0x860F, 0x0005, lambda: s_config("Sensor[1].ActiveHoming.HomePositionOffset", 2.0e12, "servo"), True, None),
    (0x8607, 0x0003, lambda: s_write_param("DynamicLimits.MaxVelocity", V.Real(1.0e9)), True, None),
    (0x8606, 0x0007, lambda: s_write_param("DynamicLimits.MinVelocity", V.Real(200.0)), True, None),
    (0x8604, 0x000A, lambda: s_write_param("Actor.DriveParameter.PulsesPerDriveRevolution", V.DInt(0)), True, None),
    (0x861A, 0x0011, lambda: s_write_param("Actor.DirectionMode", V.Int(7)), True, None),
    (0x8615, 0x0011, lambda: s_write_param("Units.LengthUnit", V.Int(4711)), True, None),
    (0x8700, 0x0001, lambda: s_table("Type", 99), False, None),
    (0x8701, 0x0005, lambda: s_table("Position", 2.0e12), False, None),
    (0x8701, 0x0006, lambda: s_table("Position", -2.0e12), False, None),
    (0x8702, 0x0008, lambda: s_table("Velocity", 500.0), False, None),
    (0x8702, 0x0009, lambda: s_table("Velocity", 0.5), False, None),
    (0x8703, 0x0021, lambda: s_table("Duration", 70000.0, {"Type": 151}), False, None),
    (0x8703, 0x0022, lambda: s_table("Duration", 0.0001, {"Type": 151}), False, None),
    (0x8704, 0x0011, lambda: s_table("NextStep", 5), False, None),
    (0x8704, 0x0023, lambda: s_table("NextStep", 1, {"Type": 151, "Duration": 1.0}), False, None),
    (0x8FFF, 0xF001, s_internal, True, True),
]


@pytest.mark.parametrize("error_id, error_info, scenario, at_power, disabled", CASES,
                         ids=[f"16#{c[0]:04X}-16#{c[1]:04X}" for c in CASES])
def test_s7_1200_12_8_error_id(error_id, error_info, scenario, at_power, disabled):
    """§12.8 / §9.6: the ErrorID/ErrorInfo appears at the triggering instruction; errors with axis stop and
    configuration errors of the axis also at MC_Power, and their reaction (remove enable or not)."""
    inst, rig = scenario()
    assert inst.Error, f"no error shown: {inst!r}"
    assert codes(inst) == (error_id, error_info), f"16#{inst.ErrorID:04X}/16#{inst.ErrorInfo:04X}"
    if rig is None:
        return
    power = rig.power()
    if at_power:
        assert power.Error and power.ErrorID == error_id, f"MC_Power: {power!r}"
        assert rig.axis.StatusBits.Error
    elif at_power is False and inst is not power:
        assert not (power.Error and power.ErrorID == error_id), "shown at MC_Power although §9.6 says not"
    if disabled is not None:
        rig.ctl.run(0.3)
        assert rig.axis.StatusBits.Enable is (not disabled)


def test_s7_1200_positioning_window_left_during_dwell_12_8_800F_0046():
    """§5.4.4.6 / §12.8 16#800F/16#0046: the actual value leaves the positioning window during the
    minimum dwell time (pushed by a disturbance: the simulated load is moved)."""
    r = Rig(merge(SERVO, {"PositioningMonitoring": {"Window": 0.05, "ToleranceTime": 1.0, "MinDwellTime": 0.5}}))
    mv = MC_MoveRelative()
    mv(Axis=r.axis, Execute=True, Distance=10.0, Velocity=50.0)
    r.run_until(lambda: bool(r.ctl.bank.pm_on[r.axis.index]) and not math.isnan(r.ctl.bank.pm_in_since[r.axis.index]),
                5.0)
    group = r.axis.drive.group
    group.x[r.axis.drive.member] += 1.0                 # a collision pushes the load out of the window
    r.finish(mv)
    assert codes(mv) == (0x800F, 0x0046)
    assert r.power().ErrorID == 0x800F


NOT_PRODUCIBLE = {
    (0x8006, 0x0012): "axis control panel of TIA Portal (communication timeout): plcmotion has no panel",
    (0x8007, 0x0025): "a TO restart is instantaneous in plcmotion, an enable cannot fall into it",
    (0x8007, 0x0026): "no download in RUN",
    (0x8013, 0x0001): "no CTRL_PTO instruction",
    (0x8203, 0x0001): "no axis control panel",
    (0x8205, 0x0013): "no axis control panel",
    (0x820A, 0x0027): "no axis control panel",
    (0x820A, 0x0047): "no download: a TO is always ready for restart",
    (0x820A, 0x0048): "no download: restart conditions are those of 16#0013/16#002C",
    (0x820B, 0x0026): "no download in RUN",
    (0x820C, 0x0001): "the configuration always exists once the axis is created",
    (0x820C, 0x0014): "no other applications share the hardware",
}


def test_s7_1200_not_producible_codes_are_documented():
    """Every code listed as not producible is explained in docs/errorids.md."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "docs" / "errorids.md").read_text()
    for (error_id, info) in NOT_PRODUCIBLE:
        assert f"16#{error_id:04X}" in text
