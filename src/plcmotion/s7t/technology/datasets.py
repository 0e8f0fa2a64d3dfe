"""Data sets of an S7-Technology axis (S7-Technology V4.1 §3.1.10, §4.5.1, §6.2.5, §9.4 numbers 2000-2073,
4020).

An axis has ``TypeOfAxis.NumberOfDataSets.numberOfDataSets`` data sets (a virtual axis one); after a restart
``initDataSet`` is in force.  Each data set ``DataSet_x`` holds what §9.4 indexes by data set and the model
uses: the controller parameters (Kv, precontrol), the dynamic following error monitoring
(``DynamicFollowing``), the clamping monitoring of the fixed end stop (``ClampingMonitoring``, 2010/2011) and
the encoder it measures with (``EncoderNumber``, ``technology.encoders``); a value a data set leaves out is
data set 1's.  The activating switches (following error monitoring on/off, precontrol on/off, DSC, the
clamping detection mode) must be equal in all data sets (§4.5.1 note) and are data set 1's; the load gear is
data set 1's too (docs/s7t/decisions.md D77).  The data set in force is the system variable
``datasetmonitoring.actualdataset`` (number 4020, 0: ``initDataSet``), which MC_ChangeDataset sets;
:func:`refine` builds the configuration from it and :func:`in_force` gives any data set value.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any, Mapping

from ...kernel.axis_config import AxisConfig
from ...kernel.schema import E12, INT, REAL, WP, R, Issue, Param
from .encoders import MAX_ENCODERS, dataset_encoder, encoder_number, encoder_rule_issues

DATA_SETS = "TypeOfAxis.NumberOfDataSets"
MAX_DATA_SETS = 16
ACTUAL = "datasetmonitoring.actualdataset"
#: §9.4.12 EnumChangeMode ValueDint
NEVER, IN_POSITION, IN_STANDSTILL, IMMEDIATELY = 92, 93, 94, 95


def _pv(x: int) -> str:
    return f"{DATA_SETS}.DataSet_{x}.ControllerStruct.PV_Controller"


def _fe(x: int) -> str:
    return f"{DATA_SETS}.DataSet_{x}.DynamicFollowing"


def _cm(x: int) -> str:
    return f"{DATA_SETS}.DataSet_{x}.ClampingMonitoring"


# fmt: off
DATASET_PARAMS: list[Param] = [
    Param(f"{DATA_SETS}.numberOfDataSets", INT, 1, R, (), 1, MAX_DATA_SETS, doc="data sets of the axis (number 2000)"),
    Param(f"{DATA_SETS}.initDataSet", INT, 1, WP, (), 1, MAX_DATA_SETS, doc="data set after a restart (2001)"),
    Param(f"{DATA_SETS}.changeMode", INT, IN_POSITION, WP, (), choices=(NEVER, IN_POSITION, IN_STANDSTILL, IMMEDIATELY),
          doc="EnumChangeMode (2002): 92 NEVER, 93 IN_POSITION, 94 IN_STANDSTILL, 95 IMMEDIATELY"),
    Param(ACTUAL, INT, 0, R, (), 0, MAX_DATA_SETS, doc="data set in force (4020); 0: initDataSet"),
]
for _x in range(2, MAX_DATA_SETS + 1):
    DATASET_PARAMS += [
        Param(f"{_pv(_x)}.kv", REAL, None, WP, (10,), 0.0, 1.0e7, lo_open=True, optional=True,
              doc="none: data set 1's"),
        Param(f"{_pv(_x)}.kpc", REAL, None, WP, (10,), 0.0, 150.0, optional=True),
        Param(f"{_fe(_x)}.maxPositionTolerance", REAL, None, WP, (10,), 0.0, E12, optional=True),
        Param(f"{_fe(_x)}.minPositionTolerance", REAL, None, WP, (10,), 0.0, E12, optional=True),
        Param(f"{_fe(_x)}.minVelocity", REAL, None, WP, (10,), 0.0, E12, optional=True),
        Param(f"{_fe(_x)}.warningLimit", REAL, None, WP, (10,), 0.0, 100.0, optional=True),
        Param(f"{_cm(_x)}.followingErrorDeviation", REAL, None, WP, (10,), 0.0, E12, optional=True),
        Param(f"{_cm(_x)}.positionTolerance", REAL, None, WP, (10,), 0.0, E12, optional=True),
        Param(encoder_number(_x), INT, None, R, (), 1, MAX_ENCODERS, optional=True, doc="none: data set 1's"),
    ]
# fmt: on


def active(p: Mapping[str, Any]) -> int:
    """The data set in force with tag values ``p``."""
    return p[ACTUAL] or p[f"{DATA_SETS}.initDataSet"]


def dataset_rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    n = cfg[f"{DATA_SETS}.numberOfDataSets"]
    issues: list[Issue] = []
    if cfg.get("Wizard.Virtual") and n != 1:
        issues.append(Issue(f"{DATA_SETS}.numberOfDataSets", "rule:virtual_one", n,
                            "1: a virtual axis has one data set (§3.1.10)"))
    if cfg[f"{DATA_SETS}.initDataSet"] > n:
        issues.append(Issue(f"{DATA_SETS}.initDataSet", "rule:above_count", cfg[f"{DATA_SETS}.initDataSet"],
                            f"at most numberOfDataSets = {n}"))
    return issues + encoder_rule_issues(cfg, n)


def _value(p: Mapping[str, Any], x: int, path: str, default: Any) -> Any:
    v = p.get(path)
    return default if x == 1 or v is None else v


def in_force(p: Mapping[str, Any], path: str) -> Any:
    """The value of the data set in force of a data set 1 tag ``path`` (``...DataSet_1...``)."""
    x = active(p)
    return p[path] if x == 1 else _value(p, x, path.replace(".DataSet_1.", f".DataSet_{x}.", 1), p[path])


def refine(config: AxisConfig, p: Mapping[str, Any]) -> AxisConfig:
    """``config`` (built from data set 1) with the controller and following error values of the data set in
    force; a value a data set leaves out is data set 1's."""
    x = active(p)
    if x == 1:
        return config
    pc, fe = config.position_control, config.following_error
    return replace(
        config,
        position_control=replace(pc, kv=_value(p, x, f"{_pv(x)}.kv", pc.kv),
                                 precontrol=_value(p, x, f"{_pv(x)}.kpc", pc.precontrol)),
        following_error=replace(
            fe, max_value=_value(p, x, f"{_fe(x)}.maxPositionTolerance", fe.max_value),
            min_value=_value(p, x, f"{_fe(x)}.minPositionTolerance", fe.min_value),
            min_velocity=_value(p, x, f"{_fe(x)}.minVelocity", fe.min_velocity),
            warning_level=_value(p, x, f"{_fe(x)}.warningLimit", fe.warning_level)))


def switch(axis: Any, x: int, sync_encoder: bool = False) -> None:
    """Put data set ``x`` in force on ``axis`` now: the configuration is rebuilt and the position controller
    and monitoring take its values in this servo cycle; a data set with another encoder changes the actual
    value over to it (``sync_encoder``: the new encoder takes the actual value of the old one, §6.2.5)."""
    store = axis.parameters
    encoders = axis.encoders
    new_encoder = dataset_encoder(store.effective, x)
    changeover = new_encoder != encoders.active
    if changeover:
        encoders.leave()
    store.values[ACTUAL] = x
    store.make_effective(dict(store.effective, **{ACTUAL: x}))
    if changeover:
        encoders.enter(new_encoder, sync_encoder)
    axis._apply_bank_config()


__all__ = ["DATASET_PARAMS", "dataset_rule_issues", "refine", "switch", "active", "in_force", "NEVER", "IN_POSITION",
           "IN_STANDSTILL", "IMMEDIATELY", "ACTUAL", "DATA_SETS"]
