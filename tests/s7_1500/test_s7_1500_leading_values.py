"""Leading value coupling (S7-1500T V5 §3.3, §8): setpoint, actual value (extrapolation), delayed and
cross-PLC coupling; chains of couplings; cycles rejected; non-position-controlled leading axes."""
import threading
import time

import pytest

from plcmotion import Controller
from plcmotion.crossplc import LocalLink
from plcmotion.s7_1500 import (MC_GearIn, MC_GearInPos, MC_MoveVelocity, MC_Power, MC_Reset)

from _s7_1500_rig import VIRTUAL, Rig


def test_s7_1500_chain_master_slave_slave_in_one_servo_cycle_s3_3():
    """A following axis that leads another one is interpolated first: the second follower sees the
    first one's setpoint of the same servo cycle (no cycle of delay along the chain)."""
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s1 = ctl.add_synchronous_axis("S1", VIRTUAL, leading_values=["M"])
    s2 = ctl.add_synchronous_axis("S2", VIRTUAL, leading_values=["S1"])
    power = [MC_Power() for _ in range(3)]
    mv, g1, g2 = MC_MoveVelocity(), MC_GearInPos(), MC_GearInPos()

    @ctl.program
    def main():
        for p, ax in zip(power, (m, s1, s2)):
            p(Axis=ax, Enable=True)
        mv(Axis=m, Execute=power[0].Status, Velocity=50.0)
        g1(Master=m, Slave=s1, Execute=power[1].Status, RatioNumerator=2, MasterSyncPosition=40.0,
           SlaveSyncPosition=0.0, MasterStartDistance=20.0)
        g2(Master=s1, Slave=s2, Execute=power[2].Status, RatioNumerator=-1, MasterSyncPosition=40.0,
           SlaveSyncPosition=10.0, MasterStartDistance=30.0)
    ctl.run_until(lambda: g2.InSync, timeout=10.0)
    for _ in range(30):
        ctl.run(0.013)
        mp = ctl.bank.sp_p[m.index]
        assert ctl.bank.sp_p[s1.index] == pytest.approx(2 * (mp - 40.0), abs=1e-9)
        assert ctl.bank.sp_p[s2.index] == pytest.approx(10.0 - (ctl.bank.sp_p[s1.index] - 40.0), abs=1e-9)


def test_s7_1500_a_cycle_of_couplings_is_rejected_s8_1_3():
    ctl = Controller(family="S7-1500T")
    a = ctl.add_synchronous_axis("A", VIRTUAL, leading_values=["B"])
    b = ctl.add_synchronous_axis("B", VIRTUAL, leading_values=["A"])
    pa, pb, ga, gb = MC_Power(), MC_Power(), MC_GearIn(), MC_GearIn()

    @ctl.program
    def main():
        pa(Axis=a, Enable=True)
        pb(Axis=b, Enable=True)
        ga(Master=b, Slave=a, Execute=pa.Status and pb.Status)
        gb(Master=a, Slave=b, Execute=ga.InGear)
    ctl.run_until(lambda: gb.Error or gb.InGear, timeout=2.0)
    assert gb.Error and gb.ErrorID == 0x8019 and ga.InGear


def test_s7_1500_master_not_configured_sets_synchronous_error_s3_3():
    rig = Rig(masters=2)
    other = rig.ctl.add_positioning_axis("Other", VIRTUAL)
    gear = MC_GearIn()
    reset = MC_Reset()
    go = {"reset": False}
    rig.steps.append(lambda: gear(Master=other, Slave=rig.slave, Execute=rig.enabled()))
    rig.steps.append(lambda: reset(Axis=rig.slave, Execute=go["reset"]))
    rig.run_until(lambda: gear.Error, timeout=1.0)
    assert gear.ErrorID == 0x8001
    assert rig.slave.ErrorWord.X14 and rig.slave.ErrorWord.SynchronousError
    assert rig.slave.StatusWord.Error
    go["reset"] = True
    rig.run_until(lambda: reset.Done, timeout=1.0)
    assert not rig.slave.ErrorWord.X14


def test_s7_1500_setpoint_coupling_waits_for_a_position_controlled_leading_axis_s3_3_5():
    rig = Rig()
    rig.enable["Master1"] = False
    gear = MC_GearIn()
    rig.steps.append(lambda: gear(Master=rig.master, Slave=rig.slave, Execute=rig.powers["Slave1"].Status))
    rig.run(0.2)
    assert gear.Busy and not gear.InGear and rig.slave.StatusSynchronizedMotion.FunctionState == 0
    rig.enable["Master1"] = True
    rig.run_until(lambda: gear.InGear, timeout=2.0)


