"""Cyclic commands and MC_TorqueControl of the Pilz motion core (Pilz V6.5 §1.8, §1.9.1, §1.10, §1.11)."""
from __future__ import annotations

import pytest

from plcmotion.pilz import Cause

from ._core import PROFILE, make_axis, start


def _feed(ctl, ax, **values):
    def controller():
        for k, v in values.items():
            ax.registers.write(k, v() if callable(v) else v)
    ctl.program(controller)
    return controller


def test_pilz_cyclic_speed_follows_and_limits():
    """Pilz V6.5 §1.8.3 / §1.8.5: MC_CyclicSpeed follows the cyclic set velocity I426 at once, limited to I10,
    override not applied; a direction forbidden by I04 gives set value 0 and I193."""
    ctl, ax = make_axis({"I10": 300.0})
    _feed(ctl, ax, I426=120.0)
    ax.registers.I230 = 50.0
    t0 = start(ax, 7, I426=120.0)
    ctl.run(0.01)
    assert ax.status.E07 == 120.0 and ax.status.I89 == 11
    ctl._programs.clear()
    _feed(ctl, ax, I426=900.0)
    ctl.run(0.01)
    assert ax.status.E07 == 300.0
    ctl._programs.clear()
    ax.write_tag("I04", 1)
    _feed(ctl, ax, I426=-50.0)
    ctl.run(0.01)
    assert ax.status.E07 == 0.0 and ax.status.I193 and not ax.status.I91
    assert t0 > 0


def test_pilz_cyclic_missing_set_values():
    """Pilz V6.5 §1.8.1: missing cyclic set values are extrapolated for at most I423, then event 78 cause 3
    cancels the command (I91 = 1, I90 = 24) with a quick stop."""
    ctl, ax = make_axis({"I423": 0.01})
    feed = _feed(ctl, ax, I426=50.0)
    start(ax, 7, I426=50.0)
    ctl.run(0.2)
    ctl._programs.remove(("controller", feed))
    ctl.run(0.005)
    assert not ax.status.I91 and ax.status.E07 == 50.0          # extrapolated
    ctl.run(0.02)
    assert ax.status.I91 and ax.status.I90 == Cause.CYCLIC_TIMEOUT and ax.status.I89 == 7
    ctl.run(0.1)
    assert ax.status.E07 == 0.0


def test_pilz_cyclic_position_interpolates_and_counts_turns():
    """Pilz V6.5 §1.11.1: MC_CyclicPosition follows I421, interpolated linearly over the controller cycle; on an
    endless axis the set position lies in 0 ... I01 and the turns are counted internally."""
    ctl, ax = make_axis({"I00": 1, "I01": 360.0, "I10": 10000.0}, app_cycle=0.004)
    angle = {"x": 0.0}

    def controller():
        angle["x"] = (angle["x"] + 4.0) % 360.0        # 1000 deg/s
        ax.registers.I421 = angle["x"]
    ctl.program(controller)
    start(ax, 10, I421=0.0)
    ctl.run(1.0)
    assert ax.status.E07 == pytest.approx(1000.0)
    assert ax.status.I96 > 900.0 and not ax.status.I91          # unwrapped: about 1000 degrees


def test_pilz_cyclic_position_outside_revolution():
    """Pilz V6.5 §1.11.1: a cyclic set position outside 0 ... I01 on an endless axis is event 78 cause 2
    (I90 = 23)."""
    ctl, ax = make_axis({"I00": 1, "I01": 360.0})
    _feed(ctl, ax, I421=400.0)
    start(ax, 10, I421=400.0)
    ctl.run(0.01)
    assert ax.status.I91 and ax.status.I90 == Cause.CYCLIC_POSITION_RANGE


def test_pilz_cyclic_torque_control():
    """Pilz V6.5 §1.10: the set torque accelerates the load (load model: torque / inertia), limited to E65
    (I194); the velocity never exceeds I10; direction = sign of the torque; I91 stays 0."""
    ctl, ax = make_axis({"Drive.Inertia": 0.01, "E65": 2.0, "E66": 2.0, "I10": 100.0})
    _feed(ctl, ax, I428=1.0)
    t0 = start(ax, 9, I428=1.0)
    ctl.run(0.1)
    # 1.0 / 0.01 = 100 unit/s^2: after ~0.1 s about 10 unit/s
    assert ax.status.E07 == pytest.approx(100.0 * (ctl.time - t0), abs=0.3)
    ctl._programs.clear()
    _feed(ctl, ax, I428=-5.0)
    ctl.run(0.01)
    assert ax.status.I194 and ax.status.E02 == -2.0
    ctl.run(3.0)
    assert ax.status.E07 == -100.0 and not ax.status.I91 and ax.status.I89 == 4


def test_pilz_cyclic_torque_ramp():
    """Pilz V6.5 §1.10.1: the set torque follows I428 with the ramps I430 (up) and I431 (down)."""
    ctl, ax = make_axis({"Drive.Inertia": 1.0})
    _feed(ctl, ax, I428=1.0, I430=10.0, I431=10.0)
    start(ax, 9, I428=1.0, I430=10.0, I431=10.0)
    ctl.run(0.05)
    assert ax.status.E02 == pytest.approx(0.5, abs=0.011)


