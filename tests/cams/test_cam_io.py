"""Point-list export/import of cams (S7-1500T V5 §6.2.7) and the cam plot (§6.2.2, §6.2.3.1)."""
import math

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.cams import (
    CamBuilder,
    PointListError,
    export_points,
    import_points,
    plot_cam,
)
from plcmotion.kernel.cam import LINEAR, interpolate


def example():
    b = CamBuilder()
    b.line(0, 60, y0=0, slope=0).transition("vdi", "modified_sine").line(120, 180, y0=100, slope=0)
    b.transition("vdi", "polynomial").sine(200, 260, 5, offset=50, phase0=math.pi / 2, period=60)
    b.point_group([(280, 45), (300, 20), (330, 5)]).point(360, 0)
    return b.build()


def test_cams_point_list_round_trip_of_1000_points_s6_2_7(tmp_path):
    d = example()
    curve = d.curve()
    path = export_points(d, tmp_path / "cam.csv", n=1000)
    pts = import_points(path)
    assert len(pts) == 1000
    xs = np.array([p[0] for p in pts])
    assert (xs[0], xs[-1]) == (curve.start, curve.end)
    again = interpolate(pts, [], LINEAR)
    assert np.array_equal(again.value(xs), curve.value(xs))          # 17 significant digits: exact


def test_cams_export_header_columns_and_derivatives_s6_2_7(tmp_path):
    d = example()
    curve = d.curve()
    path = export_points(curve, tmp_path / "cam.txt", delimiter="\t")
    lines = path.read_text().splitlines()
    assert lines[0] == "leading\tfollowing\tvelocity\tacceleration\tjerk"
    assert len(lines) == 1 + 360                                          # default number of points
    rows = np.array([[float(v) for v in line.split("\t")] for line in lines[1:]])
    f, v, a, j = curve.evaluate(rows[:, 0], 3)
    assert np.array_equal(rows[:, 1:], np.column_stack([f, v, a, j]))
    path = export_points(d, tmp_path / "pos.csv", n=5, derivatives=("jerk",))
    assert path.read_text().splitlines()[0] == "leading,following,jerk"
    assert len(import_points(path)) == 5


def test_cams_export_number_of_points_delimiter_and_curves_are_checked_s6_2_7(tmp_path):
    d = example()
    assert export_points(d, tmp_path / "empty.csv", n=0).read_text() == (
        "leading,following,velocity,acceleration,jerk\n")
    assert len(export_points(d, tmp_path / "one.csv", n=1).read_text().splitlines()) == 2
    for kw, msg in (({"n": 100_001}, "0..100000"), ({"n": 2.5}, "integer"), ({"delimiter": ";"}, "comma"),
                    ({"derivatives": ("speed",)}, "velocity, acceleration, jerk")):
        with pytest.raises(ValueError, match=msg):
            export_points(d, tmp_path / "x.csv", **kw)
    cam = Controller(family="S7-1500T").add_cam("Cam1")
    with pytest.raises(ValueError, match="not interpolated"):
        export_points(cam, tmp_path / "x.csv")
    with pytest.raises(TypeError):
        export_points([(0, 0)], tmp_path / "x.csv")


def test_cams_import_tolerates_header_comments_blank_lines_and_both_delimiters_s6_2_7(tmp_path):
    text = ("\ufeff# exported by hand\r\n"
            "leading\tfollowing\r\n"
            "\r\n"
            "0\t0.5\r\n"
            "  # a comment line\n"
            "1.5 , 2e-1,\n"                    # comma, spaces, trailing delimiter
            "3\t-4.25\n"
            "\n")
    path = tmp_path / "hand.csv"
    path.write_text(text, encoding="utf-8")
    assert import_points(path) == [(0.0, 0.5), (1.5, 0.2), (3.0, -4.25)]
    path.write_text("0,0\n10,5\n")                                          # no header
    assert import_points(path) == [(0.0, 0.0), (10.0, 5.0)]


@pytest.mark.parametrize("text,line,message", [
    ("x,y\n0,0\n1,abc\n", 3, "'abc' is not a number"),
    ("x,y\n0;0\n", 2, "comma or tab"),
    ("0\t1,5\n", 1, "decimal comma"),
    ("0,0\n1\n", 2, "a leading and a following value"),
    ("0,0,0\n1,1\n", 2, "2 fields, the file's rows have 3"),
    ("0,0\n0,1\n", 2, "does not increase"),
    ("0,nan\n", 1, "not a finite number"),
    ("0,0\nx,y\n", 2, "'x' is not a number"),
    ("", None, "no points"),
    ("# nothing\nleading,following\n", None, "no points"),
])
def test_cams_import_of_malformed_files_names_the_file_and_line_s6_2_7(tmp_path, text, line, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(PointListError, match=message) as exc:
        import_points(path)
    assert exc.value.line == line and exc.value.path == str(path)
    assert str(exc.value).startswith(f"{path}, line {line}:" if line else f"{path}:")


def test_cams_import_of_a_binary_file_is_refused_s6_2_7(tmp_path):
    path = tmp_path / "cam.bin"
    path.write_bytes(b"\x00\xff\xfe\x80\x81")
    with pytest.raises(PointListError, match="not a text file"):
        import_points(path)


def test_cams_plot_cam_writes_a_png_with_four_axes_s6_2_2(tmp_path):
    d = example()
    fig = plot_cam(d, tmp_path / "cam.png", n=500, leading_velocity=360.0, title="Cam1")
    data = (tmp_path / "cam.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    axes = fig.axes
    assert len(axes) == 4
    x, v = axes[1].lines[0].get_data()
    f1 = d.curve().evaluate(x, 1)[1]
    assert v == pytest.approx(f1 * 360.0)                                  # time derivative: f' * xdot
    _, jerk = axes[3].lines[0].get_data()
    assert jerk == pytest.approx(d.curve().evaluate(x, 3)[3] * 360.0 ** 3)
    # a bare curve and an interpolated cam TO plot too (no file)
    assert len(plot_cam(d.curve(), scale_x=2.0).axes) == 4
    ctl = Controller(family="S7-1500T")
    cam = d.apply(ctl.add_cam("Cam1"))
    cam.curve = d.curve()                                                  # as after MC_InterpolateCam
    fig = plot_cam(cam)
    marks = [ln for ln in fig.axes[0].lines if ln.get_marker() == "o"]
    assert len(marks) == 1 and list(marks[0].get_xdata()) == [p[0] for p in cam.valid_points()]
    bounds = {s.xmin for s in cam.valid_segments()} | {s.xmax for s in cam.valid_segments()}
    assert len(fig.axes[0].lines) == 2 + len(bounds)                       # curve, points, boundaries


def test_cams_a_point_list_that_never_ends_is_refused_issue8_defect7():
    """Review of issue 8: the size limit looked at st_size only (0 for a device): a cam csv naming /dev/zero
    (allowed with --allow-outside-paths) was read until memory ran out."""
    import os
    import threading

    from plcmotion.cams.io import PointListError, import_points

    if not os.path.exists("/dev/zero"):
        pytest.skip("needs /dev/zero")
    outcome: list = []

    def read():
        try:
            import_points("/dev/zero")
        except PointListError as exc:
            outcome.append(str(exc))
    worker = threading.Thread(target=read, daemon=True)
    worker.start()
    worker.join(10.0)
    assert outcome and "/dev/zero" in outcome[0] and "at most" in outcome[0], outcome
