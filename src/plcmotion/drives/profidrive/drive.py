"""The state machine of a simulated speed-controlled PROFIdrive drive (S1..S5 of the speed-control
application class, OFF1/OFF2/OFF3, faults, sign of life) with its ramp-function generator."""
from __future__ import annotations

import enum
import math
from typing import Literal

from .sign_of_life import SignOfLifeMonitor, next_sign_of_life
from .words import STW1, STW2, ZSW1, ZSW2


#: Fault number used for a sign-of-life failure (the SINAMICS number of this fault is F01912).
FAULT_SIGN_OF_LIFE = 1912


class DriveState(enum.IntEnum):
    """Main states of the PROFIdrive drive state machine."""

    S1 = 1   #: switching on inhibited (also while a fault is pending)
    S2 = 2   #: ready for switching on
    S3 = 3   #: switched on, pulses still off
    S4 = 4   #: operation: pulses on, setpoints are followed
    S5 = 5   #: switching off: braking on the OFF1 or OFF3 ramp


def _approach(value: float, target: float, rate: float, dt: float) -> float:
    """Move ``value`` towards ``target`` by at most ``rate * dt`` (an infinite rate jumps, even for dt = 0)."""
    max_step = math.inf if math.isinf(rate) else rate * dt
    if abs(target - value) <= max_step:
        return target
    return value + math.copysign(max_step, target - value)


