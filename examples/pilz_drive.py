"""A Pilz drive axis (family "Pilz", Pilz motion commands V6.5): reference it, position it, run a velocity,
stop - once with the PLCopen-style blocks and once through the command register directly.

Run: ``python examples/pilz_drive.py``
"""
from plcmotion import Controller
from plcmotion.pilz import MC_Home, MC_MoveAbsolute, MC_MoveVelocity, MC_Stop

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("Conveyor", {
    "I10": 500.0, "I11": 5000.0, "I16": 200000.0, "I22": 0.2, "I87": 0.02,       # limits, window, dwell
    "A586": 34, "I33": 20.0, "I34": 0.0,                                          # CiA 402 homing method 34
    "Plant.ZeroMarkDistance": 10.0, "Plant.ZeroMarkOffset": 4.0, "Plant.InitialPosition": 12.5})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)

dyn = dict(Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
home = MC_Home(Axis=axis)
move = MC_MoveAbsolute(Axis=axis, Position=250.0, Velocity=400.0, **dyn)
run = MC_MoveVelocity(Axis=axis, Velocity=-150.0, **dyn)
stop = MC_Stop(Axis=axis, Deceleration=3000.0, Jerk=100000.0)
phase = {"step": "home"}


@ctl.program
def sequence():
    step = phase["step"]
    if step == "done":
        return                      # the blocks leave the register to the direct writes below
    home(Execute=step == "home")
    move(Execute=step == "move")
    run(Execute=step == "run")
    stop(Execute=step == "stop")
    if step == "home" and home.Done:
        phase["step"] = "move"
    elif step == "move" and move.Done:
        phase["step"] = "run"
    elif step == "run" and run.InVelocity:
        phase["step"] = "stop"
    elif step == "stop" and stop.Done:
        phase["step"] = "done"


ctl.run_until(lambda: phase["step"] == "done", timeout=10.0)
print(f"blocks: homed (I86 = {axis.status.I86}), at {axis.status.I96:.2f} after the stop, t = {ctl.time:.3f} s")
assert axis.status.I86 and axis.status.E07 == 0.0

# the same drive through its command register: MC_MoveRelative by 100 with a 50 % override
reg = axis.registers
reg.I402 = False
ctl.step()
reg.I230 = 50.0
reg.I401, reg.I403, reg.I404, reg.I405, reg.I406, reg.I407 = 2, 100.0, 400.0, 2000.0, 2000.0, 100000.0
start = axis.status.I96
reg.I402 = True
ctl.step()
ctl.run_until(lambda: axis.status.I92 or axis.status.I91, timeout=5.0)
print(f"register: MC_MoveRelative from {start:.2f} to {axis.status.I96:.2f}, I91 = {axis.status.I91}")
assert not axis.status.I91 and abs(axis.status.I96 - (axis.status.I80 + 100.0)) < 1e-6
