"""The cam technology object (TO_Cam, S7-1500T V5 §3.2, §9.2, §A.2).

The TO holds up to 1000 points and 50 segments with their validity flags and the interpolation
settings (all "CAL" tags: written at once, used by the next MC_InterpolateCam).  Interpolation turns
them into a :class:`~plcmotion.kernel.cam.CamCurve`, which following axes evaluate every servo cycle.
Jobs on a cam (interpolate, read a leading or following value) are processed at the start of the next
servo cycle, like a job handed to MC-Servo.
"""
from __future__ import annotations

import numbers
from typing import TYPE_CHECKING, Any, Iterable, Mapping

import numpy as np

from ...kernel import faults as F
from ...kernel.cam import MAX_POINTS, MAX_SEGMENTS, CamCurve, CamDefinitionError, SegmentDef, interpolate
from ...kernel.jobs import Job, JobKind, JobState
from ...kernel.words import pack, word_type
from . import alarms as A

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

SEGMENT_FIELDS = ("xmin", "xmax", "a0", "a1", "a2", "a3", "a4", "a5", "a6", "sineAmplitude", "sinePeriod",
                  "sinePhase")
_E12 = 1.0e12

CamStatusWord = word_type("CamStatusWord", {"Control": 0, "Error": 1, "RestartActive": 2,
                                            "OnlineStartValuesChanged": 3, "CamDataChanged": 4,
                                            "Interpolated": 5, "InInterpolation": 6},
                          aliases={"RestartRequired": 3})
CamErrorWord = word_type("CamErrorWord", {"SystemFault": 0, "ConfigFault": 1, "UserFault": 2,
                                          "CommandNotAccepted": 3})
CamWarningWord = word_type("CamWarningWord", {"SystemWarning": 0, "ConfigWarning": 1, "UserWarning": 2,
                                              "CommandNotAccepted": 3})


