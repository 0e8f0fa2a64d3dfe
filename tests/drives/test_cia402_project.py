"""CiA 402 drives in project files: ``[drives.<axis>]`` connects any axis to a drive on a CAN bus, with
precise configuration errors; ``plcmotion run`` drives the simulated drive over the virtual bus (CiA 402-2
modes; S7-1200 Motion Control V6 11.1.1 MC_Power, 11.1.5 MC_MoveAbsolute for the example program)."""
from __future__ import annotations

import csv
from pathlib import Path

import pytest

pytest.importorskip("canopen")
pytest.importorskip("can")

from _cia402_rig import channel  # noqa: E402
from plcmotion.cli import main  # noqa: E402
from plcmotion.drives.spec import SetpointInterface  # noqa: E402
from plcmotion.project import check_project, load_project  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

AXIS = '''
[axes.Axis_1]
"Actor.Type" = {actor}
"Actor.Interface.DriveReadyInput" = ""
"DynamicLimits.MinVelocity" = 0.0
'''


def _project(tmp_path: Path, drives: str, actor: int = 1, family: str = "") -> Path:
    head = f'[controller]\nfamily = "{family}"\n' if family else ""
    path = tmp_path / "p.toml"
    path.write_text(head + AXIS.format(actor=actor) + drives)
    return path


def test_drives_cia402_project_connects_axis(tmp_path):
    """A [drives.Axis_1] table with type = "cia402" on the virtual bus with simulate = true: the axis has a
    CANopen drive, and enabling it brings the simulated drive to OPERATION ENABLED."""
    from plcmotion.s7_1200 import MC_Power
    path = _project(tmp_path, f'''
[drives.Axis_1]
type = "cia402"
interface = "virtual"
channel = "{channel()}"
node_id = 3
mode = "csv"
simulate = true
''')
    ctl = load_project(path)
    try:
        ax = ctl.axes["Axis_1"]
        assert ax.config.drive.interface is SetpointInterface.CANOPEN
        assert ax.config.drive.link.node_id == 3 and ax.config.drive.link.mode == "csv"
        power = MC_Power()
        for _ in range(30):
            power(Axis=ax, Enable=True)
            ctl.step()
        assert power.Status and ax.drive.simulated.state == "OPERATION ENABLED"
    finally:
        ctl.close()


def test_drives_cia402_project_s7_1500_axis(tmp_path):
    """Family-neutral: an S7-1500 positioning axis connects the same way."""
    path = tmp_path / "p.toml"
    path.write_text(f'''
[controller]
family = "S7-1500"
[axes.Axis_1]
"Actor.Type" = 1
[drives.Axis_1]
type = "cia402"
channel = "{channel()}"
node_id = 4
simulate = true
''')
    ctl = load_project(path)
    try:
        assert ctl.axes["Axis_1"].config.drive.interface is SetpointInterface.CANOPEN
    finally:
        ctl.close()


BAD = [
    ('node_id = 0', "drives.Axis_1.node_id: 0 is out of range; a CANopen node id in [1, 127]"),
    ('node_id = 1.5', "drives.Axis_1.node_id: must be an integer (a CANopen node id), got 1.5"),
    ('mode = "ip"', "drives.Axis_1.mode: 'ip' is no mode of operation for an axis; one of 'csp', 'csv', 'cst', "
                    "'pp', 'pv'"),
    ('heartbeat_ms = 70000', "drives.Axis_1.heartbeat_ms: 70000 is out of range; a heartbeat time [ms] (0 = off) "
                             "in [0, 65535]"),
    ('simulate = "yes"', "drives.Axis_1.simulate: must be true or false, got 'yes'"),
    ('bus = 1', "drives.Axis_1.bus: unknown key"),
    ('eds = "missing.eds"', "drives.Axis_1.eds: no EDS file at"),
]


@pytest.mark.parametrize("line,message", BAD, ids=[b[0].split(" ")[0] for b in BAD])
def test_drives_cia402_project_errors(tmp_path, line, message):
    """Each wrong setting of a [drives] table is reported with its key, its value and what is allowed."""
    path = _project(tmp_path, f'[drives.Axis_1]\ntype = "cia402"\nchannel = "{channel()}"\n{line}\n')
    problems = check_project(path)
    assert any(message in p for p in problems), problems


