"""CiA 402 drives on a CANopen bus behind the kernel's drive interface.

Connect any axis of any family to a CiA 402 drive before the axis is added::

    from plcmotion.drives.cia402 import Cia402Link
    ctl.connect_drive("Axis_1", Cia402Link(interface="socketcan", channel="can0", node_id=1, mode="csp"))
    ctl.add_positioning_axis("Axis_1", {...})          # a drive axis: units, dynamics, monitoring

or from a project file with a ``[drives.Axis_1]`` table (``plcmotion.project``).  The parts:

* ``profile`` - the CiA 402 words: controlword commands, statusword states, modes, the power state
  machine with its numbered transitions;
* ``link`` - :class:`Cia402Link`, the checked settings (bus, node, mode, ...), importable without canopen;
* ``master`` - ``Cia402Drives``, the drive group of one bus: SDO set-up, NMT, PDO mapping, the
  SYNC-driven exchange (the design of one cycle is in its docstring);
* ``channel`` - ``Cia402Channel``, one axis's drive (``axis.drive``): controlword, set values, faults and
  heartbeat supervision, drive-based homing (``home_in_drive``), ``quick_stop``;
* ``simulated`` / ``drive_core`` - ``SimulatedCia402``, a drive on the bus built on a canopen
  LocalNode with the shipped EDS (``EDS_PATH``), for tests and demos without hardware;
* ``homing`` - the homing methods of the simulated drive (1-14, 17-30, 33/34, 35/37) on its plant of limit
  switches, home switch and index pulses (``SwitchPlant``).

Determinism: the master sends its RPDOs at the end of a servo cycle and SYNC at the start of the next,
then waits (bounded) for the TPDOs every node sends on that SYNC; the simulated drive does all its work on
SYNC, moved on by the communication cycle period, so a program run in virtual time gives the same trace bit
for bit.  docs/drives/cia402.md has the set-up of a real bus and what to expect from Python timing.
"""
from __future__ import annotations

from .link import EDS_PATH, FIELDS, Cia402Link, LinkError
from .profile import AXIS_MODES, MODE_NAMES, Mode, PowerStateMachine, State

__all__ = ["AXIS_MODES", "EDS_PATH", "FIELDS", "MODE_NAMES", "Cia402Link", "LinkError", "Mode",
           "PowerStateMachine", "State"]
