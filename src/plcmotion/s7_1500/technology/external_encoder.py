"""External encoder technology object (TO_ExternalEncoder, S7-1500T V5 §3.3, §6.1.5.8, §A.1.10).

An encoder with no drive: it measures a machine (a conveyor, a printing cylinder driven by another
machine) and offers its extrapolated actual value as leading value ("actual value coupling", S7-1500T),
also delayed for local followers ("delayed", §3.3.3) and to other controllers (cross-PLC, §8.1.3).
The measured machine is simulated: it moves with ``Plant.Velocity`` (changeable at run time with
:meth:`ExternalEncoder.set_plant_velocity`) or follows a function of time given to
:meth:`ExternalEncoder.drive_plant`; ``Plant.PositionNoise`` adds reproducible measuring noise.  The
encoder counts whole increments of its resolution, like the encoder of an axis.
"""
from __future__ import annotations

import math
import numbers
import zlib
from typing import TYPE_CHECKING, Any, Callable, Mapping

import numpy as np

from ...kernel import faults as F
from .builder import source_config
from ...kernel.tag_views import TagAccessError
from ...kernel.fault_injection import checked_real
from ...kernel.faults import Fault, Reaction
from ...kernel.jobs import Job, JobState
from ...kernel.leading import LeadingValueProvider
from ...kernel.leading_value import LeadingValueSink
from ...kernel.schema import E12, P, R, REAL, AxisSchema, Param
from .parameters import _PARAMS_1500, canonical
from ...kernel.tag_views import TagViews as AxisTagsMixin
from . import alarms as A
from .tags import ErrorWord, WarningWord
from ...kernel.words import pack, word_type

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_PREFIXES = ("Sensor[1].Type", "Sensor[1].InverseDirection", "Sensor[1].System", "Sensor[1].Parameter.",
             "Properties.", "Units.LengthUnit", "Units.VelocityUnit", "Modulo.", "Extrapolation.",
             "CrossPlcSynchronousOperation.", "LoadGear.", "Mechanics.")
_PARAMS = [p for p in _PARAMS_1500 if p.path.startswith(_PREFIXES)] + [
    Param("Plant.InitialPosition", REAL, 0.0, P, (), -E12, E12, doc="position of the measured machine at start"),
    Param("Plant.Velocity", REAL, 0.0, P, (), -E12, E12, doc="velocity of the measured machine"),
    Param("Plant.PositionNoise", REAL, 0.0, P, (), 0.0, E12,
          doc="standard deviation of reproducible measuring noise on the position"),
]

ENCODER_SCHEMA = AxisSchema("external encoder", _PARAMS, canonical=canonical)

EncoderStatusWord = word_type("StatusWord", {"Enable": 0, "Error": 1, "RestartActive": 2,
                                             "OnlineStartValuesChanged": 3, "HomingDone": 5},
                              aliases={"RestartRequired": 3})


def _status_word(enc: "ExternalEncoder") -> int:
    return EncoderStatusWord(pack({0: enc.state == "enabled", 1: bool(enc.alarms),
                                   3: A.restart_required(enc.alarms, A.ENCODER), 5: enc.homed}))


DYNAMIC: dict[str, Callable[["ExternalEncoder"], Any]] = {
    "ActualPosition": lambda e: e._wrap(e.position),
    "ActualVelocity": lambda e: e.velocity,
    "ActualAcceleration": lambda e: e.acceleration,
    "ActualModuloCycle": lambda e: e.modulo_cycle(),
    "OperativeSensor": lambda e: 1,
    "StatusWord": _status_word,
    "ErrorWord": lambda e: ErrorWord(pack(A.error_bits(e.alarms, A.ENCODER))),
    "WarningWord": lambda e: WarningWord(0),
    "ErrorDetail.Number": lambda e: A.error_detail(e.alarms, A.ENCODER)[0],
    "ErrorDetail.Reaction": lambda e: A.error_detail(e.alarms, A.ENCODER)[1],
    "StatusSensor[1].State": lambda e: 2 if e.state == "enabled" else 0,
    "StatusSensor[1].Control": lambda e: e.state == "enabled",
    "StatusSensor[1].Error": lambda e: any(a.kind == F.ENCODER for a in e.alarms),
    "StatusSensor[1].Position": lambda e: e._wrap(e.position),
    "StatusSensor[1].Velocity": lambda e: e.velocity,
    "StatusExtrapolation.FilteredPosition": lambda e: e.lv_provider.extrapolation_status()[0],
    "StatusExtrapolation.FilteredVelocity": lambda e: e.lv_provider.extrapolation_status()[1],
    "StatusExtrapolation.ExtrapolatedPosition": lambda e: e.lv_provider.extrapolation_status()[2],
    "StatusExtrapolation.ExtrapolatedVelocity": lambda e: e.lv_provider.extrapolation_status()[3],
    "Extrapolation.LeadingAxisDependentTime": lambda e: e.lv_provider.leading_axis_dependent_time(),
    # §8.1.4: the leading value provided to delayed followers and other controllers
    "StatusProvidedLeadingValue.DelayedLeadingValue.Position": lambda e: e.lv_provider.delayed_leading_value()[0],
    "StatusProvidedLeadingValue.DelayedLeadingValue.Velocity": lambda e: e.lv_provider.delayed_leading_value()[1],
    "StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration": lambda e: e.lv_provider.delayed_leading_value()[2],
}


