"""ErrorID tables of the S7-Technology V4.1 technology DBs (§7.12.1-§7.12.8).

A technology DB's ``ErrorID`` / ``ErrorBuffer`` carry the errors (16#80xx, set ``Statusword.Error``, need
MC_Reset) and warnings (16#00xx) that arise while a TO works, as opposed to the FB's ``ErrorID`` for a command
that could not start (:mod:`plcmotion.s7t.fb_errors`).  Each table lists the codes one kind of technology DB
can show, with the S7T Config alarm numbers that may go with them; the synchronization axis has two alarm
columns, the synchronous ("following") object's and the axis's.  The reaction is the manual's where it gives
one, else ``None`` (the list is in docs/s7t/errorids.md).  MCDevice and Trace errors cannot be acknowledged.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from .tdb_error_texts import OVERRIDES, PARAMETER_ASSIGNMENT_ERROR, TEXTS, Text
from .to_kinds import TOKind

AXIS = "axis"                                   # speed-controlled and positioning axis, §7.12.1
SYNCHRONIZATION_AXIS = "synchronization axis"   # axis with synchronous object(s), §7.12.2
EXTERNAL_ENCODER = "external encoder"           # §7.12.3
CAM = "cam"                                     # §7.12.4
MEASURING_INPUT = "measuring input"             # §7.12.5
OUTPUT_CAM = "output cam"                       # §7.12.6
CAM_TRACK = "cam track"                         # §7.12.7
MCDEVICE_TRACE = "MCDevice/Trace"               # §7.12.8

#: table -> (section, first line of the table in the manual's text, TO kinds whose TDB it serves)
SECTIONS: Mapping[str, tuple[str, int, tuple[TOKind, ...]]] = MappingProxyType({
    AXIS: ("§7.12.1", 26634, (TOKind.AXIS,)),
    SYNCHRONIZATION_AXIS: ("§7.12.2", 27467, (TOKind.AXIS,)),
    EXTERNAL_ENCODER: ("§7.12.3", 28786, (TOKind.EXTERNAL_ENCODER,)),
    CAM: ("§7.12.4", 29414, (TOKind.CAM,)),
    MEASURING_INPUT: ("§7.12.5", 29828, (TOKind.MEASURING_INPUT,)),
    OUTPUT_CAM: ("§7.12.6", 30221, (TOKind.OUTPUT_CAM,)),
    CAM_TRACK: ("§7.12.7", 30598, (TOKind.CAM_TRACK,)),
    MCDEVICE_TRACE: ("§7.12.8", 30945, (TOKind.MCDEVICE, TOKind.TRACE)),
})


@dataclass(frozen=True)
class TDBError:
    """One row of a technology DB's ErrorID table."""
    table: str
    code: int
    message: str
    cause: str
    remedy: str
    alarms: tuple[int, ...]             # S7T Config alarms (synchronization axis: the axis's column)
    reaction: str | None                # what the TO does, where the manual says so
    object_alarms: tuple[int, ...] = ()  # synchronization axis: the synchronous object's alarm column
    acknowledgeable: bool = True        # MCDevice / Trace: remove the cause instead

    @property
    def warning(self) -> bool:
        """Warnings (00xx) leave Statusword.Error FALSE; acknowledging them is optional (§5.12)."""
        return self.code < 0x8000

    @property
    def kind(self) -> str:
        return "warning" if self.warning else "error"

    @property
    def to_kinds(self) -> tuple[TOKind, ...]:
        """The TO types whose technology DB can show this row."""
        return SECTIONS[self.table][2]


_ALARMS_8002 = (30004, 30005, 30010, 30011, 30015)
_ALARMS_8082 = (40006, 40007, 40008, 40009, 40010, 40011)

