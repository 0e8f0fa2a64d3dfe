"""S7-Technology V4.1: the family, an axis technology object from its tags, MC_Power and MC_MoveAbsolute.

Manual: S7-Technology V4.1 (CPU 31xT), §2.5.3 (technology DBs addressed by number), §3.1, §6.2.1, §6.2.6.
"""
from __future__ import annotations

import pytest

from plcmotion import ConfigurationError, Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_Power, device

from _s7t_rig import VIRTUAL, controller, enabled


def test_s7t_family_is_registered():
    """S7-Technology V4.1 §2.5.3: a controller of the family has the integrated technology with the MCDevice
    DB; positioning axes get technology DBs with their own numbers."""
    ctl = Controller(family="S7-Technology")
    ext = device(ctl)
    a = ctl.add_positioning_axis("A", VIRTUAL)
    b = ctl.add_positioning_axis("B", {**VIRTUAL, "DBNumber": 120})
    assert ext.db(a.db_number) is a.db and ext.db(120) is b.db
    assert ext.db(ext.mcdevice.number) is ext.mcdevice
    assert a.db_number not in (120, ext.mcdevice.number)


def test_s7t_duplicate_db_number_is_a_configuration_error():
    """S7-Technology V4.1 §2.5.3: a technology DB number names one object; a second one is refused with the
    tag named."""
    ctl = Controller(family="S7-Technology")
    ctl.add_positioning_axis("A", {**VIRTUAL, "DBNumber": 7})
    with pytest.raises(ConfigurationError, match="DBNumber"):
        ctl.add_positioning_axis("B", {**VIRTUAL, "DBNumber": 7})


def test_s7t_axis_tags_become_the_configuration():
    """S7-Technology V4.1 §9.4: expert-list tags (modulo, maximum velocity, default dynamics) configure the
    axis; a value outside the list's range names the tag."""
    ctl = Controller(family="S7-Technology")
    axis = ctl.add_positioning_axis("A", {**VIRTUAL, "Modulo": {"state": 1, "length": 720.0},
                                          "TypeOfAxis.MaxVelocity.maximum": 500.0,
                                          "userdefaultdynamics": {"velocity": 20.0}})
    c = axis.config
    assert c.modulo.enabled and c.modulo.length == 720.0
    assert c.limits.max_velocity == 500.0
    assert axis.eff["userdefaultdynamics.velocity"] == 20.0
    with pytest.raises(ConfigurationError, match="override.velocity"):
        ctl.add_positioning_axis("B", {**VIRTUAL, "override.velocity": 250.0})


def test_s7t_power_enables_by_db_number():
    """S7-Technology V4.1 §6.2.1: MC_Power with the technology DB number at Axis enables the axis: Status
    TRUE, Busy TRUE while Enable; Statusword.DriveEnabled in the technology DB."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", {**VIRTUAL, "DBNumber": 5})
    power = MC_Power()

    @ctl.program
    def ob1():
        power(Axis=5, Enable=True)
    ctl.run(0.05)
    assert power.Status and power.Busy and not power.Error
    assert axis.db.Statusword.DriveEnabled


def test_s7t_move_absolute_reaches_its_target():
    """S7-Technology V4.1 §6.2.6: MC_MoveAbsolute moves to Position; Done when the target is reached,
    Busy until then; ActualPosition of the technology DB shows the target after the next update."""
    ctl, axis, _power = enabled()
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=100.0, Velocity=50.0, Acceleration=100.0, Deceleration=100.0,
         Jerk=0.0)
    assert move.Busy and not move.Done
    # trapezoid: 0.5 s acceleration (12.5), 1.5 s at 50 (75), 0.5 s deceleration (12.5): 2.5 s in all
    t0 = ctl.time
    t = ctl.run_until(lambda: move(Execute=True).Done, 10.0)
    assert t - t0 == pytest.approx(2.5, abs=0.02)
    assert not move.Busy
    ctl.run(0.01)
    assert axis.db.ActualPosition == pytest.approx(100.0, abs=1e-6)
