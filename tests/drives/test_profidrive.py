"""PROFIdrive words, standard telegrams, speed scaling, encoder model and drive state machine."""
from __future__ import annotations

import itertools
import math
import struct

import pytest
from hypothesis import given
from hypothesis import strategies as st

from plcmotion.drives.profidrive import (
    ENCODER_ERROR_SENSOR_GROUP,
    ENCODER_ERROR_ZERO_MARK,
    FAULT_SIGN_OF_LIFE,
    G1_STW,
    G1_ZSW,
    G2_STW,
    STW1,
    STW2,
    STW2_ENC,
    TELEGRAMS,
    ZSW1,
    ZSW2,
    ZSW2_ENC,
    DriveState,
    DriveStateMachine,
    EncoderCommand,
    IncrementalEncoder,
    SignOfLifeMonitor,
    Telegram1In,
    Telegram1Out,
    Telegram3In,
    Telegram3Out,
    Telegram4In,
    Telegram83In,
    next_sign_of_life,
    nsoll_to_speed,
    speed_to_nsoll,
    telegram_types,
    xist1_difference,
)

# ---------------------------------------------------------------------------------------------------------
# Bit layouts (expected positions written out independently of the module's tables)
# ---------------------------------------------------------------------------------------------------------

LAYOUTS = {
    STW1: {"On": 0, "NoCoastStop": 1, "NoQuickStop": 2, "EnableOperation": 3, "EnableRampGenerator": 4,
           "UnfreezeRampGenerator": 5, "EnableSetpoint": 6, "AcknowledgeFault": 7, "ControlByPlc": 10},
    ZSW1: {"ReadyToSwitchOn": 0, "ReadyToOperate": 1, "OperationEnabled": 2, "FaultPresent": 3,
           "NoCoastStopActive": 4, "NoQuickStopActive": 5, "SwitchingOnInhibited": 6, "WarningPresent": 7,
           "SpeedErrorWithinTolerance": 8, "ControlRequested": 9, "ComparisonValueReached": 10},
    G1_STW: {"RequestFunction1": 0, "RequestFunction2": 1, "RequestFunction3": 2, "RequestFunction4": 3,
             "CommandBit0": 4, "CommandBit1": 5, "CommandBit2": 6, "FlyingMeasurement": 7,
             "HomePositionMode": 11, "RequestSetShiftHomePosition": 12, "RequestAbsoluteValueCyclically": 13,
             "RequestParkingEncoder": 14, "AcknowledgeEncoderError": 15},
    G1_ZSW: {"Function1Active": 0, "Function2Active": 1, "Function3Active": 2, "Function4Active": 3,
             "Value1Available": 4, "Value2Available": 5, "Value3Available": 6, "Value4Available": 7,
             "Probe1Deflected": 8, "Probe2Deflected": 9, "EncoderFaultAcknowledgeActive": 11,
             "HomePositionSetShiftExecuted": 12, "TransmitAbsoluteValueCyclically": 13,
             "ParkingEncoderActive": 14, "EncoderError": 15},
    STW2: {"ParkingAxisSelection": 7, "MasterSignOfLifeBit0": 12, "MasterSignOfLifeBit3": 15},
    ZSW2: {"ParkingAxisActive": 7, "PulsesEnabled": 10, "SlaveSignOfLifeBit0": 12, "SlaveSignOfLifeBit3": 15},
    STW2_ENC: {"FaultAcknowledge": 7, "ControlByPlc": 10, "MasterSignOfLifeBit0": 12},
    ZSW2_ENC: {"FaultPresent": 3, "AlarmPresent": 7, "ControlRequested": 9, "SlaveLifeSignBit0": 12},
}


@pytest.mark.parametrize("cls", list(LAYOUTS), ids=lambda c: c.__name__)
def test_drives_named_bits_sit_at_documented_positions(cls):
    for name, bit in LAYOUTS[cls].items():
        word = cls(1 << bit)
        assert getattr(word, name) is True, name
        assert [n for n in cls.bit_positions() if getattr(word, n)] == [name]
        assert cls(**{name: True}) == word
        assert int(word) == 1 << bit
    # every one of the 16 bits is addressable by exactly one name (reserved ones included)
    assert sorted(cls.bit_positions().values()) == list(range(16))


