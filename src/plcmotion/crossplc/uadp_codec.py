"""The leading value NetworkMessage in UADP encoding (OPC UA Part 14 §7.2.2), written and read with
``struct`` only.

Why not asyncua's decoder: it decodes whatever a datagram claims (arrays, strings, nested variants,
discovery structures) before anyone can look at it, so one random datagram can cost minutes of CPU and
gigabytes of memory (issue 8, defect 9).  This reader knows the one message it expects and checks it
field by field; its work per datagram is a fixed handful of ``unpack_from`` calls, whatever the bytes:

* the datagram is at most ``MAX_DATAGRAM`` bytes; every length in it is bounded before it is used
  (payload header count <= ``MAX_WRITERS``, nonce length 8, no strings but the configured PublisherId,
  which is compared, never decoded);
* PublisherId, WriterGroupId and DataSetWriterId must be the configured ones;
* with security the signature is checked before anything of the payload is read, then it is decrypted;
* the DataSetMessage must be a valid key frame with a sequence number, in variant encoding, with exactly
  the ten fields of ``FIELDS`` as scalars of their built-in types, and nothing after them.

Optional fields a publisher may add (DataSetClassId, GroupVersion, NetworkMessageNumber, timestamps,
status, configuration versions) have fixed sizes and are skipped.  Anything else (promoted fields,
chunks, discovery messages, other encodings, a SecurityFooter) is rejected.  The writer produces the
same bytes as asyncua's publisher for an unsecured message, so either side interoperates with asyncua.
"""
from __future__ import annotations

import math
import struct
from dataclasses import dataclass

from plcmotion.kernel.leading_value import LeadingValueSample

from .uadp_security import FLAG_ENCRYPTED, FLAG_FOOTER, FLAG_SIGNED, NONCE_SIZE, SIGNATURE_SIZE, Security

__all__ = ["FIELDS", "MAX_DATAGRAM", "Codec", "Rejected", "validate"]

MAX_DATAGRAM = 512          # bytes; our message is 97 bytes (143 secured) plus the PublisherId string
MAX_WRITERS = 16            # DataSetMessages a NetworkMessage may hold (payload header count)
MAX_PUBLISHER_ID = 64       # bytes of a String PublisherId
VALUE_LIMIT = 1.0e12        # the REAL range of positions, velocities, accelerations and times

#: (field name, built-in type id, struct code, LeadingValueSample attribute), in telegram order
FIELDS: tuple[tuple[str, int, str, str], ...] = (
    ("Time", 11, "d", "time"),
    ("Position", 11, "d", "position"),
    ("Velocity", 11, "d", "velocity"),
    ("Acceleration", 11, "d", "acceleration"),
    ("Valid", 1, "B", "valid"),
    ("Tracking", 1, "B", "tracking"),
    ("ModuloLength", 11, "d", "modulo_length"),
    ("ModuloStart", 11, "d", "modulo_start"),
    ("Sequence", 7, "I", "sequence"),
    ("DelayTime", 11, "d", "delay"),
)
_TYPES = tuple(t for _, t, _, _ in FIELDS)
_BOOLEANS = tuple(i for i, (_, t, _, _) in enumerate(FIELDS) if t == 1)
_BODY = struct.Struct("<H" + "".join("B" + code for _, _, code, _ in FIELDS))   # FieldCount, (type, value)*
_SEQ_FIELD = [a for _, _, _, a in FIELDS].index("sequence")

# UADPFlags / ExtendedFlags1 / ExtendedFlags2 (Part 14 §7.2.2.2.2)
_VERSION = 0x01
_F_PUBLISHER, _F_GROUP, _F_PAYLOAD, _F_EXT1 = 0x10, 0x20, 0x40, 0x80
_X_CLASS, _X_SECURITY, _X_TIMESTAMP, _X_PICO, _X_EXT2 = 0x08, 0x10, 0x20, 0x40, 0x80
_G_WRITER_GROUP, _G_VERSION, _G_NUMBER, _G_SEQUENCE = 0x01, 0x02, 0x04, 0x08
# DataSetFlags1 / DataSetFlags2 (Part 14 §7.2.2.3.4)
_D_VALID, _D_ENCODING, _D_SEQUENCE, _D_STATUS, _D_MAJOR, _D_MINOR, _D_FLAGS2 = 1, 6, 8, 16, 32, 64, 128
_D2_TYPE, _D2_TIMESTAMP, _D2_PICO = 0x0F, 0x10, 0x20

_U8, _U16, _U32 = struct.Struct("<B"), struct.Struct("<H"), struct.Struct("<I")
_PUBLISHER_TYPES = {0: 1, 1: 2, 2: 4, 3: 8}     # PublisherId type -> size; 4 is String


