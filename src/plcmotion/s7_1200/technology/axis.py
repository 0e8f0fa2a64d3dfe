"""The S7-1200 positioning axis technology object: the kernel's axis with the S7-1200 vocabulary.

The behaviour is the kernel's (``kernel.axis.PositioningAxis``); this class gives it the S7-1200 schema
(tags, start values, ranges, access rights and effectiveness of S7-1200 Motion Control V6 §12.9, the PTO
rules of §5.4, the builder of the typed configuration) and the status tags of V6 or V7.
"""
from __future__ import annotations

from ...kernel.axis import PositioningAxis as _KernelAxis
from . import tags as T
from .parameters import S7_1200


class PositioningAxis(_KernelAxis):
    """Positioning axis technology object of the S7-1200 (TO_PositioningAxis)."""

    schema = S7_1200
    _dynamic = T.DYNAMIC
    _dynamic_types = T.DYNAMIC_TYPES
    _dynamic_aliases = T._DYNAMIC_ALIASES
    _status_groups = T._STATUS_GROUPS
    _read_param_tags = T.READ_PARAM_TAGS

    def _use_v7_tags(self) -> None:
        """Present the S7-1200 V7 status tags on this axis (StatusSensor[1].*, ErrorBits.AdaptionError)."""
        self._dynamic = T.DYNAMIC_V7
        self._dynamic_types = T.DYNAMIC_TYPES_V7
        self._dynamic_aliases = T._DYNAMIC_ALIASES_V7
        self._read_param_tags = T.READ_PARAM_TAGS_V7
