"""The technology object sections of a project file: ``[axes.<name>]``, ``[cams.<name>]`` and
``[command_tables.<name>]`` (the file format is described in ``plcmotion.project``).

Which objects a file may declare and which schema checks their tags comes from the controller's family
(``kernel.family.Family.schemas`` and ``factories``), so a new family is loaded without a change here: a
TOML ``type`` names a kernel object kind (``TYPES``), the family's schema for that kind checks the tags,
and ``Controller.add_*`` creates the object with the family's factory.
"""
from __future__ import annotations

import json
import re
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from .. import project_rules as R
from ..kernel import family as families
from ..kernel.axis import ConfigurationError
from ..kernel.family import CAM, EXTERNAL_ENCODER, LEADING_AXIS_PROXY, POSITIONING_AXIS, SYNCHRONOUS_AXIS
from ..toml_text import key as _key
from ..toml_text import leaves as _leaves
from ..toml_text import quoted as _quoted
from ..toml_text import toml_value

if TYPE_CHECKING:  # pragma: no cover
    from ..kernel.runtime import Controller
    from .loader import _Loader

#: the ``type`` of an axis table -> the kernel kind of technology object (``kernel.family``)
TYPES = {"positioning": POSITIONING_AXIS, "synchronous": SYNCHRONOUS_AXIS, "external_encoder": EXTERNAL_ENCODER,
         "leading_axis_proxy": LEADING_AXIS_PROXY}
STEP_KEYS = ("Type", "Position", "Velocity", "Duration", "NextStep", "StepCode")
COUPLINGS = ("setpoint", "actual", "delayed")
CAM_KEYS = ("points", "segments", "csv", "interpolation_mode", "boundary_conditions")

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")       # the rule Controller.add_positioning_axis applies


def axis_types(family: families.Family) -> tuple[str, ...]:
    """The ``type`` values an axis table of ``family`` may have: the kinds it has a schema for."""
    return tuple(t for t, kind in TYPES.items() if kind in family.schemas)


def _plural(kind: str) -> str:
    """The plural without the article: "a synchronous axis" -> "synchronous axes"."""
    noun = kind.split(" ", 1)[1]
    if noun.endswith("axis"):
        return noun[:-4] + "axes"
    return noun[:-1] + "ies" if noun.endswith("y") else noun + "s"


def _choices(names: tuple[str, ...] | list[str]) -> str:
    return " or ".join(json.dumps(n) for n in names)


def beyond_default(doc: Mapping[str, Any]) -> tuple[str, str]:
    """The objects a file declares that the default family lacks, when the file names no family ("" if
    none), and the advice which family to set (the families offering them all, the richest first)."""
    controller = doc.get("controller")
    if isinstance(controller, dict) and "family" in controller:
        return "", ""
    default = families.default()
    axes = doc.get("axes")
    types = sorted({a.get("type") for a in axes.values() if isinstance(a, dict) and isinstance(a.get("type"), str)}
                   - set(axis_types(default))) if isinstance(axes, dict) else []
    kinds = [TYPES[t] for t in types if t in TYPES]
    found = [_plural(k) for k in kinds]
    if doc.get("cams") and CAM not in default.factories:
        kinds.append(CAM)
        found.append("cams")
    if not found:
        return "", ""
    fams = [families.lookup(n) for n in families.names()]
    able = sorted((f for f in fams if f is not default and all(k in f.factories for k in kinds)),
                  key=lambda f: -len(f.factories))
    if not able:
        advice = "no registered family offers them all"
    else:
        rest = f" (or {_choices([f.name for f in able[1:]])})" if len(able) > 1 else ""
        advice = f"set family = {json.dumps(able[0].name)}{rest} in [controller]"
    return " and ".join(found), advice


# --- [command_tables.<name>] ----------------------------------------------------------------------
def load_command_tables(loader: "_Loader", ctl: "Controller", section: Any, declared: list[str]) -> None:
    if section is None:
        return
    if not isinstance(section, dict):
        loader.bad("command_tables", section, "one table [command_tables.<name>] per command table")
        return
    for name, table in section.items():
        key = f"command_tables.{_key(name)}"
        if not _NAME.match(name) or name in declared:
            loader.note(f"{key}: the name must be an identifier not used by an axis")
            continue
        if not isinstance(table, dict):
            loader.bad(key, table, "a table with Command = [ { Type = ..., ... }, ... ]")
            continue
        for extra in table:
            if extra != "Command":
                loader.unknown(f"{key}.{extra}", table[extra], "key", ["Command"])
        steps = table.get("Command", [])
        if not isinstance(steps, list) or len(steps) > 32:
            loader.bad(f"{key}.Command", steps, "a list of at most 32 steps")
            continue
        from ..s7_1200.technology.command_table import step_problems
        rows = []
        ok = True
        for n, step in enumerate(steps, start=1):
            skey = f"{key}.Command[{n}]"
            if not isinstance(step, dict):
                loader.bad(skey, step, "a table { Type = 5, Position = 100.0, Velocity = 50.0 }")
                ok = False
                continue
            for field, value, allowed in step_problems(step):
                if field not in STEP_KEYS:
                    loader.unknown(f"{skey}.{field}", value, "key", STEP_KEYS)
                else:
                    loader.bad(f"{skey}.{field}", value, allowed)
                ok = False
            rows.append(step)
        if ok:
            try:
                ctl.add_command_table(name, rows)
            except (TypeError, ValueError) as exc:
                loader.note(f"{key}: {exc}")


