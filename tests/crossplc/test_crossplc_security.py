"""UADP message security with a shared key (defect 9; OPC UA Part 14 §7.2.4.4.3, PubSub-Aes128-CTR and
PubSub-Aes256-CTR): signing, optional encryption, explicit opt-out."""
from __future__ import annotations

import hashlib
import hmac
import socket
import struct

import pytest

from plcmotion.kernel.leading_value import LeadingValueSample

uadp = pytest.importorskip("plcmotion.crossplc.uadp")
pytest.importorskip("cryptography")
wire = pytest.importorskip("_uadp_wire")
from cryptography.hazmat.primitives.ciphers import Cipher, algorithms, modes  # noqa: E402

from plcmotion.crossplc import generate_key  # noqa: E402
from plcmotion.crossplc.uadp_codec import Codec  # noqa: E402
from plcmotion.crossplc.uadp_security import Security  # noqa: E402


def sample(i: int, **changes: object) -> LeadingValueSample:
    fields: dict[str, object] = {"time": i * 1e-3, "position": i * 0.25 - 7.0, "velocity": 12.5,
                                 "acceleration": 0.0, "sequence": i, "modulo_length": 360.0}
    fields.update(changes)
    return LeadingValueSample(**fields)


@pytest.fixture
def url() -> str:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    return f"opc.udp://127.0.0.1:{port}"


def _capture(url: str, pub_kwargs: dict, samples: list) -> list[bytes]:
    """The datagrams a publisher sends, caught by a plain socket in the subscriber's place."""
    port = int(url.rsplit(":", 1)[1])
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as rx:
        rx.bind(("127.0.0.1", port))
        rx.settimeout(2.0)
        with uadp.UadpLeadingValuePublisher(url, **pub_kwargs) as pub:
            for s in samples:
                pub.send(s)
            return [rx.recv(2048) for _ in samples]


def _subscriber(**kwargs):
    return uadp.UadpLeadingValueSubscriber("opc.udp://127.0.0.1:4840", **kwargs)   # never started


@pytest.mark.parametrize("policy,size", [("PubSub-Aes128-CTR", 52), ("PubSub-Aes256-CTR", 68)])
def test_crossplc_key_data_is_signing_key_encrypting_key_and_key_nonce(policy, size) -> None:
    key = generate_key(policy)
    assert len(key) == size and key != generate_key(policy)
    assert Security("sign", key).policy == policy
    with pytest.raises(ValueError, match="52 or 68 bytes"):
        Security("sign", key[:-1])
    with pytest.raises(ValueError, match="security"):
        uadp.UadpLeadingValueSubscriber(security="none", key=key)
    with pytest.raises(ValueError, match="needs key"):
        uadp.UadpLeadingValueSubscriber(security="sign")
    with pytest.raises(ValueError, match="security must be one of"):
        uadp.UadpLeadingValueSubscriber(security="tls", key=key)


@pytest.mark.parametrize("policy", ["PubSub-Aes128-CTR", "PubSub-Aes256-CTR"])
@pytest.mark.parametrize("mode", ["sign", "sign_encrypt"])
def test_crossplc_secured_link_round_trip_on_loopback(url, policy, mode) -> None:
    key = generate_key(policy)
    sent = [sample(i) for i in range(1, 51)]
    with uadp.UadpLeadingValueSubscriber(url, security=mode, key=key, security_token_id=7, wait_timeout=2.0) as sub, \
            uadp.UadpLeadingValuePublisher(url, security=mode, key=key, security_token_id=7) as pub:
        for s in sent:
            pub.send(s)
        got = []
        while len(got) < len(sent):
            batch = sub.fetch(sent[-1].time)
            if not batch:
                break
            got += batch
    assert got == sent and sub.rejected == {}


