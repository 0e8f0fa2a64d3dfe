"""MC_ActivateTO: deactivate a disabled axis (Status 2, Statusword.ToDeactivated), then activate it again
(S7-Technology V4.1 §6.7.2)."""
from plcmotion import Controller
from plcmotion.s7t import MC_ActivateTO

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


ctl.run(0.05)
assert change.Done and seen[-1] == 2 and axis.db.Statusword.ToDeactivated
mode[0] = 1
change(Execute=False)
ctl.run(0.05)
assert change.Done and seen[-1] == 1 and not axis.db.Statusword.ToDeactivated
print("deactivated (Status 2) and activated again (Status 1)")
