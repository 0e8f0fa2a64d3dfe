"""FB 453 MC_ReadRecord, FB 454 MC_WriteRecord, FB 455 MC_ReadDriveParameter and FB 456
MC_WriteDriveParameter (S7-Technology V4.1 §6.7.8-§6.7.11) against the simulated drive on DP(DRIVE).

The drive is the real axis's PROFIdrive drive at logical base address 256 (first slave); its parameters
carry SINAMICS numbers (p2000 reference speed, p1082 maximum speed, r0063 actual speed, r0947 faults, p0922
telegram) and record 47 is the PROFIdrive parameter channel.  ErrorIDs 16#81xx are 16#8100 + the PROFIdrive
error number of the drive's answer.
"""
from __future__ import annotations

import struct

import pytest

from plcmotion.s7t import (MC_MoveVelocity, MC_Power, MC_ReadDriveParameter, MC_ReadRecord, MC_WriteDriveParameter,
                           MC_WriteRecord)

from _s7t_rig import VIRTUAL, controller

OB1 = 0.004
BASE = 256
REAL_AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0, "Drive": {"ReferenceSpeed": 3000.0, "MaxSpeed": 6000.0},
             "TypeOfAxis.MaxVelocity.maximum": 500.0}


def _ctl():
    ctl = controller()
    axis = ctl.add_positioning_axis("Real", REAL_AXIS)
    ctl.add_positioning_axis("Virtual", VIRTUAL)            # a virtual axis has no slave
    ctl.run(0.02)
    return ctl, axis


def _until_done(ctl, fb, limit: int = 20) -> int:
    """Calls (one per OB1 cycle) until the command is no longer Busy; the number of calls made."""
    for n in range(1, limit + 1):
        ctl.run(OB1)
        fb(Execute=True)
        if not fb.Busy:
            return n
    raise AssertionError(f"{fb} still busy")


def test_s7t_read_drive_parameter_busy_then_done():
    """S7-Technology V4.1 §6.7.10: Busy while the request travels to the drive and back (two technology DB
    updates here), then Done with DataLength; p2000 = the configured reference speed 3000 1/min (REAL)."""
    ctl, axis = _ctl()
    data = bytearray(4)
    fb = MC_ReadDriveParameter()
    fb(Execute=True, Address=BASE, ParameterNumber=2000, Data=data)
    assert fb.Busy and not fb.Done
    assert _until_done(ctl, fb) == 2
    assert fb.Done and fb.DataLength == 4 and struct.unpack(">f", data)[0] == 3000.0
    fb(Execute=False)
    assert not fb.Done and fb.DataLength == 0


def test_s7t_write_then_read_drive_parameter():
    """S7-Technology V4.1 §6.7.11 / §6.7.10: p1082 written with 4500.0 reads back as 4500.0."""
    ctl, axis = _ctl()
    wr = MC_WriteDriveParameter()
    wr(Execute=True, Address=BASE, ParameterNumber=1082, Data=struct.pack(">f", 4500.0))
    _until_done(ctl, wr)
    assert wr.Done and not wr.Error
    data = bytearray(4)
    rd = MC_ReadDriveParameter()
    rd(Execute=True, Address=BASE, ParameterNumber=1082, Data=data)
    _until_done(ctl, rd)
    assert struct.unpack(">f", data)[0] == 4500.0


def test_s7t_read_actual_speed_of_moving_drive():
    """S7-Technology V4.1 §6.7.10: r0063 is the drive's actual speed: 50 mm/s at 10 mm per revolution is
    300 1/min."""
    ctl, axis = _ctl()
    power, move = MC_Power(), MC_MoveVelocity()

    @ctl.program
    def ob1():
        power(Axis=axis, Enable=True)
    ctl.run(0.3)
    move(Axis=axis, Execute=True, Velocity=50.0, Acceleration=500.0, Deceleration=500.0, Jerk=0.0)
    ctl.run(1.0)
    data = bytearray(4)
    rd = MC_ReadDriveParameter()
    rd(Execute=True, Address=BASE, ParameterNumber=63, Data=data)
    _until_done(ctl, rd)
    assert struct.unpack(">f", data)[0] == pytest.approx(300.0, rel=0.01)


def test_s7t_read_indexed_drive_parameter():
    """S7-Technology V4.1 §6.7.10: NumberOfElements = 8 from SubIndex 0 reads r0947[0..7] (8 x 2 bytes);
    no drive fault: all 0."""
    ctl, axis = _ctl()
    data = bytearray(16)
    rd = MC_ReadDriveParameter()
    rd(Execute=True, Address=BASE, ParameterNumber=947, SubIndex=0, NumberOfElements=8, Data=data)
    _until_done(ctl, rd)
    assert rd.Done and rd.DataLength == 16 and data == bytearray(16)


