"""Synchronous operation robustness (issue 8): a non-finite leading value never reaches a following
setpoint (defect 2, the sync stage itself), SyncDirection with a short modulo axis (defect 4), internal
errors end their job, and MC_CamIn with its defaults synchronizes at once (S7-1500T V5 §9.1.5.1,
decision 19)."""
import math

import pytest

from plcmotion import Controller
from plcmotion.kernel import sync_planning
from plcmotion.s7_1500 import MC_CamIn, MC_GearIn, MC_GearInPos, MC_InterpolateCam, MC_MoveVelocity, MC_Power

from _s7_1500_rig import VIRTUAL, Rig, merge, modulo

FINE = {"Sensor[1]": {"Parameter": {"DistancePerRevolution": 100.0, "StepsPerRevolution": 1 << 20}}}


# --- defect 2: the sync stage guards every source ------------------------------------------------------

@pytest.mark.parametrize("mode", ["actual", "delayed"])
def test_s7_1500_absurd_leading_value_of_an_external_encoder_never_reaches_the_follower_defect2(mode):
    """Whatever the source, a leading value that is not a finite number in range must not produce a
    following setpoint: here an external encoder whose machine jumps to 1e300 (public drive_plant).  The
    follower goes on one cycle with its last leading value carried forward, then the gearing ends with
    an error (alarm: invalid leading value) and the follower brakes from where it is."""
    ctl = Controller(family="S7-1500T", app_cycle=0.001)
    enc = ctl.add_external_encoder("Enc", {"Sensor": FINE, "Plant": {"Velocity": 100.0}})
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("Enc", mode)])
    pe, ps, gear = MC_Power(), MC_Power(), MC_GearIn()
    go = []

    @ctl.program
    def main():
        pe(Axis=enc, Enable=True)
        ps(Axis=s, Enable=True)
        # Execute stays TRUE once started: the encoder fault (alarm 411) removes the encoder's enable,
        # and with a falling Execute the gearing's Error would show for one call only
        if pe.Status and ps.Status and not go:
            go.append(True)
        gear(Master=enc, Slave=s, Execute=bool(go))
    ctl.run_until(lambda: gear.InGear, timeout=2.0)
    ctl.run(0.1)
    jump = ctl.time + 0.005
    x0 = enc.plant_position
    enc.drive_plant(lambda t: 1e300 if t >= jump else x0 + 100.0 * (t - jump + 0.005))
    rows = []
    for _ in range(150):
        ctl.step()
        if ctl.time >= jump:
            rows.append((s.Position, s.ActualPosition, s.Velocity))
            assert all(math.isfinite(v) and abs(v) < 1e6 for v in rows[-1]), rows[-1]
    assert ctl.mode == "RUN"
    assert gear.Error and not gear.InGear and not gear.Busy and gear.ErrorID == 0x8001
    assert s.StatusWord.Error
    assert enc.ErrorDetail.Number == 411 and enc.ErrorWord.X5      # the value never left the encoder
    steps = [b[0] - a[0] for a, b in zip(rows, rows[1:])]
    assert all(-1e-9 <= d <= 100.0 * 0.001 * 1.01 for d in steps)          # brakes, no step, no reversal
    assert rows[-1][2] == pytest.approx(0.0, abs=1e-9)


# --- defect 4: SyncDirection on a short modulo following axis -------------------------------------------

def _modulo_rig(kind, spr, direction, cam_points=((0, 0), (100, 25.5), (200, 60.8))):
    rig = Rig(slave_params=merge(VIRTUAL, modulo(1.0)))
    mv = MC_MoveVelocity()
    job = MC_GearInPos() if kind == "gear" else MC_CamIn()
    ic = MC_InterpolateCam()
    cam = rig.ctl.add_cam("Cam", points=list(cam_points), interpolation_mode=1)
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=rig.enabled(), Velocity=50.0))
    args = dict(Master=rig.master, Slave=rig.slave, SyncProfileReference=spr, SyncDirection=direction,
                MasterSyncPosition=40.0, MasterStartDistance=10.0)
    if kind == "gear":
        args["SlaveSyncPosition"] = 0.3
    else:
        args.update(Cam=cam, ApplicationMode=1)
    rig.steps.append(lambda: job(Execute=rig.enabled() and ic.Done, **args))
    rows = []
    rig.record = lambda: dict(s=float(rig.ctl.bank.sp_p[rig.slave.index]), v=float(rig.ctl.bank.sp_v[rig.slave.index]),
                              start=job.StartSync, in_sync=job.InSync, busy=job.Busy, error=job.Error)
    return rig, job, cam