# --- [axes.<name>] ------------------------------------------------------------------------------
def load_axes(loader: "_Loader", ctl: "Controller", section: Any) -> list[str]:
    """Create the axes on ``ctl``; returns the names of all axis tables (valid or not)."""
    if section is None:
        return []
    if not isinstance(section, dict):
        loader.bad("axes", section, "one table [axes.<name>] per axis")
        return []
    taken: dict[tuple[str, Any], str] = {}     # (tag, value) of a unique tag -> the key path that set it first
    for name, table in section.items():
        key = f"axes.{_key(name)}"
        valid_name = bool(_NAME.match(name))
        if not valid_name:
            loader.note(f"{key}: the axis name {_quoted(name)} is not an identifier; "
                      f"allowed: letters, digits and underscores, not starting with a digit")
        if not isinstance(table, dict):
            loader.bad(key, table, f"a table of axis tags, e.g. [{key}] with \"Actor.Type\" = 2")
            continue
        _axis(loader, ctl, name, key, table, create=valid_name, taken=taken)
    names = list(section)
    for name, table in section.items():
        raw = table.get("leading_values", []) if isinstance(table, dict) else []
        for source in (raw if isinstance(raw, (list, dict)) else []):     # other kinds: reported in axis()
            source_name = source.get("name") if isinstance(source, dict) else source
            if isinstance(source_name, str) and (source_name not in names or source_name == name):
                loader.note(f"axes.{_key(name)}.leading_values: {_quoted(source_name)} is not a technology "
                          f"object of this file; allowed: {', '.join(n for n in names if n != name) or 'none'}")
    return names


def _leading_values(loader: "_Loader", key: str, value: Any) -> list[tuple[str, str]] | None:
    if isinstance(value, dict):
        value = [{"name": k, "coupling": v} for k, v in value.items()]
    if not isinstance(value, list):
        loader.bad(key, value, 'a list of names or { name = "...", coupling = "setpoint" | "actual" | "delayed" }')
        return None
    out = []
    for i, item in enumerate(value):
        if isinstance(item, str):
            out.append((item, "setpoint"))
        elif isinstance(item, dict) and isinstance(item.get("name"), str) and \
                item.get("coupling", "setpoint") in COUPLINGS and set(item) <= {"name", "coupling"}:
            out.append((item["name"], item.get("coupling", "setpoint")))
        else:
            loader.bad(f"{key}[{i}]", item, 'a name or { name = "...", coupling = "setpoint" | "actual" | "delayed" }')
            return None
    return out


def _axis(loader: "_Loader", ctl: "Controller", name: str, key: str, table: dict[str, Any], *, create: bool,
          taken: dict[tuple[str, Any], str]) -> None:
    values = dict(table)
    family = families.lookup(ctl.family)
    types = axis_types(family)
    kind = values.pop("type", types[0] if types else "positioning")
    if kind not in types:
        loader.bad(f"{key}.type", kind, "one of " + ", ".join(json.dumps(t) for t in types) if types else
                   f"none: family {ctl.family} has no schema for the technology objects of a project file")
        create = False
    leading = None
    if "leading_values" in values:
        raw = values.pop("leading_values")
        if kind != "synchronous":
            loader.note(f"{key}.leading_values: only an axis of type = \"synchronous\" has leading values")
            create = False
        else:
            leading = _leading_values(loader, f"{key}.leading_values", raw)
            # itself as leading value: reported with the other unknown sources in axes()
            create = create and leading is not None and all(source != name for source, _ in leading)
    if not types:                                     # nothing to check the tags with: reported above
        return
    # the tags of an axis of an unknown type are still checked, as the family's first kind of axis
    schema = family.schemas[TYPES[kind if kind in types else types[0]]]
    flat: dict[str, Any] = {}
    written: dict[str, str] = {}                # canonical tag path -> spelling in the file
    for path, value in _leaves(values):
        canon = schema.canonical(path)
        if isinstance(value, Mapping) and any(tag.startswith(canon + ".") for tag in schema.params):
            continue                            # an empty group of tags, e.g. [axes.A.Homing]
        if canon in written:
            first = written[canon]
            loader.note(f"{key}.{path} = {toml_value(value)}: the tag is already set by "
                      f"{key}.{first} = {toml_value(flat[first])}; set each tag once")
            create = False
            continue
        written[canon] = path
        flat[path] = value
    _cfg, issues = schema.validate(flat)
    for issue in issues:
        loader.issue(key, issue, written)
    bad = {issue.path for issue in issues}
    for canon, path in written.items():
        # a tag no two objects may share (``Param.unique``): checked across the tables, also those with problems
        param = schema.params.get(canon)
        value = flat[path]
        if param is None or not param.unique or canon in bad or value is None or isinstance(value, (dict, list)):
            continue
        first = taken.setdefault((canon, value), f"{key}.{path}")
        if first != f"{key}.{path}":
            loader.note(f"{key}.{path} = {toml_value(value)}: allowed: a value no other object of the file has; "
                        f"{first} = {toml_value(value)}")
            create = False
    if issues or not create:
        return
    try:
        where = f"{loader.label}: {key}"
        kind = TYPES[kind]
        if kind == SYNCHRONOUS_AXIS:
            ctl.add_synchronous_axis(name, flat, leading_values=leading or (), source=where)
        elif kind == EXTERNAL_ENCODER:
            ctl.add_external_encoder(name, flat, source=where)
        elif kind == LEADING_AXIS_PROXY:
            ctl.add_leading_axis_proxy(name, flat, source=where)
        else:
            ctl.add_positioning_axis(name, flat, source=where)
    except ConfigurationError as exc:
        for issue in exc.issues:
            loader.issue(key, issue, written)
    except Exception as exc:  # noqa: BLE001 - report, never a traceback out of a project file
        loader.note(f"{key}: the axis could not be created: {type(exc).__name__}: {exc}")


