"""The simulated CiA 402 drive on its own, checked by masters that are not plcmotion's: canopen's
``BaseNode402`` (state machine, profile position mode) and a plain RemoteNode with SDO and SYNC (homing
mode, EDS objects).  CiA 402-2 (state machine, modes pp and hm, homing methods 19, 35, 37), CiA 301
(SDO, SYNC, PDO, NMT)."""
from __future__ import annotations

import time

import pytest

canopen = pytest.importorskip("canopen")
pytest.importorskip("can")

from canopen.profiles.p402 import BaseNode402  # noqa: E402

from _cia402_rig import channel  # noqa: E402
from plcmotion.drives.cia402 import EDS_PATH  # noqa: E402
from plcmotion.drives.cia402.drive_core import MotorSpec  # noqa: E402
from plcmotion.drives.cia402.homing import SwitchPlant  # noqa: E402
from plcmotion.drives.cia402.simulated import start_simulated  # noqa: E402


@pytest.fixture
def bus():
    """(simulated drive factory, master network) on a fresh virtual channel."""
    name = channel()
    nets = []

    def drive(node_id: int = 5, **motor):
        sim, net = start_simulated("virtual", name, node_id, motor=MotorSpec(**motor))
        nets.append(net)
        return sim
    master = canopen.Network()
    master.NOTIFIER_CYCLE = 0.05
    master.connect(interface="virtual", channel=name)
    nets.append(master)
    yield drive, master
    for net in nets:
        net.disconnect()


def test_drives_cia402_eds_objects():
    """The shipped EDS describes a CiA 402 servo: device type 0x00020192 (profile 402, servo drive), the
    402 objects with their CiA 402-2 data types and PDO mapping, 4 RPDOs and 4 TPDOs, heartbeat 0x1017."""
    od = canopen.import_od(EDS_PATH, 5)
    from canopen import objectdictionary as t
    expect = {0x6040: (t.UNSIGNED16, True), 0x6041: (t.UNSIGNED16, True), 0x6060: (t.INTEGER8, True),
              0x6061: (t.INTEGER8, True), 0x6064: (t.INTEGER32, True), 0x606C: (t.INTEGER32, True),
              0x607A: (t.INTEGER32, True), 0x60FF: (t.INTEGER32, True), 0x6071: (t.INTEGER16, True),
              0x6077: (t.INTEGER16, True), 0x6081: (t.UNSIGNED32, True), 0x6083: (t.UNSIGNED32, False),
              0x6084: (t.UNSIGNED32, False), 0x6098: (t.INTEGER8, False), 0x607C: (t.INTEGER32, False),
              0x609A: (t.UNSIGNED32, False), 0x1017: (t.UNSIGNED16, False)}
    for index, (dtype, mappable) in expect.items():
        assert (od[index].data_type, od[index].pdo_mappable) == (dtype, mappable), hex(index)
    assert od[0x1000].default == 0x00020192
    assert od[0x6099][1].data_type == od[0x6099][2].data_type == t.UNSIGNED32
    assert od[0x60C2][1].data_type == t.UNSIGNED8 and od[0x60C2][2].data_type == t.INTEGER8
    for n in range(4):
        assert od[0x1400 + n][1].default == 0x200 + 0x100 * n + 5
        assert od[0x1800 + n][1].default == 0x180 + 0x100 * n + 5
        assert 0x1600 + n in od and 0x1A00 + n in od


