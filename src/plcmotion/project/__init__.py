"""Project files: a controller and its axes described in TOML.

A project file has these sections::

    [controller]                  # optional
    servo_cycle = 0.001           # s, default 0.001
    app_cycle = 0.004             # s, a whole multiple of servo_cycle, default 0.004

    [axes.Axis_1]                 # one table per positioning axis, created in file order
    type = "positioning"          # optional; the only axis type so far
    "Actor.Type" = 2              # a tag as a quoted dotted key ...
    [axes.Axis_1.DynamicLimits]   # ... or as a nested table
    MaxVelocity = 500.0
    [axes.Axis_1."Sensor[1]".ActiveHoming]
    Mode = 2

    [drives.Axis_1]               # optional: the axis's drive is on a bus (plcmotion.project.drives)
    type = "cia402"               # a CiA 402 drive on CANopen: interface, channel, node_id, mode, simulate
    interface = "socketcan"
    channel = "can0"
    node_id = 1
    mode = "csp"

    [trace]                       # optional: what ``plcmotion run`` records by default
    signals = ["Axis_1.Position", "Axis_1.Velocity"]
    every = 1                     # record every n-th servo cycle

    [inputs]                      # optional: input filters of single inputs [s] (default input_filter)
    "I0.3" = { filter = 0.0008 }

    [[switches]]                  # optional: switches placed in the simulated machine, and
    [[faults]]                    # faults played at given times (plcmotion.project_faults)

    [command_tables.Table_1]      # optional: command table technology objects (S7-1200 V6 §6)
    Command = [
        { Type = 5, Position = 100.0, Velocity = 50.0, NextStep = 1, StepCode = 1 },
        { Type = 7, Velocity = 20.0, Duration = 2.0 },
    ]

``servo_cycle`` lies in [0.1 ms, 32 ms], ``app_cycle`` is a whole multiple of it up to 1 s
(``plcmotion.kernel.runtime.SERVO_CYCLE_MIN`` ...).  ``[controller]`` may also set ``input_filter``
(default filter time of the digital inputs, 0.0064 s), ``technology_version`` (the integer 6 or 7: the
S7-1200 Motion Control version whose rules apply where they differ) and ``state_file``: where retentive
data (the absolute encoder adjustment) is kept, relative to the project file; by default
``<project>.state.json`` next to it.

Files the project names (``state_file``, a cam's ``csv``) must lie in the project file's folder or
below it; ``load_project(path, allow_outside_paths=True)`` (``plcmotion check/run
--allow-outside-paths``) also accepts ``../`` and absolute paths.  A cam CSV that is no point list is
reported by line and reason only, never by its content.

Integer settings and tags take TOML integers only (``1``, not ``1.0``).  Size limits
(``plcmotion.project_rules``) are checked before any object is built: 2 MiB and 50000
lines, 1000 technology objects, lists of 4096 items, 12 levels of nesting, 1000 points and 50 segments per cam,
32 steps per command table.
``cycle_watchdog`` (default 100; 0 = off) is the wall-clock time the user programs of one application
cycle may take, in application cycles, and ``cycle_watchdog_stop = true`` puts the controller in STOP on
an overrun, as a CPU does when its maximum cycle time is exceeded (with the watchdog on: 0 and
``cycle_watchdog_stop = true`` together are refused).

``family = "S7-1500T"`` (or ``"S7-1500"``; default ``"S7-1200"``, the first registered family of
``plcmotion.kernel.family``) makes it an S7-1500 controller.  Its
axis tables then use the S7-1500 tag names (``plcmotion.s7_1500.technology.parameters``) and may have
``type = "synchronous"`` with ``leading_values = ["Master", { name = "Encoder", coupling = "actual" }]``,
``type = "external_encoder"`` or ``type = "leading_axis_proxy"``; cams are declared in ``[cams.<name>]``::

    [cams.Knife]
    points = [[0.0, 0.0], [180.0, 50.0], [360.0, 0.0]]    # Point[1..n]
    segments = [ { xmin = 0.0, xmax = 10.0, a0 = 0.0, a1 = 1.0 } ]
    csv = "knife.csv"                                     # or a point list file (relative to the project)
    interpolation_mode = 1                                # 0 linear, 1 cubic spline, 2 Bezier
    boundary_conditions = 1

Axis names are identifiers (letters, digits, underscore; not starting with a digit).  Inside an axis
table the keys are the tag paths of the positioning axis (``plcmotion.s7_1200.technology.parameters.SCHEMA``,
S7-1200 Motion Control V6 §12.9, plus the ``Plant.*`` parameters of the simulated machine); the
alternative spellings of the manuals (``Sensor.Sensor[1].``, ``PositionLimitsSW.``, ...) are accepted.
Tags the file does not set keep their start values.  A trace signal is ``"<axis>.<tag>"`` with any tag
``PositioningAxis.tag`` can read (status or configuration).

API:

* ``load_project(path)`` returns a ready :class:`~plcmotion.kernel.runtime.Controller` with the axes
  created, or raises :class:`ProjectError` listing every problem of the file.
* ``check_project(path)`` returns the same problems as a list of strings (empty when the file is valid).
* The trace settings travel on the returned controller as
  ``ctl.project = {"path": "<the path as given>", "trace": {"signals": [...], "every": n}}``;
  without a ``[trace]`` section the signal list is empty and ``every`` is 1.

Every problem is one line of the form ``<file>: <key path> = <value>: <what is allowed>``, where the key
path is the full path in the file (``axes.Axis_1.DynamicLimits.MaxVelocity``) and the value is shown in
TOML spelling.  Problems of the tag values come from the same checks ``Controller.add_positioning_axis``
runs (``parameters.validate``), so a file that passes here also passes there.

The family decides which objects a file may declare and which schema checks their tags
(``Family.schemas``, ``Family.factories``): a registered family is loaded without a change here.  The
package: ``loader`` (the file, ``[controller]``, ``[inputs]``, ``[trace]``), ``objects`` (axes, cams,
command tables); ``plcmotion.project_faults`` (switches, faults), ``plcmotion.project_rules`` (size limits).
"""
from __future__ import annotations

