"""The controller: virtual clock, user programs and the servo cycle.

Each servo cycle (S7-1200 V6 §2.2.7, LinuxCNC-style fixed order) runs the named stages of
:mod:`.servo_cycle` in order: read drives and encoders -> pre-servo hooks -> events of single axes ->
interpolation of all setpoints -> coupling -> position control and monitoring -> write drives ->
post-servo hooks (trace).  ``Controller.servo_stages`` lists them.
Every application cycle the user programs run first (like OB1), then the servo cycles of that period.
Time is virtual: ``servo cycles x servo_cycle``; the same program gives the same trace bit for bit.
"""
from __future__ import annotations

import math
import numbers
import re
import time as _wall
import traceback
import warnings
from typing import Any, Callable, Mapping

from ..drives.base import DriveGroup, DriveLink
from ..drives.plant import Plant
from ..drives.simulated import new_drive_group
from ..drives.spec import ActuatorKind, DriveSpec
from . import retain
from . import family as families
from . import schema as P
from .axis import PositioningAxis
from .errors import ConfigurationError
from .bank import AxisBank
from .servo_cycle import STAGE_NAMES, failed_stage, run_servo_cycle
from .sync import SyncStage
from .io import DEFAULT_FILTER, DigitalInputs, DigitalOutputs
from .watchdog import CycleOverrunWarning, CycleWatchdog, Overrun

RUN, STOP = "RUN", "STOP"
#: how error messages name an object whose parameters are wrong (default: its kind without the article)
_WHERE = {families.POSITIONING_AXIS: "axis", families.SYNCHRONOUS_AXIS: "axis"}
_EPS_T = 1e-9
_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")

#: servo cycle range [s].  The manuals in use give no numbers (S7-1200 V6 §2.2.7.1 only recommends
#: 2 ms + 2 ms per position-controlled axis for MC-Servo); 32 ms is the longest MC-Servo application
#: cycle of S7-1500 Motion Control and 0.1 ms lies below the shortest MC-Servo cycle of any S7 CPU
#: (0.25 ms with PROFINET IRT): finer cycles only resolve PTO pulse trains better in the simulation.
#: Outside this range a simulation is meaningless (and 1e-300 s would never end).
SERVO_CYCLE_MIN, SERVO_CYCLE_MAX = 0.0001, 0.032
#: longest application cycle (user program period) [s]: keeps one ``step()`` bounded
#: (at most APP_CYCLE_MAX / SERVO_CYCLE_MIN = 10000 servo cycles)
APP_CYCLE_MAX = 1.0


def cycle_problem(servo_cycle: Any, app_cycle: Any) -> tuple[str, Any, str] | None:
    """The first problem of a servo/application cycle pair as ``(name, value, allowed)``, else None."""
    ranges = (("servo_cycle", servo_cycle, SERVO_CYCLE_MIN, SERVO_CYCLE_MAX),
              ("app_cycle", app_cycle, SERVO_CYCLE_MIN, APP_CYCLE_MAX))
    for name, value, lo, hi in ranges:
        # one comparison refuses NaN, inf and ints beyond float range (math.isfinite(10**400) raises)
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not lo <= value <= hi:
            return name, value, f"a positive number of seconds in [{lo:g}, {hi:g}]"
    ratio = app_cycle / servo_cycle
    if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
        return "app_cycle", app_cycle, f"a whole multiple of servo_cycle ({servo_cycle!r} s)"
    return None


def _flat(params: Any, where: str) -> dict[str, Any]:
    """The tag values of ``params`` (nested and/or dotted keys) as one flat dict; a tag given twice
    (``"A.B"`` beside ``{"A": {"B": ...}}``) is a ConfigurationError naming both."""
    if params is None:
        return {}
    if not isinstance(params, Mapping):
        raise TypeError(f"{where}: params must be a mapping of tag paths to values, e.g. "
                        f"{{'DynamicLimits.MaxVelocity': 100.0}} or {{'DynamicLimits': {{'MaxVelocity': 100.0}}}}; "
                        f"got {type(params).__name__} {_short(params)}")
    flat, issues = P.flatten_checked(params)
    if issues:
        raise ConfigurationError(where, issues)
    return flat


