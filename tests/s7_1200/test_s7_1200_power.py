"""MC_Power and MC_Reset of the S7-1200 V6 (§11.1.1, §11.1.2).

Manual rules checked here (S7-1200 Motion Control V6.0):
  §11.1.1.1 enable with/without "Drive ready", Status/Busy timing, disabling (Status FALSE only after
            standstill), StopMode 0 / 1 / 2, auto re-enable after acknowledging an error while Enable stayed
            TRUE, Status FALSE -> no commands except MC_Reset, PTO axis not homed when disabled
  §9.3      one MC_Power instance per axis; StopMode taken over while Enable = TRUE
  §11.1.3.1 "Resetting the Homed status": PTO on disabling, not for incremental encoders
  §11.1.2.1 MC_Reset: Done + StatusBits.Error FALSE = acknowledged
  §12.8     16#8201, 16#8200, 16#8405/16#0011, 16#8412/16#0011, 16#800D
"""
from __future__ import annotations

import pytest

from _s7_1200_rig import (MC_Home, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_Reset, Rig,
                          calls_with)


def moving_rig(velocity: float = 50.0, **kw) -> Rig:
    """Enabled PTO axis moving at ``velocity`` with MC_MoveVelocity 'mv' (Execute held)."""
    rig = Rig(**kw)
    rig.add("mv", MC_MoveVelocity(), Velocity=velocity, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 2000, f"velocity {velocity}")
    return rig


def disable_and_watch(rig: Rig, max_scans: int = 2000):
    """Enable := FALSE; returns (snaps until MC_Power.Status is FALSE, time of the first standstill call)."""
    rig.power.Enable = False
    snaps = rig.run_scans_while(lambda s: s["power"]["Status"], max_scans)
    still = [s for s in snaps if s.vel == 0.0]
    return snaps, (still[0].t - snaps[0].t) if still else None


# ----------------------------------------------------------------------------------------------------------
# enabling
def test_s7_1200_11_1_1_enable_pto_without_ready_signal_immediately():
    """§11.1.1.1 'Enabling an axis without configured drive interface': Status and StatusBits.Enable TRUE
    at once; Busy TRUE while MC_Power is active."""
    rig = Rig(enable=False)
    assert not rig.axis.StatusBits.Enable
    rig.power.Enable = True
    s = rig.scan()
    assert s["power"]["Status"] and s["power"]["Busy"] and not s["power"]["Error"]
    assert rig.axis.StatusBits.Enable
    assert all(x["power"]["Status"] and x["power"]["Busy"] for x in rig.scans(10))


def test_s7_1200_11_1_1_enable_waits_for_drive_ready():
    """§11.1.1.1 'Enabling an axis with configured drive interface' / Status TRUE: 'the status does not
    change to TRUE until the signal Drive ready is pending'; Busy TRUE from the enable; commands are not
    accepted while Status is FALSE (16#8200)."""
    rig = Rig(actor=1, enable=False, extra={"Plant": {"ReadyDelay": 0.05}})
    rig.power.Enable = True
    rig.add("mr", MC_MoveRelative(), Distance=5.0, Velocity=10.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["power"]["Status"], 100)
    waiting = snaps[:-1]
    assert waiting and all(s["power"]["Busy"] and not s["power"]["Status"] for s in waiting)
    assert all(s.t < 0.05 for s in waiting), "Status TRUE too late"
    assert snaps[-1].t <= 0.05 + 0.004 + 1e-9, "Status must be TRUE once the drive is ready"
    assert waiting[0]["mr"]["Error"] and waiting[0]["mr"]["ErrorID"] == 0x8200
    assert rig.axis.StatusBits.Enable and rig.axis.StatusBits.DriveReady


# ----------------------------------------------------------------------------------------------------------
# disabling, StopMode
def test_s7_1200_11_1_1_disable_at_standstill():
    """§11.1.1.1 'Disabling an axis': axis at standstill, Enable := FALSE -> Busy, Status and
    StatusBits.Enable FALSE."""
    rig = Rig()
    rig.power.Enable = False
    snaps = rig.scans(3)
    assert any(not s["power"]["Status"] for s in snaps[:2])
    assert all(not s["power"]["Busy"] and not s["power"]["Status"] and not s["power"]["Error"] for s in snaps[1:])
    assert not rig.axis.StatusBits.Enable


