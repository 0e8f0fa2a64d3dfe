"""Drive connections via PROFIdrive telegram and analog output, and Simulation.Mode, derived from the S7-1200
Motion Control V6 manual (and V7 where stated).

§1.2 / §2.2.2-§2.2.5 (telegrams 1-4: 16-bit / 32-bit NSET and NACT, encoder, sign of life), §5.4.3.2
(reference speed: "On the bus, the value 16#4000 is transferred ... 100 % of the reference speed", -200 % ..
+200 %, so MaxSpeed <= 2 x ReferenceSpeed; analog outputs "-117 % to 117 %"), §5.4.3.3 (encoder: steps per
revolution and fine resolution Gx_XIST1), §10.4 (PROFIdrive frame: STW1/ZSW1, NSET/NACT, G1_ZSW, G1_XIST1),
§11.1.1 (MC_Power: Status only once the drive is ready; error disables, MC_Reset re-enables), §5.4.3.1 /
§12.9.19 (Simulation.Mode), §12.8 (16#800C, 16#863F, 16#8645, 16#8647, V7 16#864B).
Project decisions respected: docs/decisions.md rows 38, 50, 51.
"""
from __future__ import annotations

import math

import pytest

from plcmotion import ConfigurationError, Controller
from plcmotion.kernel.faults import config_fault
from plcmotion.s7_1200 import MC_Home, MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_Reset, MC_WriteParam, codes
from plcmotion.s7_1200.variables import DInt

SERVO, APP = 0.001, 0.004
REF = 3000.0                   # ReferenceSpeed [1/min]
LEAD = 10.0                    # Mechanics.LeadScrew: mm per motor revolution (start value)


def rpm(v: float) -> float:
    """Motor speed [1/min] for a load velocity [mm/s]."""
    return v / LEAD * 60.0


def drive_params(actor: int = 1, *, telegram: int = 3, max_speed: float = 6000.0, vmax: float = 1000.0,
                 **extra) -> dict:
    p = {"Actor": {"Type": actor, "DriveParameter": {"ReferenceSpeed": REF, "MaxSpeed": max_speed}},
         "DynamicLimits": {"MaxVelocity": vmax},
         "DynamicDefaults": {"Acceleration": 2000.0, "Deceleration": 2000.0, "EmergencyDeceleration": 10000.0,
                             "Jerk": 0.0},
         "Plant": {"OffRampTime": 0.05}}
    if actor == 1:
        p["Actor"]["Interface"] = {"Telegram": telegram}
        p["Sensor[1].Interface.Type"] = 2 if telegram in (3, 4) else 4
    p.update(extra)
    return p


class Drive:
    def __init__(self, cfg: dict, *, enable: bool = True):
        self.ctl = Controller(servo_cycle=SERVO, app_cycle=APP)
        self.axis = self.ctl.add_positioning_axis("Axis_1", cfg)
        self.power = MC_Power(Axis=self.axis, Enable=enable)
        self.fbs: list = [self.power]
        if enable:
            self.until(lambda: self.power.Status, 200, "enabled")

    def add(self, fb):
        fb.Axis = self.axis
        self.fbs.append(fb)
        return fb

    def scan(self) -> None:
        for fb in self.fbs:
            fb()
        self.ctl.step()

    def until(self, cond, max_scans: int = 1000, what: str = "condition") -> None:
        for _ in range(max_scans):
            self.scan()
            if cond():
                return
        raise AssertionError(f"{what} not reached (t = {self.ctl.time:.3f} s)")

    def telegrams(self):
        return self.axis.drive.telegrams()

    def run_velocity(self, v: float, position_controlled: bool = False) -> MC_MoveVelocity:
        mv = self.add(MC_MoveVelocity(Execute=True, Velocity=v, PositionControlled=position_controlled))
        self.until(lambda: mv.InVelocity, 500, "InVelocity")
        for _ in range(5):
            self.scan()
        return mv


