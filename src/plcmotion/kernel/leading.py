"""Leading value sources: setpoints, extrapolated actual values and delayed values (S7-1500T V5 §3.3).

* Setpoint coupling reads the leading axis's position setpoint of the same servo cycle.
* Actual value coupling reads the leading TO's actual position, filtered and extrapolated over the
  effective extrapolation time to make up for the delays of acquiring and processing it (§3.3.4):
  position PT2 filter, velocity PT2 filter and tolerance band, extrapolation, hysteresis.
* Delayed coupling reads the leading value of ``CrossPlcSynchronousOperation.LocalLeadingValueDelayTime``
  ago (§3.3.3) - the setpoint of an axis, the extrapolated actual value of an external encoder - so that
  local followers stay synchronous with followers on other controllers that get the value later (§8.1.3).

The manual does not print the extrapolation formula, the initial state of the tolerance band or the
hysteresis output after a reversal (catalog §11.2 item 5); plcmotion's reading (docs/s7_1500/decisions.md,
row 28): the extrapolation is exact for a constant velocity and a constant acceleration (the two cases
§3.3.4 promises to compensate), the band starts at the first filtered velocity, and the hysteresis holds
the leading value during a reversal smaller than ``Hysteresis.Value`` and is transparent otherwise.

Every TO that can lead owns a :class:`LeadingValueProvider` (``to.lv_provider``): an axis an
:class:`AxisLeadingValue`, an external encoder its own subclass.  Followers call the TO (``lv_value``,
``lv_slot``, ``lv_position_controlled``, ``lv_modulo``, ``leading_value_invalid``, the ``provides_*``
flags), which hands the call to its provider; a leading axis proxy answers them itself.  Per servo cycle
a provider costs only what a follower asked for: one extrapolation step (actual value coupling) and one
recorded sample (delayed coupling, cross-PLC output) in the synchronous operation stage.
"""
from __future__ import annotations

from collections import deque
from typing import Any, Callable, Protocol

from .axis_config import Extrapolation, LeadingValueOutput, Modulo
from .leading_value import LeadingValueSample, LeadingValueSink


def _pt1(y: float, x: float, dt: float, T: float) -> float:
    """First-order lag, discretized so that it lags a ramp by exactly T (the time the extrapolation
    adds back)."""
    if T <= 0.0:
        return x
    return y + dt / (T + dt) * (x - y)


