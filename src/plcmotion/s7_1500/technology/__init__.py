"""S7-1500 / S7-1500T technology objects (technology version V5) and their registration as families.

The objects (positioning and synchronous axes, external encoder, leading axis proxy, cam) are built on the
kernel's axis core, couplings and cam curves; here they get the S7-1500 tag names, start values, status
words and alarms.  Importing this package registers the families "S7-1500" and "S7-1500T" with the kernel
(``plcmotion`` does that on import).  The S7-1500 CPU without T offers no camming, no positioned gearing,
no actual value coupling and no external encoder, proxy or cam (S7-1500T sync V5 §1, overview of functions).
"""
from __future__ import annotations

import math
import numbers
from typing import Any, Mapping

from ...kernel import family as K
from ...kernel.axis import ConfigurationError
from ...kernel.jobs import JobKind
from ...kernel.schema import Issue
from .axes import PositioningAxis1500, SynchronousAxis
from .cam_to import CamTO
from .external_encoder import ENCODER_SCHEMA, ExternalEncoder
from .override import POLICY
from .parameters import S7_1500 as SCHEMA
from .proxy import PROXY_SCHEMA, LeadingAxisProxy
from .tags import alarm_description

#: jobs only the T CPU runs (S7-1500T sync V5 §1: camming, GearInPos, phasing, simulation, additive value)
T_ONLY_JOBS = frozenset({JobKind.GEAR_IN_POS, JobKind.CAM_IN, JobKind.PHASING, JobKind.SYNC_SIMULATION,
                         JobKind.LV_ADDITIVE})


def _short(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _positioning_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> PositioningAxis1500:
    return ctl.new_axis(PositioningAxis1500, name, flat, where)


def _synchronous_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str, *,
                      leading_values: Any = ()) -> SynchronousAxis:
    return ctl.new_axis(SynchronousAxis, name, flat, where, leading_values=leading_values)


def _external_encoder(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> ExternalEncoder:
    cfg, issues = ENCODER_SCHEMA.validate(flat)
    if issues:
        raise ConfigurationError(where, issues)
    return ExternalEncoder(ctl, name, cfg)


def _leading_axis_proxy(ctl: Any, name: str, flat: Mapping[str, Any], where: str, *,
                        source_link: Any = None) -> LeadingAxisProxy:
    cfg, issues = PROXY_SCHEMA.validate(flat)
    if issues:
        raise ConfigurationError(where, issues)
    return LeadingAxisProxy(ctl, name, cfg, source_link)


def _cam_values(name: str, points: Any, segments: Any) -> tuple[list, list]:
    """Points and segments of a new cam as lists; an int beyond the LREAL range becomes +-inf, an invalid
    value that MC_InterpolateCam reports with its ErrorID (the cam TO stores what the program wrote)."""
    def lreal(v: Any) -> Any:
        if isinstance(v, numbers.Integral) and not isinstance(v, bool) and abs(v) > 1.0e308:
            return math.inf if v > 0 else -math.inf
        return v
    for what, value in (("points", points), ("segments", segments)):
        if isinstance(value, (str, bytes, Mapping)) or not hasattr(value, "__iter__"):
            raise TypeError(f"cam {name}: {what} must be a list, got {_short(value)}")
    pts = [tuple(lreal(v) for v in p) if isinstance(p, (list, tuple)) else p for p in points]
    segs = [{k: lreal(v) for k, v in sg.items()} if isinstance(sg, Mapping) else sg for sg in segments]
    return pts, segs


def _cam(ctl: Any, name: str, points: Any, segments: Any, *, interpolation_mode: Any,
         boundary_conditions: Any) -> CamTO:
    """Point[1..n] = ``points``, Segment[1..m] = ``segments`` (dicts of xmin, xmax, a0..a6, sineAmplitude,
    sinePeriod, sinePhase) and the interpolation settings (§A.2)."""
    issues = [Issue(tag, "selection", value, "allowed: " + text)
              for tag, value, allowed, text in (
                  ("InterpolationSettings.InterpolationMode", interpolation_mode, (0, 1, 2),
                   "0 (linear), 1 (cubic spline) or 2 (Bézier spline)"),
                  ("InterpolationSettings.BoundaryConditions", boundary_conditions, (0, 1),
                   "0 (none) or 1 (equal first derivative at start and end)"))
              if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value not in allowed]
    if issues:
        raise ConfigurationError(f"cam {name}", issues)
    points, segments = _cam_values(name, points, segments)
    return CamTO(ctl, name, points, segments, interpolation_mode, boundary_conditions)


_AXES = {K.POSITIONING_AXIS: _positioning_axis, K.SYNCHRONOUS_AXIS: _synchronous_axis}
_ALL_JOBS = frozenset(JobKind)
# the tags of every kind are checked with the S7-1500 schemas in both families (a project file of an S7-1500
# without T is checked as such; its factories then refuse what the CPU does not have)
_SCHEMAS = {K.POSITIONING_AXIS: SCHEMA, K.SYNCHRONOUS_AXIS: SCHEMA, K.EXTERNAL_ENCODER: ENCODER_SCHEMA,
            K.LEADING_AXIS_PROXY: PROXY_SCHEMA}

S7_1500 = K.register(K.Family("S7-1500", versions=(5,), default_version=5, factories=_AXES,
                              job_kinds=_ALL_JOBS - T_ONLY_JOBS, policy=POLICY, schemas=_SCHEMAS,
                              describe_fault=alarm_description))
S7_1500T = K.register(K.Family(
    "S7-1500T", versions=(5,), default_version=5,
    factories={**_AXES, K.EXTERNAL_ENCODER: _external_encoder, K.LEADING_AXIS_PROXY: _leading_axis_proxy,
               K.CAM: _cam},
    job_kinds=_ALL_JOBS, features=frozenset({K.ACTUAL_VALUE_COUPLING}), policy=POLICY, schemas=_SCHEMAS,
    describe_fault=alarm_description))

__all__ = ["S7_1500", "S7_1500T", "PositioningAxis1500", "SynchronousAxis", "ExternalEncoder", "LeadingAxisProxy",
           "CamTO", "T_ONLY_JOBS"]
