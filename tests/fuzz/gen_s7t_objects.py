"""The S7-Technology objects of part 1 beyond the plain axis (S7-Technology V4.1 §3.1.4, §3.1.10, §4.5.7.5,
§4.5.10, §4.6): homing configuration with a reference cam / zero marks / an external zero mark on the
simulated plant, data sets, a fixed end stop with its clamping settings, hydraulic axes on a Q or P/Q valve
(force limiting) with cam disks as valve profiles.  Every value lies within the documented ranges, so that
the configuration is accepted (invariant 9); the instruction inputs that may be invalid come from
``gen_s7t_values``.
"""
from __future__ import annotations

import math
import random
from typing import Any

ENC = "TypeOfAxis.NumberOfEncoders.Encoder_1.IncHomingEncoder"
CLAMP = "TypeOfAxis.NumberOfDataSets.DataSet_1.ClampingMonitoring"
#: §9.4.12 EnumAxisHomingMode / EnumAxisPassiveHomingMode / EnumChangeMode / EnumRecognitionMode
HOMING_MODES = (22, 23, 24, 88)
PASSIVE_MODES = (22, 23, 24, 25)
CHANGE_MODES = (92, 93, 94, 95)
RECOGNITION = (105, 106, 107)
#: the first DB number of the cam disks (the axes take 2..599)
CAM_DB = 700


def _logu(rnd: random.Random, lo: float, hi: float) -> float:
    return math.exp(rnd.uniform(math.log(lo), math.log(hi)))


def homing(rnd: random.Random, p: dict[str, Any], k: int, vmax: float) -> None:
    """Homing of a real axis (§4.5.10): the reference cam / external zero mark on input byte ``k + 1`` (one
    byte per axis), near the start position so that a short episode meets it; zero marks every few mm."""
    mode = rnd.choice(HOMING_MODES)
    bit = rnd.randrange(8)
    start = p.get("Plant.InitialPosition", 0.0)
    p[f"{ENC}.homingMode"] = mode
    p[f"{ENC}.approachDirection"] = rnd.choice((17, 18, 19, 20)) if mode == 24 else rnd.choice((15, 16))
    if mode == 22 or rnd.random() < 0.5:
        p[f"{ENC}.logAdressBero"] = k + 1
        p[f"{ENC}.bitNumberBero"] = bit
    if mode == 24 or rnd.random() < 0.3:
        p["Drive.ExternalZeroMarkInput"] = f"I{k + 1}.{(bit + 1) % 8}"
    passive = rnd.choice(PASSIVE_MODES)
    if passive == 24 and not p.get("Drive.ExternalZeroMarkInput"):
        passive = 23
    if passive == 22 and f"{ENC}.logAdressBero" not in p:
        passive = 23
    p[f"{ENC}.passiveHomingMode"] = passive
    p[f"{ENC}.passiveApproachDirection"] = rnd.choice((17, 18, 19, 20)) if passive == 24 \
        else rnd.choice((15, 16, 21))
    p["Plant.HomingSwitchPosition"] = round(start + rnd.uniform(-40.0, 40.0), 2)
    p["Plant.HomingSwitchLength"] = round(_logu(rnd, 0.5, 30.0), 2)
    if rnd.random() < 0.2:
        p["Plant.HomingSwitchPeriod"] = round(p["Plant.HomingSwitchLength"] * rnd.uniform(2.0, 10.0), 2)
    if rnd.random() < 0.85:
        p["Plant.ZeroMarkDistance"] = round(_logu(rnd, 0.5, 20.0), 3)
        p["Plant.ZeroMarkOffset"] = round(rnd.uniform(-5.0, 5.0), 3)
    p["userdefaulthoming.homingapproachvelocity"] = round(vmax * rnd.uniform(0.05, 1.0), 3)
    p["userdefaulthoming.homingentryvelocity"] = round(vmax * rnd.uniform(0.02, 0.5), 3)
    p["userdefaulthoming.homingreducedvelocity"] = round(vmax * rnd.uniform(0.01, 0.2), 3)
    p["userdefaulthoming.homeposition"] = round(rnd.uniform(-100.0, 100.0), 2)
    if rnd.random() < 0.3:
        p[f"{ENC}.proceedShiftPos"] = round(rnd.uniform(-10.0, 10.0), 2)
    if rnd.random() < 0.3:
        p[f"{ENC}.enableZeroMarkDistance"] = 1
        p[f"{ENC}.zeroMarkDistance"] = round(_logu(rnd, 0.1, 50.0), 2)
    if rnd.random() < 0.3:
        p["TypeOfAxis.Homing.enableBeroDistance"] = 1
        p["TypeOfAxis.Homing.beroDistance"] = round(_logu(rnd, 0.1, 100.0), 2)
    if rnd.random() < 0.3:
        p["TypeOfAxis.DecodingConfig.transferSuperimposed"] = rnd.choice((0, 1, 2))


