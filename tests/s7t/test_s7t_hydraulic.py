"""Hydraulic axes (S7-Technology V4.1 §3.1.4, §4.6), MC_Power StopMode 3 / QOutputValue (§6.2.1) and
MC_SetCharacteristic (§6.2.13)."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.kernel.errors import ConfigurationError
from plcmotion.s7t import (MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_ReadSysParameter, MC_Reset,
                           MC_SetCharacteristic, MC_Stop, MC_WriteParameter, add_cam_disk)

from _s7t_rig import controller

HYD = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.DriveTechnology": 1, "Plant.InitialPosition": 100.0,
       "TypeOfAxis.MaxVelocity.maximum": 300.0, "Drive.ValveProfile1": 20}
FE = "TypeOfAxis.NumberOfDataSets.DataSet_1.DynamicFollowing"
#: a valve with a dead band of +-5 %: 300 mm/s at 100 %
PROFILE = [(-100.0, -300.0), (-5.0, 0.0), (5.0, 0.0), (100.0, 300.0)]


class Rig:
    def __init__(self, params=None, **power):
        self.ctl = controller()
        self.axis = self.ctl.add_positioning_axis("H", {**HYD, **(params or {})})
        self.cam = add_cam_disk(self.ctl, "Cam_1", PROFILE, db_number=20)
        self.power = MC_Power()
        self.inputs = dict(Enable=True, **power)
        self.ctl.program(lambda: self.power(Axis=self.axis, **self.inputs))
        self.ctl.run(0.2)

    def out(self) -> float:
        return self.axis.drive.output_percent


def test_s7t_hydraulic_axis_positions():
    """S7-Technology V4.1 §3.1.4: a hydraulic axis is positioned like an electric one (valve output, cylinder,
    encoder); MC_MoveRelative by 100 mm ends Done within the positioning window."""
    r = Rig()
    assert r.power.Status
    start = r.axis.drive.mechanical_position()
    move = MC_MoveRelative()
    move(Axis=r.axis, Execute=True, Distance=100.0, Velocity=100.0)
    for _ in range(100):
        r.ctl.run(0.1)
        move(Axis=r.axis, Execute=True)
        if move.Done:
            break
    assert move.Done
    assert r.axis.drive.mechanical_position() - start == pytest.approx(100.0, abs=1.0)


def test_s7t_hydraulic_off2_ramps_to_qoutputvalue():
    """S7-Technology V4.1 §6.2.1 StopMode 3 (OFF2Stop): the enable is removed, the output ramps at
    userdefaultqfaxis.maxderivative.qoutput (100 %/s) to QOutputValue; 16#8040 in the technology DB."""
    r = Rig(StopMode=3, QOutputValue=20.0)
    before = r.out()
    r.inputs["Enable"] = False
    r.ctl.run(0.1)
    assert not r.power.Status and r.axis.state == "disabled"
    assert r.out() == pytest.approx(before + 10.0, abs=0.5)
    r.ctl.run(0.3)
    assert r.out() == pytest.approx(20.0, abs=0.01)
    assert r.axis.db.ErrorID == 0x8040


def test_s7t_hydraulic_off2_ramp_parameter_5009():
    """S7-Technology V4.1 §6.2.1: the ramp is parameter 5009 (here 50 %/s): -10 % after 0.1 s is -5 %."""
    r = Rig({"userdefaultqfaxis.maxderivative.qoutput": 50.0}, StopMode=3, QOutputValue=-10.0)
    before = r.out()
    r.inputs["Enable"] = False
    r.ctl.run(0.1)
    assert r.out() == pytest.approx(before - 5.0, abs=0.3)


def _write(r: Rig, number: int, value: float) -> None:
    w = MC_WriteParameter()
    w(Axis=r.axis, Execute=True, ParameterNumber=number, Value=value)
    assert w.Done and not w.Error, w


def test_s7t_hydraulic_5009_written_at_run_time_reaches_the_valve():
    """S7-Technology V4.1 §9.4 parameter 5009 (effective immediately) and §6.7.5 MC_WriteParameter: 25 %/s
    written while the axis is enabled is the rate of the next OFF2 ramp: 0 -> 20 % after 0.2 s is 5 %, and
    after 0.8 s the output has reached 20 %.  MC_ReadSysParameter reads 25 back."""
    r = Rig(StopMode=3, QOutputValue=20.0)
    _write(r, 5009, 25.0)
    read = MC_ReadSysParameter()
    read(Axis=r.axis, Execute=True, ParameterNumber=5009)
    assert read.Done and read.Value == 25.0
    before = r.out()
    r.inputs["Enable"] = False
    r.ctl.run(0.2)
    assert r.out() == pytest.approx(before + 5.0, abs=0.3)
    r.ctl.run(0.8)
    assert r.out() == pytest.approx(20.0, abs=0.01)


