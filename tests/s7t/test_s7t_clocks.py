"""The clocks and the version of an S7-Technology controller (S7-Technology V4.1 §5.1 and the "system
clocks" of S7T Config; docs/s7t/decisions.md D2, D3): the kernel's servo cycle is the IPO cycle, a whole
multiple of the DP cycle, which is a whole multiple of 0.25 ms; the only technology version is V4.1 (41).
"""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.s7t import device


@pytest.mark.parametrize("servo_cycle", [0.00025, 0.00075, 0.001, 0.002, 0.004])
def test_s7t_clock_ipo_cycle_in_quarter_milliseconds(servo_cycle):
    """S7-Technology V4.1 §5.1 / system clocks: an IPO cycle of a whole number of 0.25 ms is accepted; the
    technology DBs are updated every 2nd IPO cycle by default (the example of §5.1)."""
    ctl = Controller(family="S7-Technology", servo_cycle=servo_cycle, app_cycle=servo_cycle * 4)
    assert device(ctl).db_update_ratio == 2
    before = device(ctl).mcdevice.UpdateCounter
    ctl.run(servo_cycle * 40)
    assert device(ctl).mcdevice.UpdateCounter - before == 20


@pytest.mark.parametrize("servo_cycle", [0.0001, 0.0011, 0.0015 + 1e-6, 0.0033])
def test_s7t_clock_other_ipo_cycles_are_refused(servo_cycle):
    """S7-Technology V4.1 system clocks: the DP cycle is a whole multiple of 0.25 ms, the IPO cycle a whole
    multiple of it; any other servo_cycle is refused, naming it."""
    with pytest.raises(ValueError, match="servo_cycle"):
        Controller(family="S7-Technology", servo_cycle=servo_cycle, app_cycle=servo_cycle * 4)


def test_s7t_clock_technology_version_is_41():
    """S7-Technology V4.1: technology_version is 10 * major + minor, 41 the only one and the default."""
    assert Controller(family="S7-Technology").technology_version == 41
    assert Controller(family="S7-Technology", technology_version=41).technology_version == 41
    for other in (4, 4.1, 42):
        with pytest.raises(ValueError, match="technology_version"):
            Controller(family="S7-Technology", technology_version=other)
