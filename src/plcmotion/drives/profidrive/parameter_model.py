"""Acyclic parameter access of a simulated PROFIdrive drive: a few drive parameters and the base-mode
parameter request/response of data record 47 (PROFIdrive profile, DP-V1 parameter channel).

Request (written to record 47): request reference, request ID (1 read value, 2 change value), axis,
number of parameters, then per parameter attribute (16#10 value), number of elements, parameter number and
subindex (16 bit each, big-endian); a change request follows with format, number of values and the values.
Response (read from record 47): the reference mirrored, the response ID (request ID, + 16#80 on error), axis,
number of parameters and per parameter format, number of values and the values; an error is format 16#44
with one 16-bit PROFIdrive error number (0 parameter unknown, 1 read-only, 2 limits, 3 subindex, 4 not an
array, 5 data type, 17 not in this state, 21 response too long, 22 invalid address, 23 format, 24 number of
values).  Values are big-endian; the numbers the parameters carry are the SINAMICS ones.
"""
from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from typing import Callable

RECORD = 47                     # the data record of PROFIdrive parameter access
READ, CHANGE = 0x01, 0x02       # request IDs
ERROR_FORMAT = 0x44
VALUE_ATTRIBUTE = 0x10
MAX_PAYLOAD = 234               # bytes of parameter values in one response

# PROFIdrive error numbers of a parameter response
NOT_FOUND, READ_ONLY, LIMITS, SUBINDEX, NOT_ARRAY, DATA_TYPE = 0x00, 0x01, 0x02, 0x03, 0x04, 0x05
NOT_IN_STATE, TOO_LONG, INVALID_ADDRESS, INVALID_FORMAT, VALUE_COUNT = 0x11, 0x15, 0x16, 0x17, 0x18

#: data type code -> (struct format, size); the code is also the response's format byte
UNSIGNED16, UNSIGNED32, FLOAT32 = 0x06, 0x07, 0x08
_TYPES = {UNSIGNED16: (">H", 2), UNSIGNED32: (">I", 4), FLOAT32: (">f", 4)}


@dataclass
class DriveParameter:
    """One parameter: number, data type, elements (0: not indexed), writable, limits, and for a display
    parameter (r...) the function that reads it from the drive."""
    number: int
    data_type: int
    elements: int = 0
    writable: bool = True
    minimum: float = 0.0
    maximum: float = math.inf
    only_when_off: bool = False            # a commissioning parameter: writable while the pulses are off
    read_fn: Callable[[int], float] | None = None

    @property
    def size(self) -> int:
        return _TYPES[self.data_type][1]


