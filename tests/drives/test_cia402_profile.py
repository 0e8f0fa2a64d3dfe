"""The CiA 402 power state machine and its words, against the profile (CiA 402-2, drive device state
machine: states, numbered transitions, controlword commands, statusword patterns; CANopen CiA 402-2)."""
from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from plcmotion.drives.cia402.profile import (AXIS_MODES, Mode, PowerStateMachine, State, command_of,
                                             next_command, state_of)

S = State
# statusword patterns of the profile, written out: (mask, value) over bits 0..6
STATUSWORDS = [(0x0000, S.NOT_READY_TO_SWITCH_ON), (0x0040, S.SWITCH_ON_DISABLED), (0x0021, S.READY_TO_SWITCH_ON),
               (0x0023, S.SWITCHED_ON), (0x0027, S.OPERATION_ENABLED), (0x0007, S.QUICK_STOP_ACTIVE),
               (0x000F, S.FAULT_REACTION_ACTIVE), (0x0008, S.FAULT),
               # with bits outside the state pattern: voltage enabled, remote, target reached, bit 12
               (0x0231, S.READY_TO_SWITCH_ON), (0x1637, S.OPERATION_ENABLED), (0x0250, S.SWITCH_ON_DISABLED),
               (0x0218, S.FAULT)]


@pytest.mark.parametrize("word,state", STATUSWORDS, ids=[f"{w:#06x}" for w, _ in STATUSWORDS])
def test_drives_cia402_statusword_states(word, state):
    """CiA 402-2 statusword: the state is coded in bits 0-3, 5 and 6 (xxxx xxxx x0xx 0000 not ready,
    x1xx 0000 switch on disabled, x01x 0001 ready, x01x 0011 switched on, x01x 0111 operation enabled,
    x00x 0111 quick stop, x0xx 1111 fault reaction, x0xx 1000 fault)."""
    assert state_of(word) is state


# (state, controlword, next state, transition number) - CiA 402-2 device control commands
TRANSITIONS = [
    (S.SWITCH_ON_DISABLED, 0x0006, S.READY_TO_SWITCH_ON, 2),      # shutdown
    (S.READY_TO_SWITCH_ON, 0x0007, S.SWITCHED_ON, 3),             # switch on
    (S.READY_TO_SWITCH_ON, 0x000F, S.SWITCHED_ON, 3),             # switch on (bit 3 is "don't care")
    (S.SWITCHED_ON, 0x000F, S.OPERATION_ENABLED, 4),              # enable operation
    (S.OPERATION_ENABLED, 0x0007, S.SWITCHED_ON, 5),              # disable operation
    (S.SWITCHED_ON, 0x0006, S.READY_TO_SWITCH_ON, 6),             # shutdown
    (S.READY_TO_SWITCH_ON, 0x0000, S.SWITCH_ON_DISABLED, 7),      # disable voltage
    (S.READY_TO_SWITCH_ON, 0x0002, S.SWITCH_ON_DISABLED, 7),      # quick stop
    (S.OPERATION_ENABLED, 0x0006, S.READY_TO_SWITCH_ON, 8),       # shutdown
    (S.OPERATION_ENABLED, 0x0000, S.SWITCH_ON_DISABLED, 9),       # disable voltage
    (S.SWITCHED_ON, 0x0000, S.SWITCH_ON_DISABLED, 10),            # disable voltage
    (S.SWITCHED_ON, 0x0002, S.SWITCH_ON_DISABLED, 10),            # quick stop
    (S.OPERATION_ENABLED, 0x0002, S.QUICK_STOP_ACTIVE, 11),       # quick stop
    (S.QUICK_STOP_ACTIVE, 0x0000, S.SWITCH_ON_DISABLED, 12),      # disable voltage
    (S.QUICK_STOP_ACTIVE, 0x000F, S.OPERATION_ENABLED, 16),       # enable operation
]


@pytest.mark.parametrize("start,cw,end,number", TRANSITIONS,
                         ids=[f"{n}-{s.name}-{cw:#06x}" for s, cw, _, n in TRANSITIONS])
def test_drives_cia402_transitions(start, cw, end, number):
    """CiA 402-2 state machine: each device control command leads from its state to the next one with the
    transition number of the profile."""
    sm = PowerStateMachine()
    sm.state = start
    assert sm.command(cw) == number
    assert sm.state is end


