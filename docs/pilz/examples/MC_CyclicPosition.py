"""MC_CyclicPosition (command 10): cyclic set positions 0 ... I01 on an endless axis; turns counted inside."""
from plcmotion import Controller
from plcmotion.pilz import MC_CyclicPosition

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.002)
axis = ctl.add_positioning_axis("X", {"I00": 1, "I01": 360.0, "I10": 2000.0})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
cyc = MC_CyclicPosition(Axis=axis)


@ctl.program
def program():
    cyc(Execute=True, Position=(720.0 * ctl.time) % 360.0)     # 2 turns per second, wrapped


ctl.run(1.0)
print(f"unwrapped set position {axis.status.I96:.1f}, velocity {axis.status.E07:.1f}")
assert axis.status.I96 > 700.0 and abs(axis.status.E07 - 720.0) < 1.0