class DriveStateMachine:
    """The switching-on/off logic of a speed-controlled PROFIdrive drive plus its ramp-function generator.

    Per cycle: :meth:`write` the received STW1 (and STW2), :meth:`step` the time, ask
    :meth:`effective_setpoint` what the speed controller gets, and send :attr:`zsw1`/:attr:`zsw2` back.

    Transitions, highest priority first: pending fault -> S1 (pulses off); OFF2 -> S1 (coast);
    S1 -> S2 needs ON = 0 with neither OFF2 nor OFF3; OFF3 in S2/S3 -> S1, in S4 or during OFF1 ->
    S5 with the quick-stop ramp, which always runs to standstill and ends in S1; S2 -> S3 on ON;
    S3 -> S4 on enable operation (S3 -> S2 on ON = 0); in S4 ON = 0 starts the OFF1 ramp (S5, ends in
    S2) and removing enable operation drops the pulses (S3).

    Choices where the profile leaves room: standstill is "ramp-generator output is zero"; an OFF1 ramp
    is finished even if ON returns (the drive then passes S2 -> S3 -> S4 again); removing enable
    operation during a ramp drops the pulses (S2 after OFF1, S1 after OFF3); during S5 the ZSW1 bits
    0..2 stay set because the pulses are still on.  A fault lands in S1 with ``FaultPresent``; a rising
    edge of ``AcknowledgeFault`` clears every fault whose cause is gone, after which ON must be 0 again
    to reach S2.

    Ramp times are the time to go between 0 and ``reference_rpm``: ``off1_ramp_time`` and
    ``off3_ramp_time`` for OFF1/OFF3, ``ramp_time`` for the generator in S4 (0 = generator bypassed,
    the usual setting under a position controller).  With ``ramp_time > 0`` the generator moves
    towards the setpoint given in the previous call of :meth:`effective_setpoint`.

    Process data are taken over only when ``STW1.ControlByPlc`` is set and the drive has not been
    switched to local control (:meth:`request_local_control`); otherwise the last accepted STW1 and
    setpoint stay in force.  The controller's life sign in STW2 is monitored by a
    :class:`SignOfLifeMonitor` (starting with its first non-zero value; a cycle without :meth:`write`
    repeats the old value and so counts as a failure); exceeding the tolerance raises
    :data:`FAULT_SIGN_OF_LIFE`.  The drive's own life sign in ZSW2 advances on every :meth:`step`.
    """

    def __init__(self, reference_rpm: float = 3000.0, *, off1_ramp_time: float = 1.0,
                 off3_ramp_time: float = 0.1, ramp_time: float = 0.0, sign_of_life_tolerance: int = 1,
                 speed_tolerance_rpm: float = 30.0, comparison_rpm: float | None = None) -> None:
        if not reference_rpm > 0:
            raise ValueError("reference speed must be positive")
        if min(off1_ramp_time, off3_ramp_time, ramp_time) < 0:
            raise ValueError("ramp times must be >= 0")
        self.reference_rpm = reference_rpm
        self.off1_ramp_time = off1_ramp_time
        self.off3_ramp_time = off3_ramp_time
        self.ramp_time = ramp_time
        self.speed_tolerance_rpm = speed_tolerance_rpm
        self.comparison_rpm = reference_rpm if comparison_rpm is None else comparison_rpm
        self.sign_of_life = SignOfLifeMonitor(sign_of_life_tolerance)
        self.warning = False
        self._state = DriveState.S1
        self._stop: Literal["OFF1", "OFF3"] | None = None
        self._stw1 = STW1()             # last accepted control word
        self._pzd_valid = False         # the latest write() was accepted
        self._prev_ack = False
        self._stw2: STW2 | None = None
        self._faults: dict[int, bool] = {}   # code -> cause still active
        self._local = False
        self._rfg = 0.0                 # ramp-function generator output [1/min]
        self._input = 0.0               # setpoint last handed to effective_setpoint
        self._slave_life = 0
        self._actual: float | None = None

    # -- inputs --------------------------------------------------------------------------------------------

    def write(self, stw1: STW1 | int, stw2: STW2 | int | None = None) -> None:
        """Receive this cycle's control words (STW2 only with telegrams 2, 3, 4)."""
        word = stw1 if isinstance(stw1, STW1) else STW1(stw1)
        if stw2 is not None:
            self._stw2 = stw2 if isinstance(stw2, STW2) else STW2(stw2)
        self._pzd_valid = word.ControlByPlc and not self._local
        if self._pzd_valid:
            self._stw1 = word

    def inject_fault(self, code: int, *, cause_active: bool = False) -> None:
        """Raise a fault: pulses off at once.  With ``cause_active`` it survives acknowledgement until
        :meth:`clear_fault_cause` is called."""
        self._faults[code] = self._faults.get(code, False) or cause_active
        self._pulses_off(DriveState.S1)

    def clear_fault_cause(self, code: int | None = None) -> None:
        """The cause of fault ``code`` (default: all faults) has gone."""
        for c in self._faults:
            if code is None or c == code:
                self._faults[c] = False

    def request_local_control(self) -> None:
        """Another master (e.g. a commissioning tool) takes control: ``ControlRequested`` drops and the
        controller's process data are ignored."""
        self._local = True

    def release_local_control(self) -> None:
        self._local = False

    # -- outputs -------------------------------------------------------------------------------------------

    @property
    def state(self) -> DriveState:
        return self._state

    @property
    def switching_off(self) -> Literal["OFF1", "OFF3"] | None:
        """Which ramp is running in S5, else None."""
        return self._stop if self._state is DriveState.S5 else None

    @property
    def ready_for_setpoints(self) -> bool:
        """True in S4: the speed setpoint reaches the speed controller."""
        return self._state is DriveState.S4

    @property
    def fault_present(self) -> bool:
        return bool(self._faults)

    @property
    def faults(self) -> tuple[int, ...]:
        """Codes of the pending faults, oldest first."""
        return tuple(self._faults)

    @property
    def control_requested(self) -> bool:
        return not self._local

    @property
    def speed_output(self) -> float:
        """Current ramp-function generator output [1/min] (0 whenever the pulses are off)."""
        return self._rfg

    def effective_setpoint(self, nsoll_rpm: float) -> float:
        """Speed setpoint [1/min] the speed controller gets for the controller's setpoint ``nsoll_rpm``."""
        if self._pzd_valid and not self._local:
            self._input = nsoll_rpm       # otherwise the last accepted setpoint stays in force
        s = self._stw1
        if (self._state is DriveState.S4 and s.EnableRampGenerator and s.UnfreezeRampGenerator
                and s.EnableSetpoint and self.ramp_time == 0.0):
            self._rfg = self._input
        elif self._state is DriveState.S4 and not s.EnableRampGenerator:
            self._rfg = 0.0
        return self._rfg if self._state in (DriveState.S4, DriveState.S5) else 0.0

    @property
    def zsw1(self) -> ZSW1:
        st, s = self._state, self._stw1
        actual = self._rfg if self._actual is None else self._actual
        pulses = st in (DriveState.S4, DriveState.S5)
        return ZSW1(
            ReadyToSwitchOn=st >= DriveState.S2,
            ReadyToOperate=st >= DriveState.S3,
            OperationEnabled=pulses,
            FaultPresent=self.fault_present,
            NoCoastStopActive=s.NoCoastStop,
            NoQuickStopActive=s.NoQuickStop and self.switching_off != "OFF3",
            SwitchingOnInhibited=st is DriveState.S1,
            WarningPresent=self.warning or self.sign_of_life.failures > 0,
            SpeedErrorWithinTolerance=abs(self._rfg - actual) <= self.speed_tolerance_rpm,
            ControlRequested=not self._local,
            ComparisonValueReached=abs(actual) >= self.comparison_rpm,
        )

    @property
    def zsw2(self) -> ZSW2:
        return ZSW2(self._slave_life << 12, PulsesEnabled=self._state in (DriveState.S4, DriveState.S5))

    # -- time ----------------------------------------------------------------------------------------------

    def step(self, dt: float, actual_rpm: float | None = None) -> None:
        """Advance by ``dt`` seconds.  ``actual_rpm`` (measured speed) only feeds ZSW1 bits 8 and 10;
        without it the drive is taken to follow its ramp generator exactly."""
        if dt < 0:
            raise ValueError("dt must be >= 0")
        self._actual = actual_rpm
        self._slave_life = next_sign_of_life(self._slave_life)
        if (self._stw2 is not None and not self._faults
                and not self.sign_of_life.check(self._stw2.master_sign_of_life)):
            self.inject_fault(FAULT_SIGN_OF_LIFE)
            self.sign_of_life.reset()

        s = self._stw1
        ack = s.AcknowledgeFault
        if ack and not self._prev_ack:
            self._faults = {c: active for c, active in self._faults.items() if active}
        self._prev_ack = ack

        self._transition(s)
        self._ramp(s, dt)

    def _pulses_off(self, state: DriveState) -> None:
        self._state, self._stop, self._rfg = state, None, 0.0

    def _transition(self, s: STW1) -> None:
        st = self._state
        if self._faults or not s.NoCoastStop:
            self._pulses_off(DriveState.S1)
        elif st is DriveState.S1:
            if not s.On and s.NoQuickStop:
                self._state = DriveState.S2
        elif st is DriveState.S5:
            if not s.EnableOperation:
                self._pulses_off(DriveState.S1 if self._stop == "OFF3" else DriveState.S2)
            elif not s.NoQuickStop:
                self._stop = "OFF3"
        elif not s.NoQuickStop:
            if st is DriveState.S4:
                self._state, self._stop = DriveState.S5, "OFF3"
            else:
                self._pulses_off(DriveState.S1)
        elif st is DriveState.S2:
            if s.On:
                self._state = DriveState.S3
        elif st is DriveState.S3:
            if not s.On:
                self._state = DriveState.S2
            elif s.EnableOperation:
                self._state = DriveState.S4
        elif st is DriveState.S4:
            if not s.On:
                self._state, self._stop = DriveState.S5, "OFF1"
            elif not s.EnableOperation:
                self._pulses_off(DriveState.S3)

    def _rate(self, ramp_time: float) -> float:
        return math.inf if ramp_time == 0.0 else self.reference_rpm / ramp_time

    def _ramp(self, s: STW1, dt: float) -> None:
        if self._state is DriveState.S5:
            rate = self._rate(self.off3_ramp_time if self._stop == "OFF3" else self.off1_ramp_time)
            self._rfg = _approach(self._rfg, 0.0, rate, dt)
            if self._rfg == 0.0:
                self._pulses_off(DriveState.S1 if self._stop == "OFF3" else DriveState.S2)
        elif self._state is DriveState.S4:
            if not s.EnableRampGenerator:
                self._rfg = 0.0
            elif s.UnfreezeRampGenerator:
                target = self._input if s.EnableSetpoint else 0.0
                self._rfg = _approach(self._rfg, target, self._rate(self.ramp_time), dt)
        else:
            self._rfg = 0.0
