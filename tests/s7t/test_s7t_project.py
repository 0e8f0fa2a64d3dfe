"""S7-Technology objects declared in a project file (S7-Technology V4.1 §2.5.3, §3.1, §9.4 tag names)."""
from __future__ import annotations

import pytest

import plcmotion
from plcmotion.project import ProjectError

PROJECT = '''
[controller]
family = "S7-Technology"
servo_cycle = 0.002
app_cycle = 0.004

[axes.Table]
type = "positioning"
DBNumber = 10
"TypeOfAxis.MaxVelocity.maximum" = 500.0
Wizard = { Virtual = 1 }

[axes.Fan]
type = "positioning"
Wizard.Technology = 0
Wizard.Telegram = 1

[axes.Follower]
type = "synchronous"
leading_values = ["Table"]
'''


def test_s7t_project_file_declares_the_axes(tmp_path):
    """S7-Technology V4.1 §3.1: a speed-controlled, a positioning and a synchronization axis from a project
    file, with their technology DB numbers (DB10 as declared, the others assigned)."""
    path = tmp_path / "machine.toml"
    path.write_text(PROJECT, encoding="utf-8")
    ctl = plcmotion.load_project(str(path))
    table, fan, follower = ctl.axes["Table"], ctl.axes["Fan"], ctl.axes["Follower"]
    assert table.db_number == 10 and ctl.extension.db(10) is table.db
    assert table.technology_name == "virtual positioning axis"
    assert fan.technology_name == "speed-controlled axis" and follower.technology_name == "synchronization axis"
    assert table.config.limits.max_velocity == 500.0


def test_s7t_project_file_errors_name_the_tag(tmp_path):
    """S7-Technology V4.1 §9.4: a value outside the range of the parameter list names its tag."""
    path = tmp_path / "machine.toml"
    path.write_text(PROJECT.replace("500.0", "-5.0"), encoding="utf-8")
    with pytest.raises(ProjectError, match="TypeOfAxis.MaxVelocity.maximum"):
        plcmotion.load_project(str(path))
