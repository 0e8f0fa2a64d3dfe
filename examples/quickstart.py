"""The README example: enable, set the reference point and move a PROFIdrive servo axis to 100 mm."""
from plcmotion import Controller
from plcmotion.s7_1200 import MC_Home, MC_MoveAbsolute, MC_Power

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 500.0},
    "DynamicDefaults": {"Acceleration": 1000.0, "Deceleration": 1000.0, "Jerk": 10000.0},
})
power, home, move = MC_Power(), MC_Home(), MC_MoveAbsolute()


@ctl.program
def main():
    power(Axis=axis, Enable=True)
    home(Axis=axis, Execute=power.Status, Mode=0, Position=0.0)
    move(Axis=axis, Execute=home.Done, Position=100.0, Velocity=50.0)


ctl.run_until(lambda: move.Done, timeout=10.0)
print(f"t = {ctl.time:.3f} s  ActualPosition = {axis.ActualPosition:.4f}  "
      f"HomingDone = {axis.StatusBits.HomingDone}  ErrorID = 16#{move.ErrorID:04X}")
