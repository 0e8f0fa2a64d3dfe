"""Positioning monitoring of an axis: the end of a positioning waits until the actual value is in the window.

S7-1200 V6 §5.4.4.6 ("Positioning monitoring"): when the setpoint of a positioning has reached its target,
the actual value must enter the positioning window within the tolerance time and stay there for the minimum
dwell time; then the job is done.  If it does not arrive in time, or leaves the window again, the axis gets a
positioning alarm (§12.8 16#8011) that removes its enable.  The window check itself runs vectorised over all
axes in ``kernel.monitoring``; this component only arms and disarms it for one axis and answers its verdicts.
``PositioningMonitor`` is a component of an axis (``axis.positioning_monitor``).

Standstill monitoring (configured with ``PositioningMonitoring.standstill_window``; S7-Technology V4.1
§4.5.11.2): once the positioning is done the same window check keeps watching the axis, now with the
standstill window and no end; from ``standstill_delay`` after the setpoint reached the target the actual
value must be (and stay) inside it, otherwise a standstill alarm removes the enable.  Any new job, a
disable or an alarm ends it.
"""
from __future__ import annotations

import math
from typing import Any, Protocol

from . import faults as F
from .axis_config import AxisConfig
from .faults import Fault, Reaction
from .jobs import Job, JobState
from .profiles import Profile


class MonitorHost(Protocol):
    """What the positioning monitoring needs from its axis."""

    ctl: Any                        # the controller: ``bank`` (pm_* arrays) and the ``_n_pm`` counter
    index: int                      # the axis's slot in ``ctl.bank``
    config: AxisConfig
    profile: Profile                # the setpoint profile; its final position is the target

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...


class PositioningMonitor:
    """Arms the window check for the job that ended its setpoint motion and answers the check's verdict."""

    def __init__(self, axis: MonitorHost):
        self.axis = axis
        self.job: Job | None = None                   # the positioning waiting for its actual value
        self.standstill = False                       # watching the standstill after a positioning
        self._reached = 0.0                           # when the setpoint reached the target

    def start(self, job: Job, t: float) -> None:
        """The setpoint of ``job`` has reached its target at ``t``: watch the actual value."""
        ax = self.axis
        b, i = ax.ctl.bank, ax.index
        c = ax.config.positioning
        b.pm_target[i] = ax.profile.final.p
        b.pm_deadline[i] = t + c.tolerance_time
        b.pm_in_since[i] = math.nan
        if self.standstill:
            b.pm_window[i], b.pm_dwell[i] = c.window, c.min_dwell_time   # back from a standstill watch
        self.standstill = False
        self._reached = t
        if not b.pm_on[i]:
            b.pm_on[i] = True
            ax.ctl._n_pm += 1
        self.job = job

    def stop(self) -> None:
        ax = self.axis
        b, i = ax.ctl.bank, ax.index
        if b.pm_on[i]:
            b.pm_on[i] = False
            ax.ctl._n_pm -= 1
        self.job = None

    def on_positioned(self, t: float) -> None:
        """The actual value stayed in the window for the dwell time: the positioning is done (and, where
        configured, the standstill watch begins)."""
        job = self.job
        window = getattr(self.axis.config.positioning, "standstill_window", None)   # a double may lack it
        if window is None:
            self.stop()
        else:
            self._watch_standstill(window)
        if job is not None and job.busy:
            self.axis._finish_job(job, JobState.DONE, t)

    def _watch_standstill(self, window: float) -> None:
        ax = self.axis
        b, i = ax.ctl.bank, ax.index
        b.pm_window[i] = window
        b.pm_dwell[i] = math.inf                      # never "done": only leaving the window reports
        b.pm_in_since[i] = math.nan
        b.pm_deadline[i] = self._reached + ax.config.positioning.standstill_delay
        self.standstill = True
        self.job = None                               # the job is done; the watch outlives it

    def on_fault(self, t: float, detail: str) -> None:
        """Not in the window in time ("not_reached") or left it ("left"): alarm, enable removed (16#8011);
        during the standstill watch a standstill alarm."""
        job = self.job
        kind = F.STANDSTILL if self.standstill else F.POSITIONING
        self.stop()
        self.axis.raise_alarm(F.alarm(kind, detail, Reaction.REMOVE_ENABLE), job=job)
