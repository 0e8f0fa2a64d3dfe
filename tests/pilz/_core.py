"""Helpers of the Pilz tests: a controller whose application cycle equals the motion-core cycle A150 (1 ms),
a referenced drive axis, and a recorder of the status words of every motion-core cycle."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import plcmotion  # noqa: F401 - registers the families
from plcmotion import Controller

A150 = 0.001
PROFILE = {"I404": 200.0, "I405": 2000.0, "I406": 2000.0, "I407": 100000.0}
FIELDS = ("I82", "I83", "I85", "I86", "I89", "I90", "I91", "I92", "I180", "I183", "I190", "I191", "I192", "I193",
          "I194", "I195", "I199", "I88", "I96", "E07")


@dataclass
class Row:
    t: float
    p: float            # actual position
    values: dict[str, Any]

    def __getattr__(self, name: str) -> Any:
        try:
            return self.values[name]
        except KeyError:
            raise AttributeError(name) from None


def make_axis(params: dict[str, Any] | None = None, *, referenced: bool = True, app_cycle: float = A150):
    # the drive reads its switch inputs unfiltered (the CPU input filter of the S7 families does not apply)
    ctl = Controller(family="Pilz", servo_cycle=A150, app_cycle=app_cycle, input_filter=0.0)
    ax = ctl.add_positioning_axis("X", {"I30": 5, **(params or {})})
    ax.enable()
    ctl.run(0.005)
    rows: list[Row] = []

    def record(t: float) -> None:
        s = ax.status
        rows.append(Row(round(t, 6), float(ctl.bank.act_p[ax.index]), {f: getattr(s, f) for f in FIELDS}))

    ctl.on_post_servo(record)
    ax.rows = rows
    if referenced:
        start(ax, 6)
        ctl.run(0.003)
        release(ax)
        assert ax.status.I86
    return ctl, ax


def start(ax: Any, command: int, *base: dict[str, Any], **registers: Any) -> float:
    """Write ``base`` (dicts) and ``registers`` (the later win), select ``command`` and give Execute a rising
    edge (low for a cycle first if it is high); returns the time of the motion-core cycle that sees the edge."""
    ctl = ax.ctl
    regs = ax.registers
    if regs.I402:
        regs.I402 = False
        ctl.step()
    merged: dict[str, Any] = {}
    for d in base:
        merged.update(d)
    merged.update(registers)
    for name, value in merged.items():
        regs.write(name, value)
    regs.I401 = command
    regs.I402 = True
    ctl.step()
    return ctl.time


def release(ax: Any) -> None:
    ax.registers.I402 = False
    ax.ctl.step()


def rows_from(ax: Any, t: float) -> list[Row]:
    return [r for r in ax.rows if r.t >= t - 1e-9]