def _leading_list(name: str, leading_values: Any) -> list[tuple[str, str]]:
    """The possible leading values of synchronous axis ``name`` as ``(source, coupling)`` pairs."""
    form = "a list of names or (name, coupling) pairs, e.g. ['Master', ('Encoder', 'actual')]"
    if leading_values is None:
        return []
    if isinstance(leading_values, (str, bytes)) or not isinstance(leading_values, (list, tuple)):
        raise TypeError(f"synchronous axis {name}: leading_values must be {form}; got {_short(leading_values)}")
    out = []
    for item in leading_values:
        pair = (item, "setpoint") if isinstance(item, str) else item
        if not (isinstance(pair, (list, tuple)) and len(pair) == 2 and all(isinstance(v, str) for v in pair)):
            raise TypeError(f"synchronous axis {name}: leading_values must be {form}; got the item {_short(item)}")
        if pair[0] == name:
            raise ValueError(f"synchronous axis {name}: an axis is not a leading value of itself (leading_values)")
        out.append((pair[0], pair[1]))
    return out


def _short(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


class ControllerStopped(RuntimeError):
    """The controller went to STOP (a program raised, or ``stop()`` was called)."""


class ProgramErrorWarning(RuntimeWarning):
    """A user program raised: the controller went to STOP (``run`` goes on, ``run_until`` raises)."""


def exception_text(exc: BaseException) -> str:
    """'Type: message' of any exception, also one whose ``__str__`` raises (user code must not escape)."""
    name = type(exc).__name__
    try:
        text = str(exc)
    except BaseException:  # noqa: BLE001 - the message is user code
        text = "<str() of the exception failed>"
    if isinstance(exc, SystemExit):
        text = f"{text or None} (sys.exit() in a program: a PLC program cannot end the controller)"
    return f"{name}: {text}" if text else name


def _traceback_text(exc: BaseException) -> str:
    try:
        return "".join(traceback.format_exception(exc))
    except BaseException:  # noqa: BLE001
        return "(no traceback: formatting the exception failed)\n"


class RunTimeout(TimeoutError):
    """``run_until`` did not see its condition within the timeout."""


class Controller:
    """A motion controller in virtual time.

    ``servo_cycle``: period of position control and interpolation [s] (default 1 ms).
    ``app_cycle``: period of the user programs [s], a whole multiple of ``servo_cycle`` (default 4 ms).
    ``input_filter``: default filter time of the digital inputs [s] (6.4 ms as on the CPU).
    ``state_file``: where retentive data is kept (absolute encoder adjustment); None keeps it in memory.
    ``family``: the registered family whose technology objects the controller creates (``plcmotion``
    registers "S7-1200" - the default -, "S7-1500" and "S7-1500T"; see ``kernel.family``).
    ``technology_version``: the version of the family's technology objects whose rules apply where versions
    differ (S7-1200: 6 or 7, default 6; S7-1500: 5).
    ``cycle_watchdog``: the user programs of one application cycle may take this many application cycles of
    wall-clock time; a longer run is an overrun (``CycleOverrunWarning``, ``cycle_overruns``,
    ``last_overrun``).  0 or None: no monitoring.  ``cycle_watchdog_stop``: an overrun puts the controller in
    STOP, as a CPU does when its maximum cycle time is exceeded; by default it is only reported, because the
    wall clock of a simulation says nothing about the virtual controller.
    """

    def __init__(self, servo_cycle: float = 0.001, app_cycle: float = 0.004, *,
                 input_filter: float = DEFAULT_FILTER, state_file: str | None = None,
                 technology_version: int | None = None, family: str | None = None,
                 cycle_watchdog: float | None = 100.0, cycle_watchdog_stop: bool = False):
        problem = cycle_problem(servo_cycle, app_cycle)
        if problem:
            raise ValueError(f"{problem[0]} = {problem[1]!r}: {problem[2]}")
        ratio = app_cycle / servo_cycle
        fam = families.lookup(family) if family is not None else families.default()
        #: the family whose technology objects this controller creates (a registered name, e.g. "S7-1200")
        self.family = fam.name
        self._family = fam
        if technology_version is None:
            technology_version = fam.default_version
        if (isinstance(technology_version, bool) or not isinstance(technology_version, numbers.Integral)
                or technology_version not in fam.versions):
            raise ValueError(f"technology_version for {fam.name} must be "
                             + (" or ".join(map(str, fam.versions))) + f", got {technology_version!r}")
        #: version of the family's technology objects whose rules apply where versions differ
        self.technology_version = int(technology_version)
        #: names of the version-dependent rules in force (from the family, see ``kernel.family``)
        self.rules: frozenset[str] = fam.rules(self.technology_version)
        #: optional kernel features the family uses (e.g. actual value coupling)
        self.features: frozenset[str] = fam.features
        self.servo_cycle = float(servo_cycle)
        self.app_cycle = round(ratio) * self.servo_cycle
        # time = k / rate when the servo frequency is a whole number: 1.001 instead of 1.0010000000000001
        rate = 1.0 / self.servo_cycle
        self._rate = float(round(rate)) if abs(rate - round(rate)) < 1e-9 * rate else None
        self._ratio = int(round(ratio))
        #: cycle-time monitoring of the user programs (see ``cycle_watchdog``)
        self.watchdog = CycleWatchdog(self.app_cycle, cycle_watchdog, cycle_watchdog_stop)
        self.bank = AxisBank()
        self.axes: dict[str, PositioningAxis] = {}
        self.command_tables: dict[str, Any] = {}
        self.cams: dict[str, Any] = {}
        self.objects: dict[str, Any] = {}           # other technology objects (encoders, proxies)
        self._db_counter = 0
        self._deferred: list[Callable[[float], None]] = []
        self.sync = SyncStage(self)                 # leading value couplings (synchronous axes)
        self._encoders: list[Any] = []              # external encoders: measured every servo cycle
        self._by_index: list[PositioningAxis] = []
        self._groups: dict[str, DriveGroup] = {}
        self._group_list: list[DriveGroup] = []
        self._closed_loop = False                   # a drive group whose axes the position controller drives
        self._drive_links: dict[str, Any] = {}      # axis name -> drives.base.DriveLink (connect_drive)
        self._programs: list[tuple[str, Callable[[], Any]]] = []
        self._pre_servo: list[Callable[[float], None]] = []
        self._post_servo: list[Callable[[float], None]] = []
        self._instances: dict[int, Any] = {}        # instruction instances used on this controller
        self._k = 0                                 # servo cycles done
        self.app_cycles = 0
        self.mode = RUN
        self.stop_reason: str | None = None
        self._n_fe = 0                              # axes with following error monitoring on
        self._n_few = 0                             # axes that report a following error warning
        self._n_pm = 0                              # axes in positioning monitoring
        self._n_sim = 0                             # axes whose actual values are their setpoints
        self._n_sup = 0                             # axes with a superimposed motion part
        self._bank_time = 0.0                       # time of the setpoints in the bank arrays
        self._dirty_axes: set[PositioningAxis] = set()
        self._servo_defect = False
        self.inputs = DigitalInputs(input_filter)
        self.outputs = DigitalOutputs()
        self.plant = Plant(self.inputs, self)
        self._input_axes: list[PositioningAxis] = []   # axes that watch inputs every servo cycle
        self._pto_holder: dict[int, PositioningAxis] = {}   # pulse generator number -> axis using it
        # retentive data (absolute encoder adjustment), kept in ``state_file`` when one is given
        self.state_file = state_file
        self.retain: dict[str, dict] = retain.load(state_file) if state_file else {}
        #: the family's controller-wide runtime state (``Family.setup``), None when it has none
        self.extension: Any = fam.setup(self) if fam.setup is not None else None

    # --- time ------------------------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Virtual time [s]."""
        return self._time_of(self._k)

    def _time_of(self, k: int) -> float:
        return k / self._rate if self._rate is not None else k * self.servo_cycle

    @property
    def servo_cycles(self) -> int:
        return self._k

    # --- configuration ---------------------------------------------------------------------------------
    def add_positioning_axis(self, name: str, params: Mapping[str, Any] | None = None, *,
                             source: str | None = None) -> PositioningAxis:
        """Create a positioning axis; ``params`` are nested dicts or dotted paths of the family's TO tags."""
        return self._create(families.POSITIONING_AXIS, name, params, source=source)

    def add_synchronous_axis(self, name: str, params: Mapping[str, Any] | None = None, *,
                             leading_values: Any = (), source: str | None = None):
        """Create a synchronous axis: a positioning axis that follows a leading value.

        ``leading_values``: the possible leading values, names of technology objects or ``(name, type)``
        pairs with type "setpoint" (default), "actual" or "delayed"."""
        self._offered(families.SYNCHRONOUS_AXIS)
        leading = _leading_list(name, leading_values)
        return self._create(families.SYNCHRONOUS_AXIS, name, params, source=source, leading_values=leading)

    def add_external_encoder(self, name: str, params: Mapping[str, Any] | None = None, *,
                             source: str | None = None):
        """Create an external encoder: a leading value source with actual values of a measured machine."""
        return self._create(families.EXTERNAL_ENCODER, name, params, source=source)

    def add_leading_axis_proxy(self, name: str, params: Mapping[str, Any] | None = None, *,
                               source_link: Any = None, source: str | None = None):
        """Create a leading axis proxy that takes the leading value of an axis of another controller from
        ``source_link`` (a transport, see ``plcmotion.crossplc``)."""
        return self._create(families.LEADING_AXIS_PROXY, name, params, source=source, source_link=source_link)

    def add_cam(self, name: str, points: Any = (), segments: Any = (), *, interpolation_mode: int = 0,
                boundary_conditions: int = 0):
        """Create a cam technology object from ``points`` and ``segments``; interpolate it before use."""
        factory = self._offered(families.CAM)
        self._check_name(name)
        return self._register(families.CAM, name, factory(self, name, points, segments,
                                                          interpolation_mode=interpolation_mode,
                                                          boundary_conditions=boundary_conditions))

    def add_command_table(self, name: str, commands: Any = (), *, source: str | None = None):
        """Create a command table TO from up to 32 command steps."""
        factory = self._offered(families.COMMAND_TABLE)
        self._check_name(name)
        return self._register(families.COMMAND_TABLE, name, factory(self, name, commands))

    def _offered(self, kind: str) -> Callable[..., Any]:
        """The family's factory for objects of ``kind``; a ValueError naming the families that offer it."""
        factory = self._family.factories.get(kind)
        if factory is None:
            need = " or ".join(families.offering(kind)) or "none of the registered families"
            raise ValueError(f"{kind} needs a controller of family {need} (Controller(family=...)); "
                             f"this one is {self.family}")
        return factory

    def _create(self, kind: str, name: str, params: Mapping[str, Any] | None, *, source: str | None,
                **kw: Any) -> Any:
        """A technology object made by the family's factory from validated parameters, then registered."""
        factory = self._offered(kind)
        self._check_name(name)
        where = source or f"{_WHERE.get(kind) or kind.split(' ', 1)[1]} {name}"
        return self._register(kind, name, factory(self, name, _flat(params, where), where, **kw))

    def _register(self, kind: str, name: str, obj: Any) -> Any:
        getattr(self, families.TABLES.get(kind, "objects"))[name] = obj
        if kind in (families.POSITIONING_AXIS, families.SYNCHRONOUS_AXIS):
            self._by_index.append(obj)
        return obj

    def offers(self, kind: str) -> bool:
        """Whether the family offers technology objects of ``kind`` (``kernel.family`` constants)."""
        return kind in self._family.factories

    def offers_job(self, kind: Any) -> bool:
        """Whether the family's instructions may start jobs of this kernel job kind."""
        kinds = self._family.job_kinds
        return kinds is None or kind in kinds

    def _lookup(self, name: str) -> Any:
        """The technology object named ``name`` (axes, cams, encoders, proxies)."""
        for table in (self.axes, self.cams, self.objects, self.command_tables):
            if name in table:
                return table[name]
        return None

    def new_axis(self, cls: type, name: str, flat: Mapping[str, Any], where: str, **kw: Any) -> Any:
        """For a family's factory: an axis of class ``cls`` from the flat tag values ``flat``, checked with
        ``cls.schema`` (a ConfigurationError names ``where`` and every bad tag)."""
        cfg, issues = cls.schema.validate(flat)
        if issues:
            raise ConfigurationError(where, issues)
        return cls(self, name, cfg, **kw)

    def _check_name(self, name: str) -> None:
        if not isinstance(name, str) or not _NAME.match(name):
            raise ValueError(f"technology object name {name!r} must be an identifier (letters, digits, underscore)")
        if name in self.axes or name in self.command_tables or name in self.cams or name in self.objects:
            raise ValueError(f"a technology object {name!r} exists already")

    def _next_db_number(self) -> int:
        """DB number of a new technology object (shown in tags such as ActualMaster)."""
        self._db_counter += 1
        return self._db_counter

    def _defer(self, fn: Callable[[float], None]) -> None:
        """Run ``fn(t)`` at the start of the next servo cycle (jobs handed to MC-Servo)."""
        self._deferred.append(fn)

    def _drive_group(self, spec: DriveSpec) -> DriveGroup:
        """The group of the drives of ``spec``: one per actuator kind ("servo", "stepper", "ideal", "hydraulic") for the
        simulated drives, one per ``spec.link.group_key`` for drives on a bus (``connect_drive``)."""
        key = spec.group_key
        group = self._groups.get(key)
        if group is None:
            group = spec.link.new_group(self.bank) if spec.link is not None else new_drive_group(key, self.bank)
            self._groups[key] = group
            self._group_list.append(group)
            self._closed_loop = self._closed_loop or group.closed_loop
        return group

    def connect_drive(self, axis: str, link: DriveLink) -> None:
        """Drive the axis named ``axis`` through ``link`` (a ``drives.base.DriveLink``, e.g. a CiA 402 drive
        on a CAN bus) instead of the simulated drive its configuration describes.  Call it before the axis
        is added; the family's configuration still sets units, dynamics, monitoring and mechanics."""
        if not isinstance(link, DriveLink):
            raise TypeError(f"connect_drive: link must be a drives.base.DriveLink, got {link!r}")
        if axis in self.axes:
            raise ValueError(f"connect_drive: axis {axis!r} exists already; connect its drive before adding it")
        self._drive_links[axis] = link

    def _bind_drive(self, name: str, spec: DriveSpec) -> DriveSpec:
        """The drive spec of axis ``name``: its link attached when ``connect_drive`` named it."""
        link = self._drive_links.get(name)
        return spec if link is None else link.bind(spec)

    def close(self) -> None:
        """Release the bus connections of the drive groups (threads, sockets); the controller is not used
        afterwards.  Simulated drives hold none, so closing is only needed with ``connect_drive``."""
        for group in self._group_list:
            group.close()

    def _retain_axis(self, axis: PositioningAxis) -> None:
        """Store the retentive data of an axis (written atomically to the state file)."""
        if axis.absolute_encoder():
            self.retain[axis.retain_key] = {"AbsEncoderOffset": axis.abs_offset, "HomingDone": axis.homed}
            if self.state_file:
                retain.save(self.state_file, self.retain)

    def _axis_at(self, index: int) -> PositioningAxis:
        return self._by_index[index]

    def __getitem__(self, name: str) -> PositioningAxis:
        return self.axes[name]

    # --- programs and hooks ----------------------------------------------------------------------------
    def program(self, fn: Callable[[], Any] | None = None, *, name: str | None = None):
        """Register a function called once per application cycle (decorator)."""
        def register(f: Callable[[], Any]) -> Callable[[], Any]:
            self._programs.append((name or getattr(f, "__name__", "program"), f))
            return f
        return register(fn) if fn is not None else register

    def on_pre_servo(self, fn: Callable[[float], None]) -> Callable[[float], None]:
        self._pre_servo.append(fn)
        return fn

    def on_post_servo(self, fn: Callable[[float], None]) -> Callable[[float], None]:
        """Register ``fn(t)`` called at the end of every servo cycle (traces)."""
        self._post_servo.append(fn)
        return fn

    def remove_hook(self, fn: Callable[[float], None]) -> None:
        for hooks in (self._pre_servo, self._post_servo):
            if fn in hooks:
                hooks.remove(fn)

    # --- operating mode --------------------------------------------------------------------------------
    def stop(self, reason: str = "STOP requested") -> None:
        """RUN -> STOP: programs no longer run; all axes disabled with 'remove enable' (§2.2.7.4, §9.4)."""
        if self.mode == STOP:
            return
        self.mode = STOP
        self.stop_reason = reason
        for address in list(self.outputs):          # §9.4: all CPU outputs are reset
            self.outputs[address] = False
        for axis in self._by_index:
            try:
                axis._abort_all(self.time)
                if axis.state != "disabled":
                    axis._remove_enable(self.time, by_power=True)
                axis.power_owner = None
            except Exception:  # pragma: no cover - keep stopping the others
                pass

    def start(self) -> None:
        """STOP -> STARTUP -> RUN: technology objects and instructions start from their start values."""
        if self.mode != RUN:
            self._restart("startup")

    def power_cycle(self) -> None:
        """POWER OFF -> ON (§9.4): jobs aborted, outputs reset, technology objects restarted; axes must be
        enabled (and, with incremental encoders or PTO, homed) again.  Retentive data survives; the
        virtual clock and the machine (plant) keep going."""
        self.stop("POWER OFF")
        for address in list(self.outputs):         # also when the CPU was in STOP already
            self.outputs[address] = False
        self._restart("power")

    def _restart(self, reason: str) -> None:
        for axis in self._by_index:
            axis.reinitialize(reason)
        for table in self.command_tables.values():
            table.reinitialize()
        for to in (*self.cams.values(), *self.objects.values()):
            to.reinitialize(reason)
        for inst in self._instances.values():
            inst._reinit()
        reinit = getattr(self.extension, "reinitialize", None)
        if reinit is not None:
            reinit(reason)
        self.mode = RUN
        self.stop_reason = None
        self._servo_defect = False

    # --- running ---------------------------------------------------------------------------------------
    def step(self, *, programs: bool = True) -> None:
        """One application cycle: user programs, then the servo cycles of that period.

        Whatever a program or servo hook raises puts the controller in STOP with the reason
        (``stop_reason``) and a ``ProgramErrorWarning``; ``step`` then returns.  Only KeyboardInterrupt
        leaves ``step``, after the controller went to STOP: the person at the terminal gets it.
        ``programs=False``: only the servo cycles run (a controlled shutdown lets the stop ramps run out
        without a program commanding the axes again)."""
        if programs and self.mode == RUN:
            self._run_programs()
        self.app_cycles += 1
        try:
            for _ in range(self._ratio):
                self._servo()
        except KeyboardInterrupt:
            self.stop(f"interrupted (KeyboardInterrupt) in the servo cycle at t = {self.time:.6g} s")
            raise

    def _run_programs(self) -> None:
        t0 = _wall.perf_counter()
        for name, fn in self._programs:
            try:
                fn()
            except BaseException as exc:  # noqa: BLE001 - a user program: any exception is a program fault
                self._user_fault(f"program {name!r}", exc)
                if isinstance(exc, KeyboardInterrupt):
                    raise
                return
        overrun = self.watchdog.check(self.time, _wall.perf_counter() - t0)
        if overrun is not None:
            self._on_overrun(overrun)

    def _user_fault(self, who: str, exc: BaseException) -> None:
        """A program or hook raised: STOP with the reason; like a PLC the controller goes on in STOP, and
        a warning says so where a script would not look (not for Ctrl-C: that one is re-raised)."""
        text = exception_text(exc)
        self.stop(f"{who} raised {text}\n" + _traceback_text(exc))
        if not isinstance(exc, KeyboardInterrupt):
            warnings.warn(f"controller in STOP at t = {self.time:.6g} s: {who} raised {text} "
                          f"(details: Controller.stop_reason)", ProgramErrorWarning, stacklevel=4)

    def _on_overrun(self, overrun: Overrun) -> None:
        text = self.watchdog.describe(overrun)
        if self.watchdog.stop:
            self.stop(text + " (cycle time exceeded: the CPU goes to STOP)")
        if self.watchdog.stop or self.watchdog.reportable():
            warnings.warn(text + (": controller in STOP" if self.watchdog.stop else ""), CycleOverrunWarning,
                          stacklevel=4)

    @property
    def cycle_overruns(self) -> int:
        """Number of overruns of the cycle watchdog (see ``cycle_watchdog``)."""
        return self.watchdog.count

    @property
    def last_overrun(self) -> Overrun | None:
        """The last overrun of the cycle watchdog: virtual time, wall-clock duration, limit, injected."""
        return self.watchdog.last

    def inject_cycle_overrun(self, cycles: int = 1, duration: float | None = None) -> None:
        """Fault injection for virtual commissioning: the next ``cycles`` application cycles count as
        program runs of ``duration`` wall-clock seconds (default twice the watchdog time), so the cycle
        watchdog trips as on an overloaded CPU - deterministically."""
        self.watchdog.inject(cycles, duration)

    def run(self, seconds: float) -> None:
        """Advance the virtual time by ``seconds`` (whole application cycles, rounded up)."""
        n = max(0, math.ceil(seconds / self.app_cycle - 1e-9))
        for _ in range(n):
            self.step()

    def run_until(self, predicate: Callable[[], bool], timeout: float = 10.0) -> float:
        """Step until ``predicate()`` is true; returns the virtual time. Raises RunTimeout, ControllerStopped."""
        deadline = self.time + timeout
        while not predicate():
            if self.mode == STOP:
                raise ControllerStopped(self.stop_reason or "controller in STOP")
            if self.time >= deadline - _EPS_T:
                raise RunTimeout(f"condition not met within {timeout} s of virtual time (now t = {self.time:.6g} s)")
            self.step()
        return self.time

    # --- the servo cycle -------------------------------------------------------------------------------
    @property
    def servo_stages(self) -> tuple[str, ...]:
        """The names of the servo-cycle stages in the order they run (see :mod:`.servo_cycle`)."""
        return STAGE_NAMES

    def _servo(self) -> None:
        self._k += 1
        t = self._time_of(self._k)
        if self._servo_defect:
            return
        try:    # no per-stage try: axes and hooks isolate their faults inside the stages
            run_servo_cycle(self, t)
        except Exception as exc:  # a defect in the kernel: stop in a defined state, keep the reason
            if isinstance(exc, Warning):    # a hook's ProgramErrorWarning turned into an error by a filter
                raise
            self._servo_defect = True
            self.stop(f"internal error in the servo cycle, stage {failed_stage(exc)!r}, at t = {t:.6g} s: "
                      f"{exception_text(exc)}\n" + _traceback_text(exc))

    def _run_hooks(self, hooks: list[Callable[[float], None]], t: float) -> None:
        """Hooks are user code: one that raises stops the controller (like a faulty OB), not the kernel."""
        for hook in tuple(hooks):
            try:
                hook(t)
            except BaseException as exc:  # noqa: BLE001 - user code (see step)
                if hook in hooks and not isinstance(exc, KeyboardInterrupt):
                    hooks.remove(hook)
                self._user_fault(f"servo hook {getattr(hook, '__qualname__', hook)!r}", exc)
                if isinstance(exc, KeyboardInterrupt):
                    raise


__all__ = ["Controller", "ControllerStopped", "ProgramErrorWarning", "CycleOverrunWarning", "Overrun", "RunTimeout",
           "ConfigurationError", "RUN", "STOP"]