def test_s7_1500_actual_value_coupling_to_an_external_encoder_compensates_the_delay_s3_3_4():
    """An external encoder measures a conveyor; the following axis couples to its extrapolated actual
    value and runs with it, the extrapolation making up for the filter and acquisition delays."""
    ctl = Controller(family="S7-1500T")
    enc = ctl.add_external_encoder("Conveyor", {
        "Plant": {"Velocity": 200.0},
        "Sensor": {"Sensor[1]": {"Parameter": {"DistancePerRevolution": 100.0, "StepsPerRevolution": 4096}}},
        "Extrapolation": {"PositionFilter": {"T1": 0.002}, "VelocityFilter": {"T1": 0.01, "T2": 0.01}}})
    s = ctl.add_synchronous_axis("Knife", VIRTUAL, leading_values=[("Conveyor", "actual")])
    pe, ps, gear = MC_Power(), MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        pe(Axis=enc, Enable=True)
        ps(Axis=s, Enable=True)
        gear(Master=enc, Slave=s, Execute=pe.Status and ps.Status)
    ctl.run_until(lambda: gear.InGear, timeout=2.0)
    ctl.run(1.0)
    assert enc.StatusWord.Enable and enc.StatusSensor[1].State == 2
    assert enc.ActualVelocity == pytest.approx(200.0, rel=0.05)
    # the extrapolated value is where the machine will be one interpolator cycle later: acquisition
    # time, interpolator cycle and filter time are made up for (leading-axis-dependent time)
    ahead = enc.plant_position + 200.0 * ctl.servo_cycle
    assert enc.Extrapolation.LeadingAxisDependentTime == pytest.approx(0.004)
    assert abs(enc.StatusExtrapolation.ExtrapolatedPosition - ahead) < 2 * enc.increment()
    filtered_lag = enc.plant_position - enc.StatusExtrapolation.FilteredPosition
    assert filtered_lag == pytest.approx(200.0 * (0.001 + 0.002), abs=2 * enc.increment())
    assert s.Velocity == pytest.approx(200.0, rel=0.01)


def test_s7_1500_actual_value_coupling_needs_the_t_cpu_s2_2():
    ctl = Controller(family="S7-1500")
    m = ctl.add_positioning_axis("M", {"Actor": {"Type": 1}})
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("M", "actual")])
    pm, ps, gear = MC_Power(), MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        gear(Master=m, Slave=s, Execute=pm.Status and ps.Status)
    ctl.run_until(lambda: gear.Error, timeout=2.0)
    assert gear.ErrorID == 0x8002


def test_s7_1500_gear_in_pos_needs_the_t_cpu_s2_2():
    rig = Rig(family="S7-1500")
    gip = MC_GearInPos()
    rig.steps.append(lambda: gip(Master=rig.master, Slave=rig.slave, Execute=rig.enabled()))
    rig.run_until(lambda: gip.Error, timeout=1.0)
    assert gip.ErrorID == 0x8002
    with pytest.raises(ValueError):
        rig.ctl.add_cam("Cam")


