"""Retentive data (§11.1.3 modes 6/7: StatusSensor.AbsEncoderOffset) is written atomically: a crash during
the write keeps the previous file intact."""
from __future__ import annotations

import json
import os

import pytest

from plcmotion import Controller
from plcmotion.kernel import retain
from plcmotion.s7_1200 import MC_Home, MC_Power

ABS = {"Actor": {"Type": 1}, "Sensor[1]": {"Type": 1, "Parameter": {"DeterminableRevolutions": 4096}},
       "Plant": {"InitialPosition": 123.4}}


def adjust(state_file, position):
    ctl = Controller(state_file=str(state_file))
    axis = ctl.add_positioning_axis("A", ABS)
    power, home = MC_Power(), MC_Home()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, 1.0)
    home(Axis=axis, Execute=True, Mode=7, Position=position)
    assert home.Done
    return axis


def test_offset_survives_a_new_controller_11_1_3(tmp_path):
    sf = tmp_path / "machine.state.json"
    axis = adjust(sf, 10.0)
    data = json.loads(sf.read_text())
    assert data["axes"]["A"]["AbsEncoderOffset"] == pytest.approx(axis.StatusSensor.AbsEncoderOffset)
    again = Controller(state_file=str(sf)).add_positioning_axis("A", ABS)
    assert again.ActualPosition == pytest.approx(10.0, abs=1e-5)
    assert again.StatusBits.HomingDone


def test_crash_during_write_keeps_the_old_file(tmp_path, monkeypatch):
    sf = tmp_path / "machine.state.json"
    adjust(sf, 10.0)
    before = sf.read_bytes()

    def crash(src, dst):
        raise OSError("power failure")
    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError):
        retain.save(sf, {"A": {"AbsEncoderOffset": 99.0, "HomingDone": True}})
    assert sf.read_bytes() == before                       # the old content is untouched
    assert [p.name for p in tmp_path.iterdir()] == [sf.name]   # no temporary file left behind


def test_unreadable_state_file_is_a_clear_error(tmp_path):
    sf = tmp_path / "broken.state.json"
    sf.write_text("{not json")
    with pytest.raises(ValueError, match="broken.state.json"):
        Controller(state_file=str(sf))
