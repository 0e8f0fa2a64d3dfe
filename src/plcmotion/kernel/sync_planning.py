"""Synchronization of a following axis: how an MC_GearIn, MC_GearInPos or MC_CamIn job becomes the
active synchronous operation (S7-1500T V5 §4.3, §4.4, §5.4, §9.1.2).

* MC_GearIn synchronizes over time with the job's dynamics (SyncProfileReference 0 of gearing): the
  offset to the synchronous operation function is planned once with ruckig.
* MC_GearInPos / MC_CamIn wait for their start condition, then synchronize in advance over time
  (SyncProfileReference 0: the plan ends where the leading value reaches the synchronous position), over
  a leading value distance (1, 3, 4: a quintic in the leading value) or at once (2: direct setting).

Leading values of modulo axes are unwrapped; a synchronous position given in modulo coordinates refers
to its next occurrence in the direction the leading value moves when the job starts (the manual gives
the positive direction only, catalog §11.2 item 3; docs/s7_1500/decisions.md).

These functions work for a :class:`~plcmotion.kernel.follower.Follower` (typed here by what they use of
it, :class:`Synchronizing`) and hold no state of their own.
"""
from __future__ import annotations

import math
from typing import Any, Protocol

from . import faults as F
from . import policy as O
from .faults import Reaction
from .jobs import Job, JobKind, JobState
from .motion import limits
from .profiles import INF, Planner, PlanningError, Profile
from .sync import APPENDING, CAM, GEAR, ONCE, Coupling, CouplingCycle, quintic
from .sync_revolutions import monotonic, revolutions, shift_by, slave_correction, stroke_in_revolutions

_EPS = 1e-12
SETPOINTS = ("setpoint", "cascade")      # coupling to the setpoint (cascade: ahead at a proxy, §8.1.3)


class Synchronizing(Protocol):
    """What the synchronization uses of the follower component it works for."""

    host: Any                                  # the following axis (see follower.FollowerHost)
    coupling: Coupling | None
    waiting: Coupling | None

    def modulo_length(self) -> float: ...
    def lv_now(self, source: Any, mode: str, t: float) -> tuple[float, float, float]: ...
    def total_state_at(self, t: float) -> tuple[float, float, float]: ...
    def take_over(self, t: float) -> tuple[float, float, float]: ...
    def couple(self, c: Coupling, t: float, relative: Profile) -> None: ...
    def finish_coupling_job(self, c: Coupling, state: JobState, t: float, fault: Any = None) -> None: ...
    def end_if_cam_over(self, c: Coupling, t: float) -> None: ...


# --- MC_GearIn: synchronization over time with the job's dynamics ------------------------------------
def start_gear_in(f: Synchronizing, c: Coupling, t: float) -> None:
    _limit_gear_in_dynamics(f.host, c.job)
    c.law = GEAR
    c.ratio = c.job.extra["ratio"]
    if c.mode in SETPOINTS and not c.source.lv_position_controlled():
        # §3.3.5: with setpoint coupling the job waits until the leading axis is position-controlled
        c.waiting = c.poll = True
        set_waiting(f, c, t)
        f.host._override(O.GEAR_IN, t, c.job)
        return
    f.host._override(O.GEAR_IN, t, c.job)
    activate_gear_in(f, c, t)


def _limit_gear_in_dynamics(axis: Any, job: Job) -> None:
    """§4.4.1: MC_GearIn synchronizes within the configured dynamic limits of the following axis;
    larger job values are limited and shown as a warning (WarningWord.X6, alarms 501-503)."""
    lim = limits(axis, None, job=job)
    job.acceleration, job.deceleration, job.jerk = lim.acceleration, lim.deceleration, lim.jerk
    axis._note_limits(lim)


