"""Random episodes of the dialect "S7-Technology" (S7-Technology V4.1, CPU 31xT): 1-4 axes of the family
(speed-controlled, positioning, synchronization; real or virtual; modulo; software limit switches on/off;
"Homing required" YES/NO) and the single-axis instructions FB 401-414 of ``plcmotion.s7t``.

Only drawn when the dialect is asked for (``generate(seed, "S7-Technology")``, ``--dialect``): the seeded
draw of the other dialects (``gen.DIALECTS``) is unchanged, so old seeds give the same episodes.

Beyond the random input changes of every dialect the episodes make a few situations likely: rapid
Execute toggling, MC_Power toggling, MC_Stop held for a while, MC_Reset with and without Restart (after a
disable), appended (Mode 1) and overlaid (Mode 2) commands started in the cycles after a positioning, and
``Axis`` given as a technology DB number (valid, the MCDevice DB, or no DB at all).
"""
from __future__ import annotations

import math
import random
from typing import Any

from . import gen_s7t_objects as O
from . import gen_s7t_values as PV
from . import values as V
from .values import Ref

S7T = "S7-Technology"
MCDEVICE_DB = 1

_DYN = {"Acceleration": "acc", "Deceleration": "acc", "Jerk": "jerk"}
_FLAG = ("int", tuple(range(0, 33)))
CATALOG: dict[str, dict[str, Any]] = {
    # Mode 4 (simulation) runs on real axes and is refused (8043) by virtual ones; StopMode 3 only by hydraulic axes
    "MC_Power": {"Axis": "axis", "Enable": "bool", "Mode": ("int", (0, 0, 0, 1, 2, 3, 4, 5)),
                 "StopMode": ("int", (0, 1, 2, 3, 4, 5, 6)), "QOutputValue": "pct"},
    "MC_Reset": {"Axis": "any_to", "Execute": "bool", "Restart": "bool"},
    "MC_Stop": {"Axis": "axis", "Execute": "bool", "Deceleration": "acc", "Jerk": "jerk", "DoneFlag": _FLAG},
    "MC_Halt": {"Axis": "axis", "Execute": "bool", "Deceleration": "acc", "Jerk": "jerk", "DoneFlag": _FLAG},
    "MC_MoveAbsolute": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Velocity": "vel", **_DYN,
                        "Direction": ("int", (0, 1, 2, 3, 4)), "Mode": ("int", (0, 1, 2)), "DoneFlag": _FLAG},
    "MC_MoveRelative": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "Velocity": "vel", **_DYN,
                        "Mode": ("int", (0, 1, 2)), "DoneFlag": _FLAG},
    "MC_MoveAdditive": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "Velocity": "vel", **_DYN,
                        "DoneFlag": _FLAG},
    "MC_MoveSuperImposed": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "VelocityDiff": "vel", **_DYN,
                            "DoneFlag": _FLAG},
    # Direction 2 is refused by MC_MoveVelocity (16#8043): drawn on purpose
    "MC_MoveVelocity": {"Axis": "axis", "Execute": "bool", "Velocity": "vel", **_DYN,
                        "Direction": ("int", (0, 1, 2, 3, 4)), "Current": "bool", "PositionControl": "bool",
                        "Mode": ("int", (0, 1)), "DoneFlag": _FLAG},
    # Mode 9 is refused (16#8043); which of 0-8 an axis takes depends on its encoder (§6.2.2 note)
    "MC_Home": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Mode": ("int", tuple(range(10))),
                "DoneFlag": _FLAG},
    "MC_ChangeDataset": {"Axis": "axis", "Execute": "bool", "SyncEncoder": "bool",
                         "Dataset": ("int", (0, 1, 1, 2, 2, 3, 4, 5, 16, 17)), "DoneFlag": _FLAG},
    "MC_MoveToEndPos": {"Axis": "axis", "Execute": "bool", "Direction": ("int", (0, 1, 2, 3, 4)), "Torque": "torque",
                        "Velocity": "vel", **_DYN, "DoneFlag": _FLAG},
    "MC_SetTorqueLimit": {"Axis": "axis", "Execute": "bool", "EnableLimit": "bool", "MaxTorque": "torque",
                          "DoneFlag": _FLAG},
    "MC_SetCharacteristic": {"Axis": "axis", "CamTable": "cam", "Execute": "bool", "Mode": ("int", (0, 0, 0, 1)),
                             "DoneFlag": _FLAG},
    "MC_ReadSysParameter": {"Axis": "any_to", "Execute": "bool", "ParameterNumber": "pnum", "Index": "pidx"},
    "MC_WriteParameter": {"Axis": "any_to", "Execute": "bool", "ParameterNumber": "pnum", "Index": "pidx",
                          "Value": "preal", "ValueDInt": "pdint", "ValueDword1": "dword", "ValueDword2": "dword",
                          "ValueBool": "bool"},
    "MC_ReadPeriphery": {"Enable": "bool", "InputOutput": "bool", "ByteAddress": "byteaddr", "Data": "rdata"},
    "MC_WritePeriphery": {"Execute": "bool", "ByteAddress": "byteaddr", "Data": "wdata", "DoneFlag": _FLAG},
    "MC_ReadRecord": {"Execute": "bool", "InOut": "bool", "Address": "dpaddr", "RecordNumber": "record",
                      "Data": "rdata", "DoneFlag": _FLAG},
    "MC_WriteRecord": {"Execute": "bool", "InOut": "bool", "Address": "dpaddr", "RecordNumber": "record",
                       "Data": "wdata", "DoneFlag": _FLAG},
    "MC_ReadDriveParameter": {"Execute": "bool", "InOut": "bool", "Address": "dpaddr", "ParameterNumber": "dpnum",
                              "SubIndex": "sub", "NumberOfElements": "nelem", "Data": "rdata", "DoneFlag": _FLAG},
    "MC_WriteDriveParameter": {"Execute": "bool", "InOut": "bool", "Address": "dpaddr", "ParameterNumber": "dpnum",
                               "SubIndex": "sub", "NumberOfElements": "nelem", "Data": "wdata", "DoneFlag": _FLAG},
    "MC_ActivateTO": {"Axis": "any_to", "Execute": "bool", "Mode": ("int", (0, 1, 2, 2, 3))},
    "MC_ActivateDPSlave": {"DiagnosticAddress": "diag", "Execute": "bool", "Mode": ("int", (0, 1, 2, 2, 3))},
}
#: how often generate_s7t picks each FB for a random instance (the motions twice as often as the rest)
WEIGHTS = {c: 2 if c in ("MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveSuperImposed",
                         "MC_MoveVelocity") else 1 for c in CATALOG if c != "MC_Power"}
