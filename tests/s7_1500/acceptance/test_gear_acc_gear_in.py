"""MC_GearIn (S7-1500T V5 §4.1, §4.3.1, §4.4.1, §9.1.1): outputs and status tags over time, synchronous criterion,
overrides, dynamic limits, master reversal."""
import pytest
from plcmotion.s7_1500 import MC_GearIn, MC_Halt, MC_MoveVelocity, MC_MoveRelative, MC_MoveSuperimposed
from _gear_h import H, VIRTUAL, merge, outputs_consistent


def _rec(h, fb):
    sm = h.s.StatusSynchronizedMotion
    h.rec = lambda: {"t": h.ctl.time, "m": h.m.Position, "mv": h.m.Velocity, "ma": h.m.Acceleration,
                     "s": h.s.Position, "sv": h.s.Velocity, "sa": h.s.Acceleration,
                     "Busy": fb.Busy, "InGear": fb.InGear, "Abort": fb.CommandAborted, "Error": fb.Error,
                     "X21": h.s.StatusWord.X21, "X22": h.s.StatusWord.X22, "fs": sm.FunctionState,
                     "am": sm.ActualMaster, "bad": outputs_consistent(fb)}


def _gear(h, **inp):
    fb = MC_GearIn()
    d = {"Master": h.m, "Slave": h.s, "Execute": False}
    d.update(inp)
    h.call(fb, d)
    _rec(h, fb)
    return fb, d


def test_s7_1500_gear_in_outputs_and_tags_timeline():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=3, RatioDenominator=2, Acceleration=500.0, Deceleration=500.0, Jerk=1e4)
    d["Execute"] = True
    h.step()
    r = h.rows[-1]
    assert r["Busy"] and not r["InGear"] and r["X21"] and not r["X22"]
    assert r["fs"] == 1 and r["am"] == h.m.db_number
    h.until(lambda: fb.InGear, 3.0)
    h.run(0.3)
    for r in h.rows:
        assert not r["bad"], r
        assert not (r["X21"] and r["X22"]), r
        assert r["X22"] == r["InGear"], r   # InGear and StatusWord.X22 in the same call
    first = next(r for r in h.rows if r["InGear"])
    assert first["sv"] == pytest.approx(1.5 * first["mv"], abs=1e-6)
    # synchronous: following value = const + ratio * leading value
    sync = [r for r in h.rows if r["InGear"]]
    c0 = sync[0]["s"] - 1.5 * sync[0]["m"]
    for r in sync:
        assert r["s"] - 1.5 * r["m"] == pytest.approx(c0, abs=1e-6)


def test_s7_1500_gear_in_synchronizing_respects_job_acceleration():
    """§4.3.1/§4.4.1: during synchronization the following axis moves with the job's dynamics (master at
    constant velocity, so the slave's acceleration is the synchronizing part only)."""
    h = H()
    h.move_master(200.0)
    fb, d = _gear(h, Acceleration=400.0, Deceleration=400.0, Jerk=0.0)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    accs = [abs(r["sa"]) for r in h.rows if r["X21"]]
    assert max(accs) <= 400.0 * (1 + 1e-6)
    # trapezoid, from standstill to 200: 0.5 s
    t0 = next(r["t"] for r in h.rows if r["Busy"])
    t1 = next(r["t"] for r in h.rows if r["InGear"])
    assert t1 - t0 == pytest.approx(0.5, abs=0.02)


def test_s7_1500_gear_in_in_acceleration_phase_needs_ratio_times_acceleration():
    """§4.1: synchronous when velocity AND acceleration of the leading axis times the ratio are reached."""
    h = H()
    mv = MC_MoveVelocity()
    h.call(mv, {"Axis": h.m, "Execute": True, "Velocity": 500.0, "Acceleration": 100.0, "Deceleration": 100.0,
                "Jerk": 0.0})
    fb, d = _gear(h, RatioNumerator=2, Acceleration=5000.0, Deceleration=5000.0, Jerk=0.0)
    h.until(lambda: h.m.Velocity > 50.0, 3.0)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    r = h.rows[-1]
    assert r["ma"] == pytest.approx(100.0, abs=1e-6)
    assert r["sv"] == pytest.approx(2 * r["mv"], abs=1e-6)
    assert r["sa"] == pytest.approx(200.0, abs=1e-6)


