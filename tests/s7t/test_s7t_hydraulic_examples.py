"""The examples of issue 11 §4 for S7-Technology V4.1: a hydraulic press with pressure limiting (§3.1.4,
§4.6) and a positioning axis moving to a fixed end stop (§6.2.11); both run and write their plot."""
from __future__ import annotations

import runpy
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_s7t_example_hydraulic_press(tmp_path):
    """S7-Technology V4.1 §4.6, §6.2.1, §6.2.13: the P/Q valve holds the press force at its 8 kN limit on
    the workpiece; after the retract and StopMode 3 the output is QOutputValue = 0 %."""
    ns = runpy.run_path(str(EXAMPLES / "s7t_hydraulic_press.py"))
    r = ns["run"](tmp_path)
    assert r["press_force"] == pytest.approx(8000.0, rel=1e-6)
    assert r["press_position"] == pytest.approx(300.0)
    assert r["step"] == "off" and r["final_position"] == pytest.approx(100.0, abs=1.0)
    assert r["final_output"] == 0.0
    assert (tmp_path / "s7t_hydraulic_press.png").stat().st_size > 0


def test_s7t_example_end_pos(tmp_path):
    """S7-Technology V4.1 §6.2.11 example: clamping torque 0.5 N m then doubled to 1.0 N m, a move towards
    the stop refused with 16#8056, released by MC_MoveRelative -30 mm from the held setpoint (80 + 2 mm)."""
    ns = runpy.run_path(str(EXAMPLES / "s7t_end_pos.py"))
    r = ns["run"](tmp_path)
    assert r["clamp_torque"] == pytest.approx(0.5, rel=1e-6)
    assert r["harder_torque"] == pytest.approx(1.0, rel=1e-6)
    assert r["refused"] == 0x8056
    assert r["step"] == "idle" and r["final"] == pytest.approx(82.0 - 30.0, abs=0.2)
    assert (tmp_path / "s7t_end_pos.png").stat().st_size > 0
