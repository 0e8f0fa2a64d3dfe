"""A positioning axis moving to a fixed end stop and clamping there (S7-Technology V4.1 §6.2.11, §4.5.7.5).

A clamping slide on a SINAMICS drive (telegram 105: torque reduction) closes a fixture whose jaw is a
fixed end stop at 80 mm.  The end stop is detected by the following error (``recognitionMode`` 106,
``followingErrorDeviation`` 2 mm); the clamping window is 0.2 mm.  The program

1. enables the axis and positions it at 20 mm (MC_MoveAbsolute),
2. moves to the end stop at 40 mm/s with a clamping torque of 0.5 N m (MC_MoveToEndPos): the jaw stops the
   slide, the following error reaches 2 mm, the setpoint is held there and the drive presses with 0.5 N m
   (InClamping),
3. raises the clamping torque to 1.0 N m with a second MC_MoveToEndPos in the same direction,
4. tries to move further towards the stop (MC_MoveAbsolute to 100 mm: refused, ErrorID 16#8056),
5. releases the fixture with MC_MoveRelative -30 mm (away from the stop).

It writes a plot of setpoint and actual position, drive torque and InClamping.

Run it with:  python examples/s7t_end_pos.py [output directory]
"""
import sys
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveRelative, MC_MoveToEndPos, MC_Power

JAW = 80.0
DS = "TypeOfAxis.NumberOfDataSets.DataSet_1.ClampingMonitoring"
SLIDE = {
    "Wizard.Telegram": 105,
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque": 3.2,
    f"{DS}.recognitionMode": 106, f"{DS}.followingErrorDeviation": 2.0, f"{DS}.positionTolerance": 0.2,
    "Plant.EndStopMaxPosition": JAW,
}


def run(out: Path) -> dict:
    ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
    slide = ctl.add_positioning_axis("Slide", SLIDE)
    power, start, clamp, harder = MC_Power(), MC_MoveAbsolute(), MC_MoveToEndPos(), MC_MoveToEndPos()
    further, release = MC_MoveAbsolute(), MC_MoveRelative()
    state = {"step": "start", "t0": 0.0}
    result: dict[str, float] = {}
    trace: dict[str, list[float]] = {k: [] for k in ("t", "setpoint", "actual", "torque", "clamping")}

    @ctl.program
    def main():
        step, now = state["step"], ctl.time
        power(Axis=slide, Enable=True)
        start(Axis=slide, Execute=step == "start" and power.Status, Position=20.0, Velocity=50.0)
        clamp(Axis=slide, Execute=step == "clamp", Direction=1, Torque=0.5, Velocity=40.0)
        harder(Axis=slide, Execute=step == "harder", Direction=1, Torque=1.0, Velocity=40.0)
        further(Axis=slide, Execute=step == "further", Position=100.0, Velocity=10.0)
        release(Axis=slide, Execute=step == "release", Distance=-30.0, Velocity=40.0)
        if step == "start" and start.Done:
            state["step"] = "clamp"
        elif step == "clamp" and clamp.InClamping:
            state["step"], state["t0"] = "hold", now
            result["clamp_torque"] = slide.drive.torque
        elif step == "hold" and now - state["t0"] > 0.5:
            state["step"] = "harder"
        elif step == "harder" and harder.InClamping and now - state["t0"] > 1.0:
            result["harder_torque"] = slide.drive.torque
            state["step"] = "further"
        elif step == "further" and further.Error:
            result["refused"] = further.ErrorID
            state["step"] = "release"
        elif step == "release" and release.Done:
            state["step"] = "idle"

    @ctl.on_post_servo
    def record(t: float) -> None:
        b, i = ctl.bank, slide.index
        for key, value in (("t", t), ("setpoint", float(b.sp_p[i])), ("actual", float(b.act_p[i])),
                           ("torque", slide.drive.torque),
                           ("clamping", float(clamp.InClamping or harder.InClamping))):
            trace[key].append(value)

    ctl.run(6.0)
    result["final"] = float(ctl.bank.act_p[slide.index])
    result["step"] = state["step"]
    plot(trace, out / "s7t_end_pos.png")
    return result


def plot(trace: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(8, 7))
    ax[0].plot(trace["t"], trace["setpoint"], label="setpoint")
    ax[0].plot(trace["t"], trace["actual"], label="actual")
    ax[0].axhline(JAW, color="grey", ls=":", label="fixed end stop")
    ax[0].set_ylabel("position [mm]")
    ax[0].legend(loc="lower right")
    ax[1].plot(trace["t"], trace["torque"])
    ax[1].set_ylabel("drive torque [N m]")
    ax[2].step(trace["t"], trace["clamping"], where="post")
    ax[2].set_ylabel("InClamping")
    ax[2].set_xlabel("time [s]")
    fig.suptitle("S7-Technology MC_MoveToEndPos: clamp with 0.5 N m, then 1.0 N m, release")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)


def main(out: Path) -> int:
    r = run(out)
    print(f"clamped with {r['clamp_torque']:.2f} N m, then {r['harder_torque']:.2f} N m; a move towards the stop: "
          f"ErrorID 16#{int(r['refused']):04X}; released to {r['final']:.1f} mm")
    print(f"plot: {out / 's7t_end_pos.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("s7t-end-pos")))