@pytest.mark.parametrize("cls, inputs, error_id", [
    (MC_ReadDriveParameter, dict(ParameterNumber=9999), 0x8100),                       # not found
    (MC_WriteDriveParameter, dict(ParameterNumber=63, Data=struct.pack(">f", 1.0)), 0x8101),   # r0063
    (MC_WriteDriveParameter, dict(ParameterNumber=2000, Data=struct.pack(">f", 5.0)), 0x8102),  # p2000 >= 6
    (MC_ReadDriveParameter, dict(ParameterNumber=947, SubIndex=7, NumberOfElements=2,
                                 Data=bytearray(4)), 0x8103),                            # r0947[0..7]
    (MC_ReadDriveParameter, dict(ParameterNumber=2000, SubIndex=1, NumberOfElements=1), 0x8104),
])
def test_s7t_drive_parameter_errors_of_the_drive(cls, inputs, error_id):
    """S7-Technology V4.1 §6.7.10 / §6.7.11 ErrorIDs 8100 (parameter not found), 8101 (read-only), 8102
    (limits), 8103 (subindex), 8104 (not indexed): the drive answers with the PROFIdrive error; Busy first,
    then Error."""
    ctl, axis = _ctl()
    fb = cls()
    fb(**{"Execute": True, "Address": BASE, "Data": bytearray(4), **inputs})
    assert fb.Busy
    _until_done(ctl, fb)
    assert fb.Error and fb.ErrorID == error_id and not fb.Done


def test_s7t_write_commissioning_parameter_while_drive_enabled():
    """S7-Technology V4.1 §6.7.11 (8111 access denied in the current state): p0922 (telegram) is changed only
    with the pulses off."""
    ctl, axis = _ctl()
    power = MC_Power()

    @ctl.program
    def ob1():
        power(Axis=axis, Enable=True)
    ctl.run(0.3)
    wr = MC_WriteDriveParameter()
    wr(Execute=True, Address=BASE, ParameterNumber=922, Data=struct.pack(">H", 105))
    _until_done(ctl, wr)
    assert wr.ErrorID == 0x8111


@pytest.mark.parametrize("cls, inputs, error_id", [
    (MC_ReadDriveParameter, dict(ParameterNumber=70000), 0x8043),
    (MC_ReadDriveParameter, dict(ParameterNumber=-1), 0x8043),
    (MC_ReadDriveParameter, dict(SubIndex=65536), 0x8043),
    (MC_ReadDriveParameter, dict(NumberOfElements=-1), 0x8043),
    (MC_ReadDriveParameter, dict(NumberOfElements=235), 0x8043),
    (MC_ReadDriveParameter, dict(DoneFlag=33), 0x8043),
    (MC_ReadDriveParameter, dict(Data=bytearray(241)), 0x808D),
    (MC_ReadDriveParameter, dict(Data=None), 0x8088),
    (MC_ReadDriveParameter, dict(Data=(1, 2)), 0x808C),
    (MC_ReadDriveParameter, dict(Address=0), 0x8091),
    (MC_ReadDriveParameter, dict(Address=1000), 0x8090),
    (MC_WriteDriveParameter, dict(NumberOfElements=229, Data=b"\x00\x00"), 0x8043),
    (MC_WriteDriveParameter, dict(Data=bytes(229)), 0x808D),
    (MC_WriteDriveParameter, dict(Data=b"\x00\x00"), 0x808E),       # p2000 is REAL: 4 bytes
])
def test_s7t_drive_parameter_input_errors(cls, inputs, error_id):
    """S7-Technology V4.1 §6.7.10 / §6.7.11 ErrorIDs of the inputs: 8043 ParameterNumber / SubIndex /
    NumberOfElements / DoneFlag, 808D data area too long (240 / 228 bytes), 8088 / 808C data area, 8090 no
    base address, 8091 integrated I/O, 808E data that do not fit the parameter; refused at once."""
    ctl, axis = _ctl()
    fb = cls()
    fb(**{"Execute": True, "Address": BASE, "ParameterNumber": 2000, "Data": bytearray(4), **inputs})
    assert fb.Error and fb.ErrorID == error_id and not fb.Busy


def test_s7t_drive_parameter_one_request_per_drive():
    """S7-Technology V4.1 §6.7.10 (80C7): a second command to the same drive while the first is out is
    refused; retried after the first is done it goes through."""
    ctl, axis = _ctl()
    a, b = MC_ReadDriveParameter(), MC_ReadDriveParameter()
    a(Execute=True, Address=BASE, ParameterNumber=2000, Data=bytearray(4))
    b(Execute=True, Address=BASE, ParameterNumber=1082, Data=bytearray(4))
    assert a.Busy and b.Error and b.ErrorID == 0x80C7
    _until_done(ctl, a)
    b(Execute=False)
    b(Execute=True)
    assert b.Busy


