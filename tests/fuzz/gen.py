"""Random episodes: a controller of one dialect, a few technology objects, instruction instances and a
list of timed operations (input changes, tag writes), all drawn from one ``random.Random``.

An episode is plain data (:class:`Episode`), so that it can be replayed, shrunk and printed as a script.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from typing import Any

from . import values as V
from .gen_s7t import CATALOG as _S7T_CATALOG
from .gen_s7t import S7T, generate_s7t
from .values import Ref, TagRefSpec, VarSpec

DIALECTS = ("S7-1200 V6", "S7-1200 V7", "S7-1500", "S7-1500T")
#: every dialect the fuzzer knows.  A seed without a dialect draws from DIALECTS only, so that the seeds of
#: the campaigns before S7-Technology still give the same episodes; S7-Technology (gen_s7t) is fuzzed when
#: asked for (``--dialect S7-Technology``, the CI test of each dialect).
ALL_DIALECTS = DIALECTS + ("S7-Technology",)


@dataclass
class Op:
    """One operation before the calls of application cycle ``cycle``.

    kind "in": ``target`` is an instruction instance, ``key`` an input, ``value`` its new value.
    kind "tag": ``target`` is a technology object, ``key`` a tag path (direct assignment in the program).
    """
    cycle: int
    kind: str
    target: str
    key: str
    value: Any


@dataclass
class Episode:
    seed: int
    dialect: str
    ctl: dict[str, Any]
    axes: list[dict[str, Any]] = field(default_factory=list)     # name, kind (pos/sync), params, leading
    cams: list[dict[str, Any]] = field(default_factory=list)     # name, points, interpolation, boundary
    tables: list[dict[str, Any]] = field(default_factory=list)   # name, commands
    proxies: list[dict[str, Any]] = field(default_factory=list)  # name, source settings
    fbs: list[dict[str, Any]] = field(default_factory=list)      # name, cls, init (inputs)
    ops: list[Op] = field(default_factory=list)
    cycles: int = 100

    def family(self) -> str:
        return "S7-1200" if self.dialect.startswith("S7-1200") else self.dialect


def _logu(rnd: random.Random, lo: float, hi: float) -> float:
    return math.exp(rnd.uniform(math.log(lo), math.log(hi)))


# --- technology objects ------------------------------------------------------------------------------------
def _common_params(rnd: random.Random, p: dict[str, Any], vmax: float) -> None:
    if rnd.random() < 0.2 and p.get("Actor.Type") != 2:        # S7-1200 §5.4.4.2: no modulo on PTO
        p["Modulo.Enable"] = True
        p["Modulo.Length"] = rnd.choice((1.0, 360.0, round(_logu(rnd, 0.5, 2000.0), 3)))
        p["Modulo.StartValue"] = rnd.choice((0.0, 0.0, -0.5 * p["Modulo.Length"]))
    if rnd.random() < 0.4:
        r = round(_logu(rnd, 20.0, 5000.0), 1)
        p["PositionLimits_SW.Active"] = True
        p["PositionLimits_SW.MinPosition"] = -r
        p["PositionLimits_SW.MaxPosition"] = round(r * rnd.uniform(0.2, 2.0), 1)


def axis_1200(rnd: random.Random, i: int) -> dict[str, Any]:
    actor = rnd.choice((0, 1, 2))
    # a PTO axis is bounded by its pulse output: 100 kHz = 1000 mm/s with the default mechanics
    # a PROFIdrive/analog axis by its drive: 3000 1/min x 10 mm = 500 mm/s (the default drive parameters)
    vmax = round(_logu(rnd, 5.0, 900.0 if actor == 2 else 480.0), 2)
    acc = round(vmax * _logu(rnd, 0.5, 50.0), 2)
    dec = round(vmax * _logu(rnd, 0.5, 50.0), 2)
    p: dict[str, Any] = {
        "Actor.Type": actor,
        "DynamicLimits.MaxVelocity": vmax,
        "DynamicLimits.MinVelocity": max(0.01, round(rnd.uniform(0.0, 0.1) * vmax, 2)) if actor == 2 else 0.0,
        "DynamicDefaults.Acceleration": acc,
        "DynamicDefaults.Deceleration": dec,
        "DynamicDefaults.EmergencyDeceleration": round(max(acc, dec) * rnd.uniform(1.0, 5.0), 2),
        "DynamicDefaults.Jerk": 0.0 if rnd.random() < 0.4 else round(acc * _logu(rnd, 1.0, 200.0), 1),
        "Homing.ApproachVelocity": round(vmax * 0.5, 2),
        "Homing.ReferencingVelocity": round(vmax * 0.1, 2),
    }
    if actor == 2:
        p["Actor.Interface.PTO"] = i + 1
    elif rnd.random() < 0.15:
        p["Simulation.Mode"] = 1
    if rnd.random() < 0.4:
        p["Sensor[1].ActiveHoming.Mode"] = 2
        p["Sensor[1].ActiveHoming.DigitalInputAddress"] = f"I0.{i}"
        p["Plant.HomingSwitchPosition"] = round(rnd.uniform(-200.0, 200.0), 1)
    _common_params(rnd, p, vmax)
    return p


def axis_1500(rnd: random.Random, sync: bool) -> dict[str, Any]:
    vmax = round(_logu(rnd, 5.0, 950.0), 2)           # 6000 1/min x 10 mm: 1000 mm/s at most
    amax = round(vmax * _logu(rnd, 1.0, 100.0), 1)
    dmax = round(vmax * _logu(rnd, 1.0, 100.0), 1)
    p: dict[str, Any] = {
        "DynamicLimits.MaxVelocity": vmax,
        "DynamicLimits.Velocity": vmax,
        "DynamicLimits.MaxAcceleration": amax,
        "DynamicLimits.MaxDeceleration": dmax,
        "DynamicLimits.MaxJerk": 0.0 if rnd.random() < 0.3 else round(amax * _logu(rnd, 2.0, 500.0), 1),
        "DynamicDefaults.Velocity": round(vmax * rnd.uniform(0.1, 1.0), 2),
        "DynamicDefaults.Acceleration": round(amax * rnd.uniform(0.1, 1.0), 2),
        "DynamicDefaults.Deceleration": round(dmax * rnd.uniform(0.1, 1.0), 2),
        "DynamicDefaults.Jerk": 0.0 if rnd.random() < 0.3 else round(amax * _logu(rnd, 1.0, 200.0), 1),
        "DynamicDefaults.EmergencyDeceleration": round(max(amax, dmax) * rnd.uniform(1.0, 3.0), 1),
        # generous following error limits: the fuzzer is about the setpoints, not about drive tuning
        "FollowingError.MaxValue": 1.0e6,
    }
    kind = rnd.random()
    if kind < 0.35:
        p["VirtualAxis.Mode"] = 1
    elif kind < 0.5:
        p["Simulation.Mode"] = 1
    else:
        p["Actor.Type"] = rnd.choice((0, 1))
    _common_params(rnd, p, vmax)
    return p


def cam(rnd: random.Random, name: str) -> dict[str, Any]:
    n = rnd.randint(2, 8)
    length = rnd.choice((1.0, 100.0, 360.0, round(_logu(rnd, 1.0, 1000.0), 1)))
    x0 = rnd.choice((0.0, 0.0, round(rnd.uniform(-200.0, 200.0), 1)))
    xs = sorted({round(x0 + rnd.uniform(0.0, length), 3) for _ in range(n)} | {x0})
    if len(xs) < 2:
        xs = [x0, x0 + length]
    ys = [round(rnd.uniform(-100.0, 100.0), 1) for _ in xs]
    if rnd.random() < 0.3:
        ys[-1] = ys[0]
    return {"name": name, "points": list(zip(xs, ys)), "interpolation": rnd.choice((0, 1, 2)),
            "boundary": rnd.choice((0, 1))}


def table(rnd: random.Random, name: str) -> dict[str, Any]:
    steps = []
    for _ in range(rnd.randint(1, 5)):
        steps.append({"Type": rnd.choice((0, 2, 5, 6, 7, 151)),
                      "Position": round(rnd.uniform(-500.0, 500.0), 1),
                      "Velocity": round(rnd.uniform(-100.0, 200.0), 1),
                      "Duration": round(rnd.uniform(0.0, 0.3), 3),
                      "NextStep": rnd.choice((0, 1)), "StepCode": rnd.randint(0, 9)})
    return {"name": name, "commands": steps}


def proxy(rnd: random.Random, name: str) -> dict[str, Any]:
    return {"name": name, "velocity": round(rnd.uniform(-300.0, 300.0), 1),
            "glitch": rnd.choice((0.0, 0.0, 0.01, 0.1)), "gap": rnd.choice((0.0, 0.0, 0.02)),
            "seed": rnd.randrange(1 << 30)}


# --- instructions ------------------------------------------------------------------------------------------
# the kind of each input: how a new value is drawn (see _value)
_MOVE_1200 = {
    "MC_Power": {"Axis": "axis", "Enable": "bool", "StartMode": ("int", (0, 1)), "StopMode": ("int", (0, 1, 2))},
    "MC_Reset": {"Axis": "axis", "Execute": "bool", "Restart": "bool"},
    "MC_Home": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Mode": ("int", (0, 1, 2, 3, 6, 7))},
    "MC_Halt": {"Axis": "axis", "Execute": "bool"},
    "MC_MoveAbsolute": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Velocity": "vel",
                        "Direction": ("int", (0, 1, 2, 3))},
    "MC_MoveRelative": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "Velocity": "vel"},
    "MC_MoveVelocity": {"Axis": "axis", "Execute": "bool", "Velocity": "vel", "Direction": ("int", (0, 1, 2)),
                        "Current": "bool", "PositionControlled": "bool"},
    "MC_MoveJog": {"Axis": "axis", "JogForward": "bool", "JogBackward": "bool", "Velocity": "vel",
                   "PositionControlled": "bool"},
    "MC_CommandTable": {"Axis": "axis", "CommandTable": "table", "Execute": "bool",
                        "StartStep": ("int", (1, 2, 3)), "EndStep": ("int", (1, 3, 5, 32))},
    "MC_ChangeDynamic": {"Axis": "axis", "Execute": "bool", "ChangeRampUp": "bool", "RampUpTime": "time",
                         "ChangeRampDown": "bool", "RampDownTime": "time", "ChangeEmergency": "bool",
                         "EmergencyRampTime": "time", "ChangeJerkTime": "bool", "JerkTime": "time"},
    "MC_WriteParam": {"Parameter": "param", "Value": "pvalue", "Execute": "bool"},
    "MC_ReadParam": {"Parameter": "param", "Value": "pvar", "Enable": "bool"},
}
_DYN = {"Acceleration": "acc", "Deceleration": "acc", "Jerk": "jerk"}
_MOVE_1500 = {
    "MC_Power": _MOVE_1200["MC_Power"],
    # S7-1500: MC_Reset also acknowledges alarms of (and restarts) other technology objects, e.g. cams
    "MC_Reset": {"Axis": "any_to", "Execute": "bool", "Restart": "bool"},
    "MC_Home": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Mode": ("int", (0, 1, 2, 3, 5, 6, 7, 8, 9, 10))},
    "MC_Halt": {"Axis": "axis", "Execute": "bool", "Deceleration": "acc", "Jerk": "jerk"},
    "MC_Stop": {"Axis": "axis", "Execute": "bool", "Mode": ("int", (0, 1, 2))},
    "MC_MoveAbsolute": {"Axis": "axis", "Execute": "bool", "Position": "pos", "Direction": ("int", (0, 1, 2, 3)),
                        "Velocity": "vel", **_DYN},
    "MC_MoveRelative": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "Velocity": "vel", **_DYN},
    "MC_MoveVelocity": {"Axis": "axis", "Execute": "bool", "Velocity": "vel", **_DYN,
                        "Direction": ("int", (0, 1, 2, 3)), "Current": "bool", "PositionControlled": "bool"},
    "MC_MoveJog": {"Axis": "axis", "JogForward": "bool", "JogBackward": "bool", "Velocity": "vel", **_DYN,
                   "PositionControlled": "bool"},
    "MC_MoveSuperimposed": {"Axis": "axis", "Execute": "bool", "Distance": "pos", "VelocityDiff": "vel",
                            "AccelerationDiff": "acc", "DecelerationDiff": "acc", "JerkDiff": "jerk"},
}
_SYNC_1500 = {
    "MC_GearIn": {"Master": "master", "Slave": "slave", "Execute": "bool", "RatioNumerator": "ratio",
                  "RatioDenominator": "ratio", **_DYN},
}
_SYNC_1500T = {
    **_SYNC_1500,
    "MC_GearInPos": {"Master": "master", "Slave": "slave", "Execute": "bool", "RatioNumerator": "ratio",
                     "RatioDenominator": "ratio", "MasterSyncPosition": "pos", "SlaveSyncPosition": "pos",
                     "SyncProfileReference": ("int", (0, 1, 2, 3)), "MasterStartDistance": "dist",
                     "Velocity": "vel", **_DYN, "SyncDirection": ("int", (1, 2, 3))},
    "MC_CamIn": {"Master": "master", "Slave": "slave", "Cam": "cam", "Execute": "bool", "MasterOffset": "pos",
                 "SlaveOffset": "pos", "MasterScaling": "scale", "SlaveScaling": "scale",
                 "MasterSyncPosition": "pos", "SyncProfileReference": ("int", (0, 1, 2, 3, 4)),
                 "MasterStartDistance": "dist", "Velocity": "vel", **_DYN,
                 "ApplicationMode": ("int", (0, 1, 2)), "SyncDirection": ("int", (1, 2, 3))},
    "MC_PhasingRelative": {"Master": "master", "Slave": "slave", "Execute": "bool", "PhaseShift": "pos",
                           "Velocity": "vel", **_DYN},
    "MC_PhasingAbsolute": {"Master": "master", "Slave": "slave", "Execute": "bool", "PhaseShift": "pos",
                           "Velocity": "vel", **_DYN},
    "MC_SynchronizedMotionSimulation": {"Slave": "slave", "Enable": "bool"},
    "MC_LeadingValueAdditive": {"Axis": "slave", "Enable": "bool", "Position": "pos", "Velocity": "vel",
                                "Acceleration": "acc"},
    "MC_InterpolateCam": {"Cam": "cam", "Execute": "bool"},
    "MC_GetCamLeadingValue": {"Cam": "cam", "Execute": "bool", "FollowingValue": "pos",
                              "ApproachLeadingValue": "pos"},
    "MC_GetCamFollowingValue": {"Cam": "cam", "Execute": "bool", "LeadingValue": "pos"},
}


_TO_KINDS = ("axis", "any_to", "slave", "master", "cam", "table")


def catalog(dialect: str) -> dict[str, dict[str, Any]]:
    """Instruction name -> {input: kind} for a dialect."""
    if dialect == S7T:
        return _S7T_CATALOG
    if dialect.startswith("S7-1200"):
        return _MOVE_1200
    if dialect == "S7-1500":
        return {**_MOVE_1500, **_SYNC_1500}
    return {**_MOVE_1500, **_SYNC_1500T}


# tags written directly from the program (RW tags; out-of-range values too)
_TAGS_1200 = ("DynamicDefaults.Acceleration", "DynamicDefaults.Deceleration", "DynamicDefaults.EmergencyDeceleration",
              "DynamicDefaults.Jerk", "PositionLimits_SW.Active", "PositionLimits_SW.MinPosition",
              "PositionLimits_SW.MaxPosition", "Homing.ApproachVelocity")
_TAGS_1500 = ("DynamicDefaults.Velocity", "DynamicDefaults.Acceleration", "DynamicDefaults.Deceleration",
              "DynamicDefaults.Jerk", "DynamicDefaults.EmergencyDeceleration", "DynamicLimits.Velocity",
              "DynamicLimits.MaxAcceleration", "DynamicLimits.MaxDeceleration", "DynamicLimits.MaxJerk",
              "Override.Velocity", "PositionLimits_SW.Active", "PositionLimits_SW.MinPosition",
              "PositionLimits_SW.MaxPosition")
# MC_WriteParam / MC_ReadParam targets (RW, WP, R and status tags of S7-1200 §12.9)
_PARAM_PATHS = _TAGS_1200 + ("DynamicLimits.MaxVelocity", "DynamicLimits.MinVelocity", "Simulation.Mode",
                             "Actor.Type", "Modulo.Enable", "Position", "Velocity", "ActualPosition",
                             "StatusBits.Enable", "StatusBits.HomingDone", "ErrorBits.SWLimit",
                             "PositioningMonitoring.Window", "PositionControl.Kv", "Actor.InverseDirection",
                             "Sensor[1].ActiveHoming.HomePositionOffset", "Mechanics.LeadScrew")


class Gen:
    """Draws the values of one episode."""

    def __init__(self, rnd: random.Random, ep: Episode):
        self.rnd = rnd
        self.ep = ep
        self.pos_axes = [a["name"] for a in ep.axes]
        self.slaves = [a["name"] for a in ep.axes if a["kind"] == "sync"]
        self.masters = self.pos_axes + [p["name"] for p in ep.proxies]
        self.vmax = {a["name"]: a["params"].get("DynamicLimits.MaxVelocity", 100.0) for a in ep.axes}
        self.amax = {a["name"]: a["params"].get("DynamicDefaults.Acceleration",
                                                a["params"].get("DynamicLimits.MaxAcceleration", 100.0))
                     for a in ep.axes}

    def _scale_axis(self, fb: dict[str, Any]) -> str:
        a = fb["init"].get("Axis") or fb["init"].get("Slave")
        return a.name if isinstance(a, Ref) and a.name in self.vmax else self.pos_axes[0]

    def ref(self, names: list[str]) -> Any:
        rnd = self.rnd
        if rnd.random() < 0.05 or not names:
            every = self.pos_axes + [c["name"] for c in self.ep.cams] + [t["name"] for t in self.ep.tables] \
                + [p["name"] for p in self.ep.proxies]
            return rnd.choice((None, "Axis_1", 5, Ref(rnd.choice(every))))
        return Ref(rnd.choice(names))

    def value(self, fb: dict[str, Any], name: str, kind: Any) -> Any:
        rnd = self.rnd
        ax = self._scale_axis(fb)
        vmax = self.vmax.get(ax, 100.0)
        amax = self.amax.get(ax, 100.0)
        is1500 = not self.ep.dialect.startswith("S7-1200")
        if kind == "bool":
            return not bool(fb["init"].get(name, False)) if rnd.random() < 0.9 else bool(rnd.getrandbits(1))
        if isinstance(kind, tuple):
            return V.integer(rnd, kind[1])
        if kind == "axis":
            return self.ref(self.pos_axes)
        if kind == "any_to":
            return self.ref(self.masters + [c["name"] for c in self.ep.cams])
        if kind == "slave":
            return self.ref(self.slaves)
        if kind == "master":
            return self.ref(self.masters)
        if kind == "cam":
            return self.ref([c["name"] for c in self.ep.cams])
        if kind == "table":
            return self.ref([t["name"] for t in self.ep.tables])
        if kind == "pos":
            return V.real(rnd, rnd.choice((1.0, 50.0, 500.0)))
        if kind == "dist":
            return V.real(rnd, rnd.choice((0.0, 10.0, 200.0)), signed=False)
        if kind == "vel":
            if is1500 and rnd.random() < 0.2:
                return -1.0                                     # the default dynamics
            return V.real(rnd, vmax * rnd.choice((0.1, 0.5, 1.0)), signed=name == "Velocity")
        if kind == "acc":
            if is1500 and rnd.random() < 0.4:
                return -1.0
            return V.real(rnd, amax, signed=False)
        if kind == "jerk":
            if is1500 and rnd.random() < 0.4:
                return -1.0
            return V.real(rnd, amax * rnd.choice((0.0, 10.0, 100.0)), signed=False)
        if kind == "time":
            return V.real(rnd, rnd.choice((0.01, 0.5, 5.0, 20.0)), signed=False)
        if kind == "scale":
            return V.real(rnd, 2.0)
        if kind == "ratio":
            if rnd.random() < 0.1:
                return rnd.choice((0, 10 ** 400, 1.5, float("nan"), None, -3, 2 ** 31))
            return rnd.choice((1, 1, 2, 3, -1, -2, 7, 100))
        if kind == "param":
            if rnd.random() < 0.05:
                return rnd.choice((None, "DynamicDefaults.Acceleration", 1.0))
            return TagRefSpec(rnd.choice(self.pos_axes), rnd.choice(_PARAM_PATHS))
        if kind == "pvalue":
            r = rnd.random()
            if r < 0.5:
                return V.real(rnd, rnd.choice((1.0, amax, vmax)), garbage=0.2)
            if r < 0.7:
                return rnd.choice((True, False, 0, 1, 2, -1, 10 ** 400, None, "x"))
            return VarSpec(rnd.choice(("Real", "Int", "DInt", "Bool")), None)
        if kind == "pvar":
            return VarSpec(rnd.choice(("Real", "Int", "DInt", "UDInt", "Bool")), None)
        raise ValueError(kind)  # pragma: no cover

    def tag_op(self, cycle: int) -> Op:
        rnd = self.rnd
        ax = rnd.choice(self.pos_axes)
        is1500 = not self.ep.dialect.startswith("S7-1200")
        path = rnd.choice(_TAGS_1500 if is1500 else _TAGS_1200)
        if path.endswith("Active"):
            value: Any = bool(rnd.getrandbits(1))
        elif path == "Override.Velocity":
            value = rnd.choice((0.0, 10.0, 50.0, 100.0, 150.0, 200.0, 250.0, float("nan")))
        elif "Position" in path:
            value = V.real(rnd, 1000.0, garbage=0.05)
        elif "Velocity" in path:
            value = V.real(rnd, self.vmax[ax] * 1.2, signed=False, garbage=0.1)
        elif "Jerk" in path:
            value = V.real(rnd, self.amax[ax] * rnd.choice((0.0, 1.0, 100.0, 1000.0)), signed=False, garbage=0.1)
        else:
            value = V.real(rnd, self.amax[ax] * rnd.choice((0.1, 1.0, 10.0)), signed=False, garbage=0.1)
        return Op(cycle, "tag", ax, path, value)


def _scenarios(rnd: random.Random, ep: Episode, gen: Gen) -> None:
    """Situations the issue's campaign found fragile, made likely instead of rare: a synchronous job on a
    moving leading axis (S7-1500T), a change of dynamics around a motion start (S7-1200)."""
    cat = catalog(ep.dialect)
    if ep.dialect == "S7-1500T" and gen.slaves and rnd.random() < 0.6:
        cls = rnd.choice(("MC_GearInPos", "MC_CamIn", "MC_GearIn"))
        fb = {"name": "sync", "cls": cls, "init": {"Master": Ref(gen.pos_axes[0]), "Slave": Ref(gen.slaves[0])}}
        if cls == "MC_CamIn" and ep.cams:
            fb["init"]["Cam"] = Ref(ep.cams[0]["name"])
            ep.fbs.insert(len(ep.axes), {"name": "ipo", "cls": "MC_InterpolateCam",
                                         "init": {"Cam": Ref(ep.cams[0]["name"])}})
            ep.ops.append(Op(1, "in", "ipo", "Execute", True))
        for inp, kind in cat[cls].items():
            if inp not in fb["init"] and kind not in _TO_KINDS and kind != "bool" and rnd.random() < 0.8:
                fb["init"][inp] = gen.value(fb, inp, kind)
        ep.fbs.append(fb)
        ep.ops.append(Op(rnd.randint(5, 30), "in", "sync", "Execute", True))
    if ep.dialect == "S7-1500T" and ep.cams and rnd.random() < 0.15:
        # a cam restarted by MC_Reset in the cycle a cam value is read (defect 3b)
        cam = Ref(rnd.choice(ep.cams)["name"])
        ep.fbs += [{"name": "camread", "cls": rnd.choice(("MC_GetCamFollowingValue", "MC_GetCamLeadingValue")),
                    "init": {"Cam": cam}},
                   {"name": "camreset", "cls": "MC_Reset", "init": {"Axis": cam, "Restart": True}}]
        c = rnd.randint(2, 40)
        ep.ops += [Op(c, "in", "camread", "Execute", True), Op(c, "in", "camreset", "Execute", True)]
    if ep.dialect == "S7-1500T" and gen.slaves and rnd.random() < 0.25:
        # a job rewired to another axis while it is busy (defect 5)
        cls = rnd.choice(("MC_LeadingValueAdditive", "MC_PhasingAbsolute", "MC_PhasingRelative"))
        slave = "Axis" if cls == "MC_LeadingValueAdditive" else "Slave"
        fb = {"name": "rewired", "cls": cls, "init": {slave: Ref(gen.slaves[0])}}
        if cls != "MC_LeadingValueAdditive":
            fb["init"]["Master"] = Ref(gen.pos_axes[0])
        for inp, kind in cat[cls].items():
            if inp not in fb["init"] and kind not in _TO_KINDS and kind != "bool":
                fb["init"][inp] = gen.value(fb, inp, kind)
        ep.fbs.append(fb)
        c = rnd.randint(10, 60)
        start = "Enable" if cls == "MC_LeadingValueAdditive" else "Execute"
        other = rnd.choice(gen.slaves[1:] + gen.pos_axes + [None])
        ep.ops += [Op(c, "in", "rewired", start, True),
                   Op(c + rnd.randint(1, 20), "in", "rewired", slave, Ref(other) if other else None)]
    if ep.dialect.startswith("S7-1200") and rnd.random() < 0.5:
        ax = Ref(rnd.choice(gen.pos_axes))
        move = rnd.choice(("MC_MoveRelative", "MC_MoveAbsolute", "MC_MoveVelocity", "MC_MoveJog"))
        fb = {"name": "move", "cls": move, "init": {"Axis": ax}}
        for inp, kind in cat[move].items():
            if inp not in fb["init"] and kind not in _TO_KINDS and kind != "bool":
                fb["init"][inp] = gen.value(fb, inp, kind)
        cd = {"name": "dyn", "cls": "MC_ChangeDynamic", "init": {"Axis": ax}}
        for inp, kind in cat["MC_ChangeDynamic"].items():
            if kind == "time":
                cd["init"][inp] = gen.value(cd, inp, kind)
        ep.fbs += [fb, cd]
        c = rnd.randint(3, 30)
        start = "JogForward" if move == "MC_MoveJog" else "Execute"
        ep.ops.append(Op(c, "in", "move", start, True))
        ep.ops.append(Op(c + rnd.choice((0, 0, 1, 2, 5)), "in", "dyn", "Execute", True))


# --- the episode -------------------------------------------------------------------------------------------
def generate(seed: int, dialect: str | None = None, *, max_cycles: int = 200) -> Episode:
    rnd = random.Random(seed)
    dialect = dialect or DIALECTS[rnd.randrange(len(DIALECTS))]
    if dialect == S7T:
        ep = Episode(seed, dialect, {"servo_cycle": rnd.choice((0.001, 0.002)), "app_cycle": rnd.choice((0.004, 0.008)),
                                     "family": dialect}, cycles=rnd.randint(30, max_cycles))
        generate_s7t(rnd, ep)
        return ep
    if dialect.startswith("S7-1200"):
        ctl = {"servo_cycle": 0.001, "app_cycle": rnd.choice((0.002, 0.004, 0.004)),
               "technology_version": 7 if dialect.endswith("V7") else 6}
    else:
        ctl = {"servo_cycle": 0.001, "app_cycle": rnd.choice((0.002, 0.004, 0.004)), "family": dialect}
    ep = Episode(seed, dialect, ctl, cycles=rnd.randint(30, max_cycles))
    if dialect.startswith("S7-1200"):
        for i in range(rnd.randint(1, 2)):
            ep.axes.append({"name": f"Axis_{i + 1}", "kind": "pos", "params": axis_1200(rnd, i)})
        ep.tables.append(table(rnd, "Table_1"))
    else:
        for i in range(rnd.randint(1, 2)):
            ep.axes.append({"name": f"Axis_{i + 1}", "kind": "pos", "params": axis_1500(rnd, False)})
        if dialect == "S7-1500T" and rnd.random() < 0.2:
            ep.proxies.append(proxy(rnd, "Proxy_1"))
        leading = [a["name"] for a in ep.axes] + [p["name"] for p in ep.proxies]
        for i in range(rnd.randint(0 if dialect == "S7-1500" else 1, 2)):
            name = f"Follower_{i + 1}"
            ep.axes.append({"name": name, "kind": "sync", "params": axis_1500(rnd, True), "leading": list(leading)})
            leading.append(name)
        if dialect == "S7-1500T":
            for i in range(rnd.randint(1, 2)):
                ep.cams.append(cam(rnd, f"Cam_{i + 1}"))
    gen = Gen(rnd, ep)
    cat = catalog(dialect)
    # every axis has its MC_Power, mostly enabled from the first cycle
    for a in ep.axes:
        ep.fbs.append({"name": f"power_{a['name']}", "cls": "MC_Power",
                       "init": {"Axis": Ref(a["name"]), "Enable": rnd.random() < 0.9,
                                "StartMode": 1, "StopMode": rnd.choice((0, 1, 2))}})
    if rnd.random() < 0.6:
        ep.fbs.append({"name": "home", "cls": "MC_Home",
                       "init": {"Axis": Ref(gen.pos_axes[0]), "Mode": 0, "Position": 0.0}})
        ep.ops.append(Op(rnd.randint(1, 4), "in", "home", "Execute", True))
    names = [n for n in cat if n != "MC_Power"]
    if dialect == "S7-1500T":               # prefer the synchronous operation instructions
        names += [n for n in _SYNC_1500T if n.startswith(("MC_GearIn", "MC_CamIn", "MC_Interpolate"))] * 2
    for k in range(rnd.randint(2, 7)):
        cls = rnd.choice(names)
        kinds = cat[cls]
        fb = {"name": f"fb{k}_{cls[3:]}", "cls": cls, "init": {}}
        for inp, kind in kinds.items():
            if kind in _TO_KINDS:
                fb["init"][inp] = gen.value(fb, inp, kind)
        for inp, kind in kinds.items():
            if kind not in _TO_KINDS and kind != "bool" and rnd.random() < 0.7:
                fb["init"][inp] = gen.value(fb, inp, kind)
        if cls == "MC_ReadParam":
            fb["init"]["Value"] = gen.value(fb, "Value", "pvar")    # an InOut: always a typed variable
        ep.fbs.append(fb)
        if cls == "MC_CamIn" and ep.cams and rnd.random() < 0.8:
            # interpolate the cam first so that MC_CamIn has a chance
            ep.fbs.insert(len(ep.axes), {"name": f"ipo{k}", "cls": "MC_InterpolateCam",
                                         "init": {"Cam": fb["init"].get("Cam", Ref(ep.cams[0]["name"]))}})
            ep.ops.append(Op(1, "in", f"ipo{k}", "Execute", True))
    if rnd.random() < 0.7:
        # a leading axis / first axis in motion early: gives synchronous operation and dynamics changes
        # something to act on
        ep.fbs.insert(len(ep.axes), {"name": "run", "cls": "MC_MoveVelocity",
                                     "init": {"Axis": Ref(gen.pos_axes[0]),
                                              "Velocity": round(gen.vmax[gen.pos_axes[0]] * rnd.uniform(0.1, 0.9), 2)
                                              * rnd.choice((1, 1, -1))}})
        ep.ops.append(Op(rnd.randint(1, 8), "in", "run", "Execute", True))
    _scenarios(rnd, ep, gen)
    # initial values of the BOOL inputs other than the edges/levels the operations toggle
    initial = []
    for fb in ep.fbs:
        start = {}
        for k, kd in cat[fb["cls"]].items():
            if kd == "bool" and k not in ("Execute", "Enable", "JogForward", "JogBackward"):
                start[k] = bool(rnd.getrandbits(1))
            elif k == "Enable" and "Enable" in fb["init"]:
                start[k] = fb["init"]["Enable"]
        fb["init"].update(start)
        initial.append(start)
    # timed operations: sparse, sometimes several in one cycle (same-cycle races)
    fbs = [f for f in ep.fbs]
    for c in range(1, ep.cycles):
        if rnd.random() > 0.18:
            continue
        for _ in range(1 if rnd.random() < 0.65 else rnd.randint(2, 4)):
            if rnd.random() < 0.15:
                ep.ops.append(gen.tag_op(c))
                continue
            fb = rnd.choice(fbs)
            kinds = cat[fb["cls"]]
            bools = [k for k, kd in kinds.items() if kd == "bool"]
            if bools and rnd.random() < 0.55:
                inp = "Execute" if "Execute" in kinds and rnd.random() < 0.7 else rnd.choice(bools)
            else:
                inp = rnd.choice(list(kinds))
            value = gen.value(fb, inp, kinds[inp])
            fb["init"].setdefault(inp, None)
            ep.ops.append(Op(c, "in", fb["name"], inp, value))
            if kinds[inp] == "bool":
                fb["init"][inp] = value              # so that the next toggle toggles
    for fb, start in zip(ep.fbs, initial):          # the toggle bookkeeping above is not an initial value
        for k, kd in catalog(dialect)[fb["cls"]].items():
            if kd == "bool":
                fb["init"].pop(k, None)
                if k in start:
                    fb["init"][k] = start[k]
        fb["init"] = {k: v for k, v in fb["init"].items() if v is not None or k in ("Axis", "Master", "Slave", "Cam")}
    ep.ops.sort(key=lambda o: o.cycle)
    return ep