# code -> alarms, per table, in the manual's order
# fmt: off
_AXIS_ALARMS: dict[int, tuple[int, ...]] = {
    0x0010: (20015,), 0x0020: (20010,), 0x0021: (40002, 40003, 40004, 50003, 50005), 0x0022: (20009, 40109, 50010),
    0x0023: (40013,), 0x0026: (40105,), 0x8001: (20001, 50015), 0x8002: _ALARMS_8002, 0x8003: (20004, 20006),
    0x8004: (20003, 20011), 0x8005: (30003,), 0x8006: (20002,), 0x8008: (), 0x8009: (), 0x800A: (20014,),
    0x8010: (20005, 50001), 0x8012: (40103,), 0x8013: (50007,), 0x8014: (40106, 40111), 0x8015: (40107, 40112),
    0x8016: (50102,), 0x8017: (50103,), 0x8018: (50107, 50008), 0x8019: (50106,), 0x801A: (40110, 40201),
    0x801B: (50108,), 0x801C: (40012, 40202), 0x801D: (40101, 40102), 0x801F: (50101,), 0x8020: (50016,),
    0x8030: (50002,), 0x8031: (50001, 50013), 0x8032: (30014,), 0x8033: (50006,), 0x8040: (40005,),
    0x8041: (40108,), 0x8042: (40001,), 0x8043: (30001,), 0x8045: (30006, 30009), 0x8046: (50012,),
    0x8047: (30007,), 0x8048: (20012,), 0x8049: (20007,), 0x804A: (30008,), 0x804B: (50009,),
    0x8082: _ALARMS_8082, 0x8085: (40104,),
}
# synchronization axis: code -> (synchronous object's alarms, axis's alarms); 0023's axis column prints "0023"
_SYNC_ALARMS: dict[int, tuple[tuple[int, ...], tuple[int, ...]]] = {
    0x0010: ((), (20015,)), 0x0020: ((20010,), (20010,)),
    0x0021: ((40002, 40003, 40004), (40002, 40003, 40004, 50003, 50005)),
    0x0022: ((50103, 50104, 50105, 50106, 50108, 50109), (20009, 40109, 50010)),
    0x0023: ((40013,), ()), 0x0024: ((50008,), ()), 0x0026: ((), (40105,)),
    0x8001: ((20001,), (20001, 50015)), 0x8002: (_ALARMS_8002, _ALARMS_8002), 0x8003: ((20004, 20006),) * 2,
    0x8004: ((20003, 20011),) * 2, 0x8005: ((30003,),) * 2, 0x8006: ((20002,),) * 2, 0x8008: ((), ()),
    0x8009: ((), ()), 0x800A: ((20014,),) * 2, 0x8010: ((20005,), (20005, 50001)), 0x8012: ((), (40103,)),
    0x8013: ((), (50007,)), 0x8014: ((), (40106, 40111)), 0x8015: ((), (40107, 40112)), 0x8016: ((), (50102,)),
    0x8017: ((), (50103,)), 0x8018: ((), (50107, 50008)), 0x8019: ((), (50106,)), 0x801A: ((), (40110, 40201)),
    0x801B: ((), (50108,)), 0x801C: ((), (40012,)), 0x801D: ((), (40101, 40102)), 0x801F: ((), (50101,)),
    0x8030: ((), (50002,)), 0x8031: ((), (50001, 50013)), 0x8032: ((), (30014,)), 0x8033: ((), (50006,)),
    0x8040: ((), (40005,)), 0x8041: ((), (40108,)), 0x8042: ((), (40001,)), 0x8043: ((30001, 50107), (30001,)),
    0x8045: ((30006,), (30006, 30009)), 0x8046: ((), (50012,)), 0x8047: ((30007,),) * 2,
    0x8048: ((20012,),) * 2, 0x8049: ((20007,),) * 2, 0x804A: ((30008,),) * 2, 0x804B: ((), (50009,)),
    0x8063: ((50002,), ()), 0x8064: ((50001, 50004), ()), 0x8065: ((50003,), ()), 0x8072: ((50007,), ()),
    0x8073: ((50009,), ()), 0x8074: ((50101, 50102), ()), 0x8077: ((50005,), ()), 0x8078: ((), ()),
    0x8082: (_ALARMS_8082,) * 2, 0x8085: ((), (40104,)),
}
_EXTERNAL_ENCODER_ALARMS: dict[int, tuple[int, ...]] = {
    0x0020: (20010,), 0x0021: (50003, 50005), 0x8001: (20001, 50015), 0x8002: _ALARMS_8002, 0x8003: (20004, 20006),
    0x8004: (20003, 20011), 0x8005: (30003,), 0x8006: (20002,), 0x8008: (), 0x8009: (), 0x800A: (20014,),
    0x8010: (20005, 50001), 0x8012: (40103,), 0x8013: (50007,), 0x8016: (50102,), 0x8017: (50103,),
    0x8018: (50107, 50008), 0x8019: (50106,), 0x801B: (50108,), 0x801D: (40102,), 0x801F: (50101,),
    0x8030: (50002,), 0x8031: (50001, 50013), 0x8032: (30014,), 0x8033: (50006,), 0x8040: (40005,),
    0x8043: (30001,), 0x8045: (30006, 30009), 0x8046: (50012,), 0x8047: (30007,), 0x8048: (20012,),
    0x8049: (20007,), 0x804A: (30008,), 0x804B: (50009,),
}
_CAM_ALARMS: dict[int, tuple[int, ...]] = {
    0x0020: (20010,), 0x0022: (40003,), 0x0027: (40008,), 0x8001: (20001,), 0x8002: _ALARMS_8002,
    0x8003: (20004, 20006), 0x8004: (20003, 20011), 0x8005: (30003,), 0x8006: (20002,), 0x8008: (), 0x8009: (),
    0x800A: (20014,), 0x8010: (20005,), 0x8043: (30001,), 0x8045: (30006, 30009), 0x8047: (30007,),
    0x8048: (20012,), 0x8049: (20007,), 0x804A: (30008,), 0x8051: (40001, 40002), 0x8060: (40004,),
    0x8061: (40005, 40006), 0x8062: (40007,),
}
_MEASURING_INPUT_ALARMS: dict[int, tuple[int, ...]] = {
    0x0020: (20010,), 0x8001: (20001,), 0x8002: _ALARMS_8002, 0x8003: (20004, 20006, 40006), 0x8004: (20003, 20011),
    0x8005: (30003,), 0x8006: (20002,), 0x8008: (), 0x8009: (), 0x800A: (20014,), 0x8010: (20005,),
    0x8034: (40003, 40004), 0x8035: (40005, 40007, 40008), 0x8043: (30001,), 0x8044: (40001,),
    0x8045: (30006, 30009, 40002), 0x8047: (30007,), 0x8048: (20012,), 0x8049: (20007,), 0x804A: (30008,),
}
_OUTPUT_CAM_ALARMS: dict[int, tuple[int, ...]] = {
    0x0020: (20010,), 0x8001: (20001,), 0x8002: _ALARMS_8002, 0x8003: (20004, 20006), 0x8004: (20003, 20011),
    0x8005: (30003,), 0x8006: (20002,), 0x8008: (), 0x8009: (), 0x800A: (20014,), 0x8010: (20005,),
    0x8021: (40005,), 0x8043: (30001, 40003), 0x8045: (30006, 30009), 0x8047: (30007,), 0x8048: (20012,),
    0x8049: (20007,), 0x804A: (30008,), 0x8087: (40001,),
}
_CAM_TRACK_ALARMS: dict[int, tuple[int, ...]] = {
    0x0020: (20010,), 0x8001: (20001,), 0x8002: _ALARMS_8002, 0x8003: (20004, 20006), 0x8004: (20003, 20011),
    0x8005: (30003,), 0x8006: (20002,), 0x800A: (20014,), 0x8010: (20005,), 0x8021: (40005,),
    0x8043: (30001, 40003), 0x8045: (30006, 30009), 0x8047: (30007,), 0x8048: (20012,), 0x8049: (20007,),
    0x804A: (30008,), 0x8087: (40001,),
}
_MCDEVICE_ALARMS: dict[int, tuple[int, ...]] = {0x8008: (), 0x8009: ()}
# fmt: on

