"""S7-1500T V5 §3.5, §3.5.1, §9.1.7, §9.3.2: MC_LeadingValueAdditive."""
import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_GearIn, MC_GearInPos, MC_Halt, MC_LeadingValueAdditive, MC_MoveRelative,
                               MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop)

from _lh import VIRTUAL, check_error_outputs


class AddRig:
    def __init__(self, family="S7-1500T", v=50.0, ratio=2):
        ctl = self.ctl = Controller(family=family, app_cycle=0.001)
        self.m = ctl.add_positioning_axis("M", VIRTUAL)
        self.m2 = ctl.add_positioning_axis("M2", VIRTUAL)
        self.s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["M", "M2"])
        self.pm, self.pm2, self.ps = MC_Power(), MC_Power(), MC_Power()
        self.mv, self.gear, self.gear2 = MC_MoveVelocity(), MC_GearIn(), MC_GearIn()
        self.lva, self.lva2 = MC_LeadingValueAdditive(), MC_LeadingValueAdditive()
        self.stop, self.reset, self.halt, self.mabs = MC_Stop(), MC_Reset(), MC_Halt(), MC_MoveRelative()
        self.st = dict(gear=True, gear2=False, lva=False, lva2=False, p=0.0, v=0.0, a=0.0, stop=False,
                       reset=False, restart=False, halt=False, mabs=False, slave_en=True, mv=v)

        @ctl.program
        def main():
            st = self.st
            self.pm(Axis=self.m, Enable=True)
            self.pm2(Axis=self.m2, Enable=True)
            self.ps(Axis=self.s, Enable=st["slave_en"])
            self.mv(Axis=self.m, Execute=self.pm.Status, Velocity=st["mv"])
            self.gear(Master=self.m, Slave=self.s, Execute=st["gear"] and self.ps.Status, RatioNumerator=ratio)
            self.gear2(Master=self.m2, Slave=self.s, Execute=st["gear2"], RatioNumerator=ratio)
            self.lva(Axis=self.s, Enable=st["lva"], Position=st["p"], Velocity=st["v"], Acceleration=st["a"])
            self.lva2(Axis=self.s, Enable=st["lva2"], Position=1.0)
            self.stop(Axis=self.s, Execute=st["stop"])
            self.reset(Axis=self.s, Execute=st["reset"], Restart=st["restart"])
            self.halt(Axis=self.s, Execute=st["halt"])
            self.mabs(Axis=self.s, Execute=st["mabs"], Distance=5.0)
            check_error_outputs(self.gear, self.gear2, self.lva, self.lva2, self.stop, self.reset, self.halt, self.mabs)

    def run(self, t):
        self.ctl.run(t)

    def until(self, c, timeout=3.0):
        self.ctl.run_until(c, timeout=timeout)

    def eff(self):
        return self.s.StatusSynchronizedMotion.EffectiveLeadingValue


def test_s7_1500_effective_lv_is_master_plus_additive_and_acts_immediately_s3_5():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.run(0.1)
    r.st.update(lva=True, p=10.0, v=5.0, a=0.0)
    r.ctl.step()
    assert r.lva.Busy and not r.lva.Error
    assert r.s.StatusSynchronizedMotion.StatusWord.X4
    e = r.eff()
    assert e.Position == pytest.approx(r.m.Position + 10.0, abs=1e-9)
    assert e.Velocity == pytest.approx(r.m.Velocity + 5.0, abs=1e-9)
    # no dynamic limitation: the following axis jumps by ratio x additive position in the same cycle
    assert r.s.Position == pytest.approx(2 * (r.m.Position + 10.0), abs=1e-9)
    assert r.gear.InGear
    # value changes take effect directly
    r.st["p"] = -3.0
    r.ctl.step()
    assert r.s.Position == pytest.approx(2 * (r.m.Position - 3.0), abs=1e-9)
    r.st["lva"] = False
    r.ctl.step()
    assert not r.lva.Busy and not r.s.StatusSynchronizedMotion.StatusWord.X4
    assert r.eff().Position == pytest.approx(r.m.Position, abs=1e-9)


def test_s7_1500_additive_acceleration_in_effective_leading_value_s3_5_1():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, a=7.0)
    r.ctl.step()
    assert r.eff().Acceleration == pytest.approx(r.m.Acceleration + 7.0, abs=1e-9)


def test_s7_1500_can_start_without_synchronous_operation_s3_5():
    r = AddRig()
    r.st["gear"] = False
    r.run(0.05)
    r.st.update(lva=True, p=4.0)
    r.run(0.01)
    assert r.lva.Busy and not r.lva.Error and r.s.StatusSynchronizedMotion.StatusWord.X4


def test_s7_1500_rejected_when_axis_disabled_and_not_simulated_s9_1_7():
    r = AddRig()
    r.st["slave_en"] = False
    r.st["gear"] = False
    r.run(0.02)
    r.st.update(lva=True, p=4.0)
    r.run(0.01)
    assert r.lva.Error and r.lva.ErrorID != 0 and not r.lva.Busy


