"""S7-1500T V5 §3.3.1-§3.3.3, §3.3.5, §6.1.3, §8.1.3/§8.1.4: coupling types, chains, cycles,
non-position-controlled leading axes, external encoder as a leading value source."""
import pytest

from plcmotion import Controller
from plcmotion.crossplc import LocalLink
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_MoveVelocity, MC_Power

from _lh import VIRTUAL, check_error_outputs, encoder_rig

DRIVE = {"Actor": {"Type": 1}}


def test_s7_1500_delayed_coupling_uses_the_setpoint_of_delay_time_ago_s3_3_3():
    """Delayed coupling: the local followers get the leading value delayed by
    CrossPlcSynchronousOperation.LocalLeadingValueDelayTime (shown in StatusProvidedLeadingValue)."""
    D = 0.008
    ctl = Controller(family="S7-1500T", app_cycle=0.001)
    m = ctl.add_positioning_axis("M", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": D}})
    sd = ctl.add_synchronous_axis("SD", VIRTUAL, leading_values=[("M", "delayed")])
    ss = ctl.add_synchronous_axis("SS", VIRTUAL, leading_values=[("M", "setpoint")])
    m.provide_leading_value(LocalLink())
    pw = [MC_Power() for _ in range(3)]
    mv, gd, gs = MC_MoveVelocity(), MC_GearIn(), MC_GearIn()
    hist = {}

    @ctl.program
    def main():
        for p, ax in zip(pw, (m, sd, ss)):
            p(Axis=ax, Enable=True)
        mv(Axis=m, Execute=pw[0].Status, Velocity=100.0, Acceleration=500.0, Jerk=0.0)
        gd(Master=m, Slave=sd, Execute=pw[1].Status)
        gs(Master=m, Slave=ss, Execute=pw[2].Status)
    while ctl.time < 0.3:
        ctl.step()
        hist[round(ctl.time, 6)] = m.Position
        if ctl.time > 0.05 and gd.InGear:
            want = hist[round(ctl.time - D, 6)]
            assert sd.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(want, abs=1e-9)
            assert m.StatusProvidedLeadingValue.DelayedLeadingValue.Position == pytest.approx(want, abs=1e-9)
            assert ss.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(m.Position, abs=1e-9)
    assert gd.InGear and gs.InGear


def test_s7_1500_external_encoder_delayed_coupling_is_delayed_s3_3_3():
    """§3.3.3: the leading value of an external encoder can be delayed ("Delayed" coupling).  At constant
    velocity the delayed follower lags the actual-value follower by v * LocalLeadingValueDelayTime."""
    D, v = 0.008, 100.0
    ctl, enc, (sa, sd), gears, _ = encoder_rig(
        {"Settings": {"SystemDefinedExtrapolation": 0}}, plant={"Velocity": v},
        extra={"CrossPlcSynchronousOperation": {"LocalLeadingValueDelayTime": D}},
        followers=(("SA", "actual"), ("SD", "delayed")))
    ctl.run_until(lambda: all(g.InGear for g in gears) or any(g.Error for g in gears), timeout=2.0)
    check_error_outputs(*gears)
    assert all(g.InGear for g in gears), [hex(g.ErrorID) for g in gears]
    ctl.run(0.5)
    lag = sa.StatusSynchronizedMotion.EffectiveLeadingValue.Position - sd.StatusSynchronizedMotion.EffectiveLeadingValue.Position
    assert lag == pytest.approx(v * D, abs=0.01)


def test_s7_1500_external_encoder_provides_a_cross_plc_leading_value_s8_1_3():
    """§8.1.3: a positioning axis, external encoder or synchronous axis can be the leading axis on CPU 1;
    §8.1.4 lists CrossPlcSynchronousOperation.* and StatusProvidedLeadingValue.* for the external encoder."""
    ctl, enc, _, gears, _ = encoder_rig(
        plant={"Velocity": 100.0},
        extra={"CrossPlcSynchronousOperation": {"Interface[1]": {"EnableLeadingValueOutput": True},
                                                "LocalLeadingValueDelayTime": 0.008}})
    assert hasattr(enc, "provide_leading_value"), "TO_ExternalEncoder cannot provide a cross-PLC leading value"
    enc.provide_leading_value(LocalLink())
    ctl.run(0.2)
    assert enc.tag("StatusProvidedLeadingValue.DelayedLeadingValue.Velocity") == pytest.approx(100.0, rel=0.05)


def test_s7_1500_external_encoder_status_provided_leading_value_tag_exists_s8_1_4():
    ctl, enc, _, gears, _ = encoder_rig(plant={"Velocity": 100.0})
    ctl.run(0.05)
    enc.tag("StatusProvidedLeadingValue.DelayedLeadingValue.Position")


def test_s7_1500_external_encoder_cannot_be_setpoint_coupled_s3_3_1():
    """§3.3.1: setpoint coupling is possible for positioning axis, synchronous axis, proxy - not for an
    external encoder (it has no setpoint)."""
    ctl, enc, _, gears, _ = encoder_rig(plant={"Velocity": 100.0}, followers=(("S", "setpoint"),))
    ctl.run_until(lambda: gears[0].Error or gears[0].InGear, timeout=1.0)
    assert gears[0].Error and gears[0].ErrorID != 0


def test_s7_1500_proxy_cannot_be_actual_value_coupled_s3_3_2():
    ctl = Controller(family="S7-1500T")
    proxy = ctl.add_leading_axis_proxy("P", {}, source_link=LocalLink())
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("P", "actual")])
    ps, g = MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        ps(Axis=s, Enable=True)
        g(Master=proxy, Slave=s, Execute=ps.Status)
    ctl.run_until(lambda: g.Error or g.InGear, timeout=1.0)
    assert g.Error and g.ErrorID != 0