@pytest.mark.parametrize("kind", ["gear", "cam"])
@pytest.mark.parametrize("spr", [0, 1, 3])
@pytest.mark.parametrize("direction", [1, 2, 3])
def test_s7_1500_sync_direction_with_a_short_modulo_following_axis_defect4(kind, spr, direction):
    """Defect 4: modulo length 1.0, leading axis moving positive, SyncDirection 2: SPR 0 raised an
    IndexError, 1 and 3 an assertion, and MC_GearInPos stayed Busy forever.  Every combination now
    synchronizes, with the net travel of the following axis during the synchronization in the
    requested direction (decision 17: 1 not negative, 2 not positive)."""
    rig, job, _ = _modulo_rig(kind, spr, direction)
    rig.run_until(lambda: job.InSync or job.Error, timeout=5.0)
    assert job.InSync and job.Busy and not job.Error, hex(job.ErrorID)
    assert rig.ctl.mode == "RUN" and not rig.slave.StatusWord.Error
    syncing = [r for r in rig.log if r["start"] and not r["in_sync"]]
    first = next(r for r in rig.log if r["in_sync"])
    before = rig.log[rig.log.index(syncing[0]) - 1] if syncing else first
    travel = first["s"] - before["s"]
    if direction == 1:
        assert travel >= -1e-6
    elif direction == 2:
        assert travel <= 1e-6
    rig.run(0.5)
    assert job.InSync and job.Busy


@pytest.mark.parametrize("where", ["_activate_blend", "_plan_dynamic_sync", "_prepare_positioned", "_start_gear_in",
                                   "_activate_gear_in"])
def test_s7_1500_an_internal_error_in_a_synchronous_job_ends_it_with_an_error_defect4(where, monkeypatch):
    """Defect 4: an internal error left MC_GearInPos Busy forever without Error or CommandAborted.  Any
    exception inside the kernel's synchronous job handling now ends that job: Error with 16#8FFF, Busy
    FALSE; the controller stays in RUN and the axis shows the technology alarm."""
    def broken(self, *args, **kwargs):
        raise RuntimeError("injected defect")

    # the synchronization is in kernel.sync_planning, functions of the synchronous axis's Follower (issue 9)
    public = {"_prepare_positioned", "_start_gear_in", "_activate_gear_in"}
    monkeypatch.setattr(sync_planning, where[1:] if where in public else where, broken)
    rig = Rig()
    mv = MC_MoveVelocity()
    gear_in = where in ("_start_gear_in", "_activate_gear_in")
    job = MC_GearIn() if gear_in else MC_GearInPos()
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=rig.enabled(), Velocity=50.0))
    args = {} if gear_in else dict(MasterSyncPosition=40.0, SlaveSyncPosition=0.0, MasterStartDistance=10.0,
                                   SyncProfileReference=0 if where == "_plan_dynamic_sync" else 1)
    rig.steps.append(lambda: job(Master=rig.master, Slave=rig.slave, Execute=rig.enabled(), **args))
    seen = []
    rig.record = lambda: seen.append((job.Busy, job.Error, job.ErrorID, job.CommandAborted))
    rig.run_until(lambda: job.Error, timeout=3.0)
    assert job.ErrorID == 0x8FFF and not job.Busy
    assert rig.ctl.mode == "RUN"
    assert rig.slave.StatusWord.Error and rig.slave.ErrorDetail.Number != 0
    assert all(not (busy and error) for busy, error, _, _ in seen)


# --- MC_CamIn with its defaults (decision 19) -----------------------------------------------------------

@pytest.mark.parametrize("moving", [True, False], ids=["master-moving", "master-at-standstill"])
def test_s7_1500_cam_in_with_its_defaults_is_synchronous_at_once_s9_1_5_1(moving):
    """§9.1.5.1: MasterSyncPosition 0.0 (default) "to run through the entire cam"; SyncProfileReference 1
    and MasterStartDistance 0.0 (defaults): no leading value distance to synchronize over - synchronous
    at once at the cam start (decision 19).  It used to stay Busy forever without InSync and without
    EndOfProfile.  ApplicationMode 0 (default): at the cam end EndOfProfile, Busy and InSync FALSE."""
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", points=[(0, 0), (100, 50), (200, 0)], interpolation_mode=1)
    ic, mv, ci = MC_InterpolateCam(), MC_MoveVelocity(), MC_CamIn()
    go = {"move": moving}
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=ic.Done and go["move"], Velocity=100.0))
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=ic.Done))
    rig.record = lambda: dict(m=rig.master.Position, s=rig.slave.Position, in_sync=ci.InSync, busy=ci.Busy,
                              eop=ci.EndOfProfile, error=ci.Error)
    rig.run_until(lambda: ci.InSync or ci.Error, timeout=0.1)
    assert ci.InSync and ci.Busy and not ci.Error
    first = next(r for r in rig.log if r["in_sync"])
    assert first["m"] <= 100.0 * 0.012                 # within the first cycles after the start
    if not moving:
        go["move"] = True
    rig.run_until(lambda: ci.EndOfProfile or ci.Error, timeout=4.0)
    assert ci.EndOfProfile and not ci.Busy and not ci.InSync and not ci.Error
    for r in rig.log:
        if r["in_sync"]:
            u = r["m"]
            assert r["s"] == pytest.approx(float(cam.curve.value(min(max(u, 0.0), 200.0))), abs=1e-6)


