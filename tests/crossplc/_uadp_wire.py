"""UADP datagrams built and read with asyncua's own PubSub encoder, an oracle independent of the
subscriber's hand-written reader (OPC UA Part 14 §7.2.2)."""
from __future__ import annotations

import struct

from asyncua import ua
from asyncua.common.utils import Buffer
from asyncua.pubsub.uadp import (UadpDataSetMessageHeader, UadpDataSetVariant, UadpGroupHeader, UadpHeader,
                                 UadpNetworkMessage)

from plcmotion.kernel.leading_value import LeadingValueSample

# (attribute, built-in type), the telegram order of the leading value dataset
LAYOUT = (("time", ua.VariantType.Double), ("position", ua.VariantType.Double),
          ("velocity", ua.VariantType.Double), ("acceleration", ua.VariantType.Double),
          ("valid", ua.VariantType.Boolean), ("tracking", ua.VariantType.Boolean),
          ("modulo_length", ua.VariantType.Double), ("modulo_start", ua.VariantType.Double),
          ("sequence", ua.VariantType.UInt32), ("delay", ua.VariantType.Double))


def payload(s: LeadingValueSample, dsm_seq: int | None = None) -> bytes:
    """The DataSetMessage alone (what AES-CTR encrypts)."""
    seq = s.sequence & 0xFFFF if dsm_seq is None else dsm_seq
    values = [ua.Variant(getattr(s, a) if t != ua.VariantType.UInt32 else getattr(s, a) & 0xFFFFFFFF, t)
              for a, t in LAYOUT]
    return UadpDataSetVariant(UadpDataSetMessageHeader(Valid=True, SequenceNo=ua.UInt16(seq)),
                              values).message_to_binary()


def datagram(s: LeadingValueSample, publisher_id: int = 1, writer_group_id: int = 1, dataset_writer_id: int = 1,
             dsm_seq: int | None = None) -> bytes:
    """An unsecured NetworkMessage as asyncua's publisher sends it."""
    seq = s.sequence & 0xFFFF if dsm_seq is None else dsm_seq
    values = [ua.Variant(getattr(s, a), t) for a, t in LAYOUT]
    msg = UadpNetworkMessage(
        Header=UadpHeader(PublisherId=ua.UInt32(publisher_id)),
        GroupHeader=UadpGroupHeader(WriterGroupId=ua.UInt16(writer_group_id), GroupVersion=ua.UInt32(0),
                                    NetworkMessageNo=ua.UInt16(1), SequenceNo=ua.UInt16(0)),
        DataSetPayloadHeader=[ua.UInt16(dataset_writer_id)],
        Payload=[UadpDataSetVariant(UadpDataSetMessageHeader(Valid=True, SequenceNo=ua.UInt16(seq)), values)])
    return msg.to_binary()


def decode_payload(data: bytes) -> LeadingValueSample:
    """A DataSetMessage (variant key frame) read by asyncua."""
    from asyncua.pubsub.uadp import _unpack_payload
    (dsm,) = _unpack_payload(Buffer(data), 1)
    return LeadingValueSample(**{a: v.Value for (a, _), v in zip(LAYOUT, dsm.Data)})


def decode(data: bytes) -> tuple[UadpNetworkMessage, LeadingValueSample]:
    msg = UadpNetworkMessage.from_binary(Buffer(data))
    (dsm,) = msg.Payload
    return msg, LeadingValueSample(**{a: v.Value for (a, _), v in zip(LAYOUT, dsm.Data)})


def null_array_bomb(length: int) -> bytes:
    """10 bytes that make asyncua's decoder build a list of ``length`` Nones: a NetworkMessage with one
    promoted field, a Variant array of built-in type Null (elements of zero bytes)."""
    return bytes([0x81, 0x80, 0x02]) + struct.pack("<H", 1) + bytes([0x80]) + struct.pack("<i", length)
