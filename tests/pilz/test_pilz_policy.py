"""Command Mode I409 as the Pilz override policy on the kernel job queue (Pilz V6.5 Tab. 4 "Command Mode", §1.2.7
I83 "running motion block and buffered subsequent motion block")."""
from __future__ import annotations

from plcmotion.kernel.job_queue import BufferMode
from plcmotion.kernel.policy import ABORT
from plcmotion.pilz import Cause
from plcmotion.pilz.technology.override import COLUMNS, POLICY

from ._core import PROFILE, make_axis, start


def test_pilz_policy_table():
    """Pilz V6.5 §1 / Fig. 2: one command channel per axis: every command ends the running one; I409 0 cancels,
    1 starts at the end (Buffered), one command may wait."""
    assert all(POLICY.cell(new, running) is ABORT for new in COLUMNS for running in COLUMNS)
    assert POLICY.buffer_modes == {0: BufferMode.ABORTING, 1: BufferMode.BUFFERED}
    assert POLICY.queue_depth == 1


def test_pilz_policy_one_waiting_command():
    """Pilz V6.5 §1.2.7 (I83): one follow-up command waits (I83 = 2 while it does); a second one with I409 = 1
    is denied (I90 = 12) and the first follow-up still runs."""
    ctl, ax = make_axis({"I87": 0.0})
    start(ax, 1, PROFILE, I403=100.0)
    start(ax, 1, PROFILE, I403=150.0, I409=1)
    ctl.step()
    assert ax.status.I83 == 2                   # a block runs and the buffered follow-up waits
    start(ax, 1, PROFILE, I403=300.0, I409=1)
    ctl.step()
    assert ax.status.I91 and ax.status.I90 == Cause.BUFFER_FULL
    ctl.run(2.0)
    assert ax.status.I96 == 150.0
