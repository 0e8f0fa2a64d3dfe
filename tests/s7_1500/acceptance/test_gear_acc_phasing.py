"""MC_PhasingRelative / MC_PhasingAbsolute (S7-1500T V5 §4.5, §9.1.3, §9.1.4, §9.3.2)."""
import pytest
from plcmotion.s7_1500 import (MC_GearIn, MC_GearInPos, MC_Halt, MC_MoveSuperimposed, MC_PhasingAbsolute,
                               MC_PhasingRelative)
from _gear_h import H, outputs_consistent


def _geared(h, ratio=1, v=100.0, pos=False):
    if v:
        h.move_master(v)
    if pos:
        g = MC_GearInPos()
        p = h.m.Position
        h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": ratio,
                   "MasterSyncPosition": p + 60.0, "SlaveSyncPosition": 0.0, "SyncProfileReference": 1,
                   "MasterStartDistance": 50.0})
        h.until(lambda: g.InSync, 3.0)
    else:
        g = MC_GearIn()
        h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": ratio})
        h.until(lambda: g.InGear, 3.0)
    return g


def _phasing(h, cls, **inp):
    ph = cls()
    d = {"Master": h.m, "Slave": h.s, "Execute": False, "Velocity": 100.0, "Acceleration": 1000.0,
         "Deceleration": 1000.0, "Jerk": 0.0}
    d.update(inp)
    h.call(ph, d)
    return ph, d


def _rec(h, ph, g):
    prog = "CoveredPhaseShift" if "CoveredPhaseShift" in ph.OUTPUTS else "AbsolutePhaseShift"
    sm = h.s.StatusSynchronizedMotion
    h.rec = lambda: {"t": h.ctl.time, "m": h.m.Position, "mv": h.m.Velocity, "s": h.s.Position, "sv": h.s.Velocity,
                     "sa": h.s.Acceleration, "Busy": ph.Busy, "Done": ph.Done, "Abort": ph.CommandAborted,
                     "prog": getattr(ph, prog), "X24": h.s.StatusWord.X24, "ps": sm.PhaseShift,
                     "elv": sm.EffectiveLeadingValue.Position, "bad": outputs_consistent(ph),
                     "gbad": outputs_consistent(g)}


@pytest.mark.parametrize("ratio", [1, 2, -2])
def test_s7_1500_relative_dynamics_are_following_axis_dynamics_added_to_sync_motion(ratio):
    """§9.1.3.1: Velocity/Acceleration 'of the following axis for leading value shift (added to synchronous
    operation motion)'."""
    h = H()
    g = _geared(h, ratio=ratio)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=50.0, Velocity=40.0, Acceleration=400.0,
                     Deceleration=400.0)
    _rec(h, ph, g)
    off0 = h.s.Position - ratio * h.m.Position
    d["Execute"] = True
    h.step()
    assert ph.Busy and h.s.StatusWord.X24
    h.until(lambda: ph.Done, 5.0)
    rows = [r for r in h.rows if r["Busy"]]
    extra_v = [abs(r["sv"] - ratio * r["mv"]) for r in rows]
    assert max(extra_v) <= 40.0 + 1e-6
    assert max(extra_v) == pytest.approx(40.0, rel=1e-3)     # the velocity is actually used
    for r in h.rows:
        assert not r["bad"] and not r["gbad"], r
        assert r["X24"] == r["Busy"], r
    # effective leading value = leading value + phase shift (decisions #20), slave shifted by ratio*50
    assert h.s.Position - ratio * h.m.Position == pytest.approx(off0 + ratio * 50.0, abs=1e-6)
    assert h.s.StatusSynchronizedMotion.PhaseShift == pytest.approx(50.0)
    assert h.s.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(h.m.Position + 50.0)
    assert ph.CoveredPhaseShift == pytest.approx(50.0) and g.InGear


