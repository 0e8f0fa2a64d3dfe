"""Errors the kernel raises to the user that several of its modules share (a leaf: it imports nothing)."""
from __future__ import annotations

from typing import Any, Protocol, Sequence


class ConfigIssue(Protocol):
    """One configuration problem (``kernel.schema.Issue`` or a family's own)."""

    path: str                       # the tag
    reason: str                     # type | format | too_low | too_high | selection | unknown | rule:<name>
    value: Any

    def message(self) -> str: ...


class ConfigurationError(ValueError):
    """A technology object configuration with invalid values; ``issues`` lists every problem."""

    def __init__(self, source: str, issues: Sequence[ConfigIssue]):
        self.source = source
        self.issues = issues
        lines = [f"{source}: {len(issues)} configuration problem{'s' if len(issues) != 1 else ''}"]
        lines += ["  " + i.message() for i in issues]
        super().__init__("\n".join(lines))
