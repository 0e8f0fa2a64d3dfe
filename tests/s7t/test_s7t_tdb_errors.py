"""ErrorID tables of the technology DBs, S7-Technology V4.1 §7.12: codes, warning/error, messages and S7T Config
alarm numbers transcribed from the manual's tables."""
from __future__ import annotations

import pytest

from plcmotion.s7t.technology import tdb_errors as T

# §7.12.1 "ErrorIDs - Axis technology DB", every row: (code, message, alarms)
AXIS_TABLE = [
    (0x0010, "Failure of a non position-controlled encoder", (20015,)),
    (0x0020, "Restart to activate the parameter changes", (20010,)),
    (0x0021, "Dynamic response values are limited", (40002, 40003, 40004, 50003, 50005)),
    (0x0022, "Internal warning", (20009, 40109, 50010)),
    (0x0023, "Maximum acceleration limits the holding time", (40013,)),
    (0x0026, "Position limited to software limit switch", (40105,)),
    (0x8001, "Fatal internal error", (20001, 50015)),
    (0x8002, "Internal error", (30004, 30005, 30010, 30011, 30015)),
    (0x8003, "Fatal configuration error", (20004, 20006)),
    (0x8004, "Configuration error", (20003, 20011)),
    (0x8005, "Command memory is full", (30003,)),
    (0x8006, "Insufficient memory", (20002,)),
    (0x8008, "Invalid technology DB", ()),
    (0x8009, "The technology DB is disabled because it was replaced with a newer instance", ()),
    (0x800A, "HW driver not available", (20014,)),
    (0x8010, "Drive failed", (20005, 50001)),
    (0x8012, "Homing error", (40103,)),
    (0x8013, "Hardware limit switch is active", (50007,)),
    (0x8014, "Software limit switch actuated", (40106, 40111)),
    (0x8015, "Software limit switch overshot", (40107, 40112)),
    (0x8016, "Following error out of limits", (50102,)),
    (0x8017, "Following error has exceeded the warning limit", (50103,)),
    (0x8018, "Standstill monitoring error", (50107, 50008)),
    (0x8019, "Positioning monitoring error", (50106,)),
    (0x801A, "Synchronous operation monitoring error", (40110, 40201)),
    (0x801B, "Clamping monitoring error", (50108,)),
    (0x801C, "Dynamic limits are exceeded", (40012, 40202)),
    (0x801D, "Reference cam or encoder zero mark not found", (40101, 40102)),
    (0x801F, "Dynamic control loop out of range", (50101,)),
    (0x8020, "Setpoint limiting active", (50016,)),
    (0x8030, "Limit frequency of the measuring system exceeded", (50002,)),
    (0x8031, "Actual value monitoring error", (50001, 50013)),
    (0x8032, "Cannot shift the coordinate system", (30014,)),
    (0x8033, "Encoder zero mark monitoring triggered", (50006,)),
    (0x8040, "The axis / external encoder are disabled, or the wrong mode is set", (40005,)),
    (0x8041, "Axis not homed", (40108,)),
    (0x8042, "Invalid change of the axis status", (40001,)),
    (0x8043, "Invalid command parameter value or default value", (30001,)),
    (0x8045, "Command not allowed in current state", (30006, 30009)),
    (0x8046, "Command not supported by the drive", (50012,)),
    (0x8047, "Cannot acknowledge this error", (30007,)),
    (0x8048, "Unable to restart", (20012,)),
    (0x8049, "Illegal object combination", (20007,)),
    (0x804A, "Required object connection is missing", (30008,)),
    (0x804B, "Limit switch active; invalid command", (50009,)),
    (0x8082, "Invalid Zero value in parameter", (40006, 40007, 40008, 40009, 40010, 40011)),
    (0x8085, "Impermissible end limit configuration", (40104,)),
]


