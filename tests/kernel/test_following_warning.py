"""The following error warning (``FollowingErrorMonitoring.warning_level``): an axis class that reports it
(``reports_following_warning``) hears once each time the following error rises above that share of the
admissible following error; other axes are not watched for it (the check runs only while one such axis
exists).  S7-Technology V4.1 §4.5.11.3 (warning limit, ErrorID 8017 in that family); the admissible following
error grows linearly with the velocity (§4.5.11.3, S7-1200 V6 §5.4.4.6).
"""
from __future__ import annotations

from dataclasses import replace

import pytest

from plcmotion import Controller
from plcmotion.kernel import family as families
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.jobs import Job, JobKind

from ._schema_axis import with_schema

DT = 0.001
PARAMS = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0, "DynamicDefaults.Acceleration": 200.0,
          "DynamicDefaults.Deceleration": 200.0, "DynamicDefaults.Jerk": 0.0}


class WarningAxis(PositioningAxis):
    reports_following_warning = True

    def _on_following_warning(self, t: float) -> None:
        self.warned_at = getattr(self, "warned_at", []) + [t]


@pytest.fixture(scope="module")
def family():
    axis_class = with_schema(WarningAxis, PARAMS)
    fam = families.register(families.Family(
        "Kernel-Following-Warning", versions=(1,), default_version=1,
        factories={families.POSITIONING_AXIS: lambda ctl, name, flat, where: ctl.new_axis(axis_class, name, flat,
                                                                                        where)}))
    yield fam.name
    families._REGISTRY.pop(fam.name)


def _moving(family: str | None, level: float | None):
    ctl = Controller(servo_cycle=DT) if family is None else Controller(family=family, servo_cycle=DT)
    axis = ctl.add_positioning_axis("Axis_1", PARAMS)
    fe = replace(axis.config.following_error, enabled=True, min_value=10.0, max_value=10.0, warning_level=level)
    axis.config = replace(axis.config, following_error=fe)
    axis._apply_bank_config()
    assert axis.power(object(), True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 5.0)
    axis.submit(Job(JobKind.VELOCITY, velocity=20.0))
    ctl.run(0.5)
    return ctl, axis


def test_kernel_following_warning_once_per_excursion(family):
    """A blocked drive at 20/s: the following error passes 50 % of the admissible 10 (5) after about
    0.25 s - one report, none more while it stays above; the error itself (10) follows later."""
    ctl, axis = _moving(family, 50.0)
    assert ctl._n_few == 1 and not getattr(axis, "warned_at", [])
    axis.drive.disturb(blocked=True)
    t0 = ctl.time
    ctl.run(0.4)
    assert len(axis.warned_at) == 1
    assert axis.warned_at[0] - t0 == pytest.approx(0.25, abs=0.03)
    assert axis.alarms == []
    ctl.run(0.4)
    assert len(axis.warned_at) == 1 and axis.alarms


def test_kernel_following_warning_not_with_the_error(family):
    """A warning level of 100 %: the warning would come in the same cycle as the error, which supersedes it."""
    ctl, axis = _moving(family, 100.0)
    axis.drive.disturb(blocked=True)
    ctl.run(0.8)
    assert axis.alarms and not getattr(axis, "warned_at", [])


def test_kernel_following_warning_off_without_level_or_flag(family):
    """No warning level, or an axis class that does not report it (the default family's): nothing watched."""
    ctl, axis = _moving(family, None)
    assert ctl._n_few == 0
    ctl2, plain = _moving(None, 50.0)
    assert ctl2._n_few == 0
    plain.drive.disturb(blocked=True)
    ctl2.run(0.4)
    assert not hasattr(plain, "warned_at")