def test_s7t_hydraulic_output_limit_written_at_run_time():
    """S7-Technology V4.1 §9.4 parameter 1402 (manipulated variable limit, upper; effective immediately): a
    hydraulic axis moving at 180 mm/s on the straight valve line (500 mm/s at 100 %) needs 36 % of 10 V;
    writing 20 cuts the output to 20 % at once, and it never exceeds it afterwards."""
    r = Rig()
    mv = MC_MoveVelocity()
    mv(Axis=r.axis, Execute=True, Velocity=180.0)
    r.ctl.run(3.0)
    assert r.out() > 30.0
    _write(r, 1402, 20.0)
    for _ in range(50):
        r.ctl.run(r.ctl.app_cycle)
        assert r.out() <= 20.0 + 1 / 276.48       # within one count of the analog word (27648 = 100 %)


def test_s7t_hydraulic_qoutputvalue_invalid_at_falling_edge_808b():
    """S7-Technology V4.1 §6.2.1 QOutputValue: an invalid value at the falling edge of Enable gives 16#808B for
    one call and the value taken at the rising edge (10 %) is used."""
    r = Rig(StopMode=3, QOutputValue=10.0)
    r.inputs.update(Enable=False, QOutputValue=150.0)
    r.ctl.run(0.004)
    assert r.power.Error and r.power.ErrorID == 0x808B
    r.ctl.run(0.004)
    assert not r.power.Error
    r.ctl.run(0.3)
    assert r.out() == pytest.approx(10.0, abs=0.01)


def test_s7t_hydraulic_other_stop_modes_close_the_valve():
    """S7-Technology V4.1 §6.2.1: QOutputValue applies with StopMode 3 only; after StopMode 0 the output goes
    to 0 % (no motion after disabling)."""
    r = Rig(StopMode=0, QOutputValue=30.0)
    r.inputs["Enable"] = False
    r.ctl.run(0.5)
    assert r.out() == pytest.approx(0.0, abs=0.01)


def test_s7t_hydraulic_error_after_off2_closes_the_valve():
    """S7-Technology V4.1 §6.2.1 QOutputValue: the substitute value is used when MC_Power disables with
    StopMode 3; enabled again, an error that removes the enable (a drive fault) ramps the output to 0 %."""
    r = Rig(StopMode=3, QOutputValue=20.0)
    r.inputs["Enable"] = False
    r.ctl.run(0.4)
    assert r.out() == pytest.approx(20.0, abs=0.01)
    r.inputs["Enable"] = True
    r.ctl.run(0.3)
    assert r.power.Status
    r.axis.inject_fault("drive")
    r.ctl.run(0.4)
    assert r.axis.state == "disabled"
    assert r.out() == pytest.approx(0.0, abs=0.01)


def test_s7t_hydraulic_characteristic_with_dead_band():
    """S7-Technology V4.1 §4.6.4, §6.2.13: MC_SetCharacteristic activates the valve profile of cam disk DB20
    (dead band +-5 %): at 30 mm/s the output is 5 + 95 * 30/300 = 14.5 % instead of the straight line's
    30/500 = 6 %; the changeover is compensated at 100 %/s."""
    r = Rig()
    vel = MC_MoveVelocity()
    vel(Axis=r.axis, Execute=True, Velocity=30.0, PositionControl=False)   # the output is the characteristic
    r.ctl.run(1.0)
    assert r.out() == pytest.approx(6.0, abs=0.3)
    fb = MC_SetCharacteristic()
    fb(Axis=r.axis, CamTable=20, Execute=True)
    assert fb.Done and not fb.Error
    r.ctl.run(0.02)
    assert r.out() < 6.0 + 100.0 * 0.02 + 0.3           # no jump: the compensation ramps
    r.ctl.run(0.5)
    assert r.out() == pytest.approx(14.5, abs=0.3)
    assert r.axis.drive.mechanical_position() > 100.0


def test_s7t_hydraulic_set_characteristic_error_ids():
    """S7-Technology V4.1 §6.2.13 "MC_SetCharacteristic - ErrorIDs"."""
    r = Rig()
    other = add_cam_disk(r.ctl, "Cam_2", PROFILE, db_number=21)          # not a valve profile of the axis
    electric = r.ctl.add_positioning_axis("E", {"TypeOfAxis.Homing.referencingNecessary": 0})
    cases = [
        (dict(Axis=electric, CamTable=20), 0x804D),
        (dict(CamTable=r.axis.db_number), 0x8044),
        (dict(CamTable=999), 0x8044),
        (dict(Axis=20, CamTable=20), 0x8044),
        (dict(CamTable=other.db_number), 0x804A),
        (dict(CamTable=20, Mode=1), 0x8043),
        (dict(CamTable=20, DoneFlag=-1), 0x8043),
        (dict(Axis=999, CamTable=20), 0x8083),
    ]
    for inputs, code in cases:
        fb = MC_SetCharacteristic()
        fb(**{"Axis": r.axis, "Execute": True, **inputs})
        assert fb.Error and fb.ErrorID == code, (inputs, fb)
        assert "CommandAborted" not in fb.outputs


