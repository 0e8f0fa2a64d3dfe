"""Homing in the CiA 402 drive (homing mode 6, run by the master with ``axis.drive.home_in_drive``) marks the
axis homed in its family's technology object, without an MC_Home of its own: S7-1200 StatusBits.HomingDone
(S7-1200 Motion Control V6 §12.9, §2.5), S7-1500 StatusWord.HomingDone (S7-1500T V5 §A.1.37 bit 5) and
Pilz "In reference" I86 (Pilz V6.5 §1.7.7).  The simulated drive searches the switches and index pulses of
the axis's simulated machine (``Plant.*``): CiA 402-2 homing methods 8 (cam, index pulse right of its
lower edge), 24 (the same edge without index pulse), 34 (index pulse, positive direction), 35 (here)."""
from __future__ import annotations

import pytest

pytest.importorskip("canopen")
pytest.importorskip("can")

from plcmotion import Controller  # noqa: E402
from plcmotion.drives.cia402 import Cia402Link  # noqa: E402
from plcmotion.s7_1200 import MC_MoveAbsolute  # noqa: E402

from _cia402_rig import Rig, channel  # noqa: E402

MM_PER_INC = 10.0 / (2048 << 11)      # LeadScrew 10 mm per revolution, 2048 steps x 2^11 fine resolution
CAM = {"Sensor[1].ActiveHoming.DigitalInputAddress": "I0.2", "Plant.HomingSwitchPosition": 30.0,
       "Plant.HomingSwitchLength": 10.0, "Plant.ZeroMarkOffset": 3.0}


@pytest.fixture
def rig():
    made: list[Rig] = []

    def make(**kw) -> Rig:
        made.append(Rig("csp", enable=False, extra=CAM, **kw))
        return made[-1]
    yield make
    for r in made:
        r.close()


def _machine(r: Rig) -> float:
    """Where the simulated load is [mm] (the plant's truth, not the drive's reading)."""
    return r.sim.core.x * MM_PER_INC


@pytest.mark.parametrize("method,home", [(8, 33.0), (24, 30.0)])
def test_drives_cia402_home_in_drive_marks_s7_1200_axis_homed(rig, method, home):
    """CiA 402-2 method 8: the cam from 30 to 40 mm is met moving positive; home is the first index pulse
    (one per motor revolution, at 3 + k x 10 mm) right of its lower edge: 33 mm; method 24: the edge itself,
    30 mm.  When the drive reports homing attained, the S7-1200 axis is homed (StatusBits.HomingDone) with
    the home offset 0x607C (5 mm) at the home position - no MC_Home needed: MC_MoveAbsolute, which a not
    homed axis refuses (S7-1200 V6 §11.1.5), goes to 5 mm = the home position."""
    r = rig()
    r.steps(3)
    assert not r.axis.StatusBits.HomingDone
    r.drive.home_in_drive(method, offset=5.0, switch_speed=50.0, zero_speed=5.0, acceleration=500.0)
    r.until(lambda: r.drive.homing != "running", 3.0, "homing in the drive")
    assert r.drive.homing == "attained"
    assert r.axis.StatusBits.HomingDone
    assert r.axis.ActualPosition - _machine(r) == pytest.approx(5.0 - home, abs=2 * MM_PER_INC)
    r.power.Enable = True
    r.until(lambda: r.power.Status, 0.2, "enabled")
    mv = r.start(MC_MoveAbsolute(), Position=5.0, Velocity=20.0)
    r.until(lambda: mv.Done or mv.Error, 3.0, "MC_MoveAbsolute")
    assert mv.Done and not mv.Error, hex(mv.ErrorID)
    assert _machine(r) == pytest.approx(home, abs=0.05)


def test_drives_cia402_home_in_drive_error_leaves_axis_not_homed(rig):
    """CiA 402-2: a method the drive does not offer (15 is reserved) ends with homing error (statusword bit
    13); the axis stays not homed (S7-1200 StatusBits.HomingDone FALSE) and the drive is switched off again."""
    r = rig()
    r.steps(3)
    r.drive.home_in_drive(15)
    r.until(lambda: r.drive.homing != "running", 0.5, "homing in the drive")
    assert r.drive.homing == "error" and not r.axis.StatusBits.HomingDone
    r.steps(5)
    assert r.drive.controlword == 0x06


def test_drives_cia402_home_in_drive_marks_s7_1500_axis_homed():
    """Family-neutral: on an S7-1500 axis the drive's homing (method 35: here is home, home offset 12 mm)
    sets StatusWord bit 5 HomingDone (S7-1500T V5 §A.1.37) and the actual position reads 12 mm."""
    ctl = Controller(family="S7-1500")
    ctl.connect_drive("Axis_1", Cia402Link(channel=channel(), node_id=9, simulate=True))
    ax = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1})
    try:
        for _ in range(3):
            ctl.step()
        assert not ax.StatusWord.HomingDone
        ax.drive.home_in_drive(35, offset=12.0)
        for _ in range(20):
            ctl.step()
        assert ax.drive.homing == "attained"
        assert ax.StatusWord.HomingDone and ax.ActualPosition == pytest.approx(12.0, abs=1e-5)
    finally:
        ctl.close()


def test_drives_cia402_home_in_drive_marks_pilz_axis_in_reference():
    """Family-neutral: a Pilz drive axis is "In reference" (I86, Pilz V6.5 §1.7.7) after the drive's homing
    method 34 (first index pulse in the positive direction: zero marks every 10 mm from 4 mm, start at
    12.5 mm, so 14 mm), and its actual position reads the home offset 100 mm there."""
    ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
    ctl.connect_drive("Conveyor", Cia402Link(channel=channel(), node_id=2, simulate=True))
    ax = ctl.add_positioning_axis("Conveyor", {"Plant.ZeroMarkDistance": 10.0, "Plant.ZeroMarkOffset": 4.0,
                                               "Plant.InitialPosition": 12.5})
    try:
        ctl.step()
        assert not ax.status.I86
        ax.drive.home_in_drive(34, offset=100.0, zero_speed=20.0, acceleration=1000.0)
        ctl.run_until(lambda: ax.drive.homing != "running", timeout=2.0)
        ctl.step()
        assert ax.drive.homing == "attained" and ax.status.I86
        machine = ax.drive.simulated.core.x * ax.drive.q
        assert ctl.bank.act_p[ax.index] - machine == pytest.approx(100.0 - 14.0, abs=1e-5)
    finally:
        ctl.close()


def test_drives_cia402_home_in_drive_without_answer(rig):
    """A drive that does not answer the SDO set-up of the homing run: no exception in the program, no run
    (``homing`` = "error", the object named in ``homing_error``) and a station failure 16#800C/16#003E
    (S7-1200 V6 §12.8) once the axis is enabled."""
    r = rig()
    r.steps(3)
    r.sim.silence(True)
    r.drive.home_in_drive(35)
    assert r.drive.homing == "error" and r.drive.homing_error.startswith("0x6098 homing method")
    assert not r.axis.StatusBits.HomingDone
    r.power.Enable = True
    r.steps(5)
    assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003E)
