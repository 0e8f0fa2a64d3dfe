"""EndOfProfile semantics (§9.1.5: 'The end of the cam has been reached')."""
from _cam_h import Camming


def _first_pulse_vs_insync(spr, **inp):
    h = Camming()
    h.move(360.0)
    mo = h.m + 200.0
    h.cam_in(MasterOffset=mo, SyncProfileReference=spr, ApplicationMode=1, **inp)
    h.until(lambda: h.ci[0].InSync, timeout=10.0)
    h.run(1.5)
    log = h.rig.log
    pulses = [r["m"] - mo for r in log if r["EndOfProfile0"]]
    return pulses


def test_s7_1500_cyclic_spr1_no_end_of_profile_at_sync_position():
    """Synchronizing in advance onto the cam start (MSP 0): the first EndOfProfile belongs to the cam end
    (master at MasterOffset + 360), not to the synchronous position at the cam start."""
    pulses = _first_pulse_vs_insync(1, MasterStartDistance=100.0, MasterSyncPosition=0.0)
    assert pulses and pulses[0] >= 360.0 - 1e-6, f"EndOfProfile at cam position {pulses[0]:.2f}"


def test_s7_1500_cyclic_spr0_no_end_of_profile_at_sync_position():
    pulses = _first_pulse_vs_insync(0, MasterSyncPosition=0.0, Velocity=2000.0, Acceleration=20000.0,
                                    Deceleration=20000.0)
    assert pulses and pulses[0] >= 360.0 - 1e-6, f"EndOfProfile at cam position {pulses[0]:.2f}"
