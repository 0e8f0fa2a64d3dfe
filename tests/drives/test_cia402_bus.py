"""What the master sets up on the bus and how it keeps a node in OPERATIONAL: the PDO mapping of each mode
(CiA 301 PDO communication and mapping parameters 0x1400/0x1600, 0x1800/0x1A00; CiA 402-2 objects) and NMT
(CiA 301: start, heartbeat with the node's NMT state).  Alarms: S7-1200 Motion Control V6 §12.8 (16#800C /
16#003E station failure)."""
from __future__ import annotations

import pytest

pytest.importorskip("canopen")
pytest.importorskip("can")

from _cia402_rig import Rig  # noqa: E402

#: (index << 16) | bits of each mapped object, as docs/drives/cia402.md lists them
TARGET = {"csp": 0x607A0020, "pp": 0x607A0020, "csv": 0x60FF0020, "pv": 0x60FF0020, "cst": 0x60710010}


@pytest.mark.parametrize("mode", sorted(TARGET))
def test_drives_cia402_pdo_mapping_of_each_mode(mode):
    """RPDO1 (0x200 + node): controlword 0x6040, the mode's target (0x607A position, 0x60FF velocity, 0x6071
    torque), modes of operation 0x6060; TPDO1 (0x180 + node): statusword 0x6041, position actual 0x6064,
    mode display 0x6061; TPDO2 (0x280 + node): velocity actual 0x606C, torque actual 0x6077, error code
    0x603F; all synchronous on every SYNC (transmission type 1); RPDO2-4 and TPDO3-4 switched off (bit 31
    of the COB-ID)."""
    r = Rig(mode, enable=False, node_id=4)
    try:
        sdo = r.drive.remote.sdo

        def mapped(index: int) -> list[int]:
            return [sdo[index][k].raw for k in range(1, sdo[index][0].raw + 1)]
        assert mapped(0x1600) == [0x60400010, TARGET[mode], 0x60600008]
        assert mapped(0x1A00) == [0x60410010, 0x60640020, 0x60610008]
        assert mapped(0x1A01) == [0x606C0020, 0x60770010, 0x603F0010]
        for com, cob in ((0x1400, 0x204), (0x1800, 0x184), (0x1801, 0x284)):
            assert sdo[com][1].raw == cob and sdo[com][2].raw == 1
        for com in (0x1401, 0x1402, 0x1403, 0x1802, 0x1803):
            assert sdo[com][1].raw & 0x80000000
        assert sdo[0x6060].raw == {"csp": 8, "csv": 9, "cst": 10, "pp": 1, "pv": 3}[mode]
    finally:
        r.close()


def test_drives_cia402_nmt_node_leaves_operational():
    """CiA 301 NMT: after the set-up the node is OPERATIONAL (its heartbeat says 0x05).  A node that falls back
    to PRE-OPERATIONAL (heartbeat 0x7F, no more PDOs) is a station failure 16#800C/16#003E; MC_Reset sends NMT
    start (0x01) and the axis is enabled again once the node is back in OPERATIONAL."""
    r = Rig("csp", heartbeat_ms=20)
    try:
        r.steps(30)
        assert r.drive.heartbeat_state == 0x05 and r.sim.node.nmt.state == "OPERATIONAL"
        r.sim.node.nmt.state = "PRE-OPERATIONAL"
        r.until(lambda: r.power.Error, 0.1, "communication fault")
        assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003E)
        assert r.drive.heartbeat_state == 0x7F
        r.reset()
        r.until(lambda: r.power.Status, 0.3, "enabled again")
        r.steps(30)                              # the next heartbeats (every 20 ms) say OPERATIONAL
        assert r.sim.node.nmt.state == "OPERATIONAL" and r.drive.heartbeat_state == 0x05
        assert r.power.Status and not r.power.Error
    finally:
        r.close()
