"""Leading value sources: setpoints, extrapolated actual values and delayed values (S7-1500T V5 §3.3).

* Setpoint coupling reads the leading axis's position setpoint of the same servo cycle.
* Actual value coupling reads the leading TO's actual position, filtered and extrapolated over the
  effective extrapolation time to make up for the delays of acquiring and processing it (§3.3.4):
  position PT2 filter, velocity PT2 filter and tolerance band, linear extrapolation, hysteresis.
* Delayed coupling reads the setpoint delayed by ``CrossPlcSynchronousOperation.LocalLeadingValueDelayTime``,
  so that local followers stay synchronous with followers on other controllers that get the value later
  (§8.1.3).

The manual does not print the extrapolation formula, the initial state of the tolerance band or the
hysteresis output after a reversal (catalog §11.2 item 5): extrapolation here is
``p_f + v_f * T``, the band starts at the first filtered velocity, and the hysteresis is a play operator
of width ``Hysteresis.Value`` (continuous, lagging by half the width; docs/decisions_s7_1500.md).
"""
from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from .axis1500 import PositioningAxis1500


def _pt1(y: float, x: float, dt: float, T: float) -> float:
    """First-order lag, discretized so that it lags a ramp by exactly T (the time the extrapolation
    adds back)."""
    if T <= 0.0:
        return x
    return y + dt / (T + dt) * (x - y)


