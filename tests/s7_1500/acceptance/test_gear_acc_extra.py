"""More gearing corner cases from the text of the S7-1500T V5 manual."""
import pytest
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_Halt, MC_Home, MC_PhasingRelative
from _gear_h import H, VIRTUAL, merge, modulo


def test_s7_1500_cascade_master_slave_slave():
    """§9.1.1.1: the leading axis may be a synchronous axis."""
    from plcmotion import Controller
    from plcmotion.s7_1500 import MC_Power, MC_MoveVelocity
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s1 = ctl.add_synchronous_axis("S1", VIRTUAL, leading_values=["M", "S2"])
    s2 = ctl.add_synchronous_axis("S2", VIRTUAL, leading_values=["S1"])
    pw = [MC_Power() for _ in range(3)]
    mv, g1, g2, g3 = MC_MoveVelocity(), MC_GearIn(), MC_GearIn(), MC_GearIn()
    st = {"g3": False}

    @ctl.program
    def main():
        for p, a in zip(pw, (m, s1, s2)):
            p(Axis=a, Enable=True)
        ok = all(p.Status for p in pw)
        mv(Axis=m, Execute=ok, Velocity=60.0)
        g1(Master=m, Slave=s1, Execute=ok, RatioNumerator=2)
        g2(Master=s1, Slave=s2, Execute=ok, RatioNumerator=1, RatioDenominator=2)
        g3(Master=s2, Slave=s1, Execute=st["g3"])
    ctl.run_until(lambda: g1.InGear and g2.InGear, timeout=5.0)
    ctl.run(0.1)
    assert s2.Velocity == pytest.approx(60.0, abs=1e-6)
    st["g3"] = True
    ctl.run(0.02)
    assert g3.Error and g3.ErrorID != 0          # coupling cycle rejected
    assert g1.InGear and g2.InGear


def test_s7_1500_spr3_master_standing_at_master_sync_position():
    """§4.3.4: 'Synchronization begins as soon as the leading value has reached the synchronous position'."""
    h = H()
    g = MC_GearInPos()
    d = h.call(g, {"Master": h.m, "Slave": h.s, "Execute": False, "MasterSyncPosition": 0.0,
                   "SlaveSyncPosition": 0.0, "SyncProfileReference": 3, "MasterStartDistance": 100.0})
    h.until(h.enabled, 1.0)
    d["Execute"] = True
    h.step(3)
    print("SPR3 at MasterSyncPosition, master at rest:", g.outputs, h.s.StatusSynchronizedMotion.WaitingFunctionState)
    assert g.Busy and not g.Error
    h.move_master(50.0)
    h.until(lambda: g.InSync, 4.0)
    assert h.s.Position == pytest.approx(h.m.Position, abs=1e-6)


def test_s7_1500_master_modulo_start_distance_larger_than_modulo_length():
    h = H(mp=merge(VIRTUAL, modulo(360.0)))
    h.move_master(200.0)
    g = MC_GearInPos()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": 100.0, "SlaveSyncPosition": 0.0,
               "SyncProfileReference": 1, "MasterStartDistance": 500.0})
    rows = []
    h.rec = lambda: rows.append((float(h.ctl.bank.sp_p[h.m.index]), h.m.Position, h.s.Position, g.StartSync,
                                 g.InSync, g.Error)) or {}
    h.until(lambda: g.InSync or g.Error, 8.0)
    assert g.InSync, hex(g.ErrorID)
    st = next(r for r in rows if r[3])
    sy = next(r for r in rows if r[4])
    assert sy[0] - st[0] == pytest.approx(500.0, abs=1.0)      # synchronization over 500 of master travel
    assert 100.0 <= sy[1] <= 101.0
    assert sy[2] == pytest.approx(sy[1] - 100.0, abs=1e-6)


def test_s7_1500_sync_direction_ignored_on_linear_slave():
    """SyncDirection is 'in effect for axes with activated Modulo setting' only."""
    h = H()
    hm = MC_Home()
    h.call(hm, {"Axis": h.s, "Execute": True, "Mode": 0, "Position": 500.0})
    h.until(lambda: hm.Done, 1.0)
    h.move_master(100.0)
    p = h.m.Position
    g = MC_GearInPos()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 200.0,
               "SlaveSyncPosition": 0.0, "SyncProfileReference": 1, "MasterStartDistance": 100.0, "SyncDirection": 1})
    h.until(lambda: g.InSync or g.Error, 5.0)
    assert g.InSync and h.s.Position == pytest.approx(h.m.Position - (p + 200.0), abs=0.5)


def test_s7_1500_sync_status_bits_cleared_after_override():
    h = H(sp=merge(VIRTUAL, {"DynamicLimits": {"MaxVelocity": 150.0, "Velocity": 150.0},
                             "DynamicDefaults": {"Velocity": 100.0}}))
    h.move_master(100.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 2})
    h.until(lambda: g.InGear, 3.0)
    assert h.s.StatusSynchronizedMotion.StatusWord.X0
    halt = MC_Halt()
    h.call(halt, {"Axis": h.s, "Execute": True, "Deceleration": 5000.0})
    h.until(lambda: halt.Done, 3.0)
    assert int(h.s.StatusSynchronizedMotion.StatusWord) & 0b111 == 0


def test_s7_1500_phasing_jerk_limited_extra_dynamics():
    h = H()
    h.move_master(100.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 2})
    h.until(lambda: g.InGear, 3.0)
    ph = MC_PhasingRelative()
    d = h.call(ph, {"Master": h.m, "Slave": h.s, "Execute": True, "PhaseShift": 40.0, "Velocity": 60.0,
                    "Acceleration": 300.0, "Deceleration": 300.0, "Jerk": 3000.0})
    rows = []
    h.rec = lambda: rows.append((h.s.Velocity - 2 * h.m.Velocity, h.s.Acceleration - 2 * h.m.Acceleration)) or {}
    h.until(lambda: ph.Done, 5.0)
    assert max(abs(r[0]) for r in rows) <= 60.0 + 1e-6
    assert max(abs(r[1]) for r in rows) <= 300.0 + 1e-6
    assert h.s.StatusSynchronizedMotion.PhaseShift == pytest.approx(40.0)


@pytest.mark.parametrize("num", [1, -2])
def test_s7_1500_gear_in_modulo_master_wrap_no_jump(num):
    h = H(mp=merge(VIRTUAL, modulo(360.0)))
    h.move_master(300.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": num})
    h.until(lambda: g.InGear, 3.0)
    rows = []
    h.rec = lambda: rows.append((h.m.Position, h.s.Position, h.s.Velocity)) or {}
    h.run(2.0)
    assert any(b[0] < a[0] for a, b in zip(rows, rows[1:]))          # the master wrapped
    ds = [b[1] - a[1] for a, b in zip(rows, rows[1:])]
    assert all(d == pytest.approx(num * 300.0 * 0.004, abs=1e-6) for d in ds)