def test_drives_cia402_project_structure_errors(tmp_path):
    """A [drives] table for an axis the file does not have, a kind that does not exist, two axes on one node,
    and a stepper axis (S7-1200 Actor.Type = 2: pulse output) that cannot have a CiA 402 drive."""
    ch = channel()
    path = tmp_path / "p.toml"
    path.write_text(AXIS.format(actor=1) + AXIS.format(actor=1).replace("Axis_1", "Axis_2")
                    + AXIS.format(actor=2).replace("Axis_1", "Stepper").replace("0.0", "1.0") + f'''
[drives.Axis_9]
type = "cia402"
[drives.Axis_1]
type = "ethercat"
[drives.Axis_2]
type = "cia402"
channel = "{ch}"
node_id = 2
simulate = true
[drives.Stepper]
type = "cia402"
channel = "{ch}"
node_id = 2
''')
    text = "\n".join(check_project(path))
    assert "drives.Axis_9: there is no axis \"Axis_9\" in [axes]; allowed: Axis_1, Axis_2, Stepper" in text
    assert 'drives.Axis_1.type = "ethercat": allowed: "cia402"' in text
    assert "drives.Stepper.node_id = 2: node 2 on virtual/" in text and "drives axis Axis_2 already" in text
    path.write_text(AXIS.format(actor=2).replace("0.0", "1.0") + f'[drives.Axis_1]\ntype = "cia402"\nchannel = "{channel()}"\n')
    text = "\n".join(check_project(path))
    assert "needs an axis with a drive and an encoder" in text and "stepper on a pulse output" in text


def test_drives_cia402_project_node_not_answering(tmp_path):
    """A node id with no drive behind it is reported when the project is checked, naming the node, the bus
    and the first object the master could not reach (CiA 301 SDO: no response)."""
    ch = channel()
    path = _project(tmp_path, f'[drives.Axis_1]\ntype = "cia402"\nchannel = "{ch}"\nnode_id = 42\n')
    text = "\n".join(check_project(path))
    assert f"CiA 402 drive node 42 on virtual/{ch}: 0x608F position encoder resolution: No SDO response" in text
    assert "is the drive on the bus" in text


def test_drives_cia402_cli_run_example(tmp_path):
    """plcmotion run with the example project and program: the S7-1200 slide on the simulated CiA 402 drive
    goes to 80 mm and back; the trace shows the position reaching 80 mm."""
    out = tmp_path / "trace.csv"
    code = main(["run", str(EXAMPLES / "cia402_servo.toml"), str(EXAMPLES / "cia402_servo_program.py"),
                 "--duration", "1.6", "--trace", str(out), "--quiet"])
    assert code == 0
    rows = list(csv.DictReader(out.open()))
    pos = [float(r["Slide.Position"]) for r in rows]
    assert abs(max(pos) - 80.0) <= 0.02 and pos[0] == 0.0


@pytest.mark.parametrize("family", ["S7-Technology", "Pilz"])
def test_drives_cia402_project_any_family(tmp_path, family):
    """Family-neutral: an S7-Technology axis (a real axis by default) and a Pilz drive axis connect to a
    CiA 402 drive from the project file the same way; the controller sets the node up (its position actual
    value is read over SDO) and the axis has the CANopen interface."""
    path = tmp_path / "p.toml"
    path.write_text(f'''
[controller]
family = "{family}"
servo_cycle = 0.002
[axes.Axis_1]
type = "positioning"
[drives.Axis_1]
type = "cia402"
channel = "{channel()}"
node_id = 5
simulate = true
''')
    assert check_project(path) == []
    ctl = load_project(path)
    try:
        ax = ctl.axes["Axis_1"]
        assert ax.config.drive.interface is SetpointInterface.CANOPEN and ax.drive.node_id == 5
        for _ in range(5):
            ctl.step()
        assert ax.drive.communication_ok and ax.drive.state is not None
    finally:
        ctl.close()


def test_drives_cia402_cli_run_pilz_example(tmp_path, capsys):
    """plcmotion run with the Pilz example: the drive homes itself (CiA 402-2 homing method 34), which makes
    the Pilz axis "In reference" (I86, Pilz V6.5 §1.7.7) before it moves; MC_MoveAbsolute then reaches 200 mm
    within the position window I22 (0.2 mm) and the run ends without an error."""
    out = tmp_path / "trace.csv"
    code = main(["run", str(EXAMPLES / "cia402_pilz.toml"), str(EXAMPLES / "cia402_pilz_program.py"),
                 "--duration", "1.2", "--trace", str(out)])
    assert code == 0
    text = capsys.readouterr().out
    assert "Conveyor: enabled" in text and "homed True" in text and "no error" in text
    rows = list(csv.DictReader(out.open()))
    pos = [float(r["Conveyor.I96"]) for r in rows]
    homed = [float(r["Conveyor.I86"]) for r in rows]
    assert abs(max(pos) - 200.0) <= 0.2
    first_move = next(k for k, p in enumerate(pos) if p > 1.0 and k > 0 and homed[k])
    assert all(h == 1.0 for h in homed[first_move:])
