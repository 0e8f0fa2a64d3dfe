"""The encoders of an S7-Technology axis and the encoder changeover of the data sets (S7-Technology V4.1 §3.1.9,
§3.1.10, §4.5.1, §6.2.2, §6.2.5, §9.4 numbers 3000, 4010, 4011, 4050, 4412).

An axis has ``TypeOfAxis.NumberOfEncoders.numberOfEncoders`` encoders; each data set names the one it measures
with (``DataSet_x.EncoderNumber.EncoderNumber``, the name of §9.2 "converting older projects"; a data set
without one uses data set 1's).  The wizard's "Encoder type" (§4.5, §4.6.3) has no expert-list name in the
manual: family tag ``Wizard.Encoder_x.EncoderType`` - 0 incremental, 1 absolute, 2 absolute cyclic absolute.

All encoders of the simulated axis measure the same load with the drive's resolution; each reads the counted
machine position plus an offset of its own.  The encoder in force is the drive's actual value (the kernel's
``drive.set_actual``); :class:`Encoders` keeps the offset, the homed state, the retained absolute adjustment
and the validity of the others.  At a changeover the new encoder's own reading becomes the actual value (the
axis may make a compensating motion, §6.2.5 note), or with ``SyncEncoder`` the old encoder's actual value is
set on the new one.  An absolute encoder's adjustment (MC_Home Mode 5) is retained per encoder
(``AxisT.retain_key``): encoder 1 under the axis name, encoder n under ``<axis>/Encoder_n``.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping

from ...drives.spec import EncoderKind
from ...kernel.schema import INT, R, Issue, Param

if TYPE_CHECKING:  # pragma: no cover
    from .axes import AxisT

COUNT = "TypeOfAxis.NumberOfEncoders.numberOfEncoders"
MAX_ENCODERS = 8
#: the wizard's "Encoder type" (§4.5 step 8, §4.6.3)
INCREMENTAL, ABSOLUTE, CYCLIC_ABSOLUTE = 0, 1, 2
KINDS = {INCREMENTAL: EncoderKind.INCREMENTAL, ABSOLUTE: EncoderKind.ABSOLUTE,
         CYCLIC_ABSOLUTE: EncoderKind.CYCLIC_ABSOLUTE}
#: §9.4.12.40 EnumSensorState ValueDint
SENSOR_NOT_VALID, SENSOR_VALID = 204, 206


def encoder_type(x: int) -> str:
    return f"Wizard.Encoder_{x}.EncoderType"


def encoder_number(x: int) -> str:
    return f"TypeOfAxis.NumberOfDataSets.DataSet_{x}.EncoderNumber.EncoderNumber"


# fmt: off
ENCODER_PARAMS: list[Param] = [
    Param(COUNT, INT, 1, R, (), 1, MAX_ENCODERS, doc="encoders of the axis (number 3000)"),
    Param(encoder_number(1), INT, 1, R, (), 1, MAX_ENCODERS, doc="encoder of data set 1"),
] + [
    Param(encoder_type(x), INT, INCREMENTAL, R, (), choices=tuple(KINDS),
          doc="0 incremental, 1 absolute, 2 absolute cyclic absolute") for x in range(1, MAX_ENCODERS + 1)
]
# fmt: on


def dataset_encoder(p: Mapping[str, Any], dataset: int) -> int:
    """The encoder data set ``dataset`` measures with (none of its own: data set 1's)."""
    n = p.get(encoder_number(dataset))
    return p[encoder_number(1)] if n is None else n


def kind(p: Mapping[str, Any], encoder: int) -> EncoderKind:
    return KINDS[p[encoder_type(encoder)]]


def encoder_rule_issues(cfg: Mapping[str, Any], datasets: int) -> list[Issue]:
    """Each data set's encoder must be one of the axis's (§4.5.1 step 6)."""
    count = cfg[COUNT]
    return [Issue(encoder_number(x), "rule:above_count", dataset_encoder(cfg, x),
                  f"at most {COUNT} = {count}") for x in range(1, datasets + 1) if dataset_encoder(cfg, x) > count]


def retain_key(name: str, encoder: int) -> str:
    return name if encoder == 1 else f"{name}/Encoder_{encoder}"


class Encoders:
    """The encoders of one axis that are not in force (see the module docstring): ``axis.encoders``."""

    def __init__(self, axis: "AxisT", active: int):
        self.axis = axis
        self.active = active
        count = axis.eff[COUNT]
        #: reading - counted machine position, of the encoders not in force
        self.offset = {x: 0.0 for x in range(1, count + 1)}
        self.homed = {x: False for x in self.offset}
        self.adjustment = {x: 0.0 for x in self.offset}   # retained absolute encoder adjustment
        self.valid = {x: True for x in self.offset}        # the simulated encoder gives valid values
        for x in self.offset:
            if x != active:
                self._power_on(x)

    @property
    def count(self) -> int:
        return len(self.offset)

    def absolute(self, x: int) -> bool:
        return kind(self.axis.eff, x) is not EncoderKind.INCREMENTAL

    def _power_on(self, x: int) -> None:
        """Encoder ``x`` (not in force) after POWER ON: an incremental one counts from 0 and is not homed, an
        absolute one reads its absolute value plus its retained adjustment (§3.1.9)."""
        ax = self.axis
        if self.absolute(x):
            kept = ax.ctl.retain.get(retain_key(ax.name, x), {})
            self.adjustment[x] = float(kept.get("AbsEncoderOffset", 0.0))
            self.homed[x] = bool(kept.get("HomingDone", False))
            self.offset[x] = self.adjustment[x]
        else:
            self.offset[x] = -ax.homing.absolute_raw() if ax.servo else 0.0
            self.homed[x] = False

    def reading(self, x: int) -> float:
        """The actual position encoder ``x`` gives now."""
        ax = self.axis
        if x == self.active:
            return float(ax.ctl.bank.act_p[ax.index])
        return ax.homing.absolute_raw() + self.offset[x]

    def is_valid(self, x: int) -> bool:
        """sensordata_x.state (4050) = VALID."""
        ax = self.axis
        if ax.virtual:
            return True
        return ax.sensor_valid if x == self.active else self.valid[x]

    def set_valid(self, x: int, valid: bool) -> None:
        """Simulation: encoder ``x`` (not in force) gives valid values or none (e.g. a measuring wheel that
        has no contact yet, §6.2.5 example).  The encoder in force fails with ``axis.inject_fault``."""
        if x not in self.offset:
            raise ValueError(f"axis {self.axis.name}: no encoder {x} (it has {self.count})")
        if x == self.active:
            raise ValueError(f"axis {self.axis.name}: encoder {x} is in force: use inject_fault('encoder')")
        self.valid[x] = bool(valid)

    def leave(self) -> None:
        """Keep the state of the encoder in force before the configuration changes to another one."""
        ax, x = self.axis, self.active
        self.offset[x] = float(ax.ctl.bank.act_p[ax.index]) - ax.homing.absolute_raw()
        self.homed[x] = ax.homed
        self.adjustment[x] = ax.abs_offset
        self.valid[x] = ax.sensor_valid

    def enter(self, x: int, sync: bool) -> None:
        """Encoder ``x`` is in force now (the configuration has changed): its reading becomes the actual
        value, or with ``sync`` the actual value stays and is set on it (it is homed when the old one was)."""
        ax = self.axis
        b = ax.ctl.bank
        actual = float(b.act_p[ax.index])
        value = actual if sync else self.reading(x)
        homed = ax.homed if sync else self.homed[x]
        self.active = x
        ax.abs_offset = self.adjustment[x]
        ax.homed = homed
        ax.drive.set_actual(b, value)

    def power_on(self) -> None:
        """POWER OFF -> ON of the encoders not in force."""
        for x in self.offset:
            if x != self.active:
                self._power_on(x)

    def restart(self) -> None:
        """MC_Reset Restart = TRUE: the encoders not in force lose homing unless absolute (§3.1.8)."""
        for x in self.offset:
            if x != self.active and not self.absolute(x):
                self.homed[x] = False


__all__ = ["ENCODER_PARAMS", "Encoders", "dataset_encoder", "encoder_number", "encoder_type", "encoder_rule_issues",
           "kind", "retain_key", "COUNT", "INCREMENTAL", "ABSOLUTE", "CYCLIC_ABSOLUTE", "SENSOR_VALID",
           "SENSOR_NOT_VALID"]
