"""S7-1200 program for examples/cia402_servo.toml: enable the slide on its CiA 402 drive, set the home
position, then move back and forth between 0 and 80 mm."""
from plcmotion.s7_1200 import MC_Home, MC_MoveAbsolute, MC_Power

slide = axes["Slide"]                          # noqa: F821 - given by plcmotion run
power, home, move = MC_Power(), MC_Home(), MC_MoveAbsolute()
target = 80.0


@ctl.program                                   # noqa: F821
def main() -> None:
    global target
    power(Axis=slide, Enable=True)
    home(Axis=slide, Execute=power.Status, Mode=0, Position=0.0)    # direct homing: here is 0 mm
    move(Axis=slide, Execute=home.Done, Position=target, Velocity=150.0)
    if move.Done:
        target = 0.0 if target else 80.0
        move(Axis=slide, Execute=False)
