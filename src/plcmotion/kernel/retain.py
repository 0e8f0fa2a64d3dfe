"""Retentive data of the controller (e.g. the absolute encoder offset, S7-1200 V6 §11.1.3 modes 6/7).

Stored as JSON next to the project.  Writing goes to a temporary file of a unique name in the same
directory that is flushed to disk, renamed over the old file, and then the directory itself is
flushed, so a crash or kill during the write leaves either the old or the new content, never a torn
file; temporary files a killed writer left behind are removed by the next load or save.

Reading checks every value.  A file that is not a plcmotion state file (not JSON, another format) is
an error: it is not ours to overwrite.  An axis entry with invalid content (``AbsEncoderOffset`` not a
finite number, ``HomingDone`` not true/false) is dropped with a :class:`RetainWarning`: that axis
starts as not adjusted and not homed, as after a loss of the retentive data of a CPU, and must be
adjusted again (MC_Home mode 6/7) before it may position absolutely.
"""
from __future__ import annotations

import json
import math
import os
import re
import tempfile
import time
import warnings
from pathlib import Path
from typing import Any

FORMAT = "plcmotion-retain-1"
#: the retentive values of an axis and their checks
FIELDS = ("AbsEncoderOffset", "HomingDone")
LIMIT = 1.0e12                 # the LREAL range of the position tags
MAX_BYTES = 16 * 1024 * 1024   # a state file is small; a larger one is not ours
STALE_AFTER = 60.0             # s: a temporary file this old belongs to no running write


class RetainWarning(UserWarning):
    """Retentive data of an axis was invalid and is not used (the axis is not adjusted/homed)."""


def _temp_pattern(p: Path) -> re.Pattern[str]:
    return re.compile(re.escape(p.name) + r"\.(\d+)\.[A-Za-z0-9_]+\.tmp")


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError, OverflowError):
        return True            # exists (another user) or cannot tell: leave it to the age rule
    return True


def clean_stale(path: str | os.PathLike) -> list[str]:
    """Remove temporary files of ``path`` left by a writer that was killed; returns their names.

    A temporary file carries its writer's process id; it is stale when that process is gone or the
    file is older than STALE_AFTER seconds (a process id may be reused)."""
    p = Path(path)
    pattern = _temp_pattern(p)
    removed = []
    try:
        names = os.listdir(p.parent if str(p.parent) else ".")
    except OSError:
        return removed
    now = time.time()
    for name in names:
        m = pattern.fullmatch(name)
        if not m:
            continue
        tmp = p.parent / name
        try:
            old = now - tmp.stat().st_mtime > STALE_AFTER
            if old or not _alive(int(m.group(1))):
                tmp.unlink()
                removed.append(name)
        except OSError:
            pass
    return removed


def validate(path: str | os.PathLike, axes: Any) -> dict[str, dict[str, Any]]:
    """The valid axis entries of ``axes``; every invalid one is reported (RetainWarning) and dropped."""
    if not isinstance(axes, dict):
        warnings.warn(f"{path}: retentive data: 'axes' is not a table; no axis is adjusted", RetainWarning,
                      stacklevel=3)
        return {}
    out: dict[str, dict[str, Any]] = {}
    for name, entry in axes.items():
        problem = _entry_problem(entry)
        if problem:
            warnings.warn(f"{path}: retentive data of axis {name!r} is invalid ({problem}); the axis starts "
                          f"as not adjusted and not homed: adjust it again (MC_Home mode 6/7)",
                          RetainWarning, stacklevel=3)
            continue
        out[name] = {"AbsEncoderOffset": float(entry["AbsEncoderOffset"]), "HomingDone": entry["HomingDone"]}
    return out


def _entry_problem(entry: Any) -> str:
    if not isinstance(entry, dict):
        return "not a table"
    missing = [f for f in FIELDS if f not in entry]
    if missing:
        return "missing " + ", ".join(missing)
    offset, homed = entry["AbsEncoderOffset"], entry["HomingDone"]
    if isinstance(offset, bool) or not isinstance(offset, (int, float)) or not abs(offset) <= LIMIT:
        return f"AbsEncoderOffset = {_short(offset)}: allowed: a finite number within +-{LIMIT:g}"
    if not isinstance(homed, bool):
        return f"HomingDone = {_short(homed)}: allowed: true or false"
    return ""


def _short(value: Any) -> str:
    text = json.dumps(value) if isinstance(value, (str, bool, int, float, type(None))) else type(value).__name__
    return text if len(text) <= 40 else text[:37] + "..."


def load(path: str | os.PathLike) -> dict[str, Any]:
    p = Path(path)
    clean_stale(p)
    if not p.exists():
        return {}
    try:
        if p.stat().st_size > MAX_BYTES:
            raise ValueError(f"larger than {MAX_BYTES} bytes")
        with p.open("rb") as fh:                # bounded: a device or pipe has no size and may never end
            raw = fh.read(MAX_BYTES + 1)
        if len(raw) > MAX_BYTES:
            raise ValueError(f"larger than {MAX_BYTES} bytes")
        data = json.loads(raw.decode("utf-8"))
    except (OSError, ValueError, RecursionError) as exc:
        raise ValueError(f"{p}: retentive data file cannot be read ({exc}); delete it to start afresh") from exc
    if not isinstance(data, dict) or data.get("format", FORMAT) != FORMAT:
        raise ValueError(f"{p}: not a plcmotion retentive data file (format {FORMAT!r} expected); "
                         f"choose another state_file or delete it to start afresh")
    return validate(p, data.get("axes", {}))


def save(path: str | os.PathLike, axes: dict[str, Any]) -> None:
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    clean_stale(p)
    # unique per writer: <name>.<pid>.<random>.tmp (the pid lets clean_stale see a dead writer)
    fd, tmp = tempfile.mkstemp(prefix=f"{p.name}.{os.getpid()}.", suffix=".tmp", dir=p.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            json.dump({"format": FORMAT, "axes": axes}, fh, indent=2, sort_keys=True)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, p)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    _fsync_dir(p.parent)


def _fsync_dir(folder: Path) -> None:
    """Make the rename durable: flush the directory entry (POSIX; not possible on Windows)."""
    try:
        fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)
