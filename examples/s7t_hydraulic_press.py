"""A hydraulic press axis with pressure limiting (S7-Technology V4.1 §3.1.4, §4.6, §6.2.1, §6.2.13).

A differential cylinder (piston 20 cm², rod side 10 cm², 100 bar supply) on a P/Q valve moves the press
ram; the P/Q valve limits the cylinder force to 8 kN (``Drive.ForceLimit``: pressure limiting), so the
ram cannot press harder than that whatever the controller asks.  The workpiece lies at 300 mm (a fixed
end stop of the simulated machine).  The program

1. enables the axis (MC_Power, StopMode 3 with QOutputValue 0 %: on disabling the valve output ramps to 0 %),
2. activates the measured valve profile, cam disk DB20 with a dead band of +-4 % (MC_SetCharacteristic),
3. approaches rapidly to 290 mm (MC_MoveAbsolute),
4. presses: MC_MoveVelocity at 20 mm/s without position control; the ram stops on the workpiece and the
   force rises to the 8 kN limit, held for 1 s,
5. ends the pressing with MC_MoveVelocity Velocity 0.0, still without position control (the setpoint
   velocity goes back to 0 at the stop, so the positioning that follows starts from standstill),
6. retracts to 100 mm (MC_MoveAbsolute) and disables the axis.

It writes a plot of position, valve output, cylinder force and chamber pressures.

Run it with:  python examples/s7t_hydraulic_press.py [output directory]
"""
import sys
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveVelocity, MC_Power, MC_SetCharacteristic, add_cam_disk

FORCE_LIMIT = 8000.0          # N
WORKPIECE = 300.0             # mm

PRESS = {
    "Wizard.DriveTechnology": 2,                      # hydraulic axis on a P/Q valve
    "Drive.ForceLimit": FORCE_LIMIT,
    "Drive.ValveReferenceVelocity": 400.0,
    "Drive.ValveProfile1": 20,                        # cam disk DB20 is a valve profile of this axis
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "TypeOfAxis.MaxVelocity.maximum": 300.0,
    "TypeOfAxis.NumberOfDataSets.DataSet_1.DynamicFollowing.maxPositionTolerance": 50.0,
    "userdefaultdynamics.positiveaccel": 1000.0, "userdefaultdynamics.negativeaccel": 1000.0,
    "Plant.EndStopMaxPosition": WORKPIECE, "Plant.Cylinder.StrokeMax": 400.0,
    "Plant.Cylinder.ValveOverlap": 4.0,              # the real valve's dead band the profile compensates
}
#: the valve profile as measured: output % -> velocity mm/s, flat (dead band) within +-4 %
PROFILE = [(-100.0, -640.0), (-4.0, 0.0), (4.0, 0.0), (100.0, 390.0)]


def run(out: Path) -> dict:
    ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
    ram = ctl.add_positioning_axis("Ram", PRESS)
    add_cam_disk(ctl, "ValveProfile", PROFILE, db_number=20)
    power, profile = MC_Power(), MC_SetCharacteristic()
    approach, press, release, retract = MC_MoveAbsolute(), MC_MoveVelocity(), MC_MoveVelocity(), MC_MoveAbsolute()
    state = {"step": "enable", "t0": 0.0, "enable": True}
    trace: dict[str, list[float]] = {k: [] for k in ("t", "position", "output", "force", "pa", "pb")}
    summary: dict[str, float] = {}

    @ctl.program
    def main():
        step, now = state["step"], ctl.time
        power(Axis=ram, Enable=state["enable"], StopMode=3, QOutputValue=0.0)
        profile(Axis=ram, CamTable=20, Execute=step == "profile")
        approach(Axis=ram, Execute=step == "approach", Position=WORKPIECE - 10.0, Velocity=200.0)
        press(Axis=ram, Execute=step == "press", Velocity=20.0, PositionControl=False)
        release(Axis=ram, Execute=step == "release", Velocity=0.0, PositionControl=False)
        retract(Axis=ram, Execute=step == "retract", Position=100.0, Velocity=200.0)
        if step == "enable" and power.Status:
            state["step"] = "profile"
        elif step == "profile" and profile.Done:
            state["step"] = "approach"
        elif step == "approach" and approach.Done:
            state["step"], state["t0"] = "press", now
        elif step == "press" and now - state["t0"] > 2.0:
            summary["press_force"] = ram.drive.force
            summary["press_position"] = ram.drive.mechanical_position()
            state["step"] = "release"
        elif step == "release" and release.InVelocity:
            state["step"] = "retract"
        elif step == "retract" and retract.Done:
            state["step"], state["enable"] = "off", False

    @ctl.on_post_servo
    def record(t: float) -> None:
        d = ram.drive
        pa, pb = d.pressures
        for key, value in (("t", t), ("position", d.mechanical_position()), ("output", d.output_percent),
                           ("force", d.force / 1000.0), ("pa", pa), ("pb", pb)):
            trace[key].append(value)

    ctl.run(8.0)
    summary["final_output"] = ram.drive.output_percent
    summary["final_position"] = ram.drive.mechanical_position()
    summary["step"] = state["step"]
    plot(trace, out / "s7t_hydraulic_press.png")
    return summary


def plot(trace: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(4, 1, sharex=True, figsize=(8, 9))
    ax[0].plot(trace["t"], trace["position"])
    ax[0].axhline(WORKPIECE, color="grey", ls=":", label="workpiece")
    ax[0].set_ylabel("ram [mm]")
    ax[0].legend(loc="lower right")
    ax[1].plot(trace["t"], trace["output"])
    ax[1].set_ylabel("valve output [%]")
    ax[2].plot(trace["t"], trace["force"])
    ax[2].axhline(FORCE_LIMIT / 1000.0, color="grey", ls=":", label="force limit (P/Q valve)")
    ax[2].set_ylabel("force [kN]")
    ax[2].legend(loc="upper left")
    ax[3].plot(trace["t"], trace["pa"], label="chamber A")
    ax[3].plot(trace["t"], trace["pb"], label="chamber B")
    ax[3].set_ylabel("pressure [bar]")
    ax[3].set_xlabel("time [s]")
    ax[3].legend(loc="upper left")
    fig.suptitle("S7-Technology hydraulic press: approach, press at the force limit, retract")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)


def main(out: Path) -> int:
    s = run(out)
    print(f"pressed at {s['press_position']:.2f} mm with {s['press_force']:.0f} N (limit {FORCE_LIMIT:.0f} N); "
          f"after retract and disable: {s['final_position']:.1f} mm, output {s['final_output']:.1f} %")
    print(f"plot: {out / 's7t_hydraulic_press.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("s7t-press")))