def _non_pc_rig(mode):
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", DRIVE)
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("M", mode)])
    pm, ps, mv, g = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn()
    st = {"go": False, "pc": False, "mv": True}

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=st["mv"] and pm.Status, Velocity=100.0, PositionControlled=st["pc"])
        g(Master=m, Slave=s, Execute=st["go"])
    return ctl, m, s, mv, g, st


def test_s7_1500_actual_value_coupling_starts_with_a_non_position_controlled_leading_axis_s3_3_5():
    ctl, m, s, mv, g, st = _non_pc_rig("actual")
    ctl.run_until(lambda: mv.InVelocity, timeout=2.0)
    assert m.StatusWord.NonPositionControlled
    st["go"] = True
    ctl.run_until(lambda: g.InGear, timeout=1.0)
    ctl.run(0.2)
    assert s.Velocity == pytest.approx(100.0, rel=0.02)


def test_s7_1500_setpoint_coupling_waits_for_a_non_position_controlled_leading_axis_s3_3_5():
    ctl, m, s, mv, g, st = _non_pc_rig("setpoint")
    ctl.run_until(lambda: mv.InVelocity, timeout=2.0)
    st["go"] = True
    ctl.run(0.2)
    assert g.Busy and not g.InGear and not g.Error and s.StatusSynchronizedMotion.FunctionState == 0
    assert s.Velocity == 0.0


def test_s7_1500_actual_value_coupling_stays_when_leading_axis_becomes_non_position_controlled_s3_3_5():
    ctl, m, s, mv, g, st = _non_pc_rig("actual")
    st["pc"] = True
    ctl.run_until(lambda: mv.InVelocity, timeout=2.0)
    st["go"] = True
    ctl.run_until(lambda: g.InGear, timeout=1.0)
    st["mv"], st["pc"] = False, False
    ctl.step()
    st["mv"] = True                       # new MC_MoveVelocity with PositionControlled = FALSE
    ctl.run(0.3)
    assert m.StatusWord.NonPositionControlled
    assert g.InGear and not g.CommandAborted and not g.Error
    assert s.Velocity == pytest.approx(100.0, rel=0.02)


