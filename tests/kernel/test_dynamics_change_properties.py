"""Property test for issue 8 defect 1: dynamics changed at random times during random moves.

MC_ChangeDynamic (S7-1200 V6 §11.1.10), direct writes of DynamicDefaults (§12.9.11: effective at the next
servo cycle on PROFIdrive/analog axes, at the next command on PTO axes) and, on S7-1500 axes, per-job
dynamics and the velocity override, arrive at random moments of MC_MoveRelative, MC_MoveAbsolute or
MC_MoveVelocity on every actor type.  Whatever the dynamics, the axis must

* never plan or run faster than DynamicLimits.MaxVelocity (§5.4.4.4), nor faster than the job's own
  velocity when only the dynamics of the running job changed;
* never show NaN/inf in Position or Velocity (§12.9.1);
* end a positioning that is Done on its target (§11.1.5, §11.1.6);
* never report the internal error 16#8FFF;
* never plan a jerk above the configured DynamicDefaults.Jerk as long as the jerk was never lowered
  (S7-1200 V6 §2.4, §5.4.4.4: the jerk is a limit of the motion; only a state that a lowered jerk cannot
  take back within the velocity bounds may need more, issue 8 defect 1).

Every plan is checked as a whole (all segments of the active profile, including those still to come),
so a runaway is found even when it would only happen after the end of the test.
"""
from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion import s7_1200 as S12
from plcmotion import s7_1500 as S15

APP, SERVO = 0.004, 0.001


def _log(lo: float, hi: float):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda x: 10.0 ** x)


def profile_jerk(profile, before=None) -> float:
    """Largest |jerk| of a profile over all its segments; a step of the acceleration between segments, or
    from the profile ``before`` it to its start (a re-plan), is an infinite jerk."""
    segs = profile.segments
    steps = [(segs[k + 1].a, seg.at(segs[k + 1].t)[2]) for k, seg in enumerate(segs[:-1])]
    if before is not None:
        steps.append((segs[0].a, before.at(segs[0].t)[2]))
    for a_new, a_old in steps:
        if abs(a_new - a_old) > 1e-6 * max(1.0, abs(a_old)):
            return math.inf
    return max(abs(seg.j) for seg in segs)


def profile_peak(profile) -> float:
    """Largest |velocity| of a profile over all its segments (extremes inside segments included)."""
    peak = 0.0
    segs = profile.segments
    for k, seg in enumerate(segs):
        dur = segs[k + 1].t - seg.t if k + 1 < len(segs) else 0.0
        cands = [0.0, max(dur, 0.0)]
        if seg.j != 0.0 and 0.0 < -seg.a / seg.j < dur:
            cands.append(-seg.a / seg.j)
        for tau in cands:
            peak = max(peak, abs(seg.v + tau * (seg.a + tau * seg.j / 2)))
    return peak


@st.composite
def scenarios(draw, family: str):
    vmax = draw(_log(1.0, 400.0))
    acc = vmax / draw(_log(0.005, 2.0))                  # ramp-up time 5 ms .. 2 s
    dec = vmax / draw(_log(0.005, 2.0))
    jerk = draw(st.one_of(st.just(0.0), st.builds(lambda a, t: a / t, st.just(acc), _log(0.001, 0.5))))
    kind = draw(st.sampled_from(["relative", "absolute", "velocity"]))
    distance = draw(st.floats(0.01, 2.0)) * vmax * draw(st.sampled_from([1.0, -1.0]))
    velocity = vmax * draw(st.floats(0.1, 1.0))
    events = draw(st.lists(st.tuples(st.integers(0, 40), st.sampled_from(
        ["change", "write"] + (["override", "job"] if family != "S7-1200" else [])),
        st.lists(_log(0.001, 3.0), min_size=4, max_size=4), st.lists(st.booleans(), min_size=4, max_size=4)),
        min_size=1, max_size=4))
    actor = draw(st.sampled_from([0, 1, 2])) if family == "S7-1200" else draw(st.sampled_from(["virtual", "servo"]))
    return dict(vmax=vmax, acc=acc, dec=dec, jerk=jerk, kind=kind, distance=distance, velocity=velocity,
                events=sorted(events), actor=actor)


def _axis_1200(ctl, s):
    params = {"Actor": {"Type": s["actor"]},
              "DynamicLimits": {"MaxVelocity": s["vmax"], "MinVelocity": 1.0 if s["actor"] == 2 else 0.0},
              "DynamicDefaults": {"Acceleration": s["acc"], "Deceleration": s["dec"],
                                  "EmergencyDeceleration": 10 * max(s["acc"], s["dec"]), "Jerk": s["jerk"]}}
    if s["actor"] == 2:
        s["velocity"] = max(s["velocity"], 1.0)
    return ctl.add_positioning_axis("Axis_1", params)


def _axis_1500(ctl, s):
    params = {"DynamicLimits": {"MaxVelocity": s["vmax"], "Velocity": s["vmax"], "MaxAcceleration": 1e6, "MaxDeceleration": 1e6,
                                "MaxJerk": 1e9},
              "DynamicDefaults": {"Velocity": s["velocity"], "Acceleration": s["acc"], "Deceleration": s["dec"],
                                  "Jerk": s["jerk"], "EmergencyDeceleration": 1e5}}
    if s["actor"] == "virtual":
        params["VirtualAxis"] = {"Mode": 1}
    return ctl.add_positioning_axis("Axis_1", params)


