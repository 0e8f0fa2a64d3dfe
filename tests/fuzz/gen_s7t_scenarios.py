"""Situations of S7-Technology V4.1 part 1 that random input changes rarely meet, made likely (each with its
own instances, so that the random input changes of the episode may still interfere):

* homing with every MC_Home mode (§6.2.2) on an axis whose plant has the reference cam / zero marks near
  the start, held long enough to finish, sometimes aborted by a motion or MC_Stop;
* MC_ChangeDataset (§6.2.5) while a positioning runs;
* a hydraulic axis (§3.1.4, §4.6): MC_SetCharacteristic with one of its valve profiles during a motion,
  MC_Power StopMode 3 (OFF2 with QOutputValue) while it moves;
* MC_MoveToEndPos (§6.2.11) towards the fixed end stop, then a motion away, a reversing MC_MoveToEndPos,
  MC_Stop or a disable; MC_SetTorqueLimit (§6.2.12) around it;
* MC_ActivateTO (§6.7.2) deactivating a moving axis, and deactivating / activating a disabled one with
  commands in between;
* MC_WriteParameter (§6.7.5) of a random parameter while the axis moves, then MC_Reset with Restart;
* MC_ActivateDPSlave (§6.7.3) deactivating the drive of a moving axis, a record read meanwhile.
"""
from __future__ import annotations

import random
from typing import Any

from .values import Ref


def _add(ep: Any, gen: Any, name: str, cls: str, axis: Any, p: float = 0.6, **init: Any) -> dict[str, Any]:
    from .gen_s7t import CATALOG, _fill     # gen_s7t imports this module: a late import
    fb = {"name": name, "cls": cls, "init": dict(init)}
    if "Axis" in CATALOG[cls]:
        fb["init"]["Axis"] = axis
    _fill(gen, fb, p)
    fb["init"].update(init)
    ep.fbs.append(fb)
    return fb


def _pulse(ep: Any, Op: Any, c: int, name: str, hold: int, inp: str = "Execute") -> None:
    last = ep.cycles - 1
    ep.ops += [Op(min(last, c), "in", name, inp, True), Op(min(last, c + hold), "in", name, inp, False)]


def _real(gen: Any, pred) -> list[str]:
    return [a["name"] for a in gen.ep.axes if not a["params"]["Wizard.Virtual"] and pred(a["params"])]