#: the encoder fault of a measured value that is no number in range (alarm 411, encoder disabled, §7.1.1)
_MEASURING_FAULT = F.alarm(F.ENCODER, "hardware", Reaction.REMOVE_ENABLE, "measured value invalid")


def _position(x: Any) -> float | None:
    """``x`` as a position the encoder can deliver: a real number (not bool) within the LREAL position
    range +-1e12; None for anything else (NaN, inf, 1e300, a string, an int beyond float)."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        return None
    try:
        v = float(x)
    except (OverflowError, TypeError, ValueError):
        return None
    return v if abs(v) <= E12 else None


class ExternalEncoder(AxisTagsMixin):
    """External encoder technology object: a leading value source with actual values only."""

    kind = "TO_ExternalEncoder"
    schema = ENCODER_SCHEMA
    _dynamic = DYNAMIC
    _dynamic_types = {p: "LReal" for p in DYNAMIC}
    _dynamic_aliases: dict[str, str] = {}
    _status_groups = ("StatusSensor", "StatusExtrapolation", "ErrorDetail", "StatusProvidedLeadingValue")
    _read_param_tags = frozenset(DYNAMIC)
    provides_setpoints = False
    provides_actual_values = True
    provides_delayed_values = True

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any]):
        self.ctl = ctl
        self.name = name
        self.db_number = ctl._next_db_number()
        self.cfg = dict(cfg)
        self.load_cfg = dict(cfg)
        self.eff = self.cfg
        self.config = source_config(self.cfg)     # what the kernel reads of a leading value source
        self.state = "disabled"
        self.power_owner: Any = None
        self.homed = cfg["Sensor[1].Type"] in (1, 2)
        self.alarms: list[Fault] = []
        self.busy_commands: set[int] = set()
        self.passive_home = None
        self._plant_fn: Callable[[float], float] | None = None
        self._reset_plant()
        self.lv_provider = EncoderLeadingValue(self)
        ctl._encoders.append(self)

    def __repr__(self) -> str:
        return f"<ExternalEncoder {self.name} {self.state}>"

    # --- the measured machine ----------------------------------------------------------------------------
    def _reset_plant(self) -> None:
        e = self.cfg
        self.plant_position = e["Plant.InitialPosition"]
        self.plant_velocity = e["Plant.Velocity"]
        self._rng = np.random.default_rng(zlib.crc32(self.name.encode()))
        self.offset = 0.0                 # homing offset of the actual value
        self.position = self.velocity = self.acceleration = 0.0
        self._last: float | None = None

    def set_plant_velocity(self, velocity: float) -> None:
        """Let the measured machine move at ``velocity`` from now on (a finite number within +-1e12, the
        range of ``Plant.Velocity``; TypeError/ValueError otherwise)."""
        v = checked_real("Plant.Velocity", velocity)
        self._plant_fn = None
        self.plant_velocity = v

    def drive_plant(self, position_of_time: Callable[[float], float] | None) -> None:
        """Let the measured machine follow ``position_of_time(t)`` (None: constant velocity again)."""
        self._plant_fn = position_of_time

    def increment(self) -> float:
        e = self.eff
        fine = 2 ** e["Sensor[1].Parameter.FineResolutionXist1"]
        if e["Sensor[1].System"] == 1:
            return e["Sensor[1].Parameter.DistancePerRevolution"] / (e["Sensor[1].Parameter.StepsPerRevolution"] * fine)
        return e["Sensor[1].Parameter.Resolution"] / fine

    def read(self, t: float, dt: float) -> None:
        """One servo cycle: the machine moves, the encoder counts (called by the controller)."""
        # the encoder value of this cycle was sampled at the start of the previous one (T_i, §3.3.6)
        x = self.plant_position
        if self._plant_fn is not None:
            try:
                raw = self._plant_fn(t)
            except BaseException as exc:  # noqa: BLE001 - user code: a program fault, like a servo hook
                self._plant_fn = None                   # dropped like a hook; the machine stands where it is
                self.plant_velocity = 0.0
                self.ctl._user_fault(f"plant function of external encoder {self.name!r}", exc)
                if isinstance(exc, KeyboardInterrupt):
                    raise
                return
        else:
            raw = x + self.plant_velocity * dt
        new = _position(raw)
        if new is None:
            # S7-1500T V5 §7.1.1, §A.1.31: a value the encoder cannot deliver is an encoder fault; the
            # machine model keeps its last valid position
            self.raise_alarm(_MEASURING_FAULT)
            return
        self.plant_position = new
        if self.state != "enabled":
            return
        noise = self.eff["Plant.PositionNoise"]
        if noise > 0.0:
            x += float(self._rng.normal(0.0, noise))
        q = self.increment()
        sign = -1.0 if self.eff["Sensor[1].InverseDirection"] else 1.0
        measured = _position(math.floor(sign * x / q) * q + self.offset)
        if measured is None:                    # counted beyond the position range (offset, fine increments)
            self.raise_alarm(_MEASURING_FAULT)
            return
        prev_v = self.velocity
        self.velocity = (measured - self._last) / dt if self._last is not None else 0.0
        self.acceleration = (self.velocity - prev_v) / dt if self._last is not None else 0.0
        self.position = measured
        self._last = measured

    # --- enable, acknowledge, restart (MC_Power, MC_Reset) -----------------------------------------------
    def power(self, owner: Any, enable: bool, start_mode: int, stop_mode: int) -> Fault | None:
        if self.power_owner is not None and self.power_owner is not owner:
            return F.reject(F.ALREADY_ENABLED) if enable else None
        if enable:
            if self.ctl.mode != "RUN":
                return F.reject(F.REJECTED, "starting_up")
            self.power_owner = owner
            if self.state == "disabled" and not self.alarms:
                self.state = "enabled"
                self._last = None
                self.read(self.ctl.time, self.ctl.servo_cycle)
        elif self.power_owner is owner:
            self.state = "disabled"
            self.power_owner = None
        return None

    def _blocking_alarm(self) -> Fault | None:
        return self.alarms[0] if self.alarms else None

    def acknowledge(self) -> Fault | None:
        """MC_Reset: every alarm but one that needs a restart (alarms.ALARMS) is acknowledged."""
        self.alarms = [a for a in self.alarms if A.needs_restart(a, A.ENCODER)]
        return self.alarms[0] if self.alarms else None

    def restart(self) -> Fault | None:
        if self.state != "disabled" or self.power_owner is not None:
            return F.reject(F.RESTART_IMPOSSIBLE, "enabled")
        self.reinitialize("restart")
        return None

    def reinitialize(self, reason: str) -> None:
        self.state = "disabled"
        self.power_owner = None
        self.cfg = dict(self.load_cfg)
        self.eff = self.cfg
        self.config = source_config(self.cfg)
        self.alarms.clear()
        self.homed = self.cfg["Sensor[1].Type"] in (1, 2)
        pos = self.plant_position
        self._reset_plant()
        self.plant_position = pos            # the machine keeps where it is

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        if fault in self.alarms:
            return
        self.alarms.append(fault)
        if fault.reaction == Reaction.REMOVE_ENABLE:
            self.state = "disabled"
        if fault.kind == F.ENCODER:
            self._stop_followers()

    def _stop_followers(self) -> None:
        """Actual value coupling needs valid actual values (S7-1500T V5 §3.3.2): with an encoder fault the
        followers coupled to this encoder lose their leading value and are stopped with the alarm of an
        invalid leading value - once this cycle's setpoints are complete, so that they brake from where
        they are (as a leading axis proxy does after its tolerance time)."""
        self.ctl.sync.stop_followers_of(
            self, F.alarm(F.LV_INVALID, self.name, Reaction.STOP, f"actual value of {self.name} invalid"))

    def inject_fault(self, detail: str = "") -> None:
        """Let the encoder fail (encoder error, the actual values are invalid until MC_Reset)."""
        self.raise_alarm(F.alarm(F.ENCODER, detail, Reaction.REMOVE_ENABLE))

    # --- homing (MC_Home Mode 0/1: set or shift the actual value) ----------------------------------------
    def absolute_encoder(self) -> bool:
        return self.cfg["Sensor[1].Type"] in (1, 2)

    def home_direct(self, job: Job) -> None:
        if self.state != "enabled":
            job.finish(JobState.ERROR, F.reject(F.NOT_ENABLED))
            return
        here = self.position
        target = self._wrap(job.position) if job.mode in (0, 7) else here + job.position
        delta = target - here
        self.offset += delta
        self.position += delta
        if self._last is not None:
            self._last += delta
        ex = self.lv_provider.extrapolator
        if ex is not None:
            ex.ready = False                          # restart the filters at the new coordinates
        self.homed = True
        job.reference_position = self._wrap(target)
        job.finish(JobState.DONE)

    # --- tags -------------------------------------------------------------------------------------------
    def write_tag(self, path: str, value: Any, *, via_write_param: bool = False) -> None:
        path = self.schema.canonical(path)
        param = self.schema.params.get(path)
        if param is None or param.access != "RW":
            raise TagAccessError(f"{self.name}.{path} is not a writable tag of the external encoder")
        reason, norm = param.check(value)
        if reason is not None:
            raise ValueError(f"{self.name}.{path} = {value!r}: allowed {param.allowed()}")
        self.cfg[path] = norm
        self.config = source_config(self.cfg)     # an encoder's tags take effect at once

    def _wrap(self, value: float) -> float:
        e = self.eff
        if not e["Modulo.Enable"]:
            return value
        from ...kernel.motion import wrap
        return wrap(value, e["Modulo.StartValue"], e["Modulo.Length"])

    def modulo_cycle(self) -> int:
        e = self.eff
        if not e["Modulo.Enable"]:
            return 0
        return int(math.floor((self.position - e["Modulo.StartValue"]) / e["Modulo.Length"]))

    # --- leading value source (S7-1500T V5 §3.3.2-§3.3.4, §8.1.3) ----------------------------------------
    @property
    def sim(self) -> bool:
        return False

    def lv_value(self, mode: str, t: float) -> tuple[float, float, float]:
        return self.lv_provider.lv_value(mode, t)

    def lv_slot(self, mode: str) -> int:
        return self.lv_provider.lv_slot(mode)

    def lv_position_controlled(self) -> bool:
        return self.lv_provider.lv_position_controlled()

    def lv_modulo(self) -> tuple[float, float] | None:
        return self.lv_provider.lv_modulo()

    def leading_value_invalid(self, mode: str) -> str | None:
        return self.lv_provider.leading_value_invalid(mode)

    def provide_leading_value(self, sink: LeadingValueSink) -> None:
        self.lv_provider.provide_leading_value(sink)


class EncoderLeadingValue(LeadingValueProvider):
    """The leading value of an external encoder: its extrapolated actual value, also for delayed followers
    and other controllers (an encoder has no setpoint, §3.3.3, §8.1.3)."""

    def __init__(self, encoder: ExternalEncoder):
        super().__init__(encoder)
        self.encoder = encoder

    def actual_values(self) -> tuple[float, float]:
        enc = self.encoder
        return enc.position, enc.velocity

    def actual_values_valid(self) -> bool:
        """StatusSensor[1].Error FALSE: no encoder fault pending (§A.1.31)."""
        return not any(a.kind == F.ENCODER for a in self.encoder.alarms)

    def velocity_lag(self, dt: float) -> float:
        return 0.5 * dt                 # the velocity is the difference of the last two counts

    def provided_value(self) -> tuple[float, float, float]:
        """The extrapolated actual value: what delayed followers and other controllers get (§3.3.3)."""
        ex = self.extrapolator or self.ensure_extrapolator()
        return ex.position, ex.velocity, ex.acceleration

    def provided_value_at(self, t: float) -> tuple[float, float, float]:
        return self.lv_value("actual", t)

    def provided_value_valid(self) -> tuple[bool, bool]:
        return self.lv_position_controlled(), False

    def lv_position_controlled(self) -> bool:
        """Actual value coupling needs valid actual values (§3.3.5)."""
        enc = self.encoder
        return enc.state == "enabled" and not enc.alarms

    def leading_value_invalid(self, mode: str) -> str | None:
        """With a pending encoder fault the actual value is only the last one held (§3.3.2)."""
        return None if self.actual_values_valid() else f"actual value of {self.encoder.name} invalid"


__all__ = ["EncoderLeadingValue", "ExternalEncoder", "ENCODER_SCHEMA", "R"]
