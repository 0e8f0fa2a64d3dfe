"""The built-in demo: one servo axis through the life of a small machine, in virtual time.

Enable, home, absolute and relative moves, a move overridden by another, velocity mode, halt, jog,
an invalid command answered with its ErrorID, disable.  The script is a generator: each ``yield`` waits
one application cycle, while the program calls every instruction cyclically as a PLC program would.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Iterator

from .kernel import Controller
from .s7_1200 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity,
                      MC_Power, MC_Reset, describe)

AXIS_PARAMS = {
    "Actor": {"Type": 1, "DriveParameter": {"ReferenceSpeed": 3000.0, "MaxSpeed": 6000.0}},
    "Mechanics": {"LeadScrew": 10.0},
    "DynamicLimits": {"MaxVelocity": 500.0},
    "DynamicDefaults": {"Acceleration": 1000.0, "Deceleration": 1000.0, "EmergencyDeceleration": 5000.0,
                        "Jerk": 20000.0},
    "PositionLimits_SW": {"Active": True, "MinPosition": -100.0, "MaxPosition": 1000.0},
    "PositionControl": {"Kv": 40.0},
}


@dataclass
class StepRecord:
    label: str
    instruction: str
    start: float
    end: float | None = None
    result: str = ""


@dataclass
class Demo:
    ctl: Controller
    records: list[StepRecord] = field(default_factory=list)
    instructions: dict = field(default_factory=dict)


def build() -> Demo:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", AXIS_PARAMS)
    fb = {
        "power": MC_Power(Axis=axis, StopMode=0),
        "reset": MC_Reset(Axis=axis),
        "home": MC_Home(Axis=axis),
        "move_abs": MC_MoveAbsolute(Axis=axis),
        "move_abs2": MC_MoveAbsolute(Axis=axis),
        "move_rel": MC_MoveRelative(Axis=axis),
        "velocity": MC_MoveVelocity(Axis=axis),
        "halt": MC_Halt(Axis=axis),
        "jog": MC_MoveJog(Axis=axis),
    }
    demo = Demo(ctl, instructions=fb)

    def outcome(inst) -> str | None:
        if getattr(inst, "Error", False):
            return f"Error 16#{inst.ErrorID:04X}/16#{inst.ErrorInfo:04X} ({describe(inst.ErrorID, inst.ErrorInfo)})"
        if getattr(inst, "CommandAborted", False):
            return "CommandAborted"
        if getattr(inst, "Done", False):
            return "Done"
        return None

    def run_step(label: str, name: str, until: Callable[[], bool] | None = None, **inputs) -> Iterator[None]:
        """Start instruction ``name`` with a rising Execute edge and wait for its end (or ``until``)."""
        inst = fb[name]
        rec = StepRecord(label, type(inst).__name__, ctl.time)
        demo.records.append(rec)
        for key, value in inputs.items():
            setattr(inst, key, value)
        inst.Execute = True
        yield
        while True:
            res = outcome(inst)
            if res is not None or (until is not None and until()):
                rec.end, rec.result = ctl.time, res or rec.result or "running"
                break
            yield
        inst.Execute = False

    def script() -> Iterator[None]:
        # enable the axis and wait for the drive
        rec = StepRecord("enable", "MC_Power", ctl.time)
        demo.records.append(rec)
        fb["power"].Enable = True
        while not fb["power"].Status:
            yield
        rec.end, rec.result = ctl.time, "Status"
        yield from run_step("set reference point (Mode 0)", "home", Mode=0, Position=0.0)
        yield from run_step("absolute move to 300", "move_abs", Position=300.0, Velocity=400.0)
        yield from run_step("relative move -100", "move_rel", Distance=-100.0, Velocity=250.0)
        # a long move overridden by another one after 0.4 s: the first shows CommandAborted
        first = StepRecord("absolute move to 900 (overridden)", "MC_MoveAbsolute", ctl.time)
        demo.records.append(first)
        fb["move_abs"].Position, fb["move_abs"].Velocity, fb["move_abs"].Execute = 900.0, 300.0, True
        t_override = ctl.time + 0.4
        while ctl.time < t_override:
            yield
        yield from run_step("override: absolute move to 50", "move_abs2", Position=50.0, Velocity=450.0)
        first.end, first.result = ctl.time, outcome(fb["move_abs"]) or "CommandAborted"
        fb["move_abs"].Execute = False
        # velocity mode for a while, then halt
        t_vel = ctl.time
        yield from run_step("move at velocity 150", "velocity", until=lambda: ctl.time > t_vel + 1.5,
                            Velocity=150.0)
        yield from run_step("halt", "halt")
        # jog backward for one second
        rec = StepRecord("jog backward", "MC_MoveJog", ctl.time)
        demo.records.append(rec)
        fb["jog"].Velocity, fb["jog"].JogBackward = 100.0, True
        t_jog = ctl.time
        while ctl.time < t_jog + 1.0:
            yield
        fb["jog"].JogBackward = False
        while fb["jog"].Busy:
            yield
        rec.end, rec.result = ctl.time, "stopped (Busy FALSE)"
        # an invalid command: velocity above the configured maximum
        yield from run_step("invalid: Velocity 900 > MaxVelocity", "move_abs", Position=100.0, Velocity=900.0)
        # the last move goes past the high software limit: stopped there, error also at MC_Power
        yield from run_step("move beyond the SW limit 1000", "move_rel", Distance=2000.0, Velocity=450.0)
        yield from run_step("acknowledge (MC_Reset)", "reset")
        yield from run_step("move back into the working range", "move_abs", Position=0.0, Velocity=450.0)
        # disable
        rec = StepRecord("disable", "MC_Power", ctl.time)
        demo.records.append(rec)
        fb["power"].Enable = False
        while fb["power"].Busy:
            yield
        rec.end, rec.result = ctl.time, "Status FALSE"
        while True:
            yield

    gen = script()

    @ctl.program
    def main() -> None:
        for inst in fb.values():
            inst()
        next(gen)

    return demo


def summary(demo: Demo) -> str:
    """A text table of the demo's steps."""
    rows = [("step", "instruction", "start [s]", "end [s]", "result")]
    for r in demo.records:
        rows.append((r.label, r.instruction, f"{r.start:.3f}", "" if r.end is None else f"{r.end:.3f}", r.result))
    widths = [max(len(row[i]) for row in rows) for i in range(5)]
    lines = []
    for k, row in enumerate(rows):
        lines.append("  ".join(cell.ljust(widths[i]) for i, cell in enumerate(row)).rstrip())
        if k == 0:
            lines.append("  ".join("-" * w for w in widths))
    return "\n".join(lines)


def finished(demo: Demo) -> bool:
    return bool(demo.records) and demo.records[-1].label == "disable" and demo.records[-1].end is not None