def test_drives_word_construction_and_protocol():
    w = STW1(0x047E, On=True)
    assert int(w) == 0x047F and w == STW1(0x047F) and hash(w) == hash(STW1(0x047F))
    assert w != ZSW1(0x047F)
    assert STW1(0x047F, On=False) == STW1(0x047E)
    assert w.with_bits(EnableOperation=False) == STW1(0x0477)
    assert "On" in repr(w) and "ControlByPlc" in repr(w) and "AcknowledgeFault" not in repr(w)
    assert repr(STW1()) == "STW1(0x0000: -)"
    assert w.bit(10) and not w.bit(7)
    with pytest.raises(ValueError):
        STW1(0x10000)
    with pytest.raises(ValueError):
        STW1(-1)
    with pytest.raises(TypeError):
        STW1(Bogus=True)
    with pytest.raises(TypeError):
        STW1(ZSW1(1))
    with pytest.raises(AttributeError):
        w.On = False  # type: ignore[misc]


def test_drives_multi_bit_fields():
    g = G1_STW.build(functions=1, command=EncoderCommand.READ_VALUE, RequestAbsoluteValueCyclically=True)
    assert int(g) == 0x2021 and g.command == 2 and g.requested_functions == 1
    assert G2_STW is G1_STW
    s = STW2.with_sign_of_life(9, base=0x0081)
    assert s.master_sign_of_life == 9 and int(s) == 0x9081
    assert ZSW2(0xA400).slave_sign_of_life == 0xA and ZSW2(0xA400).PulsesEnabled
    assert ZSW2_ENC(0x3200).slave_sign_of_life == 3 and STW2_ENC(0x7000).master_sign_of_life == 7


# ---------------------------------------------------------------------------------------------------------
# Telegrams
# ---------------------------------------------------------------------------------------------------------

EXPECTED_ORDER = {
    1: (["STW1", "NSOLL_A"], ["ZSW1", "NIST_A"]),
    2: (["STW1", "NSOLL_B", "STW2"], ["ZSW1", "NIST_B", "ZSW2"]),
    3: (["STW1", "NSOLL_B", "STW2", "G1_STW"],
        ["ZSW1", "NIST_B", "ZSW2", "G1_ZSW", "G1_XIST1", "G1_XIST2"]),
    4: (["STW1", "NSOLL_B", "STW2", "G1_STW", "G2_STW"],
        ["ZSW1", "NIST_B", "ZSW2", "G1_ZSW", "G1_XIST1", "G1_XIST2", "G2_ZSW", "G2_XIST1", "G2_XIST2"]),
    81: (["STW2_ENC", "G1_STW"], ["ZSW2_ENC", "G1_ZSW", "G1_XIST1", "G1_XIST2"]),
    83: (["STW2_ENC", "G1_STW"], ["ZSW2_ENC", "G1_ZSW", "G1_XIST1", "G1_XIST2", "NIST_B"]),
}
# words (PZD) per direction
EXPECTED_WORDS = {1: (2, 2), 2: (4, 4), 3: (5, 9), 4: (6, 14), 81: (2, 6), 83: (2, 8)}
ALL_TYPES = [t for pair in TELEGRAMS.values() for t in pair]


@pytest.mark.parametrize("number", sorted(TELEGRAMS))
def test_drives_field_order_and_sizes(number):
    out_t, in_t = telegram_types(number)
    assert [f[0] for f in out_t.fields()] == EXPECTED_ORDER[number][0]
    assert [f[0] for f in in_t.fields()] == EXPECTED_ORDER[number][1]
    assert (out_t.size(), in_t.size()) == tuple(2 * w for w in EXPECTED_WORDS[number])
    for name, bits, signed in out_t.fields() + in_t.fields():
        assert bits == (32 if name.startswith(("NSOLL_B", "NIST_B")) or "XIST" in name else 16)
        assert signed == name.startswith(("NSOLL", "NIST"))
    assert out_t.TELEGRAM == in_t.TELEGRAM == number


def test_drives_unknown_telegram():
    with pytest.raises(ValueError):
        telegram_types(5)


