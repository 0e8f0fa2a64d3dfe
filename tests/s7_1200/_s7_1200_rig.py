"""Test rig for the S7-1200 V6 status/override tests (tests/s7_1200/test_s7_1200_*.py).

A PLC-like harness: every *scan* calls each registered instruction instance exactly once (the way a
cyclic OB calls its FBs) and then advances the controller by one application cycle.  Inputs are changed
by assigning instance attributes before a scan (``rig.move.Execute = False``), so that "one call" of the
manual (§9.5.2 "for only one execution cycle") is exactly one scan.

Each scan returns a :class:`Snap`: the axis setpoint state *at the moment of the calls* and the outputs of
every instance right after its call.  ``scan`` also checks the generic invariants of §9.5.2-§9.5.4 on
every call: Done, CommandAborted and Error are mutually exclusive and never TRUE together with Busy.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative,
                               MC_MoveVelocity, MC_Power, MC_Reset)

APP = 0.004        # application cycle [s]
SERVO = 0.001      # servo cycle [s]

__all__ = ["Rig", "Snap", "MC_Halt", "MC_Home", "MC_MoveAbsolute", "MC_MoveJog", "MC_MoveRelative",
           "MC_MoveVelocity", "MC_Power", "MC_Reset", "APP", "SERVO", "axis_params", "calls_with",
           "contiguous_to_end"]


def _merge(base: dict, extra: dict) -> dict:
    out = dict(base)
    for k, v in extra.items():
        if isinstance(v, dict) and isinstance(out.get(k), dict):
            out[k] = _merge(out[k], v)
        else:
            out[k] = v
    return out


def axis_params(actor: int = 2, *, max_v: float = 100.0, min_v: float | None = None, acc: float = 100.0,
                dec: float = 100.0, emergency: float = 1000.0, jerk: float = 0.0,
                sw: tuple[float, float] | None = None, extra: dict | None = None) -> dict:
    """Configuration of Axis_1 (tag paths of §12.9).  PTO (actor 2) by default; start/stop velocity 1.0 for
    PTO and 0.0 for PROFIdrive/analog (§5.4.4.4: fixed at 0 for position-controlled drives)."""
    if min_v is None:
        min_v = 1.0 if actor == 2 else 0.0
    params: dict[str, Any] = {
        "Actor": {"Type": actor},
        "DynamicLimits": {"MaxVelocity": max_v, "MinVelocity": min_v},
        "DynamicDefaults": {"Acceleration": acc, "Deceleration": dec, "EmergencyDeceleration": emergency,
                            "Jerk": jerk},
        "PositionLimits_SW": {"Active": sw is not None},
    }
    if sw is not None:
        params["PositionLimits_SW"].update({"MinPosition": sw[0], "MaxPosition": sw[1]})
    return _merge(params, extra or {})


@dataclass
class Snap:
    """What the user program sees in one cycle."""
    n: int                     # scan number (1-based)
    t: float                   # virtual time of the calls
    pos: float                 # <TO>.Position (setpoint) at the calls
    vel: float                 # <TO>.Velocity (setpoint) at the calls
    out: dict[str, dict[str, Any]] = field(default_factory=dict)
    inp: dict[str, dict[str, Any]] = field(default_factory=dict)

    def __getitem__(self, name: str) -> dict[str, Any]:
        return self.out[name]


_TRACKED_INPUTS = ("Execute", "Enable", "JogForward", "JogBackward")


class Rig:
    """One controller, one axis ``Axis_1``, one MC_Power instance ``power`` and named instances."""

    def __init__(self, actor: int = 2, *, enable: bool = True, **kw: Any):
        self.ctl = Controller(servo_cycle=SERVO, app_cycle=APP)
        self.axis = self.ctl.add_positioning_axis("Axis_1", axis_params(actor, **kw))
        self.fbs: dict[str, Any] = {}
        self.history: list[Snap] = []
        self.add("power", MC_Power(Axis=self.axis, Enable=False))
        if enable:
            self.power.Enable = True
            self.scan_until(lambda s: s["power"]["Status"], 100, "axis enabled (MC_Power.Status)")

    # --- instances ---------------------------------------------------------------------------------------
    def add(self, name: str, fb: Any, **inputs: Any) -> Any:
        """Register an instance (called once per scan from now on); ``inputs`` are assigned, not evaluated."""
        if getattr(fb, "Axis", None) is None:
            fb.Axis = self.axis
        for k, v in inputs.items():
            setattr(fb, k, v)
        self.fbs[name] = fb
        return fb

    def __getattr__(self, name: str) -> Any:
        fbs = self.__dict__.get("fbs", {})
        if name in fbs:
            return fbs[name]
        raise AttributeError(name)

    # --- cycles ------------------------------------------------------------------------------------------
    def scan(self) -> Snap:
        """Call every instance once (registration order), then one application cycle of the controller."""
        ax = self.axis
        snap = Snap(len(self.history) + 1, self.ctl.time, ax.Position, ax.Velocity)
        for name, fb in self.fbs.items():
            fb()
            snap.out[name] = dict(fb.outputs)
            snap.inp[name] = {k: getattr(fb, k) for k in _TRACKED_INPUTS if hasattr(fb, k)}
            _check_exclusive(name, snap)
        self.ctl.step()
        self.history.append(snap)
        return snap

    def scans(self, n: int) -> list[Snap]:
        return [self.scan() for _ in range(n)]

    def scan_until(self, pred: Callable[[Snap], bool], max_scans: int, what: str = "condition") -> Snap:
        """Scan until ``pred(snap)``; the snap that satisfied it is returned (fails after ``max_scans``)."""
        for _ in range(max_scans):
            snap = self.scan()
            if pred(snap):
                return snap
        raise AssertionError(f"{what} not reached within {max_scans} scans "
                             f"(t = {self.ctl.time:.3f} s, last outputs: {self.history[-1].out})")

    def run_scans_while(self, pred: Callable[[Snap], bool], max_scans: int) -> list[Snap]:
        """Scan while ``pred`` holds; returns all snaps including the first one where it no longer holds."""
        out = []
        for _ in range(max_scans):
            snap = self.scan()
            out.append(snap)
            if not pred(snap):
                return out
        raise AssertionError(f"condition still true after {max_scans} scans")

    # --- common set-ups ----------------------------------------------------------------------------------
    def home(self, position: float = 0.0, mode: int = 0, name: str = "home") -> Any:
        """MC_Home Mode 0/1 with a one-scan Execute pulse; returns the instance."""
        fb = self.fbs.get(name) or self.add(name, MC_Home())
        fb.Mode, fb.Position, fb.Execute = mode, position, True
        self.scan()
        fb.Execute = False
        self.scan()
        assert self.axis.StatusBits.HomingDone, "set-up: MC_Home Mode 0/1 did not home the axis"
        return fb


def _check_exclusive(name: str, snap: Snap) -> None:
    """§9.5.2-§9.5.4: exactly one of Done/CommandAborted/Error at the end, Busy FALSE with any of them."""
    o = snap.out[name]
    finals = [k for k in ("Done", "CommandAborted", "Error") if o.get(k)]
    if "Done" not in o and "CommandAborted" not in o:
        return                                                     # MC_Power: Error with Busy allowed
    assert len(finals) <= 1, f"scan {snap.n}: {name} shows {finals} at once (§9.5.2: exactly one)"
    if finals:
        assert not o["Busy"], f"scan {snap.n}: {name} Busy TRUE together with {finals[0]} (§9.5.2)"


def calls_with(snaps: list[Snap], name: str, output: str) -> list[int]:
    """0-based positions in ``snaps`` of the calls where ``name.output`` is TRUE."""
    return [i for i, s in enumerate(snaps) if s.out[name][output]]


def contiguous_to_end(idx: list[int], n: int) -> bool:
    """``idx`` is a non-empty run ending at the last of ``n`` calls."""
    return bool(idx) and idx == list(range(idx[0], n))
