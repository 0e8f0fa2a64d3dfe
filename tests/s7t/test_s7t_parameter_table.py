"""Every axis parameter of the list by number and by name (S7-Technology V4.1 §9.4, §6.7.4 MC_ReadSysParameter,
§6.7.5 MC_WriteParameter with its examples "Drive control word" and "Backup of absolute encoder adjustment
data", §5.16).

The rows come from tests/s7t/data/s7-technology-parameters.csv (the manual's list); each number is read on an
axis of a type the row names (hydraulic for the "Hydraulic." group, an absolute encoder for the absolute
encoder parameters, an incremental one otherwise).  The codes are §6.7.5's: 8043 illegal value, 8081 read-only,
0020 restart needed.
"""
from __future__ import annotations

import csv
import functools
import math
import pathlib
import struct

import pytest

from plcmotion.s7t import MC_Home, MC_ReadSysParameter, MC_Reset, MC_WriteParameter
from plcmotion.s7t.technology.enums import ENUMS

from _s7t_homing_rig import Rig
from _s7t_rig import controller

CSV = pathlib.Path(__file__).parent / "data" / "s7-technology-parameters.csv"
ILLEGAL, READ_ONLY, RESTART = 0x8043, 0x8081, 0x0020
TECHNOLOGY = {"Positioning axis": 1, "Speed-controlled axis": 0, "synchronization axis": 2,
              "Synchronization axis": 2, "Synchronized axis": 2, "positioning axis": 1, "speed-controlled axis": 0}


def _rows() -> list[dict[str, str]]:
    with CSV.open(newline="") as f:
        return [r for r in csv.DictReader(f) if r["to"] == "Axis"]


ROWS = _rows()


def _technology(row: dict[str, str]) -> int:
    named = [TECHNOLOGY[t.strip()] for t in row["supported_for"].split(",") if t.strip() in TECHNOLOGY]
    return 1 if 1 in named else named[0]


def _setup(row: dict[str, str]) -> tuple[int, bool, int]:
    """(technology, hydraulic, encoder type) of an axis that has the parameter of ``row``."""
    absolute = any(s in row["expert_name"] for s in ("AbsBackLash", "AbsHomingEncoder", "absoluteencoder_x"))
    return _technology(row), row["dbparam_normal_name"].startswith("Hydraulic."), int(absolute)


@functools.cache
def _axis(technology: int, hydraulic: bool, encoder: int):
    ctl = controller()
    params = {"Wizard.Technology": technology, "Wizard.Encoder_1.EncoderType": encoder,
              "TypeOfAxis.Homing.referencingNecessary": 0}
    if hydraulic:
        params["Wizard.DriveTechnology"] = 1
    add = ctl.add_synchronous_axis if technology == 2 else ctl.add_positioning_axis
    axis = add("Axis1", params)
    ctl.run(0.02)
    return axis


def _read(axis, number: int, index: int = 1) -> MC_ReadSysParameter:
    return MC_ReadSysParameter()(Axis=axis, Execute=True, ParameterNumber=number, Index=index)


def _write(axis, number: int, index: int = 1, **value) -> MC_WriteParameter:
    return MC_WriteParameter()(Axis=axis, Execute=True, ParameterNumber=number, Index=index, **value)


def _value_input(row: dict[str, str], rd: MC_ReadSysParameter) -> dict:
    """What MC_ReadSysParameter gave, as MC_WriteParameter inputs of the row's data type (§6.7.4/§6.7.5)."""
    dt = row["data_type"]
    if dt == "REAL":
        return {"Value": rd.Value}
    if dt == "2xDWORD":
        return {"ValueDword1": rd.ValueDword1, "ValueDword2": rd.ValueDword2}
    if row["no"] == "4500":
        return {"ValueDword1": 0, "ValueDword2": 0}          # value + mask: mask 0 changes no bit
    if dt in ("WORD", "DWORD"):
        return {"ValueDword1": rd.ValueDword1}
    return {"ValueDInt": rd.ValueDInt}