def test_s7_1500_gear_in_master_at_standstill():
    h = H()
    fb, d = _gear(h)
    h.until(h.enabled, 1.0)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 1.0)
    assert fb.Busy and h.s.StatusWord.X22


def test_s7_1500_gear_in_negative_ratio():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=-1, RatioDenominator=4)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    h.run(0.1)
    assert h.s.Velocity == pytest.approx(-25.0, abs=1e-6)


def test_s7_1500_gear_in_follows_master_reversal_and_stays_in_gear():
    h = H()
    mv, inp = h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=2)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    n = len(h.rows)
    inp.update(Execute=False)
    h.step()
    inp.update(Execute=True, Velocity=-100.0, Acceleration=500.0, Deceleration=500.0)
    h.step()
    h.until(lambda: mv.InVelocity, 3.0)
    h.run(0.1)
    rows = h.rows[n:]
    assert all(r["InGear"] and r["Busy"] and r["X22"] for r in rows)
    assert h.s.Velocity == pytest.approx(-200.0, abs=1e-6)
    c = [r["s"] - 2 * r["m"] for r in rows]
    assert max(c) - min(c) < 1e-6


def test_s7_1500_gear_in_ratio_change_on_same_master_with_second_instance():
    """§9.3.2: MC_GearIn aborts an active MC_GearIn; the new ratio is reached by synchronizing (no jump)."""
    h = H()
    h.move_master(100.0)
    a1, d1 = _gear(h, RatioNumerator=1)
    a2 = MC_GearIn()
    d2 = h.call(a2, {"Master": h.m, "Slave": h.s, "Execute": False, "RatioNumerator": 2, "Acceleration": 500.0,
                     "Deceleration": 500.0, "Jerk": 0.0})
    d1["Execute"] = True
    h.until(lambda: a1.InGear, 3.0)
    n = len(h.rows)
    d2["Execute"] = True
    h.step(2)
    assert a1.CommandAborted and not a1.Busy and not a1.InGear
    assert a2.Busy and not a2.InGear and h.s.StatusWord.X21 and not h.s.StatusWord.X22
    h.until(lambda: a2.InGear, 3.0)
    assert h.s.Velocity == pytest.approx(200.0, abs=1e-6)
    sv = [r["sv"] for r in h.rows[n - 1:]]
    assert max(abs(b - a) for a, b in zip(sv, sv[1:])) <= 500.0 * 0.004 + 1e-6   # no velocity step


def test_s7_1500_gear_in_ratio_change_same_instance_retrigger():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=1, Acceleration=500.0, Deceleration=500.0, Jerk=0.0)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    d["Execute"] = False
    h.step()
    assert fb.Busy and fb.InGear          # Execute FALSE does not end gearing
    d.update(Execute=True, RatioNumerator=3)
    h.step()
    assert fb.Busy and not fb.Error and not fb.InGear
    h.until(lambda: fb.InGear, 3.0)
    assert h.s.Velocity == pytest.approx(300.0, abs=1e-6)


@pytest.mark.parametrize("kind", ["halt", "move_velocity", "move_relative"])
def test_s7_1500_single_axis_job_aborts_gear_in(kind):
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=2)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    n = len(h.rows)
    if kind == "halt":
        new = MC_Halt()
        inp = {"Axis": h.s, "Execute": True, "Deceleration": 1000.0, "Jerk": 0.0}
    elif kind == "move_velocity":
        new = MC_MoveVelocity()
        inp = {"Axis": h.s, "Execute": True, "Velocity": -50.0, "Acceleration": 1000.0, "Deceleration": 1000.0,
               "Jerk": 0.0}
    else:
        new = MC_MoveRelative()
        inp = {"Axis": h.s, "Execute": True, "Distance": 100.0, "Velocity": 100.0, "Acceleration": 1000.0,
               "Deceleration": 1000.0, "Jerk": 0.0}
    h.call(new, inp)
    h.step(2)
    assert fb.CommandAborted and not fb.Busy and not fb.InGear and not fb.Error
    assert new.Busy and not new.Error
    sm = h.s.StatusSynchronizedMotion
    assert sm.FunctionState == 0 and sm.ActualMaster == 0
    assert not h.s.StatusWord.X21 and not h.s.StatusWord.X22
    # §4.4.1 override: active dynamics transitioned (smoothed), no velocity step
    sv = [r["sv"] for r in h.rows[n - 1:]]
    assert max(abs(b - a) for a, b in zip(sv, sv[1:])) <= 1000.0 * 0.004 + 1e-6
    h.until(lambda: getattr(new, "InVelocity", False) or getattr(new, "Done", False), 5.0)


