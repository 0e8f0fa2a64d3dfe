"""MC_Home of a Pilz drive axis: the referencing methods of Pilz V6.5 Tab. 22 on the kernel's homing part.

The kernel's ``Homing`` keeps the coordinates (``_set_home``), the zero-mark latch of the drive and the job
path; this subclass runs the Pilz sequence for every method with a search movement:

1. search at the fast speed I32 in the initial direction until the feature: the limit switch of that side,
   the reference switch, or (zero pulse only) straight to step 3 at the slow speed I33;
   a reference switch in the middle of the travel range is searched in the other direction when the limit
   switch ahead is reached first;
2. brake, then leave the feature at the slow speed I33 - its edge is the reference point, or
3. with zero pulse: the first zero pulse after that edge in the same direction is the reference point;
4. the actual position there becomes the reference position I34, the drive brakes to standstill, and with
   I43 = 1 travels back to the reference position.

Dynamics: I39 (acceleration and deceleration), I44 (jerk), limited to I11 / I16 without setting I190/I191
(§1.7.3); zero values are no denial (§1.7.2) and mean the maxima.  Setting the reference (method O) is the
kernel's direct homing.  The torque/force stop methods (P-S) press against the mechanical end stop of the
simulated machine (``Drive.EndStopNegative`` / ``Drive.EndStopPositive``, the drive model's end stops) with
the drive's torque limited to I28 and set the reference once the torque/force has stayed at that limit for I29
(decisions.md).
"""
from __future__ import annotations

from ...kernel import faults as F
from ...kernel.faults import Reaction
from ...kernel.homing import Homing
from ...kernel.jobs import Job, JobState
from ...kernel.profiles import Limits, Planner
from .homing_methods import Feature, Method, from_cia402, from_drive_based


