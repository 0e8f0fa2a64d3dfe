"""S7-1500T V5 §3.4, §3.4.1, §9.1.6: MC_SynchronizedMotionSimulation."""
import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_GearIn, MC_GearInPos, MC_Halt, MC_LeadingValueAdditive, MC_MoveRelative,
                               MC_MoveSuperimposed, MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop,
                               MC_SynchronizedMotionSimulation)

from _lh import VIRTUAL, check_error_outputs


class SimRig:
    def __init__(self, family="S7-1500T", master_velocity=50.0):
        ctl = self.ctl = Controller(family=family)
        self.m = ctl.add_positioning_axis("M", VIRTUAL)
        self.m2 = ctl.add_positioning_axis("M2", VIRTUAL)
        self.s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["M", "M2"])
        self.pm, self.ps = MC_Power(), MC_Power()
        self.mv, self.halt, self.gear = MC_MoveVelocity(), MC_Halt(), MC_GearIn()
        self.sim = MC_SynchronizedMotionSimulation()
        self.rel, self.stop, self.reset, self.sup = MC_MoveRelative(), MC_Stop(), MC_Reset(), MC_MoveSuperimposed()
        self.gear2, self.lva = MC_GearIn(), MC_LeadingValueAdditive()
        self.st = dict(slave_en=True, mv=True, halt=False, sim=False, rel=False, stop=False, reset=False,
                       restart=False, sup=False, gear=True, gear2=False, lva=False, rel_dist=10.0, v=master_velocity)

        @ctl.program
        def main():
            st = self.st
            self.pm(Axis=self.m, Enable=True)
            self.ps(Axis=self.s, Enable=st["slave_en"])
            self.mv(Axis=self.m, Execute=st["mv"] and self.pm.Status, Velocity=st["v"])
            self.halt(Axis=self.m, Execute=st["halt"])
            self.gear(Master=self.m, Slave=self.s, Execute=st["gear"] and (self.ps.Status or self.gear.Busy), RatioNumerator=2)
            self.sim(Slave=self.s, Enable=st["sim"])
            self.rel(Axis=self.s, Execute=st["rel"], Distance=st["rel_dist"])
            self.stop(Axis=self.s, Execute=st["stop"])
            self.reset(Axis=self.s, Execute=st["reset"], Restart=st["restart"])
            self.sup(Axis=self.s, Execute=st["sup"], Distance=20.0, VelocityDiff=20.0)
            self.gear2(Master=self.m2, Slave=self.s, Execute=st["gear2"])
            self.lva(Axis=self.s, Enable=st["lva"], Position=5.0)
            check_error_outputs(self.gear, self.sim, self.rel, self.stop, self.reset, self.gear2, self.lva)

    def run(self, t):
        self.ctl.run(t)

    def until(self, cond, timeout=3.0):
        return self.ctl.run_until(cond, timeout=timeout)

    def synchronous_and_halted(self):
        self.until(lambda: self.gear.InGear)
        self.run(0.1)
        self.st["halt"] = True
        self.until(lambda: self.halt.Done)
        self.st["mv"] = False


def test_s7_1500_rejected_when_not_synchronous_s9_1_6():
    r = SimRig()
    r.st["gear"] = False              # no synchronous operation at all
    r.run(0.05)
    r.st["sim"] = True
    r.ctl.step()
    assert not r.s.StatusWord.Synchronous
    assert r.sim.Error and r.sim.ErrorID != 0 and not r.sim.InSimulation and not r.sim.Busy
    assert not r.s.StatusSynchronizedMotion.StatusWord.X3


def test_s7_1500_needs_the_t_cpu_s2_2():
    r = SimRig(family="S7-1500")
    r.until(lambda: r.gear.InGear)
    r.st["sim"] = True
    r.run(0.02)
    assert r.sim.Error and r.sim.ErrorID != 0


def test_s7_1500_procedure_disable_and_reenable_without_resynchronization_s9_1_6_1():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    assert r.sim.InSimulation and r.sim.Busy and not r.sim.Error
    assert r.s.StatusSynchronizedMotion.StatusWord.X3
    r.st["slave_en"] = False
    r.run(0.2)
    assert not r.s.StatusWord.Enable
    assert r.s.StatusWord.Synchronous and r.s.StatusSynchronizedMotion.FunctionState == 1
    assert r.gear.InGear and r.gear.Busy and not r.gear.CommandAborted
    assert r.sim.InSimulation
    r.st["slave_en"] = True
    r.run(0.1)
    r.st["sim"] = False
    r.run(0.02)
    assert not r.sim.InSimulation and not r.sim.Busy and not r.s.StatusSynchronizedMotion.StatusWord.X3
    # the master moves again: the slave follows at once without a new synchronization
    r.st["halt"], r.st["mv"] = False, True
    r.run(0.5)
    assert r.gear.InGear and not r.s.StatusWord.Synchronizing
    assert r.s.Position == pytest.approx(2 * r.m.Position, abs=1e-6)