def activate_gear_in(f: Synchronizing, c: Coupling, t: float) -> None:
    x, xv, xa = f.lv_now(c.source, c.mode, t)
    p, v, a = f.take_over(t)
    c.offset = p - c.ratio * x
    ev, ea = v - c.ratio * xv, a - c.ratio * xa
    job = c.job
    target = c.ratio * xv
    speeding_up = abs(target) > abs(v)
    up, down = job.acceleration, job.deceleration
    lim_up = up if speeding_up else down
    lim_other = down if speeding_up else up
    if ev <= 0.0:          # the offset velocity must rise
        amax, amin = lim_up, -lim_other
    else:
        amax, amin = lim_other, -lim_up
    try:
        rel = f.host.motion.planner.free(t, 0.0, ev, ea, target_p=None, vmin=-INF, vmax=INF, amin=amin,
                                         amax=amax, jerk=job.jerk if job.jerk is not None else INF)
    except PlanningError as exc:
        f.host.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
        return
    f.couple(c, t, rel)


# --- MC_GearInPos / MC_CamIn: synchronous positions ----------------------------------------------------
def prepare_positioned(f: Synchronizing, c: Coupling, t: float) -> None:
    job = c.job
    x = job.extra
    spr = x["spr"]
    lv, lvv, _ = f.lv_now(c.source, c.mode, t)
    modulo = c.source.lv_modulo()
    c.direction = d = _travel_direction(job, lv, lvv, modulo)
    if job.kind == JobKind.GEAR_IN_POS:
        c.law = GEAR
        c.ratio = x["ratio"]
        sync = x["master_sync"]
    else:
        c.law = CAM
        cam = x["cam"]
        c.cam = cam
        c.curve = cam.curve
        c.master_scaling = x["master_scaling"]
        c.slave_scaling = x["slave_scaling"]
        c.master_offset = x["master_offset"]
        c.slave_offset = x["slave_offset"]
        c.app_mode = x["app_mode"]
        c.joins_cycles = c.app_mode == APPENDING or (
            c.app_mode != ONCE and stroke_in_revolutions(c, f.modulo_length()))
        sync = c.curve.start * c.master_scaling + c.master_offset + x["master_sync"]
    length = x["start_distance"]
    if spr == 2:                                  # CamIn: direct synchronous setting
        f.host._override(O.SYNC_ACTIVE, t, job)
        _activate_direct(f, c, t)
        return
    if spr == 4:                                  # CamIn: subsequent from the current leading value
        if c.app_mode == ONCE:
            # §5.4.3: a cam run once must define the leading values of the synchronization
            u0 = (lv - c.master_offset) / c.master_scaling
            u1 = (lv + d * length - c.master_offset) / c.master_scaling
            tol = 1e-9 * max(1.0, abs(c.curve.length))
            if not all(c.curve.start - tol <= u <= c.curve.end + tol for u in (u0, u1)):
                job.finish(JobState.ERROR, F.reject(
                    F.SYNC_POSITION_RANGE, "", f"leading value {lv!r} (+ MasterStartDistance) outside the cam"))
                return
        f.host._override(O.SYNC_ACTIVE, t, job)
        _activate_blend(f, c, t, lv + d * length)
        return
    x["sync_raw"] = sync
    c.extra["base_master_offset"] = c.master_offset
    c.extra["direction_guessed"] = abs(lvv) <= 1e-9 and modulo is not None
    if not _place(c, lv, d):
        job.finish(JobState.ERROR, F.reject(F.START_DISTANCE))
        return
    c.waiting = True
    c.poll = spr == 0 or c.extra["direction_guessed"] or (
        c.mode in SETPOINTS and not c.source.lv_position_controlled())
    if spr == 0:
        c.extra["armed"] = False
    set_waiting(f, c, t)