def _cross_plc(link_a, link_b, delay=0.008):
    a = Controller(family="S7-1500T")
    b = Controller(family="S7-1500T")
    m = a.add_positioning_axis("Master", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": delay}})
    sa = a.add_synchronous_axis("SlaveA", VIRTUAL, leading_values=[("Master", "delayed")])
    proxy = b.add_leading_axis_proxy("Proxy", {"Parameter": {"LocalLeadingValueDelayTime": delay,
                                                             "ToleranceTimeExternalLeadingValueInvalid": 0.02}},
                                     source_link=link_b)
    sb = b.add_synchronous_axis("SlaveB", VIRTUAL, leading_values=["Proxy"])
    m.provide_leading_value(link_a)
    pm, pa, pb = MC_Power(), MC_Power(), MC_Power()
    mv, ga, gb = MC_MoveVelocity(), MC_GearInPos(), MC_GearInPos()
    sync = dict(RatioNumerator=1, MasterSyncPosition=100.0, SlaveSyncPosition=5.0, MasterStartDistance=50.0)

    @a.program
    def prog_a():
        pm(Axis=m, Enable=True)
        pa(Axis=sa, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=100.0)
        ga(Master=m, Slave=sa, Execute=pa.Status, **sync)

    @b.program
    def prog_b():
        pb(Axis=sb, Enable=True)
        gb(Master=proxy, Slave=sb, Execute=pb.Status, **sync)
    return a, b, m, sa, sb, proxy, ga, gb


def test_s7_1500_cross_plc_followers_on_both_controllers_move_in_step_s8_1_3():
    link = LocalLink()
    a, b, m, sa, sb, proxy, ga, gb = _cross_plc(link, link)
    for _ in range(600):
        a.step()
        b.step()
        if ga.InSync and gb.InSync:
            assert sa.Position == pytest.approx(sb.Position, abs=1e-9)
            assert sb.Position == pytest.approx(5.0 + (m.StatusProvidedLeadingValue.DelayedLeadingValue.Position
                                                       - 100.0), abs=1e-9)
    assert ga.InSync and gb.InSync
    assert proxy.StatusWord.X4 and proxy.StatusExternalLeadingValue.AdjustmentTime < 0.0


class LossyLink(LocalLink):
    """A link that loses every telegram while ``lost`` is set (a communication failure)."""

    lost = False

    def send(self, sample):
        if not self.lost:
            super().send(sample)


def test_s7_1500_gearing_to_a_proxy_with_alarm_900_pending_is_refused_s8_2_3():
    """Issue 8 review: a new coupling to a proxy whose leading value is invalid (alarm 900 pending) would
    follow the held value.  It ends with 16#8001 and the follower gets the alarm of an invalid leading
    value; the proxy must be acknowledged first."""
    link = LossyLink()
    b = Controller(family="S7-1500T")
    proxy = b.add_leading_axis_proxy("Proxy", {"Parameter": {"ToleranceTimeExternalLeadingValueInvalid": 0.02}},
                                     source_link=link)
    sb = b.add_synchronous_axis("SlaveB", VIRTUAL, leading_values=["Proxy"])
    a = Controller(family="S7-1500T")
    m = a.add_positioning_axis("Master", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}}})
    m.provide_leading_value(link)
    pb, gear = MC_Power(), MC_GearIn()
    for _ in range(50):
        a.step()
        pb(Axis=sb, Enable=True)
        b.step()
    link.lost = True
    for _ in range(50):
        a.step()
        pb(Axis=sb, Enable=True)
        b.step()
    assert proxy.ErrorWord.X2 and proxy.ErrorDetail.Number == 900 and not sb.StatusWord.Error
    seen = []
    for _ in range(10):
        a.step()
        pb(Axis=sb, Enable=True)
        gear(Master=proxy, Slave=sb, Execute=True, RatioNumerator=1, RatioDenominator=1)
        seen.append(gear.Busy or gear.InGear)
        b.step()
    assert not any(seen) and gear.Error and gear.ErrorID == 0x8001
    assert sb.StatusWord.Error and sb.ErrorDetail.Number == 601      # the follower's leading value error


def test_s7_1500_proxy_extrapolates_late_values_and_raises_alarm_900_when_they_stop_s8_2_3():
    link = LossyLink()
    a, b, m, sa, sb, proxy, ga, gb = _cross_plc(link, link, delay=0.0)
    for _ in range(500):
        a.step()
        b.step()
    assert gb.InSync and proxy.StatusExternalLeadingValue.AdjustmentTime >= 0.0   # no delay: extrapolated
    link.lost = True
    for _ in range(2):                   # within the tolerance time the followers keep going
        a.step()
        b.step()
    assert proxy.StatusWord.X4 and gb.InSync and proxy.WarningWord.X7
    for _ in range(10):
        a.step()
        b.step()
    assert not proxy.StatusWord.X4 and proxy.ErrorWord.X2 and proxy.ErrorDetail.Number == 900
    assert gb.Error and gb.ErrorID == 0x8001 and sb.StatusWord.Error
    reset = MC_Reset()
    reset(Axis=proxy, Execute=True)
    assert reset.Error                   # the leading value is still missing
    link.lost = False
    for _ in range(3):
        a.step()
        b.step()
    reset(Axis=proxy, Execute=False)
    reset(Axis=proxy, Execute=True)
    assert reset.Done and proxy.StatusWord.X4 and not proxy.ErrorWord.X2