def config_errors(cfg: dict) -> set[tuple[int, int]]:
    try:
        Controller().add_positioning_axis("Axis_1", cfg)
    except ConfigurationError as exc:
        return {codes(config_fault(i.path, i.reason)) for i in exc.issues}
    return set()


def analog_word(axis) -> int:
    """The setpoint word written to the analog output (no public accessor; read from the simulated drive)."""
    return int(axis.drive.group.word[axis.drive.member])


# ==========================================================================================================
# STW1 / ZSW1
def test_s7_1200_11_1_1_enable_stw1_047F_and_zsw1_operation_enabled():
    """§11.1.1: with Enable = TRUE the drive is switched on; Status becomes TRUE only once the drive reports
    ready.  PROFIdrive (decision 51): STW1 = 16#047F (ON, no OFF2, no OFF3, enable operation, ramp generator
    enable/unfreeze, setpoint enable, control by PLC); "drive ready" is ZSW1 bit 2 OperationEnabled (with
    bits 0 ReadyToSwitchOn, 1 ReadyToOperate, 4 no OFF2, 5 no OFF3; bit 6 SwitchingOnInhibited and bit 3
    FaultPresent clear)."""
    d = Drive(drive_params(telegram=3, **{"Plant.ReadyDelay": 0.02}), enable=False)
    for _ in range(5):
        d.scan()
    out, inp = d.telegrams()
    assert int(out.STW1) & 0x0001 == 0 and not inp.ZSW1.OperationEnabled
    d.power.Enable = True
    seen_status = False
    for _ in range(100):
        d.scan()
        out, inp = d.telegrams()
        if d.power.Status:
            seen_status = True
            assert inp.ZSW1.OperationEnabled, "Status TRUE only with the drive ready"
    assert seen_status and d.axis.StatusBits.Enable and d.axis.StatusBits.DriveReady
    assert int(out.STW1) == 0x047F
    z = int(inp.ZSW1)
    assert z & 0x0037 == 0x0037 and z & 0x0048 == 0
    assert inp.ZSW1.ControlRequested


@pytest.mark.parametrize("telegram", [1, 3])
def test_s7_1200_11_1_1_disable_switches_drive_off(telegram):
    """§11.1.1 Enable = FALSE: the axis is stopped (StopMode 0: emergency stop) and disabled; the drive is
    switched off (STW1 bit 0 ON = 0, i.e. 16#047E), and reports ready to switch on but not operating
    (ZSW1 bit 0 set, bits 1 and 2 clear); Status and StatusBits.Enable FALSE."""
    d = Drive(drive_params(telegram=telegram))
    d.run_velocity(200.0, position_controlled=True)
    d.power.Enable = False
    d.until(lambda: not d.power.Status and not d.power.Busy, 500, "disabled")
    for _ in range(30):
        d.scan()
    out, inp = d.telegrams()
    assert int(out.STW1) == 0x047E
    z = int(inp.ZSW1)
    assert z & 0x0001 and not z & 0x0006 and not z & 0x0008
    assert not d.axis.StatusBits.Enable
    speed_word = out.NSOLL_A if telegram == 1 else out.NSOLL_B
    assert speed_word == 0


def test_s7_1200_12_8_800C_drive_fault_in_zsw1_disables_and_reset_reenables():
    """§12.8 16#800C "Alarm message from drive" (reaction remove enable, ErrorBits.DriveFault) with ZSW1 bit 3
    FaultPresent and no OperationEnabled; §11.1.1: the axis disabled by an error is enabled again
    automatically after MC_Reset when Enable stayed TRUE -- STW1 16#047F and ZSW1 OperationEnabled again."""
    d = Drive(drive_params(telegram=3))
    d.axis.inject_fault("drive")
    for _ in range(3):
        d.scan()
    out, inp = d.telegrams()
    assert inp.ZSW1.FaultPresent and not inp.ZSW1.OperationEnabled
    assert not out.STW1.On
    assert d.power.Error and (d.power.ErrorID, d.power.ErrorInfo) == (0x800C, 0x0001)
    assert not d.power.Status and d.axis.ErrorBits.DriveFault
    reset = d.add(MC_Reset(Execute=True))
    d.until(lambda: d.power.Status, 200, "re-enabled after MC_Reset")
    assert reset.Done and not d.power.Error
    out, inp = d.telegrams()
    assert int(out.STW1) == 0x047F and inp.ZSW1.OperationEnabled and not inp.ZSW1.FaultPresent