class Extrapolator:
    """Actual value processing of one leading TO (§3.3.4 pipeline), one step per servo cycle.

    Closed form per cycle (S7-1500T V5 §3.3.4, §6.1.5.8, §A.1.10):

    * ``p_f`` = PT2(actual position; PositionFilter.T1, T2) -> StatusExtrapolation.FilteredPosition
    * ``v_f`` = tolerance band(PT2(actual velocity; VelocityFilter.T1, T2)) -> FilteredVelocity
    * ``a``   = change of ``v_f`` per cycle, smoothed by a PT2 with the velocity filter's time constants:
      a ramp passes the PT1 stages and the band with its slope unchanged and a constant passes the
      PT2, so this is the acceleration of a uniformly accelerating leading value (0 while the band
      holds the velocity)
    * extrapolated position over the effective extrapolation time T (§3.3.4)::

          x = p_f - a*c_p + (v_f + a*(Tv + lag - Tp))*T + a*T^2/2

      ``p_f`` stands for the position of ``Tp`` = PositionFilter.T1 + T2 ago, ``v_f`` for the velocity
      of ``Tv + lag`` ago (velocity filters T1 + T2, plus half a cycle for a velocity that is a backward
      difference); ``c_p`` is the offset the discrete PT2 filter adds to a parabola.  At constant
      velocity (a = 0) this is ``p_f + v_f*T``; at constant acceleration it is the actual position of
      ``T - Tp`` later, exactly - only a jerk displaces the follower (§3.3.4) - unless a tolerance band
      is set: the band's output trails an accelerating velocity by half its width (§3.3.4).
    * hysteresis (§3.3.4): a change of direction takes effect only once the extrapolated position has
      gone back by at least Hysteresis.Value from its turning point; meanwhile the leading value holds
      the turning point.  Then it moves on at twice the speed of the input until it has caught up with
      it (the input's next Hysteresis.Value of travel), so it never jumps and has no lasting offset.
    """

    def __init__(self, source: "LeadingValueProvider"):
        self.source = source
        self.host = source.host            # read every cycle: its configuration (one hop, as before)
        self.ready = False
        self.pf1 = self.pf2 = self.vf1 = self.vf2 = self.af1 = self.af2 = 0.0
        self.band = 0.0
        self.hyst = 0.0
        self.direction = 0                 # direction of the leading value (hysteresis), 0 = none yet
        self.turn = 0.0                    # farthest input in that direction (the turning point)
        self.filtered_position = self.filtered_velocity = 0.0
        self.position = self.velocity = self.acceleration = 0.0
        self._prev: float | None = None

    def step(self, t: float, dt: float) -> tuple[float, float, float]:
        src = self.source
        x = self.host.config.extrapolation
        if not src.actual_values_valid():
            return self._without_actual_values(dt)
        p, v = src.actual_values()
        if not self.ready:
            self.pf1 = self.pf2 = p
            self.vf1 = self.vf2 = self.band = v
            self.af1 = self.af2 = 0.0
            self.hyst = self.turn = p
            self.direction = 0
            self._prev = None
            self.ready = True
        tp1, tp2 = x.position_filter_t1, x.position_filter_t2
        tv1, tv2 = x.velocity_filter_t1, x.velocity_filter_t2
        self.pf1 = _pt1(self.pf1, p, dt, tp1)
        self.pf2 = _pt1(self.pf2, self.pf1, dt, tp2)
        self.vf1 = _pt1(self.vf1, v, dt, tv1)
        self.vf2 = _pt1(self.vf2, self.vf1, dt, tv2)
        half = x.velocity_tolerance / 2.0
        band = self.band
        self.band = min(max(band, self.vf2 - half), self.vf2 + half)
        # acceleration: the velocity's change per cycle, smoothed like the velocity (a constant one passes)
        self.af1 = _pt1(self.af1, (self.band - band) / dt, dt, tv1)
        acc = self.af2 = _pt1(self.af2, self.af1, dt, tv2)
        self.filtered_position, self.filtered_velocity = self.pf2, self.band
        T = src.extrapolation_time()
        tp = tp1 + tp2
        # PT2 on a parabola (discrete, backward difference form): p(t - Tp) + a*((tp1^2 + tp2^2)/2 + Tp*dt/2)
        c_p = 0.5 * (tp1 * tp1 + tp2 * tp2 + tp * dt)
        xp = self.pf2 + T * self.band
        if acc != 0.0:
            xp += acc * (T * (tv1 + tv2 + src.velocity_lag(dt) - tp + 0.5 * T) - c_p)
        y = self._hysteresis(xp, x.hysteresis)
        prev = self._prev
        self.position = y
        if x.differentiated_velocity and prev is not None:
            self.velocity = (y - prev) / dt
        else:
            self.velocity = self.band
        # the extrapolated acceleration; none while the hysteresis holds the leading value back
        self.acceleration = acc if y == xp else 0.0
        self._prev = y
        return self.position, self.velocity, self.acceleration

    def _without_actual_values(self, dt: float) -> tuple[float, float, float]:
        """No valid actual value (an encoder fault): in the cycle of the fault the last leading value is
        carried forward, so that the followers, stopped with the fault, brake from where they are at the
        speed they had; then it stands.  The filters start anew with the next valid value."""
        if self.ready:
            a = self.acceleration
            self.position += dt * (self.velocity + 0.5 * dt * a)
            self.velocity += dt * a
            self.ready = False
        else:
            self.velocity = self.acceleration = 0.0
        return self.position, self.velocity, self.acceleration

    def _hysteresis(self, x: float, width: float) -> float:
        """Reversal suppression of the extrapolated position ``x`` (see the class docstring)."""
        d = self.direction
        y = self.hyst
        if d == 0:
            if x != y:
                self.direction = 1 if x > y else -1
            self.hyst = self.turn = x
            return x
        on = (x - self.turn) * d                  # travel beyond the turning point in direction d
        if on < 0.0:
            if -on < width:
                return y                          # a reversal within the hysteresis: hold
            on = -on - width                      # the reversal takes effect: travel beyond the width
            d = self.direction = -d
        self.turn = x
        # move towards x by twice the input's travel at most, never past it, never backwards
        gap = (x - y) * d
        if gap > 0.0:
            y = x if 2.0 * on >= gap else y + 2.0 * on * d
            self.hyst = y
        return y