class Extrapolator:
    """Actual value processing of one leading TO (§3.3.4 pipeline), one step per servo cycle."""

    def __init__(self, source: Any):
        self.source = source
        self.ready = False
        self.pf1 = self.pf2 = self.vf1 = self.vf2 = 0.0
        self.band = 0.0
        self.hyst = 0.0
        self.filtered_position = self.filtered_velocity = 0.0
        self.position = self.velocity = 0.0
        self._prev: float | None = None

    def step(self, t: float, dt: float) -> tuple[float, float, float]:
        src = self.source
        e = src.eff
        p, v = src.actual_values()
        if not self.ready:
            self.pf1 = self.pf2 = p
            self.vf1 = self.vf2 = self.band = v
            self.hyst = p
            self.ready = True
        self.pf1 = _pt1(self.pf1, p, dt, e["Extrapolation.PositionFilter.T1"])
        self.pf2 = _pt1(self.pf2, self.pf1, dt, e["Extrapolation.PositionFilter.T2"])
        self.vf1 = _pt1(self.vf1, v, dt, e["Extrapolation.VelocityFilter.T1"])
        self.vf2 = _pt1(self.vf2, self.vf1, dt, e["Extrapolation.VelocityFilter.T2"])
        half = e["Extrapolation.VelocityTolerance.Range"] / 2.0
        self.band = min(max(self.band, self.vf2 - half), self.vf2 + half)
        self.filtered_position, self.filtered_velocity = self.pf2, self.band
        x = self.pf2 + self.band * src.extrapolation_time()
        h = e["Extrapolation.Hysteresis.Value"] / 2.0
        self.hyst = min(max(self.hyst, x - h), x + h)
        prev = self._prev
        self.position = self.hyst
        if e["Extrapolation.Settings.ExtrapolatedVelocityMode"] == 1 and prev is not None:
            self.velocity = (self.hyst - prev) / dt
        else:
            self.velocity = self.band
        self._prev = self.hyst
        return self.position, self.velocity, 0.0


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
            return self.source.lv_value("setpoint", t)
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
    """What a leading axis offers its followers (mixed into the S7-1500 axes)."""

    provides_setpoints = True

    def _lv_init(self: "PositioningAxis1500") -> None:
        self._extrapolator: Extrapolator | None = None
        self._delay: DelayLine | None = None
        self._lv_slots: dict[str, int] = {}

    @property
    def provides_actual_values(self: "PositioningAxis1500") -> bool:
        return self.eff.get("VirtualAxis.Mode", 0) == 0

    def actual_values(self: "PositioningAxis1500") -> tuple[float, float]:
        b, i = self.ctl.bank, self.index
        return float(b.act_p[i]), float(b.act_v[i])

    def lv_position_controlled(self: "PositioningAxis1500") -> bool:
        """Setpoint coupling needs a position-controlled leading axis (§3.3.5)."""
        return self.state in ("enabled", "disabling") and (self.position_controlled or not self.servo)

    def lv_modulo(self: "PositioningAxis1500") -> tuple[float, float] | None:
        e = self.eff
        return (e["Modulo.StartValue"], e["Modulo.Length"]) if e["Modulo.Enable"] else None

    def lv_value(self: "PositioningAxis1500", mode: str, t: float) -> tuple[float, float, float]:
        """The leading value this TO provides with coupling type ``mode`` at time ``t``."""
        if mode == "setpoint":
            return setpoint_at(self, t)
        if mode == "actual":
            ex = self._ensure_extrapolator()
            return ex.position, ex.velocity, 0.0
        return self._ensure_delay().at(t - self.local_delay_time())

    def lv_slot(self: "PositioningAxis1500", mode: str) -> int:
        """Slot of this source's actual or delayed leading value in the sync stage (created on first use)."""
        slot = self._lv_slots.get(mode)
        if slot is None:
            if mode == "actual":
                ex = self._ensure_extrapolator()
                slot = self.ctl.sync.register_ext(lambda t, ex=ex: (ex.position, ex.velocity, 0.0))
            else:
                line = self._ensure_delay()
                slot = self.ctl.sync.register_ext(lambda t, line=line: line.at(t - self.local_delay_time()))
            self._lv_slots[mode] = slot
        return slot

    def _ensure_extrapolator(self: "PositioningAxis1500") -> Extrapolator:
        if self._extrapolator is None:
            ex = Extrapolator(self)
            ex.step(self.now, self.ctl.servo_cycle)
            self._extrapolator = ex
            dt = self.ctl.servo_cycle
            # the filters run before the couplings of each servo cycle
            self.ctl.sync.register_ext(lambda t, ex=ex: ex.step(t, dt))
        return self._extrapolator

    def _ensure_delay(self: "PositioningAxis1500") -> DelayLine:
        if self._delay is None:
            line = DelayLine(self)
            self._delay = line
            ctl = self.ctl

            def record(t: float) -> None:
                # the bank arrays are re-created every cycle: look them up each time
                b, i = ctl.bank, self.index
                line.record(t, float(b.sp_p[i]), float(b.sp_v[i]), float(b.sp_a[i]),
                            self.local_delay_time() + 4 * ctl.servo_cycle)

            record(ctl._bank_time)
            ctl.sync.register_post(record)
        return self._delay

    def local_delay_time(self: "PositioningAxis1500") -> float:
        return self.eff.get("CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", 0.0)

    def provide_leading_value(self: "PositioningAxis1500", sink) -> None:
        """Send this axis's leading value to another controller every servo cycle (cross-PLC, §8):
        needs ``CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput`` = TRUE."""
        if not self.eff.get("CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput"):
            raise ValueError(f"{self.name}: set CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput "
                             f"to provide a cross-PLC leading value")
        from .leading_value import LeadingValueSample
        ctl = self.ctl
        counter = [0]

        def send(t: float) -> None:
            b, i = ctl.bank, self.index
            e = self.eff
            counter[0] += 1
            sink.send(LeadingValueSample(
                t, float(b.sp_p[i]), float(b.sp_v[i]), float(b.sp_a[i]),
                valid=self.state in ("enabled", "disabling") and self._blocking_alarm() is None,
                tracking=self.servo and not b.closed_loop[i],
                modulo_length=e["Modulo.Length"] if e["Modulo.Enable"] else 0.0,
                modulo_start=e["Modulo.StartValue"], sequence=counter[0]))
        ctl.sync.register_post(send)

    # --- tags -------------------------------------------------------------------------------------------
    def leading_axis_dependent_time(self: "PositioningAxis1500") -> float:
        """T_i + T_Ipo + position filter T1 + T2 (§3.3.6); T_i is one servo cycle for a real encoder."""
        e = self.eff
        ti = 0.0 if self.sim else self.ctl.servo_cycle
        return ti + self.ctl.servo_cycle + e["Extrapolation.PositionFilter.T1"] + e["Extrapolation.PositionFilter.T2"]

    def extrapolation_time(self: "PositioningAxis1500") -> float:
        """Effective extrapolation time: leading-axis part (if included) + following-axis part + delay."""
        e = self.eff
        t = e["Extrapolation.FollowingAxisDependentTime"] + self.local_delay_time()
        if e["Extrapolation.Settings.SystemDefinedExtrapolation"] == 1:
            t += self.leading_axis_dependent_time()
        return t

    def extrapolation_status(self: "PositioningAxis1500") -> tuple[float, float, float, float]:
        ex = self._extrapolator
        if ex is None:
            return 0.0, 0.0, 0.0, 0.0
        return ex.filtered_position, ex.filtered_velocity, ex.position, ex.velocity

    def delayed_leading_value(self: "PositioningAxis1500") -> tuple[float, float, float]:
        if self._delay is None:
            return 0.0, 0.0, 0.0
        return self._delay.at(self.ctl._bank_time - self.local_delay_time())
