"""DWORD status words whose bits are read as ``word.X5`` (as in SCL) or by their manual name."""
from __future__ import annotations

from typing import Mapping


class DWord(int):
    """An unsigned 32-bit status word; ``w.X3`` and ``w.<BitName>`` give single bits as bool."""

    _names: Mapping[str, int] = {}
    _aliases: Mapping[str, int] = {}        # further spellings of a bit (not listed by ``bits()``)

    def __new__(cls, value: int = 0):
        return super().__new__(cls, int(value) & 0xFFFFFFFF)

    def __getattr__(self, name: str) -> bool:
        if name.startswith("X") and name[1:].isdigit():
            bit = int(name[1:])
            if bit < 32:
                return bool(int(self) >> bit & 1)
        named = type(self)._names.get(name, type(self)._aliases.get(name))
        if named is not None:
            return bool(int(self) >> named & 1)
        raise AttributeError(f"{type(self).__name__} has no bit {name!r}")

    def __repr__(self) -> str:
        return f"16#{int(self):08X}"

    def bits(self) -> dict[str, bool]:
        """Named bits and their values."""
        return {name: bool(int(self) >> bit & 1) for name, bit in type(self)._names.items()}


def word_type(name: str, bits: Mapping[str, int], aliases: Mapping[str, int] | None = None) -> type[DWord]:
    """A DWord subclass with named bits (``{"Enable": 0, "Error": 1, ...}``); ``aliases`` are other
    names of the same bits where a manual spells a bit in more than one way."""
    return type(name, (DWord,), {"_names": dict(bits), "_aliases": dict(aliases or {}), "__slots__": ()})


def pack(bits: Mapping[int, bool]) -> int:
    value = 0
    for bit, on in bits.items():
        if on:
            value |= 1 << bit
    return value