@pytest.mark.parametrize("code, message, alarms", AXIS_TABLE, ids=[f"{r[0]:04X}" for r in AXIS_TABLE])
def test_s7t_axis_tdb_error(code, message, alarms):
    """S7-Technology V4.1 §7.12.1: each ErrorID of the axis technology DB with its message and alarms; 00xx are
    warnings, 80xx errors."""
    e = T.lookup(code, T.AXIS)
    assert (e.message, e.alarms) == (message, alarms)
    assert e.warning == (code < 0x8000) and e.kind == ("warning" if code < 0x8000 else "error")
    assert e.cause and e.remedy and e.acknowledgeable


def test_s7t_axis_tdb_table_is_complete():
    """S7-Technology V4.1 §7.12.1: the axis table has exactly these 6 warnings and 41 errors."""
    assert sorted(T.table(T.AXIS)) == [r[0] for r in AXIS_TABLE]
    assert sum(e.warning for e in T.table(T.AXIS).values()) == 6


SYNC_ONLY = [  # §7.12.2: (code, message, synchronous object's alarms, axis's alarms)
    (0x0024, "No long-term stability of gearing", (50008,), ()),
    (0x8063, "Cam is not interpolated", (50002,), ()),
    (0x8064, "Failed to access the cam", (50001, 50004), ()),
    (0x8065, "Range violation for cam", (50003,), ()),
    (0x8072, "Error occurred while activating/deactivating the synchronous operation", (50007,), ()),
    (0x8073, "Violation of leading axis dynamics in synchronous operation", (50009,), ()),
    (0x8074, "The leading axis is not configured for synchronous operation", (50101, 50102), ()),
    (0x8077, "Deactivation of synchronous operation aborted", (50005,), ()),
    (0x8078, "Superimposed synchronous operation is not possible", (), ()),
    (0x0022, "Internal warning", (50103, 50104, 50105, 50106, 50108, 50109), (20009, 40109, 50010)),
    (0x8043, "Invalid command parameter value or default value", (30001, 50107), (30001,)),
    (0x8010, "Drive failed", (20005,), (20005, 50001)),
    (0x801C, "Dynamic limits are exceeded", (), (40012,)),
]


@pytest.mark.parametrize("code, message, obj_alarms, axis_alarms", SYNC_ONLY, ids=[f"{r[0]:04X}" for r in SYNC_ONLY])
def test_s7t_synchronization_axis_tdb_error(code, message, obj_alarms, axis_alarms):
    """S7-Technology V4.1 §7.12.2: synchronization axis rows with the two alarm columns (synchronous object,
    synchronized axis)."""
    e = T.lookup(code, T.SYNCHRONIZATION_AXIS)
    assert (e.message, e.object_alarms, e.alarms) == (message, obj_alarms, axis_alarms)


def test_s7t_tdb_table_sizes_and_differences():
    """S7-Technology V4.1 §7.12.2-§7.12.8: row counts, 8020 only at the axis, the sync-only codes, the cam track
    without 8008/8009, MCDevice/Trace only 8008/8009 and not acknowledgeable."""
    sizes = {T.AXIS: 47, T.SYNCHRONIZATION_AXIS: 55, T.EXTERNAL_ENCODER: 34, T.CAM: 23, T.MEASURING_INPUT: 20,
             T.OUTPUT_CAM: 19, T.CAM_TRACK: 17, T.MCDEVICE_TRACE: 2}
    assert {k: len(v) for k, v in T.TABLES.items()} == sizes
    assert T.tables_with(0x8020) == (T.AXIS,)
    assert T.tables_with(0x8063) == (T.SYNCHRONIZATION_AXIS,)
    assert T.tables_with(0x8087) == (T.OUTPUT_CAM, T.CAM_TRACK)
    assert T.lookup(0x8008, T.CAM_TRACK) is None and T.lookup(0x8009, T.CAM_TRACK) is None
    assert sorted(T.table(T.MCDEVICE_TRACE)) == [0x8008, 0x8009]
    assert not any(e.acknowledgeable for e in T.table(T.MCDEVICE_TRACE).values())


