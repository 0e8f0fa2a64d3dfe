"""Per-cycle monitoring of all axes at once (S7-1200 V6 §5.4.4.6).

* following error: setpoint minus actual position against a velocity-dependent limit;
* positioning monitoring: after the setpoint interpolation has ended the actual position must enter the
  positioning window within the tolerance time and stay there for the minimum dwell time;
* standstill signal: actual velocity below the threshold for the minimum dwell time.

Only axes whose monitor trips are handed to Python code.
"""
from __future__ import annotations

from typing import Any

import numpy as np

#: the controller (``runtime.Controller``), not imported: the runtime runs these through the servo cycle
Controller = Any

_EPS_T = 1e-9


def following_error(ctl: Controller, t: float) -> None:
    b = ctl.bank
    speed = np.abs(b.sp_v)
    limit = np.minimum(b.fe_max, b.fe_min + b.fe_slope * np.maximum(speed - b.fe_vmin, 0.0))
    bad = b.fe_on & (np.abs(b.fe) > limit)
    if ctl._n_few:
        following_warning(ctl, t, limit, bad)
    if bad.any():
        for i in np.flatnonzero(bad):
            ctl._axis_at(i)._on_following_error(t)


def following_warning(ctl: Controller, t: float, limit: np.ndarray, bad: np.ndarray) -> None:
    """Following error above its warning level (a share of the admissible one): reported once each time it
    rises above it, only for axes that configure a warning (``fe_warn`` finite); not in the cycle the error
    itself trips (it supersedes the warning, so a level of 100 % never warns)."""
    b = ctl.bank
    warn = b.fe_on & (np.abs(b.fe) > limit * b.fe_warn)
    rising = warn & ~b.fe_warned & ~bad
    b.fe_warned = warn
    if rising.any():
        for i in np.flatnonzero(rising):
            ctl._axis_at(i)._on_following_warning(t)


def positioning(ctl: Controller, t: float) -> None:
    b = ctl.bank
    on = b.pm_on
    # the target of the basic motion; a superimposed motion moves the axis by its part on top of it
    target = b.pm_target + b.sup_now if ctl._n_sup else b.pm_target
    inside = on & (np.abs(target - b.act_p) <= b.pm_window)
    entered = np.isnan(b.pm_in_since)
    b.pm_in_since = np.where(inside & entered, t, b.pm_in_since)
    left = on & ~inside & ~entered
    done = inside & (t - b.pm_in_since >= b.pm_dwell - _EPS_T)
    late = on & ~inside & entered & (t > b.pm_deadline + _EPS_T)
    if left.any() or done.any() or late.any():
        for i in np.flatnonzero(done):
            ctl._axis_at(i)._on_positioned(t)
        for i in np.flatnonzero(left):
            ctl._axis_at(i)._on_positioning_fault(t, "left")
        for i in np.flatnonzero(late):
            ctl._axis_at(i)._on_positioning_fault(t, "not_reached")


def standstill(ctl: Controller, t: float) -> None:
    b = ctl.bank
    below = np.abs(b.act_v) < b.ss_threshold
    b.ss_since = np.where(below, b.ss_since, t)
    b.standstill = below & (t - b.ss_since >= b.ss_dwell - _EPS_T)
