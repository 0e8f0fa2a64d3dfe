"""The axis technology objects of S7-Technology (S7-Technology V4.1 §3.1-§3.4): speed-controlled axis,
positioning axis and synchronization axis, real or virtual.

All three are the kernel's ``LayeredAxis`` (basic and superimposed motion layer, the locking stop job of
MC_Stop, per-job dynamics); here they get their technology DB (``axis.db``), the error channel of the
technology DB (``axis.errors``: ErrorID, ErrorBuffer, ErrorStatus), the emergency programs of MC_Power
(StopMode 0-6) and the S7-Technology rules for the MC_Stop lock and "homing required".  The synchronization
axis is a positioning axis with the kernel's follower (its synchronous operation instructions come with
part 2 of the issue).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterator, Mapping

from ...kernel import faults as F
from ...kernel.axis import DISABLED, ENABLED, ENABLING
from ...kernel.faults import Fault, Reaction
from ...kernel.follower import Follower
from ...kernel.jobs import Job, JobKind, JobState
from ...kernel.layered_axis import LayeredAxis
from ...kernel.policy import ABORT, Activity
from . import coordinates, override
from ...kernel.reference_approach import ApproachHoming
from .builder import POSITIONING, SPEED, SYNCHRONIZATION, TELEGRAMS_NO_ENCODER, YES
from . import tags as T
from .schema import AXIS
from .tdb import AxisDB
from . import datasets as D
from .encoders import Encoders, dataset_encoder, retain_key
from .monitoring import (FOLLOWING_WARNING_ENTRY, HwLimitRetraction, hw_limit_side, note_sw_limit_at_start,
                         tdb_errors)
from .superimposed_dynamics import within_maxima
from .to_errors import W_DYNAMICS_LIMITED, W_SW_LIMIT, ErrorRecord, tdb_error

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_EPS_T = 1e-9

#: MC_Power StopMode (§6.2.1): 0 DefaultStop, 1 FastStop, 2 TimeStop, 3 OFF2Stop (hydraulic axes), 4 GearStop,
#: 5 ramp stop and 6 fast-stop ramp of the drive (real electric axes)
DEFAULT_STOP, FAST_STOP, TIME_STOP, OFF2_STOP, GEAR_STOP, RAMP_STOP, QUICK_STOP = range(7)

#: how long a technology object takes no commands after MC_Reset Restart = TRUE [s] ("several hundred ms",
#: §6.7.1; the value is plcmotion's)
RESTART_TIME = 0.2

TECHNOLOGY_NAMES = {SPEED: "speed-controlled axis", POSITIONING: "positioning axis",
                    SYNCHRONIZATION: "synchronization axis"}


class AxisT(LayeredAxis):
    """Base of the S7-Technology axes (the class of each technology below)."""

    schema = AXIS
    technology = POSITIONING
    # the technology DB's members as tag paths (traces, the command line): ``tags``
    _dynamic = T.POSITION_TAGS
    _dynamic_types = T.POSITION_TYPES
    trace_tags = T.POSITION_TRACE
    summary_tags = T.POSITION_SUMMARY
    hydraulic = False                      # a hydraulic axis (§3.1.4) sets it (its own drive model)
    #: MC_SetTorqueLimit (EnableLimit TRUE) or MC_MoveToEndPos reduces the torque (Statusword bit 23)
    torque_limiting_command = False
    #: the override policy's activity of an MC_MoveToEndPos that was released but whose clamping window
    #: the setpoint has not left yet (``s7t.end_pos``): commands toward the stop stay refused (16#8056)
    releasing_clamp = None
    #: MC_Stop lock, follower and the superimposed layer as in the kernel; a virtual axis homes at once
    _sim_homing_at_once = True
    #: homing with the reference point approach of §4.5.10 (cam and zero mark, distances, corrections)
    homing_class = ApproachHoming
    #: 8017 when the following error exceeds its warning limit (technology.monitoring)
    reports_following_warning = True

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], *, db_number: int | None = None):
        self.errors = ErrorRecord()                  # ErrorID, ErrorBuffer, ErrorStatus of the technology DB
        self.following_mode = False                  # MC_Power Mode 2/3: position control off (§3.1.2)
        self.simulation_requested = False            # MC_Power Mode 4 taken at the rising edge of Enable
        self.restart_requested = False               # Statusword.RequestRestart
        self.last_direction = 1                      # direction of the last motion (Direction = 4: "current")
        self._warned: Job | None = None
        self.restart_until: float | None = None      # a restart (MC_Reset Restart = TRUE) runs until then
        #: MC_Power QOutputValue [%]: the valve output after disabling with StopMode 3 (hydraulic axes)
        self.q_output_value = 0.0
        #: a started MC_ChangeDataset waiting for its moment (§6.2.5): ended by MC_Power Enable = FALSE (§6.8.3)
        self.dataset_change: Job | None = None
        #: §4.5.7.2: the hardware limit switch met last, until the axis has left it (technology.monitoring)
        self.hw_retraction: HwLimitRetraction | None = None
        self._initialized = True                     # the TO (re)started: the next enable is its first
        super().__init__(ctl, name, cfg, db_number=db_number)
        self.encoders = Encoders(self, self._encoder_in_force())
        self.db = AxisDB(self)

    # --- what kind of axis ------------------------------------------------------------------------------
    @property
    def positioning(self) -> bool:
        """A positioning or synchronization axis (one that has a position, §3.3)."""
        return self.technology != SPEED

    @property
    def virtual(self) -> bool:
        return self.sim

    @property
    def technology_name(self) -> str:
        return ("virtual " if self.virtual else "") + TECHNOLOGY_NAMES[self.technology]

    @property
    def without_encoder(self) -> bool:
        """A speed-controlled axis on a telegram without encoder shows no actual velocity (§7.1)."""
        return self.technology == SPEED and not self.virtual and self.cfg["Wizard.Telegram"] in TELEGRAMS_NO_ENCODER

    @property
    def homing_required(self) -> bool:
        return self.cfg["TypeOfAxis.Homing.referencingNecessary"] == YES

    def sw_limits_effective(self) -> bool:
        """§4.5.7.3: the software limit switches act on a homed axis; with "Homing required" = NO always
        (not on a modulo axis, which has no end)."""
        c = self.config
        return c.software_limits.enabled and not c.modulo.enabled and (self.homed or not self.homing_required)

    def _encoder_in_force(self) -> int:
        return dataset_encoder(self.eff, D.active(self.eff))

    @property
    def retain_key(self) -> str:
        """The retentive data (absolute encoder adjustment) belong to the encoder in force (technology.encoders)."""
        return retain_key(self.name, self._encoder_in_force())

    def queue_waiting(self) -> bool:
        return bool(self.queue.pending)

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name} DB{self.db_number} {self.state}>"

    # --- the error channel of the technology DB (§5.12) -------------------------------------------------
    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        new = fault not in self.alarms
        stop = self.stop_job
        if stop is not None and stop.busy and fault.reaction != Reaction.NONE:
            # the error reaction stops the axis: MC_Stop is done (only another MC_Stop aborts it, §6.2.3)
            self._finish_job(stop, JobState.DONE, self.now)
        layer = self._layer_position()
        super().raise_alarm(fault, job)
        self._layer_folded(layer)
        if new:
            side = hw_limit_side(fault)
            if side is not None:
                self.hw_retraction = HwLimitRetraction(side, self.drive.mechanical_position())
            for entry in tdb_errors(fault):          # a limit switch gives two (homing_params, monitoring)
                self.errors.note(*entry)

    # --- base and superimposing coordinate system (§3.1.7, §6.2.2 Mode 7; technology.coordinates) -------
    def _layer_position(self) -> float | None:
        return self.sup_state_at(self.now)[0] if self.sup_profile is not None else None

    def _layer_folded(self, before: float | None) -> None:
        """The kernel took the superimposed layer (at ``before``) into the basic motion: its coordinate
        stays in the superimposing system until a transfer."""
        if before is not None and self.sup_profile is None:
            coordinates.layer_taken_over(self, before)

    def _sup_take_over(self, t: float) -> None:
        layer = self._layer_position()
        super()._sup_take_over(t)
        self._layer_folded(layer)

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None:
        super()._finish_job(job, state, t, fault)
        coordinates.transfer_at_standstill(self)

    def _on_milestone(self, name: str, t: float) -> None:
        super()._on_milestone(name, t)
        if name == "end":                        # also the end of a stop that no command ran (error reaction)
            coordinates.transfer_at_standstill(self)

    def _on_following_warning(self, t: float) -> None:
        self.errors.note(*FOLLOWING_WARNING_ENTRY)

    def note_rejected(self, fault: Fault) -> None:
        """A command that had been accepted ended because it could not be carried out (§6.8 "abort
        error"): its ErrorID goes to the technology DB."""
        self.errors.note(*tdb_error(fault))

    def _note_limits(self, lim, job: Job | None = None) -> None:
        super()._note_limits(lim, job)
        # warning 0021 once per command whose dynamic values were cut to the limits (§6.9.3, §7.12.1)
        if self.warnings and (job is None or job is not self._warned):
            self._warned = job
            self.errors.note(W_DYNAMICS_LIMITED)

    def acknowledge(self) -> Fault | None:
        """MC_Reset Restart = FALSE: the errors whose cause is gone are acknowledged; the technology DB's
        ErrorID, ErrorBuffer and ErrorStatus are cleared when nothing remains (§6.7.1) - after a hardware
        limit switch only once the axis has left it (§4.5.7.2 retraction; the reaction is acknowledged
        before, so the axis can be driven back)."""
        fault = super().acknowledge()
        if fault is None:
            retraction = self.hw_retraction
            if retraction is None or retraction.left(self.drive.mechanical_position()):
                self.hw_retraction = None
                self.errors.clear()
        return fault

    # --- the superimposed motion stays inside the software limit switches (§4.5.7.3) -------------------
    def start_superimposed(self, job: Job, lim: Any) -> None:
        """A superimposed positioning whose end, added to the extremes of the basic motion still to come,
        would pass a software limit switch is shortened to reach it (warning 16#0026 in the technology DB):
        the kernel guards the basic motion, this the sum of both layers."""
        if self.sw_limits_effective():
            t = self.now
            prof = self.profile
            ends = [prof.at(t)[0], prof.final.p] + [seg.p for seg in prof.segments if seg.t > t]
            limits = self.config.software_limits
            here = self.sup_state_at(t)[0]
            target = here + job.position
            clamped = min(max(target, limits.minimum - min(ends)), limits.maximum - max(ends))
            if clamped != target:
                job.position = clamped - here
                self.errors.note(W_SW_LIMIT)
        # §6.2.9: the sum of both layers' dynamics stays within the configured maxima (warning 0021)
        lim, cut = within_maxima(self.profile, self.now, job.position, lim, self.config.limits)
        if cut and not self.warnings:            # not noted already for this command (_note_limits)
            self.errors.note(W_DYNAMICS_LIMITED)
        super().start_superimposed(job, lim)

    # --- restart (MC_Reset Restart = TRUE): the object takes no commands for RESTART_TIME (§6.7.1) --------
    @property
    def restarting(self) -> bool:
        until = self.restart_until
        if until is not None and self.now >= until - _EPS_T:
            self.restart_until = until = None
        return until is not None

    def _activities(self) -> Iterator[Activity]:
        """The kernel's (a running or held MC_Stop, the axis job, a waiting passive homing, couplings, the
        superimposed motion) and a running restart, column "MC_Reset Restart" of S7-Technology V4.1 §6.8.3."""
        yield from super()._activities()
        if self.restart_until is not None and self.restarting:
            yield Activity(override.RESTART, None, _restart_goes_on)
        if self.releasing_clamp is not None:
            yield self.releasing_clamp          # MC_MoveToEndPos released, the setpoint still in its window
        change = self.dataset_change
        if change is not None and change.busy:
            yield Activity(override.CHANGE_DATASET, change, self._end_dataset_change)

    def _end_dataset_change(self, t: float) -> None:
        change, self.dataset_change = self.dataset_change, None
        if change is not None and change.busy:
            self._finish_job(change, JobState.ABORTED, t)

    def begin_restart(self) -> Fault | None:
        """Restart the technology object with its start values; it is busy for ``RESTART_TIME``."""
        fault = self.restart()
        if fault is None:
            self.restart_until = self.now + RESTART_TIME
        return fault

    @property
    def simulation(self) -> bool:
        """MC_Power Mode 4 is in force (Statusword.Simulation, §3.1.2)."""
        return bool(self.ctl.bank.simulated[self.index])

    def _zero_at_enable(self) -> bool:
        """An unhomed incremental axis counts from 0 from the (re)start of its technology object; enabling
        it again, also in simulation (MC_Power Mode 4), keeps the encoder's actual value (S7-Technology
        V4.1 §3.1.2, §6.2.1; the position of an unhomed axis is not lost by a disable)."""
        first, self._initialized = self._initialized, False
        return first and super()._zero_at_enable()

    def _enable(self, start_mode: int) -> None:
        if self.restarting:                      # enabled once the restart is over (MC_Power calls again)
            return
        # simulation mode (§3.1.2): enabled without the drive, the actual values are the setpoints
        self.simulate_actual(self.simulation_requested and self.servo)
        super()._enable(start_mode)
        if self.state != ENABLED:
            self.simulate_actual(False)          # not enabled (a configuration error): no simulation

    # --- start conditions -------------------------------------------------------------------------------
    def _stop_only_locks(self) -> bool:
        """MC_Stop cannot brake the axis (disabled, being enabled or disabled, an error reaction stops it):
        it only locks it.  §6.2.3: the lock holds whatever MC_Power does, and MC_Stop's ErrorID table has
        no 8040/8045 (fuzz seeds 6, 49 of the S7-Technology campaign)."""
        return self.state != ENABLED or any(a.reaction != Reaction.NONE for a in self.alarms)

    def check_start(self, job: Job) -> Fault | None:
        if job.kind == JobKind.STOP and self.ctl.mode == "RUN" and self._stop_only_locks():
            return None                          # MC_Stop locks a disabled axis too (§6.2.3)
        if self.restarting:
            return F.reject(F.REJECTED, "restarting")
        if self.following_mode and job.kind != JobKind.STOP and self.state == "enabled":
            return F.reject(F.NOT_ENABLED, "following_mode")      # MC_Power Mode 2: no motion (8040)
        fault = super().check_start(job)
        if fault is not None and job.kind == JobKind.STOP and fault.kind == F.PENDING_ALARM:
            return None                          # an alarm without a stop reaction: MC_Stop brakes the axis
        if fault is not None and fault.kind == F.NOT_HOMED and not self.homing_required:
            # §3.1.8: absolute motion on an axis that is not homed when "Homing required" = NO
            if self.servo and not self.sensor_valid:
                return F.reject(F.REJECTED, "position_control_required")
            return None
        return fault

    def _begin(self, job: Job, t: float) -> None:
        if job.kind == JobKind.STOP and self._stop_only_locks():
            self.stop_job = job                  # nothing it may brake: done at once, the lock stays
            self._finish_job(job, JobState.DONE, t)
            return
        super()._begin(job, t)
        if job.kind != JobKind.SUPERIMPOSED:
            coordinates.transfer(self, "override")     # a command overrides the basic motion (§6.2.2)
        note_sw_limit_at_start(self, job)        # warning 0026 (technology.monitoring)
        v = job.velocity if job.kind == JobKind.VELOCITY else job.target - self._state_now()[0] \
            if job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE) else 0.0
        if v:
            self.last_direction = 1 if v > 0 else -1

    def _has_start_mode(self) -> bool:
        """Every axis switches between position and speed control (MC_Power Mode, MC_MoveVelocity
        PositionControl; Statusword.SpeedMode), a virtual one too: it has no control loop either way."""
        return True

    # --- MC_Stop keeps the axis locked while its Execute is TRUE, also across a disable (§6.2.3) ----------
    def _end_stop(self, t: float) -> None:
        old = self.stop_job
        if old is not None and not old.busy and not old.extra.get("released"):
            old.extra["superseded"] = True       # a new MC_Stop ends the held one: CommandAborted there
        super()._end_stop(t)

    def _abort_all(self, t: float, *, keep_simulated: bool = True) -> None:
        stop = self.stop_job
        if stop is not None and stop.busy:
            # the emergency program of MC_Power takes the stop over: the stop is done, its lock stays
            self._finish_job(stop, JobState.DONE, t)
        layer = self._layer_position()
        super()._abort_all(t, keep_simulated=keep_simulated)
        self._layer_folded(layer)
        if stop is not None and not stop.extra.get("released"):
            self.stop_job = stop

    # --- MC_Power: enabling modes and emergency programs (§6.2.1) ----------------------------------------
    def _disable(self, stop_mode: int) -> None:
        t = self.now
        if override.POLICY.cell(override.POWER_OFF, override.CHANGE_DATASET) is ABORT:
            self._end_dataset_change(t)          # §6.8.3: Enable = FALSE aborts a waiting MC_ChangeDataset
        self._abort_all(t)
        if self.state == ENABLING or stop_mode in (OFF2_STOP, RAMP_STOP, QUICK_STOP) and not self.virtual:
            # OFF2: pulses off, the axis coasts; 5/6: the drive brakes with its own ramp (enable removed)
            self._remove_enable(t, by_power=True)
            return
        self.state = "disabling"
        p, v, a = self._state_now()
        self._after_stop = "disable"
        if stop_mode in (FAST_STOP, TIME_STOP):
            # the ramp of the program, kept inside active software limit switches (docs/s7t decision D87)
            ramp = self.motion.stop_with(t, p, v, a, self._max_dynamics()) if stop_mode == FAST_STOP else \
                self.motion.ramp_out(t, p, v, self.cfg["userdefaultdynamics.stoptime"]).profile
            plan = self.motion.guard_stop(t, p, v, a, ramp)
            self._start_profile(plan.profile, plan)
        else:                      # DefaultStop; GearStop of an axis that is not synchronous (§6.2.1)
            plan = self.motion.stop(t, p, v, a, emergency=True, jerk=False)
            self._start_profile(plan.profile, plan)
        if self.profile.t_end <= t + _EPS_T:
            self._remove_enable(t, by_power=True)

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        super()._remove_enable(t, by_power)
        self.following_mode = False
        self.simulate_actual(False)              # the encoder's actual values from the next servo cycle
        coordinates.transfer(self, "following")  # without enable the setpoint follows the actual value

    def reinitialize(self, reason: str) -> None:
        if reason != "restart":
            self.restart_until = None
        encoders = self.encoders
        encoders.leave()                         # a waiting MC_ChangeDataset goes on (§6.8.3: restart "-")
        super().reinitialize(reason)             # the initial data set is in force again (its encoder)
        new = self._encoder_in_force()
        if new != encoders.active:
            encoders.active = new                # the kernel took its homed state and adjustment
            if reason != "power":                # (at POWER ON the kernel has read it anew)
                b = self.ctl.bank
                self.drive.set_actual(b, self.homing.absolute_raw() + encoders.offset[new])
                b.sp_p[self.index] = b.act_p[self.index]
        if reason == "power":
            encoders.power_on()
        elif reason == "restart":
            encoders.restart()
        self.stop_job = None                  # a restart ends the MC_Stop lock with the instances
        self.errors.clear()
        self.hw_retraction = None
        coordinates.transfer(self, "restart")    # Mode 7 corrections are not kept either (§6.2.2)
        self.following_mode = False
        self.restart_requested = False
        self._warned = None
        self._initialized = True

    @property
    def disabled(self) -> bool:
        return self.state == DISABLED


