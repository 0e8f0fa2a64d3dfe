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
"""
from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis


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

    def __init__(self, source: Any):
        self.source = source
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
        x = src.config.extrapolation
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

    def __init__(self, source: Any):
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


class LeadingValueMixin:
    """What a leading TO offers its followers: mixed into the S7-1500 axes and the external encoder.

    What an axis delays for its delayed followers and sends to other controllers is its setpoint; an
    external encoder has no setpoint and uses its extrapolated actual value instead (§3.3.3, §8.1.3:
    "a positioning axis, external encoder or synchronous axis" can be the leading axis on CPU 1).
    """

    provides_setpoints = True
    provides_delayed_values = True
    #: any axis has actual values; a virtual one's equal its setpoints (§3.3.2, decision 29)
    provides_actual_values = True

    def _lv_init(self: "PositioningAxis") -> None:
        self._extrapolator: Extrapolator | None = None
        self._delay: DelayLine | None = None
        self._lv_slots: dict[str, int] = {}

    def actual_values(self: "PositioningAxis") -> tuple[float, float]:
        b, i = self.ctl.bank, self.index
        return float(b.act_p[i]), float(b.act_v[i])

    def leading_value_invalid(self: "PositioningAxis", mode: str) -> str | None:
        """An axis always provides a leading value: setpoint coupling waits for position control (§3.3.5),
        and the actual values stay valid."""
        return None

    def actual_values_valid(self: "PositioningAxis") -> bool:
        """Are the actual values valid (no encoder fault)?  An axis's are as long as it has them."""
        return True

    def velocity_lag(self: "PositioningAxis", dt: float) -> float:
        """Age of the actual velocity relative to the actual position: half a cycle for a velocity that
        is the difference of two encoder values, none for the exact velocity of a simulated drive."""
        return 0.5 * dt if self.servo else 0.0

    def provided_value(self: "PositioningAxis") -> tuple[float, float, float]:
        """This servo cycle's value for delayed followers and other controllers: the setpoint."""
        b, i = self.ctl.bank, self.index
        return float(b.sp_p[i]), float(b.sp_v[i]), float(b.sp_a[i])

    def provided_value_at(self: "PositioningAxis", t: float) -> tuple[float, float, float]:
        return setpoint_at(self, t)

    def provided_value_valid(self: "PositioningAxis") -> tuple[bool, bool]:
        """(valid, tracking) of the provided value (telegram flags, §8.1.4)."""
        return (self.state in ("enabled", "disabling") and self._blocking_alarm() is None,
                bool(self.servo and not self.ctl.bank.closed_loop[self.index]))

    def lv_position_controlled(self: "PositioningAxis") -> bool:
        """Setpoint coupling needs a position-controlled leading axis (§3.3.5)."""
        return self.state in ("enabled", "disabling") and self.position_controlled

    def lv_modulo(self: "PositioningAxis") -> tuple[float, float] | None:
        m = self.config.modulo
        return (m.start, m.length) if m.enabled else None

    def lv_value(self: "PositioningAxis", mode: str, t: float) -> tuple[float, float, float]:
        """The leading value this TO provides with coupling type ``mode`` at time ``t``."""
        if mode == "setpoint":
            return self.provided_value_at(t)
        if mode == "actual":
            ex = self._ensure_extrapolator()
            p, v, a = ex.position, ex.velocity, ex.acceleration
            dt = t - self.ctl._bank_time
            if dt > 0.0:                    # between servo cycles: carried forward
                p, v = p + dt * (v + 0.5 * dt * a), v + dt * a
            return p, v, a
        return self._ensure_delay().at(t - self.local_delay_time())

    def lv_slot(self: "PositioningAxis", mode: str) -> int:
        """Slot of this source's actual or delayed leading value in the sync stage (created on first use)."""
        slot = self._lv_slots.get(mode)
        if slot is None:
            if mode == "actual":
                ex = self._ensure_extrapolator()
                slot = self.ctl.sync.register_ext(lambda t, ex=ex: (ex.position, ex.velocity, ex.acceleration))
            else:
                line = self._ensure_delay()
                slot = self.ctl.sync.register_ext(lambda t, line=line: line.at(t - self.local_delay_time()))
            self._lv_slots[mode] = slot
        return slot

    def _ensure_extrapolator(self: "PositioningAxis") -> Extrapolator:
        if self._extrapolator is None:
            ex = Extrapolator(self)
            ex.step(self.ctl.time, self.ctl.servo_cycle)
            self._extrapolator = ex
            dt = self.ctl.servo_cycle
            # the filters run before the couplings of each servo cycle
            self.ctl.sync.register_ext(lambda t, ex=ex: ex.step(t, dt))
        return self._extrapolator

    def _ensure_delay(self: "PositioningAxis") -> DelayLine:
        if self._delay is None:
            line = DelayLine(self)
            self._delay = line
            ctl = self.ctl
            provided = self.provided_value

            def record(t: float) -> None:
                line.record(t, *provided(), self.local_delay_time() + 4 * ctl.servo_cycle)

            record(ctl._bank_time)
            ctl.sync.register_post(record)
        return self._delay

    def local_delay_time(self: "PositioningAxis") -> float:
        return self.config.leading_value_output.local_delay_time

    def provide_leading_value(self: "PositioningAxis", sink) -> None:
        """Send this TO's leading value to another controller every servo cycle (cross-PLC, §8):
        needs the leading value output configured (``LeadingValueOutput.enabled``; S7-1500:
        ``CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput`` = TRUE).

        Each telegram carries the delay of the local delayed followers, so that a leading axis proxy
        provides the value these followers use at the same time (§8.1.3) without being told the delay.
        """
        if not self.config.leading_value_output.enabled:
            raise ValueError(f"{self.name}: set CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput "
                             f"to provide a cross-PLC leading value")
        from .leading_value import LeadingValueSample
        ctl = self.ctl
        counter = [0]
        provided = self.provided_value
        self._ensure_delay()                # StatusProvidedLeadingValue.DelayedLeadingValue (§8.1.4)

        def send(t: float) -> None:
            m = self.config.modulo
            counter[0] += 1
            valid, tracking = self.provided_value_valid()
            sink.send(LeadingValueSample(
                t, *provided(), valid=valid, tracking=tracking,
                modulo_length=m.length if m.enabled else 0.0,
                modulo_start=m.start, sequence=counter[0], delay=self.local_delay_time()))
        ctl.sync.register_post(send)

    # --- tags -------------------------------------------------------------------------------------------
    def leading_axis_dependent_time(self: "PositioningAxis") -> float:
        """T_i + T_Ipo + position filter T1 + T2 (§3.3.6); T_i is one servo cycle for a real encoder."""
        x = self.config.extrapolation
        ti = 0.0 if self.sim else self.ctl.servo_cycle
        return ti + self.ctl.servo_cycle + x.position_filter_t1 + x.position_filter_t2

    def extrapolation_time(self: "PositioningAxis") -> float:
        """Effective extrapolation time: leading-axis part (if included) + following-axis part + delay."""
        x = self.config.extrapolation
        t = x.following_axis_time + self.local_delay_time()
        if x.include_leading_axis_time:
            t += self.leading_axis_dependent_time()
        return t

    def extrapolation_status(self: "PositioningAxis") -> tuple[float, float, float, float]:
        ex = self._extrapolator
        if ex is None:
            return 0.0, 0.0, 0.0, 0.0
        return ex.filtered_position, ex.filtered_velocity, ex.position, ex.velocity

    def delayed_leading_value(self: "PositioningAxis") -> tuple[float, float, float]:
        if self._delay is None:
            return 0.0, 0.0, 0.0
        return self._delay.at(self.ctl._bank_time - self.local_delay_time())