def test_s7_1500_relative_done_timing_trapezoid():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=50.0, Velocity=100.0, Acceleration=1000.0,
                     Deceleration=1000.0)
    _rec(h, ph, g)
    d["Execute"] = True
    h.until(lambda: ph.Done, 3.0)
    t0 = next(r["t"] for r in h.rows if r["Busy"])
    t1 = next(r["t"] for r in h.rows if r["Done"])
    assert t1 - t0 == pytest.approx(0.6, abs=0.012)
    progs = [r["prog"] for r in h.rows if r["Busy"]]
    assert progs == sorted(progs) and progs[0] < 50.0


def test_s7_1500_phasing_at_master_standstill_moves_following_axis():
    """The shift acts on the effective leading value; with the leading axis at rest the following axis moves."""
    h = H()
    g = _geared(h, ratio=2, v=0.0)
    s0 = h.s.Position
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=-30.0)
    _rec(h, ph, g)
    d["Execute"] = True
    h.until(lambda: ph.Done, 3.0)
    assert h.s.Position == pytest.approx(s0 - 60.0, abs=1e-6)


def test_s7_1500_absolute_from_existing_shift():
    h = H()
    g = _geared(h, pos=True)
    ph, d = _phasing(h, MC_PhasingAbsolute, PhaseShift=50.0)
    _rec(h, ph, g)
    d["Execute"] = True
    h.until(lambda: ph.Done, 3.0)
    assert ph.AbsolutePhaseShift == pytest.approx(50.0)
    d["Execute"] = False
    h.step()
    d.update(Execute=True, PhaseShift=-20.0)
    n = len(h.rows)
    h.step()
    assert ph.Busy and not ph.Done
    h.until(lambda: ph.Done, 3.0)
    assert h.s.StatusSynchronizedMotion.PhaseShift == pytest.approx(-20.0)
    assert ph.AbsolutePhaseShift == pytest.approx(-20.0)
    progs = [r["prog"] for r in h.rows[n:] if r["Busy"]]
    assert progs == sorted(progs, reverse=True)
    assert all(-20.0 - 1e-9 <= p <= 50.0 + 1e-9 for p in progs)


def test_s7_1500_new_phasing_aborts_running_phasing():
    h = H()
    g = _geared(h)
    p1, d1 = _phasing(h, MC_PhasingRelative, PhaseShift=100.0, Velocity=20.0)
    p2, d2 = _phasing(h, MC_PhasingRelative, PhaseShift=10.0)
    _rec(h, p1, g)
    d1["Execute"] = True
    h.run(0.3)
    assert p1.Busy
    covered = p1.CoveredPhaseShift
    assert 0.0 < covered < 100.0
    d2["Execute"] = True
    h.step(2)
    assert p1.CommandAborted and not p1.Busy and not p1.Done
    assert p2.Busy and g.InGear and g.Busy and not g.CommandAborted
    h.until(lambda: p2.Done, 3.0)
    ps = h.s.StatusSynchronizedMotion.PhaseShift
    assert covered < ps < covered + 10.0 + 5.0     # relative to the shift in force when p2 started
    assert not h.s.StatusWord.X24


def test_s7_1500_superimposed_does_not_abort_phasing():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=50.0, Velocity=20.0)
    sup = MC_MoveSuperimposed()
    sd = h.call(sup, {"Axis": h.s, "Execute": False, "Distance": 5.0})
    d["Execute"] = True
    h.step(5)
    sd["Execute"] = True
    h.until(lambda: sup.Done, 3.0)
    assert ph.Busy and not ph.CommandAborted
    h.until(lambda: ph.Done, 5.0)


def test_s7_1500_halt_aborts_phasing_and_gearing_and_resets_shift():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=100.0, Velocity=20.0)
    d["Execute"] = True
    h.run(0.2)
    halt = MC_Halt()
    h.call(halt, {"Axis": h.s, "Execute": True})
    h.step(2)
    assert ph.CommandAborted and not ph.Busy
    assert g.CommandAborted and not g.Busy
    assert h.s.StatusSynchronizedMotion.PhaseShift == 0.0
    assert not h.s.StatusWord.X24


