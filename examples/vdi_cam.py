"""Design a cam from VDI 2143 motion laws, check its characteristic values, export it and plot it.

A feeder lifts a part 40 mm (rise), holds it (dwell), lowers it (return) and rests (dwell) during one
machine revolution of 360°.  The rise uses a modified sine (low acceleration), the return a 3-4-5
polynomial; the dwells are lines.  The script prints the segments the cam TO takes and the
characteristic values, writes a point list (CSV) and a plot of position, velocity, acceleration and jerk
at 60 machine revolutions per minute.

Run it with:  python examples/vdi_cam.py [output directory]
"""
import sys
from pathlib import Path

from plcmotion.cams import CamBuilder, export_points, plot_cam


def feeder_cam() -> CamBuilder:
    b = CamBuilder(interpolation_mode=1)
    b.line(0.0, 60.0, y0=0.0, y1=0.0)                       # rest
    b.transition("vdi", "modified_sine")                    # rise 0 -> 40 mm over 60..150°
    b.line(150.0, 210.0, y0=40.0, y1=40.0)                  # hold
    b.transition("vdi", "polynomial5")                      # return 40 -> 0 mm over 210..300°
    b.line(300.0, 360.0, y0=0.0, y1=0.0)                    # rest
    return b


def main(out: Path) -> int:
    out.mkdir(parents=True, exist_ok=True)
    definition = feeder_cam().build()
    stats = definition.statistics()
    print(f"cam: {stats['points']} points, {stats['segments']} segments (a cam TO holds 1000 / 50)")
    for info in definition.transitions:
        c = info.characteristics
        values = "  ".join(f"{k} {v:.3f}" for k, v in c.as_dict().items()) if c is not None else "no stroke"
        print(f"  {info.label}: {info.law} ({info.task}) {info.x0:g}..{info.x1:g}: {values}")
    export_points(definition, out / "feeder_cam.csv", n=361)          # both ends: a 1 degree grid
    plot_cam(definition, out / "feeder_cam.png", leading_velocity=360.0, title="feeder cam (VDI 2143)")
    print(f"point list: {out / 'feeder_cam.csv'}   plot: {out / 'feeder_cam.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("vdi-cam")))
