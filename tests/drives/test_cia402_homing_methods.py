"""The homing methods of the simulated CiA 402 drive (homing mode 6), each against its definition in
CiA 402-2 (homing methods 1-14 with the index pulse, 17-30 without, 33/34, 35/37; statusword bits 10, 12,
13 in homing mode; objects 0x6098 method, 0x607C home offset, 0x6099:1/2 speeds, 0x609A acceleration).

The machine below: negative limit switch active at and below -100000 inc, positive limit switch at and above
+100000 inc, index pulses every 10000 inc at 1234 + k * 10000, and a home switch that is, per method, a
positive home switch (active from 25500 upwards), a negative one (active up to 25500) or a cam active from
20500 to 40700.  The expected home positions are written out from the method definitions: the switch edge
(17-30), or the first index pulse beyond that edge on the method's side (1-14)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.drives.cia402.drive_core import DriveCore, MotorSpec
from plcmotion.drives.cia402.homing import SwitchPlant
from plcmotion.drives.cia402.profile import State

OFFSET = 777                                   # home offset 0x607C [inc]
FAST, SLOW, ACC = 200_000, 20_000, 4_000_000   # 0x6099:1, 0x6099:2 [inc/s], 0x609A [inc/s^2]
LIMITS = dict(negative_limit=-100_000.0, positive_limit=100_000.0, index_pitch=10_000.0, index_offset=1234.0)
POSITIVE_SWITCH = SwitchPlant(**LIMITS, home_low=25_500.0)
NEGATIVE_SWITCH = SwitchPlant(**LIMITS, home_low=-math.inf, home_high=25_500.0)
CAM = SwitchPlant(**LIMITS, home_low=20_500.0, home_high=40_700.0)
NO_SWITCH = SwitchPlant(**LIMITS)

# home position of each method, from its definition
EDGE_HOME = {
    1: (NO_SWITCH, -100_000, -98_766),      # negative limit switch; first index pulse to its right
    2: (NO_SWITCH, 100_000, 91_234),        # positive limit switch; first index pulse to its left
    3: (POSITIVE_SWITCH, 25_500, 21_234),   # positive home switch; index pulse left of the edge
    4: (POSITIVE_SWITCH, 25_500, 31_234),   # ... right of the edge
    5: (NEGATIVE_SWITCH, 25_500, 31_234),   # negative home switch; index pulse right of the edge
    6: (NEGATIVE_SWITCH, 25_500, 21_234),   # ... left of the edge
    7: (CAM, 20_500, 11_234),               # positive initial move; left of the cam's lower edge
    8: (CAM, 20_500, 21_234),               # right of the lower edge
    9: (CAM, 40_700, 31_234),               # left of the upper edge
    10: (CAM, 40_700, 41_234),              # right of the upper edge
    11: (CAM, 40_700, 41_234),              # negative initial move; right of the upper edge
    12: (CAM, 40_700, 31_234),              # left of the upper edge
    13: (CAM, 20_500, 21_234),              # right of the lower edge
    14: (CAM, 20_500, 11_234),              # left of the lower edge
}
#: start positions: below, on and above the feature (and on the limit switch a limit method searches)
STARTS = {
    1: (0.0, -100_300.0, 50_000.0), 2: (0.0, 100_300.0, -50_000.0),
    3: (0.0, 60_000.0, 25_400.0), 4: (0.0, 60_000.0, 25_600.0),
    5: (0.0, 60_000.0, 25_600.0), 6: (0.0, 60_000.0, 25_400.0),
    **{m: (-50_000.0, 30_000.0, 60_000.0, 20_400.0, 40_800.0) for m in range(7, 15)},
}
CASES = [(m, x0) for m in EDGE_HOME for x0 in STARTS[m]] + [(m + 16, x0) for m in EDGE_HOME for x0 in STARTS[m]]


def _core(plant: SwitchPlant, x0: float, method: int) -> DriveCore:
    params = {(0x607E, 0): 0, (0x608F, 1): 10_000, (0x608F, 2): 1, (0x6080, 0): 3000, (0x6084, 0): ACC,
              (0x6085, 0): 10 * ACC, (0x6098, 0): method, (0x607C, 0): OFFSET, (0x6099, 1): FAST,
              (0x6099, 2): SLOW, (0x609A, 0): ACC, (0x6083, 0): ACC, (0x6081, 0): FAST, (0x6065, 0): 0xFFFFFFFF}
    core = DriveCore(lambda i, s=0: params[(i, s)], MotorSpec(initial_position=x0, plant=plant))
    for cw in (0x06, 0x07, 0x0F):
        core.apply(cw, 6, 0, 0, 0)
    assert core.sm.state is State.OPERATION_ENABLED
    return core


def _home(core: DriveCore, seconds: float = 6.0) -> list[int]:
    """Start homing (controlword bit 4) and run until attained or error; the homing bits seen, deduplicated."""
    bits = [core.statusword() & 0x3400]
    core.apply(0x1F, 6, 0, 0, 0)
    for _ in range(int(seconds / 0.001)):
        core.step(0.001)
        sw = core.statusword() & 0x3400
        if sw != bits[-1]:
            bits.append(sw)
        if sw in (0x1400, 0x2400):
            break
    return bits


def _reads_at(core: DriveCore, mechanical: float) -> float:
    """What the position actual value 0x6064 reads with the motor at ``mechanical`` (polarity positive)."""
    return core.position_actual() - core.x + mechanical


@pytest.mark.parametrize("method,x0", CASES, ids=[f"m{m}-from{int(x)}" for m, x in CASES])
def test_drives_cia402_homing_method_end_position(method, x0):
    """CiA 402-2 homing methods 1-14 and 17-30 from every side of their switch: the run ends with homing
    attained (statusword bits 12 and 10, not 13) and the position actual value reads the home offset 0x607C
    at the home position of the method's definition - the first index pulse beyond the switch edge on the
    method's side (1-14), the edge itself (17-30)."""
    plant, edge, index = EDGE_HOME[method if method <= 14 else method - 16]
    expected = index if method <= 14 else edge
    core = _core(plant, x0, method)
    bits = _home(core)
    assert bits[-1] == 0x1400, [hex(b) for b in bits]
    assert abs(_reads_at(core, expected) - OFFSET) <= 1
    assert core.v == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize("method,x0,expected", [
    (33, 5_000.0, 1_234), (33, 1_234.0, -8_766), (34, 5_000.0, 11_234), (34, 1_234.0, 11_234),
    (35, 5_000.0, 5_000), (37, -42.0, -42)])