class Rejected(ValueError):
    """A datagram that is not a leading value telegram of the configured writer; ``reason`` says why."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def publisher_id_bytes(publisher_id: int | str) -> tuple[int, bytes]:
    """(PublisherId type, encoded value): an int as UInt32 (as asyncua sends it), a str as String."""
    if isinstance(publisher_id, str):
        raw = publisher_id.encode("utf-8")
        if not 0 < len(raw) <= MAX_PUBLISHER_ID:
            raise ValueError(f"publisher_id string must be 1..{MAX_PUBLISHER_ID} bytes, got {len(raw)}")
        return 4, _U32.pack(len(raw)) + raw
    if isinstance(publisher_id, bool) or not isinstance(publisher_id, int) or not 0 <= publisher_id <= 0xFFFFFFFF:
        raise ValueError(f"publisher_id must be an integer 0..4294967295 or a string, got {publisher_id!r}")
    return 2, _U32.pack(publisher_id)


def uint16_id(value: object, what: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 0 < value <= 0xFFFF:
        raise ValueError(f"{what} must be an integer 1..65535, got {value!r}")
    return value


@dataclass(frozen=True)
class Decoded:
    sequence: int                   # DataSetMessage SequenceNumber (UInt16)
    values: tuple                   # the ten field values, in FIELDS order


class Codec:
    """Writes and reads the NetworkMessages of one DataSetWriter (publisher id, group, writer, security)."""

    def __init__(self, publisher_id: int | str, writer_group_id: int, dataset_writer_id: int,
                 security: Security | None = None) -> None:
        self.publisher_type, self.publisher = publisher_id_bytes(publisher_id)
        self.writer_group_id = uint16_id(writer_group_id, "writer_group_id")
        self.dataset_writer_id = uint16_id(dataset_writer_id, "dataset_writer_id")
        self.security = security
        ext1 = self.publisher_type | (_X_SECURITY if security else 0)
        self._prefix = bytes((_VERSION | _F_PUBLISHER | _F_GROUP | _F_PAYLOAD | _F_EXT1, ext1)) + self.publisher
        self._messages = 0          # NetworkMessages written (group SequenceNumber, nonce sequence)

    # --- writing --------------------------------------------------------------------------------------
    def encode(self, sample: LeadingValueSample) -> bytes:
        """One NetworkMessage holding ``sample``; its SequenceNumber is the low 16 bits of
        ``sample.sequence``, so the subscriber's window works on the sender's own count."""
        self._messages += 1
        values = []
        for _, vtype, _, attr in FIELDS:
            value = getattr(sample, attr)
            if vtype == 1:
                value = 1 if value else 0
            elif vtype == 7:
                value = int(value) & 0xFFFFFFFF
            else:
                value = float(value)
            values += (vtype, value)
        seq = sample.sequence & 0xFFFF
        payload = bytes((_D_VALID | _D_SEQUENCE,)) + _U16.pack(seq) + _BODY.pack(len(FIELDS), *values)
        head = (self._prefix
                + struct.pack("<BHIHH", _G_WRITER_GROUP | _G_VERSION | _G_NUMBER | _G_SEQUENCE,
                              self.writer_group_id, 0, 1, self._messages & 0xFFFF)
                + struct.pack("<BH", 1, self.dataset_writer_id))
        sec = self.security
        if sec is None:
            return head + payload
        nonce = sec.nonce(self._messages)
        if sec.encrypt:
            payload = sec.crypt(nonce, payload)
        message = head + sec.header(nonce) + payload
        return message + sec.sign(message)

    # --- reading --------------------------------------------------------------------------------------
    def decode(self, data: bytes) -> Decoded:
        """The telegram in ``data``, or ``Rejected``; never anything else, and no work beyond a fixed
        number of field reads and (with security) one HMAC and one AES-CTR pass over <= 512 bytes."""
        if len(data) > MAX_DATAGRAM:
            raise Rejected("size")
        try:
            return self._decode(data)
        except (struct.error, IndexError):
            raise Rejected("truncated") from None

    def _decode(self, data: bytes) -> Decoded:
        flags = data[0]
        if flags & 0x0F != _VERSION:
            raise Rejected("malformed")
        ext1 = data[1] if flags & _F_EXT1 else 0
        pos = 2 if flags & _F_EXT1 else 1
        ext2 = 0
        if ext1 & _X_EXT2:
            ext2 = data[pos]
            pos += 1
        if ext2:                                    # chunk, promoted fields, discovery: not ours
            raise Rejected("unsupported")
        if not flags & _F_PUBLISHER or ext1 & 0x07 != self.publisher_type \
                or data[pos:pos + len(self.publisher)] != self.publisher:
            raise Rejected("publisher")
        pos += len(self.publisher)
        if ext1 & _X_CLASS:
            pos += 16
        if not flags & _F_GROUP:
            raise Rejected("group")
        gflags = data[pos]
        if gflags & 0xF0 or not gflags & _G_WRITER_GROUP \
                or _U16.unpack_from(data, pos + 1)[0] != self.writer_group_id:
            raise Rejected("group")
        pos += 3 + (4 if gflags & _G_VERSION else 0) + (2 if gflags & _G_NUMBER else 0) \
            + (2 if gflags & _G_SEQUENCE else 0)
        if not flags & _F_PAYLOAD:
            raise Rejected("writer")
        count = data[pos]
        if not 0 < count <= MAX_WRITERS:
            raise Rejected("malformed")
        writers = struct.unpack_from(f"<{count}H", data, pos + 1)
        if self.dataset_writer_id not in writers:
            raise Rejected("writer")
        index = writers.index(self.dataset_writer_id)
        pos += 1 + 2 * count + (8 if ext1 & _X_TIMESTAMP else 0) + (2 if ext1 & _X_PICO else 0)
        end = len(data)
        sec = self.security
        if bool(ext1 & _X_SECURITY) != (sec is not None):
            raise Rejected("security")
        if sec is not None:
            sflags, token, nonce_len = struct.unpack_from("<BIB", data, pos)
            wanted = FLAG_SIGNED | (FLAG_ENCRYPTED if sec.encrypt else 0)
            if sflags & (FLAG_SIGNED | FLAG_ENCRYPTED | FLAG_FOOTER | 0xF0) != wanted \
                    or token != sec.token_id or nonce_len != NONCE_SIZE:
                raise Rejected("security")
            nonce = data[pos + 6:pos + 6 + NONCE_SIZE]
            pos += 6 + NONCE_SIZE
            end -= SIGNATURE_SIZE
            if end < pos:
                raise Rejected("truncated")
            if not sec.verify(data[:end], data[end:]):
                raise Rejected("signature")
            payload = data[pos:end]
            if sec.encrypt:
                payload = sec.crypt(nonce, payload)
            data, pos, end = payload, 0, len(payload)
        if count > 1:                               # Sizes[count] precede the DataSetMessages
            sizes = struct.unpack_from(f"<{count}H", data, pos)
            pos += 2 * count + sum(sizes[:index])
            end = pos + sizes[index]
            if end > len(data):
                raise Rejected("truncated")
        return self._dataset_message(data, pos, end)

    @staticmethod
    def _dataset_message(data: bytes, pos: int, end: int) -> Decoded:
        f1 = data[pos]
        f2 = data[pos + 1] if f1 & _D_FLAGS2 else 0
        if not f1 & _D_VALID or f1 & _D_ENCODING or not f1 & _D_SEQUENCE or f2 & _D2_TYPE:
            raise Rejected("dataset")              # not a valid variant key frame with a sequence
        pos += 2 if f1 & _D_FLAGS2 else 1
        seq = _U16.unpack_from(data, pos)[0]
        pos += 2 + (8 if f2 & _D2_TIMESTAMP else 0) + (2 if f2 & _D2_PICO else 0) \
            + (2 if f1 & _D_STATUS else 0) + (4 if f1 & _D_MAJOR else 0) + (4 if f1 & _D_MINOR else 0)
        if end - pos != _BODY.size:
            raise Rejected("dataset")
        body = _BODY.unpack_from(data, pos)
        values = body[2::2]
        if body[0] != len(FIELDS) or body[1::2] != _TYPES or any(values[i] > 1 for i in _BOOLEANS) \
                or values[_SEQ_FIELD] & 0xFFFF != seq:
            raise Rejected("dataset")
        return Decoded(seq, values)


def validate(values: tuple, last: LeadingValueSample | None) -> LeadingValueSample | None:
    """The sample the decoded values describe; None if its time is unusable.

    A value that is not finite or outside the REAL range (1e12) makes the sample invalid (``valid``
    FALSE, as if the sender had flagged it) and is replaced by the previous sample's value (0.0 before
    the first), so no NaN or absurd number reaches the leading axis proxy."""
    kw = {attr: value for (_, _, _, attr), value in zip(FIELDS, values)}
    t = kw["time"]
    if not (math.isfinite(t) and abs(t) <= VALUE_LIMIT):
        return None
    kw["valid"], kw["tracking"] = bool(kw["valid"]), bool(kw["tracking"])
    ok = True
    for attr, low in (("position", -VALUE_LIMIT), ("velocity", -VALUE_LIMIT), ("acceleration", -VALUE_LIMIT),
                      ("modulo_start", -VALUE_LIMIT), ("modulo_length", 0.0), ("delay", 0.0)):
        v = kw[attr]
        if not (math.isfinite(v) and low <= v <= VALUE_LIMIT):
            kw[attr] = getattr(last, attr) if last is not None else 0.0
            ok = False
    if not ok:
        kw["valid"] = False
    return LeadingValueSample(**kw)