@pytest.mark.parametrize("actor,min_v", [(2, 1.0), (1, 0.0)], ids=["PTO", "PROFIdrive"])
def test_s7_1200_11_1_1_stopmode0_emergency_stop_status_false_only_at_standstill(actor, min_v):
    """§11.1.1.1 StopMode 0 'Emergency stop': brakes with the configured emergency deceleration, disabled
    after reaching standstill; 'Upon disabling, the status does not change to FALSE until the axis reaches
    a standstill' (Busy likewise, function chart ①③)."""
    rig = moving_rig(50.0, actor=actor, dec=10.0, emergency=100.0)
    snaps, t_stop = disable_and_watch(rig)
    end = snaps[-1]
    braking = [s for s in snaps if s.vel != 0.0]
    assert len(braking) > 50
    assert all(s["power"]["Status"] and s["power"]["Busy"] for s in braking), "Status/Busy fell before standstill"
    assert end.vel == 0.0 and not end["power"]["Busy"]
    # (50 - start/stop velocity) / emergency deceleration 100 (§5.4.4.4); the configured deceleration: ~5 s
    assert t_stop == pytest.approx((50.0 - min_v) / 100.0, abs=0.02)
    assert end.n - [s for s in snaps if s.vel == 0.0][0].n <= 1
    assert not rig.axis.StatusBits.Enable


@pytest.mark.parametrize("velocity,max_time", [(50.0, 0.030)], ids=["5kHz"])
def test_s7_1200_11_1_1_stopmode1_pto_immediate_stop_high_frequency(velocity, max_time):
    """§11.1.1.1 StopMode 1 'Immediate stop', PTO: pulse output stopped with a frequency-dependent
    deceleration - output frequency >= 100 Hz: max. 30 ms (50 mm/s x 100 pulses/mm = 5 kHz)."""
    rig = moving_rig(velocity, dec=10.0, emergency=100.0)
    rig.power.StopMode = 1
    snaps, t_stop = disable_and_watch(rig)
    assert t_stop is not None and t_stop <= max_time + 0.004 + 1e-9, f"stopped after {t_stop} s"
    assert all(s["power"]["Status"] for s in snaps if s.vel != 0.0)
    assert not rig.axis.StatusBits.Enable and rig.axis.Velocity == 0.0


def test_s7_1200_11_1_1_stopmode1_pto_immediate_stop_low_frequency():
    """§11.1.1.1 StopMode 1, PTO, output frequency < 100 Hz: deceleration 30 ms up to max. 1.5 s
    (0.5 mm/s x 100 pulses/mm = 50 Hz)."""
    rig = moving_rig(0.5, min_v=0.1, acc=100.0, dec=0.1, emergency=0.5)
    rig.power.StopMode = 1
    snaps, t_stop = disable_and_watch(rig)
    assert t_stop is not None and 0.030 - 0.004 <= t_stop <= 1.5 + 0.004, f"stopped after {t_stop} s"
    assert not rig.axis.StatusBits.Enable


def test_s7_1200_11_1_1_stopmode2_respects_jerk_stopmode0_does_not():
    """§11.1.1.1 StopMode 2 'Emergency stop with jerk control': emergency deceleration with the configured
    jerk; StopMode 0: emergency deceleration only (§12.8 'Stop with emergency stop ramp ... without any
    jerk limit').  Jerk 500, emergency deceleration 100: the jerk-limited stop lasts ~0.2 s longer."""
    times = {}
    for mode in (0, 2):
        rig = moving_rig(50.0, dec=10.0, emergency=100.0, jerk=500.0)
        rig.power.StopMode = mode
        snaps, t_stop = disable_and_watch(rig)
        times[mode] = t_stop
        assert not rig.axis.StatusBits.Enable
    assert times[0] == pytest.approx(0.49, abs=0.02), "StopMode 0 must brake without jerk limit"
    assert times[2] == pytest.approx(0.49 + 100.0 / 500.0, abs=0.04), "StopMode 2 must respect the jerk"


