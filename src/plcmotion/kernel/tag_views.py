"""Tags of a technology object as attributes and as string paths, in its family's names.

``axis.StatusBits.Enable``, ``axis.DynamicDefaults.Jerk`` and ``axis.Sensor[1].ActiveHoming.Mode`` read the
same values as ``axis.tag("StatusBits.Enable")`` etc.  Status tags are computed when read by the getters
the family declares (nothing is copied per cycle); configuration tags are the values of the family's
schema, which the user program may assign where the schema grants write access.  The module knows no
tag: the vocabularies are the families' (``s7_1200.technology.tags``, ``s7_1500.technology.tags``).
"""
from __future__ import annotations

import difflib
import functools
from typing import Any, Callable, Protocol

from .schema import P as PLANT


class TagAccessError(AttributeError):
    """Writing a tag the user program may not write (a status tag, or access R or WP)."""


class TagHost(Protocol):
    """What the views need of a technology object."""

    name: str
    schema: Any
    cfg: dict[str, Any]
    _dynamic: dict[str, Callable[[Any], Any]]
    _read_param_tags: frozenset[str]

    def tag(self, path: str) -> Any: ...

    def write_tag(self, path: str, value: Any) -> None: ...


class TagRef:
    """A reference to one tag of an axis, what a VARIANT pointer to ``<axis>.<tag>`` is in a PLC program
    (used by MC_ReadParam / MC_WriteParam).  Create it with ``axis.ref("StatusBits.Enable")``."""

    __slots__ = ("axis", "path", "data_type", "status")

    def __init__(self, axis: "TagHost", path: str, data_type: str, status: bool):
        self.axis, self.path, self.data_type, self.status = axis, path, data_type, status

    def read(self) -> Any:
        return self.axis.tag(self.path)

    @property
    def readable_by_read_param(self) -> bool:
        return self.status and self.path in self.axis._read_param_tags

    @property
    def access(self) -> str:
        """Access right of §12.9: 'RP' status tags, 'RW', 'WP', 'R' configuration tags."""
        if self.status:
            return "RP" if self.path in self.axis._read_param_tags else "RCCP"
        access_of = getattr(self.axis, "tag_access", None)
        return access_of(self.path) if access_of is not None else self.axis.schema.params[self.path].access

    def __repr__(self) -> str:
        return f"<TagRef {self.axis.name}.{self.path} : {self.data_type}>"


class _StatusView:
    """Read-only view of a status structure (StatusBits, ErrorBits, ...)."""

    __slots__ = ("_axis", "_prefix")

    def __init__(self, axis: "TagHost", prefix: str):
        object.__setattr__(self, "_axis", axis)
        object.__setattr__(self, "_prefix", prefix)

    def __getattr__(self, name: str) -> Any:
        path = f"{self._prefix}.{name}"
        getter = self._axis._dynamic.get(path)
        if getter is None:
            if any(k.startswith(path + ".") for k in self._axis._dynamic):
                return _StatusView(self._axis, path)          # nested structure
            raise AttributeError(_unknown(self._axis, path))
        return getter(self._axis)

    def __getitem__(self, key: int) -> "_StatusView":
        path = f"{self._prefix}[{key}]"
        if not any(k.startswith(path + ".") for k in self._axis._dynamic):
            raise IndexError(f"{self._axis.name}.{path} does not exist")
        return _StatusView(self._axis, path)

    def __setattr__(self, name: str, value: Any) -> None:
        raise TagAccessError(f"{self._axis.name}.{self._prefix}.{name} is a status tag and cannot be written")

    def __dir__(self) -> list[str]:
        n = len(self._prefix) + 1
        return [k[n:] for k in self._axis._dynamic if k.startswith(self._prefix + ".")]

    def as_dict(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in self.__dir__()}

    def __repr__(self) -> str:
        return f"{self._axis.name}.{self._prefix}({self.as_dict()})"


class _ConfigView:
    """View of a configuration structure; assignment goes through the access rules."""

    __slots__ = ("_axis", "_prefix", "_tree")

    def __init__(self, axis: "TagHost", prefix: str, tree: dict):
        object.__setattr__(self, "_axis", axis)
        object.__setattr__(self, "_prefix", prefix)
        object.__setattr__(self, "_tree", tree)

    def __getattr__(self, name: str) -> Any:
        node = self._tree.get(name)
        if node is None:
            getter = self._axis._dynamic.get(f"{self._prefix}.{name}")
            if getter is not None:                  # a read-only tag inside a configuration structure
                return getter(self._axis)
            raise AttributeError(_unknown(self._axis, f"{self._prefix}.{name}"))
        if isinstance(node, dict):
            return _ConfigView(self._axis, f"{self._prefix}.{name}", node)
        return self._axis.cfg[node]

    def __setattr__(self, name: str, value: Any) -> None:
        node = self._tree.get(name)
        if node is None or isinstance(node, dict):
            raise AttributeError(_unknown(self._axis, f"{self._prefix}.{name}"))
        self._axis.write_tag(node, value)

    def __getitem__(self, key: int) -> "_ConfigView":
        name = f"{self._prefix.rsplit('.', 1)[-1]}[{key}]"
        raise TypeError(f"{self._prefix} is not an array ({name})")

    def __dir__(self) -> list[str]:
        return list(self._tree)

    def __repr__(self) -> str:
        return f"{self._axis.name}.{self._prefix}"


