"""Traces: record axis tags and program values in the servo cycle, save them as CSV, plot them as PNG::

    trace = Trace(ctl, ["Axis_1.Position", "Axis_1.StatusBits.Done"], every=2).start()
    ctl.run(3.0)
    trace.stop()
    trace.to_csv("trace.csv")
    trace.plot("trace.png")

A trace samples at the end of the servo cycle (after the drives were written), so a row shows the state the
cycle produced.  Rows are floats; booleans become 0 and 1.  Memory stays bounded: beyond ``keep`` rows the
in-memory copy is thinned out (every second row dropped, stride doubled), while ``stream_to`` writes every
sampled row to a CSV file.  The CSV text depends only on the sampled values, so a deterministic program
gives a byte-identical file on every run.
"""
from __future__ import annotations

import contextlib

import difflib
import math
import os
import warnings
from numbers import Real
from typing import IO, TYPE_CHECKING, Any, Callable, Iterable, Iterator, Mapping, Sequence

import numpy as np

from .s7_1200.technology.axis import PositioningAxis as _Axis1200
from .s7_1200.technology.tags import DYNAMIC_V7

if TYPE_CHECKING:  # pragma: no cover
    from .kernel.runtime import Controller

Signals = Sequence[str] | Mapping[str, "str | Callable[[], Any]"] | None
PathLike = str | os.PathLike

#: tags traced for every axis when no signals are given
DEFAULT_TAGS: tuple[str, ...] = (
    "Position", "Velocity", "Acceleration", "ActualPosition", "ActualVelocity",
    "StatusPositioning.FollowingError",
) + tuple(f"StatusBits.{bit}" for bit in (
    "Enable", "HomingDone", "Done", "Error", "StandStill", "ConstantVelocity", "Accelerating",
    "Decelerating", "PositioningCommand", "VelocityCommand"))

_FLUSH_ROWS = 4096          # rows per CSV write: few syscalls, small buffer
_PENDING_BYTES = 1 << 21    # at most this much of rows waiting for the stream (fewer rows when wide)
_READ_ROWS = 8192           # rows per block when reading a CSV back
_BAD_NAME_CHARS = ',"\r\n'


class UnknownSignalError(KeyError):
    """A traced signal names an axis or a tag that does not exist."""

    def __str__(self) -> str:  # KeyError would show the message with quotes around it
        return str(self.args[0])


# --- signal resolution --------------------------------------------------------------------------------
def _resolve(ctl: Controller, signal: str) -> Callable[[], Any]:
    """Getter of ``"AxisName.tag.path"``; raises UnknownSignalError with close matches."""
    name, dot, path = signal.partition(".")
    axis = ctl.axes.get(name)
    if axis is None:
        near = difflib.get_close_matches(name, list(ctl.axes), n=3, cutoff=0.6)
        hint = f"; did you mean {' or '.join(near)}?" if near else (
            f"; axes: {', '.join(ctl.axes)}" if ctl.axes else "; the controller has no axes")
        raise UnknownSignalError(f"trace signal {signal!r}: no axis named {name!r}{hint}")
    if not dot or not path:
        raise UnknownSignalError(f"trace signal {signal!r}: expected 'AxisName.tag.path', e.g. '{name}.Position'")
    try:
        return axis.tag_getter(path)
    except KeyError as exc:  # the axis' message already suggests close tag paths
        raise UnknownSignalError(f"trace signal {signal!r}: {exc.args[0]}") from None


def _check_name(name: Any, seen: set[str]) -> str:
    if not isinstance(name, str) or not name or any(c in name for c in _BAD_NAME_CHARS):
        raise ValueError(f"trace column name {name!r} must be a non-empty string without commas, quotes or "
                         "line breaks")
    if name == "time":
        raise ValueError("trace column name 'time' is taken: it is the first column of every trace")
    if name in seen:
        raise ValueError(f"trace column {name!r} appears twice")
    seen.add(name)
    return name


