"""MC_ActivateTO: deactivate a disabled axis (Status 2, Statusword.ToDeactivated), then activate it again
(S7-Technology V4.1 §6.7.2).
Writes docs/img/s7t/MC_ActivateTO.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ActivateTO
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis1", {"Wizard": {"Virtual": 1}})
change, status = MC_ActivateTO(), MC_ActivateTO()
mode, seen = [2], []


@ctl.program
def ob1():
    change(Axis=axis.db_number, Execute=True, Mode=mode[0])
    status(Axis=axis.db_number, Execute=not status.Done, Mode=0)
    if status.Done:
        seen.append(status.Status)


trace = Trace(ctl, {
    "change.Busy": lambda: change.Busy, "change.Done": lambda: change.Done,
    "Axis1.Statusword.ToDeactivated": lambda: bool(axis.db.Statusword.ToDeactivated),
    "status.Status": lambda: status.Status,
}).start()
ctl.run(0.05)
assert change.Done and seen[-1] == 2 and axis.db.Statusword.ToDeactivated
mode[0] = 1
change(Execute=False)
ctl.run(0.05)
trace.stop()
assert change.Done and seen[-1] == 1 and not axis.db.Statusword.ToDeactivated
print("deactivated (Status 2) and activated again (Status 1)")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ActivateTO.png", title="MC_ActivateTO: deactivate (Mode 2), then activate (Mode 1)")
print(f"wrote {out / 'MC_ActivateTO.png'}")