# ==========================================================================================================
# speed setpoint words
@pytest.mark.parametrize("v", [250.0, 123.4, -77.7, 999.0])
def test_s7_1200_5_4_3_2_nsoll_b_32_bit_scaling_telegram_3(v):
    """§5.4.3.2 / §12.9.5: the speed setpoint is transmitted as a standardised value of the reference speed;
    in the 32-bit words of telegram 3 100 % = 16#40000000: NSOLL_B = round(n / ReferenceSpeed x 2^30).
    Non-position-controlled (MC_MoveVelocity PositionControlled = FALSE, §12.7) the setpoint is exactly the
    commanded velocity; NIST_B reports the actual speed with the same scaling."""
    d = Drive(drive_params(telegram=3))
    d.run_velocity(v)
    out, inp = d.telegrams()
    assert out.NSOLL_B == round(rpm(v) / REF * 0x40000000)
    assert inp.NIST_B == pytest.approx(rpm(d.axis.ActualVelocity) / REF * 0x40000000, rel=1e-3)
    assert int(out.STW1) == 0x047F


@pytest.mark.parametrize("v", [250.0, 123.4, -77.7])
def test_s7_1200_5_4_3_2_nsoll_a_16_bit_scaling_telegram_1(v):
    """§5.4.3.2 "On the bus, the value 16#4000 is transferred ... which corresponds to 100 % of the reference
    speed" (V7: "16#4000 (16 bit, for telegram 1) = 100 %"): NSOLL_A = round(n / ReferenceSpeed x 16#4000)."""
    d = Drive(drive_params(telegram=1))
    d.run_velocity(v)
    out, inp = d.telegrams()
    assert out.NSOLL_A == round(rpm(v) / REF * 0x4000)
    assert abs(inp.NIST_A - rpm(d.axis.ActualVelocity) / REF * 0x4000) <= 2


@pytest.mark.parametrize("telegram, field, hi, lo", [(3, "NSOLL_B", 0x7FFFFFFF, -0x80000000),
                                                     (1, "NSOLL_A", 0x7FFF, -0x8000)])
def test_s7_1200_5_4_3_2_200_percent_saturates_the_word(telegram, field, hi, lo):
    """§5.4.3.2: "A maximum of -200% to +200% of the reference speed can be transmitted over the bus" -- at
    MaxSpeed = 2 x ReferenceSpeed the word is at its limit (+200 % is one count short of 2 x 16#4000...)."""
    d = Drive(drive_params(telegram=telegram, max_speed=2 * REF, vmax=1000.0))
    mv = d.run_velocity(1000.0)
    assert getattr(d.telegrams()[0], field) == hi
    d.fbs.remove(mv)
    d.run_velocity(-1000.0)
    assert getattr(d.telegrams()[0], field) == lo


@pytest.mark.parametrize("v", [250.0, -300.0, 50.0])
def test_s7_1200_5_4_3_2_analog_setpoint_scaling(v):
    """§5.4.3.2 analog drive: the reference speed is the speed at 100 % of the analog output; 100 % is the
    nominal value of the S7 analog output (27648)."""
    d = Drive(drive_params(actor=0, max_speed=3510.0, vmax=500.0))
    d.run_velocity(v)
    assert analog_word(d.axis) == round(rpm(v) / REF * 27648)