def _signal_table(ctl: Controller, signals: Signals) -> list[tuple[str, Callable[[], Any]]]:
    """(column name, getter) for every signal, in the given order."""
    if signals is None:
        # an axis class may name its family's default set (``trace_tags``), else the S7-1200 names
        signals = [f"{name}.{tag}" for name, axis in ctl.axes.items()
                   for tag in getattr(axis, "trace_tags", DEFAULT_TAGS)]
        if not signals:
            raise ValueError("the controller has no axes: pass the signals to trace")
    if isinstance(signals, str):
        raise TypeError("signals must be a list of 'AxisName.tag.path' strings or a dict, not a single string")
    items: Iterable[tuple[Any, Any]]
    items = signals.items() if isinstance(signals, Mapping) else ((s, s) for s in signals)
    table: list[tuple[str, Callable[[], Any]]] = []
    seen: set[str] = set()
    for name, source in items:
        name = _check_name(name, seen)
        if isinstance(source, str):
            getter = _resolve(ctl, source)
        elif callable(source):
            getter = source
        else:
            raise TypeError(f"trace signal {name!r}: expected an 'AxisName.tag.path' string or a function "
                            f"without arguments, got {type(source).__name__}")
        _probe(name, getter)
        table.append((name, getter))
    if not table:
        raise ValueError("no signals to trace")
    return table


def _probe(name: str, getter: Callable[[], Any]) -> None:
    """Read a signal once so that a bad one fails now rather than in the servo cycle."""
    try:
        value = getter()
    except Exception as exc:
        raise ValueError(f"trace signal {name!r} cannot be read: {type(exc).__name__}: {exc}") from exc
    if not isinstance(value, (Real, np.bool_, np.number)) or isinstance(value, complex | np.complexfloating):
        raise TypeError(f"trace signal {name!r} gives {type(value).__name__} {value!r}; "
                        "only numbers and booleans can be traced")


# --- bounded storage ------------------------------------------------------------------------------------
class _Decimator:
    """Holds an evenly thinned copy of a growing row sequence in at most ``keep`` rows.

    Sample ``i`` (counted from 0) is kept when ``i % stride == 0``; when the store is full every second kept
    row is dropped and the stride doubles, so the rows always span the whole sequence.  The newest row is
    kept aside as well, so the end of the run is always visible.
    """

    def __init__(self, ncols: int, keep: int, chunk_rows: int = 1024):
        if isinstance(keep, bool) or not isinstance(keep, int) or keep < 2:
            raise ValueError(f"keep must be an integer >= 2, got {keep!r}")
        self.ncols = ncols
        self.capacity = keep - 1                     # one row is reserved for the newest sample
        self.stride = 1
        self.seen = 0                                # samples offered so far
        self._chunks: list[np.ndarray] = []
        self._buf = np.empty((min(chunk_rows, self.capacity), ncols))
        self._fill = 0
        self._kept = 0
        self._last: Sequence[float] | None = None

    def add(self, row: Sequence[float]) -> None:
        """Offer the next sample."""
        if self.seen % self.stride == 0:
            if self._kept == self.capacity:
                self._halve()
            if self.seen % self.stride == 0:
                if self._fill == len(self._buf):
                    self._chunks.append(self._buf)
                    self._buf = np.empty_like(self._buf)
                    self._fill = 0
                self._buf[self._fill] = row
                self._fill += 1
                self._kept += 1
        self._last = row
        self.seen += 1

    def add_block(self, block: np.ndarray) -> None:
        """Offer the next ``len(block)`` samples at once."""
        if not len(block):
            return
        picked = block[(-self.seen) % self.stride::self.stride]
        if len(picked):
            self._flush_buf()
            self._chunks.append(picked.copy())
            self._kept += len(picked)
            while self._kept > self.capacity:
                self._halve()
        self._last = block[-1].copy()
        self.seen += len(block)

    def rows(self) -> np.ndarray:
        """The kept rows plus the newest sample, oldest first (a new array)."""
        parts = [*self._chunks, self._buf[:self._fill]]
        if self._last is not None and (self.seen - 1) % self.stride:
            parts.append(np.asarray(self._last, dtype=float).reshape(1, self.ncols))
        return np.concatenate(parts)

    def __len__(self) -> int:
        return self._kept + (1 if self._last is not None and (self.seen - 1) % self.stride else 0)

    def _flush_buf(self) -> None:
        if self._fill:
            self._chunks.append(self._buf[:self._fill].copy())
            self._fill = 0

    def _halve(self) -> None:
        self._flush_buf()
        kept = np.concatenate(self._chunks)[::2].copy()   # copy: release the full-size array
        self._chunks = [kept]
        self._kept = len(kept)
        self.stride *= 2