_ASSIGNMENT_ERROR_TABLES = (CAM, MEASURING_INPUT, OUTPUT_CAM, CAM_TRACK)


def _text(table: str, code: int) -> Text:
    text = OVERRIDES.get((table, code), TEXTS[code])
    if code == 0x8004 and table in _ASSIGNMENT_ERROR_TABLES:
        text = text._replace(message=PARAMETER_ASSIGNMENT_ERROR)
    return text


def _table(table: str, alarms: Mapping[int, tuple[int, ...]]) -> Mapping[int, TDBError]:
    return MappingProxyType({
        code: TDBError(table, code, *_text(table, code)[:3], al, _text(table, code).reaction,
                       acknowledgeable=table != MCDEVICE_TRACE)
        for code, al in alarms.items()})


def _sync_table() -> Mapping[int, TDBError]:
    return MappingProxyType({
        code: TDBError(SYNCHRONIZATION_AXIS, code, *_text(SYNCHRONIZATION_AXIS, code)[:3], axis_al,
                       _text(SYNCHRONIZATION_AXIS, code).reaction, object_alarms=obj_al)
        for code, (obj_al, axis_al) in _SYNC_ALARMS.items()})


TABLES: Mapping[str, Mapping[int, TDBError]] = MappingProxyType({
    AXIS: _table(AXIS, _AXIS_ALARMS),
    SYNCHRONIZATION_AXIS: _sync_table(),
    EXTERNAL_ENCODER: _table(EXTERNAL_ENCODER, _EXTERNAL_ENCODER_ALARMS),
    CAM: _table(CAM, _CAM_ALARMS),
    MEASURING_INPUT: _table(MEASURING_INPUT, _MEASURING_INPUT_ALARMS),
    OUTPUT_CAM: _table(OUTPUT_CAM, _OUTPUT_CAM_ALARMS),
    CAM_TRACK: _table(CAM_TRACK, _CAM_TRACK_ALARMS),
    MCDEVICE_TRACE: _table(MCDEVICE_TRACE, _MCDEVICE_ALARMS),
})


