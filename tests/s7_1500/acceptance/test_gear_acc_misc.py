"""Monitoring during gearing (S7-1500T V5 §4.4.1, §4.4.2, §6.1.5.4), other leading value sources, output latching,
single-axis motion before gearing."""
import pytest
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_Home, MC_MoveVelocity
from _gear_h import H, VIRTUAL, merge, outputs_consistent

SW = {"PositionLimits_SW": {"Active": True, "MaxPosition": 200.0, "MinPosition": -1000.0}}


def _homed_slave(h):
    hm = MC_Home()
    h.call(hm, {"Axis": h.s, "Execute": True, "Mode": 0, "Position": 0.0})
    h.until(lambda: hm.Done, 1.0)
    assert h.s.StatusWord.X5


@pytest.mark.parametrize("which", ["gear_in", "gear_in_pos"])
def test_s7_1500_sw_limit_switch_monitored_during_gearing(which):
    """§4.4.1/§4.4.2: 'The SW limit switches continue to be monitored with the configured dynamic limits of the
    following axis.'  §6.1.5.4: with active SW limit switches an active motion comes to a stop at the
    position of the SW limit switch and the technology object signals an error (ErrorWord.X8)."""
    h = H(sp=merge(VIRTUAL, SW))
    _homed_slave(h)
    h.move_master(100.0)
    if which == "gear_in":
        fb = MC_GearIn()
        h.call(fb, {"Master": h.m, "Slave": h.s, "Execute": True})
    else:
        fb = MC_GearInPos()
        p = h.m.Position
        h.call(fb, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 50.0,
                    "SlaveSyncPosition": 10.0, "MasterStartDistance": 20.0})
    h.run(3.5)            # the synchronous law would take the slave to ~300
    assert h.s.ErrorWord.X8, "no SW limit switch error"
    assert h.s.Position <= 200.0 + 1e-6, h.s.Position
    assert not fb.Busy and (fb.Error or fb.CommandAborted)


def test_s7_1500_gear_in_from_external_encoder_master():
    """§9.1.1.1: the leading axis may be an external encoder (actual value coupling, S7-1500T)."""
    from plcmotion import Controller
    from plcmotion.s7_1500 import MC_Power
    ctl = Controller(family="S7-1500T")
    enc = ctl.add_external_encoder("E", {"Plant": {"Velocity": 200.0}})
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("E", "actual")])
    pw, pe, g = MC_Power(), MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        pe(Axis=enc, Enable=True)
        pw(Axis=s, Enable=True)
        g(Master=enc, Slave=s, Execute=pw.Status, RatioNumerator=1, RatioDenominator=2)
    ctl.run_until(lambda: enc.ActualVelocity > 100.0, timeout=5.0)
    ctl.run_until(lambda: g.InGear or g.Error, timeout=5.0)
    assert g.InGear, hex(g.ErrorID)
    ctl.run(0.3)
    assert s.Velocity == pytest.approx(100.0, rel=1e-3)
    assert s.StatusSynchronizedMotion.ActualMaster == enc.db_number


def test_s7_1500_error_latched_while_execute_then_cleared():
    h = H()
    fb = MC_GearIn()
    d = h.call(fb, {"Master": h.m, "Slave": h.s, "Execute": False, "RatioDenominator": 0})
    h.until(h.enabled, 1.0)
    d["Execute"] = True
    h.step(5)
    assert fb.Error and fb.ErrorID == 0x8018 and not fb.Busy
    d["Execute"] = False
    h.step()
    assert not fb.Error and fb.ErrorID == 0


def test_s7_1500_command_aborted_pulse_when_execute_false():
    h = H()
    h.move_master(100.0)
    g = MC_GearIn()
    d = h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.step()
    d["Execute"] = False
    h.until(lambda: g.InGear, 3.0)
    g2 = MC_GearIn()
    h.call(g2, {"Master": h.m, "Slave": h.s, "Execute": True, "RatioNumerator": 2})
    h.until(lambda: g.CommandAborted, 1.0)
    assert not g.Busy and not g.InGear
    h.step()
    assert not g.CommandAborted    # shown for exactly one call with Execute FALSE


def test_s7_1500_gear_in_takes_over_running_move_velocity_smoothly():
    """§4.3.1: synchronization starts from the dynamics of the following axis at the start time; MC_GearIn
    aborts the running MC_MoveVelocity (§9.3.1 part 2)."""
    h = H()
    h.move_master(100.0)
    mv = MC_MoveVelocity()
    h.call(mv, {"Axis": h.s, "Execute": True, "Velocity": -300.0, "Acceleration": 1000.0, "Deceleration": 1000.0,
                "Jerk": 0.0})
    h.until(lambda: mv.InVelocity, 2.0)
    g = MC_GearIn()
    d = h.call(g, {"Master": h.m, "Slave": h.s, "Execute": False, "Acceleration": 800.0, "Deceleration": 800.0,
                   "Jerk": 0.0})
    h.rec = lambda: {"sv": h.s.Velocity, "sa": h.s.Acceleration, "in": g.InGear, "bad": outputs_consistent(g)}
    d["Execute"] = True
    h.step(2)
    assert mv.CommandAborted and g.Busy
    h.until(lambda: g.InGear, 3.0)
    sv = [r["sv"] for r in h.rows]
    assert sv[0] == pytest.approx(-300.0, abs=800 * 0.004 + 1e-6)
    assert max(abs(b - a) for a, b in zip(sv, sv[1:])) <= 800.0 * 0.004 + 1e-6
    assert max(abs(r["sa"]) for r in h.rows if not r["in"]) <= 800.0 + 1e-6
    assert all(not r["bad"] for r in h.rows)


def test_s7_1500_gear_in_pos_spr1_from_moving_slave_exact():
    h = H()
    h.move_master(100.0)
    mv = MC_MoveVelocity()
    h.call(mv, {"Axis": h.s, "Execute": True, "Velocity": 40.0})
    h.until(lambda: mv.InVelocity, 2.0)
    p = h.m.Position
    g = MC_GearInPos()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 300.0,
               "SlaveSyncPosition": 500.0, "MasterStartDistance": 150.0, "RatioNumerator": 2})
    h.step(3)
    assert g.Busy and not g.StartSync and mv.Busy and not mv.CommandAborted
    rows = []
    h.rec = lambda: rows.append((float(h.ctl.bank.sp_p[h.m.index]), float(h.ctl.bank.sp_p[h.s.index]),
                                 h.s.Velocity, g.StartSync, g.InSync)) or {}
    h.until(lambda: g.InSync, 5.0)
    assert mv.CommandAborted
    vs = [r[2] for r in rows]
    assert max(abs(b - a) for a, b in zip(vs, vs[1:])) < 20.0      # no velocity jump at StartSync
    m, s = next((r[0], r[1]) for r in rows if r[4])
    assert s == pytest.approx(500.0 + 2 * (m - (p + 300.0)), abs=1e-6)
