"""A running job belongs to the technology objects it started on (issue 8, defect 5; PLCopen, S7-1500T
V5 §9.1): rewiring Axis/Slave/Master while an instruction is busy changes nothing until the next rising
edge of Execute (or Enable for the enable-type instructions MC_LeadingValueAdditive and
MC_SynchronizedMotionSimulation)."""
import pytest

from plcmotion.s7_1500 import (MC_CamIn, MC_GearIn, MC_GearInPos, MC_InterpolateCam, MC_LeadingValueAdditive,
                               MC_MoveVelocity, MC_PhasingAbsolute, MC_PhasingRelative,
                               MC_SynchronizedMotionSimulation)

from _s7_1500_rig import Rig


class Wired:
    """Master1, Master2 moving at 100 and 50; Slave1 and Slave2 geared 1:1 to Master1 (MC_GearIn); a
    program step calls the instruction under test with the wiring held in ``self.wire``."""

    def __init__(self, fb, **inputs):
        self.rig = rig = Rig(masters=2, slaves=2)
        self.fb = fb
        self.inputs = inputs
        self.mv = [MC_MoveVelocity(), MC_MoveVelocity()]
        self.gears = [MC_GearIn(), MC_GearIn()]
        self.wire = {}
        self.on = False
        rig.steps.append(lambda: self.mv[0](Axis=rig.masters[0], Execute=rig.enabled(), Velocity=100.0))
        rig.steps.append(lambda: self.mv[1](Axis=rig.masters[1], Execute=rig.enabled(), Velocity=50.0))
        for g, s in zip(self.gears, rig.slaves):
            rig.steps.append(lambda g=g, s=s: g(Master=rig.masters[0], Slave=s, Execute=rig.enabled()))
        rig.steps.append(self._call)
        rig.run_until(lambda: all(g.InGear for g in self.gears) and all(m.InVelocity for m in self.mv), timeout=3.0)

    def _call(self):
        edge = "Enable" if "Enable" in type(self.fb).INPUTS else "Execute"
        self.shift_before = self.s1.StatusSynchronizedMotion.PhaseShift     # what the call shows
        self.fb(**{edge: self.on}, **self.wire, **self.inputs)

    @property
    def s1(self):
        return self.rig.slaves[0]

    @property
    def s2(self):
        return self.rig.slaves[1]

    def lv(self, slave):
        return slave.StatusSynchronizedMotion.EffectiveLeadingValue.Position

    def m1(self):
        return float(self.rig.ctl.bank.sp_p[self.rig.masters[0].index])


def test_s7_1500_leading_value_additive_stays_on_its_axis_when_axis_is_rewired_defect5():
    """Defect 5: rewiring Axis while busy raised AttributeError or left the offset applied forever with
    Busy FALSE.  The additive value stays on the axis it started on until Enable FALSE; a new rising
    edge of Enable takes the new Axis."""
    w = Wired(MC_LeadingValueAdditive(), Position=10.0)
    w.wire = {"Axis": w.s1}
    w.on = True
    w.rig.run(0.02)
    assert w.fb.Busy and w.lv(w.s1) == pytest.approx(w.m1() + 10.0, abs=1e-9)
    for other in (w.s2, w.rig.masters[0], None, "no TO"):
        w.wire = {"Axis": other}
        w.rig.run(0.02)
        assert w.rig.ctl.mode == "RUN", w.rig.ctl.stop_reason
        assert w.fb.Busy and not w.fb.Error
        assert w.lv(w.s1) == pytest.approx(w.m1() + 10.0, abs=1e-9)
        assert w.lv(w.s2) == pytest.approx(w.m1(), abs=1e-9)
    w.on = False
    w.rig.run(0.02)
    assert not w.fb.Busy and not w.fb.Error
    assert w.lv(w.s1) == pytest.approx(w.m1(), abs=1e-9)       # removed from the axis it was on
    assert not w.s1.StatusSynchronizedMotion.StatusWord.X4
    w.wire = {"Axis": w.s2}
    w.on = True
    w.rig.run(0.02)
    assert w.fb.Busy and w.lv(w.s2) == pytest.approx(w.m1() + 10.0, abs=1e-9)
    assert w.lv(w.s1) == pytest.approx(w.m1(), abs=1e-9)


