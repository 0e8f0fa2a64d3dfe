"""MC_GearInPos (S7-1500T V5 §4.2, §4.3.2–§4.3.4, §4.4.2, §9.1.2): waiting / synchronizing / synchronous states,
exact synchronism at the synchronous positions, directions, modulo, overrides."""
import pytest
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_Home, MC_MoveVelocity, MC_Halt
from _gear_h import H, VIRTUAL, merge, modulo, outputs_consistent


def _rec(h, fb, extra=None):
    sm = h.s.StatusSynchronizedMotion
    b = h.ctl.bank

    def rec():
        r = {"t": h.ctl.time, "m": float(b.sp_p[h.m.index]), "mv": h.m.Velocity, "s": float(b.sp_p[h.s.index]),
             "sv": h.s.Velocity, "sa": h.s.Acceleration, "Busy": fb.Busy, "StartSync": fb.StartSync,
             "InSync": fb.InSync, "Abort": fb.CommandAborted, "Error": fb.Error, "X21": h.s.StatusWord.X21,
             "X22": h.s.StatusWord.X22, "fs": sm.FunctionState, "wfs": sm.WaitingFunctionState,
             "am": sm.ActualMaster, "ssw": int(sm.StatusWord), "bad": outputs_consistent(fb)}
        if extra:
            r.update(extra())
        return r
    h.rec = rec


def _gip(h, **inp):
    fb = MC_GearInPos()
    d = {"Master": h.m, "Slave": h.s, "Execute": False}
    d.update(inp)
    h.call(fb, d)
    _rec(h, fb)
    return fb, d


def _check_states(h, start_at, sync_at, direction, law):
    """Common checks of the timeline; start_at / sync_at: master positions (unwrapped)."""
    dx = 100.0 * 0.004 + 1e-6
    for r in h.rows:
        assert not r["bad"], r
        assert not (r["X21"] and r["X22"]), r
        if r["Busy"] and not r["StartSync"] and not r["InSync"]:           # waiting
            assert r["wfs"] == 2 and not r["X21"] and not r["X22"], r
        if r["StartSync"] and not r["InSync"]:                               # synchronizing
            assert r["X21"] and r["fs"] == 2 and r["wfs"] == 0, r
        if r["InSync"]:
            assert r["X22"] and r["fs"] == 2, r
    first_start = next(r for r in h.rows if r["StartSync"])
    assert 0.0 <= (first_start["m"] - start_at) * direction <= dx, (first_start["m"], start_at)
    first_sync = next(r for r in h.rows if r["InSync"])
    assert 0.0 <= (first_sync["m"] - sync_at) * direction <= dx, (first_sync["m"], sync_at)
    for r in h.rows:
        if r["InSync"]:
            assert r["s"] == pytest.approx(law(r["m"]), abs=1e-6), r


@pytest.mark.parametrize("num,den", [(1, 1), (-3, 2), (2, 5)])
@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_s7_1500_spr1_in_advance_leading_value_distance(num, den, direction):
    h = H()
    h.move_master(100.0 * direction)
    p0 = h.m.Position
    msp, ssp, dist = p0 + direction * 300.0, 77.0, 120.0
    fb, d = _gip(h, RatioNumerator=num, RatioDenominator=den, MasterSyncPosition=msp, SlaveSyncPosition=ssp,
                 SyncProfileReference=1, MasterStartDistance=dist)
    d["Execute"] = True
    h.step()
    assert fb.Busy and not fb.StartSync and h.s.StatusSynchronizedMotion.WaitingFunctionState == 2
    h.until(lambda: fb.InSync, 6.0)
    h.run(0.2)
    _check_states(h, msp - direction * dist, msp, direction, lambda m: ssp + num / den * (m - msp))
    # while waiting the slave stands still
    assert all(abs(r["sv"]) < 1e-9 for r in h.rows if r["Busy"] and not r["StartSync"])


@pytest.mark.parametrize("num,den", [(1, 1), (-1, 3)])
@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_s7_1500_spr3_subsequent_leading_value_distance(num, den, direction):
    h = H()
    h.move_master(100.0 * direction)
    p0 = h.m.Position
    msp, ssp, dist = p0 + direction * 150.0, -40.0, 80.0
    fb, d = _gip(h, RatioNumerator=num, RatioDenominator=den, MasterSyncPosition=msp, SlaveSyncPosition=ssp,
                 SyncProfileReference=3, MasterStartDistance=dist)
    d["Execute"] = True
    h.until(lambda: fb.InSync, 6.0)
    h.run(0.2)
    _check_states(h, msp, msp + direction * dist, direction, lambda m: ssp + num / den * (m - msp))