class DelayLine:
    """A leading value delayed by a (changeable) time: samples of the last cycles, interpolated."""

    def __init__(self, source: "LeadingValueProvider"):
        self.source = source
        self.samples: deque[tuple[float, float, float, float]] = deque()

    def record(self, t: float, p: float, v: float, a: float, keep: float) -> None:
        self.samples.append((t, p, v, a))
        while len(self.samples) > 2 and self.samples[1][0] < t - keep:
            self.samples.popleft()

    def at(self, t: float) -> tuple[float, float, float]:
        s = self.samples
        if not s:
            return self.source.provided_value_at(t)
        if t >= s[-1][0]:
            t0, p, v, a = s[-1]
            dt = t - t0
            return p + dt * (v + 0.5 * dt * a), v + dt * a, a
        if t <= s[0][0]:
            return s[0][1], s[0][2], s[0][3]
        lo, hi = 0, len(s) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if s[mid][0] <= t:
                lo = mid
            else:
                hi = mid
        t0, p0, v0, a0 = s[lo]
        t1, p1, v1, a1 = s[hi]
        w = (t - t0) / (t1 - t0)
        # cubic Hermite in position with the velocities as slopes
        h = t1 - t0
        w2, w3 = w * w, w * w * w
        p = (2 * w3 - 3 * w2 + 1) * p0 + (w3 - 2 * w2 + w) * h * v0 + (-2 * w3 + 3 * w2) * p1 + (w3 - w2) * h * v1
        return p, v0 + w * (v1 - v0), a0 + w * (a1 - a0)


def setpoint_at(axis: Any, t: float) -> tuple[float, float, float]:
    """The setpoint of ``axis`` at ``t``: the last servo cycle's values carried forward (for code that runs
    between servo cycles or before the interpolator of the present one)."""
    b, i = axis.ctl.bank, axis.index
    p, v, a = float(b.sp_p[i]), float(b.sp_v[i]), float(b.sp_a[i])
    dt = t - axis.ctl._bank_time
    if dt > 0.0:
        p, v = p + dt * (v + 0.5 * dt * a), v + dt * a
    return p, v, a


# --- the component ---------------------------------------------------------------------------------------
class SyncStage(Protocol):
    """The controller's synchronous operation stage, as far as a provider uses it."""

    def register_ext(self, provider: Callable[[float], tuple[float, float, float]]) -> int: ...

    def register_post(self, fn: Callable[[float], None]) -> None: ...


class LeadingValueController(Protocol):
    """What a provider needs of the controller: the clock, the synchronous operation stage and (for an
    axis) the array bank with the setpoints and actual values of the last servo cycle."""

    time: float
    servo_cycle: float
    _bank_time: float                  # servo time of the values in the bank
    sync: SyncStage
    bank: Any


class LeadingValueConfig(Protocol):
    """The part of a TO's configuration a provider reads (``AxisConfig``, ``LeadingValueSourceConfig``)."""

    @property
    def modulo(self) -> Modulo: ...

    @property
    def extrapolation(self) -> Extrapolation: ...

    @property
    def leading_value_output(self) -> LeadingValueOutput: ...


class LeadingValueHost(Protocol):
    """What a provider needs of the technology object that owns it."""

    @property
    def name(self) -> str: ...

    @property
    def ctl(self) -> LeadingValueController: ...

    @property
    def config(self) -> LeadingValueConfig: ...

    @property
    def sim(self) -> bool: ...


class LeadingAxisHost(LeadingValueHost, Protocol):
    """What :class:`AxisLeadingValue` needs of an axis in addition: its row in the bank and its state."""

    @property
    def index(self) -> int: ...

    @property
    def servo(self) -> bool: ...

    @property
    def state(self) -> str: ...

    @property
    def position_controlled(self) -> bool: ...

    def _blocking_alarm(self) -> object | None: ...


