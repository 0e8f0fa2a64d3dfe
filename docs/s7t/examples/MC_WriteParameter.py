"""MC_WriteParameter: the velocity override (parameter 4142, effective immediately) halves the speed of a
running motion; the leadscrew pitch (1100, effective after a restart) answers with warning 16#0020 and
Statusword.RequestRestart (S7-Technology V4.1 §6.7.5)."""
from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_WriteParameter

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis1", {"Wizard": {"Virtual": 1}})
power, move, override, pitch = MC_Power(), MC_MoveVelocity(), MC_WriteParameter(), MC_WriteParameter()


@ctl.program
def ob1():
    power(Axis=axis, Enable=True)
    move(Axis=axis, Execute=power.Status, Velocity=100.0)
    override(Axis=axis, Execute=ctl.time >= 2.0, ParameterNumber=4142, Value=50.0)
    pitch(Axis=axis, Execute=ctl.time >= 2.0, ParameterNumber=1100, Value=5.0)


ctl.run(3.0)
assert override.Done and abs(axis.db.CommandVelocity - 50.0) < 1e-9
assert pitch.Done and pitch.ErrorID == 0x0020 and axis.db.Statusword.RequestRestart
print(f"velocity with 50 % override: {axis.db.CommandVelocity}, leadscrew pitch: warning 16#{pitch.ErrorID:04X}")