from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck))
@given(length=st.sampled_from([0.25, 1.0, 7.5, 360.0]), ratio=st.sampled_from([1, -1, 3, -2]),
       v=st.sampled_from([50.0, -50.0]), spr=st.sampled_from([0, 1, 3]), direction=st.sampled_from([1, 2, 3]),
       slave_sync=st.floats(-100.0, 100.0), distance=st.floats(1.0, 30.0), velocity=st.sampled_from([-1.0, 400.0]))
def test_s7_1500_gear_in_pos_on_a_modulo_following_axis_always_ends_its_synchronization_defect4(
        length, ratio, v, spr, direction, slave_sync, distance, velocity):
    """Invariant (hypothesis): whatever the modulo length, gear ratio, direction of the leading axis,
    SyncProfileReference and SyncDirection, MC_GearInPos synchronizes - or, with SyncProfileReference 0
    whose dynamics cannot make it before the leading axis passes the synchronous position, waits for
    the start position to be crossed again (§5.4.1) - never an exception or an internal error; the
    setpoints stay finite; the net travel of the following axis up to the synchronous position keeps
    to SyncDirection 1/2 (decision 17)."""
    rig = Rig(slave_params=merge(VIRTUAL, modulo(length)))
    mv, job = MC_MoveVelocity(), MC_GearInPos()
    start = {"go": False, "msp": 0.0}
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=rig.enabled(), Velocity=v, Acceleration=1e4,
                                Deceleration=1e4, Jerk=0.0))
    rig.steps.append(lambda: job(Master=rig.master, Slave=rig.slave, Execute=start["go"], RatioNumerator=ratio,
                                 MasterSyncPosition=start["msp"], SlaveSyncPosition=slave_sync,
                                 SyncProfileReference=spr, MasterStartDistance=distance, SyncDirection=direction,
                                 Velocity=velocity))
    rig.record = lambda: dict(s=float(rig.ctl.bank.sp_p[rig.slave.index]), start=job.StartSync,
                              m=float(rig.ctl.bank.sp_p[rig.master.index]), in_sync=job.InSync)
    rig.run_until(lambda: mv.InVelocity, timeout=1.0)
    start["msp"] = rig.master.Position + math.copysign(distance + 20.0, v)
    start["go"] = True
    passed = lambda: (rig.master.Position - start["msp"]) * v > 0.0          # noqa: E731
    rig.run_until(lambda: job.InSync or job.Error or (spr == 0 and passed()), timeout=5.0)
    rig.run(0.1)
    assert rig.ctl.mode == "RUN" and all(math.isfinite(r["s"]) for r in rig.log)
    if spr == 0 and not job.InSync:
        # too close for the job's dynamics: it waits until the leading axis crosses the start position
        # (§5.4.1) - on a linear leading axis when it comes back
        assert job.Busy and not job.Error and not job.StartSync
        assert rig.slave.StatusSynchronizedMotion.WaitingFunctionState == 2
        return
    assert job.InSync and not job.Error, hex(job.ErrorID)
    i0 = next(i for i, r in enumerate(rig.log) if r["start"])
    first = next(r for r in rig.log if r["in_sync"])
    sync_m = start["msp"] + (math.copysign(distance, v) if spr == 3 else 0.0)
    at_sync = first["s"] - ratio * (first["m"] - sync_m)        # the follower at the synchronous position
    travel = at_sync - rig.log[max(i0 - 1, 0)]["s"]
    if direction == 1:
        assert travel >= -1e-6 * max(1.0, length)
    elif direction == 2:
        assert travel <= 1e-6 * max(1.0, length)


