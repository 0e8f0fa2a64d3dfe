"""UADP message security with a shared key (OPC UA Part 14 §7.2.4.4.3, policies PubSub-Aes128-CTR and
PubSub-Aes256-CTR): HMAC-SHA256 signature over the whole NetworkMessage, optionally AES-CTR encryption
of the payload.

The key is the key data a Security Key Service would hand out (Part 14, "layout of the key data"):
``SigningKey (32 bytes) | EncryptingKey (16 or 32 bytes) | KeyNonce (4 bytes)``, so 52 bytes select
PubSub-Aes128-CTR and 68 bytes PubSub-Aes256-CTR.  There is no key service here: the same key data is
given to publisher and subscriber (``generate_key`` makes one).  ``cryptography`` is imported only when a
key is actually used, so an unsecured link does not need it.
"""
from __future__ import annotations

import hashlib
import hmac
import os
import struct
from dataclasses import dataclass, field
from typing import Any

__all__ = ["MODES", "POLICIES", "SIGNATURE_SIZE", "NONCE_SIZE", "Security", "generate_key"]

SIGNATURE_SIZE = 32         # HMAC-SHA256
NONCE_SIZE = 8              # MessageNonce for AES-CTR: Random[4] | SequenceNumber (UInt32)
_SIGNING_KEY = 32
_KEY_NONCE = 4
#: policy name -> EncryptingKey length
POLICIES = {"PubSub-Aes128-CTR": 16, "PubSub-Aes256-CTR": 32}
#: the security modes of a link (MessageSecurityMode None / Sign / SignAndEncrypt)
MODES = ("none", "sign", "sign_encrypt")

# SecurityFlags of the SecurityHeader
FLAG_SIGNED = 0x01
FLAG_ENCRYPTED = 0x02
FLAG_FOOTER = 0x04
FLAG_FORCE_KEY_RESET = 0x08


def generate_key(policy: str = "PubSub-Aes256-CTR") -> bytes:
    """Fresh random key data for ``policy`` (give the same bytes to publisher and subscriber)."""
    if policy not in POLICIES:
        raise ValueError(f"policy must be one of {sorted(POLICIES)}, got {policy!r}")
    return os.urandom(_SIGNING_KEY + POLICIES[policy] + _KEY_NONCE)


def _policy_of(key: bytes) -> str:
    for name, enc in POLICIES.items():
        if len(key) == _SIGNING_KEY + enc + _KEY_NONCE:
            return name
    sizes = " or ".join(str(_SIGNING_KEY + e + _KEY_NONCE) for e in POLICIES.values())
    raise ValueError(f"key must be {sizes} bytes of key data (SigningKey|EncryptingKey|KeyNonce, "
                     f"see plcmotion.crossplc.generate_key), got {len(key)} bytes")


@dataclass
class Security:
    """The message security of one link end: mode, key data and SecurityTokenId."""

    mode: str
    key: bytes = field(repr=False)
    token_id: int = 1
    policy: str = field(init=False)
    _cipher: Any = field(init=False, repr=False, default=None)

    def __post_init__(self) -> None:
        if self.mode not in MODES[1:]:
            raise ValueError(f"security must be one of {MODES}, got {self.mode!r}")
        if not isinstance(self.key, (bytes, bytearray)):
            raise TypeError(f"key must be bytes, got {type(self.key).__name__}")
        self.key = bytes(self.key)
        self.policy = _policy_of(self.key)
        if isinstance(self.token_id, bool) or not isinstance(self.token_id, int) \
                or not 0 < self.token_id <= 0xFFFFFFFF:
            raise ValueError(f"security_token_id must be an integer 1..4294967295, got {self.token_id!r}")
        enc = POLICIES[self.policy]
        self._signing_key = self.key[:_SIGNING_KEY]
        self._encrypting_key = self.key[_SIGNING_KEY:_SIGNING_KEY + enc]
        self._key_nonce = self.key[_SIGNING_KEY + enc:]
        if self.encrypt:
            from cryptography.hazmat.primitives.ciphers import Cipher, algorithms  # noqa: F401  (fail early)
            self._cipher = (Cipher, algorithms)

    @property
    def encrypt(self) -> bool:
        return self.mode == "sign_encrypt"

    @property
    def flags(self) -> int:
        return FLAG_SIGNED | (FLAG_ENCRYPTED if self.encrypt else 0)

    def header(self, nonce: bytes) -> bytes:
        """SecurityHeader: SecurityFlags, SecurityTokenId, NonceLength, MessageNonce (no footer)."""
        return struct.pack("<BIB", self.flags, self.token_id, NONCE_SIZE) + nonce

    @staticmethod
    def nonce(sequence: int) -> bytes:
        """MessageNonce: four random bytes and the message sequence number (counts from 1 per key)."""
        return os.urandom(4) + struct.pack("<I", sequence & 0xFFFFFFFF)

    def sign(self, message: bytes) -> bytes:
        return hmac.new(self._signing_key, message, hashlib.sha256).digest()

    def verify(self, message: bytes, signature: bytes) -> bool:
        return hmac.compare_digest(self.sign(message), signature)

    def crypt(self, nonce: bytes, data: bytes) -> bytes:
        """AES-CTR (its own inverse).  Counter block: KeyNonce[4] | MessageNonce[8] | BlockCounter, a
        32-bit big-endian counter from 1; no message is long enough for that counter to carry over."""
        Cipher, algorithms = self._cipher
        from cryptography.hazmat.primitives.ciphers import modes
        block = self._key_nonce + nonce + b"\x00\x00\x00\x01"
        enc = Cipher(algorithms.AES(self._encrypting_key), modes.CTR(block)).encryptor()
        return enc.update(data) + enc.finalize()