@pytest.mark.parametrize("num,den", [(1, 1), (-2, 1)])
@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_s7_1500_spr0_in_advance_dynamic_parameters(num, den, direction):
    h = H()
    h.move_master(100.0 * direction)
    p0 = h.m.Position
    msp, ssp = p0 + direction * 500.0, 250.0
    vel = 400.0
    fb, d = _gip(h, RatioNumerator=num, RatioDenominator=den, MasterSyncPosition=msp, SlaveSyncPosition=ssp,
                 SyncProfileReference=0, Velocity=vel, Acceleration=800.0, Deceleration=800.0, Jerk=0.0)
    d["Execute"] = True
    h.until(lambda: fb.InSync, 8.0)
    h.run(0.2)
    first_start = next(r for r in h.rows if r["StartSync"])
    assert 0 < (msp - first_start["m"]) * direction < 500.0
    _check_states(h, first_start["m"], msp, direction, lambda m: ssp + num / den * (m - msp))
    # decisions #13: Velocity bounds the following axis during synchronization; Acceleration/Deceleration
    # bound it too while the master runs at constant velocity
    syncing = [r for r in h.rows if r["StartSync"] and not r["InSync"]]
    assert max(abs(r["sv"]) for r in syncing) <= vel + 1e-6
    assert max(abs(r["sa"]) for r in syncing) <= 800.0 + 1e-6


def test_s7_1500_spr1_master_reverses_during_synchronization():
    """§4.3.3: master dynamics are superimposed 'in accordance with the synchronous operation function'; the
    leading value may reverse (catalog erratum 1): the profile is a function of the leading value."""
    h = H()
    mv, inp = h.move_master(100.0)
    p0 = h.m.Position
    msp, ssp, dist = p0 + 300.0, 10.0, 200.0
    fb, d = _gip(h, MasterSyncPosition=msp, SlaveSyncPosition=ssp, SyncProfileReference=1, MasterStartDistance=dist)
    d["Execute"] = True
    h.until(lambda: h.m.Position > p0 + 200.0, 5.0)
    assert fb.StartSync and not fb.InSync
    n = len(h.rows)
    inp.update(Execute=False); h.step()
    inp.update(Execute=True, Velocity=-100.0)
    h.until(lambda: h.m.Position < p0 + 150.0, 5.0)
    assert fb.Busy and not fb.Error and not fb.CommandAborted
    inp.update(Execute=False); h.step()
    inp.update(Execute=True, Velocity=100.0)
    h.until(lambda: fb.InSync, 5.0)
    h.run(0.1)
    # same master position -> same slave position during synchronization
    fwd = [(r["m"], r["s"]) for r in h.rows[:n] if r["StartSync"]]
    back = [(r["m"], r["s"]) for r in h.rows[n:] if r["StartSync"] and not r["InSync"]]
    import numpy as np
    fm, fs = np.array(fwd).T
    for m, s in back:
        if fm.min() <= m <= fm.max():
            assert s == pytest.approx(float(np.interp(m, fm, fs)), abs=0.05), (m, s)
    first_sync = next(r for r in h.rows if r["InSync"])
    assert first_sync["s"] == pytest.approx(ssp + first_sync["m"] - msp, abs=1e-6)


def test_s7_1500_waiting_gear_in_pos_while_gear_in_active():
    """§9.3.2: a waiting GearInPos aborts nothing; when it becomes active it aborts the GearIn.
    §4.6: FunctionState shows the active function, WaitingFunctionState the waiting one."""
    h = H()
    h.move_master(100.0)
    g = MC_GearIn()
    gd = h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 2})
    h.until(lambda: g.InGear, 3.0)
    p0 = h.m.Position
    fb, d = _gip(h, MasterSyncPosition=p0 + 200.0, SlaveSyncPosition=0.0, SyncProfileReference=1,
                 MasterStartDistance=100.0)
    d["Execute"] = True
    h.step(2)
    sm = h.s.StatusSynchronizedMotion
    assert fb.Busy and not fb.StartSync
    assert g.InGear and g.Busy and not g.CommandAborted
    assert sm.FunctionState == 1 and sm.WaitingFunctionState == 2
    assert h.s.StatusWord.X22 and not h.s.StatusWord.X21
    h.until(lambda: fb.StartSync, 3.0)
    h.step()
    assert g.CommandAborted and not g.Busy and not g.InGear
    assert sm.FunctionState == 2 and sm.WaitingFunctionState == 0 and h.s.StatusWord.X21
    h.until(lambda: fb.InSync, 3.0)
    assert h.s.Position == pytest.approx(0.0 + (h.m.Position - (p0 + 200.0)), abs=1e-6)