@pytest.mark.timeout_guard
def test_s7_1500_cross_plc_over_opc_ua_pubsub_on_loopback_s8_1_2():
    """The leading value travels as OPC UA PubSub UADP messages over UDP (unicast on loopback); the
    sending controller runs in its own thread, the receiver waits for its telegrams (lockstep)."""
    pytest.importorskip("asyncua")
    import socket

    from plcmotion.crossplc import UadpLeadingValuePublisher, UadpLeadingValueSubscriber
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    url = f"opc.udp://127.0.0.1:{port}"
    sub = UadpLeadingValueSubscriber(url, wait_timeout=2.0)
    pub = UadpLeadingValuePublisher(url)
    sub.start()
    pub.start()
    try:
        a, b, m, sa, sb, proxy, ga, gb = _cross_plc(pub, sub, delay=0.008)
        cycles = 400
        sender = threading.Thread(target=lambda: [a.step() for _ in range(cycles)], daemon=True)
        deadline = time.monotonic() + 60.0
        sender.start()
        errors = []
        for _ in range(cycles - 3):
            b.step()
            if time.monotonic() > deadline:
                break
            if gb.InSync and abs(sb.Position - (5.0 + proxy.Position - 100.0)) > 1e-9:
                errors.append(sb.Position)
        sender.join(timeout=30.0)
        assert gb.InSync and not errors
        assert proxy.StatusWord.X4
    finally:
        pub.close()
        sub.close()


# --- external encoder: delayed and cross-PLC leading value; extrapolation; virtual axis; proxy delay -------

FINE = {"Sensor[1]": {"Parameter": {"DistancePerRevolution": 100.0, "StepsPerRevolution": 1 << 20}}}


def _encoder_rig(extrapolation=None, plant=None, extra=None, followers=(("S", "actual"),), ctl=None):
    """An external encoder (fine resolution) with followers geared 1:1 to it by MC_GearIn."""
    ctl = ctl or Controller(family="S7-1500T", app_cycle=0.001)
    cfg = {"Sensor": FINE, "Extrapolation": extrapolation or {}, "Plant": plant or {}, **(extra or {})}
    enc = ctl.add_external_encoder("Enc", cfg)
    fol = [ctl.add_synchronous_axis(name, VIRTUAL, leading_values=[("Enc", mode)]) for name, mode in followers]
    pe, pf, gears = MC_Power(), [MC_Power() for _ in fol], [MC_GearIn() for _ in fol]

    @ctl.program
    def main():
        pe(Axis=enc, Enable=True)
        for p, ax, g in zip(pf, fol, gears):
            p(Axis=ax, Enable=True)
            g(Master=enc, Slave=ax, Execute=pe.Status and p.Status)
    return ctl, enc, fol, gears


def test_s7_1500_external_encoder_leading_value_can_be_delayed_s3_3_3():
    """§3.3.3 / §6.1.3: the leading value of an external encoder can be delayed ("Delayed"): the delayed
    follower gets the extrapolated actual value of LocalLeadingValueDelayTime ago."""
    D = 0.008
    ctl, enc, (sa, sd), gears = _encoder_rig(
        plant={"Velocity": 100.0}, extra={"CrossPlcSynchronousOperation": {"LocalLeadingValueDelayTime": D}},
        followers=(("SA", "actual"), ("SD", "delayed")))
    ctl.run_until(lambda: all(g.InGear or g.Error for g in gears), timeout=2.0)
    assert all(g.InGear for g in gears), [hex(g.ErrorID) for g in gears]
    hist = {}
    for _ in range(300):
        ctl.step()
        hist[round(ctl.time, 6)] = sa.StatusSynchronizedMotion.EffectiveLeadingValue.Position
        if ctl.time > 0.2:
            want = hist[round(ctl.time - D, 6)]
            assert sd.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(want, abs=1e-9)
            assert enc.StatusProvidedLeadingValue.DelayedLeadingValue.Position == pytest.approx(want, abs=1e-9)