def table(name: str) -> Mapping[int, TDBError]:
    """The ErrorID table of one kind of technology DB (AXIS, SYNCHRONIZATION_AXIS, ...)."""
    try:
        return TABLES[name]
    except KeyError:
        raise KeyError(f"no technology DB table {name!r}; known: {', '.join(TABLES)}") from None


def lookup(code: int, table_name: str) -> TDBError | None:
    """The row of ``code`` in a technology DB's table, None if that DB cannot show it."""
    return table(table_name).get(code)


def tables_with(code: int) -> tuple[str, ...]:
    """The technology DB tables that list ``code``."""
    return tuple(name for name, rows in TABLES.items() if code in rows)


def without_reaction() -> tuple[TDBError, ...]:
    """Errors (not warnings) for which the manual states no reaction of the TO."""
    return tuple(e for rows in TABLES.values() for e in rows.values() if not e.warning and e.reaction is None)


def describe(code: int, table_name: str) -> str:
    """'16#8016 Following error out of limits (axis): ...' for a technology DB's ErrorID; unknown codes say so."""
    e = TABLES.get(table_name, {}).get(code)
    if e is None:
        return f"16#{code & 0xFFFF:04X}: not an ErrorID of the {table_name} technology DB"
    return f"16#{code:04X} {e.message} ({table_name} {e.kind}): {e.cause}; remedy: {e.remedy}"