def test_s7_1500_second_waiting_job_aborts_first_waiting_job():
    h = H()
    h.move_master(100.0)
    p0 = h.m.Position
    a1, d1 = _gip(h, MasterSyncPosition=p0 + 400.0, SyncProfileReference=1, MasterStartDistance=100.0)
    a2 = MC_GearInPos()
    d2 = h.call(a2, {"Master": h.m, "Slave": h.s, "Execute": False, "MasterSyncPosition": p0 + 500.0,
                     "SlaveSyncPosition": 5.0, "SyncProfileReference": 1, "MasterStartDistance": 100.0})
    d1["Execute"] = True
    h.step(2)
    d2["Execute"] = True
    h.step(2)
    assert a1.CommandAborted and not a1.Busy
    assert a2.Busy and h.s.StatusSynchronizedMotion.WaitingFunctionState == 2
    h.until(lambda: a2.InSync, 8.0)


def test_s7_1500_disable_slave_aborts_waiting_gear_in_pos():
    """§9.1.2.1 / §9.3.2 note 1: MC_Power.Enable = FALSE aborts the synchronous operation in every status
    (table legend A: CommandAborted)."""
    h = H()
    h.move_master(100.0)
    fb, d = _gip(h, MasterSyncPosition=h.m.Position + 1000.0, SyncProfileReference=1, MasterStartDistance=10.0)
    d["Execute"] = True
    h.step(2)
    assert fb.Busy
    h.en["S1"] = False
    h.run(0.1)
    assert not fb.Busy and fb.CommandAborted and not fb.Error
    assert h.s.StatusSynchronizedMotion.WaitingFunctionState == 0


def test_s7_1500_disable_slave_aborts_synchronizing_gear_in_pos():
    h = H()
    h.move_master(100.0)
    p0 = h.m.Position
    fb, d = _gip(h, MasterSyncPosition=p0 + 300.0, SyncProfileReference=1, MasterStartDistance=250.0)
    d["Execute"] = True
    h.until(lambda: fb.StartSync, 3.0)
    h.en["S1"] = False
    h.run(0.1)
    assert not fb.Busy and fb.CommandAborted and not fb.StartSync and not fb.InSync


def test_s7_1500_halt_does_not_abort_waiting_but_aborts_active():
    h = H()
    h.move_master(100.0)
    p0 = h.m.Position
    fb, d = _gip(h, MasterSyncPosition=p0 + 200.0, SyncProfileReference=1, MasterStartDistance=100.0)
    d["Execute"] = True
    h.step(2)
    halt = MC_Halt()
    hd = h.call(halt, {"Axis": h.s, "Execute": True})
    h.until(lambda: halt.Done, 2.0)
    assert fb.Busy and not fb.CommandAborted
    h.until(lambda: fb.InSync, 4.0)
    hd["Execute"] = False
    h.step()
    hd["Execute"] = True
    h.step(2)
    assert fb.CommandAborted and not fb.Busy and not fb.InSync
    assert h.s.StatusSynchronizedMotion.FunctionState == 0


def test_s7_1500_synchronization_exceeding_limits_only_flags():
    """§4.4.2: during synchronization/synchronous motion only MaxSpeed limits; exceeding the configured limits
    is shown in StatusSynchronizedMotion.StatusWord, no error."""
    h = H(sp=merge(VIRTUAL, {"DynamicLimits": {"MaxAcceleration": 50.0, "MaxDeceleration": 50.0}}))
    h.move_master(200.0)
    p0 = h.m.Position
    fb, d = _gip(h, MasterSyncPosition=p0 + 300.0, SlaveSyncPosition=0.0, SyncProfileReference=1,
                 MasterStartDistance=50.0)
    d["Execute"] = True
    h.until(lambda: fb.InSync or fb.Error, 4.0)
    assert fb.InSync and not fb.Error
    assert any(r["ssw"] & 0b110 for r in h.rows if r["StartSync"])
    assert h.s.ErrorWord == 0