MOVES = ("MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveSuperImposed", "MC_MoveVelocity")
#: the ENUM values of ``userdefaultdynamics.direction`` (§9.4.12 EnumDirection)
_DIRECTIONS = (3, 4, 5, 38, 39)


def _logu(rnd: random.Random, lo: float, hi: float) -> float:
    return math.exp(rnd.uniform(math.log(lo), math.log(hi)))


def axis_s7t(rnd: random.Random, db: int, technology: int) -> dict[str, Any]:
    """Tags of one axis, always within the ranges of §9.4 (a real axis's maximum velocity within what its
    drive reaches: 6000 1/min x 10 mm = 1000 mm/s)."""
    virtual = rnd.random() < 0.4
    vmax = round(_logu(rnd, 5.0, 950.0), 2)
    amax = round(vmax * _logu(rnd, 1.0, 100.0), 1)
    p: dict[str, Any] = {
        "DBNumber": db,
        "Wizard.Technology": technology,
        "Wizard.Virtual": int(virtual),
        "TypeOfAxis.MaxVelocity.maximum": vmax,
        "TypeOfAxis.MaxAcceleration.maximum": amax,
        "TypeOfAxis.MaxJerk.maximum": round(amax * _logu(rnd, 2.0, 500.0), 1),
        "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": round(amax * rnd.uniform(0.5, 3.0), 1),
        "userdefaultdynamics.velocity": round(vmax * rnd.uniform(0.1, 1.0), 2),
        "userdefaultdynamics.positiveaccel": round(amax * rnd.uniform(0.1, 1.0), 2),
        "userdefaultdynamics.negativeaccel": round(amax * rnd.uniform(0.1, 1.0), 2),
        "userdefaultdynamics.positiveaccelstartjerk": 0.0 if rnd.random() < 0.3
        else round(amax * _logu(rnd, 1.0, 200.0), 1),
        "userdefaultdynamics.stoptime": rnd.choice((0.05, 0.2, 1.0, 3.0)),
        "userdefaultdynamics.direction": rnd.choice(_DIRECTIONS),
        "TypeOfAxis.Homing.referencingNecessary": 1 if rnd.random() < 0.3 else 0,
        # generous following error limits: the fuzzer is about the setpoints, not about drive tuning
        "TypeOfAxis.NumberOfDataSets.DataSet_1.DynamicFollowing.maxPositionTolerance": 1.0e6,
    }
    if rnd.random() < 0.25:
        p["override.velocity"] = rnd.choice((0.0, 50.0, 150.0, 200.0))
    if not virtual:
        p["Wizard.Telegram"] = rnd.choice((1, 2, 3, 105)) if technology == 0 else rnd.choice((3, 4, 105))
    if technology != 0 and rnd.random() < 0.2:
        p["Modulo.state"] = 1
        p["Modulo.length"] = rnd.choice((1.0, 360.0, round(_logu(rnd, 0.5, 2000.0), 3)))
        p["Modulo.startValue"] = rnd.choice((0.0, 0.0, -0.5 * p["Modulo.length"]))
    if technology != 0 and rnd.random() < 0.45:
        r = round(_logu(rnd, 20.0, 5000.0), 1)
        p["swlimit.state"] = 1
        p["swlimit.minusposition"] = -r
        p["swlimit.plusposition"] = round(r * rnd.uniform(0.2, 2.0), 1)
    return p


