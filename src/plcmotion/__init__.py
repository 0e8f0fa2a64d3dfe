"""plcmotion: a soft motion controller with PLC technology objects and motion instructions.

>>> from plcmotion import Controller
>>> from plcmotion.s7_1200 import MC_Power, MC_MoveAbsolute
"""
from .kernel import (ConfigurationError, Controller, ControllerStopped, CycleOverrunWarning, PositioningAxis,
                     ProgramErrorWarning, RunTimeout, TagAccessError)
# the families register their technology objects with the kernel (Controller(family=...))
from .s7_1200 import technology as _s7_1200  # noqa: E402,F401
from .s7_1500 import technology as _s7_1500  # noqa: E402,F401
from .s7t import technology as _s7t  # noqa: E402,F401

__version__ = "0.1.0"


def load_project(path):
    """Read a TOML project file and return a ready :class:`Controller` (see ``plcmotion.project``)."""
    from .project import load_project as _load

    return _load(path)


__all__ = ["Controller", "ControllerStopped", "ProgramErrorWarning", "CycleOverrunWarning", "RunTimeout",
           "ConfigurationError", "TagAccessError",
           "PositioningAxis", "load_project", "__version__"]
