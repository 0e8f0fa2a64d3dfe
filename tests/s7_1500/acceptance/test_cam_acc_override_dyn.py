"""§5.5 'Synchronous operation override': configured limits apply again, the active dynamics are
transitioned (smoothed); no velocity step."""
from plcmotion.s7_1500 import MC_Halt

from _cam_h import Camming


def test_s7_1500_halt_from_fast_camming_is_smooth():
    steep = [(0, 0), (180, 1800), (360, 0)]
    h = Camming(cams={"Cam": steep})
    halt = MC_Halt()
    hin = {"Execute": False}
    h.extra_steps.append(lambda: halt(Axis=h.rig.slave, **hin))
    h.cam_in(SyncProfileReference=2, ApplicationMode=1, MasterSyncPosition=20.0)
    h.move(360.0)
    h.run(0.05)
    vs = []
    idx = h.rig.slave.index
    hin["Execute"] = True
    # sample the slave velocity setpoint every application cycle
    for _ in range(2000):
        h.run(0.004)
        vs.append(float(h.ctl.bank.sp_v[idx]))
        if halt.Done:
            break
    assert h.ci[0].CommandAborted
    dv = [abs(b - a) for a, b in zip(vs, vs[1:])]
    dec = h.rig.slave.tag("DynamicDefaults.Deceleration")
    assert max(dv) <= max(dec, 1.0) * 0.004 * 1.5 + 1e-6, (max(dv), vs[:5])
    assert halt.Done