def _out_of_range(row: dict[str, str]) -> dict | None:
    """A value the row's type or range excludes, as MC_WriteParameter inputs."""
    dt, lo, hi = row["data_type"], row["min"], row["max"]
    if dt == "REAL":
        return {"Value": 1.0e12}                              # REAL inputs lie strictly inside +-1E+12 (§6.9.3)
    if dt.startswith("DINT Enum"):
        return {"ValueDInt": max(ENUMS[dt.split()[1]].codes()) + 1000}
    if dt == "2xDWORD":                                       # the double of a NaN: no adjustment
        return {"ValueDword1": 0x7FF8_0000, "ValueDword2": 0}
    if row["no"] == "4500":
        return {"ValueDword1": 1, "ValueDword2": 1}           # CW1 bit 0 belongs to the TO
    if dt == "WORD":
        return {"ValueDword1": int(hi) + 1 if hi not in ("-", "") else 0x1_0000}
    if dt == "DINT" and hi not in ("-", ""):
        return {"ValueDInt": int(hi) + 1}
    return None


@pytest.mark.parametrize("row", ROWS, ids=lambda r: r["no"])
def test_s7t_parameter_table_every_number_readable(row):
    """S7-Technology V4.1 §9.4, §6.7.4: every axis parameter of the list is read on an axis of its type,
    at the output of its data type."""
    axis = _axis(*_setup(row))
    rd = _read(axis, int(row["no"]))
    assert rd.Done and not rd.Error, (row["no"], hex(rd.ErrorID))


WRITABLE = [r for r in ROWS if "Write" in r["access"]]
READ_ONLY_ROWS = [r for r in ROWS if "Write" not in r["access"]]


@pytest.mark.parametrize("row", WRITABLE, ids=lambda r: r["no"])
def test_s7t_parameter_table_writable_accept_default_refuse_range(row):
    """S7-Technology V4.1 §6.7.5: a "Read, Write" parameter takes its own (default) value back without a
    restart (0020 only when the value changes) and refuses a value outside its type or range with 8043."""
    axis = _axis(*_setup(row))
    number = int(row["no"])
    default = _value_input(row, _read(axis, number))
    wr = _write(axis, number, **default)
    assert wr.Done and not wr.Error and wr.ErrorID == 0, (row["no"], hex(wr.ErrorID))
    bad = _out_of_range(row)
    if bad is not None:
        wr = _write(axis, number, **bad)
        assert wr.Error and wr.ErrorID == ILLEGAL, (row["no"], hex(wr.ErrorID))
        assert _value_input(row, _read(axis, number)) == default


@pytest.mark.parametrize("row", READ_ONLY_ROWS, ids=lambda r: r["no"])
def test_s7t_parameter_table_read_only_refused(row):
    """S7-Technology V4.1 §6.7.5: writing a "Read" parameter gives 8081."""
    axis = _axis(*_setup(row))
    number = int(row["no"])
    wr = _write(axis, number, **_value_input(row, _read(axis, number)))
    assert wr.Error and wr.ErrorID == READ_ONLY, (row["no"], hex(wr.ErrorID))


def _restart(ctl, axis) -> None:
    reset = MC_Reset()
    reset(Axis=axis, Execute=True, Restart=True)
    for _ in range(200):
        ctl.run(0.004)
        if reset(Execute=True).Done:
            break
    assert reset.Done
    ctl.run(0.01)