def test_pilz_cyclic_move_speed_takeover():
    """Pilz V6.5 §1.9.1: MC_MoveSpeed takes changes of I426 cyclically (I119 = 0), with the cyclic ramps;
    without position control; I216 = 0 keeps the last acceleration (§1.9.2)."""
    ctl, ax = make_axis()
    speed = {"v": 100.0}
    _feed(ctl, ax, I426=lambda: speed["v"], I216=1000.0, I217=1000.0)
    start(ax, 8, I426=100.0, I216=1000.0, I217=1000.0, I407=1e5)
    ctl.run(0.3)
    assert ax.status.E07 == 100.0 and ax.status.I92 and ax.status.I89 == 4
    assert not ax.position_controlled
    speed["v"] = 150.0
    ctl.run(0.3)
    assert ax.status.E07 == 150.0
    ctl._programs.clear()
    _feed(ctl, ax, I426=0.0, I216=0.0, I217=0.0)
    ctl.run(0.02)
    assert ax.status.E07 == pytest.approx(150.0 - 1000.0 * 0.015, abs=1.0)   # the last deceleration stays


def test_pilz_cyclic_move_velocity_continuous_update():
    """Pilz V6.5 §1.5.1: with I424 = 1 MC_MoveVelocity takes a changed I404 while it runs; with 0 only at the
    start."""
    for mode, expected in ((1, 80.0), (0, 40.0)):
        ctl, ax = make_axis()
        start(ax, 4, PROFILE, I404=40.0, I424=mode)
        ctl.run(0.2)
        ax.registers.I404 = 80.0
        ctl.run(0.3)
        assert ax.status.E07 == expected


@pytest.mark.parametrize("plant_inertia,feed,friction", [(2.0e-3, 10.0, 0.0), (5.0e-4, 4.0, 0.0),
                                                         (2.0e-3, 10.0, 2.0e-3)])
def test_pilz_cyclic_torque_control_on_the_drive_models_inertia(plant_inertia, feed, friction):
    """Pilz V6.5 §1.10.5: the set torque E02 drives the load.  Without a load model of its own (Drive.Inertia
    unset) the load is the simulated drive's: J = Plant.Inertia [kg m²] at the motor shaft, 2 pi / feed rad
    per unit, so torque T gives the load acceleration a = (T - friction x v) / (J x 2 pi / feed); and the
    drive's speed loop then asks for that same torque (axis.drive.torque, on average over its setpoint steps)."""
    import math

    ctl, ax = make_axis({"Plant.Inertia": plant_inertia, "Drive.FeedPerRevolution": feed, "Drive.Friction": friction,
                         "E65": 10.0, "E66": 10.0})
    torque = 0.05
    _feed(ctl, ax, I428=torque)
    t0 = start(ax, 9, I428=torque)
    j = plant_inertia * 2.0 * math.pi / feed                      # torque per unit/s² of load acceleration
    ctl.run(0.2)
    t = ctl.time - t0
    # v' = (T - c v) / j  ->  v(t) = T / c (1 - exp(-c t / j)), or T t / j without friction
    expected = torque * t / j if friction == 0.0 else torque / friction * (1.0 - math.exp(-friction * t / j))
    assert ax.status.E02 == torque and not ax.status.I194
    assert ax.status.E07 == pytest.approx(expected, rel=0.02)
    if friction == 0.0:
        demand = []
        for _ in range(200):
            ctl.step()
            demand.append(ax.drive.torque)
        assert sum(demand) / len(demand) == pytest.approx(torque, rel=0.05)


def test_pilz_cyclic_torque_control_own_load_model_wins():
    """Pilz V6.5 §1.10.5: a load model of its own (Drive.Inertia) replaces the drive's inertia: 1.0 / 0.5 =
    2 unit/s² whatever Plant.Inertia says."""
    ctl, ax = make_axis({"Drive.Inertia": 0.5, "Plant.Inertia": 1.0})
    _feed(ctl, ax, I428=1.0)
    t0 = start(ax, 9, I428=1.0)
    ctl.run(0.5)
    assert ax.status.E07 == pytest.approx(2.0 * (ctl.time - t0), abs=0.01)


@pytest.mark.parametrize("torque", [2.0, -2.0])
def test_pilz_cyclic_torque_control_stays_inside_software_limits(torque):
    """Pilz V6.5 §1.10.3 with the project rule (docs/pilz/decisions.md, Commands): a torque that drives a referenced
    limited axis towards a software limit switch (I50 / I51) is cancelled with I90 = 21 and the quick stop ends
    inside the switches; never beyond them."""
    ctl, ax = make_axis({"Drive.Inertia": 0.01, "E65": 5.0, "E66": 5.0, "I10": 100.0, "I11": 1000.0,
                         "I50": 20.0, "I51": -20.0})
    _feed(ctl, ax, I428=torque)
    start(ax, 9, I428=torque)
    ctl.run(2.0)
    assert ax.status.I91 and ax.status.I90 == Cause.SW_LIMIT_REACHED
    assert ax.status.E07 == 0.0
    assert max(abs(r.I96) for r in ax.rows) <= 20.0 + 1e-9
    assert max(abs(r.p) for r in ax.rows) <= 20.0 + 1e-6