def test_s7_1500_spr0_too_close_on_a_modulo_leading_axis_synchronizes_one_revolution_later_s4_3_1():
    """§4.3/§5.4.1 (SyncProfileReference 0): a modulo leading axis too close to the synchronous position
    for the job's dynamics passes it; the synchronization is then planned for its next occurrence, one
    revolution later (it used to wait for ever for the position already passed)."""
    rig = Rig(master_params=merge(VIRTUAL, modulo(360.0)))
    mv, job = MC_MoveVelocity(), MC_GearInPos()
    st = {"go": False, "msp": 0.0}
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=rig.enabled(), Velocity=360.0))
    rig.steps.append(lambda: job(Master=rig.master, Slave=rig.slave, Execute=st["go"], SyncProfileReference=0,
                                 MasterSyncPosition=st["msp"], SlaveSyncPosition=50.0, Velocity=500.0,
                                 Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0))
    rig.record = lambda: dict(m=float(rig.ctl.bank.sp_p[rig.master.index]), in_sync=job.InSync)
    rig.run_until(lambda: mv.InVelocity, timeout=2.0)
    m0 = float(rig.ctl.bank.sp_p[rig.master.index])
    st["msp"] = (rig.master.Position + 5.0) % 360.0          # 5 degrees ahead: too close at 360 deg/s
    st["go"] = True
    rig.run_until(lambda: job.InSync or job.Error, timeout=3.0)
    assert job.InSync and not job.Error
    first = next(r for r in rig.log if r["in_sync"])
    assert first["m"] - m0 > 360.0                            # the next revolution
    assert rig.slave.Position == pytest.approx(50.0 + (rig.master.Position - st["msp"]) % 360.0, abs=1e-6)


@pytest.mark.parametrize("spr,msp", [(1, 200.0), (0, 200.0), (3, 200.0), (3, 180.0)])
def test_s7_1500_cam_run_once_synchronized_at_or_past_its_end_ends_with_end_of_profile_s9_1_5_1(spr, msp):
    """§9.1.5.1: with non-cyclic application InSync and Busy go FALSE when EndOfProfile is set.  A
    synchronization that ends at the cam end (MasterSyncPosition = cam length) or beyond it (subsequent
    synchronization over the end) used to leave MC_CamIn InSync and Busy for ever, the cam end already
    behind: the end event came while the following axis was still synchronizing."""
    rig = Rig()
    cam = rig.ctl.add_cam("Cam", points=[(0, 0), (100, 50), (200, 0)], interpolation_mode=1)
    ic, mv, ci = MC_InterpolateCam(), MC_MoveVelocity(), MC_CamIn()
    rig.steps.append(lambda: ic(Cam=cam, Execute=True))
    rig.steps.append(lambda: mv(Axis=rig.master, Execute=ic.Done, Velocity=100.0))
    rig.steps.append(lambda: ci(Master=rig.master, Slave=rig.slave, Cam=cam, Execute=ic.Done, SyncProfileReference=spr,
                                MasterSyncPosition=msp, MasterStartDistance=50.0, MasterOffset=60.0))
    rig.run_until(lambda: ci.EndOfProfile or ci.Error or rig.master.Position > 500.0, timeout=6.0)
    assert ci.EndOfProfile and not ci.Busy and not ci.InSync and not ci.Error
    assert rig.master.Position < 60.0 + 200.0 + (50.0 if spr == 3 else 0.0) + 100.0 * 0.012
    assert rig.slave.Position == pytest.approx(0.0, abs=1e-3)          # the cam's end value


def test_s7_1500_cam_in_with_a_denormal_master_scaling_ends_its_job_not_the_controller_issue8():
    """MC_CamIn, cyclic (ApplicationMode 2), MasterScaling 1e-300: the scaled leading value lies ~1e300 cam
    cycles away, which cannot be counted.  The job ends with an error, the controller stays in RUN and the
    follower's setpoint stays finite (fuzz finding F9, issue 8)."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.002, family="S7-1500T")
    lead = ctl.add_positioning_axis("Lead", {"VirtualAxis.Mode": 1})
    fol = ctl.add_synchronous_axis("Follower", {"Simulation.Mode": 1}, leading_values=["Lead"])
    cam = ctl.add_cam("Cam_1", [(162.8, 60.0), (163.078, 80.4), (163.673, 56.1)])
    p, ipo = MC_Power(Axis=fol, Enable=True), MC_InterpolateCam(Cam=cam)
    c = MC_CamIn(Master=lead, Slave=fol, Cam=cam, MasterOffset=-1.4774834616323842, MasterScaling=1e-300,
                 SyncProfileReference=4, ApplicationMode=2)
    for k in range(20):
        p()
        ipo(Execute=k >= 1)
        c(Execute=k >= 5)
        ctl.step()
        assert ctl.mode == "RUN", ctl.stop_reason
        assert math.isfinite(fol.Position) and math.isfinite(fol.Velocity)
    assert c.Error and not c.Busy and c.ErrorID != 0
