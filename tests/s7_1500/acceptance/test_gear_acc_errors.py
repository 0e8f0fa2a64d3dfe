"""Rejected jobs (S7-1500T V5 §9.1.1.1, §9.1.2.1, §9.1.3.1, §9.1.4.1 parameter tables and requirements): Error TRUE,
ErrorID != 0, Busy FALSE, no motion, the running synchronous operation continues."""
import math
import pytest
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_PhasingRelative, MC_PhasingAbsolute
from _gear_h import VIRTUAL, H, merge, modulo, outputs_consistent


def _start(h, fb, **inputs):
    base = {"Master": h.m, "Slave": h.s, "Execute": False}
    base.update(inputs)
    h.call(fb, base)
    h.until(h.enabled, 1.0)
    base["Execute"] = True
    h.step()
    return base


def _rejected(fb, code=None):
    assert fb.Error, fb.outputs
    assert fb.ErrorID != 0
    assert not fb.Busy
    assert not outputs_consistent(fb), outputs_consistent(fb)
    if code is not None:
        assert fb.ErrorID == code, hex(fb.ErrorID)


@pytest.mark.parametrize("inp,code", [
    ({"RatioNumerator": 0}, 0x8017),
    ({"RatioDenominator": 0}, 0x8018),
    ({"RatioDenominator": -1}, 0x8018),
    ({"RatioNumerator": 2**31}, 0x8017),
    ({"RatioDenominator": 2**31}, 0x8018),
    ({"RatioNumerator": 1.5}, 0x8017),
    ({"Acceleration": 0.0}, 0x8004),
    ({"Deceleration": 0.0}, 0x8005),
    ({"Acceleration": math.nan}, 0x8004),
    ({"Deceleration": math.inf}, 0x8005),
    ({"Jerk": math.nan}, 0x8006),
])
def test_s7_1500_gear_in_invalid_inputs(inp, code):
    h = H()
    fb = MC_GearIn()
    _start(h, fb, **inp)
    _rejected(fb, code)
    assert h.s.StatusSynchronizedMotion.FunctionState == 0


def test_s7_1500_gear_in_jerk_zero_is_trapezoid_not_error():
    h = H()
    h.move_master(50.0)
    fb = MC_GearIn()
    _start(h, fb, Jerk=0.0, Acceleration=1000.0, Deceleration=1000.0)
    assert fb.Busy and not fb.Error
    h.until(lambda: fb.InGear, 2.0)


def test_s7_1500_gear_in_negative_dynamics_use_defaults_no_error():
    h = H()
    fb = MC_GearIn()
    _start(h, fb, Acceleration=-5.0, Deceleration=-1.0, Jerk=-3.0)
    assert fb.Busy and not fb.Error


@pytest.mark.parametrize("inp,code", [
    ({"RatioNumerator": 0}, 0x8017),
    ({"RatioDenominator": 0}, 0x8018),
    ({"SyncProfileReference": 2}, 0x8036),
    ({"SyncProfileReference": 4}, 0x8036),
    ({"SyncProfileReference": -1}, 0x8036),
    ({"SyncProfileReference": 5}, 0x8036),
    ({"MasterStartDistance": -1.0, "SyncProfileReference": 1}, 0x8026),
    ({"MasterStartDistance": -1.0, "SyncProfileReference": 3}, 0x8026),
    ({"MasterSyncPosition": math.nan}, 0x8034),
    ({"SlaveSyncPosition": math.inf}, 0x8035),
    ({"SyncProfileReference": 0, "Velocity": 0.0}, 0x8003),
    ({"SyncProfileReference": 0, "Acceleration": 0.0}, 0x8004),
    ({"SyncProfileReference": 0, "Deceleration": 0.0}, 0x8005),
])
def test_s7_1500_gear_in_pos_invalid_inputs(inp, code):
    h = H()
    fb = MC_GearInPos()
    base = dict(MasterSyncPosition=500.0, SlaveSyncPosition=0.0, MasterStartDistance=100.0)
    base.update(inp)
    _start(h, fb, **base)
    _rejected(fb, code)
    sm = h.s.StatusSynchronizedMotion
    assert sm.WaitingFunctionState == 0 and sm.FunctionState == 0