def options_s7t(rnd: random.Random, p: dict[str, Any], k: int, cams: list[int]) -> None:
    """The objects of part 1 beyond the plain axis on axis ``k`` (``gen_s7t_objects``): a hydraulic drive, the
    homing configuration on the simulated plant, data sets, a fixed end stop (electric drives)."""
    if p["Wizard.Virtual"]:
        return
    if p["Wizard.Technology"] != 0 and rnd.random() < 0.3:
        O.hydraulic(rnd, p, cams)
    if p["Wizard.Technology"] != 0 and rnd.random() < 0.7:
        O.homing(rnd, p, k, p["TypeOfAxis.MaxVelocity.maximum"])
    if rnd.random() < 0.4:
        O.data_sets(rnd, p)
    if p.get("Wizard.DriveTechnology", 0) == 0 and rnd.random() < 0.4:
        O.end_stop(rnd, p)
    if "swlimit.state" in p and "Plant.InitialPosition" in p:
        # the SW limits around the start of the cylinder: the axis starts inside them
        x = p["Plant.InitialPosition"]
        p["swlimit.minusposition"] = round(min(p["swlimit.minusposition"] + x, x - 1.0), 1)
        p["swlimit.plusposition"] = round(max(p["swlimit.plusposition"] + x, x + 1.0), 1)


