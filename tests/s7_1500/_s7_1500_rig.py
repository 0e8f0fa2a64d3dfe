"""Test rig for the S7-1500 synchronous operation tests: a controller with leading and following axes,
their MC_Power instances and a program that calls a list of steps every application cycle."""
from __future__ import annotations

from typing import Any, Callable

from plcmotion import Controller
from plcmotion.s7_1500 import MC_Power

VIRTUAL = {"VirtualAxis": {"Mode": 1}}
ROTARY = {"Properties": {"MotionType": 1}, "Units": {"LengthUnit": 1005, "VelocityUnit": 1521}}


def modulo(length: float = 360.0) -> dict:
    return {"Modulo": {"Enable": True, "Length": length, "StartValue": 0.0}}


def merge(*dicts: dict) -> dict:
    out: dict = {}
    for d in dicts:
        for k, v in d.items():
            if isinstance(v, dict) and isinstance(out.get(k), dict):
                out[k] = merge(out[k], v)
            else:
                out[k] = v
    return out


class Rig:
    """``Rig(masters=1, slaves=1)``: axes Master1.., Slave1.. (virtual unless params say otherwise),
    each enabled by its own MC_Power; every slave may follow every master."""

    def __init__(self, masters: int = 1, slaves: int = 1, *, master_params: dict | None = None,
                 slave_params: dict | None = None, family: str = "S7-1500T", servo_cycle: float = 0.001,
                 app_cycle: float = 0.004, coupling: str = "setpoint"):
        self.ctl = Controller(servo_cycle=servo_cycle, app_cycle=app_cycle, family=family)
        mp = master_params if master_params is not None else VIRTUAL
        sp = slave_params if slave_params is not None else VIRTUAL
        self.masters = [self.ctl.add_positioning_axis(f"Master{i + 1}", mp) for i in range(masters)]
        names = [(m.name, coupling) for m in self.masters]
        self.slaves = [self.ctl.add_synchronous_axis(f"Slave{i + 1}", sp, leading_values=names)
                       for i in range(slaves)]
        self.powers = {ax.name: MC_Power() for ax in self.masters + self.slaves}
        self.enable = {ax.name: True for ax in self.masters + self.slaves}
        self.steps: list[Callable[[], Any]] = []
        self.log: list[dict] = []
        self.record: Callable[[], dict] | None = None

        @self.ctl.program
        def main() -> None:
            for ax in self.masters + self.slaves:
                self.powers[ax.name](Axis=ax, Enable=self.enable[ax.name])
            for step in self.steps:
                step()
            if self.record is not None:
                self.log.append(self.record())

    @property
    def master(self):
        return self.masters[0]

    @property
    def slave(self):
        return self.slaves[0]

    def enabled(self) -> bool:
        return all(p.Status for p in self.powers.values())

    def run_until(self, cond: Callable[[], bool], timeout: float = 10.0) -> float:
        return self.ctl.run_until(cond, timeout=timeout)

    def run(self, seconds: float) -> None:
        self.ctl.run(seconds)

    def first(self, key: str, value: Any = True) -> dict | None:
        """The first logged row where ``key`` has ``value``."""
        return next((r for r in self.log if r.get(key) == value), None)


class Feed:
    """A leading value source the test fills (a stand-in for a cross-PLC transport): ``fetch`` hands over
    what the test queued since the last call."""

    def __init__(self):
        self.queue = []

    def fetch(self, needed):
        out, self.queue = self.queue, []
        return out