def test_s7_1200_5_4_3_2_analog_setpoint_limited_to_max_speed_within_117_percent():
    """§5.4.3.2: "Analog outputs can be overloaded by approximately 17%" (-117 % .. 117 %) and the maximum speed
    limits the setpoint: with MaxSpeed = 1.17 x ReferenceSpeed the position controller's correction during
    acceleration cannot drive the word beyond round(1.17 x 27648) = 32348, below the overrange limit 32511."""
    d = Drive(drive_params(actor=0, max_speed=1.17 * REF, vmax=585.0,
                           **{"Plant.SpeedTimeConstant": 0.05, "FollowingError.EnableMonitoring": False}))
    words = []
    mv = d.add(MC_MoveVelocity(Execute=True, Velocity=585.0))
    for _ in range(150):
        d.scan()
        words.append(analog_word(d.axis))
    d.fbs.remove(mv)
    d.add(MC_MoveVelocity(Execute=True, Velocity=-585.0))
    for _ in range(300):
        d.scan()
        words.append(analog_word(d.axis))
    limit = round(1.17 * 27648)
    assert max(words) == limit and min(words) == -limit
    assert all(-32512 <= w <= 32511 for w in words)


# ==========================================================================================================
# encoder value G1_XIST1
def test_s7_1200_5_4_3_3_g1_xist1_is_the_encoder_count_with_fine_resolution_modulo_2_32():
    """§5.4.3.3 / §2.2.2: rotary encoder with StepsPerRevolution (2048) and fine resolution Gx_XIST1 (11 bits):
    one count = 10 mm / (2048 x 2^11); §10.4 G1_XIST1 is the cyclic incremental actual value (a 32-bit
    counter, so a negative count wraps modulo 2^32).  The actual position changes by the counted increments."""
    d = Drive(drive_params(telegram=3, **{"Plant.InitialPosition": -5.0}))
    q = LEAD / (2048 * 2 ** 11)
    _, inp = d.telegrams()
    x1 = inp.G1_XIST1
    assert x1 == math.floor(-5.0 / q) % 2 ** 32 == 2 ** 32 - 2097152
    a1 = d.axis.ActualPosition
    mr = d.add(MC_MoveRelative(Execute=True, Distance=12.5, Velocity=200.0))
    d.until(lambda: mr.Done, 1000)
    _, inp = d.telegrams()
    x2 = inp.G1_XIST1
    assert x2 == math.floor(d.axis.drive.mechanical_position() / q) % 2 ** 32
    assert ((x2 - x1) % 2 ** 32) * q == pytest.approx(d.axis.ActualPosition - a1, abs=1e-9)
    assert d.axis.ActualPosition - a1 == pytest.approx(12.5, abs=1.0)      # positioning window 1.0 mm


def test_s7_1200_5_4_3_3_fine_resolution_changes_the_count():
    """§5.4.3.3: the count per revolution is StepsPerRevolution x 2^FineResolutionXist1 -- 1000 steps without
    fine resolution: one count = 0.01 mm."""
    d = Drive(drive_params(telegram=3, **{"Sensor[1].Parameter.StepsPerRevolution": 1000,
                                         "Sensor[1].Parameter.FineResolutionXist1": 0}))
    mr = d.add(MC_MoveRelative(Execute=True, Distance=7.0, Velocity=100.0))
    d.until(lambda: mr.Done, 1000)
    _, inp = d.telegrams()
    assert inp.G1_XIST1 == math.floor(d.axis.drive.mechanical_position() / 0.01)
    assert inp.G1_XIST1 * 0.01 == pytest.approx(d.axis.ActualPosition, abs=1e-9)
    assert inp.G1_XIST1 == pytest.approx(700, abs=100)                     # positioning window 1.0 mm


