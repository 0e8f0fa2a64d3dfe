"""Kernel: runtime, technology objects, motion jobs, profiles and monitoring.

The kernel knows no dialect, file format or network; dialects (``plcmotion.s7_1200``) map their
instructions onto its jobs and its faults onto their ErrorIDs.
"""
from .axis import ConfigurationError, PositioningAxis
from .tag_views import TagAccessError
from .faults import Fault, Reaction
from .jobs import Job, JobKind, JobState
from .runtime import RUN, STOP, Controller, ControllerStopped, ProgramErrorWarning, RunTimeout
from .watchdog import CycleOverrunWarning, Overrun

__all__ = ["Controller", "ControllerStopped", "ProgramErrorWarning", "CycleOverrunWarning", "Overrun", "RunTimeout",
           "ConfigurationError", "TagAccessError", "PositioningAxis", "Fault", "Reaction", "Job", "JobKind", "JobState", "RUN", "STOP"]
