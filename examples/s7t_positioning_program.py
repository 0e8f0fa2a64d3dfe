"""User program for s7t_positioning.toml: S7-Technology instructions on a positioning and a speed axis.

OB1 (``@ctl.program``, every application cycle):
1. MC_Power enables both axes; the table by its technology object, the conveyor by the number of its
   technology DB (``Axis=11``), as an S7-300 program passes it.
2. The conveyor runs at 1000 mm/s (MC_MoveVelocity); at 4 s a second MC_MoveVelocity slows it to 400 mm/s.
3. The table moves to 150 mm and, started in the same cycle with Mode 1 (append), on to 300 mm: it stops at
   150 mm, then goes on.  The appended command sets DoneFlag 1, which toggles ``MCDevice.DoneFlag[1]``
   when it is done.
4. Then a move to 450 mm at 300 mm/s with a move to 550 mm at 100 mm/s overlaid (Mode 2): the table does not
   stop at 450 mm, it passes it at the lower of the two velocities.  Finally back to 0 at full speed.

The program reads the table's technology DB only when its ``UpdateCounter`` has changed (a new snapshot of
the DB update, S7-Technology V4.1 §7.11), and an OB65 program, which runs after every DB update, keeps the
largest following error.

Run it with:  plcmotion run examples/s7t_positioning.toml examples/s7t_positioning_program.py --duration 7
"""
from plcmotion import s7t
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveVelocity, MC_Power


def setup(ctl):
    table = ctl.axes["Table"]
    device = s7t.device(ctl)                         # the integrated technology: DBs, MCDevice DB, OB65
    power_table, power_conveyor = MC_Power(), MC_Power()
    run_fast, run_slow = MC_MoveVelocity(), MC_MoveVelocity()
    to_150, then_300 = MC_MoveAbsolute(), MC_MoveAbsolute()
    to_450, over_550 = MC_MoveAbsolute(), MC_MoveAbsolute()
    back = MC_MoveAbsolute()
    state = {"step": "power", "counter": None, "snapshots": 0, "max_following_error": 0.0, "done_flag": False,
             "passed_450": None, "stopped_at_150": False}

    @ctl.program
    def main():
        power_table(Axis=table, Enable=True)
        power_conveyor(Axis=11, Enable=True)         # technology DB 11: the conveyor
        run_fast(Axis=11, Execute=power_conveyor.Status, Velocity=1000.0)
        run_slow(Axis=11, Execute=ctl.time >= 4.0, Velocity=400.0)

        step = state["step"]
        to_150(Axis=table, Execute=step == "append", Position=150.0, Velocity=300.0)
        then_300(Axis=table, Execute=step == "append", Position=300.0, Velocity=300.0, Mode=1, DoneFlag=1)
        to_450(Axis=table, Execute=step == "overlay", Position=450.0, Velocity=300.0)
        over_550(Axis=table, Execute=step == "overlay", Position=550.0, Velocity=100.0, Mode=2)
        back(Axis=table, Execute=step == "back", Position=0.0, Velocity=400.0)

        db = table.db
        if db.UpdateCounter != state["counter"]:     # a new snapshot of the technology DB
            state["counter"] = db.UpdateCounter
            state["snapshots"] += 1
            if step == "append" and to_150.Done and db.Statusword.Standstill and abs(db.ActualPosition - 150.0) < 1.0:
                state["stopped_at_150"] = True       # appended: the table stood at 150 mm before going on
            if step == "overlay" and state["passed_450"] is None and db.CommandPosition >= 450.0:
                state["passed_450"] = db.CommandVelocity
        if step == "power" and power_table.Status:
            state["step"] = "append"
        elif step == "append" and then_300.Done:
            state["step"] = "overlay"
        elif step == "overlay" and over_550.Done:
            state["step"] = "back"
        elif step == "back" and back.Done:
            state["step"] = "done"
        state["done_flag"] = device.mcdevice.DoneFlag[1]

    @s7t.ob65(ctl)
    def after_db_update():
        state["max_following_error"] = max(state["max_following_error"], abs(table.db.FollowingError))

    ctl.s7t_example = state                          # for tests and curious users
