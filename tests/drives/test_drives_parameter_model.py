"""The acyclic parameter channel of the simulated PROFIdrive drive (PROFIdrive profile, base mode parameter
access in data record 47): request/response layout and the profile's error numbers."""
from __future__ import annotations

import struct

from plcmotion.drives.profidrive import parameter_model as PM


def _model() -> PM.ParameterModel:
    params = [PM.DriveParameter(2000, PM.FLOAT32, minimum=6.0, maximum=210000.0),
              PM.DriveParameter(922, PM.UNSIGNED16, minimum=1, maximum=999, only_when_off=True),
              PM.DriveParameter(947, PM.UNSIGNED16, elements=8, writable=False, read_fn=lambda i: 10.0 + i)]
    return PM.ParameterModel(params, {2000: [3000.0], 922: [105.0]}, pulses_on=lambda: False)


def test_drives_parameter_read_response_layout():
    """PROFIdrive base mode: read request of p2000 -> reference mirrored, response ID 1, format 8 (float),
    one value 3000.0 big-endian."""
    resp = _model().process(bytes([9, 0x01, 0, 1, 0x10, 1]) + struct.pack(">HH", 2000, 0))
    assert resp[:6] == bytes([9, 0x01, 0, 1, 0x08, 1]) and struct.unpack(">f", resp[6:10])[0] == 3000.0
    assert PM.response_values(resp) == (None, resp[6:10])


def test_drives_parameter_indexed_read():
    """PROFIdrive base mode: 3 elements of an array parameter from subindex 2 (format 6 = Unsigned16)."""
    resp = _model().process(PM.ParameterModel.request(1, PM.READ, 947, 2, 3))
    assert resp[4:6] == bytes([0x06, 3]) and struct.unpack(">3H", resp[6:12]) == (12, 13, 14)


def test_drives_parameter_error_numbers():
    """PROFIdrive error numbers: 0 not found, 1 read-only, 2 limits, 3 subindex, 4 not an array, 5 data type,
    17 not in this state; the response ID has bit 16#80 set."""
    m = _model()
    cases = [(PM.ParameterModel.request(1, PM.READ, 1234, 0, 0), PM.NOT_FOUND),
             (PM.ParameterModel.request(1, PM.CHANGE, 947, 0, 1, struct.pack(">H", 1), PM.UNSIGNED16), PM.READ_ONLY),
             (PM.ParameterModel.request(1, PM.CHANGE, 2000, 0, 0, struct.pack(">f", 1.0), PM.FLOAT32), PM.LIMITS),
             (PM.ParameterModel.request(1, PM.READ, 947, 7, 2), PM.SUBINDEX),
             (PM.ParameterModel.request(1, PM.READ, 2000, 1, 1), PM.NOT_ARRAY),
             (PM.ParameterModel.request(1, PM.CHANGE, 2000, 0, 0, struct.pack(">H", 7), PM.UNSIGNED16), PM.DATA_TYPE)]
    for request, error in cases:
        resp = m.process(request)
        assert resp[1] & 0x80 and PM.response_values(resp)[0] == error, (request, resp)
    busy = PM.ParameterModel(list(m.parameters.values()), {922: [105.0]}, pulses_on=lambda: True)
    resp = busy.process(PM.ParameterModel.request(1, PM.CHANGE, 922, 0, 0, struct.pack(">H", 3), PM.UNSIGNED16))
    assert PM.response_values(resp)[0] == PM.NOT_IN_STATE


def test_drives_parameter_change_and_record_47():
    """PROFIdrive base mode: a change request written to record 47 is answered once (response ID 2, no
    values) and the value reads back; a second read of the record has no answer."""
    m = _model()
    m.write_record(PM.ParameterModel.request(5, PM.CHANGE, 2000, 0, 0, struct.pack(">f", 1500.0), PM.FLOAT32))
    assert m.read_record() == bytes([5, 0x02, 0, 1]) and m.read_record() is None
    resp = m.process(PM.ParameterModel.request(6, PM.READ, 2000, 0, 0))
    assert struct.unpack(">f", resp[6:10])[0] == 1500.0


def test_drives_parameter_malformed_requests_never_raise():
    """Any bytes give an error response, never an exception."""
    m = _model()
    for raw in (b"", b"\x01", bytes(4), bytes([1, 1, 0, 3, 0x10]), bytes([1, 9, 0, 1, 0x10, 1, 0, 0, 0, 0]),
                bytes([1, 2, 0, 1, 0x10, 1, 0x07, 0xD0, 0, 0])):
        resp = m.process(raw)
        assert isinstance(resp, bytes) and len(resp) >= 4
