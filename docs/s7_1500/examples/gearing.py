"""Gearing: MC_GearIn follows at once, MC_GearInPos reaches exact synchronous positions (S7-1500T V5 §4)."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_GearIn, MC_GearInPos, MC_MoveVelocity, MC_Power

ctl = Controller(family="S7-1500T")
master = ctl.add_positioning_axis("Master", {"VirtualAxis": {"Mode": 1}})
a = ctl.add_synchronous_axis("A", {"VirtualAxis": {"Mode": 1}}, leading_values=["Master"])
b = ctl.add_synchronous_axis("B", {"VirtualAxis": {"Mode": 1}}, leading_values=["Master"])
power = [MC_Power() for _ in range(3)]
move, gear_in, gear_pos = MC_MoveVelocity(), MC_GearIn(), MC_GearInPos()


@ctl.program
def main():
    for p, axis in zip(power, (master, a, b)):
        p(Axis=axis, Enable=True)
    move(Axis=master, Execute=power[0].Status, Velocity=100.0)
    gear_in(Master=master, Slave=a, Execute=power[1].Status, RatioNumerator=2, RatioDenominator=1)
    gear_pos(Master=master, Slave=b, Execute=power[2].Status, RatioNumerator=1, RatioDenominator=2,
             MasterSyncPosition=300.0, SlaveSyncPosition=50.0, SyncProfileReference=1, MasterStartDistance=100.0)


ctl.run_until(lambda: gear_in.InGear and gear_pos.InSync, timeout=10.0)
assert abs(b.Position - (50.0 + 0.5 * (master.Position - 300.0))) < 1e-6
print(f"t = {ctl.time:.3f} s: master {master.Position:.2f}, A {a.Position:.2f} (InGear, v = {a.Velocity:.1f}), "
      f"B {b.Position:.3f} (InSync)")
