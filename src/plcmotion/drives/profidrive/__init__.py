"""PROFIdrive cyclic data for simulated drives and encoders, bit-exact on the wire.

Four layers, each usable on its own (only the standard library and numpy-compatible integers are needed),
each in its own module; this package exports their public names:

* **Control and status words** (:mod:`.words`: :class:`STW1`, :class:`ZSW1`, :class:`STW2`, :class:`ZSW2`,
  :class:`STW2_ENC`, :class:`ZSW2_ENC`, :class:`G1_STW`, :class:`G1_ZSW`): immutable 16-bit values whose
  bits are named like the members of the ``PD_TELx`` data types of S7-1200 Motion Control V7 (e.g.
  ``ZSW1.SwitchingOnInhibited``, ``G1_ZSW.EncoderFaultAcknowledgeActive``, ``G1_STW.RequestParkingEncoder``;
  S7-1200 catalogue §10.3).  Bits the speed-control profile leaves to the manufacturer are called
  ``Reserved_BitNN`` so that every bit of the word can still be addressed by name.
* **Standard telegrams** 1, 2, 3, 4 (drive) and 81, 83 (encoder) (:mod:`.telegrams`): ``TelegramNOut``
  (controller -> device) and ``TelegramNIn`` (device -> controller) with ``pack()``/``unpack()`` in PROFINET
  byte order (big-endian; setpoints and speeds in two's complement, position values unsigned), and the
  speed scaling between 1/min and NSOLL/NIST (:func:`speed_to_nsoll`, :func:`nsoll_to_speed`).
* **Sign of life** (:mod:`.sign_of_life`): the 4-bit life sign sequence and its monitor.
* **Device models**: :class:`IncrementalEncoder` (:mod:`.encoder`: Gx_XIST1/Gx_XIST2, reference mark
  search, absolute value, error, parking) and :class:`DriveStateMachine` (:mod:`.drive`: the S1..S5 state
  machine of the speed-control application class, OFF1/OFF2/OFF3, faults, sign of life).

Where the public sources leave a detail open, the choice made here is stated in the docstring of the
class that makes it.
"""
from __future__ import annotations

from .drive import FAULT_SIGN_OF_LIFE, DriveState, DriveStateMachine
from .encoder import ENCODER_ERROR_SENSOR_GROUP, ENCODER_ERROR_ZERO_MARK, IncrementalEncoder, xist1_difference
from .sign_of_life import SignOfLifeMonitor, next_sign_of_life
from .telegrams import (TELEGRAMS, Telegram1In, Telegram1Out, Telegram2In, Telegram2Out, Telegram3In,
                        Telegram3Out, Telegram4In, Telegram4Out, Telegram81In, Telegram81Out, Telegram83In,
                        Telegram83Out, nsoll_to_speed, speed_to_nsoll, telegram_types)
from .words import (G1_STW, G1_ZSW, G2_STW, G2_ZSW, STW1, STW2, STW2_ENC, ZSW1, ZSW2, ZSW2_ENC, EncoderCommand,
                    Word16)

__all__ = [
    "ENCODER_ERROR_SENSOR_GROUP",
    "ENCODER_ERROR_ZERO_MARK",
    "FAULT_SIGN_OF_LIFE",
    "G1_STW",
    "G1_ZSW",
    "G2_STW",
    "G2_ZSW",
    "STW1",
    "STW2",
    "STW2_ENC",
    "TELEGRAMS",
    "ZSW1",
    "ZSW2",
    "ZSW2_ENC",
    "DriveState",
    "DriveStateMachine",
    "EncoderCommand",
    "IncrementalEncoder",
    "SignOfLifeMonitor",
    "Telegram1In",
    "Telegram1Out",
    "Telegram2In",
    "Telegram2Out",
    "Telegram3In",
    "Telegram3Out",
    "Telegram4In",
    "Telegram4Out",
    "Telegram81In",
    "Telegram81Out",
    "Telegram83In",
    "Telegram83Out",
    "Word16",
    "next_sign_of_life",
    "nsoll_to_speed",
    "speed_to_nsoll",
    "telegram_types",
    "xist1_difference",
]