OTHER = [  # (table, code, message, alarms) from §7.12.3-§7.12.7
    (T.EXTERNAL_ENCODER, 0x0021, "Dynamic response values are limited", (50003, 50005)),
    (T.EXTERNAL_ENCODER, 0x801D, "Reference cam or encoder zero mark not found", (40102,)),
    (T.CAM, 0x0027, "Interpolation properties cannot be maintained", (40008,)),
    (T.CAM, 0x8004, "Parameter assignment error", (20003, 20011)),
    (T.CAM, 0x8051, "Read/write access denied", (40001, 40002)),
    (T.CAM, 0x8060, "Error when adding a cam segment", (40004,)),
    (T.CAM, 0x8061, "Cam point out of the domain/range", (40005, 40006)),
    (T.CAM, 0x8062, "Access to an interpolated cam not allowed", (40007,)),
    (T.MEASURING_INPUT, 0x8003, "Fatal configuration error", (20004, 20006, 40006)),
    (T.MEASURING_INPUT, 0x8034, "Could not record a measured value in this range", (40003, 40004)),
    (T.MEASURING_INPUT, 0x8035, "Measuring command canceled", (40005, 40007, 40008)),
    (T.MEASURING_INPUT, 0x8044, "Command not supported by the technology object", (40001,)),
    (T.MEASURING_INPUT, 0x8045, "Command not allowed in current state", (30006, 30009, 40002)),
    (T.OUTPUT_CAM, 0x8021, "Invalid cam position", (40005,)),
    (T.OUTPUT_CAM, 0x8043, "Invalid command parameter value or default value", (30001, 40003)),
    (T.OUTPUT_CAM, 0x8087, "Illegal output cam position", (40001,)),
    (T.CAM_TRACK, 0x8004, "Parameter assignment error", (20003, 20011)),
    (T.CAM_TRACK, 0x8021, "Invalid cam position", (40005,)),
]


@pytest.mark.parametrize("table, code, message, alarms", OTHER, ids=[f"{r[0]}-{r[1]:04X}" for r in OTHER])
def test_s7t_other_tdb_errors(table, code, message, alarms):
    """S7-Technology V4.1 §7.12.3-§7.12.7: rows of the external encoder, cam, measuring input, output cam and cam
    track tables."""
    e = T.lookup(code, table)
    assert (e.message, e.alarms) == (message, alarms)


def test_s7t_tdb_reactions_the_manual_states():
    """S7-Technology V4.1 §4.5.7.2 (HW limit switch: stop, 8013 with 804B), §4.5.7.3 (SW limit switch), §4.7.14
    (801A stops the following axis), §6.5.1 (8021 switches an actual-value output cam off); none where the
    manual gives none (8016, 8018, 8019)."""
    assert "stopped" in T.lookup(0x8013, T.AXIS).reaction and "804B" in T.lookup(0x8013, T.AXIS).reaction
    assert "stops at the limit" in T.lookup(0x8014, T.AXIS).reaction
    assert "8014" in T.lookup(0x0026, T.AXIS).reaction
    assert "following axis is stopped" in T.lookup(0x801A, T.SYNCHRONIZATION_AXIS).reaction
    assert "switched off" in T.lookup(0x8021, T.OUTPUT_CAM).reaction
    for code in (0x8016, 0x8018, 0x8019):
        assert T.lookup(code, T.AXIS).reaction is None
    assert T.lookup(0x8013, T.EXTERNAL_ENCODER).reaction is None
    missing = T.without_reaction()
    assert all(not e.warning and e.reaction is None for e in missing)
    assert any(e.code == 0x8016 and e.table == T.AXIS for e in missing)


def test_s7t_tdb_describe():
    """S7-Technology V4.1 §7.12: a readable line per code; a code the DB cannot show is named as such."""
    assert T.describe(0x8016, T.AXIS).startswith("16#8016 Following error out of limits (axis error)")
    assert "not an ErrorID of the cam technology DB" in T.describe(0x8016, T.CAM)
    with pytest.raises(KeyError):
        T.table("conveyor")