@pytest.mark.parametrize("direction", [0, 4, -1])
def test_s7_1500_gear_in_pos_invalid_sync_direction_on_modulo_axes(direction):
    """§9.1.2.1: SyncDirection 1, 2, 3 with modulo axes; another value is rejected (16#8007)."""
    h = H(mp=merge(VIRTUAL, modulo()), sp=merge(VIRTUAL, modulo()))
    fb = MC_GearInPos()
    _start(h, fb, MasterSyncPosition=200.0, SlaveSyncPosition=0.0, MasterStartDistance=100.0,
           SyncDirection=direction)
    _rejected(fb, 0x8007)


def test_s7_1500_gear_in_pos_sync_direction_not_read_between_linear_axes():
    """§9.1.2.1: SyncDirection is in effect for axes with the modulo setting only."""
    h = H()
    fb = MC_GearInPos()
    _start(h, fb, MasterSyncPosition=500.0, SlaveSyncPosition=0.0, MasterStartDistance=100.0, SyncDirection=0)
    assert fb.Busy and not fb.Error, hex(fb.ErrorID)


@pytest.mark.parametrize("spr", [1, 3])
def test_s7_1500_gear_in_pos_dynamics_not_relevant_for_spr_1_3(spr):
    """§9.1.2.1: Velocity/Acceleration/Deceleration/Jerk 'not relevant' with SPR 1, 3: 0.0 must not be rejected."""
    h = H()
    fb = MC_GearInPos()
    _start(h, fb, SyncProfileReference=spr, MasterSyncPosition=500.0, MasterStartDistance=100.0,
           Velocity=0.0, Acceleration=0.0, Deceleration=0.0)
    assert fb.Busy and not fb.Error, hex(fb.ErrorID)


def test_s7_1500_gear_in_pos_start_distance_not_relevant_for_spr_0():
    h = H()
    fb = MC_GearInPos()
    _start(h, fb, SyncProfileReference=0, MasterSyncPosition=500.0, MasterStartDistance=-5.0)
    assert fb.Busy and not fb.Error, hex(fb.ErrorID)


def test_s7_1500_gear_in_pos_spr1_master_too_close():
    """§9.1.2.1 requirement: SPR 1 needs the master >= MasterStartDistance from MasterSyncPosition."""
    h = H()
    fb = MC_GearInPos()
    _start(h, fb, SyncProfileReference=1, MasterSyncPosition=50.0, MasterStartDistance=100.0)
    _rejected(fb)


def test_s7_1500_gear_in_pos_spr1_master_too_close_moving_negative():
    h = H()
    h.move_master(-100.0)
    fb = MC_GearInPos()
    p = h.m.Position
    _start(h, fb, SyncProfileReference=1, MasterSyncPosition=p - 50.0, MasterStartDistance=100.0)
    _rejected(fb)


def test_s7_1500_slave_not_enabled():
    h = H()
    h.en["S1"] = False
    fb = MC_GearIn()
    base = {"Master": h.m, "Slave": h.s, "Execute": False}
    h.call(fb, base)
    h.until(lambda: h.power["M1"].Status, 1.0)
    base["Execute"] = True
    h.step()
    _rejected(fb, 0x800F)


def test_s7_1500_gear_in_pos_slave_not_enabled():
    h = H()
    h.en["S1"] = False
    fb = MC_GearInPos()
    base = {"Master": h.m, "Slave": h.s, "Execute": False, "MasterSyncPosition": 500.0}
    h.call(fb, base)
    h.until(lambda: h.power["M1"].Status, 1.0)
    base["Execute"] = True
    h.step()
    _rejected(fb, 0x800F)


