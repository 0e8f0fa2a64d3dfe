"""Position control runs for every drive group whose axes the controller closes the loop over
(``DriveGroup.closed_loop``): speed servos and hydraulic valves, not steppers or ideal drives.

S7-1200 V6 §5.4.4.7 / S7-Technology V4.1 §3.3.1: the position controller's command is speed precontrol
plus Kv times the following error; a controller with hydraulic axes only must compute it as well.
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.drives import ActuatorKind
from plcmotion.kernel import servo_cycle
from plcmotion.kernel.bank import AxisBank


@pytest.mark.parametrize("kind, closed", [(ActuatorKind.SPEED_SERVO, True), (ActuatorKind.HYDRAULIC, True),
                                          (ActuatorKind.PULSE, False), (ActuatorKind.IDEAL, False)])
def test_kernel_controller_knows_whether_a_drive_group_is_closed_loop(kind, closed):
    """S7-Technology V4.1 §3.3.1: a hydraulic group is position controlled like a servo group."""
    ctl = Controller()
    assert not ctl._closed_loop
    ctl._drive_group(SimpleNamespace(group_key=kind.value, link=None))    # a drive spec of that kind
    assert ctl._closed_loop is closed


@pytest.mark.parametrize("closed", [True, False])
def test_kernel_control_stage_runs_only_with_a_closed_loop_group(closed):
    """S7-1200 V6 §5.4.4.7: command = Kpc * setpoint velocity + Kv * following error on closed-loop axes."""
    bank = AxisBank()
    i = bank.add()
    bank.closed_loop[i] = True
    bank.kv[i], bank.kpc[i] = 10.0, 1.0
    bank.sp_p[i], bank.act_p[i], bank.sp_v[i] = 5.0, 4.5, 20.0
    servo_cycle.control(SimpleNamespace(_closed_loop=closed, bank=bank), 0.0)
    assert float(bank.cmd_v[i]) == (1.0 * 20.0 + 10.0 * 0.5 if closed else 0.0)


def test_kernel_loop_mask_counts_follow_enable_and_disable():
    """S7-1200 V6 §5.4.4.7, §11.1.1: an enabled, position-controlled servo axis is in the position loop; a
    disabled one has its setpoint follow the actual value.  The bank counts both masks for the servo cycle,
    and a partly closed loop still gives the enabled axis Kpc * v + Kv * e and the disabled one its
    setpoint velocity."""
    from plcmotion.s7_1200 import MC_Power

    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    servo = {"Actor": {"Type": 1, "DriveParameter": {"MaxSpeed": 3000.0, "ReferenceSpeed": 3000.0}}}
    a = ctl.add_positioning_axis("A", servo)
    b = ctl.add_positioning_axis("B", servo)
    bank = ctl.bank
    assert (bank.n_closed, bank.n_follow) == (0, 2)           # both disabled: setpoints follow
    power = MC_Power()
    for _ in range(100):
        power(Axis=a, Enable=True)
        ctl.step()
    assert power.Status
    assert list(bank.closed_loop) == [True, False] and list(bank.follow_act) == [False, True]
    assert (bank.n_closed, bank.n_follow) == (1, 1)
    assert float(bank.cmd_v[b.index]) == float(bank.sp_v[b.index])    # outside the loop: setpoint velocity
    for _ in range(100):
        power(Axis=a, Enable=False)
        ctl.step()
    assert not power.Status
    assert (bank.n_closed, bank.n_follow) == (0, 2)
    assert not bank.closed_loop.any() and bank.follow_act.all()