# ==========================================================================================================
# telegram layout
def test_s7_1200_2_2_3_telegram_3_pack_unpack():
    """§2.2.3 telegram 3 (32-bit NSET, 32-bit NACT, 1 encoder, sign of life): the PROFIdrive standard layout
    out = STW1, NSOLL_B, STW2, G1_STW (5 words), in = ZSW1, NIST_B, ZSW2, G1_ZSW, G1_XIST1, G1_XIST2
    (9 words), big-endian; unpack(pack()) gives the same telegram."""
    d = Drive(drive_params(telegram=3))
    d.run_velocity(-250.0)
    out, inp = d.telegrams()
    raw_out, raw_in = out.pack(), inp.pack()
    assert len(raw_out) == 10 and len(raw_in) == 18
    assert raw_out[0:2] == b"\x04\x7f"
    assert int.from_bytes(raw_out[2:6], "big", signed=True) == out.NSOLL_B == round(rpm(-250.0) / REF * 2 ** 30)
    assert int.from_bytes(raw_in[0:2], "big") == int(inp.ZSW1)
    assert int.from_bytes(raw_in[10:14], "big") == inp.G1_XIST1
    assert type(out).unpack(raw_out) == out and type(inp).unpack(raw_in) == inp
    assert [name for name, *_ in type(out).fields()] == ["STW1", "NSOLL_B", "STW2", "G1_STW"]
    assert [name for name, *_ in type(inp).fields()] == ["ZSW1", "NIST_B", "ZSW2", "G1_ZSW", "G1_XIST1",
                                                         "G1_XIST2"]


def test_s7_1200_2_2_3_telegram_1_pack_unpack():
    """§2.2.3 telegram 1 (16-bit NSET, 16-bit NACT): out = STW1, NSOLL_A; in = ZSW1, NIST_A (2 words each)."""
    d = Drive(drive_params(telegram=1))
    d.run_velocity(300.0)
    out, inp = d.telegrams()
    raw_out, raw_in = out.pack(), inp.pack()
    assert len(raw_out) == 4 and len(raw_in) == 4
    assert raw_out == bytes([0x04, 0x7F]) + round(rpm(300.0) / REF * 0x4000).to_bytes(2, "big", signed=True)
    assert type(out).unpack(raw_out) == out and type(inp).unpack(raw_in) == inp
    assert [name for name, *_ in type(out).fields()] == ["STW1", "NSOLL_A"]


def test_s7_1200_2_2_3_telegram_3_sign_of_life_counts_every_cycle():
    """§2.2.3: telegram 3 carries a sign of life (§12.8 16#800C/16#003F if it fails): the controller's life
    sign in STW2 bits 12-15 advances by one every cycle, 1..15 (0 is skipped)."""
    d = Drive(drive_params(telegram=3))
    signs = []
    d.ctl.on_post_servo(lambda t: signs.append(d.telegrams()[0].STW2.master_sign_of_life))
    for _ in range(10):
        d.scan()
    assert all(1 <= s <= 15 for s in signs)
    assert all(b == (a % 15) + 1 for a, b in zip(signs, signs[1:])), signs[:20]


# ==========================================================================================================
# configuration rules
@pytest.mark.parametrize("actor, max_speed, ok", [(1, 6000.0, True), (1, 6001.0, False), (1, 3000.0, True),
                                                  (0, 3510.0, True), (0, 3511.0, False), (0, 6000.0, False)])
def test_s7_1200_12_8_863F_max_speed_limited_by_reference_speed(actor, max_speed, ok):
    """§5.4.3.2: "The maximum speed can thus be twice the reference speed at maximum" (PROFIdrive), analog
    -117 % .. 117 %; §12.8 16#863F/16#0030 invalid Actor.DriveParameter.MaxSpeed (remedy: reference value
    MaxSpeed/2 resp. MaxSpeed/1.17)."""
    errors = config_errors(drive_params(actor, max_speed=max_speed, vmax=100.0))
    assert (errors == set()) if ok else ((0x863F, 0x0030) in errors)