class _ArrayView:
    """A configuration structure that is an array (``axis.Sensor[1]``); ``axis.Sensor.Sensor[1]`` is the
    spelling of some manual tables for the same element."""

    __slots__ = ("_axis", "_name")

    def __init__(self, axis: "TagHost", name: str):
        self._axis = axis
        self._name = name

    def __getitem__(self, key: int) -> _ConfigView:
        schema = self._axis.schema
        node = schema.tree.get(f"{self._name}[{key}]")
        if node is None:
            have = ", ".join(k for k in schema.tree if k.startswith(self._name + "["))
            raise IndexError(f"{self._axis.name}.{self._name}[{key}]: the {schema.title} has {have}")
        return _ConfigView(self._axis, f"{self._name}[{key}]", node)

    def __getattr__(self, name: str) -> "_ArrayView":
        if name == self._name:
            return self
        raise AttributeError(name)


def _unknown(axis: "TagHost", path: str) -> str:
    candidates = list(axis._dynamic) + list(axis.schema.params)
    near = difflib.get_close_matches(path, candidates, n=3, cutoff=0.6)
    hint = f"; did you mean {' or '.join(near)}?" if near else ""
    return f"{axis.name}.{path} is not a tag of the {axis.schema.title}{hint}"


class TagViews:
    """Attribute and string-path access to the tags of a technology object, in its family's names.

    The family's class declares its vocabulary: the status tags (``_dynamic``: path -> getter, their data
    types, alias spellings, the status structures ``_status_groups`` and the tags MC_ReadParam may read)
    and the configuration ``schema``; this class presents them as ``obj.StatusBits.Enable``,
    ``obj.Sensor[1].ActiveHoming.Mode``, ``obj.tag(path)`` and ``obj.ref(path)``.
    """

    _dynamic: dict[str, Callable[[Any], Any]] = {}
    _dynamic_types: dict[str, str] = {}
    _dynamic_aliases: dict[str, str] = {}
    _status_groups: tuple[str, ...] = ()
    _read_param_tags: frozenset[str] = frozenset()

    def __getattr__(self, name: str) -> Any:
        # only called for names not found normally: status and configuration structures
        if name.startswith("__"):
            raise AttributeError(name)
        if name in ("schema", "_dynamic"):
            raise AttributeError(name)            # not set up yet (during __init__)
        dynamic = self._dynamic
        if name in self._status_groups or any(k.startswith(name + "[") for k in dynamic):
            return _StatusView(self, name)  # type: ignore[arg-type]
        if name in dynamic:
            return dynamic[name](self)
        tree = self.schema.tree  # type: ignore[attr-defined]
        node = tree.get(name)
        if isinstance(node, dict):
            return _ConfigView(self, name, node)  # type: ignore[arg-type]
        if any(k.startswith(name + "[") for k in tree):
            return _ArrayView(self, name)  # type: ignore[arg-type]
        raise AttributeError(f"{type(self).__name__} has no attribute {name!r}")

    # --- string paths ----------------------------------------------------------------------------------
    def tag(self, path: str) -> Any:
        """Value of the tag at ``path`` (e.g. ``"StatusBits.Enable"``, ``"Sensor[1].ActiveHoming.Mode"``)."""
        return self.tag_getter(path)()

    def tag_getter(self, path: str) -> Callable[[], Any]:
        """A function returning the current value of the tag at ``path`` (fast repeated reads)."""
        canon = self._dynamic_aliases.get(path, path)
        getter = self._dynamic.get(canon)
        if getter is not None:
            return functools.partial(getter, self)    # no Python frame of its own: traces call it per sample
        word, _, bit = canon.rpartition(".")
        word_getter = self._dynamic.get(word)
        if word_getter is not None and bit:
            value = word_getter(self)  # type: ignore[arg-type]
            if hasattr(value, "bits"):                    # a bit of a status word: "StatusWord.X22"
                try:
                    getattr(value, bit)
                except AttributeError:
                    names = list(value.bits())
                    close = difflib.get_close_matches(bit, names, n=1, cutoff=0.6)
                    hint = f" (did you mean {word}.{close[0]}?)" if close else ""
                    raise KeyError(f"{self.name}.{path}: {word} has no bit {bit!r}{hint}; allowed: X0 .. X31 "  # type: ignore[attr-defined]
                                   f"or a bit name: {', '.join(names)}") from None
                return lambda: getattr(word_getter(self), bit)  # type: ignore[arg-type]
        schema = self.schema  # type: ignore[attr-defined]
        canon = schema.canonical(path)
        if canon in schema.params and schema.params[canon].access != PLANT:
            return lambda: self.cfg[canon]  # type: ignore[attr-defined]
        raise KeyError(_unknown(self, path))  # type: ignore[arg-type]

    def ref(self, path: str) -> TagRef:
        """A reference to the tag at ``path`` (for MC_ReadParam / MC_WriteParam)."""
        canon = self._dynamic_aliases.get(path, path)
        if canon in self._dynamic:
            return TagRef(self, canon, self._dynamic_types[canon], True)  # type: ignore[arg-type]
        schema = self.schema  # type: ignore[attr-defined]
        canon = schema.canonical(path)
        if canon in schema.params and schema.params[canon].access != PLANT:
            return TagRef(self, canon, schema.data_type(canon), False)  # type: ignore[arg-type]
        raise KeyError(_unknown(self, path))  # type: ignore[arg-type]

    def set_tag(self, path: str, value: Any) -> None:
        """Assign a tag by path with the access rules of direct assignment in the user program."""
        self.write_tag(path, value)  # type: ignore[attr-defined]

    @classmethod
    def tag_paths(cls) -> list[str]:
        """All tag paths of the technology object (status and configuration)."""
        return list(cls._dynamic) + [p for p, prm in cls.schema.params.items() if prm.access != PLANT]  # type: ignore[attr-defined]