# --- CSV ------------------------------------------------------------------------------------------------
def _csv_text(rows: list[list[float]]) -> str:
    """CSV lines of ``rows`` (Python floats): shortest exact repr, integral values without '.0'."""
    if not rows:
        return ""
    text = "\n".join([",".join(map(repr, row)) for row in rows]) + "\n"
    # repr ends an integral float in ".0" (never inside a number: 1e+16 has no ".0"); "1" reads back as 1.0
    return text.replace(".0,", ",").replace(".0\n", "\n")


def _write_csv(path: PathLike, columns: Sequence[str], rows: np.ndarray) -> None:
    with open(path, "w", encoding="ascii", newline="") as f:
        f.write(",".join(columns) + "\n")
        for i in range(0, len(rows), _FLUSH_ROWS):
            f.write(_csv_text(rows[i:i + _FLUSH_ROWS].tolist()))


def _read_blocks(path: PathLike, block_rows: int = _READ_ROWS) -> tuple[list[str], Iterator[np.ndarray]]:
    """Column names and an iterator over blocks of at most ``block_rows`` rows."""
    f = open(path, encoding="ascii", newline="")
    header = f.readline().rstrip("\r\n")
    if not header:
        f.close()
        raise ValueError(f"{os.fspath(path)}: empty file, expected a header line with the column names")
    columns = header.split(",")

    def blocks() -> Iterator[np.ndarray]:
        with f:
            lines: list[str] = []
            for line in f:
                if line.strip():
                    lines.append(line)
                if len(lines) == block_rows:
                    yield _parse(lines, len(columns), path)
                    lines = []
            if lines:
                yield _parse(lines, len(columns), path)

    return columns, blocks()


def _parse(lines: list[str], ncols: int, path: PathLike) -> np.ndarray:
    block = np.loadtxt(lines, delimiter=",", dtype=float, ndmin=2)
    if block.shape[1] != ncols:
        raise ValueError(f"{os.fspath(path)}: rows have {block.shape[1]} values, the header names {ncols} columns")
    return block


def read_csv(path: PathLike) -> tuple[list[str], np.ndarray]:
    """Read a trace CSV file: the column names and a 2-D float array with one row per sample."""
    columns, blocks = _read_blocks(path)
    parts = list(blocks)
    return columns, np.concatenate(parts) if parts else np.empty((0, len(columns)))