def test_s7_1500_external_encoder_provides_a_cross_plc_leading_value_s8_1_3():
    """§8.1.3: an external encoder can be the leading object on CPU 1; its delayed local follower and the
    follower of the leading axis proxy on CPU 2 move in step (§8.1.4 tags on the encoder)."""
    link = LocalLink()
    a, b = Controller(family="S7-1500T", app_cycle=0.001), Controller(family="S7-1500T", app_cycle=0.001)
    _, enc, (local,), (g_local,) = _encoder_rig(
        plant={"Velocity": 100.0}, ctl=a, followers=(("Local", "delayed"),),
        extra={"CrossPlcSynchronousOperation": {"Interface[1]": {"EnableLeadingValueOutput": True},
                                                "LocalLeadingValueDelayTime": 0.008}})
    enc.provide_leading_value(link)
    proxy = b.add_leading_axis_proxy("P", {}, source_link=link)
    remote = b.add_synchronous_axis("Remote", VIRTUAL, leading_values=["P"])
    pr, g_remote = MC_Power(), MC_GearIn()

    @b.program
    def prog_b():
        pr(Axis=remote, Enable=True)
        g_remote(Master=proxy, Slave=remote, Execute=pr.Status)
    for _ in range(3000):
        a.step()
        b.step()
        if g_local.InGear and g_remote.InGear:
            break
    assert g_local.InGear and g_remote.InGear and proxy.StatusWord.X4
    assert enc.StatusProvidedLeadingValue.DelayedLeadingValue.Velocity == pytest.approx(100.0, rel=1e-3)
    assert proxy.Position == pytest.approx(enc.StatusProvidedLeadingValue.DelayedLeadingValue.Position, abs=1e-9)
    x0, l0, r0 = proxy.Position, local.Position, remote.Position
    for _ in range(50):
        a.step()
        b.step()
        assert local.Position - l0 == pytest.approx(remote.Position - r0, abs=1e-9)
    assert proxy.Position - x0 == pytest.approx(5.0, rel=1e-3)


def test_s7_1500_constant_acceleration_is_extrapolated_exactly_s3_3_4():
    """§3.3.4: delays at constant velocity and at constant acceleration are compensated.  The leading value
    is the actual position of (effective extrapolation time - position filter time) later, whatever the
    filter settings; at constant velocity it stays FilteredPosition + FilteredVelocity * T."""
    a, v0 = 2000.0, 30.0
    for ext in ({"PositionFilter": {"T1": 0.002}, "VelocityFilter": {"T1": 0.01, "T2": 0.01},
                 "FollowingAxisDependentTime": 0.01},
                {"PositionFilter": {"T1": 0.003, "T2": 0.002}, "VelocityFilter": {"T1": 0.0, "T2": 0.0}},
                {"VelocityFilter": {"T1": 0.007, "T2": 0.0}, "FollowingAxisDependentTime": 0.02,
                 "Settings": {"SystemDefinedExtrapolation": 0}}):
        ctl, enc, _, gears = _encoder_rig(ext)
        def plant(t):
            return v0 * t + 0.5 * a * t * t
        enc.drive_plant(plant)
        ctl.run_until(lambda g=gears[0]: g.InGear, timeout=2.0)
        ctl.run(0.3)
        e = enc.eff
        lead = enc.lv_provider.extrapolation_time() - e["Extrapolation.PositionFilter.T1"] - e["Extrapolation.PositionFilter.T2"]
        for _ in range(5):
            ctl.run(0.05)
            # the encoder value of a servo cycle was measured one cycle earlier (T_i)
            want = plant(ctl.time - ctl.servo_cycle + lead)
            assert enc.StatusExtrapolation.ExtrapolatedPosition == pytest.approx(want, abs=1e-5), ext
    ctl, enc, _, gears = _encoder_rig({"PositionFilter": {"T1": 0.002}, "FollowingAxisDependentTime": 0.01},
                                      plant={"Velocity": 150.0})
    ctl.run_until(lambda: gears[0].InGear, timeout=2.0)
    ctl.run(0.3)
    se = enc.StatusExtrapolation
    assert se.ExtrapolatedPosition == pytest.approx(se.FilteredPosition + se.FilteredVelocity * enc.lv_provider.extrapolation_time(),
                                                    abs=1e-6)


def test_s7_1500_effective_leading_value_acceleration_with_actual_value_coupling_s3_5_1():
    """§A.1.33 EffectiveLeadingValue.Acceleration: the extrapolated acceleration of the actual value."""
    a = 2000.0
    ctl, enc, (s,), gears = _encoder_rig({"VelocityFilter": {"T1": 0.005}})
    enc.drive_plant(lambda t: 0.5 * a * t * t)
    ctl.run_until(lambda: gears[0].InGear, timeout=2.0)
    ctl.run(0.3)
    assert s.StatusSynchronizedMotion.EffectiveLeadingValue.Acceleration == pytest.approx(a, rel=1e-3)
    enc.set_plant_velocity(100.0)
    ctl.run(0.2)
    assert s.StatusSynchronizedMotion.EffectiveLeadingValue.Acceleration == pytest.approx(0.0, abs=0.1)


