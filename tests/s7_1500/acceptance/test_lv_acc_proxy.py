"""S7-1500T V5 §8 cross-PLC synchronous operation, §A.3 leading axis proxy tags, §8.3.1.1 diagnostics."""
import socket
import threading
import time

import pytest

from plcmotion import Controller
from plcmotion.crossplc import LocalLink
from plcmotion.s7_1500 import MC_GearInPos, MC_MoveVelocity, MC_Power, MC_Reset

SYNC = dict(RatioNumerator=1, MasterSyncPosition=20.0, SlaveSyncPosition=0.0, MasterStartDistance=10.0)

from _lh import VIRTUAL, check_error_outputs


class LossyLink(LocalLink):
    lost = False

    def send(self, sample):
        if not self.lost:
            super().send(sample)


class Cross:
    """CPU A: leading axis M (+ local follower LA, delayed coupling); CPU B: proxy P, follower RB."""

    def __init__(self, sender_delay=0.008, proxy_delay=0.008, tolerance=0.02, master=None, link=None,
                 sender_family="S7-1500T", app_cycle=0.004, v=100.0, pc=True, local=True):
        self.link = link or LossyLink()
        a = self.a = Controller(family=sender_family, app_cycle=app_cycle)
        b = self.b = Controller(family="S7-1500T", app_cycle=app_cycle)
        self.m = a.add_positioning_axis("M", {**(master or VIRTUAL), "CrossPlcSynchronousOperation": {
            "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": sender_delay}})
        self.la = a.add_synchronous_axis("LA", VIRTUAL, leading_values=[("M", "delayed" if local else "setpoint")])
        pparams = {"ToleranceTimeExternalLeadingValueInvalid": tolerance}
        if proxy_delay is not None:
            pparams["LocalLeadingValueDelayTime"] = proxy_delay
        self.p = b.add_leading_axis_proxy("P", {"Parameter": pparams}, source_link=self.link)
        self.rb = b.add_synchronous_axis("RB", VIRTUAL, leading_values=["P"])
        self.m.provide_leading_value(self.link)
        self.pm, self.pla, self.prb = MC_Power(), MC_Power(), MC_Power()
        self.mv, self.ga, self.gb, self.reset = MC_MoveVelocity(), MC_GearInPos(), MC_GearInPos(), MC_Reset()
        self.st = dict(mv=True, m_en=True, v=v, pc=pc, la=local and sender_family == "S7-1500T", rb=True, reset=False)

        @a.program
        def pa():
            st = self.st
            self.pm(Axis=self.m, Enable=st["m_en"])
            self.pla(Axis=self.la, Enable=True)
            self.mv(Axis=self.m, Execute=st["mv"] and self.pm.Status, Velocity=st["v"], PositionControlled=st["pc"])
            self.ga(Master=self.m, Slave=self.la, Execute=st["la"] and self.pla.Status, **SYNC)

        @b.program
        def pb():
            self.prb(Axis=self.rb, Enable=True)
            self.gb(Master=self.p, Slave=self.rb, Execute=self.st["rb"] and self.prb.Status, **SYNC)
            self.reset(Axis=self.p, Execute=self.st["reset"])
            check_error_outputs(self.gb, self.reset)

    def step(self, n=1):
        for _ in range(n):
            self.a.step()
            self.b.step()


def test_s7_1500_proxy_value_is_the_leading_value_of_delay_time_ago_s8_1_4():
    x = Cross(sender_delay=0.008, proxy_delay=0.008)
    hist = {}
    for _ in range(100):
        x.step()
        hist[round(x.a.time, 6)] = (x.m.Position, x.m.Velocity)
    t = round(x.b.time - 0.008, 6)
    assert x.p.Position == pytest.approx(hist[t][0], abs=1e-9)
    assert x.p.Velocity == pytest.approx(hist[t][1], abs=1e-9)
    assert x.p.StatusWord.X4 and x.p.StatusExternalLeadingValue.AdjustmentTime < 0.0


def test_s7_1500_followers_in_step_when_only_the_leading_axis_delay_is_set_s8_1_3():
    """§8.1.3: the delay is configured at the leading axis; 'depending on the set delay time, the leading
    value at the leading axis proxy is automatically interpolated or extrapolated ... guarantees the
    synchronicity of all following axes'.  §8.2.3.2: the proxy's own Delay time is the one of a virtual
    following axis that re-provides the value in a cascade - there is no cascade here (default 0)."""
    x = Cross(sender_delay=0.008, proxy_delay=None)
    x.step(150)
    assert x.ga.InSync and x.gb.InSync
    diff = (x.la.Position - x.m.Position) - (x.rb.Position - x.m.Position)
    assert x.la.Position == pytest.approx(x.rb.Position, abs=1e-6), f"followers differ by {diff}"


def test_s7_1500_modulo_leading_axis_s8_1_4_a_3():
    x = Cross(master={**VIRTUAL, "Modulo": {"Enable": True, "Length": 360.0, "StartValue": 0.0}}, v=2000.0)
    x.step(60)
    p = x.p
    assert p.StatusWord.X5 and p.StatusExternalLeadingValue.ModuloLength == 360.0
    assert p.StatusExternalLeadingValue.ModuloStartValue == 0.0
    assert 0.0 <= p.Position < 360.0
    assert x.m.Position < 360.0