def _place(c: Coupling, lv: float, d: float) -> bool:
    """Unwrapped start and synchronous positions ahead of the leading value in direction ``d``."""
    x = c.job.extra
    spr = x["spr"]
    length = x["start_distance"]
    sync = x["sync_raw"]
    c.direction = d
    if c.law == CAM:
        c.master_offset = c.extra["base_master_offset"]
    start = sync - d * length if spr == 1 else sync
    modulo = c.source.lv_modulo()
    if modulo is not None:
        m_len = modulo[1]
        k = math.ceil(((lv - start) * d) / m_len - 1e-12) if (start - lv) * d < 0 else 0
        shift = d * k * m_len
        sync += shift
        start += shift
        if c.law == CAM:
            c.master_offset += shift
    elif spr == 1 and (sync - lv) * d < length * (1 - 1e-12):
        return False
    x["sync_u"] = sync
    x["start_u"] = start
    if c.law == GEAR:
        c.offset = x["slave_sync"] - c.ratio * sync
    c.trigger = start
    # the start must be crossed (or reached) in direction d; a leading value already past it waits
    c.extra["wprev"] = (lv - start) * d if (lv - start) * d <= 0 else math.nan
    return True


def _travel_direction(job: Job, lv: float, lvv: float, modulo) -> float:
    """Direction in which the leading value is expected to travel (catalog §11.2 item 3).

    The direction of a moving leading axis; at standstill the direction towards the synchronous
    position (positive on a modulo axis, where every position lies ahead)."""
    if abs(lvv) > 1e-9:
        return 1.0 if lvv > 0 else -1.0
    x = job.extra
    if job.kind == JobKind.GEAR_IN_POS and modulo is None and x["spr"] in (0, 1, 3):
        gap = x["master_sync"] - lv
        if abs(gap) > 1e-12:
            return 1.0 if gap > 0 else -1.0
    return 1.0


def set_waiting(f: Synchronizing, c: Coupling, t: float) -> None:
    """A new waiting job replaces a waiting one (§9.3.2); the active synchronous operation goes on."""
    sync = f.host.ctl.sync
    old = f.waiting
    if old is not None:
        f.finish_coupling_job(old, JobState.ABORTED, t)
        sync.remove(old)
    if c.job.kind != JobKind.GEAR_IN:
        cam = c.job.extra.get("cam")
        if cam is not None:
            cam.acquire(c.job)
    f.waiting = c
    try:
        sync.add(c)
    except CouplingCycle:
        f.waiting = None
        c.job.finish(JobState.ERROR, F.reject(F.COUPLING_CYCLE))


def poll(f: Synchronizing, c: Coupling, t: float) -> None:
    """Waiting condition checked every cycle: a position-controlled leading axis; SPR 0 start time."""
    if c.mode in SETPOINTS and not c.source.lv_position_controlled():
        return
    sync = f.host.ctl.sync
    if c.job.kind == JobKind.GEAR_IN:
        f.waiting = None
        c.waiting = c.poll = False
        sync.remove(c)
        activate_gear_in(f, c, t)
        return
    spr = c.job.extra["spr"]
    x, xv, xa = f.lv_now(c.source, c.mode, t)
    if c.extra.get("direction_guessed"):
        if abs(xv) <= 1e-9:
            return                          # direction still unknown: wait for the leading axis to move
        c.extra["direction_guessed"] = False
        d = 1.0 if xv > 0 else -1.0
        if d != c.direction:
            _place(c, x, d)
            sync.changed()
    if spr != 0:
        c.poll = False                      # from now on the vectorised trigger watches the start
        sync.changed()
        return
    d = c.direction
    remaining = (c.job.extra["sync_u"] - x) * d
    if remaining < 0.0:
        _sync_position_passed(f, c, x)
        return
    speed = xv * d
    if speed <= _EPS:
        c.extra["armed"] = remaining > 0.0
        return
    plan = _plan_dynamic_sync(f, c, t, x, xv, xa)
    if plan is None:
        return
    need = plan.t_end - t
    margin = 2.0 * f.host.ctl.servo_cycle
    arrival = _arrival_time(remaining, speed, xa * d)
    if arrival > need + margin:
        c.extra["armed"] = True
        return
    if not c.extra.get("armed"):
        return                              # §5.4.1: the start position must be crossed first
    _activate_dynamic(f, c, t, arrival)


