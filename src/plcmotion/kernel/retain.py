"""Retentive data of the controller (e.g. the absolute encoder offset, S7-1200 V6 §11.1.3 modes 6/7).

Stored as JSON next to the project.  Writing goes to a temporary file in the same directory that is
flushed to disk and then renamed over the old file, so a crash during the write leaves either the old
or the new content, never a torn file.
"""
from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any


def load(path: str | os.PathLike) -> dict[str, Any]:
    p = Path(path)
    if not p.exists():
        return {}
    try:
        data = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ValueError(f"{p}: retentive data file cannot be read ({exc}); delete it to start afresh") from exc
    return data.get("axes", {}) if isinstance(data, dict) else {}


def save(path: str | os.PathLike, axes: dict[str, Any]) -> None:
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=p.name + ".", suffix=".tmp", dir=p.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            json.dump({"format": "plcmotion-retain-1", "axes": axes}, fh, indent=2, sort_keys=True)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, p)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