def test_s7t_record_47_parameter_request_round_trip():
    """S7-Technology V4.1 §6.7.9 / §6.7.8: a PROFIdrive parameter request written to record 47 with
    MC_WriteRecord is answered in record 47 (MC_ReadRecord): reference 7 mirrored, response ID 1, format 8
    (FLOATING_POINT), one value: p2000 = 3000.0."""
    ctl, axis = _ctl()
    request = bytes([7, 0x01, 0, 1, 0x10, 1]) + struct.pack(">HH", 2000, 0)
    wr = MC_WriteRecord()
    wr(Execute=True, Address=BASE, RecordNumber=47, Data=request)
    _until_done(ctl, wr)
    assert wr.Done
    data = bytearray(32)
    rd = MC_ReadRecord()
    rd(Execute=True, Address=BASE, RecordNumber=47, Data=data)
    _until_done(ctl, rd)
    assert rd.Done and rd.DataLength == 10
    assert data[:6] == bytes([7, 0x01, 0, 1, 0x08, 1]) and struct.unpack(">f", data[6:10])[0] == 3000.0
    rd(Execute=False)
    rd(Execute=True)
    _until_done(ctl, rd)
    assert rd.Error and rd.ErrorID == 0x80C0                 # the answer was read already


@pytest.mark.parametrize("cls, inputs, error_id, at_once", [
    (MC_ReadRecord, dict(RecordNumber=5), 0x80B0, False),
    (MC_ReadRecord, dict(RecordNumber=47), 0x80C0, False),           # no request: no data
    (MC_ReadRecord, dict(RecordNumber=256), 0x8043, True),
    (MC_ReadRecord, dict(RecordNumber=47, Data=bytearray(241)), 0x808D, True),
    (MC_ReadRecord, dict(RecordNumber=47, Address=288), 0x8090, True),   # only one real drive
    (MC_ReadRecord, dict(RecordNumber=47, Address=0), 0x8091, True),
    (MC_WriteRecord, dict(RecordNumber=5, Data=b"\x00"), 0x80B0, False),
    (MC_WriteRecord, dict(RecordNumber=47, Data=bytes(241)), 0x808D, True),
    (MC_WriteRecord, dict(RecordNumber=-1, Data=b"\x00"), 0x8043, True),
])
def test_s7t_record_errors(cls, inputs, error_id, at_once):
    """S7-Technology V4.1 §6.7.8 / §6.7.9 ErrorIDs: 80B0 record not supported, 80C0 no data yet, 8043
    RecordNumber, 808D longer than 240 bytes, 8090 / 8091 address; input errors at once, the slave's
    answers after Busy."""
    ctl, axis = _ctl()
    fb = cls()
    fb(**{"Execute": True, "Address": BASE, "Data": bytearray(8), **inputs})
    if not at_once:
        assert fb.Busy
        _until_done(ctl, fb)
    assert fb.Error and fb.ErrorID == error_id


def test_s7t_read_record_data_area_too_short():
    """S7-Technology V4.1 §6.7.8 (80B1): the answer (10 bytes) does not fit a Data area of 8 bytes."""
    ctl, axis = _ctl()
    wr = MC_WriteRecord()
    wr(Execute=True, Address=BASE, RecordNumber=47, Data=bytes([1, 1, 0, 1, 0x10, 1, 0x07, 0xD0, 0, 0]))
    _until_done(ctl, wr)
    rd = MC_ReadRecord()
    rd(Execute=True, Address=BASE, RecordNumber=47, Data=bytearray(8))
    _until_done(ctl, rd)
    assert rd.ErrorID == 0x80B1


def test_s7t_write_record_same_record_busy():
    """S7-Technology V4.1 §6.7.9 (80C0): a write to a record whose previous write still runs is refused."""
    ctl, axis = _ctl()
    a, b = MC_WriteRecord(), MC_WriteRecord()
    req = bytes([1, 1, 0, 1, 0x10, 1, 0x07, 0xD0, 0, 0])
    a(Execute=True, Address=BASE, RecordNumber=47, Data=req)
    b(Execute=True, Address=BASE, RecordNumber=47, Data=req)
    assert a.Busy and b.Error and b.ErrorID == 0x80C0


def test_s7t_read_drive_parameter_done_flag():
    """S7-Technology V4.1 §6.9.2: DoneFlag = 3 toggles MCDevice.DoneFlag[3] at Done."""
    ctl, axis = _ctl()
    fb = MC_ReadDriveParameter()
    fb(Execute=True, Address=BASE, ParameterNumber=2000, Data=bytearray(4), DoneFlag=3)
    assert not ctl.extension.mcdevice.DoneFlag[3]
    _until_done(ctl, fb)
    ctl.run(OB1)
    assert ctl.extension.mcdevice.DoneFlag[3]


def test_s7t_record_fbs_do_not_abort_motion():
    """S7-Technology V4.1 §6.8: the record and drive-parameter FBs abort no command."""
    ctl, axis = _ctl()
    power, move = MC_Power(), MC_MoveVelocity()

    @ctl.program
    def ob1():
        power(Axis=axis, Enable=True)
    ctl.run(0.3)
    move(Axis=axis, Execute=True, Velocity=20.0)
    rd = MC_ReadDriveParameter()
    rd(Execute=True, Address=BASE, ParameterNumber=2000, Data=bytearray(4))
    _until_done(ctl, rd)
    assert rd.Done and move(Execute=True).Busy and not move.CommandAborted
