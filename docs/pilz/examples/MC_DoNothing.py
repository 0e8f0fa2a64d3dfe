"""MC_DoNothing (command 0): no status, no motion ID switch - the default of the command selection."""
from plcmotion import Controller

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"I30": 5})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
reg = axis.registers
reg.I400, reg.I401, reg.I402 = 7, 6, True          # MC_Home (define home) with motion ID 7
ctl.run(0.01)
before = (axis.status.I82, axis.status.I92, axis.status.I89)
reg.I402 = False
ctl.step()
reg.I400, reg.I401, reg.I402 = 9, 0, True          # MC_DoNothing with motion ID 9
ctl.run(0.01)
print(f"I82, I92, I89 before {before}, after {(axis.status.I82, axis.status.I92, axis.status.I89)}")
assert (axis.status.I82, axis.status.I92, axis.status.I89) == before
