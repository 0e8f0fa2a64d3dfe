"""MC_ActivateDPSlave: deactivate the drive's DP slave (diagnostic address 1023) after its axis was
deactivated; MCDevice.StationLifeList[2] shows it, and activating it again takes a few command slices
(S7-Technology V4.1 §6.7.3).
Writes docs/img/s7t/MC_ActivateDPSlave.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ActivateDPSlave, MC_ActivateTO
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis1", {})
to, slave, status = MC_ActivateTO(), MC_ActivateDPSlave(), MC_ActivateDPSlave()
mode, seen = [2], []


@ctl.program
def ob1():
    to(Axis=axis.db_number, Execute=True, Mode=2)
    slave(DiagnosticAddress=1023, Execute=to.Done, Mode=mode[0])
    status(DiagnosticAddress=1023, Execute=not status.Done, Mode=0)
    if status.Done:
        seen.append(status.Status)


trace = Trace(ctl, {
    "to.Done": lambda: to.Done, "slave.Busy": lambda: slave.Busy, "slave.Done": lambda: slave.Done,
    "status.Status": lambda: status.Status,
    "StationLifeList[2]": lambda: ctl.extension.mcdevice.StationLifeList[2],
}).start()
ctl.run(0.1)
life = ctl.extension.mcdevice.StationLifeList
assert slave.Done and seen[-1] == 2 and life[2] == 0
mode[0] = 1
slave(Execute=False)
ctl.run(0.1)
trace.stop()
assert seen[-1] == 1 and ctl.extension.mcdevice.StationLifeList[2] == 1
print("DP slave 2 deactivated (StationLifeList[2] = 0) and active again")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ActivateDPSlave.png", title="MC_ActivateDPSlave: deactivate DP slave 1023 (Mode 2), then activate (Mode 1)")
print(f"wrote {out / 'MC_ActivateDPSlave.png'}")