def test_s7_1500_superimposed_does_not_abort_gear_in():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    sup = MC_MoveSuperimposed()
    h.call(sup, {"Axis": h.s, "Execute": True, "Distance": 10.0, "VelocityDiff": 50.0, "AccelerationDiff": 1000.0,
                 "DecelerationDiff": 1000.0, "JerkDiff": 0.0})
    h.until(lambda: sup.Done, 3.0)
    assert fb.InGear and fb.Busy and not fb.CommandAborted


def test_s7_1500_gear_in_synchronous_exceeds_configured_limits_warns_not_errors():
    """§4.4.1: in synchronous motion only Actor.DriveParameter.MaxSpeed limits; exceeding the configured
    MaxVelocity is shown in StatusSynchronizedMotion.StatusWord.X0, no error."""
    h = H(sp=merge(VIRTUAL, {"DynamicLimits": {"MaxVelocity": 200.0, "Velocity": 200.0}}))
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=3)
    d["Execute"] = True
    h.until(lambda: fb.InGear or fb.Error, 3.0)
    h.run(0.1)
    assert fb.InGear and not fb.Error
    assert h.s.Velocity == pytest.approx(300.0, abs=1e-6)
    assert h.s.StatusSynchronizedMotion.StatusWord.X0
    assert h.s.ErrorWord == 0 and not h.s.StatusWord.X1


def test_s7_1500_gear_in_acceleration_above_limit_is_limited_not_rejected():
    """§4.4.1: 'During the synchronizing phase, dynamic limits configured for the technology object apply to
    the following axis.'  §A DynamicLimits: greater values given at an instruction -> motion with the limits
    and a warning (alarms 501-503, WarningWord.X6 DynamicWarning)."""
    h = H(sp=merge(VIRTUAL, {"DynamicLimits": {"MaxAcceleration": 300.0, "MaxDeceleration": 300.0}}))
    h.move_master(100.0)
    fb, d = _gear(h, Acceleration=5000.0, Deceleration=5000.0, Jerk=0.0)
    d["Execute"] = True
    h.step()
    assert fb.Busy and not fb.Error
    warned = h.s.WarningWord.X6
    h.until(lambda: fb.InGear, 3.0)
    accs = [abs(r["sa"]) for r in h.rows if r["X21"]]
    assert max(accs) <= 300.0 * (1 + 1e-6), f"max slave acceleration while synchronizing {max(accs)}"
    assert warned, "WarningWord.X6 (DynamicWarning) not set"


def test_s7_1500_gear_in_dynamic_warning_when_acceleration_above_limit():
    h = H(sp=merge(VIRTUAL, {"DynamicLimits": {"MaxAcceleration": 300.0, "MaxDeceleration": 300.0}}))
    h.move_master(100.0)
    fb, d = _gear(h, Acceleration=5000.0, Deceleration=5000.0, Jerk=0.0)
    d["Execute"] = True
    h.step()
    assert h.s.WarningWord.X6, "WarningWord.X6 (DynamicWarning) not set"


def test_s7_1500_disable_slave_aborts_gear_in_with_command_aborted():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    h.en["S1"] = False
    h.run(0.2)
    assert fb.CommandAborted and not fb.Busy and not fb.InGear and not fb.Error
    assert h.s.StatusSynchronizedMotion.FunctionState == 0


def test_s7_1500_disable_master_keeps_gear_in_during_braking_ramp():
    h = H()
    h.move_master(100.0)
    fb, d = _gear(h, RatioNumerator=2)
    d["Execute"] = True
    h.until(lambda: fb.InGear, 3.0)
    n = len(h.rows)
    h.en["M1"] = False
    h.run(0.5)
    rows = h.rows[n:]
    assert all(r["InGear"] and r["Busy"] for r in rows)
    c = [r["s"] - 2 * r["m"] for r in rows]
    assert max(c) - min(c) < 1e-6
    assert abs(h.m.Velocity) < 1e-9 and abs(h.s.Velocity) < 1e-9
    # after re-enable the slave follows again
    h.en["M1"] = True
    h.until(lambda: h.power["M1"].Status, 1.0)
    h.move_master(50.0)
    h.run(0.1)
    assert h.s.Velocity == pytest.approx(100.0, abs=1e-6) and fb.InGear