def test_drives_cia402_basenode402_profile_position(bus):
    """canopen's own CiA 402 master (BaseNode402) reads the drive's PDO configuration, brings it to
    OPERATION ENABLED, switches to PROFILED POSITION, starts a move with the new-set-point bit and reads the
    position back: the drive arrives at the target (statusword bit 10 target reached)."""
    drive, master = bus
    sim = drive(5)
    node = BaseNode402(5, EDS_PATH)
    master.add_node(node)
    # BaseNode402's waits are wall-clock: generous bounds for a loaded test machine (its logic is unchanged)
    node.sdo.RESPONSE_TIMEOUT = 2.0
    node.TIMEOUT_SWITCH_STATE_FINAL = node.TIMEOUT_SWITCH_STATE_SINGLE = 5.0
    node.TIMEOUT_SWITCH_OP_MODE = node.TIMEOUT_CHECK_TPDO = 2.0
    node.nmt.state = "PRE-OPERATIONAL"
    node.setup_402_state_machine()
    node.nmt.state = "OPERATIONAL"
    master.sync.start(0.002)                # the drive's clock: 1 ms of drive time per SYNC
    try:
        node.state = "OPERATION ENABLED"
        assert node.state == "OPERATION ENABLED" and sim.state == "OPERATION ENABLED"
        node.op_mode = "PROFILED POSITION"
        assert node.op_mode == "PROFILED POSITION"
        node.sdo[0x6081].raw = 400_000          # inc/s
        node.sdo[0x6083].raw = node.sdo[0x6084].raw = 4_000_000
        node.sdo[0x607A].raw = 50_000
        node.controlword = 0x1F                 # enable operation + new set-point
        deadline = time.monotonic() + 5.0
        while not node.sdo[0x6041].raw & 0x1000:          # set-point acknowledge
            assert time.monotonic() < deadline
        node.controlword = 0x0F
        while not node.sdo[0x6041].raw & 0x0400:          # target reached
            assert time.monotonic() < deadline, node.sdo[0x6064].raw
            time.sleep(0.005)
        assert abs(node.sdo[0x6064].raw - 50_000) <= 200  # position window of the simulated drive
        assert abs(node.tpdo_values[0x6064] - 50_000) <= 200   # the same value in TPDO2 (synchronous)
    finally:
        master.sync.stop()


def _sync(master, n: int) -> None:
    for _ in range(n):
        master.sync.transmit()
        time.sleep(0.0005)                     # let the drive's thread answer; results do not depend on it


def _enable(node) -> None:
    for cw in (0x06, 0x07, 0x0F):
        node.sdo[0x6040].raw = cw               # device control by SDO takes effect at once
    assert node.sdo[0x6041].raw & 0x6F == 0x27


@pytest.mark.parametrize("method", [35, 37])
def test_drives_cia402_homing_current_position(bus, method):
    """CiA 402-2 homing methods 35 and 37: the current position is the home position; after the start
    (controlword bit 4) the position actual value reads the home offset 0x607C, statusword bits 10 and 12
    (target reached, homing attained) are set, bit 13 (homing error) is not."""
    drive, master = bus
    drive(6, initial_position=12_345.0)
    node = canopen.RemoteNode(6, EDS_PATH)
    master.add_node(node)
    node.sdo.RESPONSE_TIMEOUT = 2.0             # a loaded test machine may schedule the drive's thread late
    node.nmt.send_command(0x01)
    _enable(node)
    node.sdo[0x6060].raw = 6
    node.sdo[0x6098].raw = method
    node.sdo[0x607C].raw = 1000
    _sync(master, 2)
    assert node.sdo[0x6061].raw == 6
    node.sdo[0x6040].raw = 0x1F
    _sync(master, 2)
    sw = node.sdo[0x6041].raw
    assert sw & 0x3400 == 0x1400
    assert node.sdo[0x6064].raw == 1000


def test_drives_cia402_homing_switch(bus):
    """CiA 402-2 homing method 19 with the home switch (digital input 0x60FD bit 2) active at and above
    100000 inc: from below, the drive searches at 0x6099:1, turns back at 0x6099:2 and takes the switch's
    edge as the home position (home offset 0x607C = 0); then it stands with bits 10 and 12 set and the
    position reads the distance from the edge."""
    drive, master = bus
    sim = drive(7, plant=SwitchPlant(home_low=100_000.0))
    node = canopen.RemoteNode(7, EDS_PATH)
    master.add_node(node)
    node.sdo.RESPONSE_TIMEOUT = 2.0
    node.nmt.send_command(0x01)
    _enable(node)
    node.sdo[0x6060].raw = 6
    node.sdo[0x6098].raw = 19
    node.sdo[0x6099][1].raw = 200_000           # inc/s
    node.sdo[0x6099][2].raw = 20_000
    node.sdo[0x609A].raw = 2_000_000            # inc/s^2
    assert node.sdo[0x60FD].raw & 0x4 == 0
    node.sdo[0x6040].raw = 0x1F
    for _ in range(400):
        _sync(master, 10)
        sw = node.sdo[0x6041].raw
        if sw & 0x1400 == 0x1400:
            break
    assert sw & 0x3400 == 0x1400, hex(sw)
    # it stopped below the edge: the switch is off and the position is negative, within the stop distance
    # of the zero search speed (v^2 / 2a = 100 inc) plus the lag of the speed loop
    assert node.sdo[0x60FD].raw & 0x4 == 0
    assert -400 <= node.sdo[0x6064].raw < 0
    assert sim.core.x + sim.core.offset == pytest.approx(node.sdo[0x6064].raw, abs=1)