@pytest.mark.parametrize("actor", [1, 0])
@pytest.mark.parametrize("lead, vmax, ok", [(10.0, 500.0, True), (10.0, 501.0, False), (5.0, 250.0, True),
                                            (5.0, 260.0, False)])
def test_s7_1200_12_8_8645_max_velocity_must_be_reachable(actor, lead, vmax, ok):
    """§12.8 16#8645/16#0001 "The maximum velocity cannot be reached with the configured drive and axis
    parameters": MaxSpeed 3000 1/min with LeadScrew mm per revolution reaches 3000/60 x LeadScrew mm/s."""
    errors = config_errors(drive_params(actor, max_speed=3000.0, vmax=vmax, Mechanics={"LeadScrew": lead}))
    assert (errors == set()) if ok else ((0x8645, 0x0001) in errors)


@pytest.mark.parametrize("value, ok", [(0, True), (1, True), (2, False)])
def test_s7_1200_v7_12_8_864B_behavior_gx_xist1(value, ok):
    """V7 §12.9 Sensor[1].Parameter.BehaviorGx_XIST1 0..1; V7 §12.8 16#864B/16#0001 invalid value."""
    errors = config_errors(drive_params(1, **{"Sensor[1].Parameter.BehaviorGx_XIST1": value}))
    assert (errors == set()) if ok else ((0x864B, 0x0001) in errors)


# ==========================================================================================================
# Simulation.Mode
def sim_params(actor: int = 1, **extra) -> dict:
    p = drive_params(actor, max_speed=3000.0, vmax=400.0, Simulation={"Mode": 1},
                     **{"Plant.ReadyDelay": 0.5, "Actor.Interface.DriveReadyInput": "I0.0"})
    p.update(extra)
    return p


@pytest.mark.parametrize("actor", [1, 0])
def test_s7_1200_5_4_3_1_simulation_enables_immediately(actor):
    """§5.4.3.1: in simulation "MC_Power enables immediately without waiting for drive feedback" (here: a drive
    ready input that is FALSE and a drive that needs 0.5 s); StatusBits.AxisSimulation (§12.9.23)."""
    d = Drive(sim_params(actor), enable=False)
    d.power.Enable = True
    d.power()
    assert d.power.Status and d.axis.StatusBits.Enable
    assert d.axis.StatusBits.AxisSimulation


def test_s7_1200_12_9_23_axis_simulation_false_without_simulation():
    """§12.9.23 StatusBits.AxisSimulation is FALSE in normal operation (Simulation.Mode = 0)."""
    d = Drive(drive_params(1))
    assert not d.axis.StatusBits.AxisSimulation


def test_s7_1200_5_4_3_1_simulation_ideal_actual_values():
    """§5.4.3.1: in simulation no setpoints are output and no actual values are read -- the axis behaves
    ideally: ActualPosition equals Position in every servo cycle, the following error is 0."""
    d = Drive(sim_params(1))
    worst = []
    d.ctl.on_post_servo(lambda t: worst.append(abs(d.axis.ActualPosition - d.axis.Position)))
    mr = d.add(MC_MoveRelative(Execute=True, Distance=40.0, Velocity=300.0))
    d.until(lambda: mr.Done, 1000)
    assert d.axis.Position == pytest.approx(40.0) and d.axis.ActualPosition == pytest.approx(40.0)
    assert max(worst) < 1e-9
    assert d.axis.StatusPositioning.FollowingError == pytest.approx(0.0, abs=1e-9)


SIM_SWITCHES = {"Sensor[1].ActiveHoming.DigitalInputAddress": "I0.2",
                "PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I0.3", "MaxSwitchAddress": "I0.4",
                                      "MinSwitchLevel": True, "MaxSwitchLevel": True}}