def test_s7t_parameter_table_stored_restart_parameter():
    """S7-Technology V4.1 §6.7.5 (0020), §7.1 RequestRestart: a "Restart" parameter without a modelled effect
    (1264 friction compensation activation) follows the same rule: the old value until MC_Reset Restart."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", {"TypeOfAxis.Homing.referencingNecessary": 0})
    ctl.run(0.02)
    wr = _write(axis, 1264, ValueDInt=1)                     # EnumYesNo YES
    assert wr.Done and wr.ErrorID == RESTART and not wr.Error
    ctl.run(0.01)
    assert axis.db.Statusword.RequestRestart and _read(axis, 1264).ValueDInt == 0
    _restart(ctl, axis)
    assert not axis.db.Statusword.RequestRestart and _read(axis, 1264).ValueDInt == 1
    assert _write(axis, 1113, Value=0.05).ErrorID == 0       # Immediately: read back at once
    assert _read(axis, 1113).Value == pytest.approx(0.05)


def test_s7t_parameter_table_by_name_in_project_files():
    """S7-Technology V4.1 §9.4: the expert-list names configure the axis; MC_ReadSysParameter reads what was
    configured (4121 minuslimitsofdynamics.negativeaccel, 3011 of encoder 1, 5005 of a hydraulic axis)."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", {
        "minuslimitsofdynamics.negativeaccel": 250.0,
        "TypeOfAxis.NumberOfEncoders.Encoder_1.AdaptDrive.denFactor": 4,
        "TypeOfAxis.Homing.referencingNecessary": 0})
    hyd = ctl.add_positioning_axis("Press", {"Wizard.DriveTechnology": 1,
                                             "TypeOfAxis.SlidingFriction.FactorMotionControl": 0.5})
    ctl.run(0.02)
    assert _read(axis, 4121).Value == 250.0
    assert _read(axis, 3011).ValueDInt == 4
    assert _read(hyd, 5005).Value == 0.5
    with pytest.raises(Exception, match="negativeaccel"):
        controller().add_positioning_axis("Bad", {"minuslimitsofdynamics.negativeaccel": -1.0})


def test_s7t_parameter_table_index_beyond_the_encoders():
    """S7-Technology V4.1 §6.7.4: Index names an encoder of the axis; encoder 2 of a one-encoder axis is no
    parameter of it (8080)."""
    axis = _axis(1, False, 0)
    assert _read(axis, 3011, index=2).ErrorID == 0x8080


