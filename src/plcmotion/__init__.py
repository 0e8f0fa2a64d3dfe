"""plcmotion: a soft motion controller with PLC technology objects and motion instructions.

>>> from plcmotion import Controller
>>> from plcmotion.s7_1200 import MC_Power, MC_MoveAbsolute
"""
from .kernel import (ConfigurationError, Controller, ControllerStopped, CycleOverrunWarning, PositioningAxis,
                     ProgramErrorWarning, RunTimeout, TagAccessError)

__version__ = "0.1.0"


def load_project(path):
    """Read a TOML project file and return a ready :class:`Controller` (see ``plcmotion.project``)."""
    from .project import load_project as _load

    return _load(path)


__all__ = ["Controller", "ControllerStopped", "ProgramErrorWarning", "CycleOverrunWarning", "RunTimeout",
           "ConfigurationError", "TagAccessError",
           "PositioningAxis", "load_project", "__version__"]