def test_s7_1200_9_3_stopmode_taken_over_while_enable_true():
    """§9.3: 'StopMode' of MC_Power is an exception to the rising-edge rule - a change is applied while
    Enable = TRUE.  Enabled with StopMode 0, changed to 1 while enabled -> immediate stop (<= 30 ms)
    instead of the 0.49 s emergency ramp."""
    rig = moving_rig(50.0, dec=10.0, emergency=100.0)
    assert rig.power.StopMode == 0
    rig.power.StopMode = 1
    rig.scans(2)
    snaps, t_stop = disable_and_watch(rig)
    assert t_stop <= 0.030 + 0.004 + 1e-9, f"stopped after {t_stop} s: StopMode 1 not taken over"


def test_s7_1200_11_1_1_disabled_axis_accepts_only_mc_reset():
    """§11.1.1.1 Status FALSE: 'The axis does not execute Motion Control commands and does not accept any
    new commands (exception: MC_Reset command)' - 16#8200 'Axis is not enabled' (§12.8)."""
    rig = Rig(enable=False)
    mr = rig.add("mr", MC_MoveRelative(), Distance=5.0, Velocity=10.0, Execute=True)
    jog = rig.add("jog", MC_MoveJog(), Velocity=10.0, JogForward=True)
    home = rig.add("home", MC_Home(), Mode=0, Position=5.0, Execute=True)
    rst = rig.add("rst", MC_Reset(), Execute=True)
    snaps = rig.scans(3)
    s = snaps[-1]
    assert s["mr"]["Error"] and (s["mr"]["ErrorID"], s["mr"]["ErrorInfo"]) == (0x8200, 0x0001)
    assert s["jog"]["Error"] and s["jog"]["ErrorID"] == 0x8200
    assert s["home"]["Error"] and s["home"]["ErrorID"] == 0x8200, "§11.1.3.1 requirement: axis enabled"
    assert not rig.axis.StatusBits.HomingDone
    home.Execute = False
    assert calls_with(snaps, "rst", "Done") and not calls_with(snaps, "rst", "Error")
    assert rig.axis.Position == 0.0 and rig.axis.Velocity == 0.0
    mr.Execute = rst.Execute = False
    jog.JogForward = False


# ----------------------------------------------------------------------------------------------------------
# one MC_Power per axis, invalid modes
def test_s7_1200_9_3_second_mc_power_instance_8201():
    """§9.3 'each axis must be called with a separate call of MC_Power with a separate instance DB';
    §12.8 16#8201/16#0001 'Axis has already been enabled by another MC_Power instance'.  The axis stays
    enabled by the first instance (operating error without axis stop, §9.6)."""
    rig = Rig()
    rig.add("mv", MC_MoveVelocity(), Velocity=30.0, Execute=True)
    p2 = rig.add("p2", MC_Power(), Enable=True)
    snaps = rig.scans(5)
    s = snaps[-1]
    assert s["p2"]["Error"] and (s["p2"]["ErrorID"], s["p2"]["ErrorInfo"]) == (0x8201, 0x0001)
    assert not s["p2"]["Status"]
    assert s["power"]["Status"] and not s["power"]["Error"]
    assert rig.axis.StatusBits.Enable and s["mv"]["Busy"]
    p2.Enable = False
    assert rig.scan()["power"]["Status"], "the second instance must not disable the axis"


@pytest.mark.parametrize("stop_mode", [3, -1])
def test_s7_1200_12_8_invalid_stopmode_8405(stop_mode):
    """§12.8 16#8405/16#0011 'Invalid value at parameter StopMode' - remedy 'Correct the selection value;
    enable the axis again': the axis is not enabled."""
    rig = Rig(enable=False)
    rig.power.StopMode = stop_mode
    rig.power.Enable = True
    snaps = rig.scans(3)
    s = snaps[-1]
    assert s["power"]["Error"] and (s["power"]["ErrorID"], s["power"]["ErrorInfo"]) == (0x8405, 0x0011)
    assert not s["power"]["Status"] and not rig.axis.StatusBits.Enable
    rig.power.StopMode = 0                              # corrected: the axis can be enabled again
    rig.power.Enable = False
    rig.scan()
    rig.power.Enable = True
    s = rig.scan_until(lambda s: s["power"]["Status"], 10, "enabled after correcting StopMode")
    assert not s["power"]["Error"]