def data_sets(rnd: random.Random, p: dict[str, Any]) -> None:
    """2-4 data sets (§3.1.10) with their own controller gains and following error limits."""
    n = rnd.randint(2, 4)
    p["TypeOfAxis.NumberOfDataSets.numberOfDataSets"] = n
    p["TypeOfAxis.NumberOfDataSets.initDataSet"] = rnd.randint(1, n)
    p["TypeOfAxis.NumberOfDataSets.changeMode"] = rnd.choice(CHANGE_MODES)
    for x in range(2, n + 1):
        ds = f"TypeOfAxis.NumberOfDataSets.DataSet_{x}"
        if rnd.random() < 0.7:
            p[f"{ds}.ControllerStruct.PV_Controller.kv"] = round(_logu(rnd, 1.0, 100.0), 2)
        p[f"{ds}.DynamicFollowing.maxPositionTolerance"] = rnd.choice((1.0e6, round(_logu(rnd, 1.0, 1e4), 1)))


def end_stop(rnd: random.Random, p: dict[str, Any]) -> None:
    """A fixed end stop a little way from the start (§4.5.7.5) and the clamping settings of data set 1 on a
    drive with torque reduction (telegram 105)."""
    start = p.get("Plant.InitialPosition", 0.0)
    p["Wizard.Telegram"] = rnd.choice((102, 105, 106))
    if rnd.random() < 0.7:
        p["Plant.EndStopMaxPosition"] = round(start + _logu(rnd, 1.0, 100.0), 2)
    if rnd.random() < 0.5:
        p["Plant.EndStopMinPosition"] = round(start - _logu(rnd, 1.0, 100.0), 2)
    p[f"{CLAMP}.recognitionMode"] = rnd.choice(RECOGNITION)
    p[f"{CLAMP}.followingErrorDeviation"] = round(_logu(rnd, 0.01, 10.0), 3)
    p[f"{CLAMP}.positionTolerance"] = round(_logu(rnd, 0.01, 5.0), 3)
    if rnd.random() < 0.5:
        p["TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque"] = round(_logu(rnd, 0.1, 50.0), 2)


def hydraulic(rnd: random.Random, p: dict[str, Any], cams: list[int]) -> None:
    """A hydraulic axis (§3.1.4, §4.6): Q or P/Q valve (with a force limit: pressure limiting), output limits,
    the cylinder with the piston inside its stroke, valve profiles from the episode's cam disks."""
    pq = rnd.random() < 0.6
    p["Wizard.DriveTechnology"] = 2 if pq else 1
    p.pop("Wizard.Telegram", None)
    lo, hi = 0.0, rnd.choice((200.0, 500.0, 1000.0))
    p["Plant.Cylinder.StrokeMin"] = lo
    p["Plant.Cylinder.StrokeMax"] = hi
    p["Plant.InitialPosition"] = round(rnd.uniform(0.2, 0.8) * hi, 1)
    if pq and rnd.random() < 0.8:
        p["Drive.ForceLimit"] = round(_logu(rnd, 50.0, 20000.0), 1)
    if rnd.random() < 0.3:
        p["Plant.Cylinder.LoadForce"] = round(rnd.uniform(-2000.0, 2000.0), 1)
    if rnd.random() < 0.3:
        p["Plant.Cylinder.ValveOverlap"] = round(rnd.uniform(0.0, 10.0), 1)
    if rnd.random() < 0.3:
        p["TypeOfAxis.SpeedLimitation.MinSpeed"] = round(-rnd.uniform(20.0, 100.0), 1)
        p["TypeOfAxis.SpeedLimitation.MaxSpeed"] = round(rnd.uniform(20.0, 100.0), 1)
    if rnd.random() < 0.4:
        p["userdefaultqfaxis.maxderivative.qoutput"] = round(_logu(rnd, 1.0, 10000.0), 1)
    p["Drive.ValveReferenceVelocity"] = round(p["TypeOfAxis.MaxVelocity.maximum"] * rnd.uniform(1.0, 3.0), 1)
    for k, db in enumerate(cams[:4]):
        if rnd.random() < 0.7:
            p[f"Drive.ValveProfile{k + 1}"] = db


def valve_profile(rnd: random.Random, vmax: float) -> list[tuple[float, float]]:
    """A valve profile (§4.6.4): output [%] -> velocity, monotonic, through standstill, optionally with a dead
    band and a kink."""
    dead = rnd.choice((0.0, 0.0, round(rnd.uniform(0.5, 8.0), 1)))
    top = round(vmax * rnd.uniform(1.0, 3.0), 1)
    neg = round(top * rnd.uniform(0.4, 1.0), 1)
    points = [(-100.0, -neg)]
    if rnd.random() < 0.5:
        k = round(rnd.uniform(20.0, 80.0), 1)
        points.append((-k, -round(neg * rnd.uniform(0.1, 0.9) * k / 100.0, 2)))
    points += [(-dead, 0.0), (dead, 0.0)] if dead else [(0.0, 0.0)]
    if rnd.random() < 0.5:
        k = round(rnd.uniform(20.0, 80.0), 1)
        points.append((k, round(top * rnd.uniform(0.1, 0.9) * k / 100.0, 2)))
    points.append((100.0, top))
    return points


__all__ = ["homing", "data_sets", "end_stop", "hydraulic", "valve_profile", "CAM_DB", "ENC"]