def test_s7_1500_tracking_leading_axis_clears_leading_axis_control_s8_1_4():
    """StatusWord.X6 (LeadingAxisControl): 0 = leading axis in follow-up (tracking) mode."""
    x = Cross(master={"Actor": {"Type": 1}}, pc=True)
    x.step(60)
    assert x.p.StatusWord.X6
    x.st["pc"], x.st["mv"] = False, False
    x.step(1)
    x.st["mv"] = True
    x.step(60)
    assert x.m.StatusWord.NonPositionControlled
    assert not x.p.StatusWord.X6


def test_s7_1500_setpoint_coupling_to_proxy_waits_until_leading_value_is_valid_s3_3_5():
    x = Cross()
    x.link.lost = True
    x.step(20)
    assert not x.p.StatusWord.X4
    assert x.gb.Busy and not x.gb.InSync and not x.gb.Error
    x.link.lost = False
    for _ in range(100):
        x.step()
        if x.gb.InSync:
            break
    assert x.gb.InSync


def test_s7_1500_values_stop_alarm_900_after_tolerance_time_follower_extrapolated_meanwhile_s8_1_2():
    tol = 0.02
    x = Cross(tolerance=tol, sender_delay=0.0, proxy_delay=0.0)
    x.step(150)
    assert x.gb.InSync and x.p.StatusWord.X4
    x.link.lost = True
    t_lost = x.b.time
    p0 = x.rb.Position
    alarm_at = None
    while x.b.time < t_lost + 0.1:
        x.step()
        if x.p.ErrorWord.X2 and alarm_at is None:
            alarm_at = x.b.time
        if alarm_at is None:
            assert x.p.StatusWord.X4 and not x.p.StatusWord.X1
    assert alarm_at is not None
    assert tol - 1e-9 <= alarm_at - t_lost <= tol + 2 * x.b.app_cycle
    assert x.p.ErrorDetail.Number == 900 and x.p.ErrorDetail.Reaction == 13
    assert x.p.StatusWord.X1 and not x.p.StatusWord.X4


def test_s7_1500_follower_keeps_moving_during_tolerance_time_s8_1_2():
    tol = 0.05
    x = Cross(tolerance=tol, sender_delay=0.0, proxy_delay=0.0)
    x.step(150)
    x.link.lost = True
    p0 = x.rb.Position
    x.step(5)                               # 20 ms < tolerance
    assert x.rb.Position == pytest.approx(p0 + 100.0 * 0.02, abs=1e-6)


def test_s7_1500_invalid_telegram_when_leading_axis_disabled_s8_1_4():
    x = Cross(tolerance=0.02)
    x.step(100)
    x.st["m_en"] = False
    x.step(40)
    assert not x.p.StatusWord.X4
    assert x.p.ErrorDetail.Number == 900


def test_s7_1500_mc_reset_acknowledges_after_values_return_s8_1_2():
    x = Cross(tolerance=0.02)
    x.step(100)
    x.link.lost = True
    x.step(20)
    assert x.p.ErrorWord.X2
    x.link.lost = False
    x.step(3)
    x.st["reset"] = True
    x.step(3)
    assert x.reset.Done and not x.p.ErrorWord.X2 and x.p.StatusWord.X4 and not x.p.StatusWord.X1


def test_s7_1500_sender_can_provide_the_leading_value_s8_1():
    """§8.1: 'The S7-1500 and S7-1500T CPUs can make the leading value available'."""
    x = Cross(sender_family="S7-1500", sender_delay=0.0, proxy_delay=0.0)
    x.step(100)
    assert x.p.StatusWord.X4 and x.gb.InSync
    assert x.rb.Position == pytest.approx(x.m.Position - 20.0, abs=1e-6)


def test_s7_1500_proxy_needs_an_s7_1500t_receiver_s8_1():
    ctl = Controller(family="S7-1500")
    with pytest.raises(Exception):
        ctl.add_leading_axis_proxy("P", {}, source_link=LocalLink())


def test_s7_1500_uadp_modulo_and_tracking_fields_arrive_s8_1_2():
    pytest.importorskip("asyncua")
    from plcmotion.crossplc import UadpLeadingValuePublisher, UadpLeadingValueSubscriber
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    url = f"opc.udp://127.0.0.1:{port}"
    sub = UadpLeadingValueSubscriber(url, wait_timeout=1.0)
    pub = UadpLeadingValuePublisher(url)
    sub.start()
    pub.start()
    try:
        x = Cross(link=LocalLink(), master={**VIRTUAL, "Modulo": {"Enable": True, "Length": 360.0,
                                                                   "StartValue": 0.0}}, v=2000.0)
        x.m.provide_leading_value(pub)
        x.p.connect(sub)
        n = 80
        sender = threading.Thread(target=lambda: [x.a.step() for _ in range(n)], daemon=True)
        deadline = time.monotonic() + 20.0
        sender.start()
        for _ in range(n - 3):
            x.b.step()
            if time.monotonic() > deadline:
                break
        sender.join(timeout=10.0)
        assert x.p.StatusWord.X4 and x.p.StatusWord.X5 and x.p.StatusWord.X6
        assert x.p.StatusExternalLeadingValue.ModuloLength == 360.0
    finally:
        pub.close()
        sub.close()