def test_s7t_hydraulic_set_characteristic_during_stop_and_restart():
    """S7-Technology V4.1 §6.8.3 (MC_SetCharacteristic row: MC_Stop no influence, a running restart refuses,
    16#8045 as for every command during a restart, §6.7.1; decisions D28/D31), §6.2.13: during a held MC_Stop
    the profile is activated (Done, MC_Stop stays Busy); while MC_Reset Restart runs, 16#8045."""
    r = Rig()
    stop, fb = MC_Stop(), MC_SetCharacteristic()
    stop(Axis=r.axis, Execute=True)
    r.ctl.run(0.1)
    fb(Axis=r.axis, CamTable=20, Execute=True)
    stop(Axis=r.axis, Execute=True)
    assert fb.Done and not fb.Error
    assert stop.Busy and not stop.CommandAborted
    r.inputs["Enable"] = False
    stop(Axis=r.axis, Execute=False)
    r.ctl.run(0.5)
    assert r.axis.state == "disabled"
    reset, during = MC_Reset(), MC_SetCharacteristic()
    reset(Axis=r.axis, Execute=True, Restart=True)
    assert reset.Busy
    during(Axis=r.axis, CamTable=20, Execute=True)
    assert during.Error and during.ErrorID == 0x8045


@pytest.mark.parametrize("params, tag", [
    ({"Wizard.Virtual": 1}, "Wizard.DriveTechnology"),
    ({"Drive.ForceLimit": 1000.0}, "Drive.ForceLimit"),               # a Q valve limits no force
    ({"TypeOfAxis.SpeedLimitation.MinSpeed": 50.0, "TypeOfAxis.SpeedLimitation.MaxSpeed": 40.0},
     "TypeOfAxis.SpeedLimitation.MinSpeed"),
    ({"Plant.InitialPosition": 900.0}, "Plant.InitialPosition"),
])
def test_s7t_hydraulic_configuration_errors(params, tag):
    """S7-Technology V4.1 §3.1.4, §4.6: a hydraulic axis is real; output limits ordered; the force limit is
    a P/Q valve's; the piston starts inside its cylinder."""
    ctl = controller()
    with pytest.raises(ConfigurationError) as exc:
        ctl.add_positioning_axis("H", {**HYD, **params})
    assert tag in str(exc.value)


def test_s7t_hydraulic_pq_valve_limits_the_force():
    """S7-Technology V4.1 §4.6 (P/Q valve, pressure limiting): pressing against a fixed end stop the cylinder
    force stays at Drive.ForceLimit (5 kN) although the supply could give p_S A_A = 20 kN."""
    r = Rig({"Wizard.DriveTechnology": 2, "Drive.ForceLimit": 5000.0, "Plant.EndStopMaxPosition": 150.0,
             f"{FE}.enable": 0})
    vel = MC_MoveVelocity()
    vel(Axis=r.axis, Execute=True, Velocity=100.0, PositionControl=False)
    r.ctl.run(4.0)
    assert r.axis.drive.mechanical_position() == pytest.approx(150.0)
    assert r.axis.drive.force == pytest.approx(5000.0, rel=1e-6)
    assert r.axis.drive.torque_limit_active


@settings(max_examples=12, deadline=None)
@given(q=st.floats(-100.0, 100.0), ramp=st.floats(20.0, 400.0))
def test_s7t_hydraulic_off2_output_property(q, ramp):
    """S7-Technology V4.1 §6.2.1 StopMode 3: after disabling, the output never changes faster than parameter
    5009 allows and ends at QOutputValue (to the 1/27648 resolution of the analog output)."""
    r = Rig({"userdefaultqfaxis.maxderivative.qoutput": ramp}, StopMode=3, QOutputValue=q)
    outs = []
    r.ctl.on_post_servo(lambda t: outs.append(r.out()))
    r.inputs["Enable"] = False
    r.ctl.run(200.0 / ramp + 0.05)
    steps = [abs(b - a) for a, b in zip(outs, outs[1:])]
    assert max(steps) <= ramp * r.ctl.servo_cycle + 2.0 / 276.48
    assert r.out() == pytest.approx(q, abs=0.5 / 276.48 + 1e-9)
