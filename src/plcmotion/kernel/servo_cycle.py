"""The servo cycle as an ordered list of named stages (MC-Servo in the S7 manuals, the servo thread of
LinuxCNC): one place that says what happens in every servo cycle and in which order.

Every stage is a function ``stage(ctl, t)`` over the controller's axis bank (the numpy arrays of all
axes, see :mod:`.bank`) at the servo time ``t``.  Python code per axis runs only where something
happens to that axis (an event is due, a monitor trips, an input changed), never as a loop over all axes.

The order is the table :data:`SERVO_STAGES` at the end of this module, the only place that defines it;
the stage functions above it are in the same order, and :func:`describe` lists names and what each does
(``Controller.servo_stages`` gives the names).  In short: read drives, encoders and inputs -> pre-servo
hooks -> jobs, inputs, re-plans and events of single axes -> interpolate, superimpose, couple the
setpoints of all axes -> position control and monitoring -> write drives -> post-servo hooks (trace).

Each stage names the controller attributes that say whether it has work (``when``: no encoders, no
hooks, no superimposed motion, no axes ...); :func:`compile_cycle` turns the table into one function
with one line per stage, so an idle stage costs one attribute test and no call - as cheap as the
hand-written pipeline this table replaced.  A new kind of per-cycle work is a new row in the table.

Failures are handled where the cause is known: a defect while handling one axis stops only that axis
(``PositioningAxis._internal_error``, 16#8FFF); a hook that raises is user code and stops the controller
(``Controller._run_hooks``); anything else escaping a stage is a kernel defect, which the controller
turns into STOP naming the stage (:func:`failed_stage`).
"""
from __future__ import annotations

import linecache
from typing import Any, Callable, NamedTuple

import numpy as np

from . import monitoring

#: the controller whose cycle runs (``runtime.Controller``; not imported: the runtime imports this module)
Controller = Any

#: time tolerance of events [s]: an event due within it is handled in this cycle
_EPS_T = 1e-9
_SIXTH = 1.0 / 6.0


# --- inputs ----------------------------------------------------------------------------------------------
def read_drives(ctl: Controller, t: float) -> None:
    """Drive groups deliver the actual values of this cycle (encoder counts, pulses output)."""
    b = ctl.bank
    dt = ctl.servo_cycle
    for g in ctl._group_list:
        g.read(b, t, dt)


def read_encoders(ctl: Controller, t: float) -> None:
    """External encoders (measuring systems that are no axis) take their actual values."""
    dt = ctl.servo_cycle
    for enc in ctl._encoders:
        enc.read(t, dt)


def read_inputs(ctl: Controller, t: float) -> None:
    """The machine model writes the digital inputs of this cycle, then the input filters apply."""
    inputs = ctl.inputs
    inputs.begin_cycle(t)
    if ctl.plant.items:
        ctl.plant.update(t)
    inputs.update(t)


def pre_servo(ctl: Controller, t: float) -> None:
    """User hooks before the motion: actual values and inputs of this cycle, setpoints of the last one."""
    ctl._run_hooks(ctl._pre_servo, t)


# --- motion: events and re-plans of single axes --------------------------------------------------------
def accept_jobs(ctl: Controller, t: float) -> None:
    """Work that the application cycle handed to the servo cycle runs at its start, in order."""
    work, ctl._deferred = ctl._deferred, []
    for fn in work:
        fn(t)


def watch_inputs(ctl: Controller, t: float) -> None:
    """Axes that evaluate inputs every cycle (hardware limit switches, homing, drive signals)."""
    for axis in ctl._input_axes:
        try:
            axis._check_inputs(t)
        except Exception as exc:          # isolate a defect to its axis (16#8FFF, axis stopped)
            axis._internal_error(exc)


def replan(ctl: Controller, t: float) -> None:
    """Axes whose parameters changed while they move plan again, in axis order (deterministic)."""
    dirty = sorted(ctl._dirty_axes, key=lambda ax: ax.index)
    ctl._dirty_axes.clear()
    for axis in dirty:
        try:
            axis._apply_dirty("servo")
        except Exception as exc:          # a re-plan with the new values failed: 16#8FFF, stopped
            axis._internal_error(exc)


