"""The invariants of the S7-Technology FBs and objects of part 1 beyond those every instruction has (see
``tests/fuzz/__init__.py``, invariants 11-17).  The runner calls :meth:`S7TOracle.edge` at every rising Execute,
:meth:`S7TOracle.outputs` after every FB call and :meth:`S7TOracle.cycle` after every application cycle; each
returns the violations as (kind, where, message, key) tuples.
"""
from __future__ import annotations

import math
from typing import Any, Iterator

from plcmotion.s7t.technology import activation as A
from plcmotion.s7t.technology import datasets as D
from plcmotion.s7t.technology.hydraulic_params import OUTPUT_MAX, OUTPUT_MIN

Violation = tuple[str, str, str, tuple]
#: FBs that never wait for an axis: Busy longer than this (virtual time) is "stuck" (§6.7: the basic
#: functions complete within a few command slices; the data set change and the homing may wait)
SERVICE_SECONDS = 2.5
SERVICE_FBS = frozenset({"MC_ReadSysParameter", "MC_WriteParameter", "MC_WritePeriphery", "MC_ReadRecord",
                         "MC_WriteRecord", "MC_ReadDriveParameter", "MC_WriteDriveParameter", "MC_ActivateTO",
                         "MC_ActivateDPSlave", "MC_SetCharacteristic", "MC_SetTorqueLimit"})
#: MC_Home modes after whose Done the axis is homed (§6.2.2: 0-3 and 5 home, 4/6/7 keep the state, 8 cancels)
HOMING_MODES = frozenset({0, 1, 2, 3, 5})
#: Status values of MC_ActivateTO (§6.7.2: 1 activated, 2 deactivated, 3 being activated, 4 being
#: deactivated) and MC_ActivateDPSlave (§6.7.3: 1, 2, 3, 4 and 5 not connected); 0 before the first Done
TO_STATUS = frozenset({0, 1, 2, 3, 4})
DP_STATUS = frozenset({0, 1, 2, 3, 4, 5})
#: one count of the S7 analog output word (27648 = 100 %)
_COUNT = 100.0 / 27648
_AREA_FBS = ("MC_ReadRecord", "MC_ReadDriveParameter")


class S7TOracle:
    def __init__(self, run: Any):
        self.run = run
        self.started: dict[str, dict[str, Any]] = {}      # inputs taken at the last rising Execute
        self.prev_done: dict[str, bool] = {}
        self.busy: dict[str, int] = {}                    # service FBs: application cycles Busy in a row

    def edge(self, name: str, cls: str, fb: Any) -> None:
        d = fb.__dict__
        axis = d.get("Axis")
        axis = self.run._by_db.get(axis, axis) if type(axis) is int else axis
        self.started[name] = {"Mode": d.get("Mode"), "Dataset": d.get("Dataset"),
                              "axis": axis if any(axis is a for a in self.run.axes) else None}

    def outputs(self, name: str, cls: str, fb: Any, out: dict) -> Iterator[Violation]:
        busy, error = out.get("Busy"), out.get("Error")
        if cls == "MC_ReadPeriphery" and out.get("DataValid") and (not busy or error):
            yield ("exclusive", name, f"{cls} DataValid without Busy or with Error", (cls, "DataValid"))
        if cls == "MC_MoveToEndPos" and out.get("InClamping") and (not busy or error or out.get("CommandAborted")):
            yield ("exclusive", name, f"{cls} InClamping without Busy or with Error/CommandAborted",
                   (cls, "InClamping"))
        if cls == "MC_ReadSysParameter" and not math.isfinite(_float(out.get("Value", 0.0))):
            yield ("nonfinite", name, f"{cls}.Value = {out.get('Value')!r}", (cls, "Value"))
        status = out.get("Status")
        if status is not None and status not in (TO_STATUS if cls == "MC_ActivateTO" else DP_STATUS):
            yield ("errorid", name, f"{cls}.Status = {status!r} is no Status of the manual", (cls, "Status"))
        if cls in _AREA_FBS and out.get("Done"):
            data = fb.__dict__.get("Data")
            if not isinstance(data, bytearray) or out.get("DataLength", 0) > len(data):
                yield ("errorid", name, f"{cls} Done with DataLength {out.get('DataLength')} for a Data area of "
                       f"{len(data) if isinstance(data, (bytes, bytearray)) else data!r}", (cls, "DataLength"))
        done = bool(out.get("Done"))
        if done and not self.prev_done.get(name):
            yield from self._done(name, cls)
        self.prev_done[name] = done
        if cls in SERVICE_FBS:
            n = self.busy[name] = self.busy.get(name, 0) + 1 if busy else 0
            if n * self.run.ctl.app_cycle > SERVICE_SECONDS:
                yield ("stuck", name, f"{cls} Busy for {SERVICE_SECONDS} s", (cls,))

    def _done(self, name: str, cls: str) -> Iterator[Violation]:
        started = self.started.get(name, {})
        axis = started.get("axis")
        if axis is None:
            return
        if cls == "MC_ChangeDataset" and isinstance(started.get("Dataset"), int):
            now = D.active(axis.eff)
            if now != started["Dataset"]:
                yield ("dataset", name, f"MC_ChangeDataset Done with data set {now} in force, not "
                       f"{started['Dataset']} (§6.2.5)", (cls,))
        if cls == "MC_Home" and started.get("Mode") in HOMING_MODES and not axis.homed:
            yield ("homing", name, f"MC_Home Mode {started['Mode']} Done but the axis is not homed (§6.2.2)",
                   (cls, started["Mode"]))

    def cycle(self) -> Iterator[Violation]:
        for ax in self.run.axes:
            if A.state(ax) == A.DEACTIVATED:
                b = self.run.ctl.bank
                if ax.state != "disabled" or b.sp_v[ax.index] != 0.0:
                    yield ("activation", ax.name, f"deactivated {ax.name} is {ax.state} with setpoint velocity "
                           f"{b.sp_v[ax.index]!r} (§6.7.2)", ("deactivated",))
            if ax.hydraulic:
                drive = ax.drive
                u, force = drive.output_percent, drive.force
                lo, hi = ax.eff.get(OUTPUT_MIN, -100.0), ax.eff.get(OUTPUT_MAX, 100.0)
                if not (math.isfinite(u) and math.isfinite(force)):
                    yield ("nonfinite", ax.name, f"hydraulic output {u!r} %, force {force!r} N", ("hydraulic",))
                elif not lo - _COUNT <= u <= hi + _COUNT:      # the output word rounds to a count
                    yield ("hydraulic", ax.name, f"valve output {u:.6g} % outside the manipulated variable limits "
                           f"[{lo:g}, {hi:g}] (§4.6, parameters 1401/1402)", ("output",))


def _float(x: Any) -> float:
    try:
        return float(x)
    except (TypeError, ValueError, OverflowError):
        return math.nan


__all__ = ["S7TOracle", "SERVICE_FBS"]
