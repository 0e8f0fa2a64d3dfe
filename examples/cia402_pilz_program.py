"""Pilz program for examples/cia402_pilz.toml: the CiA 402 drive homes itself (homing mode 6, method 34:
the first index pulse in the positive direction - at 14 mm from the start at 12.5 mm - reads 0 mm), which
makes the axis "In reference" (I86); then it is enabled and moves between 0 and 200 mm with MC_MoveAbsolute."""
from plcmotion.pilz import MC_MoveAbsolute

conveyor = axes["Conveyor"]                    # noqa: F821 - given by plcmotion run
move = MC_MoveAbsolute(Axis=conveyor, Velocity=400.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
state = {"step": "home", "target": 200.0}


@ctl.program                                   # noqa: F821
def main() -> None:
    s = state
    if s["step"] == "home":
        conveyor.drive.home_in_drive(34, offset=0.0, zero_speed=20.0, acceleration=1000.0)
        s["step"] = "homing"
    elif s["step"] == "homing" and conveyor.drive.homing == "attained":
        conveyor.enable()
        s["step"] = "enabling"
    elif s["step"] == "enabling" and conveyor.status.I89 == 2:     # motion core at standstill: ready
        s["step"] = "move"
    elif s["step"] == "move":
        move(Execute=True, Position=s["target"])
        if move.Done:
            s["target"] = 0.0 if s["target"] else 200.0
            move(Execute=False)