def test_drives_cia402_homing_index_pulse_and_current_position(method, x0, expected):
    """CiA 402-2 methods 33/34: the first index pulse in the negative / positive direction (one the motor
    stands on is not passed, so not found); 35/37: the current position is home."""
    core = _core(NO_SWITCH, x0, method)
    assert _home(core)[-1] == 0x1400
    assert abs(_reads_at(core, expected) - OFFSET) <= 1


def test_drives_cia402_homing_status_bits_timeline():
    """CiA 402-2 homing mode statusword: bit 10 alone before the start (not started), 0 while searching
    (in progress), bit 12 alone once home is found and the drive brakes (attained, target not reached),
    bits 12 + 10 at standstill (completed)."""
    core = _core(CAM, -50_000.0, 8)
    assert _home(core) == [0x0400, 0x0000, 0x1000, 0x1400]


@pytest.mark.parametrize("method,plant,x0,why", [
    (3, NO_SWITCH, 0.0, "positive home switch missing: the positive limit switch is reached"),
    (5, NO_SWITCH, 0.0, "negative home switch missing: the negative limit switch is reached"),
    (7, NO_SWITCH, 0.0, "cam missing: reversed at the positive limit switch, then the negative one"),
    (1, NO_SWITCH, 100_300.0, "started on the opposite limit switch"),
    (15, CAM, 0.0, "15 is a reserved method"),
    (0, CAM, 0.0, "0: no homing method"),
])
def test_drives_cia402_homing_error(method, plant, x0, why):
    """CiA 402-2 homing error: bit 13 while the drive still moves, bits 13 + 10 at standstill; never homing
    attained (bit 12)."""
    core = _core(plant, x0, method)
    bits = _home(core, 10.0)
    assert bits[-1] == 0x2400, (why, [hex(b) for b in bits])
    assert not any(b & 0x1000 for b in bits)


def test_drives_cia402_homing_halt_interrupts():
    """CiA 402-2 homing mode, controlword bit 8 (halt): the run stops with the homing acceleration and
    shows "interrupted" (bit 10 alone); it is not attained."""
    core = _core(CAM, -50_000.0, 8)
    core.apply(0x1F, 6, 0, 0, 0)
    for _ in range(50):
        core.step(0.001)
    assert core.statusword() & 0x3400 == 0
    core.apply(0x11F, 6, 0, 0, 0)
    for _ in range(200):
        core.step(0.001)
    assert core.statusword() & 0x3400 == 0x0400 and abs(core.v) < 1.0


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(list(range(7, 15)) + list(range(23, 31))), st.floats(-95_000.0, 95_000.0))
def test_drives_cia402_homing_cam_methods_from_anywhere(method, x0):
    """CiA 402-2 methods 7-14 / 23-30 from any start between the limit switches: always the same home
    position (the method's index pulse or cam edge), never a homing error."""
    plant, edge, index = EDGE_HOME[method if method <= 14 else method - 16]
    core = _core(plant, x0, method)
    assert _home(core)[-1] == 0x1400
    assert abs(_reads_at(core, index if method <= 14 else edge) - OFFSET) <= 1
