"""The S7-1200 override table (s7_1200/technology/override.py) against the manual's "Override response" lists.

S7-1200 Motion Control V6 §11.1.3.1 (MC_Home by mode), §11.1.4.1 MC_Halt, §11.1.5.1 MC_MoveAbsolute,
§11.1.6.1 MC_MoveRelative, §11.1.7.1 MC_MoveVelocity, §11.1.8.1 MC_MoveJog, §11.1.9.1 MC_CommandTable give,
per instruction, "can be aborted by" and "aborts"; §12.8 gives the rejections of 16#8207 (ErrorInfo
16#0016, 16#0018, 16#0019).  They are written out below as printed, not taken from the code under test.
"""
from __future__ import annotations

import pytest

from plcmotion.kernel.policy import Reject
from plcmotion.s7_1200 import errors as E
from plcmotion.s7_1200.technology import override as O

HOME01, HOME67, HOME2, HOME3 = "MC_Home Mode 0/1", "MC_Home Mode 6/7", "MC_Home Mode 2", "MC_Home Mode 3"
_MOTION = ["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity", "MC_MoveJog"]
_EVERY = [HOME3, *_MOTION, "MC_CommandTable"]      # the list printed under each motion command

# instruction: (can be aborted by, aborts)
MANUAL_11_1 = {
    HOME01: ([], []),                     # Mode 0/1/6/7: "cannot be aborted ... does not abort"
    HOME67: ([], []),
    HOME2: ([HOME2, HOME3], [HOME2]),
    HOME3: (_EVERY, [HOME2, *_EVERY]),
    **{name: (_EVERY, _EVERY) for name in _MOTION},
    "MC_CommandTable": (_EVERY, _EVERY),
}

# §11.1.3 "Requirements" / §12.8 16#8207: (new, running) -> ErrorInfo of the rejection
MANUAL_12_8_REJECTS = {
    (HOME01, HOME3): 0x0016, (HOME67, HOME3): 0x0016, (HOME2, HOME3): 0x0016,   # active homing is running
    ("MC_CommandTable", HOME2): 0x0018,                       # no table while the axis is passively homed
    (HOME01, "MC_CommandTable"): 0x0019, (HOME2, "MC_CommandTable"): 0x0019,   # no homing during a table
}


@pytest.mark.parametrize("new", list(MANUAL_11_1))
def test_s7_1200_override_table_rows_are_the_aborts_lists(new):
    """S7-1200 V6 §11.1.x "The new ... command aborts the following active Motion Control commands"."""
    aborts = MANUAL_11_1[new][1]
    for running in O.COLUMNS:
        assert O.POLICY.aborts(new, running) == (running in aborts), (new, running)


@pytest.mark.parametrize("running", list(MANUAL_11_1))
def test_s7_1200_override_table_columns_are_the_aborted_by_lists(running):
    """S7-1200 V6 §11.1.x "The ... command can be aborted by the following Motion Control commands"."""
    aborted_by = MANUAL_11_1[running][0]
    for new in O.COLUMNS:
        assert O.POLICY.aborts(new, running) == (new in aborted_by), (new, running)


def test_s7_1200_override_table_rejections_s12_8():
    """S7-1200 V6 §12.8 ErrorID 16#8207: the cells that refuse the new command, with their ErrorInfo."""
    rejects = {(new, running): cell for new, row in O.TABLE.items() for running, cell in row.items()
               if isinstance(cell, Reject)}
    assert set(rejects) == set(MANUAL_12_8_REJECTS)
    for cell_at, info in MANUAL_12_8_REJECTS.items():
        assert E.codes(rejects[cell_at].fault()) == (0x8207, info), cell_at


def test_s7_1200_override_table_covers_every_instruction_s11_1():
    assert set(O.COLUMNS) == set(MANUAL_11_1) == set(O.TABLE)
