"""The S7-1500T synchronous operation examples do what their descriptions say (S7-1500T V5 §4.2, §5)."""
import runpy
from pathlib import Path

import numpy as np
import pytest

from plcmotion import load_project
from plcmotion.cli import load_program

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_docs_flying_saw_cuts_with_the_carriage_synchronous_to_the_bar_s4_2():
    ctl = load_project(EXAMPLES / "flying_saw.toml")
    load_program(ctl, str(EXAMPLES / "flying_saw_program.py"))
    bar, carriage = ctl.axes["Material"], ctl.axes["Carriage"]
    cutting = []

    @ctl.program
    def watch():
        if ctl.outputs["Q0.0"]:
            # blade down: the carriage moves exactly with the bar, mark under the blade
            cutting.append((bar.Position, carriage.Position, carriage.Velocity, bar.Velocity,
                            carriage.StatusWord.Synchronous))
    ctl.run(10.0)
    assert ctl.saw["pieces"] == 3
    rows = np.array([r[:4] for r in cutting])
    assert np.allclose(rows[:, 1] - rows[:, 0], 400.0 - 500.0, atol=1e-6)
    assert np.allclose(rows[:, 2], rows[:, 3])
    assert all(r[4] for r in cutting)
    assert not carriage.alarms and carriage.StatusPositioning.FollowingError < 20.0


def test_docs_rotary_knife_runs_with_the_web_in_the_cut_zone_s5_2():
    ctl = load_project(EXAMPLES / "rotary_knife.toml")
    load_program(ctl, str(EXAMPLES / "rotary_knife_program.py"))
    web, knife = ctl.axes["Web"], ctl.axes["Knife"]
    namespace = runpy.run_path(str(EXAMPLES / "rotary_knife_program.py"))
    fmt, circumference = namespace["FORMAT"], namespace["CIRCUMFERENCE"]
    cuts = []

    @ctl.program
    def watch():
        if knife.StatusWord.Synchronous:
            u = (web.Position % fmt) / fmt * 360.0            # format degrees
            if abs(u - 180.0) < 25.0:
                surface = knife.Velocity / 360.0 * circumference
                cuts.append((surface, web.Velocity, knife.Position))
    ctl.run(5.0)
    assert len(cuts) > 20
    for surface, web_speed, angle in cuts:
        assert surface == pytest.approx(web_speed, rel=1e-9)    # blade and web at the same speed
    assert not knife.alarms


def test_docs_vdi_cam_example_writes_points_and_plot(tmp_path, capsys):
    ns = runpy.run_path(str(EXAMPLES / "vdi_cam.py"))
    assert ns["main"](tmp_path) == 0
    assert (tmp_path / "feeder_cam.csv").read_text().count("\n") > 360
    assert (tmp_path / "feeder_cam.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "modified_sine" in capsys.readouterr().out