# --- §6.7.5 example "Drive control word" ------------------------------------------------------------------------
def test_s7t_parameter_table_control_word_mask_example():
    """S7-Technology V4.1 §6.7.5 example: ValueDword1 = DW#16#00010300 under the mask ValueDword2 =
    DW#16#0FFFFB00 writes the free bits of CW1 (8, 9, 11-15) and CW2 (0-11); bit 10 of CW1 and the TO's bits
    stay the TO's.  A read gives both words unmasked in ValueDword1; unmasked bits keep their state."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", {"TypeOfAxis.Homing.referencingNecessary": 0})
    ctl.run(0.02)
    own = _read(axis, 4500).ValueDword1                      # the TO's bits of the disabled axis
    assert own & ~0x0000_04FF == 0                           # only CW1 bits 0-7 and 10 are set by the TO
    wr = _write(axis, 4500, ValueDword1=0x0001_0300, ValueDword2=0x0FFF_FB00)
    assert wr.Done and not wr.Error
    assert _read(axis, 4500).ValueDword1 == own | 0x0001_0300
    assert _write(axis, 4500, ValueDword1=0, ValueDword2=0x0000_0100).Done     # clear bit 8 only
    assert _read(axis, 4500).ValueDword1 == own | 0x0001_0200
    assert _write(axis, 4500, ValueDword1=0x0000_0400, ValueDword2=0x0000_0400).ErrorID == ILLEGAL  # bit 10
    assert _write(axis, 4500, ValueDword1=0, ValueDword2=0xF000_0000).ErrorID == ILLEGAL  # master sign of life
    assert _read(axis, 4500).ValueDword1 == own | 0x0001_0200


# --- §6.7.5 example "Backup of absolute encoder adjustment data" -----------------------------------------------
ABS_AXIS = {"Wizard.Encoder_1.EncoderType": 1, "Plant.InitialPosition": 37.0, "swlimit.state": 0}


def test_s7t_parameter_table_absolute_encoder_backup_and_restore(tmp_path):
    """S7-Technology V4.1 §6.7.5 example: after MC_Home (absolute encoder adjustment) MC_ReadSysParameter 4010
    gives the adjustment in ValueDword1/ValueDword2; on a replaced CPU (no retentive data) the axis is not
    adjusted (4011 NO) until MC_WriteParameter 4010 writes the two DWORDs back - then the axis is at the
    adjusted position and homed again, and the adjustment is retained."""
    r = Rig(ABS_AXIS, state_file=str(tmp_path / "old.json"))
    h = MC_Home()
    r.call(h, 0.02, Execute=True, Mode=5, Position=100.0)
    assert h.Done and not h.Error
    r.ctl.run(0.1)
    backup = _read(r.axis, 4010)
    assert backup.Done and not backup.Error and _read(r.axis, 4011).ValueDInt == 1      # EnumYesNo YES
    dwords = {"ValueDword1": backup.ValueDword1, "ValueDword2": backup.ValueDword2}
    assert struct.unpack(">d", struct.pack(">II", backup.ValueDword1, backup.ValueDword2))[0] == \
        pytest.approx(63.0, abs=0.01)                         # 100 - 37: the offset to the encoder's value

    new = Rig(ABS_AXIS, state_file=str(tmp_path / "new.json"), enable=False)   # the replaced CPU
    db = new.axis.db
    assert db.ActualPosition == pytest.approx(37.0, abs=0.001) and not db.Statusword.HomingDone
    assert _read(new.axis, 4011).ValueDInt == 0
    wr = _write(new.axis, 4010, **dwords)
    assert wr.Done and not wr.Error
    new.ctl.run(0.1)
    assert db.ActualPosition == pytest.approx(100.0, abs=0.001) and db.Statusword.HomingDone
    assert _read(new.axis, 4011).ValueDInt == 1
    again = Rig(ABS_AXIS, state_file=str(tmp_path / "new.json"), enable=False)    # POWER OFF -> ON
    assert again.axis.db.ActualPosition == pytest.approx(100.0, abs=0.001)


def test_s7t_parameter_table_absolute_encoder_only():
    """S7-Technology V4.1 §6.7.5: the adjustment exists for an encoder of the type "absolute encoder"; an
    incremental encoder has no 4010 (8080); a NaN as adjustment is an illegal value (8043)."""
    inc = _axis(1, False, 0)
    assert _read(inc, 4010).ErrorID == 0x8080 and _write(inc, 4010, ValueDword1=0, ValueDword2=0).ErrorID == 0x8080
    nan = struct.unpack(">II", struct.pack(">d", math.nan))
    assert _write(_axis(1, False, 1), 4010, ValueDword1=nan[0], ValueDword2=nan[1]).ErrorID == ILLEGAL


def test_s7t_parameter_table_docs_say_what_acts():
    """S7-Technology V4.1 §9.4: docs/s7t/parameters.md says for every axis parameter whether it acts in the
    model, is computed, or is only stored (1100 leadscrew pitch acts, 1264 friction compensation is stored,
    4010 absolute encoder adjustment is kept by the technology)."""
    page = (pathlib.Path(__file__).parents[2] / "docs" / "s7t" / "parameters.md").read_text()
    axis_part = page.split("## Axis", 1)[1].split("\n## ", 1)[0]
    lines = {int(line.split("|")[1]): line for line in axis_part.splitlines() if line[:3] == "| 1" or
             line[:2] == "| " and line.split("|")[1].strip().isdigit()}
    assert set(lines) == {int(r["no"]) for r in ROWS}
    kinds = {n: line.split("|")[11].strip() for n, line in lines.items()}
    assert set(kinds.values()) == {"acts", "computed", "stored"}
    assert (kinds[1100], kinds[1264], kinds[4010], kinds[4121]) == ("acts", "stored", "computed", "stored")


@pytest.mark.parametrize("position, state", [(110.0, 1), (50.0, 0)])
def test_s7t_parameter_table_bero_state(position, state):
    """S7-Technology V4.1 §9.4 4174 homingcommand.berostate (EnumActiveInactive): ACTIVE while the reference
    cam (I0.0, machine 100..120) is actuated."""
    r = Rig({"Plant.InitialPosition": position}, enable=False)
    assert _read(r.axis, 4174).ValueDInt == state
