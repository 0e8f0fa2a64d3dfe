"""Camming on a modulo leading axis (common application; decision 16 for synchronous positions)."""
import pytest

from _s7_1500_rig import ROTARY, VIRTUAL, merge, modulo

from _cam_h import HUMP, Camming, flin


def test_s7_1500_cyclic_cam_on_modulo_master_spr1():
    h = Camming(master_params=merge(VIRTUAL, ROTARY, modulo(360.0)))
    h.move(360.0)
    h.cam_in(MasterOffset=0.0, MasterSyncPosition=0.0, MasterStartDistance=90.0, SyncProfileReference=1,
             ApplicationMode=1)
    h.until(lambda: h.ci[0].InSync, timeout=5.0)
    h.run(1.2)
    rows = [r for r in h.rig.log if r["InSync0"]]
    assert len(rows) > 200
    for r in rows:
        assert r["s"] == pytest.approx(flin(HUMP, r["m"] % 360.0), abs=1e-6), r
    h.check_log()


def test_s7_1500_once_cam_on_modulo_master_ends_after_one_revolution():
    h = Camming(master_params=merge(VIRTUAL, ROTARY, modulo(360.0)))
    h.move(360.0)
    h.cam_in(MasterOffset=0.0, MasterSyncPosition=0.0, MasterStartDistance=90.0, SyncProfileReference=1,
             ApplicationMode=0)
    h.until(lambda: h.ci[0].InSync, timeout=5.0)
    h.until(lambda: h.ci[0].EndOfProfile, timeout=5.0)
    rows = [r for r in h.rig.log if r["InSync0"]]
    assert 0.9 * 360 / (360 * 0.004) < len(rows) <= 360 / (360 * 0.004) + 2
    h.run(0.3)
    assert h.s == pytest.approx(0.0, abs=1e-6)
