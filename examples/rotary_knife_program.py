"""User program for rotary_knife.toml: build the knife cam for the format, interpolate it and cut.

The cam maps one format of web travel (0..360 "format degrees") to one drum revolution (0..360°).
Around the cut (format degrees 150..210) the drum surface runs with the web: the slope there is
format length / circumference.  Polynomial transitions (VDI 2143, velocity and acceleration
continuous) connect the cut zone with the boundaries, where the drum has its mean speed.  MC_CamIn
runs the cam cyclically and appending (the drum keeps turning), with MasterScaling = format / 360.

Run it with:  plcmotion run examples/rotary_knife.toml examples/rotary_knife_program.py --duration 6
"""
from plcmotion.cams import CamBuilder
from plcmotion.s7_1500 import MC_CamIn, MC_InterpolateCam, MC_MoveVelocity, MC_Power

FORMAT = 800.0            # mm of web per cut
CIRCUMFERENCE = 600.0     # mm, one blade on the drum
WEB_SPEED = 1000.0        # mm/s
CUT_ZONE = 30.0           # half width of the synchronous zone [format degrees]


def knife_cam(format_length: float, circumference: float) -> CamBuilder:
    k = format_length / circumference           # drum degrees per format degree with the web's speed
    b = CamBuilder(interpolation_mode=1, boundary_conditions=1)
    b.point(0.0, 0.0, v=1.0, a=0.0)
    b.transition("vdi", "polynomial", continuity="acceleration")
    b.line(180.0 - CUT_ZONE, 180.0 + CUT_ZONE, y0=180.0 - k * CUT_ZONE, slope=k)
    b.transition("vdi", "polynomial", continuity="acceleration")
    b.point(360.0, 360.0, v=1.0, a=0.0)
    return b


def setup(ctl):
    web, knife = ctl.axes["Web"], ctl.axes["Knife"]
    cam = ctl.cams["KnifeCam"]
    knife_cam(FORMAT, CIRCUMFERENCE).build().apply(cam)
    p_web, p_knife = MC_Power(), MC_Power()
    run_web, interpolate, cam_in = MC_MoveVelocity(), MC_InterpolateCam(), MC_CamIn()

    @ctl.program
    def main():
        p_web(Axis=web, Enable=True)
        p_knife(Axis=knife, Enable=True)
        interpolate(Cam=cam, Execute=True)
        run_web(Axis=web, Execute=p_web.Status, Velocity=WEB_SPEED)
        cam_in(Master=web, Slave=knife, Cam=cam, Execute=p_knife.Status and interpolate.Done,
               ApplicationMode=2, MasterScaling=FORMAT / 360.0, SyncProfileReference=1,
               MasterStartDistance=FORMAT / 2, MasterOffset=FORMAT, SyncDirection=1)
