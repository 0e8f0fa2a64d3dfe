"""Trace: sampling in the servo cycle, bounded memory, exact and reproducible CSV, PNG plots."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveRelative, MC_Power
from plcmotion.trace import DEFAULT_TAGS, Trace, UnknownSignalError, plot_csv, read_csv

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def make_machine(repeat: bool = False):
    """One axis moving 100 mm relative (again and again with ``repeat``); returns (ctl, axis, move)."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {
        "DynamicLimits": {"MaxVelocity": 500.0},
        "DynamicDefaults": {"Acceleration": 1000.0, "Deceleration": 1000.0, "Jerk": 10000.0}})
    power, move = MC_Power(), MC_MoveRelative()

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        execute = power.Status and not (repeat and (move.Done or move.Error))
        move(Axis=axis, Execute=execute, Distance=100.0, Velocity=50.0)

    return ctl, axis, move


def reference(ctl: Controller, read) -> list[tuple[float, float]]:
    """(time, value) after every servo cycle, read independently of the trace."""
    seen: list[tuple[float, float]] = []
    ctl.on_post_servo(lambda t: seen.append((ctl.time, read())))
    return seen


def test_trace_position_column_is_the_axis_position_at_the_sample_times():
    ctl, axis, move = make_machine()
    trace = Trace(ctl).start()
    seen = reference(ctl, lambda: axis.Position)
    ctl.run(3.0)
    trace.stop()

    data = trace.data
    assert trace.columns == ["time"] + [f"Axis_1.{tag}" for tag in DEFAULT_TAGS]
    assert data["time"].tolist() == [t for t, _ in seen]
    assert data["Axis_1.Position"].tolist() == [p for _, p in seen]
    assert data["Axis_1.Position"][-1] == 100.0
    # booleans as 0/1: Done rises once the move has ended
    done = data["Axis_1.StatusBits.Done"]
    assert set(done.tolist()) == {0.0, 1.0}
    assert done[-1] == 1.0 and move.Done


def test_trace_recording_begins_at_start_and_ends_at_stop():
    ctl, _, _ = make_machine()
    trace = Trace(ctl, ["Axis_1.Position"])
    ctl.run(0.1)
    assert trace.samples == 0 and not trace.recording
    with trace:
        ctl.run(0.1)
    assert trace.samples == 100
    ctl.run(0.1)
    assert trace.samples == 100
    assert trace.data["time"][0] == pytest.approx(0.101)
    assert trace.data["time"][-1] == pytest.approx(0.2)


def test_trace_every_samples_each_nth_servo_cycle():
    ctl, axis, _ = make_machine()
    trace = Trace(ctl, ["Axis_1.Velocity"], every=5).start()
    seen = reference(ctl, lambda: axis.Velocity)
    ctl.run(1.0)
    expected = seen[4::5]                  # servo cycles 5, 10, 15, ...
    assert len(trace) == 200
    assert trace.data["time"].tolist() == [t for t, _ in expected]
    assert trace.data["Axis_1.Velocity"].tolist() == [v for _, v in expected]


def test_trace_instruction_outputs_and_functions_can_be_traced():
    ctl, _, move = make_machine()
    trace = Trace(ctl, {"move.Done": lambda: move.Done, "move.ErrorID": lambda: move.ErrorID,
                        "pos": "Axis_1.Position"}).start()
    ctl.run(3.0)
    assert trace.columns == ["time", "move.Done", "move.ErrorID", "pos"]
    assert trace.data["move.Done"][0] == 0.0 and trace.data["move.Done"][-1] == 1.0
    assert trace.data["pos"][-1] == 100.0


def test_trace_csv_round_trip_is_exact(tmp_path: Path):
    ctl, _, _ = make_machine()
    trace = Trace(ctl).start()
    ctl.run(3.0)
    trace.to_csv(tmp_path / "trace.csv")

    columns, rows = read_csv(tmp_path / "trace.csv")
    assert columns == trace.columns
    assert rows.tobytes() == trace.rows.tobytes()
    # booleans are written as 0 and 1
    line = (tmp_path / "trace.csv").read_text().splitlines()[-1].split(",")
    enable = trace.columns.index("Axis_1.StatusBits.Enable")
    assert line[enable] == "1"


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(allow_nan=False) | st.booleans() | st.integers(-2**53, 2**53), min_size=1, max_size=30))
def test_trace_csv_round_trip_of_any_value(tmp_path_factory, values):
    ctl = Controller(servo_cycle=0.001, app_cycle=0.001)
    source = iter(values)
    trace = Trace(ctl, {"x": lambda: next(source, 0.0)})    # the construction probe reads values[0]
    trace.start()
    ctl.run(len(values) * 0.001)
    path = tmp_path_factory.mktemp("csv") / "values.csv"
    trace.to_csv(path)
    _, rows = read_csv(path)
    expected = np.array([float(v) for v in values[1:]] + [0.0])
    assert rows[:, 1].tobytes() == expected.tobytes()      # bit for bit, including -0.0 and infinities


def test_trace_identical_runs_give_byte_identical_csv(tmp_path: Path):
    files = []
    for run in ("a", "b"):
        ctl, _, move = make_machine(repeat=True)
        trace = Trace(ctl, {**{f"Axis_1.{tag}": f"Axis_1.{tag}" for tag in DEFAULT_TAGS},
                            "move.Busy": lambda move=move: move.Busy},
                      stream_to=tmp_path / f"stream_{run}.csv").start()
        ctl.run(5.0)
        trace.stop()
        trace.to_csv(tmp_path / f"memory_{run}.csv")
        files.append(run)
    for kind in ("memory", "stream"):
        a, b = ((tmp_path / f"{kind}_{run}.csv").read_bytes() for run in files)
        assert a == b and len(a) > 100_000
    # without decimation the streamed file and the in-memory copy are the same text
    assert (tmp_path / "stream_a.csv").read_bytes() == (tmp_path / "memory_a.csv").read_bytes()


