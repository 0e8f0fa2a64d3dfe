"""The ``[[switches]]`` and ``[[faults]]`` sections of a project file (virtual commissioning).

Both go through the public API a Python program uses - ``Controller.plant.place_switch``,
``axis.inject_fault`` / ``clear_fault`` / ``disturb_load``, ``Switch.stick`` / ``chatter`` / ``repair`` and
``Controller.plant.scenario.at`` - and every entry is checked while the file is loaded, so a fault cannot
fail while the controller runs.  Shapes (docs/fault_injection.md)::

    [[switches]]
    input = "I0.5"                 # the input it is wired to
    axis = "Axis_1"                # whose machine position actuates it
    low = 100.0                    # actuated in [low, high]; one of the two may be left out
    high = 110.0
    active_high = true             # optional, default true (false: NC contact)
    period = 360.0                 # optional: repeats every period
    name = "part present"          # optional

    [[faults]]
    at = 0.5                       # controller time [s]
    axis = "Axis_1"
    inject = "communication_loss"  # drive, encoder, drive_not_ready, encoder_loss, communication_loss
    detail = ""                    # optional (drive, encoder)
    persistent = true              # optional: stays until a "clear" entry

    # other actions, one per entry: load = { jump = 2.0, force = 20.0, blocked = true } (axis),
    # clear = "communication_loss" | "load" | "all" (axis), switch = "stuck_actuated" | "stuck_released" |
    # "chatter" | "repair" with input = "I0.2" (and period = 0.02 for chatter)

Each entry has exactly one action and only the keys that action uses (``ACTION_KEYS``); any other key, a time
outside [0, 1e12] s or a number beyond float range is a message with its key path.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Callable

from .kernel.fault_injection import KINDS, check_load

if TYPE_CHECKING:  # pragma: no cover
    from .kernel.runtime import Controller
    from .project import _Loader

SWITCH_KEYS = ("input", "axis", "low", "high", "active_high", "period", "name")
FAULT_KEYS = ("at", "axis", "input", "inject", "detail", "persistent", "load", "clear", "switch", "period")
ACTIONS = ("inject", "load", "clear", "switch")
LOAD_KEYS = ("jump", "force", "blocked")
ACTION_KEYS = {"inject": ("at", "axis", "inject", "detail", "persistent"), "load": ("at", "axis", "load"),
               "clear": ("at", "axis", "clear"), "switch": ("at", "input", "switch")}    # + period for chatter
SWITCH_ACTIONS = ("stuck_actuated", "stuck_released", "chatter", "repair")
MAX_ENTRIES = 10_000
MAX_TIME = 1e12            # FaultScenario.at's range [s]


def _number(value: Any) -> bool:
    """A finite TOML number (an int beyond float range is none: math.isfinite would overflow)."""
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:
        return False


def _entries(loader: "_Loader", name: str, section: Any) -> list[tuple[str, dict]]:
    if section is None:
        return []
    if not isinstance(section, list) or not all(isinstance(e, dict) for e in section):
        loader.bad(name, section, f"an array of tables [[{name}]]")
        return []
    if len(section) > MAX_ENTRIES:
        loader.note(f"{name}: {len(section)} entries; allowed: at most {MAX_ENTRIES}")
        return []
    return [(f"{name}[{i}]", e) for i, e in enumerate(section)]


def _axis(loader: "_Loader", ctl: "Controller", key: str, entry: dict, declared: list[str]) -> Any:
    name = entry.get("axis")
    axes = [n for n in declared if n in ctl.axes or ctl._lookup(n) is None]
    if not isinstance(name, str) or name not in axes:
        other = ctl._lookup(name) if isinstance(name, str) else None
        what = (f" ({name} is of type {type(other).__name__}; faults act on the drive and load of an axis)"
                if other else "")
        loader.bad(f"{key}.axis", name, "the name of a positioning or synchronous axis of this file: "
                   + (", ".join(axes) or "none") + what)
        return None
    return ctl.axes.get(name)           # None when the axis table itself has problems (reported there)


def load_switches(loader: "_Loader", ctl: "Controller", section: Any, declared: list[str]) -> None:
    """``[[switches]]``: place each switch with ``ctl.plant.place_switch``."""
    for key, entry in _entries(loader, "switches", section):
        for k, v in entry.items():
            if k not in SWITCH_KEYS:
                loader.unknown(f"{key}.{k}", v, "key", SWITCH_KEYS)
        axis = _axis(loader, ctl, key, entry, declared)
        ok = True
        for k in ("low", "high", "period"):
            if k in entry and not _number(entry[k]):
                loader.bad(f"{key}.{k}", entry[k], "a finite number" + (" > 0" if k == "period" else ""))
                ok = False
        for k, kind in (("input", str), ("name", str), ("active_high", bool)):
            if k in entry and not isinstance(entry[k], kind):
                loader.bad(f"{key}.{k}", entry[k], {"input": "an input address like \"I0.5\"",
                                                    "name": "a string", "active_high": "true or false"}[k])
                ok = False
        if "input" not in entry:
            loader.note(f"{key}: the input is missing; allowed: input = \"I<byte>.<bit>\", e.g. \"I0.5\"")
            ok = False
        if not ok or axis is None:
            continue
        try:
            ctl.plant.place_switch(entry["input"], axis=axis, low=entry.get("low", -math.inf),
                                   high=entry.get("high", math.inf), active_high=entry.get("active_high", True),
                                   period=entry.get("period"), name=entry.get("name", "switch"))
        except (TypeError, ValueError) as exc:
            loader.note(f"{key}: {exc}")


def load_faults(loader: "_Loader", ctl: "Controller", section: Any, declared: list[str]) -> None:
    """``[[faults]]``: check each entry, then schedule it on ``ctl.plant.scenario``."""
    for key, entry in _entries(loader, "faults", section):
        for k, v in entry.items():
            if k not in FAULT_KEYS:
                loader.unknown(f"{key}.{k}", v, "key", FAULT_KEYS)
        at = entry.get("at")
        if not _number(at) or not 0 <= at <= MAX_TIME:
            loader.bad(f"{key}.at", at, f"the controller time [s] of the fault, in [0, {MAX_TIME:g}]")
            continue
        actions = [a for a in ACTIONS if a in entry]
        if len(actions) != 1:
            loader.note(f"{key}: give exactly one action of {', '.join(ACTIONS)} (found {len(actions)})")
            continue
        used = ACTION_KEYS[actions[0]] + (("period",) if entry.get("switch") == "chatter" else ())
        unused = [k for k in entry if k in FAULT_KEYS and k not in used]
        for k in unused:                # a key the action ignores is a mistake in the file, not a no-op
            loader.note(f"{key}.{k}: not used by this {actions[0]} entry; its keys: {', '.join(used)}")
        if unused:
            continue
        action = _action(loader, ctl, key, entry, actions[0], declared)
        if action is not None:
            what = f"{key}: {actions[0]} {entry[actions[0]]!r}"
            ctl.plant.scenario.at(float(at), action, what)


def _action(loader: "_Loader", ctl: "Controller", key: str, entry: dict, action: str,
            declared: list[str]) -> Callable[[], Any] | None:
    value = entry[action]
    if action == "switch":
        address = entry.get("input")
        try:
            switch = ctl.plant.switch(address)
        except (KeyError, TypeError, ValueError) as exc:
            loader.bad(f"{key}.input", address, f"an input with a switch of the plant ({exc.args[0]})")
            return None
        if value not in SWITCH_ACTIONS:
            loader.bad(f"{key}.switch", value, ", ".join(SWITCH_ACTIONS))
            return None
        if value == "chatter":
            period = entry.get("period")
            if not _number(period) or not 0 < period <= 3600:
                loader.bad(f"{key}.period", period, "the chatter period in (0, 3600] s")
                return None
            start = float(entry["at"])
            return lambda: switch.chatter(float(period), start=start)
        if value == "repair":
            return switch.repair
        return lambda: switch.stick(value == "stuck_actuated")
    axis = _axis(loader, ctl, key, entry, declared)
    if axis is None:
        return None
    if action == "inject":
        detail, persistent = entry.get("detail", ""), entry.get("persistent", False)
        if value not in KINDS:
            loader.bad(f"{key}.inject", value, ", ".join(KINDS))
            return None
        if not isinstance(detail, str):
            loader.bad(f"{key}.detail", detail, "a string (see docs/fault_injection.md)")
            return None
        if not isinstance(persistent, bool):
            loader.bad(f"{key}.persistent", persistent, "true or false")
            return None
        try:
            axis.fault_injection.expand(value, detail)
        except ValueError as exc:
            loader.note(f"{key}: {exc}")
            return None
        return lambda: axis.inject_fault(value, detail, persistent=persistent)
    if action == "clear":
        if value not in KINDS + ("load", "all"):
            loader.bad(f"{key}.clear", value, ", ".join(KINDS + ("load", "all")))
            return None
        return lambda: axis.clear_fault(None if value == "all" else value)
    if not isinstance(value, dict) or not value or any(k not in LOAD_KEYS for k in value):
        loader.bad(f"{key}.load", value, "a table with jump, force and/or blocked, e.g. { jump = 2.0 }")
        return None
    try:
        check_load(axis, value.get("jump", 0.0), value.get("force"), value.get("blocked"))
    except (TypeError, ValueError) as exc:
        loader.note(f"{key}.load: {exc}")
        return None
    return lambda: axis.disturb_load(**value)