# --- [cams.<name>] -------------------------------------------------------------------------------
def load_cams(loader: "_Loader", ctl: "Controller", section: Any, declared: list[str]) -> None:
    if section is None:
        return
    if not isinstance(section, dict):
        loader.bad("cams", section, "one table [cams.<name>] per cam")
        return
    if not ctl.offers(CAM):
        offering = families.offering(CAM)
        loader.note(f"cams: cams need family = {_choices(offering)} in [controller]" if offering else
                    "cams: no registered family offers cams")
        return
    from ..cams.builder import SEGMENT_FIELDS
    for name, table in section.items():
        key = f"cams.{_key(name)}"
        if not _NAME.match(name) or name in declared:
            loader.note(f"{key}: the name must be an identifier not used by an axis")
            continue
        if not isinstance(table, dict):
            loader.bad(key, table, "a table with points, segments, interpolation_mode, boundary_conditions")
            continue
        ok = True
        for extra, value in table.items():
            if extra not in CAM_KEYS:
                loader.unknown(f"{key}.{extra}", value, "key", CAM_KEYS)
                ok = False
        points = table.get("points", [])
        if not isinstance(points, list):
            loader.bad(f"{key}.points", points, "a list of [x, y] number pairs")
            ok, points = False, []
        elif (bad := R.point_problem(points)) is not None:
            i, allowed = bad
            if i is None:
                loader.note(f"{key}.points: {len(points)} points; allowed: {allowed}")
            else:
                loader.bad(f"{key}.points[{i}]", points[i], allowed)
            ok, points = False, []
        if "csv" in table:
            path = table["csv"]
            if not isinstance(path, str):
                loader.bad(f"{key}.csv", path, "a file name relative to the project file")
                ok = False
            elif (where := loader.inside(f"{key}.csv", path)) is None:
                ok = False
            else:
                from ..cams.io import PointListError, import_points
                try:
                    # a file that is no point list is named with line and reason, never its content
                    read = [list(p) for p in import_points(where, show_content=False,
                                                           max_points=R.MAX_CAM_POINTS)]
                except PointListError as exc:
                    loader.note(f"{key}.csv = {toml_value(path)}: {exc}")
                    ok = False
                except OSError as exc:
                    loader.note(f"{key}.csv = {toml_value(path)}: cannot read the file: {exc.strerror or exc}")
                    ok = False
                else:
                    if ok and (bad := R.point_problem(points + read)) is not None:
                        at = "" if bad[0] is None else f" (at point {bad[0] + 1} of both together)"
                        loader.bad(f"{key}.csv", path, "points that continue the points of the table: "
                                 + bad[1] + at)
                        ok = False
                    points = points + read
        segments = table.get("segments", [])
        if not isinstance(segments, list):
            loader.bad(f"{key}.segments", segments, "a list of tables with " + ", ".join(SEGMENT_FIELDS))
            ok, segments = False, []
        elif (bad := R.segment_problem(segments, SEGMENT_FIELDS)) is not None:
            i, allowed = bad
            if i is None:
                loader.note(f"{key}.segments: {len(segments)} segments; allowed: {allowed}")
            else:
                loader.bad(f"{key}.segments[{i}]", segments[i], allowed)
            ok, segments = False, []
        settings = {}
        for field, allowed in (("interpolation_mode", (0, 1, 2)), ("boundary_conditions", (0, 1))):
            value = table.get(field, 0)
            if type(value) is not int or value not in allowed:      # 1.0 is a float in TOML: refused
                loader.bad(f"{key}.{field}", value, "the integer " + " or ".join(map(str, allowed)))
                ok = False
            settings[field] = value
        if ok:
            try:
                ctl.add_cam(name, [tuple(p) for p in points], segments, **settings)
            except (TypeError, ValueError) as exc:
                loader.note(f"{key}: {exc}")
