"""The acceleration override of the neutral configuration (``DynamicDefaults.acceleration_override``): a
motion's acceleration and deceleration are scaled by it, an emergency stop is not, and the dynamic limits
still hold.  Expected values: the percentages applied by hand."""
from __future__ import annotations

from types import SimpleNamespace

from plcmotion.kernel.axis_config import DynamicDefaults, DynamicLimits
from plcmotion.kernel.jobs import Job, JobKind
from plcmotion.kernel.motion import limits


def _axis(override: float | None, max_acc: float | None = None) -> SimpleNamespace:
    # limits() reads the dynamic groups of the configuration only
    cfg = SimpleNamespace(defaults=DynamicDefaults(acceleration=40.0, deceleration=80.0, emergency_deceleration=500.0,
                                                   acceleration_override=override),
                          limits=DynamicLimits(max_velocity=100.0, max_acceleration=max_acc, max_deceleration=max_acc))
    return SimpleNamespace(config=cfg, pto=False)


def test_kernel_acceleration_override_scales_defaults_and_job_dynamics():
    lim = limits(_axis(50.0), 10.0)
    assert (lim.acceleration, lim.deceleration) == (20.0, 40.0)
    job = Job(JobKind.VELOCITY, velocity=10.0)
    job.acceleration, job.deceleration = 10.0, 30.0
    lim = limits(_axis(250.0), 10.0, job=job)
    assert (lim.acceleration, lim.deceleration) == (25.0, 75.0)


def test_kernel_acceleration_override_none_changes_nothing():
    lim = limits(_axis(None), 10.0)
    assert (lim.acceleration, lim.deceleration) == (40.0, 80.0)


def test_kernel_acceleration_override_leaves_emergency_stop_and_limits():
    lim = limits(_axis(10.0), 10.0, emergency=True)
    assert lim.deceleration == 500.0
    lim = limits(_axis(1000.0, max_acc=100.0), 10.0)
    assert (lim.acceleration, lim.deceleration) == (100.0, 100.0)
    assert "acceleration" in lim.limited and "deceleration" in lim.limited
