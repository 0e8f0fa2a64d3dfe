"""Referencing methods of MC_Home on the Pilz drive axis (Pilz V6.5 §1.7.5.1 Tab. 22, Tab. 19, §1.7.6).

The simulated machine: limit switches at -100 (negative) and +100 (positive), reference switch [lo, lo + 10],
encoder zero pulses at 3 + 10 k.  Each method must take the reference point at the feature the table names,
approached from the initial direction the table gives, and give that point the reference position I34."""
from __future__ import annotations

import pytest

from plcmotion.pilz.technology.homing_methods import (CIA402_LETTER, METHODS, POSITION_CONTROLLED, SET_REFERENCE,
                                                      VELOCITY_CONTROLLED, Feature, control_type, from_drive_based)

from ._core import make_axis, rows_from, start

I34 = 500.0
BASE = {"I101": "I0.0", "I102": "I0.1", "I103": "I0.2", "LimitSwitchLevel": True,
        "Plant.HWLimitMinPosition": -100.0, "Plant.HWLimitMaxPosition": 100.0, "Plant.ZeroMarkDistance": 10.0,
        "Plant.ZeroMarkOffset": 3.0, "Plant.HomingSwitchLength": 10.0, "I32": 100.0, "I33": 10.0, "I34": I34,
        "I39": 2000.0}

# (A586, reference switch lower end, start position, machine position of the reference point)
CASES = [
    (1, 20.0, 0.0, -97.0),      # A: negative limit switch, then the first zero pulse moving away
    (17, 20.0, 0.0, -100.0),    # C: negative limit switch
    (2, 20.0, 0.0, 93.0),       # E: positive limit switch + zero pulse
    (18, 20.0, 0.0, 100.0),     # G: positive limit switch
    (21, -60.0, 0.0, -50.0),    # D: reference switch at the negative end: its positive edge
    (5, -60.0, 0.0, -47.0),     # B: ... + zero pulse
    (19, 50.0, 0.0, 50.0),      # H: reference switch at the positive end: its negative edge
    (3, 50.0, 0.0, 43.0),       # F: ... + zero pulse
    (23, 20.0, 0.0, 20.0),      # J: middle switch, positive search, found at once
    (23, 20.0, 50.0, 30.0),     # J: ... from beyond it: reversed at the positive limit switch
    (7, 20.0, 0.0, 13.0),       # I: ... + zero pulse
    (27, 20.0, 50.0, 30.0),     # L: middle switch, negative search
    (27, 20.0, 0.0, 20.0),      # L: ... from below it: reversed at the negative limit switch
    (11, 20.0, 50.0, 33.0),     # K: ... + zero pulse
    (33, 20.0, 0.0, -7.0),      # M: zero pulse only, negative
    (34, 20.0, 0.0, 3.0),       # N: zero pulse only, positive
]


@pytest.mark.parametrize("a586,switch,here,point", CASES, ids=[f"{CIA402_LETTER[c[0]]}-{c[0]}-{c[2]}" for c in CASES])
def test_pilz_homing_methods(a586, switch, here, point):
    """Pilz V6.5 Tab. 22 / §1.7.6: the reference point of each CiA 402 method gets I34; I92 and I86 at the end,
    I89 8 during the search, no fault."""
    ctl, ax = make_axis({**BASE, "A586": a586, "Plant.HomingSwitchPosition": switch, "Plant.InitialPosition": here},
                        referenced=False)
    t0 = start(ax, 6)
    ctl.run_until(lambda: ax.status.I92 or ax.status.I91, timeout=20.0)
    assert ax.status.I92 and ax.status.I86 and not ax.alarms
    assert rows_from(ax, t0)[1].I89 == 8 and ax.status.I89 == 2
    offset = float(ctl.bank.act_p[ax.index]) - ax.drive.mechanical_position()
    assert offset == pytest.approx(I34 - point, abs=0.02)


def test_pilz_homing_travel_to_reference_position():
    """Pilz V6.5 §1.7.6 (I43): after referencing the axis travels back to the reference position."""
    ctl, ax = make_axis({**BASE, "A586": 34, "I43": 1}, referenced=False)
    start(ax, 6)
    ctl.run_until(lambda: ax.status.I92, timeout=10.0)
    assert ax.status.I96 == pytest.approx(I34) and ax.drive.mechanical_position() == pytest.approx(3.0, abs=0.01)