import os

from ..kernel import family as _families
from ..kernel.runtime import Controller
from ..toml_text import toml_value
from .loader import (CONTROLLER_DEFAULTS, CONTROLLER_KEYS, CYCLE_RANGES, MAX_EVERY, SECTIONS, TRACE_KEYS,
                     _Loader)
from .objects import CAM_KEYS, COUPLINGS, STEP_KEYS, TYPES, axis_types

#: the axis types of the default family, and every axis type a project file knows (former names)
AXIS_TYPES = axis_types(_families.default())
AXIS_TYPES_1500 = tuple(TYPES)


class ProjectError(ValueError):
    """A project file that cannot be loaded; ``problems`` holds one message per problem."""

    def __init__(self, path: str | os.PathLike, problems: list[str]):
        self.path = os.fspath(path)
        self.problems = list(problems)
        n = len(self.problems)
        head = f"{self.path}: {n} problem{'s' if n != 1 else ''} in the project file"
        super().__init__("\n".join([head] + ["  " + p for p in self.problems]))


def load_project(path: str | os.PathLike, *, allow_outside_paths: bool = False) -> Controller:
    """Read the project file at ``path`` and return a controller with its axes created.

    Files the project names (``state_file``, cam ``csv``) must lie in the project file's folder or
    below it; ``allow_outside_paths=True`` also accepts ``../`` and absolute paths."""
    ctl, problems = _Loader(path, allow_outside_paths).load()
    if problems:
        raise ProjectError(path, problems)
    assert ctl is not None
    return ctl


def check_project(path: str | os.PathLike, *, allow_outside_paths: bool = False) -> list[str]:
    """All problems of the project file at ``path``; an empty list when it loads."""
    ctl, problems = _Loader(path, allow_outside_paths).load()
    if ctl is not None:
        ctl.close()                              # nothing runs on a checked project: release drive buses
    return problems


__all__ = ["AXIS_TYPES", "AXIS_TYPES_1500", "SECTIONS", "ProjectError", "check_project", "load_project", "toml_value"]