def _run(s: dict, family: str) -> None:
    M = S12 if family == "S7-1200" else S15
    ctl = Controller(servo_cycle=SERVO, app_cycle=APP, **({} if family == "S7-1200" else {"family": family}))
    axis = (_axis_1200 if family == "S7-1200" else _axis_1500)(ctl, s)
    vmax = s["vmax"]
    power = M.MC_Power(Axis=axis, Enable=True)
    for _ in range(50):
        power()
        ctl.step()
    assert power.Status, power.outputs
    home = M.MC_Home(Axis=axis, Mode=0, Position=0.0, Execute=True)
    home()
    ctl.step()
    if s["kind"] == "relative":
        move = M.MC_MoveRelative(Axis=axis, Distance=s["distance"], Velocity=s["velocity"])
        target = axis.Position + s["distance"]
    elif s["kind"] == "absolute":
        move = M.MC_MoveAbsolute(Axis=axis, Position=s["distance"], Velocity=s["velocity"])
        target = s["distance"]
    else:
        move = M.MC_MoveVelocity(Axis=axis, Velocity=math.copysign(s["velocity"], s["distance"]))
        target = None
    move.Execute = True
    events = list(s["events"])
    job_velocity = s["velocity"]
    restarted = False
    tol = vmax * 1e-6 + 1e-9
    jerks = [s["jerk"]]                                  # configured jerk values in time order (0: no limit)
    seen = [None]                                        # profiles planned so far

    def note_jerk() -> None:
        j = float(axis.DynamicDefaults.Jerk)
        if j != jerks[-1]:
            jerks.append(j)

    def jerk_bound() -> float | None:
        """The configured jerk the plans must keep, or None when it was lowered or disabled once."""
        if 0.0 in jerks or any(b < a for a, b in zip(jerks, jerks[1:])):
            return None
        return max(jerks)

    def check() -> None:
        assert math.isfinite(axis.Position) and math.isfinite(axis.Velocity)
        assert abs(axis.Velocity) <= vmax + tol
        assert profile_peak(axis.profile) <= vmax + tol, (axis.profile.segments, vmax)
        if not restarted and family == "S7-1200":
            assert profile_peak(axis.profile) <= job_velocity + tol, (axis.profile.segments, job_velocity)
        bound = jerk_bound()
        if bound is not None and not restarted and axis.profile is not seen[-1]:
            assert profile_jerk(axis.profile, seen[-1]) <= bound * (1 + 1e-9), (axis.profile.segments, jerks)
        seen.append(axis.profile)
        assert move.ErrorID != 0x8FFF and power.ErrorID != 0x8FFF, (move.outputs, axis.alarms)

    for n in range(45):
        while events and events[0][0] == n:
            _, what, times, flags = events.pop(0)
            if what == "change":
                change = M.MC_ChangeDynamic if family == "S7-1200" else None
                if change is not None:
                    fb = change(Axis=axis, ChangeRampUp=flags[0], RampUpTime=times[0], ChangeRampDown=flags[1],
                                RampDownTime=times[1], ChangeEmergency=flags[2], EmergencyRampTime=times[2],
                                ChangeJerkTime=flags[3], JerkTime=min(times[3], 1.0), Execute=True)
                    fb()
                    assert fb.ErrorID != 0x8FFF
            elif what == "write":
                for path, flag, t in zip(("Acceleration", "Deceleration", "Jerk"), flags, times):
                    if flag:
                        value = vmax / t if path != "Jerk" else vmax / (t * min(t, 1.0))
                        setattr(axis.DynamicDefaults, path, value)
            elif what == "override":
                axis.Override.Velocity = max(100.0 * times[0] / 3.0, 10.0)
            elif what == "job" and not move.Busy and not move.Done:
                pass
            elif what == "job":
                # a new command with its own dynamics: ordinary jerk-limited overshoot of the new velocity
                # is allowed, MaxVelocity still holds
                restarted = True
                move.Execute = False
                move()
                if s["kind"] == "relative":
                    target = axis.Position + s["distance"]      # a new relative move starts from here
                move.Acceleration, move.Deceleration, move.Jerk = vmax / times[0], vmax / times[1], \
                    vmax / (times[2] * min(times[3], 1.0))
                move.Execute = True
        note_jerk()
        power()
        move()
        ctl.step()
        check()
    # let the motion end (no more calls needed: the kernel goes on; call to read the outputs)
    for _ in range(120):
        ctl.run(0.5)
        check()
        move()
        power()
        if target is None or not move.Busy:
            break
    check()
    if target is not None and move.Done:
        assert abs(axis.Position - target) <= 1e-6 * max(1.0, abs(target)), (axis.Position, target)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenarios("S7-1200"))
def test_kernel_s7_1200_dynamics_changes_never_exceed_the_velocity_limits_defect1(s):
    """S7-1200 V6 §11.1.10 / §12.9.11 on analog, PROFIdrive and PTO axes (issue 8 defect 1)."""
    _run(s, "S7-1200")


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenarios("S7-1500T"))
def test_kernel_s7_1500_dynamics_changes_never_exceed_the_velocity_limits_defect1(s):
    """S7-1500: DynamicDefaults writes, velocity override and new jobs with their own dynamics during a
    motion never exceed DynamicLimits.MaxVelocity (issue 8 defect 1)."""
    _run(s, "S7-1500T")
