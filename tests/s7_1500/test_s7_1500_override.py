"""The override response tables of S7-1500T V5 §9.3.1 and §9.3.2, cell by cell: a job of one class is
running on the following axis, a job of another class starts, and the running one is aborted
(CommandAborted) or goes on."""
import pytest

from plcmotion.s7_1500.technology import override as O
from plcmotion.s7_1500 import (MC_GearIn, MC_GearInPos, MC_Halt, MC_Home, MC_LeadingValueAdditive,
                               MC_MoveRelative, MC_MoveSuperimposed, MC_MoveVelocity, MC_PhasingRelative, MC_Stop)

from _s7_1500_rig import Rig

SERVO = {"Actor": {"Type": 1}, "Sensor": {"Sensor[1]": {"ActiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"},
                                                       "PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
         "Plant": {"HomingSwitchPosition": 1.0e6}, "FollowingError": {"MaxValue": 1000.0, "MinValue": 1000.0},
         "DynamicLimits": {"MaxVelocity": 1000.0}}


class Scenario:
    """A running job on the following axis and a new one; ``fbs`` are the instances by name."""

    def __init__(self):
        self.rig = Rig(slave_params=SERVO)
        self.rig.ctl.inputs["I0.0"] = False
        self.fbs = {}
        self.exe = {}
        r = self.rig
        mv = MC_MoveVelocity()
        r.steps.append(lambda: mv(Axis=r.master, Execute=r.enabled(), Velocity=50.0))
        r.run_until(lambda: mv.InVelocity, timeout=2.0)

    def add(self, name, fb, **inputs):
        self.fbs[name] = fb
        self.exe[name] = False
        execute = "Enable" if isinstance(fb, MC_LeadingValueAdditive) else "Execute"
        r = self.rig
        slave_input = "Axis" if "Axis" in fb.INPUTS else "Slave"
        extra = {"Master": r.master} if "Master" in fb.INPUTS else {}
        r.steps.append(lambda: fb(**{slave_input: r.slave, execute: self.exe[name], **extra, **inputs}))
        return fb

    def start(self, name, until=None, timeout=3.0):
        self.exe[name] = True
        fb = self.fbs[name]
        self.rig.run_until(until or (lambda: fb.Busy or fb.Error), timeout=timeout)
        assert not fb.Error, f"{name}: 16#{fb.ErrorID:04X}"


def running_job(sc: Scenario, cls: str):
    """Start a job of class ``cls`` on the following axis; returns the instance that shows its state."""
    m = sc.rig.master
    if cls == O.HOME_PASSIVE:
        fb = sc.add("run", MC_Home(), Mode=2)
        sc.start("run")
    elif cls == O.HOME_ACTIVE:
        fb = sc.add("run", MC_Home(), Mode=3)
        sc.start("run")
    elif cls == O.MOTION:
        fb = sc.add("run", MC_MoveVelocity(), Velocity=20.0)
        sc.start("run", lambda: fb.InVelocity)
    elif cls == O.STOP:
        v = sc.add("pre", MC_MoveVelocity(), Velocity=400.0)
        sc.start("pre", lambda: v.InVelocity)
        fb = sc.add("run", MC_Stop(), Mode=2)
        sc.start("run")
    elif cls == O.SUPERIMPOSED:
        fb = sc.add("run", MC_MoveSuperimposed(), Distance=1.0e5, VelocityDiff=10.0)
        sc.start("run")
    elif cls == O.GEAR_IN:
        fb = sc.add("run", MC_GearIn())
        sc.start("run", lambda: fb.InGear)
    elif cls == O.SYNC_WAITING:
        fb = sc.add("run", MC_GearInPos(), MasterSyncPosition=m.Position + 1.0e4, SyncProfileReference=1,
                    MasterStartDistance=10.0)
        sc.start("run")
    elif cls == O.SYNC_ACTIVE:
        fb = sc.add("run", MC_GearInPos(), MasterSyncPosition=m.Position + 20.0, SyncProfileReference=1,
                    MasterStartDistance=10.0)
        sc.start("run", lambda: fb.InSync)
    elif cls == O.PHASING:
        gear = sc.add("gear", MC_GearIn())
        sc.start("gear", lambda: gear.InGear)
        fb = sc.add("run", MC_PhasingRelative(), PhaseShift=1.0e4, Velocity=10.0)
        sc.start("run")
    elif cls == O.LV_ADDITIVE:
        fb = sc.add("run", MC_LeadingValueAdditive(), Position=0.0)
        sc.start("run")
    else:  # pragma: no cover
        raise ValueError(cls)
    return fb


def new_job(sc: Scenario, cls: str):
    """Start a job of class ``cls``; returns (instance, condition for 'the job has taken effect')."""
    m = sc.rig.master
    if cls == O.HOME_ACTIVE:
        fb = sc.add("new", MC_Home(), Mode=3)
    elif cls == O.HOME_CANCEL:
        fb = sc.add("new", MC_Home(), Mode=9)
    elif cls == O.HALT:
        fb = sc.add("new", MC_Halt())
    elif cls == O.MOTION:
        fb = sc.add("new", MC_MoveRelative(), Distance=5.0)
    elif cls == O.SUPERIMPOSED:
        fb = sc.add("new", MC_MoveSuperimposed(), Distance=1.0)
    elif cls == O.STOP:
        fb = sc.add("new", MC_Stop(), Mode=0)
    elif cls == O.GEAR_IN:
        fb = sc.add("new", MC_GearIn(), RatioNumerator=2)
    elif cls == O.SYNC_WAITING:
        fb = sc.add("new", MC_GearInPos(), MasterSyncPosition=m.Position + 2.0e4, SyncProfileReference=1,
                    MasterStartDistance=10.0)
    elif cls == O.SYNC_ACTIVE:
        fb = sc.add("new", MC_GearInPos(), RatioNumerator=3, MasterSyncPosition=m.Position + 30.0,
                    SyncProfileReference=1, MasterStartDistance=10.0)
        sc.exe["new"] = True
        return fb, lambda: fb.StartSync or fb.Error
    elif cls == O.PHASING:
        fb = sc.add("new", MC_PhasingRelative(), PhaseShift=1.0)
    elif cls == O.LV_ADDITIVE:
        fb = MC_LeadingValueAdditive()
        sc.add("new", fb, Position=0.0)
        sc.exe["new"] = True
        return fb, lambda: True
    else:  # pragma: no cover
        raise ValueError(cls)
    sc.exe["new"] = True
    return fb, lambda: True


def aborted(fb) -> bool:
    if isinstance(fb, MC_LeadingValueAdditive):
        return not fb.Busy
    return fb.CommandAborted


RUNNING = [O.HOME_PASSIVE, O.HOME_ACTIVE, O.MOTION, O.STOP, O.SUPERIMPOSED, O.GEAR_IN, O.SYNC_WAITING,
           O.SYNC_ACTIVE, O.PHASING, O.LV_ADDITIVE]
NEW = [O.HOME_ACTIVE, O.HOME_CANCEL, O.HALT, O.MOTION, O.SUPERIMPOSED, O.STOP, O.GEAR_IN, O.SYNC_WAITING,
       O.SYNC_ACTIVE, O.LV_ADDITIVE, O.PHASING]
# cells the tables do not fill, or that need a state the running job excludes
SKIP = {(O.PHASING, r) for r in RUNNING if r != O.PHASING}

# The two tables of S7-1500T V5 §9.3.1 and §9.3.2 as printed (rows: new job, columns: running job; A = the
# running job is aborted, - = it goes on; the MC_MotionIn* row and column are left out: no such instruction
# here).  Written out from the manual, not taken from the code under test.
_COLUMNS_9_3_1 = (O.HOME_PASSIVE, O.HOME_ACTIVE, O.MOTION, O.STOP, O.SUPERIMPOSED)
_TABLE_9_3_1 = {
    #                Home 2/8/10  Home 3/5  Halt/Move*/Jog  Stop  MoveSuperimposed
    O.HOME_ACTIVE:  "A            A         A               -     A",
    O.HOME_CANCEL:  "A            -         -               -     -",
    O.HALT:         "-            A         A               -     A",
    O.MOTION:       "-            A         A               -     A",
    O.SUPERIMPOSED: "-            -         -               -     A",
    # "B": a stop is aborted by a stop with the same or a higher stop response; the new MC_Stop here
    # (Mode 0, emergency stop) is higher than the running one (Mode 2, maximum dynamic values)
    O.STOP:         "A            A         A               B     A",
    O.GEAR_IN:      "-            A         A               -     A",
    O.SYNC_WAITING: "-            -         -               -     -",
    O.SYNC_ACTIVE:  "-            A         A               -     A",
    O.LV_ADDITIVE:  "-            -         -               -     -",
}
_COLUMNS_9_3_2 = (O.GEAR_IN, O.SYNC_WAITING, O.SYNC_ACTIVE, O.PHASING, O.LV_ADDITIVE)
_TABLE_9_3_2 = {
    #                GearIn  waiting  active  Phasing  LeadingValueAdditive
    O.HOME_ACTIVE:  "A       -        -       -        -",
    O.HALT:         "A       -        A       A        -",
    O.MOTION:       "A       -        A       A        -",
    O.SUPERIMPOSED: "-       -        -       -        -",
    O.STOP:         "A       A        A       A        A",
    O.GEAR_IN:      "A       A        A       A        -",
    O.SYNC_WAITING: "-       A        -       -        -",
    O.SYNC_ACTIVE:  "A       A        A       A        -",
    O.PHASING:      "-       -        -       A        -",
    O.LV_ADDITIVE:  "-       -        -       -        A",
    # MC_Home Mode 9 is not a row of §9.3.2: it only cancels a passive homing, a synchronous job goes on
    O.HOME_CANCEL:  "-       -        -       -        -",
}


def manual_aborts(new: str, running: str) -> bool | None:
    """One cell of the manual's tables (None: the manual has no such cell)."""
    columns, table = (_COLUMNS_9_3_1, _TABLE_9_3_1) if running in _COLUMNS_9_3_1 else (_COLUMNS_9_3_2, _TABLE_9_3_2)
    return table[new].split()[columns.index(running)] in ("A", "B") if new in table else None


@pytest.mark.parametrize("new", NEW)
@pytest.mark.parametrize("running", RUNNING)
def test_s7_1500_override_response_s9_3(running, new):
    if (new, running) in SKIP:
        pytest.skip("phasing needs a synchronous gearing")
    sc = Scenario()
    run = running_job(sc, running)
    fb, effective = new_job(sc, new)
    sc.rig.run_until(effective, timeout=3.0)
    sc.rig.run(0.02)
    expect = manual_aborts(new, running)
    if running == O.PHASING:
        # a phasing job lives on its gearing: a job that aborts the MC_GearIn ends the phasing with it
        expect = expect or manual_aborts(new, O.GEAR_IN)
    assert aborted(run) == expect, (f"new {new} / running {running}: new Error={getattr(fb, 'Error', None)} "
                                    f"16#{getattr(fb, 'ErrorID', 0):04X}")


def test_s7_1500_the_code_tables_match_the_manual_s9_3():
    """s7_1500.technology.override holds the same cells as the manual's tables (both written out independently)."""
    cells = [(new, running) for new in NEW for running in RUNNING if manual_aborts(new, running) is not None]
    # only a phase shift against a running homing or motion job has no cell (it needs a gearing)
    assert len(cells) == len(NEW) * len(RUNNING) - len(_COLUMNS_9_3_1)
    for new, running in cells:
        assert O.aborts(new, running) == manual_aborts(new, running), (new, running)


def test_s7_1500_the_table_cells_s9_3_1_and_s9_3_2():
    """Spot checks of the tables as printed in the manual."""
    assert O.aborts(O.HOME_ACTIVE, O.HOME_PASSIVE) and not O.aborts(O.HOME_ACTIVE, O.STOP)
    assert O.aborts(O.HOME_CANCEL, O.HOME_PASSIVE) and not O.aborts(O.HOME_CANCEL, O.MOTION)
    assert not O.aborts(O.SUPERIMPOSED, O.MOTION) and O.aborts(O.SUPERIMPOSED, O.SUPERIMPOSED)
    assert O.aborts(O.STOP, O.STOP) and O.aborts(O.STOP, O.LV_ADDITIVE)
    assert not O.aborts(O.SYNC_WAITING, O.MOTION) and O.aborts(O.SYNC_ACTIVE, O.MOTION)
    assert not O.aborts(O.HALT, O.SYNC_WAITING) and O.aborts(O.HALT, O.SYNC_ACTIVE)
    assert O.aborts(O.HOME_ACTIVE, O.GEAR_IN) and not O.aborts(O.HOME_ACTIVE, O.SYNC_ACTIVE)
    assert not O.aborts(O.SUPERIMPOSED, O.GEAR_IN) and not O.aborts(O.GEAR_IN, O.LV_ADDITIVE)
    assert O.aborts(O.SYNC_WAITING, O.SYNC_WAITING) and not O.aborts(O.SYNC_WAITING, O.GEAR_IN)
    assert O.aborts(O.PHASING, O.PHASING) and not O.aborts(O.PHASING, O.GEAR_IN)
    assert O.aborts(O.LV_ADDITIVE, O.LV_ADDITIVE) and not O.aborts(O.LV_ADDITIVE, O.SYNC_ACTIVE)


def test_s7_1500_waiting_job_aborts_nothing_until_it_starts_synchronizing_s9_3_2_note1():
    sc = Scenario()
    run = running_job(sc, O.MOTION)
    m = sc.rig.master
    gip = sc.add("new", MC_GearInPos(), MasterSyncPosition=m.Position + 40.0, SyncProfileReference=1,
                 MasterStartDistance=20.0)
    sc.exe["new"] = True
    sc.rig.ctl.step()
    sc.rig.ctl.step()
    assert gip.Busy and not gip.StartSync and not run.CommandAborted and run.InVelocity
    sc.rig.run_until(lambda: gip.StartSync, timeout=2.0)
    sc.rig.ctl.step()
    assert run.CommandAborted


def test_s7_1500_mc_stop_locks_the_axis_until_execute_is_reset_s9_3_1():
    sc = Scenario()
    stop = running_job(sc, O.STOP)
    sc.rig.run_until(lambda: stop.Done, timeout=5.0)
    assert sc.rig.slave.StatusWord2.X0
    move = sc.add("move", MC_MoveRelative(), Distance=1.0)
    sc.exe["move"] = True
    sc.rig.run_until(lambda: move.Error, timeout=1.0)
    assert stop.Done and not stop.CommandAborted
    sc.exe["run"] = False
    sc.exe["move"] = False
    sc.rig.run(0.02)
    assert not sc.rig.slave.StatusWord2.X0
    sc.exe["move"] = True
    sc.rig.run_until(lambda: move.Done, timeout=2.0)


def test_s7_1500_a_weaker_mc_stop_does_not_abort_a_stronger_one_s9_3_1_b():
    sc = Scenario()
    v = sc.add("pre", MC_MoveVelocity(), Velocity=400.0)
    sc.start("pre", lambda: v.InVelocity)
    strong = sc.add("strong", MC_Stop(), Mode=0)
    weak = sc.add("weak", MC_Stop(), Mode=2)
    sc.exe["strong"] = True
    sc.rig.ctl.step()
    sc.exe["weak"] = True
    sc.rig.run_until(lambda: weak.Error or strong.Done, timeout=2.0)
    assert weak.Error and not strong.CommandAborted