class GenS7T:
    """Draws the input values of one S7-Technology episode."""

    def __init__(self, rnd: random.Random, ep: Any):
        self.rnd = rnd
        self.ep = ep
        self.names = [a["name"] for a in ep.axes]
        self.dbs = {a["name"]: a["params"]["DBNumber"] for a in ep.axes}
        self.vmax = {a["name"]: a["params"]["TypeOfAxis.MaxVelocity.maximum"] for a in ep.axes}
        self.amax = {a["name"]: a["params"]["TypeOfAxis.MaxAcceleration.maximum"] for a in ep.axes}
        self.cams = [(c["name"], c["db"]) for c in ep.cams]
        self.slaves = sum(1 for a in ep.axes if not a["params"]["Wizard.Virtual"]      # DP(DRIVE) slaves
                          and not a["params"].get("Wizard.DriveTechnology"))

    def axis(self, mcdevice: bool = False) -> Any:
        """The Axis input: the technology object mostly, else its DB number, another DB or no DB at all."""
        rnd = self.rnd
        r = rnd.random()
        name = rnd.choice(self.names)
        if r < 0.8:
            return Ref(name)
        if r < 0.92:
            db = self.dbs[name]
            return db - 65536 if db > 32767 else db          # a DB above 32767 given as an INT (§6.9.3)
        if mcdevice and r < 0.95:
            return MCDEVICE_DB
        return rnd.choice((MCDEVICE_DB, 0, 999, -1, 70000, 2 ** 31, None, "DB10", 10.0, True, [1.0]))

    def _scale_axis(self, fb: dict[str, Any]) -> str:
        a = fb["init"].get("Axis")
        if isinstance(a, Ref):
            return a.name
        for name, db in self.dbs.items():
            if a == db:
                return name
        return self.names[0]

    def value(self, fb: dict[str, Any], name: str, kind: Any) -> Any:
        rnd = self.rnd
        ax = self._scale_axis(fb)
        vmax, amax = self.vmax[ax], self.amax[ax]
        if kind == "bool":
            return not bool(fb["init"].get(name, False)) if rnd.random() < 0.9 else bool(rnd.getrandbits(1))
        if isinstance(kind, tuple):
            return V.integer(rnd, kind[1])
        if kind == "axis":
            return self.axis()
        if kind == "any_to":
            return self.axis(mcdevice=True)
        if kind == "pos":
            return V.real(rnd, rnd.choice((1.0, 50.0, 500.0, 5000.0)))
        if kind == "vel":
            if rnd.random() < 0.2:
                return -1.0                                     # the default dynamics (§6.9.3)
            if rnd.random() < 0.03:
                return rnd.choice((1e12, 2e12, 1e11, 9.99e11))  # at and around the REAL range of §6.9.3
            return V.real(rnd, vmax * rnd.choice((0.1, 0.5, 1.0, 3.0)), signed=name == "Velocity")
        if kind == "acc":
            if rnd.random() < 0.4:
                return -1.0
            if rnd.random() < 0.03:
                return rnd.choice((1e12, 2e12, 1e11))
            return V.real(rnd, amax * rnd.choice((0.1, 1.0, 3.0)), signed=False)
        if kind == "jerk":
            if rnd.random() < 0.4:
                return -1.0
            return V.real(rnd, amax * rnd.choice((0.0, 10.0, 100.0)), signed=False)
        if kind == "pct":
            return V.real(rnd, 100.0, garbage=0.2)
        return self._basic(fb, kind)

    def _basic(self, fb: dict[str, Any], kind: str) -> Any:
        """The inputs of the §6.7 basic functions, MC_SetCharacteristic and the torque FBs."""
        rnd = self.rnd
        number = fb["init"].get("ParameterNumber")
        draw = {"pnum": PV.parameter_number, "pidx": PV.parameter_index, "dword": PV.dword,
                "byteaddr": PV.byte_address, "rdata": PV.read_area, "wdata": PV.write_area,
                "record": PV.record_number, "dpnum": PV.drive_parameter, "sub": PV.sub_index,
                "nelem": PV.elements, "torque": PV.torque}.get(kind)
        if draw is not None:
            return draw(rnd)
        if kind == "preal":
            return PV.parameter_real(rnd, number)
        if kind == "pdint":
            return PV.parameter_dint(rnd, number)
        if kind == "dpaddr":
            return PV.dp_address(rnd, self.slaves)
        if kind == "diag":
            return PV.diagnostic_address(rnd, self.slaves)
        if kind == "cam":
            return PV.cam_table(rnd, self.cams, self.names)
        raise ValueError(kind)  # pragma: no cover


def _fill(gen: GenS7T, fb: dict[str, Any], p: float = 0.7) -> None:
    for inp, kind in CATALOG[fb["cls"]].items():
        if inp not in fb["init"] and kind not in ("axis", "any_to", "bool") and gen.rnd.random() < p:
            fb["init"][inp] = gen.value(fb, inp, kind)
    if fb["cls"] in ("MC_ReadPeriphery", "MC_ReadRecord", "MC_ReadDriveParameter", "MC_WritePeriphery",
                     "MC_WriteRecord", "MC_WriteDriveParameter") and "Data" not in fb["init"]:
        fb["init"]["Data"] = gen.value(fb, "Data", CATALOG[fb["cls"]]["Data"])     # an area mostly