@pytest.mark.parametrize("start,cw", [(S.SWITCH_ON_DISABLED, 0x000F), (S.SWITCH_ON_DISABLED, 0x0007),
                                      (S.READY_TO_SWITCH_ON, 0x0006), (S.SWITCHED_ON, 0x0007),
                                      (S.OPERATION_ENABLED, 0x000F)])
def test_drives_cia402_commands_without_transition(start, cw):
    """CiA 402-2: a command that has no transition from the current state leaves the state as it is (enable
    operation from SWITCH ON DISABLED does not skip READY TO SWITCH ON and SWITCHED ON)."""
    sm = PowerStateMachine()
    sm.state = start
    assert sm.command(cw) is None
    assert sm.state is start


def test_drives_cia402_fault_and_reset_edge():
    """CiA 402-2 transitions 13, 14, 15: a fault goes through FAULT REACTION ACTIVE to FAULT; only a rising
    edge of controlword bit 7 leaves FAULT (to SWITCH ON DISABLED), and not while the cause is present."""
    sm = PowerStateMachine()
    for cw in (0x06, 0x07, 0x0F):
        sm.command(cw)
    sm.fault()
    assert sm.state is S.FAULT_REACTION_ACTIVE
    assert sm.command(0x0F) is None and sm.state is S.FAULT_REACTION_ACTIVE
    sm.reaction_done()
    assert sm.state is S.FAULT
    assert sm.command(0x80, cause_present=True) is None and sm.state is S.FAULT   # cause still there
    assert sm.command(0x80) is None and sm.state is S.FAULT                       # bit 7 held: no edge
    sm.command(0x00)
    assert sm.command(0x80) == 15 and sm.state is S.SWITCH_ON_DISABLED


def test_drives_cia402_command_decoding():
    """CiA 402-2 device control commands: bit 1 = 0 is disable voltage whatever else is set, bit 2 = 0 quick
    stop, then shutdown (x110), switch on (0111), enable operation (1111)."""
    assert [command_of(cw).value for cw in (0x00, 0x0D, 0x02, 0x0B, 0x06, 0x0E, 0x07, 0x0F, 0x1F)] == [
        "disable voltage", "disable voltage", "quick stop", "quick stop", "shutdown", "shutdown", "switch on",
        "enable operation", "enable operation"]


def test_drives_cia402_master_walks_to_operation_enabled():
    """The master's controlword sequence from SWITCH ON DISABLED: shutdown 0x06, switch on 0x07, enable
    operation 0x0F (CiA 402-2 transitions 2, 3, 4); disabling from OPERATION ENABLED sends shutdown (8); in
    FAULT the master sends disable voltage, so that a fault reset can be a rising edge of bit 7."""
    sm = PowerStateMachine()
    words = []
    while sm.state is not S.OPERATION_ENABLED:
        cw = next_command(sm.state, enable=True)
        words.append(cw)
        sm.command(cw)
    assert words == [0x06, 0x07, 0x0F]
    assert next_command(S.OPERATION_ENABLED, enable=False) == 0x06
    assert next_command(S.OPERATION_ENABLED, enable=True, quick_stop=True) == 0x02
    assert next_command(S.FAULT, enable=True) == 0x00


def test_drives_cia402_mode_codes():
    """CiA 402-2 modes of operation 0x6060: 1 profile position, 3 profile velocity, 6 homing, 8/9/10 cyclic
    synchronous position/velocity/torque."""
    assert [int(m) for m in Mode] == [1, 3, 6, 8, 9, 10]
    assert AXIS_MODES == ("csp", "csv", "cst", "pp", "pv")


@given(st.lists(st.integers(0, 0xFFFF), max_size=40))
def test_drives_cia402_no_shortcut_to_operation(words):
    """CiA 402-2 invariant: OPERATION ENABLED is entered only from SWITCHED ON (4) or QUICK STOP ACTIVE (16),
    and FAULT is left only to SWITCH ON DISABLED (15), whatever controlwords arrive."""
    sm = PowerStateMachine()
    for k, cw in enumerate(words):
        before = sm.state
        if k == len(words) // 2:
            sm.fault()
            sm.reaction_done()
            before = sm.state
        sm.command(cw)
        if sm.state is S.OPERATION_ENABLED and before is not S.OPERATION_ENABLED:
            assert before in (S.SWITCHED_ON, S.QUICK_STOP_ACTIVE)
        if before is S.FAULT and sm.state is not S.FAULT:
            assert sm.state is S.SWITCH_ON_DISABLED