def test_s7_1200_12_8_invalid_startmode_8412():
    """§12.8 16#8412/16#0011 'Value at StartMode parameter invalid' (PROFIdrive axis; StartMode 0/1 only) -
    remedy 'enable the axis again': the axis is not enabled."""
    rig = Rig(actor=1, enable=False)
    rig.power.StartMode = 2
    rig.power.Enable = True
    snaps = rig.scans(5)
    s = snaps[-1]
    assert s["power"]["Error"] and (s["power"]["ErrorID"], s["power"]["ErrorInfo"]) == (0x8412, 0x0011)
    assert not s["power"]["Status"] and not rig.axis.StatusBits.Enable


# ----------------------------------------------------------------------------------------------------------
# error -> acknowledge -> automatic re-enable
def _following_error_rig() -> Rig:
    """PROFIdrive axis with a sluggish drive and a tight following error limit; moving it causes 16#800D
    (error reaction 'Remove enable', §12.8)."""
    return Rig(actor=1, extra={"Plant": {"SpeedTimeConstant": 0.5, "ReadyDelay": 0.02, "OffRampTime": 0.05},
                               "FollowingError": {"MinValue": 0.5, "MaxValue": 1.0}})


def _trip_following_error(rig: Rig):
    rig.add("mv", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    s = rig.scan_until(lambda s: s["power"]["Error"], 500, "following error")
    assert (s["power"]["ErrorID"], s["power"]["ErrorInfo"]) == (0x800D, 0x0001)
    assert rig.axis.ErrorBits.FollowingErrorFault and rig.axis.StatusBits.Error
    rig.fbs["mv"].Execute = False
    snaps = rig.scans(50)
    assert all(not x["power"]["Status"] for x in snaps), "the error removes the enable"
    assert not rig.axis.StatusBits.Enable
    assert all(x["power"]["Error"] and x["power"]["ErrorID"] == 0x800D for x in snaps), \
        "§9.6: the pending operating error is shown at MC_Power"


def test_s7_1200_11_1_1_auto_reenable_after_acknowledge_while_enable_true():
    """§11.1.1.1 note and function chart ②: 'If the axis is switched off due to an error, it will be
    enabled again automatically after the error has been eliminated and acknowledged. This requires that
    Enable has retained the value TRUE.'  §11.1.2.1: Done TRUE and StatusBits.Error FALSE."""
    rig = _following_error_rig()
    _trip_following_error(rig)
    rig.add("rst", MC_Reset(), Execute=True)
    s = rig.scan_until(lambda s: s["rst"]["Done"], 5, "MC_Reset Done")
    assert not s["rst"]["Error"]
    assert not rig.axis.StatusBits.Error
    s = rig.scan_until(lambda s: s["power"]["Status"], 50, "automatic re-enable")
    assert not s["power"]["Error"] and s["power"]["Busy"] and rig.axis.StatusBits.Enable
    mr = rig.add("mr", MC_MoveRelative(), Distance=0.2, Velocity=0.1, Execute=True)
    assert rig.scan()["mr"]["Busy"] or mr.Done, "the re-enabled axis accepts commands"


def test_s7_1200_11_1_1_no_reenable_when_enable_was_reset():
    """§11.1.1.1 note: the automatic re-enable requires Enable to have stayed TRUE; with Enable FALSE the
    axis stays disabled after the acknowledgement."""
    rig = _following_error_rig()
    _trip_following_error(rig)
    rig.power.Enable = False
    rig.scans(2)
    rig.add("rst", MC_Reset(), Execute=True)
    rig.scan_until(lambda s: s["rst"]["Done"], 5, "MC_Reset Done")
    snaps = rig.scans(30)
    assert all(not s["power"]["Status"] and not s["power"]["Busy"] and not s["power"]["Error"] for s in snaps)
    assert not rig.axis.StatusBits.Enable


def test_s7_1200_11_1_2_reset_acknowledges_sw_limit_error():
    """§11.1.2.1: MC_Reset acknowledges an 'operating error with axis stop' (16#8002 SW limit, §12.8);
    afterwards StatusBits.Error FALSE, MC_Power without error, and the axis can be moved out of the limit
    in the negative direction."""
    rig = Rig(sw=(-100.0, 10.0))
    rig.home(0.0)
    rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    rig.scan_until(lambda s: s["power"]["Error"], 1000, "SW limit error")
    assert rig.power.ErrorID == 0x8002 and rig.axis.ErrorBits.SWLimit
    assert rig.axis.StatusBits.Enable, "16#8002/16#000E does not remove the enable"
    rst = rig.add("rst", MC_Reset(), Execute=True)
    s = rig.scan_until(lambda s: s["rst"]["Done"], 5, "MC_Reset Done")
    s = rig.scan()
    assert not rig.axis.StatusBits.Error and not s["power"]["Error"] and s["power"]["Status"]
    rst.Execute = False
    rig.add("back", MC_MoveRelative(), Distance=-5.0, Velocity=10.0, Execute=True)
    end = rig.scan_until(lambda s: s["back"]["Done"], 1000, "moved out of the limit")
    assert end.pos == pytest.approx(5.0, abs=1e-6)


# ----------------------------------------------------------------------------------------------------------
# homing status and disabling
def test_s7_1200_11_1_3_pto_axis_loses_homing_done_when_disabled():
    """§11.1.3.1 'Resetting the Homed status', PTO: 'Disabling of axis by the MC_Power instruction';
    §11.1.1.1 Status FALSE: 'For drive connection via PTO: The axis is not homed'."""
    rig = Rig()
    rig.home(25.0)
    assert rig.axis.StatusBits.HomingDone
    rig.power.Enable = False
    rig.scan_until(lambda s: not s["power"]["Status"] and not s["power"]["Busy"], 10, "disabled")
    rig.scan()
    assert not rig.axis.StatusBits.HomingDone
    rig.power.Enable = True
    rig.scan_until(lambda s: s["power"]["Status"], 10, "enabled again")
    assert not rig.axis.StatusBits.HomingDone, "re-enabling does not restore the homed status"


def test_s7_1200_11_1_3_incremental_encoder_axis_keeps_homing_done_when_disabled():
    """§11.1.3.1 'Resetting the Homed status' for technology objects with incremental actual values does not
    list disabling: a PROFIdrive axis stays homed through MC_Power Enable FALSE/TRUE."""
    rig = Rig(actor=1)
    rig.home(25.0)
    rig.power.Enable = False
    rig.scan_until(lambda s: not s["power"]["Status"] and not s["power"]["Busy"], 50, "disabled")
    rig.scans(2)
    assert rig.axis.StatusBits.HomingDone
    rig.power.Enable = True
    rig.scan_until(lambda s: s["power"]["Status"], 50, "enabled again")
    assert rig.axis.StatusBits.HomingDone
    assert rig.axis.Position == pytest.approx(25.0, abs=0.01)


def test_s7_1200_11_1_2_reset_restart_only_when_disabled():
    """§11.1.2.1 Restart = TRUE: 'The command can only be executed when the axis is disabled' - on an
    enabled axis MC_Reset ends with Error 16#820A (§12.8 'Restart of axis not possible'), latched while
    Execute TRUE (§9.5.2); on the disabled axis it ends with Done."""
    rig = Rig()
    rst = rig.add("rst", MC_Reset(), Restart=True, Execute=True)
    snaps = rig.scans(4)
    assert all(not s["rst"]["Busy"] for s in snaps[1:])
    assert all(s["rst"]["Error"] and s["rst"]["ErrorID"] == 0x820A for s in snaps[1:])
    assert snaps[-1]["power"]["Status"], "a rejected restart leaves the axis enabled"
    rst.Execute = False
    assert not rig.scan()["rst"]["Error"]
    rig.power.Enable = False
    rig.scan_until(lambda s: not s["power"]["Status"] and not s["power"]["Busy"], 10, "disabled")
    rst.Execute = True
    snaps = rig.scans(3)
    assert calls_with(snaps, "rst", "Done") and not calls_with(snaps, "rst", "Error")