def generate_s7t(rnd: random.Random, ep: Any) -> None:
    """Fill ``ep`` (dialect S7-Technology, ``ep.cycles`` drawn) from ``rnd``."""
    from .gen import Op                     # gen imports this module: a late import

    n = rnd.randint(1, 4)
    dbs = rnd.sample(range(2, 600), n)
    if rnd.random() < 0.1:
        dbs[0] = rnd.choice((32768, 40000, 65535))          # a DB number beyond the INT range
    cams = [O.CAM_DB + k for k in range(rnd.choice((0, 1, 1, 2)))]
    for i in range(n):
        technology = rnd.choices((0, 1, 2), (0.2, 0.6, 0.2))[0]
        params = axis_s7t(rnd, dbs[i], technology)
        options_s7t(rnd, params, i, cams)
        a = {"name": f"Axis_{i + 1}", "kind": "sync" if technology == 2 else "pos", "params": params}
        if technology == 2:
            a["leading"] = [x["name"] for x in ep.axes]
        ep.axes.append(a)
    vmax = max(a["params"]["TypeOfAxis.MaxVelocity.maximum"] for a in ep.axes)
    for k, db in enumerate(cams):
        ep.cams.append({"name": f"Cam_{k + 1}", "db": db, "points": O.valve_profile(rnd, vmax)})
    gen = GenS7T(rnd, ep)
    for a in ep.axes:
        ep.fbs.append({"name": f"power_{a['name']}", "cls": "MC_Power",
                       "init": {"Axis": Ref(a["name"]), "Enable": rnd.random() < 0.9,
                                "Mode": rnd.choice((0, 0, 0, 1, 5)) if not a["params"]["Wizard.Virtual"] else 0,
                                "StopMode": rnd.choice((0, 1, 2, 3, 4) if a["params"].get("Wizard.DriveTechnology")
                                                       else (0, 1, 2, 4)),
                                "QOutputValue": round(rnd.uniform(-100.0, 100.0), 1)}})
    names, weights = list(WEIGHTS), list(WEIGHTS.values())
    for k in range(rnd.randint(2, 10)):
        cls = rnd.choices(names, weights)[0]
        fb = {"name": f"fb{k}_{cls[3:]}", "cls": cls, "init": {}}
        kind = CATALOG[cls].get("Axis")
        if kind is not None:
            fb["init"]["Axis"] = gen.axis(mcdevice=kind == "any_to") if rnd.random() < 0.3 \
                else Ref(rnd.choice(gen.names))
        _fill(gen, fb)
        ep.fbs.append(fb)
    _scenarios_s7t(rnd, ep, gen, Op)
    scenarios_part1(rnd, ep, gen, Op)
    initial = []
    for fb in ep.fbs:
        start = {}
        for k, kd in CATALOG[fb["cls"]].items():
            if kd == "bool" and k not in ("Execute", "Enable"):
                start[k] = bool(rnd.getrandbits(1))
            elif k == "Enable" and "Enable" in fb["init"]:
                start[k] = fb["init"]["Enable"]
        fb["init"].update(start)
        initial.append(start)
    for c in range(1, ep.cycles):
        if rnd.random() > 0.2:
            continue
        for _ in range(1 if rnd.random() < 0.65 else rnd.randint(2, 4)):
            fb = rnd.choice(ep.fbs)
            kinds = CATALOG[fb["cls"]]
            bools = [k for k, kd in kinds.items() if kd == "bool"]
            if rnd.random() < 0.55:
                inp = "Execute" if "Execute" in kinds and rnd.random() < 0.7 else rnd.choice(bools)
            else:
                inp = rnd.choice(list(kinds))
            value = gen.value(fb, inp, kinds[inp])
            fb["init"].setdefault(inp, None)
            ep.ops.append(Op(c, "in", fb["name"], inp, value))
            if kinds[inp] == "bool":
                fb["init"][inp] = value              # so that the next toggle toggles
    for fb, start in zip(ep.fbs, initial):          # the toggle bookkeeping above is not an initial value
        for k, kd in CATALOG[fb["cls"]].items():
            if kd == "bool":
                fb["init"].pop(k, None)
                if k in start:
                    fb["init"][k] = start[k]
        fb["init"] = {k: v for k, v in fb["init"].items() if v is not None or k == "Axis"}
    ep.ops.sort(key=lambda o: o.cycle)