def test_pilz_homing_set_reference():
    """Pilz V6.5 Tab. 22 method O (A586 = 35 / 37, I30 = 5): the actual position becomes I34 without motion."""
    for params in ({"A586": 35}, {"A586": 37}, {"I30": 5}):
        ctl, ax = make_axis({**BASE, **params, "Plant.InitialPosition": 12.0}, referenced=False)
        start(ax, 6)
        ctl.run(0.003)
        assert ax.status.I92 and ax.status.I96 == pytest.approx(I34) and ax.drive.mechanical_position() == 12.0


def test_pilz_homing_not_found_between_limit_switches():
    """Pilz V6.5 §1.7.6: a middle reference switch that is not between the limit switches is not found: the
    command is cancelled (I91, I90 = 25)."""
    ctl, ax = make_axis({**BASE, "A586": 23, "Plant.HomingSwitchPosition": 500.0}, referenced=False)
    start(ax, 6)
    ctl.run_until(lambda: ax.status.I91, timeout=20.0)
    assert ax.status.I90 == 25 and not ax.status.I86


def test_pilz_homing_method_tables():
    """Pilz V6.5 Tab. 22 (19 methods A-S with initial movement, zero pulse, feature) and Tab. 19 (A586 numbers by
    control type)."""
    rows = {"A": (-1, True, "limit switch"), "B": (-1, True, "reference switch at the end of travel"),
            "C": (-1, False, "limit switch"), "D": (-1, False, "reference switch at the end of travel"),
            "E": (1, True, "limit switch"), "F": (1, True, "reference switch at the end of travel"),
            "G": (1, False, "limit switch"), "H": (1, False, "reference switch at the end of travel"),
            "I": (1, True, "reference switch in the middle"), "J": (1, False, "reference switch in the middle"),
            "K": (-1, True, "reference switch in the middle"), "L": (-1, False, "reference switch in the middle"),
            "M": (-1, True, "zero pulse"), "N": (1, True, "zero pulse"), "O": (0, False, "setting the reference"),
            "P": (1, False, "torque/force stop"), "Q": (1, True, "torque/force stop"),
            "R": (-1, False, "torque/force stop"), "S": (-1, True, "torque/force stop")}
    assert {k: (m.direction, m.zero_pulse, m.feature.value) for k, m in METHODS.items()} == rows
    assert POSITION_CONTROLLED == (1, 2, 3, 5, 7, 11, 17, 18, 19, 21, 23, 27, 33, 34)
    assert VELOCITY_CONTROLLED == (-1, -2, -3, -4) and SET_REFERENCE == (35, 37)
    for number in POSITION_CONTROLLED:
        assert control_type(METHODS[CIA402_LETTER[number]]) == "position"
    assert {CIA402_LETTER[n] for n in POSITION_CONTROLLED} == set("ABCDEFGHIJKLMN")
    assert {CIA402_LETTER[n] for n in VELOCITY_CONTROLLED} == set("PQRS")
    assert control_type(METHODS["O"]) == "unchanged" and control_type(METHODS["P"]) == "velocity"


@pytest.mark.parametrize("i30,i31,i35,middle,letter", [
    (2, 1, 1, False, "A"), (1, 1, 1, False, "B"), (2, 1, 0, False, "C"), (1, 1, 0, False, "D"),
    (2, 0, 1, False, "E"), (1, 0, 1, False, "F"), (2, 0, 0, False, "G"), (1, 0, 0, False, "H"),
    (1, 0, 1, True, "I"), (1, 0, 0, True, "J"), (1, 1, 1, True, "K"), (1, 1, 0, True, "L"),
    (3, 1, 1, False, "M"), (3, 0, 1, False, "N"), (5, 0, 0, False, "O"), (4, 0, 0, False, "P"),
    (4, 0, 1, False, "Q"), (4, 1, 0, False, "R"), (4, 1, 1, False, "S")])
def test_pilz_homing_drive_based_selection(i30, i31, i35, middle, letter):
    """Pilz V6.5 §1.7.5.1: Drive Based / PROFIdrive build the method from I30 type, I31 direction and I35 zero
    pulse (Tab. 22 letters)."""
    assert from_drive_based(i30, i31, i35, middle) is METHODS[letter]
    assert from_drive_based(0, i31, i35, middle) is None