def _value_strategy(bits: int, signed: bool):
    return st.integers(-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else st.integers(0, (1 << bits) - 1)


@st.composite
def telegram_values(draw):
    cls = draw(st.sampled_from(ALL_TYPES))
    return cls, {name: draw(_value_strategy(bits, signed)) for name, bits, signed in cls.fields()}


@given(telegram_values())
def test_drives_pack_unpack_round_trip(tv):
    cls, values = tv
    tel = cls(**values)
    data = tel.pack()
    assert len(data) == cls.size()
    back = cls.unpack(data)
    assert back == tel
    assert {name: int(v) for name, v in back.values()} == values


@given(st.sampled_from(ALL_TYPES).flatmap(lambda c: st.tuples(st.just(c), st.binary(min_size=c.size(),
                                                                                 max_size=c.size()))))
def test_drives_every_byte_pattern_survives_unpack_pack(cb):
    cls, data = cb
    assert cls.unpack(data).pack() == data


def test_drives_byte_order_is_big_endian():
    assert Telegram1Out(STW1=0x047F, NSOLL_A=-2).pack() == bytes.fromhex("047f fffe")
    t3 = Telegram3Out(STW1=STW1(0x047F), NSOLL_B=0x40000000, STW2=0xF000, G1_STW=0x2000).pack()
    assert t3 == bytes.fromhex("047f 40000000 f000 2000")
    t = Telegram3In(ZSW1=0xE637, NIST_B=-1, ZSW2=0x1000, G1_ZSW=0x2000, G1_XIST1=0x12345678,
                    G1_XIST2=0xFFFFFFFE).pack()
    assert t == bytes.fromhex("e637 ffffffff 1000 2000 12345678 fffffffe")
    t83 = Telegram83In(NIST_B=-(1 << 31), G1_XIST1=1).pack()
    assert t83[-4:] == bytes.fromhex("80000000") and t83[4:8] == bytes.fromhex("00000001")
    assert struct.unpack(">h", Telegram1In(NIST_A=-16384).pack()[2:])[0] == -16384


def test_drives_out_of_range_and_bad_input():
    with pytest.raises(ValueError):
        Telegram1Out(NSOLL_A=32768)
    with pytest.raises(ValueError):
        Telegram3In(G1_XIST1=-1)
    with pytest.raises(ValueError):
        Telegram3In(G1_XIST2=1 << 32)
    with pytest.raises(ValueError):
        Telegram3Out(NSOLL_B=1 << 31)
    with pytest.raises(ValueError):
        Telegram1Out(STW1=0x10000)
    with pytest.raises(TypeError):
        Telegram1Out(NSOLL_A=1.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        Telegram4In.unpack(bytes(27))
    tel = Telegram1Out()
    tel.NSOLL_A = -40000
    with pytest.raises(ValueError):
        tel.pack()
    tel.NSOLL_A = -32768
    tel.STW1 = 0x047F  # type: ignore[assignment]
    assert tel.pack() == bytes.fromhex("047f8000") and tel.STW1 == STW1(0x047F)


# ---------------------------------------------------------------------------------------------------------
# Speed scaling
# ---------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bits, full", [(16, 0x4000), (32, 0x40000000)])
def test_drives_speed_scaling_fixed_points(bits, full):
    ref = 3000.0
    top, bottom = (1 << (bits - 1)) - 1, -(1 << (bits - 1))
    assert speed_to_nsoll(0.0, ref, bits) == 0
    assert speed_to_nsoll(ref, ref, bits) == full
    assert speed_to_nsoll(-ref, ref, bits) == -full
    assert speed_to_nsoll(2 * ref, ref, bits) == top          # +200 % is one step beyond the range
    assert speed_to_nsoll(-2 * ref, ref, bits) == bottom == -2 * full
    assert speed_to_nsoll(1e9, ref, bits) == top and speed_to_nsoll(-math.inf, ref, bits) == bottom
    assert nsoll_to_speed(full, ref, bits) == ref
    assert nsoll_to_speed(bottom, ref, bits) == -2 * ref
    assert nsoll_to_speed(top, ref, bits) == pytest.approx(2 * ref, rel=1e-4)
    lsb = ref / full
    assert speed_to_nsoll(0.5 * lsb, ref, bits) == 1 and speed_to_nsoll(-0.5 * lsb, ref, bits) == -1
    assert speed_to_nsoll(0.49 * lsb, ref, bits) == 0
    with pytest.raises(ValueError):
        nsoll_to_speed(top + 1, ref, bits)


def test_drives_speed_scaling_rejects_bad_arguments():
    for args in [(1.0, 3000.0, 24), (math.nan, 3000.0, 16), (1.0, 0.0, 16), (1.0, -1.0, 32)]:
        with pytest.raises(ValueError):
            speed_to_nsoll(*args)


@given(st.floats(-5999.0, 5999.0), st.sampled_from([16, 32]))
def test_drives_speed_scaling_inverse(rpm, bits):
    ref = 3000.0
    v = speed_to_nsoll(rpm, ref, bits)
    assert abs(nsoll_to_speed(v, ref, bits) - rpm) <= 0.5 * ref / (1 << (bits - 2)) * (1 + 1e-9)
    assert speed_to_nsoll(nsoll_to_speed(v, ref, bits), ref, bits) == v


# ---------------------------------------------------------------------------------------------------------
# Encoder
# ---------------------------------------------------------------------------------------------------------

PER_REV = 2048 << 11  # default encoder: 2^22 counts per revolution, XIST1 wraps every 1024 revolutions


def test_drives_xist1_counts_and_wrap_around():
    enc = IncrementalEncoder()
    assert enc.xist1_per_revolution == PER_REV
    assert enc.count_at(0.0) == 0 and enc.count_at(1.5) == 3 * PER_REV // 2
    assert enc.count_at(-1.0 / PER_REV) == 0xFFFFFFFF
    assert enc.count_at(1024.0) == 0                      # 2^32 counts: full wrap
    before, after = enc.count_at(1023.9), enc.count_at(1024.1)
    assert after < before
    assert enc.counts_to_revolutions_delta(before, after) == pytest.approx(0.2, abs=1 / PER_REV)
    assert enc.counts_to_revolutions_delta(after, before) == pytest.approx(-0.2, abs=1 / PER_REV)
    assert xist1_difference(0xFFFFFFFF, 0) == 1 and xist1_difference(0, 0xFFFFFFFF) == -1
    enc.update(1023.95)
    x0 = enc.xist1
    enc.update(1024.05)
    assert enc.xist1 < x0 and enc.counts_to_revolutions_delta(x0, enc.xist1) == pytest.approx(0.1, abs=1e-6)


@given(st.floats(-5000.0, 5000.0), st.floats(-100.0, 100.0))
def test_drives_revolution_delta_survives_wrap(p, d):
    enc = IncrementalEncoder()
    delta = enc.counts_to_revolutions_delta(enc.count_at(p), enc.count_at(p + d))
    assert abs(delta - d) <= 1.0 / PER_REV + 1e-9 * max(1.0, abs(p))


def test_drives_absolute_value_multi_and_single_turn():
    multi = IncrementalEncoder(4096, 11, 0, determinable_revolutions=4096)
    assert multi.absolute_value_at(2.5) == 2 * 4096 + 2048
    assert multi.absolute_value_at(4096.25) == 1024       # multi-turn range wraps
    assert multi.absolute_value_at(-0.25) == 4096 * 4096 - 1024
    single = IncrementalEncoder(4096, 11, 9, determinable_revolutions=1)
    assert single.absolute_value_at(7.5) == 2048 << 9
    with pytest.raises(ValueError):
        IncrementalEncoder().absolute_value_at(1.0)
    with pytest.raises(ValueError):
        IncrementalEncoder(1 << 20, 11, 9, determinable_revolutions=1 << 12)   # > 32 bits


def test_drives_cyclic_absolute_value_handshake():
    enc = IncrementalEncoder(4096, 11, 0, determinable_revolutions=4096)
    enc.update(3.25)
    assert enc.xist2 == 0 and not enc.zsw.TransmitAbsoluteValueCyclically
    enc.update(3.5, G1_STW(RequestAbsoluteValueCyclically=True))
    assert enc.zsw.TransmitAbsoluteValueCyclically and enc.xist2 == 3 * 4096 + 2048
    inc = IncrementalEncoder()
    inc.update(3.5, G1_STW(RequestAbsoluteValueCyclically=True))
    assert not inc.zsw.TransmitAbsoluteValueCyclically and inc.xist2 == 0


ACTIVATE = G1_STW.build(functions=1, command=EncoderCommand.ACTIVATE)
READ = G1_STW.build(functions=1, command=EncoderCommand.READ_VALUE)
ABORT = G1_STW.build(functions=1, command=EncoderCommand.ABORT)


def test_drives_reference_mark_search_sequence():
    enc = IncrementalEncoder(zero_mark_angle=0.25)
    enc.update(0.0)
    enc.update(0.1, ACTIVATE)
    assert enc.zsw.Function1Active and not enc.zsw.Value1Available
    enc.update(0.2, ACTIVATE)
    assert not enc.zsw.Value1Available
    enc.update(0.3, ACTIVATE)                                  # crosses the mark at 0.25 rev
    assert enc.zsw.Value1Available and enc.latched_value == enc.count_at(0.25) == PER_REV // 4
    assert enc.xist2 == 0                                      # not before the read command
    enc.update(1.3, ACTIVATE)                                  # held "activate" does not re-arm
    assert enc.latched_value == PER_REV // 4
    enc.update(1.4, READ)
    assert enc.xist2 == PER_REV // 4 and enc.zsw.Value1Available
    enc.update(1.5, G1_STW())                                  # request withdrawn -> idle
    assert not enc.zsw.Function1Active and not enc.zsw.Value1Available and enc.xist2 == 0
    enc.update(1.6, ACTIVATE)
    enc.update(1.7, ABORT)
    assert not enc.zsw.Function1Active and enc.latched_value is None
    enc.update(2.5, ABORT)                                     # aborted: mark at 2.25 ignored
    assert enc.latched_value is None
    fly = G1_STW.build(functions=1, command=EncoderCommand.ACTIVATE, FlyingMeasurement=True)
    enc.update(2.6, G1_STW())
    enc.update(2.7, fly)
    assert not enc.zsw.Function1Active                         # flying measurement not modelled


@given(angle=st.floats(0.0, 0.999), start=st.floats(-50.0, 50.0),
       speed=st.floats(0.001, 0.45) | st.floats(-0.45, -0.001), phase=st.floats(0.0, 1.0))
def test_drives_reference_mark_latch_is_exact(angle, start, speed, phase):
    """The latched XIST1 equals the count at the exact zero-mark position (within one count)."""
    enc = IncrementalEncoder(zero_mark_angle=angle)
    p = start
    enc.update(p)
    enc.update(p, ACTIVATE)                                    # armed at p, nothing crossed yet
    # first mark strictly beyond p in the direction of motion, computed independently
    gap = ((angle - p) if speed > 0 else (p - angle)) % 1.0
    z = p + math.copysign(gap if gap > 0 else 1.0, speed)
    p += speed * phase                                          # arbitrary phase of the cycle grid
    for _ in range(int(1.0 / abs(speed)) + 3):
        enc.update(p, ACTIVATE)
        if enc.zsw.Value1Available:
            break
        p += speed
    assert enc.zsw.Value1Available
    expected = math.floor(z * PER_REV) % (1 << 32)
    assert abs(xist1_difference(expected, enc.latched_value)) <= 1


def test_drives_encoder_error_and_acknowledge():
    enc = IncrementalEncoder(determinable_revolutions=1)
    enc.inject_error(ENCODER_ERROR_ZERO_MARK, cause_active=True)
    enc.update(0.5, G1_STW(RequestAbsoluteValueCyclically=True))
    assert enc.zsw.EncoderError and enc.xist2 == 0x0002 and not enc.zsw.TransmitAbsoluteValueCyclically
    enc.update(0.5, G1_STW(AcknowledgeEncoderError=True))     # cause still there: stays
    assert enc.zsw.EncoderError and enc.zsw.EncoderFaultAcknowledgeActive
    enc.clear_error_cause()
    enc.update(0.5, G1_STW(AcknowledgeEncoderError=True))     # no new edge: stays
    assert enc.zsw.EncoderError
    enc.update(0.5, G1_STW())
    assert not enc.zsw.EncoderFaultAcknowledgeActive
    enc.update(0.5, G1_STW(AcknowledgeEncoderError=True))
    assert not enc.zsw.EncoderError and enc.xist2 == 0 and enc.error_code == 0
    enc.inject_error()
    enc.update(0.5, G1_STW())
    assert enc.xist2 == ENCODER_ERROR_SENSOR_GROUP == 0x0001
    enc.update(0.5, G1_STW(AcknowledgeEncoderError=True))
    assert not enc.zsw.EncoderError


def test_drives_parking_freezes_values():
    enc = IncrementalEncoder(determinable_revolutions=1)
    enc.update(0.25, G1_STW(RequestAbsoluteValueCyclically=True))
    x1, x2 = enc.xist1, enc.xist2
    enc.update(0.75, G1_STW(RequestParkingEncoder=True, RequestAbsoluteValueCyclically=True))
    assert enc.zsw == G1_ZSW(ParkingEncoderActive=True) and (enc.xist1, enc.xist2) == (x1, x2)
    assert enc.parked
    enc.probe2 = True
    enc.update(0.8, G1_STW())
    assert not enc.zsw.ParkingEncoderActive and enc.xist1 == enc.count_at(0.8)
    assert enc.zsw.Probe2Deflected and not enc.zsw.Probe1Deflected


def test_drives_home_position_set_and_shift():
    enc = IncrementalEncoder(home_preset=10.0)
    enc.update(3.0, G1_STW(RequestSetShiftHomePosition=True))
    assert enc.zsw.HomePositionSetShiftExecuted and enc.xist1 == 10 * PER_REV
    enc.update(3.5, G1_STW())
    assert not enc.zsw.HomePositionSetShiftExecuted and enc.xist1 == 10 * PER_REV + PER_REV // 2
    enc.home_preset = -1.0
    enc.update(3.5, G1_STW(RequestSetShiftHomePosition=True, HomePositionMode=True))
    assert enc.xist1 == 9 * PER_REV + PER_REV // 2


# ---------------------------------------------------------------------------------------------------------
# Drive state machine
# ---------------------------------------------------------------------------------------------------------

DT = 0.004
OFF1 = STW1(0x047E)                  # everything enabled except ON
RUN = STW1(0x047F)
PAT_S1 = {"ReadyToSwitchOn": False, "ReadyToOperate": False, "OperationEnabled": False, "SwitchingOnInhibited": True}
PAT_S2 = {"ReadyToSwitchOn": True, "ReadyToOperate": False, "OperationEnabled": False, "SwitchingOnInhibited": False}
PAT_S3 = {"ReadyToSwitchOn": True, "ReadyToOperate": True, "OperationEnabled": False, "SwitchingOnInhibited": False}
PAT_S4 = {"ReadyToSwitchOn": True, "ReadyToOperate": True, "OperationEnabled": True, "SwitchingOnInhibited": False}


def cycle(d: DriveStateMachine, stw1, nsoll: float = 0.0, stw2=None) -> float:
    d.write(stw1, stw2)
    d.step(DT)
    return d.effective_setpoint(nsoll)


def assert_pattern(z: ZSW1, pattern: dict[str, bool]) -> None:
    assert {k: getattr(z, k) for k in pattern} == pattern, z


def enabled_drive(**kw) -> DriveStateMachine:
    d = DriveStateMachine(3000.0, **kw)
    cycle(d, OFF1)
    cycle(d, RUN)
    cycle(d, RUN)
    assert d.state is DriveState.S4
    return d


def test_drives_full_enable_sequence():
    d = DriveStateMachine(3000.0)
    assert d.state is DriveState.S1
    assert_pattern(d.zsw1, PAT_S1)
    assert cycle(d, STW1(ControlByPlc=True), 500.0) == 0.0        # OFF2 and OFF3 active: stays in S1
    assert d.state is DriveState.S1 and not d.zsw1.NoCoastStopActive
    assert cycle(d, OFF1, 500.0) == 0.0
    assert d.state is DriveState.S2
    assert_pattern(d.zsw1, PAT_S2)
    cycle(d, OFF1.with_bits(On=True, EnableOperation=False), 500.0)
    assert d.state is DriveState.S3 and not d.ready_for_setpoints
    assert_pattern(d.zsw1, PAT_S3)
    assert cycle(d, RUN, 500.0) == 500.0
    assert d.state is DriveState.S4 and d.ready_for_setpoints
    z = d.zsw1
    assert_pattern(z, PAT_S4)
    assert z.NoCoastStopActive and z.NoQuickStopActive and z.ControlRequested and not z.FaultPresent
    assert int(z) & 0x067F == 0x0237


def test_drives_s1_to_s2_needs_on_reset():
    d = DriveStateMachine()
    cycle(d, RUN)
    assert d.state is DriveState.S1


def test_drives_setpoint_gating_in_operation():
    d = enabled_drive()
    assert cycle(d, RUN, 1200.0) == 1200.0
    assert cycle(d, RUN.with_bits(UnfreezeRampGenerator=False), 1500.0) == 1200.0   # frozen
    assert cycle(d, RUN.with_bits(EnableSetpoint=False), 1500.0) == 0.0
    assert cycle(d, RUN, -700.0) == -700.0
    assert cycle(d, RUN.with_bits(EnableRampGenerator=False), 1500.0) == 0.0
    assert cycle(d, RUN.with_bits(EnableOperation=False), 1500.0) == 0.0
    assert d.state is DriveState.S3


def test_drives_ramp_generator_with_ramp_time():
    d = enabled_drive(ramp_time=1.0)           # 3000 1/min per second
    d.effective_setpoint(600.0)
    outs = [cycle(d, RUN, 600.0) for _ in range(60)]
    assert outs[0] == pytest.approx(12.0) and outs[9] == pytest.approx(120.0) and outs[-1] == 600.0


def test_drives_off1_ramps_down_then_ready_for_switching_on():
    d = enabled_drive(off1_ramp_time=1.0)      # 3000 1/min per second
    cycle(d, RUN, 1500.0)
    speeds = []
    while d.state is not DriveState.S2:
        speeds.append(cycle(d, OFF1, 1500.0))
        if d.state is DriveState.S5:
            assert d.switching_off == "OFF1"
            assert_pattern(d.zsw1, PAT_S4)
        assert len(speeds) < 1000
    assert speeds[0] == pytest.approx(1500.0 - 12.0)
    assert all(b < a for a, b in itertools.pairwise(speeds[:-1]))
    assert len(speeds) == pytest.approx(0.5 / DT, abs=1)
    assert speeds[-1] == 0.0
    assert_pattern(d.zsw1, PAT_S2)


def test_drives_off1_ramp_is_completed_even_if_on_returns():
    d = enabled_drive(off1_ramp_time=1.0)
    cycle(d, RUN, 300.0)
    cycle(d, OFF1, 300.0)
    assert d.state is DriveState.S5
    states = [(cycle(d, RUN, 300.0), d.state) for _ in range(40)]
    assert (0.0, DriveState.S2) in states and states[-1] == (300.0, DriveState.S4)


def test_drives_off2_coasts_immediately():
    d = enabled_drive()
    cycle(d, RUN, 1000.0)
    assert cycle(d, RUN.with_bits(NoCoastStop=False), 1000.0) == 0.0
    assert d.state is DriveState.S1 and d.speed_output == 0.0
    assert_pattern(d.zsw1, PAT_S1)
    assert not d.zsw1.NoCoastStopActive
    cycle(d, RUN)
    assert d.state is DriveState.S1                       # ON must go to 0 first
    cycle(d, OFF1)
    assert d.state is DriveState.S2


def test_drives_off3_quick_stop_ends_in_switching_on_inhibited():
    d = enabled_drive(off3_ramp_time=0.1, off1_ramp_time=10.0)   # 30000 1/min per second
    cycle(d, RUN, 1500.0)
    quick = RUN.with_bits(NoQuickStop=False)
    first = cycle(d, quick, 1500.0)
    assert d.state is DriveState.S5 and d.switching_off == "OFF3"
    assert first == pytest.approx(1500.0 - 120.0)
    assert not d.zsw1.NoQuickStopActive
    n = 1
    while d.state is DriveState.S5:
        cycle(d, RUN, 1500.0)                             # releasing OFF3 does not stop the quick stop
        n += 1
    assert n == pytest.approx(0.05 / DT, abs=1)
    assert d.state is DriveState.S1
    assert_pattern(d.zsw1, PAT_S1)
    for state_before in (DriveState.S2, DriveState.S3):
        d = DriveStateMachine()
        cycle(d, OFF1)
        if state_before is DriveState.S3:
            cycle(d, RUN.with_bits(EnableOperation=False))
        assert d.state is state_before
        cycle(d, OFF1.with_bits(NoQuickStop=False))
        assert d.state is DriveState.S1


def test_drives_fault_and_acknowledge():
    d = enabled_drive()
    cycle(d, RUN, 900.0)
    d.inject_fault(7860, cause_active=True)
    assert cycle(d, RUN, 900.0) == 0.0
    assert d.state is DriveState.S1 and d.zsw1.FaultPresent and d.faults == (7860,)
    assert_pattern(d.zsw1, PAT_S1)
    ack = RUN.with_bits(AcknowledgeFault=True)
    cycle(d, ack)
    assert d.fault_present                                # cause still active
    d.clear_fault_cause()
    cycle(d, ack)
    assert d.fault_present                                # needs a new rising edge
    cycle(d, RUN)
    cycle(d, ack)
    assert not d.fault_present and d.state is DriveState.S1
    cycle(d, RUN)
    assert d.state is DriveState.S1                       # ON still set
    cycle(d, OFF1)
    cycle(d, RUN)
    cycle(d, RUN)
    assert d.state is DriveState.S4


def test_drives_transient_fault_acknowledged_at_once():
    d = enabled_drive()
    d.inject_fault(1)
    cycle(d, RUN)
    cycle(d, OFF1.with_bits(AcknowledgeFault=True))
    assert not d.fault_present
    cycle(d, OFF1)
    assert d.state is DriveState.S2


def test_drives_control_requested_and_control_by_plc():
    d = enabled_drive()
    cycle(d, RUN, 500.0)
    d.request_local_control()
    assert not d.zsw1.ControlRequested
    assert cycle(d, RUN.with_bits(NoCoastStop=False), 800.0) == 500.0   # controller ignored
    assert d.state is DriveState.S4
    d.release_local_control()
    assert d.zsw1.ControlRequested
    assert cycle(d, RUN.with_bits(ControlByPlc=False, On=False), 800.0) == 500.0
    assert d.state is DriveState.S4
    assert cycle(d, RUN, 800.0) == 800.0


def test_drives_speed_status_bits():
    d = enabled_drive(speed_tolerance_rpm=10.0, comparison_rpm=1000.0)
    d.write(RUN)
    d.step(DT, actual_rpm=1195.0)
    d.effective_setpoint(1200.0)
    assert d.zsw1.SpeedErrorWithinTolerance and d.zsw1.ComparisonValueReached
    d.step(DT, actual_rpm=900.0)
    assert not d.zsw1.SpeedErrorWithinTolerance and not d.zsw1.ComparisonValueReached
    d.warning = True
    assert d.zsw1.WarningPresent


# ---------------------------------------------------------------------------------------------------------
# Sign of life
# ---------------------------------------------------------------------------------------------------------

def test_drives_life_counter_sequence():
    seq = [0]
    for _ in range(32):
        seq.append(next_sign_of_life(seq[-1]))
    assert seq[:17] == [0, *range(1, 16), 1] and 0 not in seq[1:]


def test_drives_life_sign_increments_each_cycle():
    d = DriveStateMachine()
    seen = []
    for _ in range(20):
        d.step(DT)
        seen.append(d.zsw2.slave_sign_of_life)
    assert seen == [*range(1, 16), 1, 2, 3, 4, 5]


def test_drives_sign_of_life_monitor():
    m = SignOfLifeMonitor(tolerance=1)
    assert m.check(0) and m.check(0) and not m.started      # not started yet
    life = 0
    for _ in range(40):                                     # includes the 15 -> 1 wrap
        life = next_sign_of_life(life)
        assert m.check(life)
    assert m.check(life) and m.failures == 1                # one repeat tolerated
    life = next_sign_of_life(life)
    assert m.check(life) and m.failures == 0
    assert m.check(0) and m.failures == 1                   # 0 after start is a failure
    assert not m.check(0) and m.tripped


def test_drives_detects_sign_of_life_failure():
    d = enabled_drive(sign_of_life_tolerance=1)
    life = 0
    for _ in range(40):
        life = next_sign_of_life(life)
        cycle(d, RUN, 100.0, STW2.with_sign_of_life(life))
    assert d.state is DriveState.S4 and not d.fault_present
    cycle(d, RUN, 100.0)                                    # no new telegram: stale value, tolerated
    assert d.state is DriveState.S4 and d.zsw1.WarningPresent
    life = next_sign_of_life(life)
    cycle(d, RUN, 100.0, STW2.with_sign_of_life(life))
    assert not d.zsw1.WarningPresent
    cycle(d, RUN, 100.0, STW2.with_sign_of_life(life))       # two failures in a row
    cycle(d, RUN, 100.0, STW2.with_sign_of_life(life))
    assert d.fault_present and d.faults == (FAULT_SIGN_OF_LIFE,) and d.state is DriveState.S1
    # acknowledge; monitoring restarts with the next value the controller sends
    for stw1 in (OFF1.with_bits(AcknowledgeFault=True), OFF1, RUN, RUN):
        life = next_sign_of_life(life)
        cycle(d, stw1, 100.0, STW2.with_sign_of_life(life))
    assert not d.fault_present and d.state is DriveState.S4


def test_drives_telegram_1_drive_has_no_sign_of_life_monitoring():
    d = enabled_drive()
    for _ in range(50):
        cycle(d, RUN, 100.0)
    assert not d.fault_present