@pytest.mark.parametrize("sync_direction,num", [(1, 1), (2, -1), (3, 1), (3, -1)])
@pytest.mark.parametrize("slave_start", [60.0, 350.0, 180.0])
def test_s7_1500_sync_direction_modulo_following_axis(sync_direction, num, slave_start):
    """§9.1.2.1 SyncDirection: 1 = the following axis may only travel in positive direction during
    synchronization; 2 = only negative; 3 = shortest (direction changes permitted)."""
    h = H(sp=merge(VIRTUAL, modulo(360.0)))
    home = MC_Home()
    h.call(home, {"Axis": h.s, "Execute": True, "Mode": 0, "Position": slave_start})
    h.until(lambda: home.Done, 1.0)
    h.move_master(100.0)
    p0 = h.m.Position
    msp, ssp = p0 + 200.0, 10.0
    fb, d = _gip(h, RatioNumerator=num, MasterSyncPosition=msp, SlaveSyncPosition=ssp, SyncProfileReference=1,
                 MasterStartDistance=100.0, SyncDirection=sync_direction)
    d["Execute"] = True
    h.until(lambda: fb.InSync or fb.Error, 5.0)
    assert fb.InSync, hex(fb.ErrorID)
    syncing = [r for r in h.rows if r["StartSync"] and not r["InSync"]]
    first = next(r for r in h.rows if r["InSync"])
    law = (ssp + num * (first["m"] - msp)) % 360.0
    assert (first["s"] - law + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-6)
    vs = [r["sv"] for r in syncing]
    if sync_direction == 1:
        assert min(vs) >= -1e-6, min(vs)
    elif sync_direction == 2:
        assert max(vs) <= 1e-6, max(vs)


def test_s7_1500_master_modulo_sync_position_next_occurrence():
    h = H(mp=merge(VIRTUAL, modulo(360.0)))
    h.move_master(100.0)
    h.until(lambda: 290.0 < h.m.Position < 300.0, 5.0)
    fb, d = _gip(h, MasterSyncPosition=100.0, SlaveSyncPosition=0.0, SyncProfileReference=1,
                 MasterStartDistance=50.0)
    d["Execute"] = True
    h.step()
    assert fb.Busy and not fb.Error
    h.until(lambda: fb.InSync, 5.0)
    r = next(r for r in h.rows if r["StartSync"])
    assert 50.0 <= r["m"] % 360.0 <= 50.0 + 0.4 + 1e-6
    r = next(r for r in h.rows if r["InSync"])
    assert 100.0 <= r["m"] % 360.0 <= 100.4 + 1e-6
    assert r["s"] == pytest.approx(r["m"] % 360.0 - 100.0, abs=1e-6)


@pytest.mark.parametrize("spr", [0, 1, 3])
def test_s7_1500_exact_at_sync_position_with_accelerating_master(spr):
    """§4.3.x: master dynamics changes during synchronization are superimposed; synchronism still exactly at
    the synchronous positions."""
    h = H()
    mv = MC_MoveVelocity()
    h.call(mv, {"Axis": h.m, "Execute": True, "Velocity": 400.0, "Acceleration": 150.0, "Deceleration": 150.0,
                "Jerk": 0.0})
    h.until(lambda: h.m.Velocity > 20.0, 2.0)
    p0 = h.m.Position
    msp, ssp = p0 + 300.0, -123.0
    fb, d = _gip(h, RatioNumerator=-5, RatioDenominator=3, MasterSyncPosition=msp, SlaveSyncPosition=ssp,
                 SyncProfileReference=spr, MasterStartDistance=150.0 if spr != 3 else 100.0, Velocity=600.0,
                 Acceleration=2000.0, Deceleration=2000.0, Jerk=0.0)
    d["Execute"] = True
    h.until(lambda: fb.InSync or fb.Error, 8.0)
    assert fb.InSync, hex(fb.ErrorID)
    h.run(0.1)
    first = next(r for r in h.rows if r["InSync"])
    sync_at = msp if spr != 3 else msp + 100.0
    for r in h.rows:
        if r["InSync"]:
            assert r["s"] == pytest.approx(ssp - 5 / 3 * (r["m"] - msp), abs=1e-6)
    # first recorded row at/after the synchronous master position: on the synchronous law already?
    at = next(r for r in h.rows if r["m"] >= sync_at)
    err = at["s"] - (ssp - 5 / 3 * (at["m"] - msp))
    assert sync_at <= first["m"] <= sync_at + 400.0 * 0.004 + 1e-6, \
        f"InSync first at master {first['m']:.3f}, synchronous position {sync_at:.3f}; " \
        f"slave off the law by {err:.4f} at master {at['m']:.3f}"