def axis_events(ctl: Controller, t: float) -> None:
    """Axes with an event due now (segment end, milestone, timer) handle it; the others are not visited."""
    due = ctl.bank.next_event <= t + _EPS_T
    if due.any():
        by_index = ctl._by_index
        for i in np.flatnonzero(due):
            axis = by_index[i]
            try:
                axis._on_event(t)
            except Exception as exc:      # isolate a defect to its axis (16#8FFF, axis stopped)
                axis._internal_error(exc)


# --- setpoints of all axes at once --------------------------------------------------------------------
def interpolate(ctl: Controller, t: float) -> None:
    """Evaluate the active constant-jerk segment of every axis at ``t``: the setpoint of this cycle."""
    b = ctl.bank
    tau = t - b.seg_t
    j = b.seg_j
    a = b.seg_a
    b.sp_p = b.seg_p + tau * (b.seg_v + tau * (0.5 * a + tau * (j * _SIXTH)))
    b.sp_v = b.seg_v + tau * (a + (0.5 * tau) * j)
    b.sp_a = a + tau * j
    b.sp_j = j
    ctl._bank_time = t


def superimpose(ctl: Controller, t: float) -> None:
    """Add the superimposed motion part (MC_MoveSuperimposed) to the basic motion of every axis."""
    b = ctl.bank
    tau = t - b.sup_t
    j = b.sup_j
    a = b.sup_a
    b.sup_now = b.sup_p + tau * (b.sup_v + tau * (0.5 * a + tau * (j * _SIXTH)))
    b.sp_p = b.sp_p + b.sup_now
    b.sp_v = b.sp_v + (b.sup_v + tau * (a + (0.5 * tau) * j))
    b.sp_a = b.sp_a + (a + tau * j)


def couple(ctl: Controller, t: float) -> None:
    """Synchronous operation: following axes take their setpoints from their leading values."""
    ctl.sync.run(t)


# --- closed loops -------------------------------------------------------------------------------------
def control(ctl: Controller, t: float) -> None:
    """Position control of the closed-loop axes (speed precontrol plus Kv times the following error);
    axes without position control have their setpoint follow the actual position."""
    if ctl._closed_loop:
        b = ctl.bank
        if getattr(ctl, "_n_sim", 0):
            # a simulation mode of the family: the setpoints are the actual values, the drive stands still
            b.act_p = np.where(b.simulated, b.sp_p, b.act_p)
            b.act_v = np.where(b.simulated, b.sp_v, b.act_v)
        # the masks are counted (``AxisBank.n_follow``, ``n_closed``): a uniform one needs no np.where
        if b.n_follow:
            b.sp_p = np.where(b.follow_act, b.act_p, b.sp_p)
        err = b.sp_p - b.act_p
        b.fe = err
        cmd = b.kpc * b.sp_v + b.kv * err
        b.cmd_v = cmd if b.n_closed == b.n else np.where(b.closed_loop, cmd, b.sp_v)


def monitor(ctl: Controller, t: float) -> None:
    """Following error, positioning and standstill monitoring of the closed-loop axes."""
    if ctl._closed_loop:
        if ctl._n_fe:
            monitoring.following_error(ctl, t)
        if ctl._n_pm:
            monitoring.positioning(ctl, t)
        monitoring.standstill(ctl, t)


# --- outputs ------------------------------------------------------------------------------------------
def write_drives(ctl: Controller, t: float) -> None:
    """Drive groups take the commands of this cycle (speed setpoints, pulse trains)."""
    b = ctl.bank
    for g in ctl._group_list:
        g.write(b, t)


def post_servo(ctl: Controller, t: float) -> None:
    """User hooks after the motion (traces, tags): setpoints and drive commands of this cycle."""
    ctl._run_hooks(ctl._post_servo, t)


Stage = Callable[[Controller, float], None]


class ServoStage(NamedTuple):
    """One stage of the servo cycle: ``run(ctl, t)`` is called when every attribute path of ``when``
    (e.g. ``"_encoders"``, ``"bank.n"``) is true on the controller; an empty ``when``: every cycle."""
    name: str
    run: Stage
    when: tuple[str, ...] = ()