class LeadingValueProvider:
    """The leading value a technology object provides to its followers (S7-1500T V5 §3.3, §8.1.3).

    The owner is the leading TO (an axis, an external encoder); its followers keep calling the TO
    (``lv_value``, ``lv_slot``, ...), which hands the call on.  This class holds what every kind of
    leading TO shares: the actual value processing (:class:`Extrapolator`, created with the first
    follower that couples to the actual value), the delay line of the delayed value (created with the
    first delayed follower or the cross-PLC output), the slots of both in the synchronous operation stage
    and the cross-PLC output.  What the owner measures and provides - its actual values, the value it
    delays and sends - is given by the subclass for its kind of TO (:class:`AxisLeadingValue` here, the
    external encoder's in its own module).
    """

    def __init__(self, host: LeadingValueHost):
        self.host = host
        self.ctl = host.ctl
        self.extrapolator: Extrapolator | None = None
        self.delay_line: DelayLine | None = None
        self.slots: dict[str, int] = {}       # coupling type -> slot in the sync stage

    def __repr__(self) -> str:
        return f"<{type(self).__name__} of {self.host.name}>"

    # --- what the owner measures and provides (given by the subclass) ----------------------------------
    def actual_values(self) -> tuple[float, float]:
        """The actual position and velocity of this servo cycle."""
        raise NotImplementedError

    def actual_values_valid(self) -> bool:
        """Are the actual values valid (no encoder fault)?"""
        return True

    def velocity_lag(self, dt: float) -> float:
        """Age of the actual velocity relative to the actual position."""
        raise NotImplementedError

    def provided_value(self) -> tuple[float, float, float]:
        """This servo cycle's value for delayed followers and other controllers."""
        raise NotImplementedError

    def provided_value_at(self, t: float) -> tuple[float, float, float]:
        """The provided value at ``t`` (between servo cycles: carried forward)."""
        raise NotImplementedError

    def provided_value_valid(self) -> tuple[bool, bool]:
        """(valid, tracking) of the provided value (telegram flags, §8.1.4)."""
        raise NotImplementedError

    def lv_position_controlled(self) -> bool:
        """May a follower with setpoint coupling start following now (§3.3.5)?"""
        raise NotImplementedError

    def leading_value_invalid(self, mode: str) -> str | None:
        """Why a new coupling of type ``mode`` cannot use this leading value now (None: it can)."""
        return None

    # --- what followers read ---------------------------------------------------------------------------
    def lv_modulo(self) -> tuple[float, float] | None:
        """(start, length) of the modulo range of the leading value, None without modulo."""
        m = self.host.config.modulo
        return (m.start, m.length) if m.enabled else None

    def lv_value(self, mode: str, t: float) -> tuple[float, float, float]:
        """The leading value this TO provides with coupling type ``mode`` at time ``t``."""
        if mode == "setpoint":
            return self.provided_value_at(t)
        if mode == "actual":
            ex = self.ensure_extrapolator()
            p, v, a = ex.position, ex.velocity, ex.acceleration
            dt = t - self.ctl._bank_time
            if dt > 0.0:                    # between servo cycles: carried forward
                p, v = p + dt * (v + 0.5 * dt * a), v + dt * a
            return p, v, a
        return self.ensure_delay_line().at(t - self.local_delay_time())

    def lv_slot(self, mode: str) -> int:
        """Slot of this source's actual or delayed leading value in the sync stage (created on first use)."""
        slot = self.slots.get(mode)
        if slot is None:
            if mode == "actual":
                ex = self.ensure_extrapolator()
                slot = self.ctl.sync.register_ext(lambda t, ex=ex: (ex.position, ex.velocity, ex.acceleration))
            else:
                line = self.ensure_delay_line()
                host = self.host            # bound here: the delay is read every cycle
                slot = self.ctl.sync.register_ext(
                    lambda t, line=line: line.at(t - host.config.leading_value_output.local_delay_time))
            self.slots[mode] = slot
        return slot

    def ensure_extrapolator(self) -> Extrapolator:
        """The actual value processing; the first call starts it in the sync stage (before the couplings
        of each servo cycle)."""
        if self.extrapolator is None:
            ctl = self.ctl
            ex = Extrapolator(self)
            ex.step(ctl.time, ctl.servo_cycle)
            self.extrapolator = ex
            dt = ctl.servo_cycle
            ctl.sync.register_ext(lambda t, ex=ex: ex.step(t, dt))
        return self.extrapolator

    def ensure_delay_line(self) -> DelayLine:
        """The delay line of the provided value; the first call starts recording it after each servo cycle
        (the delay plus four cycles are kept)."""
        if self.delay_line is None:
            line = DelayLine(self)
            self.delay_line = line
            ctl = self.ctl
            host = self.host
            provided = self.provided_value

            def record(t: float) -> None:
                line.record(t, *provided(), host.config.leading_value_output.local_delay_time + 4 * ctl.servo_cycle)

            record(ctl._bank_time)
            ctl.sync.register_post(record)
        return self.delay_line

    def local_delay_time(self) -> float:
        """CrossPlcSynchronousOperation.LocalLeadingValueDelayTime: the delay of delayed followers (§3.3.3)."""
        return self.host.config.leading_value_output.local_delay_time

    def provide_leading_value(self, sink: LeadingValueSink) -> None:
        """Send the provided value to another controller every servo cycle (cross-PLC, §8): needs the
        leading value output configured (``LeadingValueOutput.enabled``; S7-1500:
        ``CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput`` = TRUE).

        Each telegram carries the delay of the local delayed followers, so that a leading axis proxy
        provides the value these followers use at the same time (§8.1.3) without being told the delay.
        """
        host = self.host
        if not host.config.leading_value_output.enabled:
            raise ValueError(f"{host.name}: set CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput "
                             f"to provide a cross-PLC leading value")
        counter = [0]
        provided = self.provided_value
        valid_now = self.provided_value_valid
        self.ensure_delay_line()            # StatusProvidedLeadingValue.DelayedLeadingValue (§8.1.4)

        def send(t: float) -> None:
            config = host.config
            m = config.modulo
            counter[0] += 1
            valid, tracking = valid_now()
            sink.send(LeadingValueSample(
                t, *provided(), valid=valid, tracking=tracking,
                modulo_length=m.length if m.enabled else 0.0,
                modulo_start=m.start, sequence=counter[0], delay=config.leading_value_output.local_delay_time))
        self.ctl.sync.register_post(send)

    # --- status (tags) ---------------------------------------------------------------------------------
    def leading_axis_dependent_time(self) -> float:
        """T_i + T_Ipo + position filter T1 + T2 (§3.3.6); T_i is one servo cycle for a real encoder."""
        x = self.host.config.extrapolation
        cycle = self.ctl.servo_cycle
        ti = 0.0 if self.host.sim else cycle
        return ti + cycle + x.position_filter_t1 + x.position_filter_t2

    def extrapolation_time(self) -> float:
        """Effective extrapolation time: leading-axis part (if included) + following-axis part + delay."""
        x = self.host.config.extrapolation
        t = x.following_axis_time + self.local_delay_time()
        if x.include_leading_axis_time:
            t += self.leading_axis_dependent_time()
        return t

    def extrapolation_status(self) -> tuple[float, float, float, float]:
        """StatusExtrapolation: filtered position and velocity, extrapolated position and velocity."""
        ex = self.extrapolator
        if ex is None:
            return 0.0, 0.0, 0.0, 0.0
        return ex.filtered_position, ex.filtered_velocity, ex.position, ex.velocity

    def delayed_leading_value(self) -> tuple[float, float, float]:
        """StatusProvidedLeadingValue.DelayedLeadingValue (§8.1.4): zero until something is delayed."""
        if self.delay_line is None:
            return 0.0, 0.0, 0.0
        return self.delay_line.at(self.ctl._bank_time - self.local_delay_time())