def _scenarios_s7t(rnd: random.Random, ep: Any, gen: GenS7T, Op: Any) -> None:
    """The situations of the brief made likely: each with its own instances, so that the random input
    changes of the episode may still meet them."""
    last = ep.cycles - 1
    axis = Ref(rnd.choice(gen.names))
    if rnd.random() < 0.6:
        # a positioning, then an appended (Mode 1) or overlaid (Mode 2) command a few cycles later
        first = {"name": "first", "cls": rnd.choice(("MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity")),
                 "init": {"Axis": axis}}
        second = {"name": "second", "cls": rnd.choice(("MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity")),
                  "init": {"Axis": axis}}
        _fill(gen, first, 0.5)
        _fill(gen, second, 0.5)
        second["init"]["Mode"] = rnd.choice((1, 2)) if second["cls"] != "MC_MoveVelocity" else 1
        ep.fbs += [first, second]
        c = rnd.randint(1, 20)
        ep.ops += [Op(c, "in", "first", "Execute", True),
                   Op(min(last, c + rnd.choice((0, 1, 2, 5, 20))), "in", "second", "Execute", True)]
    if rnd.random() < 0.35:
        # rapid Execute toggling: a rising edge every second or third cycle
        cls = rnd.choice(MOVES + ("MC_Halt",))
        fb = {"name": "toggler", "cls": cls, "init": {"Axis": Ref(rnd.choice(gen.names))}}
        _fill(gen, fb, 0.5)
        ep.fbs.append(fb)
        c, on = rnd.randint(1, 10), True
        for _ in range(rnd.randint(4, 20)):
            if c > last:
                break
            ep.ops.append(Op(c, "in", "toggler", "Execute", on))
            on = not on
            c += rnd.choice((1, 1, 2))
    if rnd.random() < 0.3:
        # MC_Power toggled (its instance: the power_ instance of the axis)
        name = rnd.choice(gen.names)
        c, on = rnd.randint(5, 40), False
        for _ in range(rnd.randint(1, 6)):
            if c > last:
                break
            ep.ops.append(Op(c, "in", f"power_{name}", "Enable", on))
            on = not on
            c += rnd.choice((1, 2, 5, 15))
    if rnd.random() < 0.3:
        # MC_Stop held for a while, motion commands during it
        fb = {"name": "stopper", "cls": "MC_Stop", "init": {"Axis": Ref(rnd.choice(gen.names))}}
        _fill(gen, fb, 0.4)
        ep.fbs.append(fb)
        c = rnd.randint(2, 40)
        ep.ops += [Op(c, "in", "stopper", "Execute", True),
                   Op(min(last, c + rnd.randint(1, 80)), "in", "stopper", "Execute", False)]
    if rnd.random() < 0.3:
        # MC_Reset with or without Restart, mostly after a disable
        name = rnd.choice(gen.names)
        fb = {"name": "resetter", "cls": "MC_Reset", "init": {"Axis": Ref(name), "Restart": rnd.random() < 0.5}}
        ep.fbs.append(fb)
        c = rnd.randint(5, 60)
        if rnd.random() < 0.7:
            ep.ops += [Op(c, "in", f"power_{name}", "Enable", False),
                       Op(min(last, c + rnd.randint(10, 40)), "in", f"power_{name}", "Enable", True)]
        ep.ops += [Op(min(last, c + rnd.randint(0, 8)), "in", "resetter", "Execute", True),
                   Op(min(last, c + rnd.randint(9, 30)), "in", "resetter", "Execute", False)]


from .gen_s7t_scenarios import scenarios_part1  # noqa: E402 - it uses CATALOG and _fill of this module

__all__ = ["S7T", "CATALOG", "generate_s7t", "axis_s7t", "options_s7t"]
