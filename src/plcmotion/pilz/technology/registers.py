"""The command register of the motion core and its status words (Pilz V6.5 §1, the "Motion core" columns).

A program drives an axis through these parameters: it selects a command in I401, puts the set values in
I403 ... I431 and starts the command with a rising edge of I402; the motion core answers in the status
words.  ``CommandRegister`` holds the inputs with their types (a wrong type or a value out of range raises
:class:`RegisterError` at the write, as a drive refuses a bad parameter write); ``StatusWords`` holds the
outputs the motion core computes every cycle A150.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np


class RegisterError(ValueError):
    """A write to the motion core that the drive refuses: unknown parameter, wrong type, out of range,
    or a status word (read only)."""


@dataclass(frozen=True)
class Register:
    name: str
    kind: type                  # bool, int or float
    default: Any
    doc: str
    choices: tuple[int, ...] | None = None
    cyclic: bool = False        # read every cycle by some command (not only at the edge of I402)


# fmt: off
INPUTS: tuple[Register, ...] = (
    Register("I400", int, 0, "motion ID: becomes the active motion ID I82 at the start"),
    Register("I401", int, 0, "command: 0 MC_DoNothing ... 11 MC_Halt (Tab. 1)", choices=tuple(range(12))),
    Register("I402", bool, False, "Execute: a rising edge starts the command in I401"),
    Register("I403", float, 0.0, "Position A: absolute set position or distance"),
    Register("I404", float, 0.0, "velocity (MC_MoveVelocity: signed set velocity)", cyclic=True),
    Register("I405", float, 0.0, "acceleration"),
    Register("I406", float, 0.0, "deceleration"),
    Register("I407", float, 0.0, "jerk"),
    Register("I409", int, 0, "command mode: 0 cancel the running command, 1 start at its end", choices=(0, 1)),
    Register("I410", bool, False, "engage the brake at the end"),
    Register("I411", int, 0, "movement direction on an endless axis: 0 optimized, 1 positive only, "
                             "2 negative only, 3 keep direction", choices=(0, 1, 2, 3)),
    Register("I421", float, 0.0, "cyclic position set value (MC_CyclicPosition)", cyclic=True),
    Register("I424", int, 0, "MC_MoveVelocity mode: 0 take the velocity at the start, 1 cyclic takeover",
             choices=(0, 1)),
    Register("I426", float, 0.0, "cyclic reference speed (MC_CyclicSpeed, MC_MoveSpeed)", cyclic=True),
    Register("I428", float, 0.0, "cyclic reference torque/force (MC_TorqueControl)", cyclic=True),
    Register("I429", float, 0.0, "end velocity of a positioning"),
    Register("I430", float, 0.0, "torque/force ramp up [torque/s] (0: no ramp)", cyclic=True),
    Register("I431", float, 0.0, "torque/force ramp down [torque/s] (0: no ramp)", cyclic=True),
    Register("I216", float, 0.0, "cyclic acceleration (MC_MoveSpeed)", cyclic=True),
    Register("I217", float, 0.0, "cyclic deceleration (MC_MoveSpeed)", cyclic=True),
    Register("I230", float, 100.0, "velocity override [%]", cyclic=True),
)
# fmt: on
BY_NAME: dict[str, Register] = {r.name: r for r in INPUTS}


def check(reg: Register, value: Any) -> Any:
    """The value a write of ``value`` to ``reg`` stores; RegisterError for a value the drive refuses."""
    if reg.kind is bool:
        if isinstance(value, (bool, np.bool_)) or (isinstance(value, (int, np.integer)) and value in (0, 1)):
            return bool(value)
        raise RegisterError(f"{reg.name} is a BOOL parameter; got {value!r}")
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise RegisterError(f"{reg.name} takes a number; got {value!r}")
    if reg.kind is int:
        if not float(value).is_integer():
            raise RegisterError(f"{reg.name} takes an integer; got {value!r}")
        value = int(value)
        if reg.choices is not None and value not in reg.choices:
            raise RegisterError(f"{reg.name} = {value!r}: allowed {', '.join(map(str, reg.choices))}")
        return value
    try:
        x = float(value)
    except OverflowError:
        raise RegisterError(f"{reg.name} = {value!r}: beyond the range of a REAL") from None
    if not math.isfinite(x) or abs(x) > 1e12:
        raise RegisterError(f"{reg.name} = {value!r}: a finite number of at most 1e12 in magnitude")
    return x


class CommandRegister:
    """The inputs of the motion core, as attributes (``reg.I401 = 1``) or by name (``reg.write("I401", 1)``).

    Every write is checked (:class:`RegisterError`) and time-stamped: the cyclic commands watch for set
    values that stop coming (extrapolation time I423)."""

    __slots__ = ("_values", "_written", "_clock", "live")

    def __init__(self, clock: Any):
        values = {r.name: r.default for r in INPUTS}
        object.__setattr__(self, "_values", values)
        #: the values as a dict, for reading in the motion core's cycle (write through ``write`` only)
        object.__setattr__(self, "live", values)
        object.__setattr__(self, "_written", {r.name: -math.inf for r in INPUTS})
        object.__setattr__(self, "_clock", clock)

    def write(self, name: str, value: Any) -> None:
        reg = BY_NAME.get(name)
        if reg is None:
            if name in STATUS_NAMES:
                raise RegisterError(f"{name} is a status word of the motion core (read only)")
            raise RegisterError(f"{name} is not a parameter of the command register "
                                f"({', '.join(BY_NAME)})")
        self._values[name] = check(reg, value)
        self._written[name] = self._clock()

    def read(self, name: str) -> Any:
        try:
            return self._values[name]
        except KeyError:
            raise RegisterError(f"{name} is not a parameter of the command register") from None

    def written_at(self, name: str) -> float:
        """Controller time of the last write of ``name`` (-inf: never written)."""
        return self._written[name]

    def values(self) -> dict[str, Any]:
        return dict(self._values)

    def __getattr__(self, name: str) -> Any:
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(name) from None

    def __setattr__(self, name: str, value: Any) -> None:
        self.write(name, value)

    def __repr__(self) -> str:
        return "CommandRegister(" + ", ".join(f"{k}={v!r}" for k, v in self._values.items()) + ")"


@dataclass(slots=True)
class StatusWords:
    """What the motion core reports (Pilz V6.5 status tables Tab. 5, 8, 12, 15, 18, 23, 26, 29, 32, 35, 38)."""

    I82: int = 0              # active motion ID
    I83: int = 0              # state motion command (values: decisions.md)
    I85: bool = False         # motion profile done
    I86: bool = False         # in reference
    I89: int = 0              # PLCopen state (0 disabled: decisions.md; 2, 3, 4, 6, 7, 8, 11 as the manual)
    I90: int = 0              # PLCopen ErrorStop cause (causes.Cause)
    I91: bool = False         # error: the command was denied or cancelled
    I92: bool = False         # done
    I180: bool = False        # actual position in window
    I183: bool = False        # speed reached
    I190: bool = False        # velocity limit active
    I191: bool = False        # acceleration/jerk limit active
    I192: bool = False        # cyclical position limit active
    I193: bool = False        # cyclical velocity limit active
    I194: bool = False        # cyclical torque/force limit active
    I195: bool = False        # cyclical acceleration limit active
    I199: bool = False        # set and actual velocity zero (standstill)
    I80: float = 0.0          # actual position at the start of the command
    I88: float = 0.0          # actual velocity
    I96: float = 0.0          # calculated set position
    E07: float = 0.0          # calculated set velocity
    E02: float = 0.0          # set torque/force of MC_TorqueControl
    extra: dict = field(default_factory=dict, repr=False)

    def clear_command(self) -> None:
        """The status of the previous command goes at a command start (the handshake, §1.2.7)."""
        self.I85 = self.I91 = self.I92 = self.I180 = self.I183 = False
        self.I190 = self.I191 = self.I192 = self.I193 = self.I194 = self.I195 = False
        self.I90 = 0


STATUS_NAMES: tuple[str, ...] = tuple(f.name for f in fields(StatusWords) if f.name != "extra")

#: PLCopen states I89 (§1.2.4 ff.; 0 is ours)
DISABLED, STANDSTILL, DISCRETE, CONTINUOUS, STOPPING, ERROR_STOP, HOMING, CYCLIC = 0, 2, 3, 4, 6, 7, 8, 11
#: state motion command I83 (the manual names it but gives no values: decisions.md)
I83_IDLE, I83_ACTIVE, I83_ACTIVE_WITH_FOLLOWER, I83_DONE, I83_ERROR = 0, 1, 2, 3, 4

__all__ = ["BY_NAME", "CONTINUOUS", "CYCLIC", "CommandRegister", "DISABLED", "DISCRETE", "ERROR_STOP", "HOMING",
           "I83_ACTIVE", "I83_ACTIVE_WITH_FOLLOWER", "I83_DONE", "I83_ERROR", "I83_IDLE", "INPUTS", "Register",
           "RegisterError", "STANDSTILL", "STATUS_NAMES", "STOPPING", "StatusWords", "check"]