def _sync_position_passed(f: Synchronizing, c: Coupling, x: float) -> None:
    """SPR 0: the leading value passed the synchronous position before the synchronization could
    start (too close for the job's dynamics).  The job goes on waiting (§5.4.1: the start position
    must be crossed first): a modulo leading value meets the synchronous position again one
    revolution later, a linear one when it comes back."""
    c.extra["armed"] = False
    if c.source.lv_modulo() is not None:
        _place(c, x, c.direction)
        f.host.ctl.sync.changed()


def _sync_velocity(job: Job, law_velocity: float) -> float:
    """Velocity bound of a synchronization over time (decision 13): the job's Velocity, but never
    below the synchronous velocity the following axis must reach (§4.3: the limits may be exceeded
    by the leading axis's dynamics; a bound below it would make the synchronization impossible)."""
    v = abs(law_velocity)
    return job.velocity if v < job.velocity else 1.01 * v


def _plan_dynamic_sync(f: Synchronizing, c: Coupling, t: float, x: float, xv: float,
                       xa: float) -> Profile | None:
    """Offset to the synchronous operation function, planned with the job's dynamics (SPR 0)."""
    job = c.job
    law = f.host.ctl.sync.law_at
    p, v, a = f.total_state_at(t)
    y, yv, ya = law(c, x, xv, xa)
    e0 = slave_correction(c, p - y, law(c, job.extra["sync_u"], 0.0, 0.0)[0] - y, f.modulo_length())
    vmax = _sync_velocity(job, yv)
    try:
        return f.host.motion.planner.free(t, e0, v - yv, a - ya, target_p=0.0, vmin=-vmax - yv, vmax=vmax - yv,
                                          amin=-job.deceleration, amax=job.acceleration,
                                          jerk=job.jerk if job.jerk is not None else INF, duration=None)
    except PlanningError:
        return None


def _activate_dynamic(f: Synchronizing, c: Coupling, t: float, duration: float) -> None:
    axis = f.host
    law = axis.ctl.sync.law_at
    x, xv, xa = f.lv_now(c.source, c.mode, t)
    axis._override(O.SYNC_ACTIVE, t, c.job)
    p, v, a = f.take_over(t)
    y, yv, ya = law(c, x, xv, xa)
    delta = law(c, c.job.extra["sync_u"], 0.0, 0.0)[0] - y
    e0 = slave_correction(c, p - y, delta, f.modulo_length(), shift_law=True)
    job = c.job
    vmax = _sync_velocity(job, yv)
    try:
        rel = axis.motion.planner.free(t, e0, v - yv, a - ya, target_p=0.0, vmin=-vmax - yv, vmax=vmax - yv,
                                       amin=-job.deceleration, amax=job.acceleration,
                                       jerk=job.jerk if job.jerk is not None else INF, duration=duration)
    except PlanningError as exc:
        axis.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
        return
    leave_waiting(f, c)
    c.extra["sync_x"] = c.job.extra["sync_u"]
    f.couple(c, t, rel)


def _activate_direct(f: Synchronizing, c: Coupling, t: float) -> None:
    """CamIn SyncProfileReference 2: InSync at once at the present positions (§5.4.4)."""
    x, xv, xa = f.lv_now(c.source, c.mode, t)
    job = c.job
    p, v, a = f.take_over(t)
    curve = c.curve
    u_sync = curve.start + job.extra["master_sync"] / c.master_scaling
    c.master_offset = x - curve.start * c.master_scaling - job.extra["master_sync"]
    c.slave_offset = p - float(curve.value(u_sync)) * c.slave_scaling
    if c.app_mode != ONCE:
        c.master_offset = x - u_sync * c.master_scaling
    rel = Planner.hold(t, 0.0)
    job.in_sync = True
    c.extra["inside"] = cam_inside(c, x)
    c.extra["sync_x"] = x
    f.couple(c, t, rel)


