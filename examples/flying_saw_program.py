"""User program for flying_saw.toml: cut the running bar every time its mark passes the saw.

Sequence per piece: wait for the mark with MC_GearInPos (synchronization over 250 mm of bar travel, so
that the carriage is at 400 mm with the bar's speed when the mark is at 500 mm) -> blade down while the
carriage runs synchronously for 150 mm -> blade up, MC_MoveAbsolute back to park (this ends the
synchronous operation) -> next piece.

Run it with:  plcmotion run examples/flying_saw.toml examples/flying_saw_program.py --duration 10
"""
from plcmotion.s7_1500 import MC_GearInPos, MC_Home, MC_MoveAbsolute, MC_MoveVelocity, MC_Power

BAR_SPEED = 400.0          # mm/s
MARK = 500.0               # bar position of the cut mark [mm] within a piece (modulo 1200)
CUT_AT = 400.0             # carriage position where the blade meets the mark [mm]
CUT_LENGTH = 150.0         # bar travel while the blade is down [mm]
PARK = 100.0               # carriage park position [mm]


def setup(ctl):
    bar, carriage = ctl.axes["Material"], ctl.axes["Carriage"]
    p_bar, p_car = MC_Power(), MC_Power()
    home, run_bar = MC_Home(), MC_MoveVelocity()
    sync, back = MC_GearInPos(), MC_MoveAbsolute()
    state = {"step": "home", "pieces": 0}
    ctl.outputs["Q0.0"] = False                      # blade down

    @ctl.program
    def main():
        p_bar(Axis=bar, Enable=True)
        p_car(Axis=carriage, Enable=True)
        run_bar(Axis=bar, Execute=p_bar.Status, Velocity=BAR_SPEED)
        step = state["step"]
        home(Axis=carriage, Execute=step == "home" and p_car.Status, Mode=0, Position=PARK)
        sync(Master=bar, Slave=carriage, Execute=step in ("wait", "cut"), RatioNumerator=1,
             MasterSyncPosition=MARK, SlaveSyncPosition=CUT_AT, SyncProfileReference=1,
             MasterStartDistance=250.0)
        back(Axis=carriage, Execute=step == "return", Position=PARK)
        if step == "home" and home.Done:
            state["step"] = "wait"
        elif step == "wait" and sync.InSync:
            ctl.outputs["Q0.0"] = True               # blade down: cutting
            state["step"] = "cut"
        elif step == "cut" and bar.Position >= MARK + CUT_LENGTH:
            ctl.outputs["Q0.0"] = False
            state["pieces"] += 1
            state["step"] = "return"
        elif step == "return" and back.Done:
            state["step"] = "wait"

    ctl.saw = state                                  # for tests and curious users
