"""``[drives.<axis>]``: an axis of the project driven by a real (or simulated) drive on a bus instead of the
simulated drive its tags describe.  Family-neutral: the axis's family tags still give units, dynamics,
monitoring and mechanics; the table says where the drive is::

    [drives.Axis_1]
    type = "cia402"               # a CiA 402 drive on CANopen (the only kind so far)
    interface = "socketcan"       # python-can interface; "virtual" for tests and demos
    channel = "can0"
    node_id = 1                   # 1..127
    mode = "csp"                  # csp | csv | cst | pp | pv
    simulate = false              # true: start a simulated CiA 402 drive with this node id on the bus
    heartbeat_ms = 100            # producer heartbeat time written to the drive, 0 = off
    # bitrate, eds (relative to the project file), increments_per_revolution, speed_gain, realtime

The axis must be a drive axis (a servo with an encoder) in its family's tags.  The keys and their ranges:
``plcmotion.drives.cia402.FIELDS``; docs/drives/cia402.md.
"""
from __future__ import annotations

import importlib.util
import os
from typing import TYPE_CHECKING, Any

from ..drives.cia402 import FIELDS, Cia402Link, LinkError
from ..toml_text import key as _key
from ..toml_text import toml_value

if TYPE_CHECKING:
    from ..kernel.runtime import Controller
    from .loader import _Loader

KINDS = ("cia402",)


def load_drives(loader: "_Loader", ctl: "Controller", section: Any, axes: Any) -> None:
    """Connect the drives of ``[drives]`` to ``ctl`` (before the axes are created); problems go to ``loader``."""
    if section is None:
        return
    if not isinstance(section, dict):
        loader.bad("drives", section, "one table [drives.<axis>] per axis whose drive is on a bus")
        return
    names = list(axes) if isinstance(axes, dict) else []
    used: dict[tuple[str, str, int], str] = {}
    for name, table in section.items():
        key = f"drives.{_key(name)}"
        if name not in names:
            loader.note(f"{key}: there is no axis {toml_value(name)} in [axes]; allowed: "
                        + (", ".join(names) if names else "none, the file has no [axes.<name>] table"))
            continue
        if not isinstance(table, dict):
            loader.bad(key, table, 'a table with type = "cia402", interface, channel, node_id and mode')
            continue
        kind = table.get("type")
        if kind not in KINDS:
            loader.bad(f"{key}.type", kind, ", ".join(f'"{k}"' for k in KINDS))
            continue
        link = _link(loader, key, table)
        if link is None:
            continue
        bus = (link.interface, link.channel, link.node_id)
        if bus in used:
            loader.note(f"{key}.node_id = {link.node_id}: node {link.node_id} on {link.interface}/{link.channel} "
                        f"drives axis {used[bus]} already; each axis needs a node of its own")
            continue
        used[bus] = name
        ctl.connect_drive(name, link)


def _link(loader: "_Loader", key: str, table: dict[str, Any]) -> Cia402Link | None:
    values = {k: v for k, v in table.items() if k != "type"}
    bad = False
    for k, v in values.items():
        if k not in FIELDS:
            loader.unknown(f"{key}.{k}", v, "key", list(FIELDS))
            bad = True
    if "eds" in values:
        if not isinstance(values["eds"], str) or not values["eds"]:
            loader.bad(f"{key}.eds", values["eds"], "the path of an EDS file, relative to the project file")
            return None
        where = loader.inside(f"{key}.eds", values["eds"])
        if where is None:
            return None
        values["eds"] = os.fspath(where)
    if bad:
        return None
    try:
        link = Cia402Link(**values)
    except LinkError as exc:
        loader.note(f"{key}.{exc}")
        return None
    if importlib.util.find_spec("canopen") is None or importlib.util.find_spec("can") is None:
        loader.note(f"{key}: a CiA 402 drive needs the packages canopen and python-can "
                    "(pip install 'plcmotion[cia402]')")
        return None
    return link
