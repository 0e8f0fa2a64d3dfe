"""Property tests: random sequences of valid motion commands on PTO and PROFIdrive axes.

Only what the S7-1200 Motion Control V6 manual (seeds/000_a03aa7b7d80586ce.txt) guarantees is asserted:

* §5.4.4.4 dynamics: the setpoint velocity never exceeds DynamicLimits.MaxVelocity; while no axis
  error is pending (no emergency stop) the setpoint acceleration never exceeds
  max(Acceleration, Deceleration);
* §5.4.4.4: on a PTO axis the setpoint velocity is 0 or at least the start/stop velocity ("the
  minimum permissible velocity of the axis");
* §12.9.1 / §12.9.2: Position, Velocity, ActualPosition are numbers (no NaN / infinity);
* §9.5.2 - §9.5.4: Busy / Done / CommandAborted / Error are mutually exclusive at every call; when
  Busy of an instruction with Done output falls, exactly one of Done, CommandAborted, Error is TRUE;
* §11.1.4 - §11.1.8 override lists: every motion command aborts the active one, so at most one motion
  instance of the axis is Busy (checked at a call pass where no new command starts; the outputs of an
  instance only change when it is called, §9.3; a MC_MoveVelocity with Velocity = 0.0 that has
  reached standstill keeps Busy/InVelocity latched while Execute = TRUE, §11.1.7.1, and is left out);
* §11.1.5 / §11.1.6 / §11.1.4: Done means target reached at standstill (MoveAbsolute: Position,
  MoveRelative: position at the start + Distance, MC_Halt: velocity zero);
  §11.1.7 / §11.1.8: InVelocity means the commanded velocity is reached;
* §9.6 / §12.8: valid inputs on an enabled, homed axis without limit switches give no error at all.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative,
                               MC_MoveVelocity, MC_Power, MC_Reset)

APP = 0.004


# ----------------------------------------------------------------------------------------------------
# strategies
@dataclass
class Axis:
    kind: str
    vmax: float
    vmin: float
    acc: float
    dec: float
    jerk: float


@st.composite
def axes(draw):
    kind = draw(st.sampled_from(["pto", "pd"]))
    vmax = draw(st.floats(20.0, 200.0))
    vmin = draw(st.floats(1.0, 10.0)) if kind == "pto" else 0.0
    acc = draw(st.floats(10.0, 300.0))
    dec = draw(st.floats(10.0, 300.0))
    jerk = draw(st.one_of(st.just(0.0), st.floats(50.0, 5000.0)))
    return Axis(kind, vmax, vmin, acc, dec, jerk)


frac = st.floats(0.0, 1.0)
gap = st.integers(0, 100)                         # application cycles before the command
held = st.booleans()                              # Execute kept TRUE, or a one-cycle pulse

commands = st.one_of(
    st.tuples(st.just("abs"), gap, held, st.floats(-300.0, 300.0), frac),
    st.tuples(st.just("rel"), gap, held, st.floats(-300.0, 300.0), frac),
    st.tuples(st.just("vel"), gap, held, frac, st.sampled_from([1, -1]), st.sampled_from([0, 1, 2]),
              st.booleans()),
    st.tuples(st.just("halt"), gap, held),
    st.tuples(st.just("jog"), gap, st.booleans(), frac, st.integers(0, 150)),
)


# ----------------------------------------------------------------------------------------------------
@dataclass
class Rec:
    fb: object
    kind: str
    release_at: int | None = None        # cycle at which Execute / the jog input goes FALSE
    target: float | None = None          # positioning: absolute target
    velocity: float | None = None        # velocity / jog: signed commanded velocity
    prev_busy: bool = False
    prev_done: bool = False
    zero_done: bool = False              # MoveVelocity(0.0) reached standstill (latched outputs)
    history: list = field(default_factory=list)


class ServoCheck:
    """Per servo cycle invariants, collected (an exception inside a hook would stop the controller)."""

    def __init__(self, ctl, axis, cfg: Axis, limits=None, check_vmin=False):
        self.axis, self.cfg, self.limits, self.check_vmin = axis, cfg, limits, check_vmin
        self.violations: list[str] = []
        self.amax = max(cfg.acc, cfg.dec)
        self.short_move = False           # §12.5: a PTO positioning shorter than 2 ms runs slower
        ctl.on_post_servo(self)

    def __call__(self, t):
        ax = self.axis
        p, v, a, pa = ax.Position, ax.Velocity, ax.Acceleration, ax.ActualPosition
        if not all(math.isfinite(x) for x in (p, v, a, pa)):
            self.violations.append(f"t={t:.3f}: not finite p={p} v={v} a={a} actual={pa}")
            return
        if abs(v) > self.cfg.vmax * (1 + 1e-9) + 1e-9:
            self.violations.append(f"t={t:.3f}: |v|={abs(v)} > MaxVelocity {self.cfg.vmax}")
        # §5.4.4.4: "The start/stop velocity is the minimum permissible velocity of the axis" (PTO)
        if (self.check_vmin and self.cfg.kind == "pto" and 0.0 < abs(v) < self.cfg.vmin * (1 - 1e-6)
                and not self.short_move):
            self.violations.append(f"t={t:.3f}: 0 < |v|={abs(v)} < start/stop velocity {self.cfg.vmin}")
        # ruckig's solutions meet the limits to about 1e-8 relative (floating point root finding)
        if not ax.StatusBits.Error and abs(a) > self.amax * (1 + 1e-8) + 1e-9:
            self.violations.append(f"t={t:.3f}: |a|={abs(a)} > max(acc, dec) {self.amax}")
        if self.limits is not None and not self.limits[0] - 1e-6 <= p <= self.limits[1] + 1e-6:
            self.violations.append(f"t={t:.3f}: setpoint {p} outside the SW limits {self.limits}")


def _velocity(cfg: Axis, f: float) -> float:
    """A valid Velocity input: start/stop velocity <= v <= max velocity, > 0 (§11.1.5 - §11.1.8)."""
    lo = cfg.vmin if cfg.kind == "pto" else 0.02 * cfg.vmax
    return lo + f * (cfg.vmax - lo)


def _check_call(rec: Rec, axis, cfg: Axis, errors: list[str], label: str, allowed=frozenset()):
    fb = rec.fb
    flags = {"Busy": fb.Busy, "Error": fb.Error, "CommandAborted": getattr(fb, "CommandAborted", False)}
    if hasattr(fb, "Done"):
        flags["Done"] = fb.Done
    on = [k for k, val in flags.items() if val]
    if len(on) > 1 and not (rec.zero_done and on == ["Busy"]):
        errors.append(f"{label}: {type(fb).__name__} outputs not exclusive: {on}")
    if (fb.Error or fb.ErrorID) and not (fb.Error and (fb.ErrorID, fb.ErrorInfo) in allowed):
        errors.append(f"{label}: {type(fb).__name__} Error 16#{fb.ErrorID:04X}/16#{fb.ErrorInfo:04X}")
    ptol = 1e-6 * max(1.0, abs(rec.target or 0.0)) if cfg.kind == "pd" else 0.011
    if hasattr(fb, "Done"):
        if rec.prev_busy and not fb.Busy and sum(flags[k] for k in ("Done", "CommandAborted", "Error")) != 1:
            errors.append(f"{label}: {type(fb).__name__} Busy fell without exactly one of "
                          f"Done/CommandAborted/Error ({fb!r})")
        if fb.Done and not rec.prev_done and rec.kind in ("abs", "rel", "halt"):
            if axis.Velocity != 0.0:
                errors.append(f"{label}: {type(fb).__name__} Done at velocity {axis.Velocity}")
            if rec.target is not None and abs(axis.Position - rec.target) > ptol:
                errors.append(f"{label}: {type(fb).__name__} Done at {axis.Position}, target {rec.target}")
        rec.prev_done = fb.Done
    # with SW limits, Busy/InVelocity stay TRUE while the limit brakes the axis until the error
    # (§9.5.3: "until the command is overridden ... or stopped by an error"): not checked then
    if getattr(fb, "InVelocity", False) and not rec.zero_done:
        tol = 1e-6 * max(1.0, abs(rec.velocity))
        if abs(axis.Velocity - rec.velocity) > tol and not allowed:
            errors.append(f"{label}: {type(fb).__name__} InVelocity at {axis.Velocity}, "
                          f"commanded {rec.velocity}")
        if rec.velocity == 0.0:
            rec.zero_done = True
    rec.prev_busy = fb.Busy


def run_scenario(cfg: Axis, cmds, finish: bool = False, limits=None, check_vmin=False) -> list[str]:
    """Run the commands; with ``finish`` keep going until the last command has ended (Done).
    ``limits``: (MinPosition, MaxPosition) of active SW limit switches; then only the SW limit errors
    16#8001/16#8002 ErrorInfo 16#000E (reached with the configured deceleration) are allowed."""
    ctl = Controller(servo_cycle=0.001, app_cycle=APP)
    params = {"Actor": {"Type": 2 if cfg.kind == "pto" else 1},
              "DynamicLimits": {"MaxVelocity": cfg.vmax},
              "DynamicDefaults": {"Acceleration": cfg.acc, "Deceleration": cfg.dec, "Jerk": cfg.jerk,
                                  "EmergencyDeceleration": 5 * max(cfg.acc, cfg.dec)}}
    if cfg.kind == "pto":
        params["DynamicLimits"]["MinVelocity"] = cfg.vmin
    allowed = frozenset()
    if limits is not None:
        params["PositionLimits_SW"] = {"Active": True, "MinPosition": limits[0], "MaxPosition": limits[1]}
        allowed = frozenset({(0x8001, 0x000E), (0x8002, 0x000E)})
    axis = ctl.add_positioning_axis("Axis_1", params)
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    home = MC_Home()
    home(Axis=axis, Execute=True, Mode=0, Position=0.0)
    ctl.run_until(lambda: home().Done, timeout=1.0)

    check = ServoCheck(ctl, axis, cfg, limits, check_vmin)
    errors: list[str] = []
    starts: dict[int, list] = {}
    k = 0
    for cmd in cmds:
        k += cmd[1]
        starts.setdefault(k, []).append(cmd)
    total = k + 150
    recs: list[Rec] = []

    cycle = -1
    while True:
        cycle += 1
        if cycle > total and not (finish and recs and recs[-1].fb.Busy and cycle < total + 20000):
            break
        label = f"cycle {cycle} (t={ctl.time:.3f})"
        # 1) the program calls every instance (no new command in this pass)
        for rec in recs:
            fb = rec.fb
            if rec.release_at == cycle:
                if rec.kind == "jog":
                    fb(JogForward=False, JogBackward=False)
                else:
                    fb(Execute=False)
            else:
                fb()
            _check_call(rec, axis, cfg, errors, label, allowed)
        busy = [type(r.fb).__name__ for r in recs if r.fb.Busy and not r.zero_done and r.kind != "reset"]
        if len(busy) > 1:
            errors.append(f"{label}: more than one motion instance Busy: {busy}")
        power()
        if not power.Status or (power.Error and (power.ErrorID, power.ErrorInfo) not in allowed):
            errors.append(f"{label}: MC_Power {power!r}")
        if errors or check.violations:
            break
        # 2) new commands of this cycle
        for cmd in starts.get(cycle, []):
            kind = cmd[0]
            check.short_move = False
            rec = Rec(None, kind)
            if kind == "abs":
                _, _, hold, pos, f = cmd
                rec.fb, rec.target = MC_MoveAbsolute(), pos
                # §12.5: from standstill a move of less than start/stop velocity x 2 ms takes 2 ms
                check.short_move = axis.Velocity == 0.0 and abs(pos - axis.Position) < cfg.vmin * 0.002
                rec.fb(Axis=axis, Execute=True, Position=pos, Velocity=_velocity(cfg, f))
            elif kind == "rel":
                _, _, hold, dist, f = cmd
                rec.fb, rec.target = MC_MoveRelative(), axis.Position + dist
                check.short_move = axis.Velocity == 0.0 and abs(dist) < cfg.vmin * 0.002
                rec.fb(Axis=axis, Execute=True, Distance=dist, Velocity=_velocity(cfg, f))
            elif kind == "vel":
                _, _, hold, f, sign, direction, zero = cmd
                v = 0.0 if zero and f < 0.2 else _velocity(cfg, f) * sign
                rec.fb = MC_MoveVelocity()
                rec.velocity = v if direction == 0 else abs(v) if direction == 1 else -abs(v)
                rec.fb(Axis=axis, Execute=True, Velocity=v, Direction=direction)
            elif kind == "reset":
                _, _, hold = cmd
                rec.fb = MC_Reset()
                rec.fb(Axis=axis, Execute=True)
            elif kind == "halt":
                _, _, hold = cmd
                rec.fb = MC_Halt()
                rec.fb(Axis=axis, Execute=True)
            else:
                _, _, forward, f, hold_cycles = cmd
                v = _velocity(cfg, f)
                rec.fb, rec.velocity = MC_MoveJog(), v if forward else -v
                rec.fb(Axis=axis, JogForward=forward, JogBackward=not forward, Velocity=v)
                hold = True
                rec.release_at = cycle + 1 + hold_cycles
            if kind != "jog":
                rec.release_at = None if hold else cycle + 1
            _check_call(rec, axis, cfg, errors, label + " start", allowed)
            recs.append(rec)
        ctl.step()
    errors.extend(check.violations[:5])
    if finish and not errors:
        last = recs[-1].fb
        if not last.Done:
            errors.append(f"last command did not end with Done: {last!r}")
    return errors


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cfg=axes(), cmds=st.lists(commands, min_size=1, max_size=8))
def test_kernel_random_command_sequences_keep_manual_invariants(cfg, cmds):
    """§5.4.4.4, §9.5.2-§9.5.4, §9.6, §11.1.4-§11.1.8: invariants of every random sequence of valid
    MC_MoveAbsolute / MC_MoveRelative / MC_MoveVelocity / MC_Halt / MC_MoveJog commands."""
    errors = run_scenario(cfg, cmds)
    assert not errors, "\n".join(errors[:10])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cfg=axes(), cmds=st.lists(st.tuples(st.just("abs"), st.integers(0, 30), st.just(True),
                                           st.floats(-100.0, 100.0), st.floats(0.3, 1.0)),
                                 min_size=2, max_size=6))