def test_s7_1500_chain_evaluated_in_one_cycle_independent_of_creation_order_s3_3():
    """A following axis that leads another one: S2 (created first) sees S1's setpoint of the same cycle."""
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s2 = ctl.add_synchronous_axis("S2", VIRTUAL, leading_values=["S1"])
    s1 = ctl.add_synchronous_axis("S1", VIRTUAL, leading_values=["M"])
    s3 = ctl.add_synchronous_axis("S3", VIRTUAL, leading_values=["S2"])
    pw = [MC_Power() for _ in range(4)]
    mv, g1, g2, g3 = MC_MoveVelocity(), MC_GearIn(), MC_GearIn(), MC_GearIn()

    @ctl.program
    def main():
        for p, ax in zip(pw, (m, s1, s2, s3)):
            p(Axis=ax, Enable=True)
        mv(Axis=m, Execute=pw[0].Status, Velocity=50.0, Acceleration=200.0, Jerk=0.0)
        g1(Master=m, Slave=s1, Execute=pw[1].Status, RatioNumerator=2)
        g2(Master=s1, Slave=s2, Execute=pw[2].Status, RatioNumerator=3)
        g3(Master=s2, Slave=s3, Execute=pw[3].Status, RatioNumerator=-1)
    ctl.run_until(lambda: g1.InGear and g2.InGear and g3.InGear, timeout=5.0)
    p1, p2, p3 = s1.Position, s2.Position, s3.Position
    x0 = m.Position
    for _ in range(20):
        ctl.step()          # master still accelerating for a while: a one-cycle lag would show
        dx = m.Position - x0
        assert s1.Position - p1 == pytest.approx(2 * dx, abs=1e-9)
        assert s2.Position - p2 == pytest.approx(6 * dx, abs=1e-9)
        assert s3.Position - p3 == pytest.approx(-6 * dx, abs=1e-9)


def test_s7_1500_three_axis_cycle_rejected_s8_1_3():
    ctl = Controller(family="S7-1500T")
    a = ctl.add_synchronous_axis("A", VIRTUAL, leading_values=["C"])
    b = ctl.add_synchronous_axis("B", VIRTUAL, leading_values=["A"])
    c = ctl.add_synchronous_axis("C", VIRTUAL, leading_values=["B"])
    pw = [MC_Power() for _ in range(3)]
    ga, gb, gc = MC_GearIn(), MC_GearIn(), MC_GearIn()

    @ctl.program
    def main():
        for p, ax in zip(pw, (a, b, c)):
            p(Axis=ax, Enable=True)
        ok = all(p.Status for p in pw)
        gb(Master=a, Slave=b, Execute=ok)
        gc(Master=b, Slave=c, Execute=ok)
        ga(Master=c, Slave=a, Execute=gb.InGear and gc.InGear)
    ctl.run_until(lambda: ga.Error or ga.InGear, timeout=2.0)
    assert ga.Error and ga.ErrorID == 0x8019 and gb.InGear and gc.InGear


def test_s7_1500_waiting_gearinpos_cycle_rejected_s8_1_3():
    """A cycle closed by a waiting GearInPos is also a recursion that would become effective."""
    ctl = Controller(family="S7-1500T")
    a = ctl.add_synchronous_axis("A", VIRTUAL, leading_values=["B"])
    b = ctl.add_synchronous_axis("B", VIRTUAL, leading_values=["A"])
    pa, pb, ga, gb = MC_Power(), MC_Power(), MC_GearInPos(), MC_GearIn()

    @ctl.program
    def main():
        pa(Axis=a, Enable=True)
        pb(Axis=b, Enable=True)
        ga(Master=b, Slave=a, Execute=pa.Status and pb.Status, MasterSyncPosition=100.0, SlaveSyncPosition=0.0,
           MasterStartDistance=10.0)
        gb(Master=a, Slave=b, Execute=ga.Busy)
    ctl.run_until(lambda: gb.Error or gb.InGear, timeout=2.0)
    assert gb.Error and gb.ErrorID == 0x8019


def test_s7_1500_actual_value_coupling_to_a_virtual_positioning_axis_s3_3_2():
    """§3.3.2 lists positioning axis and synchronous axis without exception; a virtual axis has actual
    values (they equal its setpoints)."""
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("M", "actual")])
    pm, ps, mv, g = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn()

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=100.0)
        g(Master=m, Slave=s, Execute=ps.Status)
    ctl.run_until(lambda: g.InGear or g.Error, timeout=2.0)
    check_error_outputs(g)
    assert g.InGear, hex(g.ErrorID)


def test_s7_1500_actual_value_coupling_to_a_simulated_drive_axis_s3_3_2():
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", {"Actor": {"Type": 1}, "Simulation": {"Mode": 1}})
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("M", "actual")])
    pm, ps, mv, g = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn()

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=100.0)
        g(Master=m, Slave=s, Execute=ps.Status)
    ctl.run_until(lambda: g.InGear or g.Error, timeout=2.0)
    check_error_outputs(g)
    assert g.InGear, hex(g.ErrorID)