def test_s7_1500_new_gear_in_aborts_phasing_and_resets_shift():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=100.0, Velocity=20.0)
    d["Execute"] = True
    h.run(0.2)
    g2 = MC_GearIn()
    h.call(g2, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 1})
    h.step(2)
    assert ph.CommandAborted and g.CommandAborted and g2.Busy
    assert h.s.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_waiting_gear_in_pos_does_not_abort_phasing_active_one_does():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=1000.0, Velocity=10.0)
    d["Execute"] = True
    h.step(3)
    gp = MC_GearInPos()
    p = h.m.Position
    h.call(gp, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 100.0,
                "SyncProfileReference": 1, "MasterStartDistance": 50.0})
    h.step(3)
    assert gp.Busy and not gp.StartSync
    assert ph.Busy and not ph.CommandAborted and g.InGear
    h.until(lambda: gp.StartSync, 3.0)
    h.step()
    assert ph.CommandAborted and g.CommandAborted
    assert h.s.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_disabling_master_does_not_abort_phasing():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=30.0, Velocity=20.0)
    d["Execute"] = True
    h.step(3)
    h.en["M1"] = False
    h.until(lambda: ph.Done or ph.CommandAborted or ph.Error, 5.0)
    assert ph.Done and g.InGear
    assert h.s.StatusSynchronizedMotion.PhaseShift == pytest.approx(30.0)


def test_s7_1500_phase_shift_reset_after_gearing_overridden_by_halt_done():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=20.0)
    d["Execute"] = True
    h.until(lambda: ph.Done, 3.0)
    assert h.s.StatusSynchronizedMotion.PhaseShift == pytest.approx(20.0)
    halt = MC_Halt()
    h.call(halt, {"Axis": h.s, "Execute": True})
    h.step(2)
    assert g.CommandAborted
    assert h.s.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_relative_zero_shift_completes():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=0.0)
    d["Execute"] = True
    h.until(lambda: ph.Done or ph.Error, 1.0)
    assert ph.Done and ph.CoveredPhaseShift == 0.0


def test_s7_1500_done_output_latched_while_execute_and_pulse_otherwise():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=5.0)
    d["Execute"] = True
    h.step()
    d["Execute"] = False
    h.until(lambda: ph.Done, 2.0)
    h.step()
    assert not ph.Done and not ph.Busy


def test_s7_1500_disable_slave_aborts_phasing_and_gearing():
    h = H()
    g = _geared(h)
    ph, d = _phasing(h, MC_PhasingRelative, PhaseShift=100.0, Velocity=20.0)
    d["Execute"] = True
    h.step(3)
    h.en["S1"] = False
    h.run(0.2)
    assert not ph.Busy and ph.CommandAborted and not ph.Error
    assert not g.Busy and g.CommandAborted
    assert not h.s.StatusWord.X24 and h.s.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_phasing_on_gear_in_pos_law_shifted():
    """Slave = SlaveSyncPosition + ratio * (master + PhaseShift - MasterSyncPosition) (decisions #20)."""
    h = H()
    h.move_master(100.0)
    g = MC_GearInPos()
    p = h.m.Position
    msp = p + 60.0
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 3, "RatioDenominator": 2,
               "MasterSyncPosition": msp, "SlaveSyncPosition": 7.0, "MasterStartDistance": 50.0})
    h.until(lambda: g.InSync, 3.0)
    ph, d = _phasing(h, MC_PhasingAbsolute, PhaseShift=-25.0)
    d["Execute"] = True
    h.until(lambda: ph.Done, 3.0)
    h.run(0.1)
    assert h.s.Position == pytest.approx(7.0 + 1.5 * (h.m.Position - 25.0 - msp), abs=1e-6)
    assert g.InSync and g.Busy