# --- the trace ------------------------------------------------------------------------------------------
class Trace:
    """Records signals of a controller every ``every``-th servo cycle once started.

    ``signals``: ``"AxisName.tag.path"`` strings (the column is named like the string), or a dict mapping a
    column name to such a string or to a function without arguments (e.g. ``lambda: move.Done``); ``None``
    traces :data:`DEFAULT_TAGS` of every axis.  Every signal is read once here, so an unknown axis or tag or a
    value that is not a number fails at construction.

    Samples are taken when the number of servo cycles done is a multiple of ``every`` (the sample times do
    not depend on when the trace was started).  At most ``keep`` rows stay in memory; ``stream_to`` names a
    CSV file that receives every sampled row, written on ``start()`` and completed by ``stop()``.
    """

    def __init__(self, ctl: Controller, signals: Signals = None, *, every: int = 1,
                 stream_to: PathLike | None = None, keep: int = 20000):
        if isinstance(every, bool) or not isinstance(every, int) or every < 1:
            raise ValueError(f"every must be a whole number of servo cycles >= 1, got {every!r}")
        table = _signal_table(ctl, signals)
        self.ctl = ctl
        self.every = every
        self.stream_to = stream_to
        self.columns: list[str] = ["time"] + [name for name, _ in table]
        self.errors: dict[str, str] = {}            # column -> first exception its signal raised while sampled
        self.write_error: str | None = None         # why the stream file could not be written, if it could not
        self._getters = [getter for _, getter in table]
        self._store = _Decimator(len(self.columns), keep)
        self._stream: IO[str] | None = None
        # rows not yet written to the stream: a preallocated float block, filled up to ``_npending``
        rows = max(16, min(_FLUSH_ROWS, _PENDING_BYTES // (8 * len(self.columns))))
        self._pending = np.empty((rows, len(self.columns))) if stream_to is not None else np.empty((0, 0))
        self._npending = 0
        self._streamed = False                      # the stream file was created already
        self._recording = False

    # --- recording -------------------------------------------------------------------------------------
    def start(self) -> Trace:
        """Begin (or resume) sampling; returns the trace, so ``Trace(ctl).start()`` reads well."""
        if self._recording:
            return self
        if self.stream_to is not None:
            # a resumed trace appends to its own file instead of overwriting it
            self._stream = open(self.stream_to, "a" if self._streamed else "w", encoding="ascii", newline="")
            if not self._streamed:
                self._stream.write(",".join(self.columns) + "\n")
                self._streamed = True
        self.ctl.on_post_servo(self._sample)
        self._recording = True
        return self

    def stop(self) -> Trace:
        """Stop sampling and complete the stream file; the recorded rows stay available."""
        if self._recording:
            self.ctl.remove_hook(self._sample)
            self._recording = False
        if self._stream is not None:
            self._flush()
        if self._stream is not None:
            try:
                self._stream.close()
            except OSError as exc:
                self.write_error = self.write_error or f"{exc.strerror or exc}"
            self._stream = None
        return self

    @property
    def recording(self) -> bool:
        return self._recording

    def __enter__(self) -> Trace:
        return self.start()

    def __exit__(self, *exc: Any) -> None:
        self.stop()

    def _sample(self, t: float) -> None:
        if self.ctl.servo_cycles % self.every:
            return
        try:
            row = [t, *[float(g()) for g in self._getters]]
        except Exception:
            row = self._careful_row(t)
        self._store.add(row)
        if self._stream is not None:
            pending = self._pending
            pending[self._npending] = row
            self._npending += 1
            if self._npending == len(pending):
                self._flush()

    def _careful_row(self, t: float) -> list[float]:
        """A row where a signal that raises reads NaN: a faulty signal must not stop the servo cycle."""
        row = [t]
        for name, getter in zip(self.columns[1:], self._getters, strict=True):
            try:
                row.append(float(getter()))
            except Exception as exc:
                row.append(math.nan)
                if name not in self.errors:
                    self.errors[name] = f"{type(exc).__name__}: {exc}"
                    warnings.warn(f"trace signal {name!r} raised {self.errors[name]} at t = {t:.6g} s; "
                                  "recorded as NaN", RuntimeWarning, stacklevel=2)
        return row

    def _flush(self) -> None:
        if self._npending and self._stream is not None:
            try:
                # tolist() gives back the very floats sampled, so the text is that of the rows themselves
                self._stream.write(_csv_text(self._pending[:self._npending].tolist()))
                self._stream.flush()
            except OSError as exc:
                # a full disk must not stop the servo cycle (this runs in its hook): stop streaming, keep the
                # rows in memory and say why in ``write_error``
                self.write_error = f"{exc.strerror or exc} (at t = {self.ctl.time:.6g} s)"
                stream, self._stream = self._stream, None
                with contextlib.suppress(OSError):
                    stream.close()
        self._npending = 0

    # --- results ---------------------------------------------------------------------------------------
    @property
    def samples(self) -> int:
        """Number of rows sampled since the first start (all of them are in the stream file)."""
        return self._store.seen

    @property
    def stride(self) -> int:
        """Spacing of the in-memory rows in samples (1 until ``keep`` was exceeded)."""
        return self._store.stride

    def __len__(self) -> int:
        """Number of rows in memory."""
        return len(self._store)

    @property
    def rows(self) -> np.ndarray:
        """The in-memory rows as a 2-D array (a copy), one column per name in :attr:`columns`."""
        return self._store.rows()

    @property
    def data(self) -> dict[str, np.ndarray]:
        """Column name -> 1-D array of the in-memory rows."""
        rows = self.rows
        return {name: rows[:, i] for i, name in enumerate(self.columns)}

    def to_csv(self, path: PathLike) -> None:
        """Write the in-memory rows (thinned out if the trace outgrew ``keep``) to a CSV file."""
        _write_csv(path, self.columns, self.rows)

    def plot(self, path: PathLike, title: str | None = None) -> None:
        """Save a PNG of the in-memory rows: motion panels per axis and step lanes for the binary signals."""
        _plot(self.columns, self.rows, path, title)

    def __repr__(self) -> str:
        state = "recording" if self._recording else "stopped"
        return f"<Trace {len(self.columns) - 1} signals, {self.samples} samples, {len(self)} in memory, {state}>"


def plot_csv(csv_path: PathLike, png_path: PathLike, title: str | None = None, *, keep: int = 20000) -> None:
    """Plot a trace CSV file of any length, reading it in blocks and keeping at most ``keep`` rows."""
    columns, blocks = _read_blocks(csv_path)
    store = _Decimator(len(columns), keep)
    for block in blocks:
        store.add_block(block)
    _plot(columns, store.rows(), png_path, title)


# --- plotting -------------------------------------------------------------------------------------------
#: the motion panels: setpoint and actual value of position, velocity and acceleration
_MOTION_PANELS = (("Position", "ActualPosition"), ("Velocity", "ActualVelocity"), ("Acceleration",))
_FOLLOWING_ERROR = "StatusPositioning.FollowingError"
#: other families' names of the same values (technology DB members of S7-Technology): plotted alike
_SAME_AS = {"CommandPosition": "Position", "CommandVelocity": "Velocity", "CommandAcceleration": "Acceleration",
            "FollowingError": _FOLLOWING_ERROR}
_AXIS_TAGS = frozenset(_Axis1200.tag_paths()) | frozenset(DYNAMIC_V7) | frozenset(_SAME_AS)   # V7: a few more


def _layout(columns: Sequence[str], rows: np.ndarray) -> tuple[dict[str, dict[str, int]], list[int], list[int]]:
    """Group columns: axis name -> {tag: column}, other binary columns, other analog columns."""
    axes: dict[str, dict[str, int]] = {}
    lanes: list[int] = []
    analog: list[int] = []
    for i, name in enumerate(columns):
        if i == 0:
            continue
        axis, _, tag = name.partition(".")
        if tag in _AXIS_TAGS:
            axes.setdefault(axis, {})[_SAME_AS.get(tag, tag)] = i
        elif _binary(rows[:, i]):
            lanes.append(i)
        else:
            analog.append(i)
    return axes, lanes, analog


def _binary(values: np.ndarray) -> bool:
    return bool(np.all((values == 0) | (values == 1)))


def _draw_lanes(ax: Any, t: np.ndarray, rows: np.ndarray, cols: list[tuple[str, int]]) -> None:
    """One 0/1 step line per signal, stacked from the top down, each labelled on the y axis."""
    n = len(cols)
    for k, (_, i) in enumerate(cols):
        base = 1.5 * (n - 1 - k)
        ax.axhline(base, color="0.85", linewidth=0.5)
        line, = ax.step(t, base + rows[:, i], where="post", linewidth=1.0)
        # shading tells a lane's 1 apart from the 0 of the lane above it
        ax.fill_between(t, base, base + rows[:, i], step="post", color=line.get_color(), alpha=0.2, linewidth=0)
    ax.set_yticks([1.5 * (n - 1 - k) + 0.5 for k in range(n)], [label for label, _ in cols], fontsize=7)
    ax.set_ylim(-0.3, 1.5 * (n - 1) + 1.3)
    ax.tick_params(axis="y", length=0)


def _plot(columns: Sequence[str], rows: np.ndarray, path: PathLike, title: str | None) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg  # Agg without touching pyplot's backend
    from matplotlib.figure import Figure

    axes, lanes, analog = _layout(columns, rows)
    t = rows[:, 0]
    # panels: (kind, payload, height ratio)
    panels: list[tuple[str, Any, float]] = []
    for name, tags in axes.items():
        for group in _MOTION_PANELS:
            present = [tag for tag in group if tag in tags]
            if present:
                panels.append(("motion", (name, [(tag, tags[tag]) for tag in present],
                                          tags.get(_FOLLOWING_ERROR) if group[0] == "Position" else None), 1.0))
        others = [(tag, i) for tag, i in tags.items() if not any(tag in g for g in _MOTION_PANELS)
                  and tag != _FOLLOWING_ERROR]
        bits = [(tag.rpartition(".")[2], i) for tag, i in others if _binary(rows[:, i])]
        analog.extend(i for _, i in others if not _binary(rows[:, i]))
        if bits:
            panels.append(("lanes", (f"{name} status", bits), max(1.2, 0.18 * len(bits))))
        if _FOLLOWING_ERROR in tags and not any(tag in tags for tag in _MOTION_PANELS[0]):
            analog.append(tags[_FOLLOWING_ERROR])
    if lanes:
        cols = [(columns[i], i) for i in lanes]
        panels.append(("lanes", ("signals", cols), max(1.2, 0.18 * len(cols))))
    if analog:
        panels.append(("analog", sorted(analog), 1.0))

    height = max(9.0, 2.0 * sum(h for _, _, h in panels))
    fig = Figure(figsize=(12, height), dpi=100, layout="constrained")
    FigureCanvasAgg(fig)
    fig.suptitle(title or "Trace")
    if not panels or not len(rows):
        fig.text(0.5, 0.5, "no samples recorded" if not len(rows) else "no signals to plot",
                 ha="center", va="center")
    else:
        subplots = fig.subplots(len(panels), 1, sharex=True, squeeze=False,
                                gridspec_kw={"height_ratios": [h for _, _, h in panels]})[:, 0]
        for ax, (kind, payload, _) in zip(subplots, panels, strict=True):
            if kind == "motion":
                name, lines, fe = payload
                for tag, i in lines:
                    ax.plot(t, rows[:, i], label="setpoint" if not tag.startswith("Actual") else "actual",
                            linewidth=1.0, linestyle="--" if tag.startswith("Actual") else "-")
                ax.set_ylabel(f"{name}\n{lines[0][0]}")
                if fe is not None:
                    twin = ax.twinx()
                    twin.plot(t, rows[:, fe], color="tab:red", linewidth=0.7, label="following error")
                    twin.set_ylabel("following error", color="tab:red", fontsize=8)
                    twin.tick_params(axis="y", labelcolor="tab:red", labelsize=7)
                if len(lines) > 1 or fe is not None:
                    ax.legend(loc="upper left", fontsize=7)
            elif kind == "lanes":
                label, cols = payload
                _draw_lanes(ax, t, rows, cols)
                ax.set_ylabel(label)
            else:
                for i in payload:
                    ax.plot(t, rows[:, i], label=columns[i], linewidth=1.0)
                ax.legend(loc="upper left", fontsize=7)
            ax.grid(True, linewidth=0.3)
        subplots[-1].set_xlabel("time [s]")
        subplots[-1].set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1e-3)
    fig.savefig(os.fspath(path), format="png")


__all__ = ["Trace", "UnknownSignalError", "DEFAULT_TAGS", "read_csv", "plot_csv"]