def scenarios_part1(rnd: random.Random, ep: Any, gen: Any, Op: Any) -> None:
    homing = _real(gen, lambda p: "Plant.HomingSwitchPosition" in p)
    if homing and rnd.random() < 0.5:
        name = rnd.choice(homing)
        mode = rnd.choice((0, 0, 1, 1, 2, 2, 3, 4, 5, 6, 7, 8))
        ep.cycles = max(ep.cycles, rnd.randint(150, 400))     # time to find the cam and the zero mark
        _add(ep, gen, "homer", "MC_Home", Ref(name), Mode=mode)
        c = rnd.randint(2, 20)
        _pulse(ep, Op, c, "homer", rnd.choice((1, 50, 400)))
        if mode == 2:                                          # passive: a motion over the cam and back
            _add(ep, gen, "passing", "MC_MoveVelocity", Ref(name), Mode=0)
            _pulse(ep, Op, c + rnd.randint(0, 10), "passing", 1)
        if rnd.random() < 0.3:                                 # aborted by a motion, MC_Stop or another homing
            cls = rnd.choice(("MC_MoveRelative", "MC_Stop", "MC_Home", "MC_Halt"))
            _add(ep, gen, "interrupt", cls, Ref(name))
            _pulse(ep, Op, c + rnd.randint(5, 100), "interrupt", rnd.randint(1, 30))
    sets = _real(gen, lambda p: p.get("TypeOfAxis.NumberOfDataSets.numberOfDataSets", 1) > 1)
    if sets and rnd.random() < 0.5:
        name = rnd.choice(sets)
        n = next(a for a in ep.axes if a["name"] == name)["params"]["TypeOfAxis.NumberOfDataSets.numberOfDataSets"]
        _add(ep, gen, "mover", rnd.choice(("MC_MoveRelative", "MC_MoveVelocity")), Ref(name), 0.4)
        _add(ep, gen, "dataset", "MC_ChangeDataset", Ref(name), 0.0, Dataset=rnd.randint(1, n))
        c = rnd.randint(1, 20)
        _pulse(ep, Op, c, "mover", rnd.randint(1, 60))
        _pulse(ep, Op, c + rnd.randint(0, 30), "dataset", rnd.randint(1, 60))
    hydraulic = _real(gen, lambda p: p.get("Wizard.DriveTechnology", 0) != 0)
    if hydraulic and rnd.random() < 0.6:
        name = rnd.choice(hydraulic)
        params = next(a for a in ep.axes if a["name"] == name)["params"]
        profiles = [params[k] for k in ("Drive.ValveProfile1", "Drive.ValveProfile2") if k in params]
        _add(ep, gen, "hmove", rnd.choice(("MC_MoveRelative", "MC_MoveVelocity", "MC_MoveAbsolute")), Ref(name), 0.5)
        c = rnd.randint(1, 20)
        _pulse(ep, Op, c, "hmove", rnd.randint(1, 100))
        if profiles or rnd.random() < 0.3:
            cam = rnd.choice(profiles) if profiles else gen.value({"init": {}}, "CamTable", "cam")
            _add(ep, gen, "charact", "MC_SetCharacteristic", Ref(name), 0.0, CamTable=cam, Mode=0)
            _pulse(ep, Op, c + rnd.randint(0, 40), "charact", 1)
        if rnd.random() < 0.4:
            ep.ops += [Op(min(ep.cycles - 1, c + rnd.randint(5, 60)), "in", f"power_{name}", "StopMode", 3),
                       Op(min(ep.cycles - 1, c + rnd.randint(5, 60)), "in", f"power_{name}", "Enable", False)]
    stops = _real(gen, lambda p: "TypeOfAxis.NumberOfDataSets.DataSet_1.ClampingMonitoring.recognitionMode" in p
                  and p["Wizard.Technology"] != 0)
    if stops and rnd.random() < 0.6:
        name = rnd.choice(stops)
        ep.cycles = max(ep.cycles, rnd.randint(100, 300))
        params = next(a for a in ep.axes if a["name"] == name)["params"]
        torque = params.get("TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque", 3.2) * rnd.uniform(0.05, 1.1)
        _add(ep, gen, "endpos", "MC_MoveToEndPos", Ref(name), 0.3, Direction=rnd.choice((0, 1, 1, 3)),
             Velocity=round(gen.vmax[name] * rnd.uniform(0.1, 0.5), 2), Torque=round(torque, 3))
        power = next(f for f in ep.fbs if f["name"] == f"power_{name}")
        power["init"].update(Enable=True, Mode=0)         # enabled position-controlled (§6.2.11)
        c = rnd.randint(1, 20)
        ep.ops += [Op(c - 1, "in", power["name"], "Enable", True), Op(c - 1, "in", power["name"], "Mode", 0)]
        _pulse(ep, Op, c, "endpos", rnd.randint(1, 200))
        if rnd.random() < 0.6:
            cls = rnd.choice(("MC_MoveRelative", "MC_MoveVelocity", "MC_MoveToEndPos", "MC_Stop", "MC_Halt",
                              "MC_SetTorqueLimit", "MC_MoveAbsolute"))
            _add(ep, gen, "release", cls, Ref(name))
            _pulse(ep, Op, c + rnd.randint(20, 250), "release", rnd.randint(1, 30))
        if rnd.random() < 0.2:
            ep.ops.append(Op(min(ep.cycles - 1, c + rnd.randint(20, 250)), "in", f"power_{name}", "Enable", False))
    if rnd.random() < 0.35:
        name = rnd.choice(gen.names)
        _add(ep, gen, "activator", "MC_ActivateTO", Ref(name), 0.0, Mode=2)
        c = rnd.randint(1, 40)
        if rnd.random() < 0.5:                                 # deactivate a moving axis (refused: 8045)
            _add(ep, gen, "amove", rnd.choice(("MC_MoveVelocity", "MC_MoveRelative")), Ref(name), 0.5)
            _pulse(ep, Op, c, "amove", 2)
            _pulse(ep, Op, c + rnd.randint(1, 10), "activator", 2)
        else:                                                  # disable, deactivate, command, activate, enable
            last = ep.cycles - 1
            d = c + rnd.randint(2, 40)
            ep.ops += [Op(min(last, c), "in", f"power_{name}", "Enable", False),
                       Op(min(last, d), "in", "activator", "Execute", True),
                       Op(min(last, d + rnd.randint(1, 20)), "in", "activator", "Execute", False),
                       Op(min(last, d + rnd.randint(1, 20)), "in", f"power_{name}", "Enable", True),
                       Op(min(last, d + rnd.randint(10, 40)), "in", "activator", "Mode", 1),
                       Op(min(last, d + rnd.randint(41, 60)), "in", "activator", "Execute", True)]
    if rnd.random() < 0.35:
        name = rnd.choice(gen.names)
        _add(ep, gen, "wmove", rnd.choice(("MC_MoveVelocity", "MC_MoveRelative", "MC_MoveAbsolute")), Ref(name), 0.5)
        _add(ep, gen, "writer", "MC_WriteParameter", Ref(name), 1.0)
        c = rnd.randint(1, 30)
        _pulse(ep, Op, c, "wmove", rnd.randint(1, 40))
        _pulse(ep, Op, c + rnd.randint(0, 30), "writer", 1)
        if rnd.random() < 0.5:
            _add(ep, gen, "restarter", "MC_Reset", Ref(name), 0.0, Restart=True)
            d = c + rnd.randint(10, 80)
            ep.ops.append(Op(min(ep.cycles - 1, d), "in", f"power_{name}", "Enable", False))
            _pulse(ep, Op, d + rnd.randint(1, 20), "restarter", rnd.randint(1, 20))
            ep.ops.append(Op(min(ep.cycles - 1, d + rnd.randint(20, 60)), "in", f"power_{name}", "Enable", True))
    if gen.slaves and rnd.random() < 0.3:
        name = rnd.choice(_real(gen, lambda p: not p.get("Wizard.DriveTechnology")))
        _add(ep, gen, "dpslave", "MC_ActivateDPSlave", None, 0.0, Mode=2,
             DiagnosticAddress=1023 - rnd.randrange(gen.slaves))
        _add(ep, gen, "dpmove", "MC_MoveVelocity", Ref(name), 0.5)
        _add(ep, gen, "dpread", "MC_ReadRecord", None, 0.3, RecordNumber=47)
        c = rnd.randint(1, 30)
        _pulse(ep, Op, c, "dpmove", 2)
        _pulse(ep, Op, c + rnd.randint(1, 20), "dpslave", 2)
        _pulse(ep, Op, c + rnd.randint(1, 30), "dpread", rnd.randint(1, 10))
        ep.ops += [Op(min(ep.cycles - 1, c + rnd.randint(30, 80)), "in", "dpslave", "Mode", 1),
                   Op(min(ep.cycles - 1, c + rnd.randint(81, 100)), "in", "dpslave", "Execute", True)]


__all__ = ["scenarios_part1"]