def test_s7_1500_synchronous_velocity_setpoint_set_to_zero_at_start_s9_1_6():
    r = SimRig()
    r.until(lambda: r.gear.InGear)
    r.run(0.1)
    r.st["sim"] = True                  # the master is still moving (manual: 'should' be stopped)
    r.run(0.02)
    assert r.sim.InSimulation
    p = r.s.Position
    r.run(0.1)
    assert r.s.Velocity == 0.0 and r.s.Position == p
    assert r.s.StatusWord.Synchronous


def test_s7_1500_single_axis_job_during_simulation_moves_the_axis_and_keeps_the_sync_s3_4():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    p = r.s.Position
    r.st["rel"] = True
    r.until(lambda: r.rel.Done or r.rel.Error)
    assert r.rel.Done and r.s.Position == pytest.approx(p + 10.0)
    assert r.gear.InGear and not r.gear.CommandAborted and r.s.StatusWord.Synchronous
    assert r.sim.InSimulation
    # move back so that the positions match, then end the simulation: no step
    r.st["rel"], r.st["rel_dist"] = False, -10.0
    r.ctl.step()
    r.st["rel"] = True
    r.until(lambda: r.rel.Done)
    r.st["sim"] = False
    r.run(0.02)
    assert r.s.Position == pytest.approx(2 * r.m.Position, abs=1e-9)


def test_s7_1500_end_of_simulation_with_position_difference_is_a_setpoint_step_s9_1_6():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    r.st["rel"] = True
    r.until(lambda: r.rel.Done)
    assert r.s.Position != pytest.approx(2 * r.m.Position)
    r.st["sim"] = False
    r.ctl.step()
    assert r.s.Position == pytest.approx(2 * r.m.Position, abs=1e-9)   # acts immediately


def test_s7_1500_mc_stop_does_not_end_the_simulated_synchronous_operation_s9_1_6():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    r.st["stop"] = True
    r.run(0.1)
    assert r.sim.InSimulation and r.s.StatusWord.Synchronous and r.gear.InGear and not r.gear.CommandAborted
    r.st["stop"] = False
    r.run(0.05)
    r.st["sim"] = False
    r.run(0.05)
    assert r.gear.InGear and r.s.StatusSynchronizedMotion.FunctionState == 1


def test_s7_1500_superimposed_motion_continues_during_simulation_s3_4():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sup"] = True
    r.run(0.05)
    assert r.sup.Busy
    r.st["sim"] = True
    r.run(0.02)
    p = r.s.Position
    r.run(0.05)
    assert r.s.Position > p and r.sim.InSimulation      # superimposed setpoints still output
    r.until(lambda: r.sup.Done)


def test_s7_1500_synchronous_operation_jobs_rejected_while_enable_true_s9_1_6():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    r.pm2 = MC_Power()
    r.st["gear2"] = True
    r.run(0.02)
    assert r.gear2.Error and r.gear2.ErrorID != 0
    assert r.gear.InGear and not r.gear.CommandAborted


def test_s7_1500_restart_ends_simulation_and_aborts_synchronous_operation_s9_1_6():
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    r.st["slave_en"] = False
    r.run(0.05)
    r.st["reset"], r.st["restart"] = True, True
    r.run(0.1)
    assert not r.sim.InSimulation and not r.s.StatusSynchronizedMotion.StatusWord.X3
    assert not r.gear.Busy and not r.gear.InGear
    assert r.s.StatusSynchronizedMotion.FunctionState == 0


def test_s7_1500_lv_additive_allowed_in_simulation_while_disabled_s9_1_7():
    """§9.1.7 requirement: the TO is enabled OR in simulation with MC_SynchronizedMotionSimulation."""
    r = SimRig()
    r.synchronous_and_halted()
    r.st["sim"] = True
    r.run(0.02)
    r.st["slave_en"] = False
    r.run(0.05)
    r.st["lva"] = True
    r.run(0.02)
    assert r.lva.Busy and not r.lva.Error
    assert r.s.StatusSynchronizedMotion.StatusWord.X4


def test_s7_1500_rejected_while_synchronizing_s9_1_6():
    ctl = Controller(family="S7-1500T", app_cycle=0.001)
    m = ctl.add_positioning_axis("M", VIRTUAL)
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["M"])
    pm, ps, mv, gip, sim = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearInPos(), MC_SynchronizedMotionSimulation()
    st = {"sim": False}

    @ctl.program
    def main():
        pm(Axis=m, Enable=True)
        ps(Axis=s, Enable=True)
        mv(Axis=m, Execute=pm.Status, Velocity=50.0)
        gip(Master=m, Slave=s, Execute=ps.Status, MasterSyncPosition=100.0, SlaveSyncPosition=0.0,
            MasterStartDistance=50.0, SyncProfileReference=1)
        sim(Slave=s, Enable=st["sim"])
    ctl.run_until(lambda: gip.StartSync and not gip.InSync, timeout=5.0)
    assert s.StatusWord.Synchronizing and not s.StatusWord.Synchronous
    st["sim"] = True
    ctl.step()
    assert sim.Error and sim.ErrorID != 0 and not sim.InSimulation
    ctl.run_until(lambda: gip.InSync, timeout=5.0)
    assert not gip.CommandAborted