def test_s7_1500_hysteresis_acts_on_reversals_only_s3_3_4():
    """§3.3.4 hysteresis: no offset in one-way motion; a reversal takes effect once the position has gone
    back by the hysteresis value, then the leading value catches up with the input (twice its speed) and
    follows it again without offset (docs/s7_1500/decisions.md row 28)."""
    H = 2.0
    def prof(t):
        return 100 * t if t < 0.1 else 10 - 100 * (t - 0.1)
    ctl, enc, _, gears = _encoder_rig({"Hysteresis": {"Value": H}, "Settings": {"SystemDefinedExtrapolation": 0}})
    enc.drive_plant(prof)
    se = enc.StatusExtrapolation
    last, turn = None, 0.0
    while ctl.time < 0.2:
        ctl.step()
        x, y = se.FilteredPosition, se.ExtrapolatedPosition
        turn = max(turn, x)
        if x == turn:
            assert y == x                                  # forward only: no displacement
        elif x > turn - H:
            assert y == turn                               # a reversal smaller than H: held
        if last is not None:
            assert abs(y - last) <= 2 * 0.1 + 1e-6         # no jump: at most twice the input's travel
        last = y
        if x < turn - 2 * H:                               # back by more than 2 H: caught up
            assert y == x
    assert gears[0].InGear and y == x < turn - 2 * H


def test_s7_1500_actual_value_coupling_to_a_virtual_axis_s3_3_2():
    """§3.3.2 allows actual value coupling to positioning and synchronous axes; a virtual axis's actual
    value is its setpoint (T_i = 0, decision 29), so the leading value equals the setpoint."""
    ctl = Controller(family="S7-1500T")
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("M", "actual")])
    pm, ps, mv, g = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn()

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=1000.0, Acceleration=200.0, Jerk=0.0)
        g(Master=m, Slave=s, Execute=ps.Status)
    ctl.run_until(lambda: g.InGear or g.Error, timeout=2.0)
    assert g.InGear, hex(g.ErrorID)
    ctl.run(0.5)                                           # still accelerating
    lv = s.StatusSynchronizedMotion.EffectiveLeadingValue
    assert lv.Position == pytest.approx(m.Position, abs=1e-9)
    assert lv.Acceleration == pytest.approx(200.0, rel=1e-9)


def test_s7_1500_proxy_takes_the_delay_from_the_sender_s8_1_3():
    """§8.1.3 / §8.2.3.2: the delay is set at the leading axis only; the proxy provides the value the
    sender's delayed followers use at the same time (its own LocalLeadingValueDelayTime is for a cascade
    and stays 0 here).  A changed delay (DIR) reaches the proxy with the next telegram."""
    link = LocalLink()
    a, b = Controller(family="S7-1500T"), Controller(family="S7-1500T")
    m = a.add_positioning_axis("Master", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": 0.008}})
    sa = a.add_synchronous_axis("SlaveA", VIRTUAL, leading_values=[("Master", "delayed")])
    proxy = b.add_leading_axis_proxy("Proxy", {}, source_link=link)
    sb = b.add_synchronous_axis("SlaveB", VIRTUAL, leading_values=["Proxy"])
    m.provide_leading_value(link)
    pm, pa, pb, mv, ga, gb = MC_Power(), MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn(), MC_GearIn()

    @a.program
    def prog_a():
        pm(Axis=m, Enable=True)
        pa(Axis=sa, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=100.0, Acceleration=400.0, Jerk=0.0)
        ga(Master=m, Slave=sa, Execute=pa.Status)

    @b.program
    def prog_b():
        pb(Axis=sb, Enable=True)
        gb(Master=proxy, Slave=sb, Execute=pb.Status)
    for delay in (0.008, 0.012):
        m.write_tag("CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", delay)
        for _ in range(100):
            a.step()
            b.step()
        assert ga.InGear and gb.InGear and proxy.tag("Parameter.LocalLeadingValueDelayTime") == 0.0
        for _ in range(20):
            a.step()
            b.step()
            assert proxy.Position == pytest.approx(m.StatusProvidedLeadingValue.DelayedLeadingValue.Position, abs=1e-9)
            assert sb.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(
                sa.StatusSynchronizedMotion.EffectiveLeadingValue.Position, abs=1e-9)
        assert proxy.StatusExternalLeadingValue.AdjustmentTime < 0.0
    assert proxy.Parameter.LocalLeadingValueDelayTime == 0.0        # configuration tags read as attributes


def test_s7_1500_the_leading_value_of_a_proxy_cannot_be_delayed_s3_3_3():
    """§3.3.3 names positioning axis, synchronous axis and external encoder; not the proxy."""
    ctl = Controller(family="S7-1500T")
    proxy = ctl.add_leading_axis_proxy("P", {}, source_link=LocalLink())
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("P", "delayed")])
    ps, g = MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        ps(Axis=s, Enable=True)
        g(Master=proxy, Slave=s, Execute=ps.Status)
    ctl.run_until(lambda: g.Error or g.InGear, timeout=1.0)
    assert g.Error and g.ErrorID == 0x8002