class Referencing(Homing):
    """The homing part of a Pilz drive axis (``axis.homing``, also ``axis.referencing``)."""

    #: the torque-stop job that limits the drive's torque to I28 (None: no limit set by referencing)
    torque_job: Job | None = None

    def method(self) -> Method | None:
        """The referencing method the parameters select (A586 if set, else I30/I31/I35); None: inactive."""
        e = self.axis.eff
        if e["A586"] is not None:
            return from_cia402(e["A586"])
        return from_drive_based(e["I30"], e["I31"], e["I35"], e["ReferenceSwitchPlacement"] == 1)

    # --- dynamics -------------------------------------------------------------------------------------------
    def _limits(self, speed: float | None = None) -> Limits:
        e = self.axis.eff
        acc = min(e["I39"] or e["I11"], e["I11"])
        jerk = min(e["I44"] or e["I16"], e["I16"])
        v = e["I10"] if speed is None else min(abs(speed), e["I10"])
        return Limits(velocity=v, acceleration=acc, deceleration=acc, jerk=jerk, max_velocity=e["I10"])

    def _speed(self, name: str) -> float:
        e = self.axis.eff
        override = self.axis.core.override / 100.0
        return min((e[name] or e["I10"]) * override, e["I10"])

    def _run(self, job: Job, phase: str, velocity: float, t: float) -> None:
        a = self.axis
        job.extra["phase"] = phase
        p, v, acc = a._state_now()
        lim = self._limits(velocity)
        profile = (a.motion.planner.velocity(t, p, v, acc, velocity, lim) if velocity != 0.0
                   else a.motion.stop_with(t, p, v, acc, lim))
        a._interpolating = True
        a._start_profile(profile)

    # --- the sequence ---------------------------------------------------------------------------------------
    def _start(self, job: Job, t: float) -> None:
        a = self.axis
        m = self.method()
        if m is None:                                # not reached: the core denies an inactive method
            a._finish_job(job, JobState.ERROR, F.reject(F.NOT_AVAILABLE, "homing"))
            return
        a.homed = False
        x = job.extra
        x.update(method=m, d=float(m.direction), search=float(m.direction), reversed=False)
        if m.feature is Feature.ZERO_PULSE:
            self._index(job, x["d"], t)
        elif m.feature is Feature.TORQUE_STOP:
            # the drive pushes against the stop with at most I28; I28 = 0: no limit, the stop is never detected
            self.axis.drive.set_torque_limit(self.axis.eff["I28"] or None)
            self.torque_job = job
            self._run(job, "search", x["search"] * self._speed("I32"), t)
        elif self._feature_active(job):
            self._run(job, "brake", 0.0, t)
        else:
            self._run(job, "search", x["search"] * self._speed("I32"), t)

    def _index(self, job: Job, direction: float, t: float) -> None:
        job.extra["index_dir"] = direction
        self._run(job, "index", direction * self._speed("I33"), t)
        self.axis.drive.arm_zero_mark(direction)

    def _feature_active(self, job: Job) -> bool:
        m: Method = job.extra["method"]
        if m.feature is Feature.LIMIT_SWITCH:
            return self.axis.limit_switches.actuated("max" if m.direction > 0 else "min")
        return self._cam("Active")

    def on_profile_end(self, job: Job, t: float) -> None:
        a = self.axis
        x = job.extra
        phase = x.get("phase")
        if phase == "brake":
            # on the feature: leave it at the slow speed, against the direction it was found in
            self._run(job, "leave", -x["search"] * self._speed("I33"), t)
        elif phase == "reverse":
            x["search"] = -x["search"]
            self._run(job, "search", x["search"] * self._speed("I32"), t)
        elif phase == "stop":
            if a.eff["I43"] == 1:
                p, v, acc = a._state_now()
                x["phase"] = "return"
                a._start_profile(a.motion.planner.position(t, p, v, acc, job.position,
                                                           self._limits(self._speed("I33"))))
                return
            self._done(job, t)
        elif phase == "return":
            self._done(job, t)

    def _done(self, job: Job, t: float) -> None:
        a = self.axis
        a._interpolating = False
        a._finish_job(job, JobState.DONE, t)

    def _torque_stop(self, job: Job, t: float) -> None:
        """Methods P - S: press against the mechanical end stop.  The drive model's end stop holds the load, the
        setpoint runs on, the speed loop's torque rises to the limit I28; once it has stayed there for I29 the
        setpoint stops where the load stands and the reference is set there (or, with zero pulse, at the first
        zero pulse away from the stop)."""
        a = self.axis
        x = job.extra
        at_limit = a.drive.torque_limit_active
        if x.get("phase") == "search":
            if at_limit:
                x["phase"], x["since"] = "press", t
        elif not at_limit:
            x["phase"] = "search"                        # the torque/force must stay at the limit
        elif t - x["since"] >= a.eff["I29"] - 1e-9:
            a._start_profile(Planner.hold(t, float(a.ctl.bank.act_p[a.index])))
            self.release_torque()
            if x["method"].zero_pulse:
                self._index(job, -x["search"], t)
            else:
                self._reference(job, self._latch_position(), t)

    def release_torque(self) -> None:
        """The drive's torque limit of the torque-stop search goes (done, cancelled, or the axis took a new
        command)."""
        if self.torque_job is not None:
            self.torque_job = None
            self.axis.drive.set_torque_limit(None)

    def check_inputs(self, t: float) -> None:
        job = self.torque_job
        if job is not None and (job is not self.axis.job or not job.busy):
            self.release_torque()
        super().check_inputs(t)

    def _active_inputs(self, job: Job, t: float) -> None:
        x = job.extra
        phase = x.get("phase")
        if x["method"].feature is Feature.TORQUE_STOP and phase in ("search", "press"):
            self._torque_stop(job, t)
            return
        active = self._feature_active(job)
        was = x.get("active", active)
        x["active"] = active
        if phase == "index":
            latched = self.axis.drive.zero_mark_latched()
            if latched is not None:
                self._reference(job, latched, t)
            return
        if phase == "search" and active and not was:
            self._run(job, "brake", 0.0, t)
        elif phase == "leave" and was and not active:
            if x["method"].zero_pulse:
                self._index(job, -x["search"], t)
            else:
                self._reference(job, self._latch_position(), t)

    def _reference(self, job: Job, latched: float, t: float) -> None:
        """The reference point: the actual position there becomes I34; then brake to standstill."""
        a = self.axis
        a.drive.disarm_zero_mark()
        self._set_home(latched, a._wrap(job.position))
        job.reference_position = self.reference_mark
        self._run(job, "stop", 0.0, t)

    def hw_limit(self, side: str, t: float) -> bool:
        """A limit switch reached while referencing: the feature of a limit switch method, the reversal
        point of a method with the reference switch in the middle; otherwise the fault stands."""
        a = self.axis
        job = a.job
        if job is None:
            return False
        x = job.extra
        m: Method | None = x.get("method")
        if m is None:
            return False
        ahead = (side == "max") == (x.get("search", 0.0) > 0)
        if m.feature is Feature.LIMIT_SWITCH and ahead and x.get("phase") == "search":
            x["active"] = True
            self._run(job, "brake", 0.0, t)
            return True
        if m.feature is Feature.LIMIT_SWITCH and x.get("phase") in ("brake", "leave"):
            return True
        if m.feature is Feature.SWITCH_IN_MIDDLE and ahead and x.get("phase") == "search":
            if x["reversed"]:
                a.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "", Reaction.EMERGENCY))
                return True
            x["reversed"] = True
            self._run(job, "reverse", 0.0, t)
            return True
        return False


__all__ = ["Referencing"]