def test_s7_1500_survives_leading_value_switchover_s3_5():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, p=10.0)
    r.run(0.02)
    r.st["gear2"] = True
    r.until(lambda: r.gear2.InGear)
    assert r.gear.CommandAborted
    assert r.lva.Busy and r.s.StatusSynchronizedMotion.StatusWord.X4
    assert r.eff().Position == pytest.approx(r.m2.Position + 10.0, abs=1e-9)


@pytest.mark.parametrize("job", ["halt", "mabs"])
def test_s7_1500_single_axis_jobs_do_not_abort_it_s9_3_2(job):
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, p=1.0)
    r.run(0.02)
    r.st[job] = True
    r.run(0.05)
    assert r.gear.CommandAborted
    assert r.lva.Busy and r.s.StatusSynchronizedMotion.StatusWord.X4


def test_s7_1500_aborted_by_mc_stop_s9_1_7():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, p=1.0)
    r.run(0.02)
    r.st["stop"] = True
    r.run(0.02)
    assert not r.lva.Busy and not r.lva.Error
    assert not r.s.StatusSynchronizedMotion.StatusWord.X4


def test_s7_1500_aborted_by_reset_with_restart_s9_1_7():
    r = AddRig()
    r.st["gear"] = False
    r.st.update(lva=True, p=1.0)
    r.run(0.02)
    assert r.lva.Busy
    r.st["slave_en"] = False
    r.run(0.02)
    r.st.update(reset=True, restart=True)
    r.run(0.05)
    assert not r.lva.Busy and not r.s.StatusSynchronizedMotion.StatusWord.X4


def test_s7_1500_not_aborted_by_mc_reset_without_restart_s9_1_7():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, p=1.0)
    r.run(0.02)
    r.st.update(reset=True, restart=False)
    r.run(0.02)
    assert r.lva.Busy


def test_s7_1500_second_job_aborts_the_first_only_one_active_s3_5_s9_3_2():
    r = AddRig()
    r.until(lambda: r.gear.InGear)
    r.st.update(lva=True, p=10.0)
    r.run(0.02)
    r.st["lva2"] = True
    r.run(0.02)
    assert r.lva2.Busy and not r.lva.Busy
    assert r.eff().Position == pytest.approx(r.m.Position + 1.0, abs=1e-9)


def test_s7_1500_section_b_start_position_from_effective_leading_value_s9_1_7_2():
    """Chart §9.1.7.2 B: additive value 100 first, then GearInPos (SPR 1, start at effective LV 200):
    StartSync when the master is at 100.  After InSync the additive value ramps down while the master
    moves on: the effective LV stays constant and the following axis stands still."""
    ctl = Controller(family="S7-1500T", app_cycle=0.001)
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["M"])
    pm, ps, mv, gip, lva = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearInPos(), MC_LeadingValueAdditive()
    st = {"add": 0.0, "exe": False}

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=pm.Status and st["exe"], Velocity=100.0)
        lva(Axis=s, Enable=True, Position=st["add"], Velocity=0.0)
        gip(Master=m, Slave=s, Execute=st["exe"], RatioNumerator=1, MasterSyncPosition=250.0,
            SlaveSyncPosition=0.0, MasterStartDistance=50.0, SyncProfileReference=1)
    ctl.run(0.01)
    st["add"] = 100.0
    st["exe"] = True
    ctl.run_until(lambda: gip.StartSync, timeout=5.0)
    assert m.Position == pytest.approx(100.0, abs=0.5)
    assert s.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(200.0, abs=0.5)
    ctl.run_until(lambda: gip.InSync, timeout=5.0)
    assert s.Position == pytest.approx(0.0, abs=1e-6) or m.Position + 100.0 - 250.0 == pytest.approx(s.Position)
    # ramp the additive value down as fast as the master moves: effective LV constant, slave stands
    e0, p0 = s.StatusSynchronizedMotion.EffectiveLeadingValue.Position, s.Position
    x0 = m.Position
    while st["add"] > 0.0:
        st["add"] = max(0.0, 100.0 - (m.Position - x0))
        ctl.step()
        if st["add"] > 0.0:
            assert s.StatusSynchronizedMotion.EffectiveLeadingValue.Position == pytest.approx(e0, abs=0.2)
            assert s.Position == pytest.approx(p0, abs=0.2)
    ctl.run(0.1)
    assert s.Velocity == pytest.approx(100.0)


def test_s7_1500_needs_the_t_cpu_s2_2():
    r = AddRig(family="S7-1500")
    r.st["gear"] = True
    r.run(0.1)
    r.st.update(lva=True, p=1.0)
    r.run(0.01)
    assert r.lva.Error and r.lva.ErrorID != 0