def _restart_goes_on(t: float) -> None:
    """A restart is never aborted by a command (S7-Technology V4.1 §6.8.3: its column holds no abort)."""


class SpeedAxis(AxisT):
    """Speed-controlled axis (§3.2): velocity only, no position control."""

    technology = SPEED
    _dynamic = T.SPEED_TAGS
    _dynamic_types = T.SPEED_TYPES
    trace_tags = T.SPEED_TRACE
    summary_tags = T.SPEED_SUMMARY

    def _set_position_control(self, on: bool) -> None:
        super()._set_position_control(False)       # always speed-controlled (Statusword.SpeedMode, §7.1)


class PositioningAxisT(AxisT):
    """Positioning axis (§3.3)."""

    technology = POSITIONING


class SynchronizationAxis(PositioningAxisT):
    """Synchronization axis (§3.4): a positioning axis with a following object (the kernel's follower)."""

    technology = SYNCHRONIZATION

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], *, leading_values=(),
                 db_number: int | None = None):
        self.follower = Follower(self, leading_values, name)
        super().__init__(ctl, name, cfg, db_number=db_number)


#: the axis class of each technology (family tag Wizard.Technology)
AXIS_CLASSES = {SPEED: SpeedAxis, POSITIONING: PositioningAxisT, SYNCHRONIZATION: SynchronizationAxis}

__all__ = ["AxisT", "SpeedAxis", "PositioningAxisT", "SynchronizationAxis", "AXIS_CLASSES", "DEFAULT_STOP",
           "FAST_STOP", "TIME_STOP", "OFF2_STOP", "GEAR_STOP", "RAMP_STOP", "QUICK_STOP"]
