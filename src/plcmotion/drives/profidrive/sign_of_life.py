"""The PROFIdrive life sign: its 4-bit sequence and the monitor that checks a partner's."""
from __future__ import annotations


def next_sign_of_life(value: int) -> int:
    """The life sign after ``value``: 1, 2, ..., 15, 1, ... (0 only ever means 'not started')."""
    return 1 if value >= 15 else value + 1


class SignOfLifeMonitor:
    """Checks a partner's 4-bit life sign once per cycle.

    Monitoring starts with the first non-zero value.  From then on every value must be the successor of
    the previous one (:func:`next_sign_of_life`); a repeated, skipped or zero value is a failure.  The
    monitor trips when more than ``tolerance`` failures occur in a row; a correct value resets the run.
    Choice made here: consecutive failures are counted (the SINAMICS tolerance parameter counts them this
    way); the comparison always continues from the value last received, so one skipped value costs one
    failure, not a permanent mismatch.
    """

    def __init__(self, tolerance: int = 1) -> None:
        if tolerance < 0:
            raise ValueError("tolerance must be >= 0")
        self.tolerance = tolerance
        self.reset()

    def reset(self) -> None:
        """Forget the history; monitoring restarts with the next non-zero value."""
        self._last: int | None = None
        self.failures = 0
        self.tripped = False

    @property
    def started(self) -> bool:
        return self._last is not None

    def check(self, value: int) -> bool:
        """Evaluate this cycle's value; returns False once the tolerance has been exceeded."""
        if not 0 <= value <= 15:
            raise ValueError("life sign must be 0..15")
        if self._last is None:
            if value != 0:
                self._last = value
            return not self.tripped
        if value != 0 and value == next_sign_of_life(self._last):
            self.failures = 0
        else:
            self.failures += 1
            if self.failures > self.tolerance:
                self.tripped = True
        if value != 0:
            self._last = value
        return not self.tripped