class ParameterModel:
    """The parameters of one drive and its record 47; ``pulses_on()`` tells whether the drive is in
    operation (commissioning parameters refuse a change then)."""

    def __init__(self, parameters: list[DriveParameter], values: dict[int, list[float]],
                 pulses_on: Callable[[], bool] = lambda: False):
        self.parameters = {p.number: p for p in parameters}
        self.values = {n: list(v) for n, v in values.items()}
        self.pulses_on = pulses_on
        self._response: bytes | None = None

    # --- record 47 --------------------------------------------------------------------------------------
    def write_record(self, request: bytes) -> None:
        """A request written to record 47; its response waits for the next read of the record."""
        self._response = self.process(bytes(request))

    def read_record(self) -> bytes | None:
        """The response to the last request (once), None when there is none."""
        out, self._response = self._response, None
        return out

    def process(self, req: bytes) -> bytes:
        """The response to one base-mode request."""
        if len(req) < 4:
            return bytes([req[0] if req else 0, 0x81, 0, 1, ERROR_FORMAT, 1]) + struct.pack(">H", INVALID_FORMAT)
        ref, rid, axis, count = req[0], req[1], req[2], req[3]
        head = bytes([ref, rid, axis, count])
        addresses, pos = [], 4
        for _ in range(count):
            if pos + 6 > len(req):
                return self._failed(head, INVALID_FORMAT, count)
            attr, elements, number, sub = req[pos], req[pos + 1], *struct.unpack(">HH", req[pos + 2:pos + 6])
            addresses.append((attr, elements, number, sub))
            pos += 6
        if rid == READ:
            return self._read(head, addresses)
        if rid == CHANGE:
            return self._change(head, addresses, req[pos:])
        return self._failed(head, INVALID_FORMAT, count)

    def _failed(self, head: bytes, error: int, count: int) -> bytes:
        body = b"".join(bytes([ERROR_FORMAT, 1]) + struct.pack(">H", error) for _ in range(max(count, 1)))
        return bytes([head[0], head[1] | 0x80, head[2], head[3]]) + body

    def _address(self, attr: int, elements: int, number: int, sub: int) -> tuple[DriveParameter | None, int]:
        p = self.parameters.get(number)
        if attr != VALUE_ATTRIBUTE:
            return None, INVALID_ADDRESS
        if p is None:
            return None, NOT_FOUND
        if p.elements == 0 and (sub != 0 or elements > 1):
            return None, NOT_ARRAY
        last = sub + max(elements, 1)
        if p.elements and last > p.elements:
            return None, SUBINDEX
        return p, -1

    def _get(self, p: DriveParameter, i: int) -> float:
        return p.read_fn(i) if p.read_fn is not None else self.values[p.number][i]

    def _read(self, head: bytes, addresses: list[tuple[int, int, int, int]]) -> bytes:
        body, error = b"", False
        for attr, elements, number, sub in addresses:
            p, err = self._address(attr, elements, number, sub)
            n = max(elements, 1)
            if p is not None and p.size * n > MAX_PAYLOAD:
                p, err = None, TOO_LONG
            if p is None:
                body += bytes([ERROR_FORMAT, 1]) + struct.pack(">H", err)
                error = True
                continue
            fmt = _TYPES[p.data_type][0]
            values = [self._encode(p, fmt, self._get(p, sub + k)) for k in range(n)]
            body += bytes([p.data_type, n]) + b"".join(values)
        rid = head[1] | (0x80 if error else 0)
        return bytes([head[0], rid, head[2], head[3]]) + body

    @staticmethod
    def _encode(p: DriveParameter, fmt: str, value: float) -> bytes:
        if p.data_type == FLOAT32:
            return struct.pack(fmt, float(value))
        limit = (1 << (8 * p.size)) - 1
        return struct.pack(fmt, min(max(int(value), 0), limit))

    def _change(self, head: bytes, addresses: list[tuple[int, int, int, int]], data: bytes) -> bytes:
        if len(addresses) != 1:
            return self._failed(head, VALUE_COUNT, len(addresses))
        attr, elements, number, sub = addresses[0]
        p, err = self._address(attr, elements, number, sub)
        if p is None:
            return self._failed(head, err, 1)
        if not p.writable:
            return self._failed(head, READ_ONLY, 1)
        if len(data) < 2:
            return self._failed(head, INVALID_FORMAT, 1)
        fmt_code, n = data[0], data[1]
        if fmt_code != p.data_type:
            return self._failed(head, DATA_TYPE, 1)
        if n != max(elements, 1) or len(data) - 2 != n * p.size:
            return self._failed(head, VALUE_COUNT, 1)
        fmt = _TYPES[p.data_type][0]
        values = [struct.unpack(fmt, data[2 + k * p.size:2 + (k + 1) * p.size])[0] for k in range(n)]
        if any(not math.isfinite(v) or v < p.minimum or v > p.maximum for v in values):
            return self._failed(head, LIMITS, 1)
        if p.only_when_off and self.pulses_on():
            return self._failed(head, NOT_IN_STATE, 1)
        stored = self.values.setdefault(p.number, [0.0] * max(p.elements, 1))
        for k, v in enumerate(values):
            stored[sub + k] = v
        return head

    # --- helpers for a master that builds requests --------------------------------------------------------
    @staticmethod
    def request(ref: int, rid: int, number: int, sub: int, elements: int, values: bytes = b"",
                data_type: int = 0) -> bytes:
        """A base-mode request for one parameter (``values``: the raw values of a change)."""
        req = bytes([ref & 0xFF, rid, 0, 1, VALUE_ATTRIBUTE, elements & 0xFF]) + struct.pack(">HH", number, sub)
        if rid == CHANGE:
            count = max(elements, 1)
            req += bytes([data_type, count]) + values
        return req

    def type_of(self, number: int) -> int | None:
        p = self.parameters.get(number)
        return None if p is None else p.data_type


def response_values(resp: bytes) -> tuple[int | None, bytes]:
    """(PROFIdrive error number or None, the raw values) of a one-parameter response."""
    if len(resp) < 4:
        return INVALID_FORMAT, b""
    if resp[1] & 0x80:
        err = struct.unpack(">H", resp[6:8])[0] if len(resp) >= 8 else INVALID_FORMAT
        return err, b""
    if resp[1] == CHANGE:
        return None, b""
    fmt, n = resp[4], resp[5]
    size = _TYPES.get(fmt, (None, 0))[1]
    return None, resp[6:6 + n * size]


__all__ = ["RECORD", "READ", "CHANGE", "DriveParameter", "ParameterModel", "response_values", "UNSIGNED16",
           "UNSIGNED32", "FLOAT32", "NOT_FOUND", "READ_ONLY", "LIMITS", "SUBINDEX", "NOT_ARRAY", "DATA_TYPE",
           "NOT_IN_STATE", "TOO_LONG", "INVALID_ADDRESS", "INVALID_FORMAT", "VALUE_COUNT", "MAX_PAYLOAD"]