class AxisLeadingValue(LeadingValueProvider):
    """The leading value of an axis: what it delays for its delayed followers and sends to other
    controllers is its setpoint; its actual values are those of its drive - a virtual axis's equal its
    setpoints (§3.3.2, decision 29).  Setpoint coupling waits for position control (§3.3.5)."""

    def __init__(self, host: LeadingAxisHost):
        super().__init__(host)
        self.axis = host
        self.index = host.index              # the axis's row in the bank (fixed for its life)

    def actual_values(self) -> tuple[float, float]:
        b, i = self.ctl.bank, self.index
        return float(b.act_p[i]), float(b.act_v[i])

    def velocity_lag(self, dt: float) -> float:
        """Half a cycle for a velocity that is the difference of two encoder values, none for the exact
        velocity of a simulated drive."""
        return 0.5 * dt if self.axis.servo else 0.0

    def provided_value(self) -> tuple[float, float, float]:
        b, i = self.ctl.bank, self.index
        return float(b.sp_p[i]), float(b.sp_v[i]), float(b.sp_a[i])

    def provided_value_at(self, t: float) -> tuple[float, float, float]:
        return setpoint_at(self, t)

    def provided_value_valid(self) -> tuple[bool, bool]:
        ax = self.axis
        return (ax.state in ("enabled", "disabling") and ax._blocking_alarm() is None,
                bool(ax.servo and not self.ctl.bank.closed_loop[self.index]))

    def lv_position_controlled(self) -> bool:
        """Setpoint coupling needs a position-controlled leading axis (§3.3.5)."""
        ax = self.axis
        return ax.state in ("enabled", "disabling") and ax.position_controlled
