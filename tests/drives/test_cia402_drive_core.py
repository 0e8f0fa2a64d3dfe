"""The simulated drive's inside (``drives.cia402.drive_core.DriveCore``) without a bus: invariants of the
profile modes and the speed limit (CiA 402-2: max motor speed 0x6080, profile position mode with profile
velocity 0x6081 and the target reached bit 10, profile velocity mode)."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.drives.cia402.drive_core import DriveCore, MotorSpec
from plcmotion.drives.cia402.profile import State

INC = 10_000                               # increments per motor revolution
PARAMS = {(0x607E, 0): 0, (0x608F, 1): INC, (0x608F, 2): 1, (0x6080, 0): 600,    # 600 1/min = 100000 inc/s
          (0x6081, 0): 50_000, (0x6083, 0): 500_000, (0x6084, 0): 500_000, (0x6085, 0): 2_000_000,
          (0x6072, 0): 3000, (0x6065, 0): 0xFFFFFFFF, (0x6098, 0): 35, (0x607C, 0): 0,
          (0x6099, 1): 1000, (0x6099, 2): 100, (0x609A, 0): 10_000}
VMAX = 600 * INC / 60


def _enabled(mode: int) -> DriveCore:
    core = DriveCore(lambda i, s=0: PARAMS[(i, s)], MotorSpec(speed_time_constant=0.002))
    for cw in (0x06, 0x07, 0x0F):
        core.apply(cw, mode, 0, 0, 0)
    assert core.sm.state is State.OPERATION_ENABLED
    return core


@settings(max_examples=40)
@given(st.lists(st.integers(-400_000, 400_000), min_size=1, max_size=6))
def test_drives_cia402_core_speed_limit(targets):
    """CiA 402-2 0x6080: whatever target velocities a master sends in csv, the motor never turns faster than
    the max motor speed (here 600 1/min = 100000 inc/s)."""
    core = _enabled(9)
    for v in targets:
        core.apply(0x0F, 9, 0, v, 0)
        for _ in range(50):
            core.step(0.001)
            assert abs(core.velocity_actual()) <= VMAX + 1


@settings(max_examples=30)
@given(st.integers(-60_000, 60_000))
def test_drives_cia402_core_profile_position_arrives(target):
    """CiA 402-2 profile position: after a new set point (bit 4) the drive moves to the target with at most
    the profile velocity 0x6081 and then shows target reached (statusword bit 10) within the position
    window, standing still."""
    core = _enabled(1)
    core.apply(0x1F, 1, target, 0, 0)
    core.apply(0x0F, 1, target, 0, 0)
    for _ in range(3000):
        core.step(0.001)
        assert abs(core.gv) <= PARAMS[(0x6081, 0)] + 1e-6
        if core.statusword() & 0x0400 and abs(core.v) < 1.0:
            break
    assert core.statusword() & 0x0400
    assert abs(core.position_actual() - target) <= MotorSpec().position_window


def test_drives_cia402_core_quick_stop_ramp():
    """CiA 402-2 quick stop (transition 11, option code 2 of 0x605A): the drive stops with the quick stop
    deceleration 0x6085 (here 2e6 inc/s^2: 50000 inc/s in 25 ms) and is then SWITCH ON DISABLED (12)."""
    core = _enabled(9)
    core.apply(0x0F, 9, 0, 50_000, 0)
    for _ in range(200):
        core.step(0.001)
    core.apply(0x02, 9, 0, 50_000, 0)
    assert core.sm.state is State.QUICK_STOP_ACTIVE
    steps = 0
    while core.sm.state is State.QUICK_STOP_ACTIVE:
        core.step(0.001)
        steps += 1
    assert core.sm.state is State.SWITCH_ON_DISABLED and core.v == 0.0
    assert 25 <= steps <= 27