@pytest.mark.parametrize("cls", [MC_PhasingAbsolute, MC_PhasingRelative])
def test_s7_1500_phasing_stays_on_its_slave_when_slave_or_master_is_rewired_defect5(cls):
    """Defect 5: MC_PhasingAbsolute read its progress from the axis wired now (AttributeError for a
    positioning axis).  The phase shift runs to its end on the axis it started on and the progress
    output shows that axis; the other axis is not shifted."""
    w = Wired(cls(), PhaseShift=4.0, Velocity=20.0, Acceleration=200.0, Deceleration=200.0, Jerk=0.0)
    out = cls.PROGRESS
    w.wire = {"Master": w.rig.masters[0], "Slave": w.s1}
    w.on = True
    w.rig.run(0.02)
    assert w.fb.Busy
    for other in ({"Slave": w.s2}, {"Slave": w.rig.masters[1]}, {"Master": w.rig.masters[1]}, {"Slave": None}):
        w.wire = {"Master": w.rig.masters[0], "Slave": w.s1, **other}
        w.rig.ctl.step()
        assert w.rig.ctl.mode == "RUN", w.rig.ctl.stop_reason
        assert not w.fb.Error
        assert getattr(w.fb, out) == pytest.approx(w.shift_before, abs=1e-9) and w.shift_before > 0.0
    w.rig.run_until(lambda: w.fb.Done or w.fb.Error, timeout=2.0)
    assert w.fb.Done and getattr(w.fb, out) == pytest.approx(4.0)
    assert w.s1.StatusSynchronizedMotion.PhaseShift == pytest.approx(4.0)
    assert w.s2.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_synchronized_motion_simulation_ends_on_its_slave_when_rewired_defect5():
    """MC_SynchronizedMotionSimulation: Enable FALSE ended the simulation of the axis wired at that
    moment, leaving the first one simulating forever with Busy FALSE.  Rewiring acts at the next edge."""
    w = Wired(MC_SynchronizedMotionSimulation())
    w.wire = {"Slave": w.s1}
    w.on = True
    w.rig.run(0.02)
    assert w.fb.InSimulation and w.fb.Busy
    p1 = w.s1.Position
    w.wire = {"Slave": w.s2}
    w.rig.run(0.02)
    assert w.fb.InSimulation and w.fb.Busy and not w.fb.Error
    assert w.s1.Position == pytest.approx(p1)                  # still simulated: the axis stands
    assert w.s2.Velocity == pytest.approx(100.0)               # not simulated: it moves with Master1
    w.wire = {"Slave": "no TO"}
    w.rig.run(0.02)
    assert w.fb.InSimulation and not w.fb.Error
    w.on = False
    w.rig.run(0.02)
    assert not w.fb.Busy and not w.fb.InSimulation
    assert w.s1.Velocity == pytest.approx(100.0)               # simulation over: it moves again
    assert w.gears[0].InGear and w.gears[1].InGear


@pytest.mark.parametrize("cls", [MC_GearIn, MC_GearInPos, MC_CamIn])
def test_s7_1500_synchronous_operation_stays_on_its_objects_when_rewired_defect5(cls):
    """MC_GearIn, MC_GearInPos, MC_CamIn: rewiring Slave and Master while busy leaves the synchronous
    operation where it started; the next rising edge of Execute starts one with the new wiring."""
    rig = Rig(masters=2, slaves=2)
    cam = rig.ctl.add_cam("Cam", points=[(0, 0), (360, 360)], interpolation_mode=0)
    ic = MC_InterpolateCam()
    mv = [MC_MoveVelocity(), MC_MoveVelocity()]
    fb = cls()
    st = {"exe": False, "Master": rig.masters[0], "Slave": rig.slaves[0]}
    extra = {}
    if cls is MC_GearInPos:
        extra = dict(SyncProfileReference=4 - 1, SlaveSyncPosition=0.0, MasterStartDistance=5.0)
    elif cls is MC_CamIn:
        extra = dict(Cam=cam, SyncProfileReference=2, ApplicationMode=1)
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv[0](Axis=rig.masters[0], Execute=rig.enabled(), Velocity=100.0))
    rig.steps.append(lambda: mv[1](Axis=rig.masters[1], Execute=rig.enabled(), Velocity=-50.0))
    rig.steps.append(lambda: fb(Execute=st["exe"], Master=st["Master"], Slave=st["Slave"], **extra))
    rig.run_until(lambda: ic.Done and rig.enabled() and mv[0].InVelocity and mv[1].InVelocity, timeout=3.0)
    if cls is MC_GearInPos:
        extra["MasterSyncPosition"] = rig.masters[0].Position + 5.0
    st["exe"] = True
    done = (lambda: fb.InGear) if cls is MC_GearIn else (lambda: fb.InSync)
    rig.run_until(lambda: done() or fb.Error, timeout=3.0)
    assert done(), hex(fb.ErrorID)
    s1, s2 = rig.slaves
    for wiring in ({"Slave": s2}, {"Master": rig.masters[1]}, {"Slave": rig.masters[1]}, {"Slave": None}):
        st.update(wiring)
        rig.run(0.02)
        assert rig.ctl.mode == "RUN" and fb.Busy and done() and not fb.Error
        assert s1.Velocity == pytest.approx(100.0, abs=1e-6)       # still following Master1
        assert s2.Velocity == 0.0
    st.update(Master=rig.masters[1], Slave=s2, exe=False)
    rig.ctl.step()
    if cls is MC_GearInPos:
        extra["MasterSyncPosition"] = rig.masters[1].Position - 5.0
    st["exe"] = True
    rig.ctl.step()
    assert fb.Busy and (cls is MC_CamIn or not done())             # a new job has started (CamIn: direct)
    rig.run_until(lambda: done() or fb.Error, timeout=3.0)
    assert done() and s2.Velocity == pytest.approx(-50.0, abs=1e-6)
    assert s1.Velocity == pytest.approx(100.0, abs=1e-6)           # the first job keeps running
    assert s1.StatusSynchronizedMotion.FunctionState != 0