def _real(owner: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{owner} is an LREAL tag; got {value!r}")
    return float(value)


def _bool(owner: str, value: Any) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and value in (0, 1):
        return bool(value)
    raise TypeError(f"{owner} is a BOOL tag; got {value!r}")


class _PointView:
    __slots__ = ("_cam", "_i")

    def __init__(self, cam: "CamTO", i: int):
        object.__setattr__(self, "_cam", cam)
        object.__setattr__(self, "_i", i)

    def __getattr__(self, name: str) -> float:
        if name == "x":
            return float(self._cam._px[self._i])
        if name == "y":
            return float(self._cam._py[self._i])
        raise AttributeError(f"Point has the elements x and y, not {name!r}")

    def __setattr__(self, name: str, value: Any) -> None:
        owner = f"{self._cam.name}.Point[{self._i + 1}].{name}"
        if name == "x":
            self._cam._px[self._i] = _real(owner, value)
        elif name == "y":
            self._cam._py[self._i] = _real(owner, value)
        else:
            raise AttributeError(f"Point has the elements x and y, not {name!r}")
        self._cam._changed()


class _SegmentView:
    __slots__ = ("_cam", "_i")

    def __init__(self, cam: "CamTO", i: int):
        object.__setattr__(self, "_cam", cam)
        object.__setattr__(self, "_i", i)

    def __getattr__(self, name: str) -> float:
        try:
            return float(self._cam._seg[self._i, SEGMENT_FIELDS.index(name)])
        except ValueError:
            raise AttributeError(f"Segment has the elements {', '.join(SEGMENT_FIELDS)}, not {name!r}") from None

    def __setattr__(self, name: str, value: Any) -> None:
        if name not in SEGMENT_FIELDS:
            raise AttributeError(f"Segment has the elements {', '.join(SEGMENT_FIELDS)}, not {name!r}")
        self._cam._seg[self._i, SEGMENT_FIELDS.index(name)] = _real(
            f"{self._cam.name}.Segment[{self._i + 1}].{name}", value)
        self._cam._changed()


class _Array:
    """1-based array tag (Point[1..1000], ValidSegment[1..50], ...)."""

    __slots__ = ("_cam", "_name", "_n", "_get", "_set")

    def __init__(self, cam: "CamTO", name: str, n: int, get, set_=None):
        self._cam, self._name, self._n, self._get, self._set = cam, name, n, get, set_

    def _index(self, key: Any) -> int:
        if isinstance(key, bool) or not isinstance(key, numbers.Integral) or not 1 <= key <= self._n:
            raise IndexError(f"{self._cam.name}.{self._name}[{key!r}]: index 1..{self._n}")
        return int(key) - 1

    def __getitem__(self, key: int):
        return self._get(self._index(key))

    def __setitem__(self, key: int, value: Any) -> None:
        if self._set is None:
            raise TypeError(f"{self._cam.name}.{self._name}[{key}] is a structure; assign its elements")
        self._set(self._index(key), value)

    def __len__(self) -> int:
        return self._n


class _Struct:
    __slots__ = ("_cam", "_prefix", "_fields", "_writable")

    def __init__(self, cam: "CamTO", prefix: str, fields: Mapping[str, Any], writable: bool):
        object.__setattr__(self, "_cam", cam)
        object.__setattr__(self, "_prefix", prefix)
        object.__setattr__(self, "_fields", fields)
        object.__setattr__(self, "_writable", writable)

    def __getattr__(self, name: str) -> Any:
        if name not in self._fields:
            raise AttributeError(f"{self._cam.name}.{self._prefix} has no element {name!r}")
        return self._cam.tag(f"{self._prefix}.{name}")

    def __setattr__(self, name: str, value: Any) -> None:
        self._cam.set_tag(f"{self._prefix}.{name}", value)

    def __dir__(self) -> list[str]:
        return list(self._fields)


class CamTO:
    """Cam technology object.

    ``points``: (x, y) pairs for Point[1..n] (valid); ``segments``: dicts with the ``Segment`` elements
    (xmin, xmax, a0..a6, sineAmplitude, sinePeriod, sinePhase) or :class:`SegmentDef` for Segment[1..m].
    These are the start values; a restart of the TO returns to them.  The cam must be interpolated
    (MC_InterpolateCam) before it can be used.
    """

    kind = "TO_Cam"

    def __init__(self, ctl: "Controller", name: str, points: Iterable = (), segments: Iterable = (),
                 interpolation_mode: int = 0, boundary_conditions: int = 0, db_number: int | None = None):
        self.ctl = ctl
        self.name = name
        self.db_number = db_number if db_number is not None else ctl._next_db_number()
        self._px = np.zeros(MAX_POINTS)
        self._py = np.zeros(MAX_POINTS)
        self._pvalid = np.zeros(MAX_POINTS, dtype=bool)
        self._seg = np.zeros((MAX_SEGMENTS, len(SEGMENT_FIELDS)))
        self._svalid = np.zeros(MAX_SEGMENTS, dtype=bool)
        self._mode = 0
        self._bc = 0
        self.set_points(points, _mark=False)
        self.set_segments(segments, _mark=False)
        self._set_setting("InterpolationMode", interpolation_mode)
        self._set_setting("BoundaryConditions", boundary_conditions)
        self._start = self._snapshot()
        self.curve: CamCurve | None = None
        self.data_changed = False
        self.in_interpolation = False
        self.users: set[Any] = set()          # jobs (camming) that use the cam
        self.alarms: list[F.Fault] = []
        self.last_definition_error: str | None = None

    def __repr__(self) -> str:
        state = "interpolated" if self.curve is not None else "not interpolated"
        return f"<CamTO {self.name} {state}>"

    # --- definition ------------------------------------------------------------------------------------
    def _snapshot(self) -> tuple:
        return (self._px.copy(), self._py.copy(), self._pvalid.copy(), self._seg.copy(), self._svalid.copy(),
                self._mode, self._bc)

    def _changed(self) -> None:
        self.data_changed = True

    def set_points(self, points: Iterable, *, _mark: bool = True) -> None:
        """Point[1..n] = ``points`` (valid), all further points invalid."""
        pts = [tuple(p) for p in points]
        if len(pts) > MAX_POINTS:
            raise ValueError(f"{self.name}: a cam holds at most {MAX_POINTS} points, got {len(pts)}")
        self._pvalid[:] = False
        for i, p in enumerate(pts):
            if len(p) != 2:
                raise ValueError(f"{self.name}.Point[{i + 1}]: expected (x, y), got {p!r}")
            self._px[i] = _real(f"{self.name}.Point[{i + 1}].x", p[0])
            self._py[i] = _real(f"{self.name}.Point[{i + 1}].y", p[1])
            self._pvalid[i] = True
        if _mark:
            self._changed()

    def set_segments(self, segments: Iterable, *, _mark: bool = True) -> None:
        """Segment[1..m] = ``segments`` (valid), all further segments invalid."""
        segs = list(segments)
        if len(segs) > MAX_SEGMENTS:
            raise ValueError(f"{self.name}: a cam holds at most {MAX_SEGMENTS} segments, got {len(segs)}")
        self._svalid[:] = False
        for i, s in enumerate(segs):
            if isinstance(s, SegmentDef):
                row = [s.xmin, s.xmax, *s.a, s.sine_amplitude, s.sine_period, s.sine_phase]
            elif isinstance(s, Mapping):
                unknown = set(s) - set(SEGMENT_FIELDS)
                if unknown:
                    raise ValueError(f"{self.name}.Segment[{i + 1}]: unknown elements {sorted(unknown)}; "
                                     f"elements: {', '.join(SEGMENT_FIELDS)}")
                row = [s.get(f, 0.0) for f in SEGMENT_FIELDS]
            else:
                raise TypeError(f"{self.name}.Segment[{i + 1}]: a mapping or SegmentDef, got {s!r}")
            self._seg[i] = [_real(f"{self.name}.Segment[{i + 1}].{f}", v) for f, v in zip(SEGMENT_FIELDS, row)]
            self._svalid[i] = True
        if _mark:
            self._changed()

    def _set_setting(self, name: str, value: Any) -> None:
        if isinstance(value, bool) or not isinstance(value, numbers.Integral):
            if not (isinstance(value, float) and value.is_integer()):
                raise TypeError(f"{self.name}.InterpolationSettings.{name} is a DINT tag; got {value!r}")
        value = int(value)
        if name == "InterpolationMode":
            self._mode = value
        else:
            self._bc = value
        self._changed()

    def valid_points(self) -> list[tuple[float, float]]:
        idx = np.flatnonzero(self._pvalid)
        return [(float(self._px[i]), float(self._py[i])) for i in idx]

    def valid_segments(self) -> list[SegmentDef]:
        out = []
        for i in np.flatnonzero(self._svalid):
            r = self._seg[i]
            out.append(SegmentDef(float(r[0]), float(r[1]), tuple(float(v) for v in r[2:9]),  # type: ignore[arg-type]
                                  float(r[9]), float(r[10]), float(r[11])))
        return out

    # --- tags ------------------------------------------------------------------------------------------
    @property
    def Point(self) -> _Array:  # noqa: N802 - tag names
        return _Array(self, "Point", MAX_POINTS, lambda i: _PointView(self, i))

    @property
    def ValidPoint(self) -> _Array:  # noqa: N802
        def set_(i: int, v: Any) -> None:
            self._pvalid[i] = _bool(f"{self.name}.ValidPoint[{i + 1}]", v)
            self._changed()
        return _Array(self, "ValidPoint", MAX_POINTS, lambda i: bool(self._pvalid[i]), set_)

    @property
    def Segment(self) -> _Array:  # noqa: N802
        return _Array(self, "Segment", MAX_SEGMENTS, lambda i: _SegmentView(self, i))

    @property
    def ValidSegment(self) -> _Array:  # noqa: N802
        def set_(i: int, v: Any) -> None:
            self._svalid[i] = _bool(f"{self.name}.ValidSegment[{i + 1}]", v)
            self._changed()
        return _Array(self, "ValidSegment", MAX_SEGMENTS, lambda i: bool(self._svalid[i]), set_)

    @property
    def InterpolationSettings(self) -> _Struct:  # noqa: N802
        return _Struct(self, "InterpolationSettings", {"InterpolationMode": 0, "BoundaryConditions": 0}, True)

    @property
    def StatusCam(self) -> _Struct:  # noqa: N802
        return _Struct(self, "StatusCam", {"StartLeadingValue": 0, "EndLeadingValue": 0}, False)

    @property
    def ErrorDetail(self) -> _Struct:  # noqa: N802
        return _Struct(self, "ErrorDetail", {"Number": 0, "Reaction": 0}, False)

    @property
    def StatusWord(self):  # noqa: N802
        return CamStatusWord(pack({0: bool(self.users), 1: bool(self.alarms),
                                   3: A.restart_required(self.alarms, A.CAM), 4: self.data_changed,
                                   5: self.curve is not None, 6: self.in_interpolation}))

    @property
    def ErrorWord(self):  # noqa: N802
        return CamErrorWord(pack(A.error_bits(self.alarms, A.CAM)))

    @property
    def WarningWord(self):  # noqa: N802
        return CamWarningWord(0)

    _TAGS = ("InterpolationSettings.InterpolationMode", "InterpolationSettings.BoundaryConditions",
             "StatusCam.StartLeadingValue", "StatusCam.EndLeadingValue", "StatusWord", "ErrorWord",
             "WarningWord", "ErrorDetail.Number", "ErrorDetail.Reaction")

    def tag(self, path: str) -> Any:
        """Value of a tag by path: ``"StatusCam.EndLeadingValue"``, ``"Point[3].y"``, ``"StatusWord"``."""
        if path == "InterpolationSettings.InterpolationMode":
            return self._mode
        if path == "InterpolationSettings.BoundaryConditions":
            return self._bc
        if path == "StatusCam.StartLeadingValue":
            return self.curve.start if self.curve is not None else 0.0
        if path == "StatusCam.EndLeadingValue":
            return self.curve.end if self.curve is not None else 0.0
        if path in ("StatusWord", "ErrorWord", "WarningWord"):
            return getattr(self, path)
        if path in ("ErrorDetail.Number", "ErrorDetail.Reaction"):
            # the cam's job failures are instruction errors; an alarm would show with reaction 6 (§A.2.10)
            return A.error_detail(self.alarms, A.CAM)[path.endswith("Reaction")]
        return self._resolve(path)(None)

    def set_tag(self, path: str, value: Any) -> None:
        if path in ("InterpolationSettings.InterpolationMode", "InterpolationSettings.BoundaryConditions"):
            self._set_setting(path.split(".")[1], value)
            return
        if path in self._TAGS:
            from ...kernel.tag_views import TagAccessError
            raise TagAccessError(f"{self.name}.{path} is read-only")
        self._resolve(path)(value)

    def _resolve(self, path: str):
        import re

        m = re.fullmatch(r"(Point|Segment|ValidPoint|ValidSegment)\[(\d+)\](?:\.(\w+))?", path)
        if m is None:
            raise KeyError(f"{self.name}.{path} is not a tag of the cam")
        arr, idx, elem = m.group(1), int(m.group(2)), m.group(3)
        array = getattr(self, arr)
        if elem is None:
            if arr.startswith("Valid"):
                return lambda v: array[idx] if v is None else array.__setitem__(idx, v)
            raise KeyError(f"{self.name}.{path}: give an element ({arr}[{idx}].x ...)")
        view = array[idx]
        return lambda v: getattr(view, elem) if v is None else setattr(view, elem, v)

    # --- jobs ------------------------------------------------------------------------------------------
    def submit(self, job: Job) -> None:
        """Queue a cam job for the next servo cycle; checks that need no computation answer at once."""
        if self.ctl.mode != "RUN":
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "starting_up"))
            return
        if job.kind == JobKind.CAM_INTERPOLATE:
            if self.users:
                job.finish(JobState.ERROR, F.reject(F.CAM_IN_USE))
                return
            self.in_interpolation = True
        elif self.curve is None:
            job.finish(JobState.ERROR, F.reject(F.CAM_NOT_INTERPOLATED))
            return
        self.ctl._defer(lambda t: self._run(job))

    def _run(self, job: Job) -> None:
        """Process a queued job; a defect ends the job (16#8FFF), never the controller."""
        try:
            self._process(job)
        except Exception as exc:
            if job.kind == JobKind.CAM_INTERPOLATE:
                self.in_interpolation = False
            job.finish(JobState.ERROR, F.reject(F.INTERNAL, "", f"{type(exc).__name__}: {exc}"))

    def _process(self, job: Job) -> None:
        """A job given in an earlier application cycle; what happened to the cam since (a restart, an
        interpolation) counts: the state at processing time decides."""
        if not job.busy:
            return
        if job.kind == JobKind.CAM_INTERPOLATE:
            self.in_interpolation = False
            if self.users:                       # taken into use since the job was given
                job.finish(JobState.ERROR, F.reject(F.CAM_IN_USE))
                return
            try:
                curve = interpolate(self.valid_points(), self.valid_segments(), self._mode, self._bc)
            except CamDefinitionError as exc:
                self.last_definition_error = str(exc)
                # "empty" with one valid point is a bad definition, not a cam without elements
                reason = "too_few" if exc.reason == "empty" and (
                    self.valid_points() or self.valid_segments()) else exc.reason
                job.finish(JobState.ERROR, F.reject(F.CAM_DEFINITION, reason, str(exc)))
                return
            self.curve = curve
            self.data_changed = False
            self.last_definition_error = None
            job.finish(JobState.DONE)
            return
        curve = self.curve
        if curve is None:                        # restarted (MC_Reset Restart) since the job was given
            job.finish(JobState.ERROR, F.reject(F.CAM_NOT_INTERPOLATED))
            return
        if job.kind == JobKind.CAM_FOLLOWING:
            x = job.position
            if not curve.start - 1e-12 * max(1.0, abs(curve.start)) <= x <= curve.end + 1e-12 * max(1.0, abs(curve.end)):
                job.finish(JobState.ERROR, F.reject(F.CAM_OUT_OF_RANGE, "", f"LeadingValue {x!r} outside "
                                                    f"[{curve.start!r}, {curve.end!r}]"))
                return
            y, d1, d2 = curve.evaluate(np.array([x]))
            job.extra.update(value=float(y[0]), first=float(d1[0]), second=float(d2[0]))
            job.finish(JobState.DONE)
        elif job.kind == JobKind.CAM_LEADING:
            x = curve.solve(job.position, job.extra.get("approach", 0.0))
            if x is None:
                job.finish(JobState.ERROR, F.reject(F.CAM_NO_SOLUTION, "", f"the cam never takes the following "
                                                    f"value {job.position!r}"))
                return
            job.extra["value"] = x
            job.finish(JobState.DONE)

    # --- use by following axes ---------------------------------------------------------------------------
    def acquire(self, user: Any) -> None:
        self.users.add(user)

    def release(self, user: Any) -> None:
        self.users.discard(user)

    # --- acknowledgement / restart -----------------------------------------------------------------------
    def acknowledge(self) -> F.Fault | None:
        self.alarms.clear()
        return None

    def restart(self) -> F.Fault | None:
        """Restart (MC_Reset Restart = TRUE): start values again, not interpolated; not while in use and
        not during an interpolation (StatusWord.X6 InInterpolation)."""
        if self.users:
            return F.reject(F.CAM_IN_USE)
        if self.in_interpolation:
            return F.reject(F.RESTART_IMPOSSIBLE, "in_interpolation")
        self.reinitialize("restart")
        return None

    def reinitialize(self, reason: str) -> None:
        px, py, pv, seg, sv, mode, bc = self._start
        self._px, self._py, self._pvalid = px.copy(), py.copy(), pv.copy()
        self._seg, self._svalid = seg.copy(), sv.copy()
        self._mode, self._bc = mode, bc
        self.curve = None
        self.data_changed = False
        self.in_interpolation = False
        self.users.clear()
        self.alarms.clear()


__all__ = ["CamTO", "SEGMENT_FIELDS", "CamStatusWord"]
