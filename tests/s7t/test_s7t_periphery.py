"""FB 450 MC_ReadPeriphery and FB 451 MC_WritePeriphery: the technology I/O image 0..63 (S7-Technology V4.1
§6.7.6, §6.7.7, §5.6), here the controller's digital inputs and outputs (input byte n bit b = ``In.b``).
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_ReadPeriphery, MC_WritePeriphery
from plcmotion.s7t.service import MAX_COMMANDS

from _s7t_rig import controller

OB1 = 0.004            # one OB1 cycle = one technology DB update (IPO 2 ms, DB update every 2 IPO cycles)


def _ctl():
    ctl = controller(input_filter=0.0)
    ctl.run(0.02)
    return ctl


def test_s7t_read_periphery_timeline():
    """S7-Technology V4.1 §6.7.6 example: the first call with Enable is Busy (command handed over), the
    second delivers the image of the first command cycle with DataValid, every further call the image of
    the previous one."""
    ctl = _ctl()
    ctl.inputs["I10.0"] = True
    ctl.inputs["I11.7"] = True
    data = bytearray(2)
    fb = MC_ReadPeriphery()
    fb(Enable=True, InputOutput=False, ByteAddress=10, Data=data)
    assert fb.Busy and not fb.DataValid and data == bytearray(2)
    ctl.inputs["I10.1"] = True                         # changes after the first command cycle
    ctl.run(OB1)
    fb(Enable=True)
    assert fb.Busy and fb.DataValid and data == bytearray([0x01, 0x80])
    ctl.run(OB1)
    fb(Enable=True)
    assert data == bytearray([0x03, 0x80])
    fb(Enable=False)
    assert not fb.Busy and not fb.DataValid and not fb.Error


def test_s7t_read_periphery_output_image_and_integrated_io():
    """S7-Technology V4.1 §6.7.6: InputOutput = TRUE reads the output image; byte 0 is the integrated I/O of
    the CPU, which the MCDevice DB shows as DIStatus / DOStatus (§7.10)."""
    ctl = _ctl()
    ctl.outputs["Q0.2"] = True
    ctl.inputs["I0.3"] = True
    outs, ins = bytearray(1), bytearray(1)
    a, b = MC_ReadPeriphery(), MC_ReadPeriphery()
    for _ in range(2):
        a(Enable=True, InputOutput=True, ByteAddress=0, Data=outs)
        b(Enable=True, InputOutput=False, ByteAddress=0, Data=ins)
        ctl.run(OB1)
    assert outs == bytearray([0x04]) and ins == bytearray([0x08])
    mc = ctl.extension.mcdevice
    assert mc.DOStatus[2] and mc.DIStatus[3]


def test_s7t_write_periphery_round_trip():
    """S7-Technology V4.1 §6.7.7: Done at the second call; the bytes are in the output image (Q20.x, Q21.x)
    and a MC_ReadPeriphery of the output image reads them back."""
    ctl = _ctl()
    fb = MC_WritePeriphery()
    fb(Execute=True, ByteAddress=20, Data=bytes([0xA5, 0x01]))
    assert fb.Busy and not fb.Done and not ctl.outputs["Q20.0"]
    ctl.run(OB1)
    fb(Execute=True)
    assert fb.Done and not fb.Busy
    assert [ctl.outputs[f"Q20.{b}"] for b in range(8)] == [True, False, True, False, False, True, False, True]
    assert ctl.outputs["Q21.0"] and not ctl.outputs["Q21.1"]
    data = bytearray(2)
    rd = MC_ReadPeriphery()
    for _ in range(2):
        rd(Enable=True, InputOutput=True, ByteAddress=20, Data=data)
        ctl.run(OB1)
    assert data == bytearray([0xA5, 0x01])


def test_s7t_write_periphery_cyclic_retrigger():
    """S7-Technology V4.1 §6.7.7: cyclic writing with Execute := NOT Busy AND NOT Error writes every other
    call."""
    ctl = _ctl()
    fb = MC_WritePeriphery()
    written = []
    for k in range(8):
        fb(Execute=not fb.Busy and not fb.Error, ByteAddress=30, Data=bytes([k]))
        if fb.Done:
            written.append(k)
        ctl.run(OB1)
    assert written == [1, 3, 5, 7]


def test_s7t_write_periphery_done_flag():
    """S7-Technology V4.1 §6.9.2: DoneFlag = 5 toggles MCDevice.DoneFlag[5] when the write is done."""
    ctl = _ctl()
    fb = MC_WritePeriphery()
    fb(Execute=True, ByteAddress=1, Data=b"\x01", DoneFlag=5)
    ctl.run(3 * OB1)
    assert ctl.extension.mcdevice.DoneFlag[5] is True


@pytest.mark.parametrize("fb_cls, inputs, error_id", [
    (MC_ReadPeriphery, dict(ByteAddress=64, Data=bytearray(1)), 0x8043),
    (MC_ReadPeriphery, dict(ByteAddress=-1, Data=bytearray(1)), 0x8043),
    (MC_ReadPeriphery, dict(ByteAddress=0, Data=None), 0x8088),
    (MC_ReadPeriphery, dict(ByteAddress=0, Data=[0, 0]), 0x808C),
    (MC_ReadPeriphery, dict(ByteAddress=0, Data=b"\x00"), 0x808C),      # a destination must be writable
    (MC_ReadPeriphery, dict(ByteAddress=0, Data=bytearray(65)), 0x8089),
    (MC_ReadPeriphery, dict(ByteAddress=60, Data=bytearray(8)), 0x8089),
    (MC_ReadPeriphery, dict(ByteAddress=0, Data=bytearray(0)), 0x8089),
    (MC_WritePeriphery, dict(ByteAddress=64, Data=b"\x00"), 0x8043),
    (MC_WritePeriphery, dict(ByteAddress=0, Data=b"\x00", DoneFlag=33), 0x8043),
    (MC_WritePeriphery, dict(ByteAddress=0, Data=None), 0x8088),
    (MC_WritePeriphery, dict(ByteAddress=0, Data="ab"), 0x808C),
    (MC_WritePeriphery, dict(ByteAddress=63, Data=b"\x00\x00"), 0x8089),
    (MC_WritePeriphery, dict(ByteAddress=0, Data=bytes(65)), 0x8089),
])
def test_s7t_periphery_errors(fb_cls, inputs, error_id):
    """S7-Technology V4.1 §6.7.6 / §6.7.7 ErrorIDs: 8043 ByteAddress (0..63) or DoneFlag, 8088 no data area,
    808C pointer format, 8089 more than 64 bytes or beyond the image; nothing is written."""
    ctl = _ctl()
    fb = fb_cls()
    start = {"Enable": True} if fb_cls is MC_ReadPeriphery else {"Execute": True}
    fb(**start, **inputs)
    assert fb.Error and fb.ErrorID == error_id and not fb.Busy and not fb.ENO
    ctl.run(2 * OB1)
    assert not any(ctl.outputs[f"Q{n}.{b}"] for n in range(64) for b in range(8))


def test_s7t_periphery_command_capacity():
    """S7-Technology V4.1 §6.7.6 (8005): too many running commands of the data-transfer FBs; the command
    is refused until one of them is finished."""
    ctl = _ctl()
    readers = [MC_ReadPeriphery() for _ in range(MAX_COMMANDS)]
    for r in readers:
        r(Enable=True, ByteAddress=0, Data=bytearray(1))
        assert r.Busy
    extra = MC_WritePeriphery()
    extra(Execute=True, ByteAddress=0, Data=b"\x01")
    assert extra.Error and extra.ErrorID == 0x8005
    readers[0](Enable=False)
    extra(Execute=False)
    extra(Execute=True)
    assert extra.Busy and not extra.Error