def test_s7_1500_master_not_configured_as_leading_value():
    """§4.6: ErrorWord.X14 SynchronousError: the leading axis given is not configured as possible leading axis."""
    h = H(masters=2, leading=["M1"])
    fb = MC_GearIn()
    base = {"Master": h.masters[1], "Slave": h.s, "Execute": False}
    h.call(fb, base)
    h.until(h.enabled, 1.0)
    base["Execute"] = True
    h.step()
    _rejected(fb)
    assert h.s.ErrorWord.X14


@pytest.mark.parametrize("which", ["slave_positioning", "master_cam", "master_none", "slave_is_master"])
def test_s7_1500_wrong_technology_objects(which):
    h = H()
    fb = MC_GearIn()
    cam = h.ctl.add_cam("C", points=[(0, 0), (360, 10)], interpolation_mode=1)
    base = {"Master": h.m, "Slave": h.s, "Execute": False}
    if which == "slave_positioning":
        base["Slave"] = h.m
    elif which == "master_cam":
        base["Master"] = cam
    elif which == "master_none":
        base["Master"] = None
    else:
        base["Master"] = h.s
    h.call(fb, base)
    h.until(h.enabled, 1.0)
    base["Execute"] = True
    h.step()
    _rejected(fb)


def test_s7_1500_gear_in_pos_needs_t_family():
    h = H(family="S7-1500")
    fb = MC_GearInPos()
    _start(h, fb, MasterSyncPosition=500.0, MasterStartDistance=100.0)
    _rejected(fb, 0x8002)


def test_s7_1500_gear_in_works_on_s7_1500_non_t():
    h = H(family="S7-1500")
    h.move_master(50.0)
    fb = MC_GearIn()
    _start(h, fb)
    assert fb.Busy and not fb.Error
    h.until(lambda: fb.InGear, 2.0)


@pytest.mark.parametrize("cls", [MC_PhasingRelative, MC_PhasingAbsolute])
def test_s7_1500_phasing_needs_t_family(cls):
    """§2.2 / §9.1.3, §9.1.4: MC_PhasingRelative/Absolute are S7-1500T functions; on an S7-1500 with a
    synchronous MC_GearIn they must be rejected."""
    h = H(family="S7-1500")
    h.move_master(50.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.until(lambda: g.InGear, 2.0)
    ph = cls()
    _start(h, ph, PhaseShift=10.0)
    _rejected(ph)
    assert g.InGear and g.Busy


@pytest.mark.parametrize("cls", [MC_PhasingRelative, MC_PhasingAbsolute])
@pytest.mark.parametrize("inp,code", [({"Velocity": 0.0}, 0x8003), ({"Acceleration": 0.0}, 0x8004),
                                      ({"Deceleration": 0.0}, 0x8005), ({"PhaseShift": math.nan}, 0x8070)])
def test_s7_1500_phasing_invalid_inputs_keep_gearing(cls, inp, code):
    h = H()
    h.move_master(50.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.until(lambda: g.InGear, 2.0)
    ph = cls()
    _start(h, ph, **dict({"PhaseShift": 10.0}, **inp))
    _rejected(ph, code)
    h.step(3)
    assert g.InGear and g.Busy and not g.CommandAborted
    assert h.s.StatusSynchronizedMotion.PhaseShift == 0.0


def test_s7_1500_phasing_while_gear_in_pos_only_synchronizing_rejected():
    """§9.1.3.1 requirement: InSync must be TRUE; during synchronization (StartSync only) the job is rejected."""
    h = H()
    h.move_master(100.0)
    g = MC_GearInPos()
    p = h.m.Position
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 300.0,
               "MasterStartDistance": 250.0, "SyncProfileReference": 1})
    h.until(lambda: g.StartSync, 2.0)
    assert not g.InSync
    ph = MC_PhasingRelative()
    _start(h, ph, PhaseShift=10.0)
    _rejected(ph, 0x80A9)
    assert g.Busy and not g.CommandAborted