def test_s7_1500_cascade_keeps_all_followers_in_step_with_interpolation_s8_1_3():
    """§8.1.3 cascade: CPU 1 leading axis (delay for its local followers), CPU 2 proxy with a follower and a
    virtual axis that provides the value on to CPU 3 with its own delay, entered also at the proxy
    (Parameter.LocalLeadingValueDelayTime, §8.2.3.2).  All followers get the same leading value at the same
    time, and both proxies interpolate (AdjustmentTime < 0)."""
    hop = 0.008                                        # 2 application cycles of a receiving CPU
    link1, link2 = LocalLink(), LocalLink()
    a, b, c = (Controller(family="S7-1500T") for _ in range(3))
    m = a.add_positioning_axis("Master", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": 2 * hop}})
    f1 = a.add_synchronous_axis("F1", VIRTUAL, leading_values=[("Master", "delayed")])
    p2 = b.add_leading_axis_proxy("P2", {"Parameter": {"LocalLeadingValueDelayTime": hop}}, source_link=link1)
    f2 = b.add_synchronous_axis("F2", VIRTUAL, leading_values=["P2"])
    v = b.add_synchronous_axis("V", {**VIRTUAL, "CrossPlcSynchronousOperation": {
        "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": hop}},
        leading_values=["P2"])
    p3 = c.add_leading_axis_proxy("P3", {}, source_link=link2)
    f3 = c.add_synchronous_axis("F3", VIRTUAL, leading_values=["P3"])
    m.provide_leading_value(link1)
    v.provide_leading_value(link2)
    fbs = {name: (MC_Power(), MC_GearIn()) for name in ("F1", "F2", "V", "F3")}
    pm, mv = MC_Power(), MC_MoveVelocity()

    def couple(name, master, slave):
        power, gear = fbs[name]
        power(Axis=slave, Enable=True)
        gear(Master=master, Slave=slave, Execute=power.Status)

    @a.program
    def prog_a():
        pm(Axis=m, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=100.0, Acceleration=50.0, Jerk=0.0)
        couple("F1", m, f1)

    @b.program
    def prog_b():
        couple("F2", p2, f2)
        couple("V", p2, v)

    @c.program
    def prog_c():
        couple("F3", p3, f3)

    for _ in range(150):                               # the sending controllers run first in each cycle
        a.step(), b.step(), c.step()
    assert all(gear.InGear for _, gear in fbs.values())
    offsets = []
    for _ in range(50):                                # the master still accelerates: a time shift would show
        a.step(), b.step(), c.step()
        assert m.Acceleration == pytest.approx(50.0)
        lv1 = f1.StatusSynchronizedMotion.EffectiveLeadingValue.Position
        assert f2.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(lv1, abs=1e-9)
        # CPU 3 follows the position of V, which took up the gearing with an offset of its own
        offsets.append(f3.StatusSynchronizedMotion.EffectiveLeadingValue.Position - lv1)
        assert f3.StatusSynchronizedMotion.EffectiveLeadingValue.Velocity == pytest.approx(
            f1.StatusSynchronizedMotion.EffectiveLeadingValue.Velocity, abs=1e-9)
    assert max(offsets) - min(offsets) < 1e-9
    assert p2.StatusExternalLeadingValue.AdjustmentTime < 0.0 and p3.StatusExternalLeadingValue.AdjustmentTime < 0.0