def test_trace_long_streamed_run_keeps_memory_bounded_and_the_file_complete(tmp_path: Path):
    ctl, axis, _ = make_machine(repeat=True)
    keep = 2000
    path = tmp_path / "long.csv"
    trace = Trace(ctl, ["Axis_1.Position", "Axis_1.StatusBits.Done"], keep=keep, stream_to=path).start()
    for _ in range(10):
        ctl.run(20.0)
        assert len(trace) <= keep
        assert len(trace.data["time"]) == len(trace)
    trace.stop()

    assert trace.samples == 200_000
    assert trace.stride > 1
    columns, rows = read_csv(path)
    assert columns == trace.columns
    assert len(rows) == 200_000
    assert rows[0, 0] == 0.001 and rows[-1, 0] == ctl.time
    assert np.all(np.diff(rows[:, 0]) > 0)
    # the in-memory rows are evenly spaced rows of the file covering the whole run, plus the newest one
    kept = trace.rows
    assert kept[0, 0] == rows[0, 0] and kept[-1, 0] == rows[-1, 0]
    assert np.array_equal(kept[:-1], rows[::trace.stride][:len(kept) - 1])
    assert rows[-1, 1] == axis.Position

    png = tmp_path / "long.png"
    plot_csv(path, png, keep=keep)
    assert png.read_bytes()[:8] == PNG_SIGNATURE


def test_trace_plot_writes_a_png(tmp_path: Path):
    ctl, _, move = make_machine()
    trace = Trace(ctl, {**{f"Axis_1.{tag}": f"Axis_1.{tag}" for tag in DEFAULT_TAGS},
                        "move.Done": lambda: move.Done, "distance": lambda: 100.0 - ctl["Axis_1"].Position},
                  every=4).start()
    ctl.run(3.0)
    path = tmp_path / "trace.png"
    trace.plot(path, title="MC_MoveRelative 100 mm")
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE and len(data) > 20_000


@pytest.mark.parametrize("signals, error, words", [
    (["Axis_2.Position"], UnknownSignalError, ["Axis_2", "Axis_1"]),
    (["Axis_1.Postion"], UnknownSignalError, ["Axis_1.Postion", "Position"]),
    (["Axis_1.StatusBits.Dne"], UnknownSignalError, ["StatusBits.Done"]),
    (["Axis_1"], UnknownSignalError, ["AxisName.tag.path"]),
    ({"x": "Axis_9.Velocity"}, UnknownSignalError, ["Axis_9"]),
    ({"x": 3}, TypeError, ["'x'"]),
    ({"x": lambda: "fast"}, TypeError, ["'x'", "str"]),
    ({"x": lambda: 1 / 0}, ValueError, ["'x'", "ZeroDivisionError"]),
    ({"time": "Axis_1.Position"}, ValueError, ["time"]),
    ({"a,b": "Axis_1.Position"}, ValueError, ["a,b"]),
])
def test_trace_bad_signals_raise_at_construction(signals, error, words):
    ctl, _, _ = make_machine()
    with pytest.raises(error) as info:
        Trace(ctl, signals)
    for word in words:
        assert word in str(info.value)
    ctl.run(0.1)                           # nothing was left hooked into the servo cycle
    assert ctl.mode == "RUN"


def test_trace_unknown_signal_is_a_key_error():
    ctl, _, _ = make_machine()
    with pytest.raises(KeyError):
        Trace(ctl, ["Axis_1.Positon"])


def test_trace_a_signal_failing_in_the_cycle_reads_nan_and_the_controller_keeps_running():
    ctl, _, _ = make_machine()
    box = {"value": 1.0}
    trace = Trace(ctl, {"x": lambda: box["value"], "pos": "Axis_1.Position"}).start()
    ctl.run(0.1)
    box["value"] = None                    # float(None) raises from now on
    with pytest.warns(RuntimeWarning, match="'x'"):
        ctl.run(0.1)
    assert ctl.mode == "RUN"
    x = trace.data["x"]
    assert x[99] == 1.0 and math.isnan(x[100]) and math.isnan(x[-1])
    assert "x" in trace.errors and not np.isnan(trace.data["pos"]).any()


def test_trace_resumed_stream_appends_below_one_header(tmp_path: Path):
    ctl, _, _ = make_machine()
    path = tmp_path / "resumed.csv"
    trace = Trace(ctl, ["Axis_1.Position"], stream_to=path)
    for _ in range(2):
        with trace:
            ctl.run(0.5)
        ctl.run(0.5)
    lines = path.read_text().splitlines()
    assert lines[0] == "time,Axis_1.Position" and len(lines) == 1 + 1000
    columns, rows = read_csv(path)
    assert rows.tobytes() == trace.rows.tobytes()


def test_trace_bad_options_are_rejected():
    ctl, _, _ = make_machine()
    with pytest.raises(ValueError):
        Trace(ctl, every=0)
    with pytest.raises(ValueError):
        Trace(ctl, keep=1)
    with pytest.raises(ValueError):
        Trace(Controller(), None)          # no axes, nothing to trace by default