def test_s7_1500_phasing_with_other_master_rejected():
    h = H(masters=2)
    h.move_master(50.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.until(lambda: g.InGear, 2.0)
    ph = MC_PhasingRelative()
    _start(h, ph, PhaseShift=10.0, Master=h.masters[1])
    _rejected(ph)
    assert g.InGear


def test_s7_1500_phasing_with_camming_rejected():
    """§4.5 / catalog 2.5: phasing not available for camming."""
    from plcmotion.s7_1500 import MC_CamIn, MC_InterpolateCam
    h = H()
    cam = h.ctl.add_cam("C", points=[(0, 0), (360, 0)], interpolation_mode=1)
    ic = MC_InterpolateCam()
    h.call(ic, {"Cam": cam, "Execute": True})
    h.move_master(50.0)
    ci = MC_CamIn()
    h.call(ci, {"Master": h.m, "Slave": h.s, "Cam": cam, "Execute": True, "ApplicationMode": 1,
                "SyncProfileReference": 2})
    h.until(lambda: ci.InSync or ci.Error, 2.0)
    assert ci.InSync, hex(ci.ErrorID)
    ph = MC_PhasingRelative()
    _start(h, ph, PhaseShift=10.0)
    _rejected(ph)


def test_s7_1500_new_rejected_gear_in_does_not_abort_running_gearing():
    h = H()
    h.move_master(50.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.until(lambda: g.InGear, 2.0)
    bad = MC_GearIn()
    _start(h, bad, RatioDenominator=0)
    _rejected(bad)
    h.step(2)
    assert g.InGear and g.Busy and not g.CommandAborted


def test_s7_1500_new_rejected_gear_in_pos_does_not_abort_running_gearing():
    h = H()
    h.move_master(50.0)
    g = MC_GearIn()
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.until(lambda: g.InGear, 2.0)
    bad = MC_GearInPos()
    _start(h, bad, SyncProfileReference=2)
    _rejected(bad)
    h.step(2)
    assert g.InGear and g.Busy and not g.CommandAborted


def test_s7_1500_after_unconfigured_master_error_a_valid_gear_in_is_possible_after_reset():
    from plcmotion.s7_1500 import MC_Reset
    h = H(masters=2, leading=["M1"])
    h.move_master(50.0)
    bad, good = MC_GearIn(), MC_GearIn()
    db = h.call(bad, {"Master": h.masters[1], "Slave": h.s, "Execute": True})
    h.step(2)
    assert bad.Error and h.s.ErrorWord.X14
    dg = h.call(good, {"Master": h.m, "Slave": h.s, "Execute": True})
    h.step(2)
    print("valid GearIn with ErrorWord.X14 pending:", good.outputs, int(h.s.ErrorWord), h.s.ErrorDetail.Number,
          h.s.ErrorDetail.Reaction)
    rs = MC_Reset()
    h.call(rs, {"Axis": h.s, "Execute": True})
    h.step(3)
    assert not h.s.ErrorWord.X14 and h.s.ErrorDetail.Number == 0
    dg["Execute"] = False
    h.step()
    dg["Execute"] = True
    h.until(lambda: good.InGear or good.Error, 2.0)
    assert good.InGear


def test_s7_1500_master_disable_keeps_waiting_gear_in_pos():
    h = H()
    h.move_master(100.0)
    g = MC_GearInPos()
    p = h.m.Position
    h.call(g, {"Master": h.m, "Slave": h.s, "Execute": True, "MasterSyncPosition": p + 2000.0,
               "MasterStartDistance": 100.0})
    h.step(2)
    h.en["M1"] = False
    h.run(0.5)
    assert g.Busy and not g.CommandAborted and not g.Error