#: the servo cycle, in order.  The names are public (``Controller.servo_stages``); ``when`` keeps an
#: idle stage from being called at all (no encoders, no hooks, no superimposed motion, no axes ...).
SERVO_STAGES: tuple[ServoStage, ...] = (
    ServoStage("read_drives", read_drives, ("_group_list",)),
    ServoStage("read_encoders", read_encoders, ("_encoders",)),
    ServoStage("read_inputs", read_inputs),
    ServoStage("pre_servo", pre_servo, ("_pre_servo",)),
    ServoStage("accept_jobs", accept_jobs, ("_deferred",)),
    ServoStage("watch_inputs", watch_inputs, ("_input_axes",)),
    ServoStage("replan", replan, ("bank.n", "_dirty_axes")),
    ServoStage("axis_events", axis_events, ("bank.n",)),
    ServoStage("interpolate", interpolate, ("bank.n",)),
    ServoStage("superimpose", superimpose, ("bank.n", "_n_sup")),
    ServoStage("couple", couple, ("bank.n", "sync.active")),
    ServoStage("control", control, ("bank.n",)),
    ServoStage("monitor", monitor, ("bank.n",)),
    ServoStage("write_drives", write_drives, ("_group_list",)),
    ServoStage("post_servo", post_servo, ("_post_servo",)),
)

#: the names of the stages in order
STAGE_NAMES: tuple[str, ...] = tuple(stage.name for stage in SERVO_STAGES)


def compile_cycle(stages: tuple[ServoStage, ...]) -> tuple[Callable[[Controller, float], None], str]:
    """One function that runs ``stages`` in order, one source line per stage.

    Generated instead of a loop over the list because a loop costs a call per stage even when the
    stage is idle and measurably slows the cycle (bench/axes.py); the generated code is what one
    would write by hand: ``if ctl.<when> and ...: stage_<name>(ctl, t)``.  The line of a stage is also how
    :func:`failed_stage` finds the stage that raised, without any per-stage bookkeeping."""
    lines = ["def run_servo_cycle(ctl, t):"]
    namespace: dict[str, object] = {}
    for stage in stages:
        fn = f"stage_{stage.name}"          # prefixed: a stage named "t" or "if" cannot break the code
        paths = [part for path in stage.when for part in path.split(".")]
        if not fn.isidentifier() or fn in namespace or not all(p.isidentifier() for p in paths):
            raise ValueError(f"servo stage {stage.name!r} (when {stage.when!r}): names must be unique identifiers")
        namespace[fn] = stage.run
        call = f"{fn}(ctl, t)"
        lines.append(f"    if {' and '.join('ctl.' + p for p in stage.when)}: {call}" if stage.when
                     else f"    {call}")
    source = "\n".join(lines) + "\n"
    filename = "<servo cycle>"
    exec(compile(source, filename, "exec"), namespace)   # noqa: S102 - our own table, no outside input
    # tracebacks through the generated function show its lines like those of a file
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    return namespace["run_servo_cycle"], source  # type: ignore[return-value]


#: ``run_servo_cycle(ctl, t)``: one servo cycle; RUNNER_SOURCE is its generated source (for reading)
run_servo_cycle, RUNNER_SOURCE = compile_cycle(SERVO_STAGES)


def failed_stage(exc: BaseException) -> str | None:
    """The name of the stage in which ``exc`` was raised by :func:`run_servo_cycle`, else None."""
    tb = exc.__traceback__
    code = run_servo_cycle.__code__
    while tb is not None:
        if tb.tb_frame.f_code is code:
            k = tb.tb_lineno - 2            # line 1 is the def, then one line per stage
            return STAGE_NAMES[k] if 0 <= k < len(STAGE_NAMES) else None
        tb = tb.tb_next
    return None


def describe() -> list[tuple[str, str]]:
    """``(name, what it does)`` of every stage in order, for docs and trace tools."""
    return [(s.name, " ".join((s.run.__doc__ or "").split("\n\n")[0].split())) for s in SERVO_STAGES]


__all__ = ["SERVO_STAGES", "STAGE_NAMES", "ServoStage", "compile_cycle", "describe", "failed_stage",
           "run_servo_cycle"]
