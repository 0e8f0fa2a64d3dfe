"""Camming: interpolate a cam, couple cyclically, read values back (S7-1500T V5 §5, §9.2)."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_CamIn, MC_GetCamFollowingValue, MC_InterpolateCam, MC_MoveVelocity, MC_Power

ctl = Controller(family="S7-1500T")
master = ctl.add_positioning_axis("Master", {"VirtualAxis": {"Mode": 1}})
slave = ctl.add_synchronous_axis("Slave", {"VirtualAxis": {"Mode": 1}}, leading_values=["Master"])
cam = ctl.add_cam("Cam", [(0, 0), (90, 40), (180, 100), (270, 40), (360, 0)], interpolation_mode=1,
                  boundary_conditions=1)
pm, ps = MC_Power(), MC_Power()
interpolate, move, cam_in, read = MC_InterpolateCam(), MC_MoveVelocity(), MC_CamIn(), MC_GetCamFollowingValue()


@ctl.program
def main():
    pm(Axis=master, Enable=True)
    ps(Axis=slave, Enable=True)
    interpolate(Cam=cam, Execute=True)
    move(Axis=master, Execute=pm.Status, Velocity=360.0)
    cam_in(Master=master, Slave=slave, Cam=cam, Execute=ps.Status and interpolate.Done, ApplicationMode=1,
           MasterOffset=200.0, SyncProfileReference=1, MasterStartDistance=100.0)
    read(Cam=cam, Execute=interpolate.Done, LeadingValue=180.0)


ctl.run_until(lambda: cam_in.InSync and read.Done, timeout=10.0)
ctl.run(0.5)
print(f"InSync at master {master.Position:.1f}, slave {slave.Position:.3f}; f(180) = {read.Value:.1f}, "
      f"f'(180) = {read.FirstDerivative:.4f}; cam in use: {cam.StatusWord.Control}")
assert read.Value == 100.0