@pytest.mark.parametrize("params,point", [
    ({"A586": -1}, 80.0), ({"A586": -2}, 73.0), ({"A586": -3}, -80.0), ({"A586": -4}, -77.0),
    ({"I30": 4, "I31": 0, "I35": 0}, 80.0), ({"I30": 4, "I31": 1, "I35": 1}, -77.0)])
def test_pilz_homing_torque_stop(params, point):
    """Pilz V6.5 Tab. 22 P - S, Tab. 21 I28 / I29: the axis presses against the mechanical end stop; the
    reference is set when the torque/force has stayed at the limit I28 for I29 - at the stop, or with zero
    pulse at the first zero pulse away from it."""
    ctl, ax = make_axis({**BASE, **params, "Drive.EndStopPositive": 80.0, "Drive.EndStopNegative": -80.0,
                         "I29": 0.2}, referenced=False)
    t0 = start(ax, 6)
    arrived = None
    while not (ax.status.I92 or ax.status.I91) and ctl.time < t0 + 10.0:
        ctl.step()
        if arrived is None and abs(ax.drive.mechanical_position()) >= 80.0 - 1e-9:
            arrived = ctl.time
    assert ax.status.I92 and ax.status.I86 and not ax.alarms
    assert ctl.time - arrived >= 0.2
    offset = float(ctl.bank.act_p[ax.index]) - ax.drive.mechanical_position()
    assert offset == pytest.approx(I34 - point, abs=0.02)
    assert all(METHODS[c].feature is Feature.TORQUE_STOP for c in "PQRS")


def test_pilz_homing_torque_stop_presses_with_the_torque_limit():
    """Pilz V6.5 Tab. 21 I28 / I29, Tab. 22 P: at the end stop the drive's torque rises to the limit I28 and
    stays there; the reference is set after I29 at the limit, not before; afterwards the limit is gone (a move
    may use more torque than I28 again).  I28 lies above the torque of the search acceleration (I39 = 2000
    unit/s² x 1e-3 kg m² x 2 pi / 10 unit = 1.26)."""
    limit = 2.0
    ctl, ax = make_axis({**BASE, "A586": -1, "Drive.EndStopPositive": 30.0, "I28": limit, "I29": 0.1,
                         "I11": 10000.0}, referenced=False)
    t0 = start(ax, 6)
    at_limit = []                                      # times the drive pushed with the limit torque
    referenced = None
    while not (ax.status.I92 or ax.status.I91) and ctl.time < t0 + 5.0:
        ctl.step()
        if referenced is None and ax.status.I86:
            referenced = ctl.time
        if referenced is None and ax.drive.torque_limit_active:
            assert ax.drive.torque == pytest.approx(limit)
            at_limit.append(ctl.time)
    assert ax.status.I92 and referenced is not None
    assert at_limit and ax.drive.mechanical_position() == pytest.approx(30.0)
    assert referenced - at_limit[0] >= 0.1 - 1e-9
    # the limit has gone: 5000 unit/s² asks for 5000 x 1e-3 x 2 pi / 10 = 3.1 > I28 without being held back
    start(ax, 2, I403=-20.0, I404=500.0, I405=5000.0, I406=5000.0, I407=1e7)
    peak = 0.0
    while not ax.status.I92 and ctl.time < t0 + 10.0:
        ctl.step()
        assert not ax.drive.torque_limit_active
        peak = max(peak, abs(ax.drive.torque))
    assert ax.status.I92 and peak > limit


def test_pilz_homing_torque_stop_needs_the_limit_reached():
    """Pilz V6.5 Tab. 21 I28: a torque limit the drive cannot reach at the stop (the speed loop asks for less)
    sets no reference: the axis keeps pressing, MC_Home stays in homing (I89 = 8)."""
    ctl, ax = make_axis({**BASE, "A586": -1, "Drive.EndStopPositive": 30.0, "I28": 1e9, "I29": 0.1},
                        referenced=False)
    t0 = start(ax, 6)
    ctl.run(3.0)
    assert ax.drive.mechanical_position() == pytest.approx(30.0)
    assert not ax.status.I92 and not ax.status.I86 and ax.status.I89 == 8 and ctl.time > t0 + 2.5