def test_s7_1200_5_4_3_1_simulation_active_homing_completes_without_motion():
    """§5.4.3.1 table "Motion Control instructions with adapted behavior in simulation mode": MC_Home "Homing
    jobs are executed immediately without simulated axis motion" -- active homing (Mode 3) is Done at once
    with the axis at Position, it does not travel to look for the (ignored) homing switch."""
    d = Drive(sim_params(1, **SIM_SWITCHES))
    home = d.add(MC_Home(Execute=True, Mode=3, Position=100.0))
    for _ in range(5):
        d.scan()
        if home.Done or home.Error:
            break
    assert home.Done and d.axis.StatusBits.HomingDone, home.outputs
    assert d.axis.Position == pytest.approx(100.0) and d.axis.Velocity == 0.0


def test_s7_1200_5_4_3_1_simulation_hw_limit_switches_have_no_effect():
    """§5.4.3.1: "Hardware limit switches and homing switches have no effect" in simulation."""
    d = Drive(sim_params(1, **SIM_SWITCHES))
    d.ctl.inputs["I0.4"] = True                     # high HW limit switch "approached"
    mr = d.add(MC_MoveRelative(Execute=True, Distance=20.0, Velocity=200.0))
    d.until(lambda: mr.Done or mr.Error, 500)
    assert mr.Done and not d.axis.StatusBits.Error and d.axis.Position == pytest.approx(20.0)
    assert not d.axis.StatusBits.HWLimitMaxActive


def test_s7_1200_12_8_8647_simulation_not_supported_for_pto():
    """§5.4.3.1 simulation only for PROFIdrive/analog; §12.8 16#8647/16#0001 "Simulation is not supported for
    PTO axes"."""
    cfg = {"Actor": {"Type": 2}, "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0},
           "Simulation": {"Mode": 1}}
    assert (0x8647, 0x0001) in config_errors(cfg)
    cfg["Simulation"]["Mode"] = 0
    assert config_errors(cfg) == set()


def test_s7_1200_decision_50_simulation_mode_not_written_at_runtime():
    """§12.9.19 Simulation.Mode (PROFIdrive/analog: via the load memory and a restart); decision 50: MC_WriteParam
    refuses it with 16#8410/16#002B "Value at VARIANT 'Parameter' cannot be written"."""
    d = Drive(drive_params(1), enable=False)
    wp = MC_WriteParam(Parameter=d.axis.ref("Simulation.Mode"), Value=DInt(1), Execute=True)
    wp()
    assert wp.Error and (wp.ErrorID, wp.ErrorInfo) == (0x8410, 0x002B)
    assert not d.axis.StatusBits.AxisSimulation


def test_s7_1200_12_8_8000_drive_ready_lost_removes_enable_output():
    """§5.4.3.2 enable output / ready input; §12.8 16#8000 "Drive error, loss of 'Drive ready'" (ErrorBits.
    DriveFault), decision 38: the enable is removed -- the "Drive enabled" output drops; after the ready
    signal returns MC_Reset re-enables the axis (Enable stayed TRUE, §11.1.1)."""
    cfg = drive_params(0, max_speed=3510.0, vmax=500.0,
                       Actor={"Type": 0, "DriveParameter": {"ReferenceSpeed": REF, "MaxSpeed": 3510.0},
                              "Interface": {"EnableDriveOutput": "Q0.1", "DriveReadyInput": "I0.0"}})
    d = Drive(cfg)
    assert d.ctl.outputs["Q0.1"] and d.ctl.inputs["I0.0"]
    d.ctl.inputs.force("I0.0", False)              # the drive's "ready" wire drops
    d.until(lambda: d.power.Error, 100, "16#8000")
    assert (d.power.ErrorID, d.power.ErrorInfo) == (0x8000, 0x0001) and d.axis.ErrorBits.DriveFault
    assert not d.power.Status and not d.ctl.outputs["Q0.1"]
    d.ctl.inputs.force("I0.0", None)
    d.add(MC_Reset(Execute=True))
    d.until(lambda: d.power.Status, 100, "re-enabled")
    assert d.ctl.outputs["Q0.1"] and not d.power.Error
