"""The PROFIdrive connection of one simulated servo axis: control and status words, speed setpoint words,
encoder counts (S7-1200 V6 §2.2.3, §2.2.5; PROFIdrive standard telegrams 1, 2, 3, 4).

The technology object writes STW1 (and G1_STW for the encoder) only when something changes; the drive's
state machine (``profidrive.DriveStateMachine``) then steps cycle by cycle until it is steady again, so
enabling takes the drive through S1 -> S2 -> S3 -> S4 and "drive ready" is ZSW1.OperationEnabled.  The
speed setpoint is quantised to the telegram's word (16#4000 = 100 % for 16 bits, 16#40000000 for
32 bits) by the vectorised servo group; encoder positions are integer counts with the configured fine
resolution, so G1_XIST1 is the counter modulo 2^32.  :meth:`telegrams` assembles the exact telegram
contents of the moment on request.
"""
from __future__ import annotations

import math
from typing import Any

from .profidrive import (G1_STW, G1_ZSW, STW1, STW2, DriveState, DriveStateMachine, EncoderCommand,
                         telegram_types)
from .spec import DriveSpec

_OFF = STW1(NoCoastStop=True, NoQuickStop=True, EnableOperation=True, EnableRampGenerator=True,
            UnfreezeRampGenerator=True, EnableSetpoint=True, ControlByPlc=True)   # 16#047E: OFF1
_ON = _OFF.with_bits(On=True)                                                      # 16#047F
_U32 = 1 << 32


def word_scale(telegram: int, analog: bool) -> tuple[float, int]:
    """(counts per 100 % of the reference speed, saturation) of the speed setpoint word."""
    if analog:
        return 27648.0, 32511          # S7 analog output: 27648 = nominal range, 32511 = overrange limit
    if telegram == 1:
        return float(0x4000), 0x7FFF
    return float(0x40000000), 0x7FFFFFFF


class ProfidriveLink:
    """Per-axis state of the telegram exchange."""

    def __init__(self, spec: DriveSpec, servo_cycle: float):
        self.telegram = spec.telegram
        self.reference_rpm = spec.reference_speed
        off = max(spec.off_ramp_time, 0.0)
        self.sm = DriveStateMachine(self.reference_rpm, off1_ramp_time=off, off3_ramp_time=off)
        self.fault_code = spec.fault_code
        self.stw1 = _OFF
        self.g1_stw = G1_STW()
        self.cycles = 0
        self.enable = False
        self._ack = False
        enc = spec.encoder
        self.steps = enc.steps_per_revolution
        self.fine1 = enc.fine_bits
        self.fine2 = enc.fine_bits_absolute
        self.revolutions = enc.determinable_revolutions if enc.absolute else 0
        self.encoder_error = 0

    # --- written by the technology object --------------------------------------------------------------
    def command(self, enable: bool) -> None:
        self.enable = enable
        self.stw1 = _ON if enable else _OFF

    def acknowledge(self) -> None:
        """Rising edge of STW1 bit 7 (fault acknowledge) for one cycle."""
        self._ack = True

    def set_fault(self, on: bool) -> None:
        if on:
            self.sm.inject_fault(self.fault_code, cause_active=True)
        else:
            self.sm.clear_fault_cause()
            self.acknowledge()

    # --- cyclic ---------------------------------------------------------------------------------------
    def step(self, dt: float) -> None:
        # PROFIdrive switch-on sequence: from "switching on inhibited" (S1) the drive needs ON = 0 first
        self.stw1 = _ON if self.enable and self.sm.state is not DriveState.S1 else _OFF
        word = self.stw1.with_bits(AcknowledgeFault=True) if self._ack else self.stw1
        self._ack = False
        self.sm.write(word)
        self.sm.step(dt)

    @property
    def steady(self) -> bool:
        """Nothing changes without a new control word: the drive can skip stepping."""
        st = self.sm.state
        return not self._ack and not self.sm.fault_present and ((self.enable and st is DriveState.S4)
                                  or (not self.enable and st is DriveState.S2 and not self.sm.fault_present))

    @property
    def operation_enabled(self) -> bool:
        return self.sm.state is DriveState.S4

    # --- the telegram as it is on the wire ---------------------------------------------------------------
    def telegrams(self, *, setpoint_word: int, actual_rpm: float, count: int, zero_mark: tuple[bool, bool, int],
                  absolute_count: int | None) -> tuple[Any, Any]:
        out_type, in_type = telegram_types(self.telegram)
        life = (self.cycles % 15) + 1
        scale, limit = word_scale(self.telegram, analog=False)
        nist = max(-limit - 1, min(limit, round(actual_rpm / self.reference_rpm * scale)))
        searching, latched, latched_count = zero_mark
        g1_stw = G1_STW.build(functions=1, command=EncoderCommand.ACTIVATE) if searching else self.g1_stw
        g1_zsw = G1_ZSW(Function1Active=searching or latched, Value1Available=latched,
                        EncoderError=bool(self.encoder_error))
        xist2 = self.encoder_error or (latched_count % _U32 if latched else
                                       (absolute_count % _U32 if absolute_count is not None else 0))
        out: dict[str, Any] = {"STW1": int(self.stw1)}
        inp: dict[str, Any] = {"ZSW1": int(self.sm.zsw1)}
        if self.telegram == 1:
            out["NSOLL_A"] = setpoint_word
            inp["NIST_A"] = nist
        else:
            out.update(NSOLL_B=setpoint_word, STW2=int(STW2.with_sign_of_life(life)))
            inp.update(NIST_B=nist, ZSW2=int(self.sm.zsw2))
        if self.telegram in (3, 4):
            out["G1_STW"] = int(g1_stw)
            inp.update(G1_ZSW=int(g1_zsw), G1_XIST1=count % _U32, G1_XIST2=xist2)
        if self.telegram == 4:
            out["G2_STW"] = 0
        return out_type(**out), in_type(**inp)


def encoder_count(x: float, q: float) -> int:
    """Encoder counter value for load position ``x`` with increment ``q``."""
    return math.floor(x / q)
