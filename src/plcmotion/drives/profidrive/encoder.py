"""A simulated PROFIdrive encoder channel (Gx_XIST1/Gx_XIST2, reference mark search, absolute value,
error, parking)."""
from __future__ import annotations

import enum
import math
import operator

from .words import G1_STW, G1_ZSW, EncoderCommand


_U32_MOD = 1 << 32

#: Gx_XIST2 error codes used by :meth:`IncrementalEncoder.inject_error`.
ENCODER_ERROR_SENSOR_GROUP = 0x0001
ENCODER_ERROR_ZERO_MARK = 0x0002


def xist1_difference(prev: int, new: int) -> int:
    """Signed count difference ``new - prev`` of a free-running 32-bit counter (shortest way round)."""
    return (operator.index(new) - operator.index(prev) + (1 << 31)) % _U32_MOD - (1 << 31)


class _RefSearch(enum.Enum):
    IDLE = 0
    SEARCHING = 1
    LATCHED = 2


class IncrementalEncoder:
    """A rotary PROFIdrive encoder channel (the Gx_ part of telegrams 3, 4, 81, 83).

    Counts: Gx_XIST1 = floor(position * steps * 2**fine_resolution_xist1) modulo 2**32, a free-running
    counter.  With ``determinable_revolutions >= 1`` the encoder is absolute and Gx_XIST2 can carry
    floor(position * steps * 2**fine_resolution_xist2) modulo (determinable_revolutions * steps *
    2**fine_resolution_xist2) -- single-turn when ``determinable_revolutions == 1``.  0 means incremental
    (the TO's ``DeterminableRevolutions`` convention).  Positions are shaft revolutions (float).

    Per cycle call :meth:`update` with the shaft position and the received Gx_STW; then read
    :attr:`zsw`, :attr:`xist1`, :attr:`xist2`.  Modelled:

    * reference mark search (function 1, mode 0): activation -> ``Function1Active``; the first zero mark
      crossed after that (one per revolution at ``zero_mark_angle``) latches the XIST1 value of the exact
      crossing point, computed from the positions at the start and end of the cycle ->
      ``Value1Available``; the "read value" command puts the latched value into Gx_XIST2; "abort", or
      withdrawing every function request with command 0, returns to idle.  A held "activate" does not
      re-arm a latched search; the controller must withdraw the request first.  ``Function1Active`` stays
      set while a value is latched.  Functions 2..4 and flying measurement are not modelled (requests
      for them are not acknowledged).
    * cyclic absolute value (bit 13), absolute encoders only;
    * error injection: ``EncoderError`` and the error code in Gx_XIST2 until acknowledged by a rising
      edge of ``AcknowledgeEncoderError`` after the cause has gone; ``EncoderFaultAcknowledgeActive``
      mirrors the acknowledge bit while it is held;
    * parking: only ``ParkingEncoderActive`` is reported, XIST1/XIST2 stay frozen, a running reference
      mark search is dropped;
    * set/shift home position (bits 11/12) by ``home_preset`` revolutions, applied to both XIST1 and
      XIST2 (zero marks stay where they are on the shaft);
    * the probe inputs ``probe1``/``probe2`` (set by the caller) are mirrored in bits 8/9.

    Priority of Gx_XIST2: error code > latched value being read > cyclic absolute value > 0.
    """

    def __init__(self, steps_per_revolution: int = 2048, fine_resolution_xist1: int = 11,
                 fine_resolution_xist2: int = 9, determinable_revolutions: int = 0,
                 zero_mark_angle: float = 0.0, home_preset: float = 0.0) -> None:
        if not 1 <= steps_per_revolution <= 8388608:
            raise ValueError("steps per revolution must be 1..8388608")
        if not 0 <= fine_resolution_xist1 <= 31 or not 0 <= fine_resolution_xist2 <= 31:
            raise ValueError("fine resolution must be 0..31 bits")
        if not 0 <= determinable_revolutions <= 8388608:
            raise ValueError("determinable revolutions must be 0..8388608")
        self.steps_per_revolution = steps_per_revolution
        self.fine_resolution_xist1 = fine_resolution_xist1
        self.fine_resolution_xist2 = fine_resolution_xist2
        self.determinable_revolutions = determinable_revolutions
        self.xist1_per_revolution = steps_per_revolution << fine_resolution_xist1
        self.xist2_per_revolution = steps_per_revolution << fine_resolution_xist2
        self.absolute_range = determinable_revolutions * self.xist2_per_revolution
        if self.absolute_range > _U32_MOD:
            raise ValueError("absolute value does not fit into 32 bits")
        self.zero_mark_angle = zero_mark_angle % 1.0
        self.home_preset = home_preset
        self.offset = 0.0           # revolutions added by set/shift home position
        self.probe1 = False
        self.probe2 = False
        self._prev_pos: float | None = None
        self._prev_stw = G1_STW()
        self._search = _RefSearch.IDLE
        self._latched: int | None = None
        self._reading = False
        self._home_done = False
        self._error = 0
        self._error_cause = False
        self._parked = False
        self._abs_cyclic = False
        self.xist1 = 0
        self.xist2 = 0
        self.zsw = G1_ZSW()

    # -- conversions -------------------------------------------------------------------------------------

    @property
    def absolute(self) -> bool:
        return self.determinable_revolutions >= 1

    def count_at(self, position: float) -> int:
        """Gx_XIST1 for a shaft position [rev] (home offset included)."""
        return math.floor((position + self.offset) * self.xist1_per_revolution) % _U32_MOD

    def absolute_value_at(self, position: float) -> int:
        """Gx_XIST2 absolute value for a shaft position [rev]; ValueError for an incremental encoder."""
        if not self.absolute:
            raise ValueError("an incremental encoder has no absolute value")
        return math.floor((position + self.offset) * self.xist2_per_revolution) % self.absolute_range

    def counts_to_revolutions_delta(self, prev: int, new: int) -> float:
        """Shaft travel [rev] between two Gx_XIST1 readings, across the 32-bit wrap-around."""
        return xist1_difference(prev, new) / self.xist1_per_revolution

    def zero_mark_crossing(self, start: float, end: float) -> float | None:
        """First zero mark passed when moving from ``start`` to ``end`` [rev], or None.

        The interval is half-open at ``start`` so a mark lying exactly there belongs to the previous cycle.
        """
        a = self.zero_mark_angle
        if end > start:
            z = math.floor(start - a) + 1 + a
            return z if z <= end else None
        if end < start:
            z = math.ceil(start - a) - 1 + a
            return z if z >= end else None
        return None

    # -- fault injection -------------------------------------------------------------------------------

    def inject_error(self, code: int = ENCODER_ERROR_SENSOR_GROUP, *, cause_active: bool = False) -> None:
        """Report an encoder error (code shown in Gx_XIST2).  With ``cause_active`` the error cannot be
        acknowledged until :meth:`clear_error_cause` is called."""
        if not 1 <= code <= 0xFFFFFFFF:
            raise ValueError("error code must be a non-zero 32-bit value")
        self._error = code
        self._error_cause = cause_active

    def clear_error_cause(self) -> None:
        """The condition behind the error has gone; the next acknowledgement clears it."""
        self._error_cause = False

    @property
    def error_code(self) -> int:
        """Pending error code, 0 if none."""
        return self._error

    @property
    def parked(self) -> bool:
        """The encoder is parked (values frozen)."""
        return self._parked

    @property
    def latched_value(self) -> int | None:
        """XIST1 value latched at the reference mark, if any."""
        return self._latched

    # -- cycle -------------------------------------------------------------------------------------------

    def update(self, position: float, g1_stw: G1_STW | int = 0) -> None:
        """One cycle: apply ``g1_stw`` (in force while the shaft moved to ``position``), then produce the
        status word and actual values."""
        stw = g1_stw if isinstance(g1_stw, G1_STW) else G1_STW(g1_stw)
        prev_stw, self._prev_stw = self._prev_stw, stw
        start, self._prev_pos = self._prev_pos, position

        if stw.AcknowledgeEncoderError and not prev_stw.AcknowledgeEncoderError and not self._error_cause:
            self._error = 0

        self._parked = stw.RequestParkingEncoder
        if self._parked:
            self._search, self._latched, self._reading = _RefSearch.IDLE, None, False
            self._home_done = False
            self.zsw = G1_ZSW(ParkingEncoderActive=True)
            return                  # XIST1/XIST2 keep their last values

        if stw.RequestSetShiftHomePosition and not prev_stw.RequestSetShiftHomePosition:
            if stw.HomePositionMode:
                self.offset += self.home_preset
            else:
                self.offset = self.home_preset - position
            self._home_done = True
        elif not stw.RequestSetShiftHomePosition:
            self._home_done = False

        self._reference_mark(stw, start, position)
        self._abs_cyclic = stw.RequestAbsoluteValueCyclically and self.absolute

        self.xist1 = self.count_at(position)
        if self._error:
            self.xist2 = self._error & 0xFFFFFFFF
        elif self._reading and self._latched is not None:
            self.xist2 = self._latched
        elif self._abs_cyclic:
            self.xist2 = self.absolute_value_at(position)
        else:
            self.xist2 = 0
        self.zsw = G1_ZSW(
            Function1Active=self._search is not _RefSearch.IDLE,
            Value1Available=self._search is _RefSearch.LATCHED,
            Probe1Deflected=self.probe1,
            Probe2Deflected=self.probe2,
            EncoderFaultAcknowledgeActive=stw.AcknowledgeEncoderError,
            HomePositionSetShiftExecuted=self._home_done,
            TransmitAbsoluteValueCyclically=self._abs_cyclic and not self._error,
            EncoderError=bool(self._error),
        )

    def _reference_mark(self, stw: G1_STW, start: float | None, end: float) -> None:
        cmd = stw.command
        if cmd == EncoderCommand.ABORT or (stw.requested_functions == 0 and cmd == EncoderCommand.NONE):
            self._search, self._latched, self._reading = _RefSearch.IDLE, None, False
            return
        if not stw.RequestFunction1:
            return
        if (cmd == EncoderCommand.ACTIVATE and not stw.FlyingMeasurement
                and self._search is _RefSearch.IDLE):
            self._search = _RefSearch.SEARCHING
        self._reading = cmd == EncoderCommand.READ_VALUE and self._search is _RefSearch.LATCHED
        if self._search is _RefSearch.SEARCHING and start is not None:
            z = self.zero_mark_crossing(start, end)
            if z is not None:
                self._latched = self.count_at(z)
                self._search = _RefSearch.LATCHED