def test_kernel_rapid_absolute_overrides(cfg, cmds):
    """§11.1.5 override: MC_MoveAbsolute started while another one runs (S-MABS-2) -- each new command
    aborts the previous one and the last one ends Done exactly at its target, within the limits."""
    errors = run_scenario(cfg, cmds, finish=True)
    assert not errors, "\n".join(errors[:10])


limit_commands = st.one_of(commands, st.tuples(st.just("reset"), gap, held))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cfg=axes(), cmds=st.lists(limit_commands, min_size=1, max_size=10),
       lo=st.floats(-150.0, -5.0), hi=st.floats(5.0, 150.0))
# found by this property: a slower MC_MoveAbsolute to the limit position overriding the limit braking
# of a PTO axis passes the limit (see test_s7_1200_override_during_limit_braking_never_passes_limit_5_4_4_3)
@example(cfg=Axis(kind="pto", vmax=20.0, vmin=2.0, acc=103.0, dec=17.0, jerk=0.0),
         cmds=[("vel", 0, False, 1.0, 1, 0, False), ("abs", 25, False, 0.0, 0.0), ("abs", 0, False, 5.0, 0.0)],
         lo=-5.0, hi=5.0)
def test_kernel_random_commands_with_sw_limits(cfg, cmds, lo, hi):
    """§5.4.4.3 / §12.8 / §12.4: with active SW limit switches on a homed axis and unchanged dynamics,
    every motion is stopped at the latest at the limit with the configured deceleration: the setpoint
    never leaves [MinPosition, MaxPosition], the only errors are 16#8001/16#8002 ErrorInfo 16#000E
    (never 16#000F/16#0010, which need a coordinate jump or a lower deceleration), the axis stays
    enabled, and all other invariants of the first property hold.  MC_Reset commands are interleaved."""
    errors = run_scenario(cfg, cmds, limits=(lo, hi))
    assert not errors, "\n".join(errors[:10])


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cfg=axes().filter(lambda c: c.kind == "pto"), cmds=st.lists(commands, min_size=1, max_size=8))
# found by this property: MC_MoveRelative(Distance = 0.0) while moving at the start/stop velocity with
# the jerk limit on overshoots and returns at velocities below the start/stop velocity
@example(cfg=Axis(kind="pto", vmax=20.0, vmin=1.0, acc=10.0, dec=10.0, jerk=50.0),
         cmds=[("vel", 0, True, 0.0, 1, 0, False), ("rel", 30, True, 0.0, 0.0)])
def test_kernel_pto_velocity_zero_or_at_least_start_stop(cfg, cmds):
    """§5.4.4.4: "The start/stop velocity is the minimum permissible velocity of the axis" -- the
    setpoint velocity of a PTO axis is 0 or at least DynamicLimits.MinVelocity in every servo cycle,
    for any sequence of valid commands (and all invariants of the first property hold)."""
    errors = run_scenario(cfg, cmds, check_vmin=True)
    assert not errors, "\n".join(errors[:10])