@pytest.mark.parametrize("policy,enc", [("PubSub-Aes128-CTR", 16), ("PubSub-Aes256-CTR", 32)])
def test_crossplc_secured_datagram_follows_part14_layout(url, policy, enc) -> None:
    """Checked by hand against Part 14: ExtendedFlags1 bit 4, SecurityHeader (flags 0x03, token id,
    nonce length 8, nonce = 4 random bytes + UInt32 message number), payload AES-CTR with counter block
    KeyNonce|MessageNonce|00000001, HMAC-SHA256 of everything before the 32-byte signature."""
    key = generate_key(policy)
    s = sample(9, position=123.456)
    (data,) = _capture(url, {"publisher_id": 3, "security": "sign_encrypt", "key": key,
                             "security_token_id": 0x01020304}, [s])
    assert data[1] & 0x10
    head_len = 2 + 4 + 11 + 3                       # flags, UInt32 PublisherId, group header, payload header
    flags, token, nonce_len = struct.unpack_from("<BIB", data, head_len)
    assert (flags, token, nonce_len) == (0x03, 0x01020304, 8)
    nonce = data[head_len + 6:head_len + 14]
    assert struct.unpack("<I", nonce[4:])[0] == 1   # the first message of this key
    body, signature = data[head_len + 14:-32], data[-32:]
    assert signature == hmac.new(key[:32], data[:-32], hashlib.sha256).digest()
    block = key[32 + enc:] + nonce + b"\x00\x00\x00\x01"
    plain = Cipher(algorithms.AES(key[32:32 + enc]), modes.CTR(block)).decryptor().update(body)
    assert wire.decode_payload(plain) == s
    assert struct.pack("<d", 123.456) not in data   # the value does not travel in clear


def test_crossplc_signed_only_datagram_is_readable_but_signed(url) -> None:
    key = generate_key("PubSub-Aes128-CTR")
    s = sample(4)
    (data,) = _capture(url, {"security": "sign", "key": key}, [s])
    assert data[20] == 0x01
    assert wire.decode_payload(data[20 + 14:-32]) == s
    assert data[-32:] == hmac.new(key[:32], data[:-32], hashlib.sha256).digest()


def test_crossplc_every_single_bit_flip_of_a_signed_datagram_is_rejected() -> None:
    key = generate_key()
    data = Codec(1, 1, 1, Security("sign_encrypt", key)).encode(sample(1))
    sub = _subscriber(key=key)
    for bit in range(len(data) * 8):
        forged = bytearray(data)
        forged[bit // 8] ^= 1 << (bit % 8)
        sub.receive(bytes(forged), "127.0.0.1")
    assert sub.accepted == 0 and sum(sub.rejected.values()) == len(data) * 8
    assert sub.rejected["signature"] > len(data) * 4
    sub.receive(data, "127.0.0.1")
    assert sub.accepted == 1


def test_crossplc_wrong_key_token_or_mode_is_rejected_and_replay_dropped() -> None:
    key = generate_key()
    codec = Codec(1, 1, 1, Security("sign_encrypt", key))
    first, second = codec.encode(sample(1)), codec.encode(sample(2))
    cases = {
        "signature": _subscriber(key=generate_key()),
        "security": _subscriber(key=key, security_token_id=2),
    }
    for reason, sub in cases.items():
        sub.receive(first)
        assert sub.rejected == {reason: 1} and sub.accepted == 0
    for sub in (_subscriber(key=key, security="sign"), _subscriber()):   # mode mismatch, unsecured reader
        sub.receive(first)
        assert sub.rejected == {"security": 1}
    secured = _subscriber(key=key)
    secured.receive(wire.datagram(sample(1)))           # an unsigned telegram
    assert secured.rejected == {"security": 1}
    for data in (first, second, first, second):          # replayed datagrams are duplicates
        secured.receive(data)
    assert secured.accepted == 2 and secured.dropped == 2
    assert [s.sequence for s in secured.fetch(0.0)] == [1, 2]


def test_crossplc_security_page_quick_start_runs() -> None:
    """docs/crossplc_security.md: the quick start builds a secured publisher and subscriber."""
    from pathlib import Path
    page = (Path(__file__).resolve().parents[2] / "docs" / "crossplc_security.md").read_text()
    code = page.split("```python\n", 1)[1].split("```", 1)[0]
    scope: dict = {}
    exec(compile(code, "crossplc_security.md", "exec"), scope)
    assert scope["pub"].security.mode == scope["sub"].security.mode == "sign_encrypt"
    assert scope["sub"].security.policy == "PubSub-Aes256-CTR"
    scope["pub"].close()
    scope["sub"].close()