def _activate_blend(f: Synchronizing, c: Coupling, t: float, x_end: float) -> None:
    """Synchronize over the leading value distance up to ``x_end`` (SPR 1, 3, 4)."""
    x, xv, xa = f.lv_now(c.source, c.mode, t)
    p, v, a = f.take_over(t)
    law = f.host.ctl.sync.law_at
    y, dy, ddy = law(c, x, 1.0, 0.0)                       # law and its derivatives in x
    law_delta = law(c, x_end, 0.0, 0.0)[0] - y
    length = x_end - x
    if length * c.direction <= 1e-12 * max(1.0, abs(x_end)):
        # no leading value distance left (MasterStartDistance 0, or the synchronous position passed
        # in the servo cycle that started the synchronization): synchronous at once (decision 19)
        _synchronous_at_once(f, c, t, x, p - y, x_end)
        return
    if abs(xv) > 1e-9:
        sx = v / xv
        sxx = (a - sx * xa) / (xv * xv)
    else:
        sx, sxx = dy, ddy
    d0, dd0 = (sx - dy) * length, (sxx - ddy) * length * length
    chosen = None
    m_len = f.modulo_length()
    one_way = c.job.extra.get("sync_direction", 3) in (1, 2)   # 3: direction changes allowed
    for k in revolutions(c, p - y, law_delta, m_len):
        coef = quintic(p - y - k * m_len, d0, dd0)
        if chosen is None:
            chosen = (k, coef)
        if not one_way or monotonic(c, coef, x, length, law_delta, law):
            chosen = (k, coef)
            break
    assert chosen is not None
    k, c.blend = chosen
    shift_by(c, k, m_len)
    c.blend_x0 = x
    c.blend_len = length
    c.extra["sync_x"] = x_end
    if c.law == CAM:
        c.extra["inside"] = cam_inside(c, x)
    f.couple(c, t, Planner.hold(t, 0.0))


def _synchronous_at_once(f: Synchronizing, c: Coupling, t: float, x: float, e0: float, x_end: float) -> None:
    """Synchronous in this servo cycle at the leading value ``x``: the following axis takes the
    synchronous operation function (of the nearest revolution in SyncDirection) at once."""
    m_len = f.modulo_length()
    k = revolutions(c, e0, 0.0, m_len)[0]
    shift_by(c, k, m_len)
    c.blend = None
    c.job.in_sync = True
    c.extra["sync_x"] = x_end
    if c.law == CAM:
        c.extra["inside"] = cam_inside(c, x)
    f.couple(c, t, Planner.hold(t, 0.0))
    f.end_if_cam_over(c, t)


def cam_inside(c: Coupling, x: float) -> bool:
    u = (x - c.master_offset) / c.master_scaling
    return bool(c.curve.start <= u <= c.curve.end)


def trigger(f: Synchronizing, c: Coupling, t: float) -> None:
    """The leading value crossed the start position of a waiting GearInPos/CamIn (SPR 1, 3)."""
    if c is not f.waiting:
        return
    if c.mode in SETPOINTS and not c.source.lv_position_controlled():
        c.poll = True                       # §3.3.5: wait for a position-controlled leading axis
        f.host.ctl.sync.changed()
        return
    job = c.job
    spr = job.extra["spr"]
    d = c.direction
    f.host._override(O.SYNC_ACTIVE, t, job)
    leave_waiting(f, c)
    end = job.extra["sync_u"] if spr == 1 else job.extra["sync_u"] + d * job.extra["start_distance"]
    _activate_blend(f, c, t, end)


def leave_waiting(f: Synchronizing, c: Coupling) -> None:
    if f.waiting is c:
        f.waiting = None
    c.waiting = c.poll = False


def _arrival_time(remaining: float, speed: float, acc: float) -> float:
    """Time the leading value needs for ``remaining`` at its present velocity and acceleration (§4.3.2:
    synchronous when the leading axis reaches the synchronous position, also while it accelerates);
    a leading value that would stop short is taken at its present velocity."""
    if remaining <= 0.0:
        return 0.0
    if abs(acc) > 1e-12:
        disc = speed * speed + 2.0 * acc * remaining
        if disc >= 0.0:
            return 2.0 * remaining / (speed + math.sqrt(disc))   # the root without cancellation
    return remaining / speed
