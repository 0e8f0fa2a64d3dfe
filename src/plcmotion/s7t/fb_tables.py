"""The ErrorID table of every technology function of S7-Technology V4.1 (§6.2-§6.7, FB 401 ... FB 463).

For each FB: its number and name, the codes its table lists (with the drive's parameter-error ranges where the
table gives a range), and the causes the table names for this FB in particular (our words).  The general
meaning of each code is in :data:`plcmotion.s7t.fb_errors.COMMON`.  FB numbers and names follow the FB
descriptions; the numeric list of §6.1 swaps the texts of FB 457 and FB 460 and its alphabetic list calls
MC_CamTrack FB 460 (decisions.md).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping


@dataclass(frozen=True)
class FBTable:
    """One FB's ErrorID table: ``line`` is where it starts in the manual's text."""
    number: int
    name: str
    line: int
    messages: Mapping[int, str] = field(default_factory=dict)    # FB-specific name of a code
    codes: frozenset[int] = frozenset()
    ranges: tuple[tuple[int, int], ...] = ()
    causes: Mapping[int, str] = field(default_factory=dict)

    def all_codes(self) -> frozenset[int]:
        return self.codes | frozenset(c for lo, hi in self.ranges for c in range(lo, hi + 1))

    @property
    def title(self) -> str:
        return f"FB {self.number} {self.name}"


def _c(*codes: int) -> frozenset[int]:
    return frozenset(codes)


# fmt: off
FBS: tuple[FBTable, ...] = (
    FBTable(401, 'MC_Power', 12298,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804C, 0x804E, 0x804F, 0x8050, 0x8052,
                 0x8053, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode or StopMode out of range (e.g. Mode = 129)',
        0x8044: 'e.g. the TDB of an output cam at Axis',
        0x8045: 'the axis is deactivated (S7T Config or MC_ActivateTO)',
        0x804E: 'another MC_Power instance is busy on the same axis',
        0x804F: 'Enable fell while Axis names another axis than the one this instance enabled',
    }),
    FBTable(402, 'MC_Reset', 21349,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8045, 0x8047, 0x8048, 0x804C, 0x8050, 0x8052, 0x8053, 0x8083,
                 0x8084), causes={
        0x8045: 'a MC_Reset with Restart = TRUE is still running',
        0x8047: ('the axis was stopped by an error MC_Reset cannot acknowledge, new errors came during '
                 'acknowledgement or restart, or superimposed commands still limit the dynamics (warning 0021 at '
                 'the synchronization TDB)'),
        0x8048: 'restart refused: the axis is enabled, or the cam is in use',
    }),
    FBTable(403, 'MC_Home', 12633,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x804D, 0x8050,
                 0x8052, 0x8053, 0x8083, 0x8084, 0x808B), causes={
        0x8022: 'the encoder delivers no valid actual value',
        0x8043: 'a REAL input, Mode or DoneFlag out of range',
        0x8044: 'the TO is a speed-controlled axis or an output cam',
        0x8045: ('MC_Stop active; absolute encoder adjustment without position control; active homing (Mode 0/1) '
                 'during MC_MoveToEndPos; axis speed-controlled; power unit locked (e.g. emergency stop); a '
                 'parameter change awaits a restart; changes are being collected (parameter 4001 = '
                 'COLLECT_CHANGED_CONFIG_DATA); Mode 8 without a running passive homing'),
        0x804D: 'Mode 0, 1, 2 or 5 at a virtual axis',
    }),
    FBTable(404, 'MC_Stop', 12876,
             codes=_c(0x0000, 0x0021, 0x0028, 0x8001, 0x8005, 0x8043, 0x8044, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B),),
    FBTable(405, 'MC_Halt', 13079,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input or DoneFlag out of range',
        0x8044: 'e.g. the TDB of an external encoder',
        0x8045: 'MC_Stop is active',
        0x8056: 'the axis is clamped at a fixed stop',
    }),
    FBTable(406, 'MC_ReadSysParameter', 21995,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053, 0x8080,
                 0x8083, 0x8084, 0x8086), causes={
        0x8043: 'ParameterNumber or Index out of range',
        0x8044: 'e.g. the MCDevice DB',
        0x8045: 'the synchronization axis is deactivated (MC_ActivateTO)',
        0x8086: ('incremental-encoder parameter at an absolute encoder, encoder type "absolute encoder cyclic '
                 'absolute", data set of Index not active (MC_ChangeDataset), or the TO is restarting'),
    }),
    FBTable(407, 'MC_WriteParameter', 22372,
             codes=_c(0x0000, 0x0020, 0x8001, 0x8005, 0x8043, 0x8044, 0x804C, 0x8050, 0x8052, 0x8053, 0x8080,
                 0x8081, 0x8083, 0x8084, 0x8086, 0x808B), causes={
        0x0020: 'the parameter is of effect "Restart" and the value changed',
        0x8043: ("value out of the parameter's range or no code of its ENUM, or in conflict with another parameter"
                 ' (e.g. a smaller leadscrew pitch 1100 or gear factor 2020/2021 makes the maximum velocity 8 '
                 'unreachable; maximum velocity 8 below the minimum velocity 2072 of dynamic following error '
                 'monitoring)'),
        0x8044: 'the MCDevice DB',
        0x8080: 'the TO has no such parameter number or index',
        0x8086: 'as at MC_ReadSysParameter: inactive data set, encoder type, restart running',
    }),
    FBTable(409, 'MC_ChangeDataset', 13339,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804C, 0x804D, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084), causes={
        0x8043: 'Dataset or DoneFlag out of range',
        0x8045: ('changeMode is NEVER, the TO is restarting, or the encoder of the new data set is not valid (e.g.'
                 ' right after STOP->RUN, a restart or a hardware failure)'),
        0x804D: 'the axis is virtual',
    }),
    FBTable(410, 'MC_MoveAbsolute', 13676,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8055, 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode, Direction or DoneFlag out of range; Mode 2 with Direction 4 on a modulo axis',
        0x8045: 'MC_Stop is active',
        0x8055: 'Mode 1/2 while basic or superimposed synchronous operation or MC_Halt is active',
    }),
    FBTable(411, 'MC_MoveRelative', 14007,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8055, 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode or DoneFlag out of range',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(412, 'MC_MoveAdditive', 14257,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input or DoneFlag out of range',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(413, 'MC_MoveSuperImposed', 14487,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input or DoneFlag out of range',
        0x8044: 'e.g. a speed-controlled axis',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(414, 'MC_MoveVelocity', 14863,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8055, 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Direction (2 is not allowed), Mode or DoneFlag out of range',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(415, 'MC_MoveToEndPos', 15182,
             codes=_c(0x0000, 0x0029, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x804D, 0x8050,
                 0x8052, 0x8053, 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x0029: 'the new MC_MoveToEndPos would reverse the direction of the active one',
        0x8043: ('a REAL input, Direction or DoneFlag out of range; fixed end stop detection not configured; drive'
                 ' telegram not 101-106, or Torque does not fit the maximum drive torque'),
        0x8045: 'MC_Stop is active, or the axis is clamped and the new MC_MoveToEndPos reverses the direction',
        0x804D: 'the axis is virtual or hydraulic',
    }),
    FBTable(420, 'MC_GearIn', 15941,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050,
                 0x8052, 0x8053, 0x8056, 0x807A, 0x807B, 0x8083, 0x8084, 0x808B), causes={
        0x8040: 'the slave is not enabled',
        0x8043: ('a REAL input, RatioNumerator, RatioDenominator, Mode or DoneFlag out of range, or a configured '
                 'default such as synchronization length 0'),
        0x8044: ('Master is no positioning axis, synchronization axis or external encoder, or Slave is no '
                 'synchronization axis'),
        0x8045: 'MC_Stop is active',
        0x804A: 'Master is not a selected master of the slave\'s synchronous object',
        0x8083: 'at Master or Slave',
    }),
    FBTable(421, 'MC_CamIn', 17144,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050,
                 0x8052, 0x8053, 0x8056, 0x807A, 0x807B, 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, Mode or DoneFlag out of range, or a configured default such as synchronization '
                 'length 0'),
        0x8044: 'Master must be at least a positioning axis, Slave a synchronization axis',
        0x8045: 'MC_Stop is active',
        0x804A: 'master or cam not selected at the slave\'s synchronous object',
        0x8083: 'at Master, Slave or CamTable',
    }),
    FBTable(422, 'MC_GearOut', 16172,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084), causes={
        0x8043: 'the configured desynchronization length is 0',
        0x8044: 'Slave is no synchronization axis',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(423, 'MC_CamOut', 17380,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084), causes={
        0x8043: 'the configured desynchronization length is 0',
        0x8044: 'Slave is no synchronization axis',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(424, 'MC_Phasing', 18118,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8079, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input or DoneFlag out of range',
        0x8045: 'no synchronous operation is active',
        0x8079: 'master and slave are not coupled',
    }),
    FBTable(430, 'MC_CamSwitch', 19700,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, Mode, Direction, DoneFlagPos or DoneFlagNeg out of range; Hysteresis above a '
                 'quarter of the operating range or modulo length'),
        0x8044: 'a measuring input, or an output cam configured time-based',
        0x8045: 'output hardware failed (e.g. ET 200M) or the TO is deactivated',
        0x804A: 'the assigned axis is deactivated',
    }),
    FBTable(431, 'MC_CamSwitchTime', 19931,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, Mode, Direction, DoneFlagPos or DoneFlagNeg out of range; Hysteresis above a '
                 'quarter of the operating range or modulo length'),
        0x8044: 'an output cam that is not time-based, or a measuring input',
        0x8045: 'output hardware failed (e.g. ET 200M) or the TO is deactivated',
        0x804A: 'the assigned axis is deactivated',
    }),
    FBTable(432, 'MC_ExternalEncoder', 21110,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052,
                 0x8053, 0x8083, 0x8084, 0x808B), causes={
        0x8040: 'the encoder is disabled: enable it with Mode 1 first',
        0x8043: 'a REAL input, Mode (e.g. 167) or DoneFlag out of range',
        0x8044: 'e.g. an axis',
        0x8045: 'the encoder value is invalid at the start (e.g. hardware switched off)',
    }),
    FBTable(433, 'MC_MeasuringInput', 20871,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8034, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050, 0x8052,
                 0x8053, 0x8083, 0x8084, 0x808B), causes={
        0x8034: 'no edge inside the measuring range, or the measuring input of the drive is not set up',
        0x8043: 'a REAL input, Mode or DoneFlag out of range',
        0x8044: 'e.g. an output cam',
        0x8045: 'the TO is deactivated',
        0x804A: 'the assigned axis is deactivated',
    }),
    FBTable(434, 'MC_CamClear', 18526,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8044, 0x8045, 0x804C, 0x8050, 0x8051, 0x8052, 0x8053, 0x8083,
                 0x8084), causes={
        0x8044: 'e.g. an axis',
        0x8045: 'the cam is in use',
        0x8051: 'the cam is used in synchronous operation',
    }),
    FBTable(435, 'MC_CamSectorAdd', 18835,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8006, 0x800B, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8051,
                 0x8052, 0x8053, 0x8062, 0x8083, 0x8084, 0x8088, 0x8089, 0x808A, 0x808C), causes={
        0x800B: 'another data-transfer FB holds the buffer; or too many points at once',
        0x8043: 'e.g. Table = 167, or a polynomial with X-Min = X-Max',
        0x8044: 'e.g. an output cam',
        0x8045: '(firmware V3.0.x) another MC_CamSectorAdd is busy',
        0x8051: 'the cam is used in synchronous operation',
        0x8062: 'the cam is interpolated: clear it first',
        0x8088: 'DB or start address not found, or the area is too short',
        0x8089: 'a polynomial takes 60 bytes, a point table a multiple of 8 bytes',
        0x808C: 'areas I, O, M, DB, DI and types BYTE, CHAR, WORD, INT, DWORD, DINT, REAL only',
    }),
    FBTable(436, 'MC_CamInterpolate', 19148, messages={0x8062: 'Cam interpolation failed'},
             codes=_c(0x0000, 0x0027, 0x8001, 0x8005, 0x8006, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8051,
                 0x8052, 0x8053, 0x8062, 0x8066, 0x8083, 0x8084, 0x808B), causes={
        0x0027: 'e.g. a single polynomial whose gradients at start and end differ',
        0x8006: 'out of memory: interpolation failed',
        0x8043: 'a REAL input, Mode or CamMode out of range; StartPoint = EndPoint (both 0.0 is allowed)',
        0x8045: 'the cam is already interpolated',
        0x8051: 'the cam is used in synchronous operation',
        0x8062: 'cam interpolation failed: the cam is in use or already interpolated',
    }),
    FBTable(437, 'MC_SetTorqueLimit', 15446,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804C, 0x804D, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'MaxTorque is negative',
        0x8045: 'MC_Stop is active',
        0x804D: 'the axis is virtual or hydraulic',
    }),
    FBTable(438, 'MC_GetCamPoint', 19441,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053, 0x8061,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode or DoneFlag out of range',
        0x8044: 'e.g. an axis',
        0x8045: 'the cam is not interpolated',
    }),
    FBTable(439, 'MC_SetCharacteristic', 15630,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x804A, 0x804C, 0x804D, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084), causes={
        0x8043: 'Mode or DoneFlag out of range',
        0x8044: 'Axis is no axis, or CamTable is no cam',
        0x804A: 'the cam is not assigned as valve profile of the axis',
        0x804D: 'the axis is not hydraulic',
    }),
    FBTable(440, 'MC_GearInSuperImposed', 16505,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050,
                 0x8052, 0x8053, 0x8056, 0x807A, 0x807B, 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, the ratio, Mode or DoneFlag out of range, or a configured default such as '
                 'synchronization length 0'),
        0x8044: 'Master must be at least a positioning axis, Slave a synchronization axis',
        0x8045: 'MC_Stop is active, or the slave runs speed-controlled (MC_MoveVelocity PositionControl = FALSE)',
        0x804A: 'Master is not selected at the superimposed synchronous object',
    }),
    FBTable(441, 'MC_CamInSuperImposed', 17659,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050,
                 0x8052, 0x8053, 0x8056, 0x807A, 0x807B, 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, Mode or DoneFlag out of range, a configured default, or the cam not selected at '
                 'the synchronous object'),
        0x8044: 'e.g. a measuring input or an output cam',
        0x8045: 'MC_Stop is active, the cam is restarting, or the slave runs speed-controlled',
        0x804A: 'master or cam not selected at the superimposed synchronous object',
    }),
    FBTable(442, 'MC_GearOutSuperImposed', 16750,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode or DoneFlag out of range',
        0x8044: 'e.g. a measuring input or an output cam',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(443, 'MC_CamOutSuperImposed', 17904,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: 'a REAL input, Mode or DoneFlag out of range, or a configured default',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(444, 'MC_PhasingSuperImposed', 18351,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8040, 0x8043, 0x8044, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8056, 0x8079, 0x8083, 0x8084, 0x808B), causes={
        0x8044: 'e.g. a measuring input or a cam',
        0x8045: 'MC_Stop is active',
    }),
    FBTable(450, 'MC_ReadPeriphery', 22636,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8086, 0x8088,
                 0x8089, 0x808C, 0x808D), causes={
        0x8043: 'ByteAddress out of 0..63',
        0x8086: 'retry later',
        0x8089: 'more than 64 bytes, or beyond the DP(DRIVE) process image',
    }),
    FBTable(451, 'MC_WritePeriphery', 22841,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8086, 0x8088,
                 0x8089, 0x808C, 0x808D),),
    FBTable(453, 'MC_ReadRecord', 23015,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8088, 0x8089,
                 0x808C, 0x808D, 0x8090, 0x8091, 0x8092, 0x80A0, 0x80A2, 0x80A3, 0x80B0, 0x80B1, 0x80C0, 0x80C2,
                 0x80C3, 0x80C4, 0x80C5, 0x80C6), causes={
        0x8043: 'RecordNumber or DoneFlag out of range',
        0x8089: 'the Data area is shorter than the record',
        0x808D: 'longer than 240 bytes',
        0x8090: 'no module assigned at that address, or it is not a base address',
        0x8091: 'e.g. integrated I/O of the CPU',
        0x80A0: 'module removed or defective',
        0x80A2: 'retry in the next cycle',
        0x80B0: 'record not supported, or number outside 0..255',
        0x80B1: 'the Data area does not match the record length',
        0x80C0: 'no data yet: retry in the next cycle',
        0x80C2: 'retry immediately',
        0x80C3: 'retry immediately',
        0x80C4: 'parity, ready, block length or checksum error: retry immediately',
        0x80C5: 'retry in the next cycle',
        0x80C6: 'retry in the next cycle',
    }),
    FBTable(454, 'MC_WriteRecord', 23274, messages={0x80C0: 'Previous write command is still busy'},
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8088, 0x8089,
                 0x808C, 0x808D, 0x8090, 0x8091, 0x8092, 0x80A1, 0x80A2, 0x80A3, 0x80B0, 0x80B1, 0x80C0, 0x80C2,
                 0x80C3, 0x80C4, 0x80C5, 0x80C6), causes={
        0x80A1: 'the module refused the write',
        0x80C0: 'previous write to the same record still busy: retry immediately',
        0x808D: 'longer than 240 bytes',
    }),
    FBTable(455, 'MC_ReadDriveParameter', 23547,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8088, 0x8089,
                 0x808C, 0x808D, 0x8090, 0x8091, 0x8092, 0x80A0, 0x80A2, 0x80B0, 0x80B5, 0x80B7, 0x80C3, 0x80C5,
                 0x80C7, 0x8100, 0x8103, 0x8104, 0x8111, 0x8115, 0x8116, 0x8119), ranges=((0x8120, 0x8164), (0x8165,
                 0x81FF),), causes={
        0x8043: 'ParameterNumber, SubIndex, NumberOfElements or DoneFlag out of range',
        0x808D: 'longer than 240 bytes',
        0x80B5: "system function not executable in drive's state: retry",
        0x80B7: 'PROFIBUS DP error',
        0x80C3: 'resources busy (also within this FB)',
        0x80C7: 'retry in the next cycle',
        0x8115: 'size of the data type times NumberOfElements must not exceed 234 bytes',
        0x8116: 'attribute, number of elements, parameter number or subindex invalid',
    }),
    FBTable(456, 'MC_WriteDriveParameter', 23828,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x804C, 0x8050, 0x8052, 0x8053, 0x8088, 0x8089,
                 0x808C, 0x808D, 0x808E, 0x8090, 0x8091, 0x8092, 0x80A1, 0x80A2, 0x80B0, 0x80B5, 0x80B7, 0x80C3,
                 0x80C5, 0x80C7, 0x8100, 0x8101, 0x8102, 0x8103, 0x8104, 0x8105, 0x8106, 0x810B, 0x8111, 0x8114,
                 0x8116, 0x8117, 0x8118, 0x8119), ranges=((0x8120, 0x8164), (0x8165, 0x81FF),), causes={
        0x808D: 'longer than 228 bytes',
        0x80A1: 'the module refused the write',
        0x8114: 'value not allowed (compatibility)',
    }),
    FBTable(457, 'MC_ActivateDPSlave', 21827, messages={0x8090: 'Logical address invalid'},
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8050, 0x8052, 0x8053, 0x8057, 0x8058, 0x8090), causes={
        0x8043: 'Mode out of range',
        0x8057: 'an activation or deactivation is running',
        0x8058: 'the slave\'s configuration could not be loaded at activation',
        0x8090: 'the diagnostic address names no DP slave',
    }),
    FBTable(460, 'MC_ActivateTO', 21607,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8045, 0x804C, 0x8050, 0x8052, 0x8053, 0x8054, 0x8057,
                 0x8083, 0x8084), causes={
        0x8043: 'Mode out of range',
        0x8045: 'the axis is enabled, or another command (e.g. a restart) is not finished',
        0x8054: 'the TO is still in use',
    }),
    FBTable(461, 'MC_CamTrack', 20247,
             codes=_c(0x0000, 0x8001, 0x8005, 0x8043, 0x8044, 0x8045, 0x804A, 0x804C, 0x8050, 0x8052, 0x8053,
                 0x8083, 0x8084, 0x808B), causes={
        0x8043: ('a REAL input, Mode (3 is illegal) or CommandMode out of range; Hysteresis above a quarter of the'
                 ' operating range or modulo length'),
        0x8044: 'e.g. an axis',
        0x8045: 'output hardware failed (e.g. ET 200M), or the axis of the cam track runs speed-controlled',
        0x804A: 'the assigned axis is deactivated',
    }),
    FBTable(462, 'MC_ReadCamTrackData', 20448,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x8044, 0x804C, 0x8050, 0x8052, 0x8053, 0x8083,
                 0x8084, 0x8086, 0x8088, 0x8089, 0x808C), causes={
        0x800B: 'another data-transfer FB holds the buffer',
        0x8043: 'a REAL input or StartCam (0..31) out of range',
        0x8044: 'e.g. an axis',
        0x8086: 'data not available now: retry later',
        0x8089: 'more than 576 bytes, or not a multiple of 18 bytes',
    }),
    FBTable(463, 'MC_WriteCamTrackData', 20638,
             codes=_c(0x0000, 0x8001, 0x8005, 0x800B, 0x8043, 0x8044, 0x804C, 0x8050, 0x8052, 0x8053, 0x8083,
                 0x8084, 0x8086, 0x8088, 0x8089, 0x808A, 0x808C), causes={
        0x8043: 'a REAL input or StartCam (0..31) out of range',
        0x8044: 'e.g. a measuring input',
        0x8089: 'more than 576 bytes, or not a multiple of 18 bytes',
        0x808A: 'the data area holds an invalid REAL',
    }),
)
# fmt: on

FB_BY_NAME: Mapping[str, FBTable] = MappingProxyType({fb.name: fb for fb in FBS})
FB_BY_NUMBER: Mapping[int, FBTable] = MappingProxyType({fb.number: fb for fb in FBS})
#: FB number -> name (FB 401 MC_Power ... FB 463 MC_WriteCamTrackData); 408, 452, 458 and 459 are not used
FB_NAMES: Mapping[int, str] = MappingProxyType({fb.number: fb.name for fb in FBS})


def table(fb: str | int) -> FBTable:
    """The table of an FB by name ("MC_Power") or number (401); KeyError names the FB if §6 has none."""
    found = FB_BY_NUMBER.get(fb) if isinstance(fb, int) else FB_BY_NAME.get(fb)
    if found is None:
        raise KeyError(f"S7-Technology V4.1 has no technology function {fb!r}")
    return found
