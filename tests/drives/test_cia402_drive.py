"""An S7-1200 axis on a simulated CiA 402 drive over the virtual CAN bus: the power state machine on the
bus, every operation mode moving the drive, EMCY and statusword faults, heartbeat and PDO loss, and
determinism.  Words and transitions: CiA 402-2 (drive device state machine, modes of operation); alarms:
S7-1200 Motion Control V6 section 12.8 (16#800C drive fault, ErrorInfo 16#0001 alarm from the drive,
16#003D drive has shut down, 16#003E station failure)."""
from __future__ import annotations

import pytest

pytest.importorskip("canopen")
pytest.importorskip("can")

from plcmotion.drives.cia402.profile import EMCY_OVERCURRENT, State  # noqa: E402
from plcmotion.s7_1200 import MC_Home, MC_MoveAbsolute, MC_MoveVelocity  # noqa: E402
from plcmotion.trace import Trace  # noqa: E402

from _cia402_rig import Rig  # noqa: E402

INC_PER_REV = 2048 << 11          # the S7-1200 default encoder: 2048 steps, 11 bit fine resolution
MM_PER_INC = 10.0 / INC_PER_REV   # LeadScrew 10 mm per motor revolution


@pytest.fixture
def rigs():
    made: list[Rig] = []

    def make(*args, **kw) -> Rig:
        made.append(Rig(*args, **kw))
        return made[-1]
    yield make
    for r in made:
        r.close()


def _words(rig: Rig) -> list[tuple[int, int]]:
    """Record (controlword sent, statusword received) every servo cycle; consecutive repeats dropped."""
    seen: list[tuple[int, int]] = []

    def sample(t: float) -> None:
        pair = (rig.drive.controlword, rig.drive.statusword)
        if not seen or seen[-1] != pair:
            seen.append(pair)
    rig.ctl.on_post_servo(sample)
    return seen


def test_drives_cia402_switch_on_sequence(rigs):
    """CiA 402-2 transitions 2, 3, 4 on the bus: MC_Power Enable = TRUE makes the master send shutdown
    (0x06, already while disabled), switch on (0x07), enable operation (0x0F) one after the other as the
    drive's statusword shows SWITCH ON DISABLED (0x0240 with remote), READY TO SWITCH ON (0x0231 with voltage enabled, quick stop off, remote), SWITCHED ON (0x0233) and
    OPERATION ENABLED (0x1237, bit 12: the drive follows the cyclic target); MC_Power.Status only then
    (S7-1200 V6 11.1.1: enabled once the drive is ready).  Disabling sends shutdown (transition 8)."""
    r = rigs(enable=False)
    words = _words(r)
    r.steps(3)
    # disabled: the master keeps the drive in READY TO SWITCH ON (shutdown, transition 2)
    assert r.drive.state is State.READY_TO_SWITCH_ON and r.drive.statusword == 0x0231
    r.power.Enable = True
    r.until(lambda: r.power.Status, 0.1, "enabled")
    states = [sw for _, sw in words]
    assert [s for k, s in enumerate(states) if k == 0 or s != states[k - 1]][:4] == [0x0240, 0x0231, 0x0233, 0x1237]
    sent = [cw for cw, _ in words]
    assert [c for k, c in enumerate(sent) if k == 0 or c != sent[k - 1]][:3] == [0x06, 0x07, 0x0F]
    assert r.sim.state == "OPERATION ENABLED"
    r.power.Enable = False
    r.until(lambda: r.drive.state is State.READY_TO_SWITCH_ON, 0.1, "disabled")
    assert r.drive.controlword == 0x06 and not r.power.Status


@pytest.mark.parametrize("mode", ["csp", "csv", "cst", "pp", "pv"])
def test_drives_cia402_move_absolute_in_each_mode(rigs, mode):
    """MC_MoveAbsolute (S7-1200 V6 11.1.5) to 20 mm at 50 mm/s over a CiA 402 drive in each mode the axis
    can use (CiA 402-2: csp target position, csv target velocity, cst target torque, pp streamed set points,
    pv target velocity): Done, and the drive's own position actual value 0x6064 is 20 mm / (10 mm per
    revolution) * 2^22 increments per revolution."""
    r = rigs(mode)
    home = r.start(MC_Home(), Mode=0, Position=0.0)
    r.until(lambda: home.Done, 0.1, "homed")
    mv = r.start(MC_MoveAbsolute(), Position=20.0, Velocity=50.0)
    r.until(lambda: mv.Done or mv.Error, 2.0, f"{mode}: MC_MoveAbsolute done")
    assert mv.Done and not mv.Error, (mv.ErrorID, r.axis.alarms)
    assert r.sim.state == "OPERATION ENABLED"
    assert abs(r.sim.position - 20.0 / MM_PER_INC) <= 0.05 / MM_PER_INC          # within 0.05 mm
    assert abs(r.axis.Position - 20.0) <= 0.05


@pytest.mark.parametrize("mode", ["csv", "pv", "csp"])
def test_drives_cia402_move_velocity(rigs, mode):
    """MC_MoveVelocity (S7-1200 V6 11.1.8) 30 mm/s: InVelocity, and the drive reports velocity actual
    value 0x606C = 30 mm/s / 10 mm per revolution * 2^22 inc per revolution."""
    r = rigs(mode)
    mv = r.start(MC_MoveVelocity(), Velocity=30.0)
    r.until(lambda: mv.InVelocity, 1.0, "in velocity")
    r.steps(25)
    assert abs(r.drive.velocity - 30.0 / MM_PER_INC) <= 0.01 * 30.0 / MM_PER_INC
    assert abs(r.axis.Velocity - 30.0) <= 0.3


def test_drives_cia402_emcy_fault_and_fault_reset(rigs):
    """A drive fault (EMCY 0x2310 overcurrent, error register 0x03: generic + current) becomes the axis's
    drive fault 16#800C/16#0001 with the reaction remove enable (S7-1200 V6 12.8); the drive is in FAULT
    (statusword 0x0208: FAULT with remote).  MC_Reset acknowledges: the master sends a fault reset (controlword 0x80, a rising
    edge of bit 7, CiA 402-2 transition 15), the drive clears its error (EMCY 0x0000) and MC_Power enables the
    axis again through 0x06, 0x07, 0x0F."""
    r = rigs("csv")
    mv = r.start(MC_MoveVelocity(), Velocity=30.0)
    r.until(lambda: mv.InVelocity, 1.0, "in velocity")
    r.sim.inject_fault(EMCY_OVERCURRENT)
    r.until(lambda: mv.Error, 0.05, "the move ends with the drive fault")
    assert (mv.ErrorID, mv.ErrorInfo) == (0x800C, 0x0001)
    assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x0001) and not r.power.Status
    assert (EMCY_OVERCURRENT, 0x03) in r.drive.emcy
    r.until(lambda: r.drive.state is State.FAULT, 0.5, "drive in FAULT after its reaction")
    assert r.drive.statusword == 0x0208 and r.drive.error_code == EMCY_OVERCURRENT
    assert r.axis.ErrorBits.DriveFault
    words = _words(r)
    rs = r.reset()
    assert rs.Done and not rs.Error
    r.until(lambda: r.power.Status, 0.2, "enabled again")
    sent = [cw for cw, _ in words]
    # 0x00 (disable voltage) while the statusword still shows FAULT - the drive answers one SYNC later
    assert 0x80 in sent and sent[sent.index(0x80):sent.index(0x80) + 5] == [0x80, 0x00, 0x06, 0x07, 0x0F]
    assert r.drive.emcy[-1] == (0x0000, 0x00) and r.drive.error_code == 0


def test_drives_cia402_fault_with_cause_stays(rigs):
    """S7-1200 V6 12.7: an alarm whose cause is still there comes back after MC_Reset - the drive refuses the
    fault reset while its cause lasts (CiA 402-2: FAULT is left only when the fault is gone); once the cause
    is gone MC_Reset clears it and the axis is enabled again."""
    r = rigs("csp")
    r.sim.inject_fault(0x5000, cause=True)
    r.until(lambda: r.power.Error, 0.05, "fault")
    r.until(lambda: r.drive.state is State.FAULT, 0.5, "FAULT")
    r.reset()
    r.steps(15)
    assert r.drive.state is State.FAULT and r.power.Error and r.axis.alarms
    r.sim.clear_fault()
    r.reset()
    r.until(lambda: r.power.Status, 0.2, "enabled again")
    assert not r.axis.alarms


def test_drives_cia402_heartbeat_loss(rigs):
    """A drive whose heartbeat (0x1017 = 20 ms) stops is lost after 1.5 heartbeat times (30 ms): station
    failure 16#800C/16#003E (S7-1200 V6 12.8), StatusDrive.CommunicationOK = FALSE.  With the heartbeat back,
    MC_Reset acknowledges and the axis is enabled again."""
    r = rigs("csp", heartbeat_ms=20)
    r.steps(5)
    assert r.axis.StatusDrive.CommunicationOK
    lost: list[float] = []
    r.ctl.on_post_servo(lambda t: lost.append(t) if not lost and not r.drive.communication_ok else None)
    r.sim.heartbeat(False)
    r.until(lambda: r.power.Error, 0.1, "communication fault")
    # the first servo cycle more than 30 ms after the last heartbeat (servo cycle 1 ms)
    assert 0.030 < lost[0] - r.drive.last_heartbeat <= 0.031 + 1e-9
    assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003E)
    assert not r.axis.StatusDrive.CommunicationOK
    r.sim.heartbeat(True)
    r.steps(10)
    r.reset()
    r.until(lambda: r.power.Status, 0.2, "enabled again")
    assert r.axis.StatusDrive.CommunicationOK


def test_drives_cia402_silent_node(rigs):
    """A drive that stops answering altogether (power or cable lost): its TPDOs are missing for 3 servo
    cycles -> station failure 16#800C/16#003E (S7-1200 V6 12.8), CommunicationOK FALSE, even before the
    heartbeat time runs out."""
    r = rigs("csp", heartbeat_ms=1000)
    r.sim.silence(True)
    r.until(lambda: r.power.Error, 0.02, "communication fault")
    assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003E)
    assert not r.axis.StatusDrive.CommunicationOK
    r.sim.silence(False)
    r.steps(3)
    r.reset()
    r.until(lambda: r.power.Status, 0.2, "enabled again")


def test_drives_cia402_quick_stop(rigs):
    """CiA 402-2 transitions 11 and 12: the quick stop command (0x02) stops the moving drive with its quick
    stop deceleration 0x6085 (statusword QUICK STOP ACTIVE 0x0217), then SWITCH ON DISABLED.  The axis sees
    its drive shut down: 16#800C/16#003D (S7-1200 V6 12.8), remove enable."""
    r = rigs("csv")
    mv = r.start(MC_MoveVelocity(), Velocity=50.0)
    r.until(lambda: mv.InVelocity, 1.0, "in velocity")
    words = _words(r)
    r.drive.quick_stop()
    r.until(lambda: r.drive.state is State.SWITCH_ON_DISABLED, 0.3, "quick stop done")
    assert 0x02 in [cw for cw, _ in words]
    assert 0x0217 in [sw for _, sw in words] or 0x1217 in [sw for _, sw in words]
    assert abs(r.drive.velocity) == 0
    assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003D)


def _trace_run(mode: str) -> list[list[float]]:
    r = Rig(mode)
    try:
        trace = Trace(r.ctl, ["Axis_1.Position", "Axis_1.Velocity"]).start()
        mv = r.start(MC_MoveVelocity(), Velocity=40.0)
        r.steps(60)
        mv.Execute = False
        r.steps(5)
        trace.stop()
        return trace.rows.tolist()
    finally:
        r.close()


@pytest.mark.parametrize("mode", ["csp", "cst"])
def test_drives_cia402_deterministic(mode):
    """Virtual time: the same program over the bus gives the same trace bit for bit (the exchange of a servo
    cycle depends on the frames only, never on thread timing)."""
    first, second = _trace_run(mode), _trace_run(mode)
    assert len(first) > 200 and first == second


def test_drives_cia402_s7_1200_power_and_move_absolute_trace(rigs):
    """The default family (S7-1200, Controller()): MC_Power and MC_MoveAbsolute (S7-1200 V6 11.1.1, 11.1.5)
    move a CiA 402 drive in csp over the virtual bus; the trace of Axis_1.Position rises from 0 to the
    target 35 mm, never beyond it by more than the positioning window, and ends there."""
    r = rigs("csp")
    trace = Trace(r.ctl, ["Axis_1.Position"]).start()
    home = r.start(MC_Home(), Mode=0, Position=0.0)
    r.until(lambda: home.Done, 0.1, "homed")
    mv = r.start(MC_MoveAbsolute(), Position=35.0, Velocity=60.0)
    r.until(lambda: mv.Done, 2.0, "done")
    trace.stop()
    pos = trace.data["Axis_1.Position"]
    assert abs(pos[0]) < 1e-6 and abs(pos[-1] - 35.0) <= 0.05
    assert max(pos) <= 35.0 + 0.05
    assert abs(r.sim.position * MM_PER_INC - 35.0) <= 0.05


def test_drives_cia402_homing_mode_from_the_master(rigs):
    """Drive-based homing (CiA 402-2 homing mode 6, method 35: the current position is the home position)
    run by the master while the axis is disabled: the drive is switched on in mode 6, started with
    controlword bit 4, and switched off again when the statusword shows homing attained (bits 10 and 12);
    the position then reads the home offset 0x607C (here 5 mm) and the drive is back in its operating mode
    (csp: mode display 8) when the axis is enabled again."""
    r = rigs("csp", enable=False)
    r.steps(3)
    words = _words(r)
    r.drive.home_in_drive(35, offset=5.0)
    r.until(lambda: r.drive.homing != "running", 0.1, "homing ended")
    assert r.drive.homing == "attained"
    assert 0x1F in [cw for cw, _ in words]                     # enable operation + start homing
    assert any(sw & 0x1400 == 0x1400 for _, sw in words)      # homing attained, target reached
    assert r.axis.ActualPosition == pytest.approx(5.0, abs=MM_PER_INC)
    r.power.Enable = True
    r.until(lambda: r.power.Status, 0.1, "enabled")
    assert r.drive.mode_display == 8
    with pytest.raises(RuntimeError, match="needs the axis disabled"):
        r.drive.home_in_drive(35)


def test_drives_cia402_s7_1500_drive_fault():
    """Family-neutral: on an S7-1500 axis the same EMCY is that family's drive fault - technology alarm 421
    with ErrorWord bit 4 and StatusDrive.Error (the CPU's technology alarm 421 "drive error"; the
    reaction remove enable); a heartbeat loss sets ErrorWord bit 7 (communication fault) and
    StatusDrive.CommunicationOK = FALSE; MC_Reset with the causes gone re-enables."""
    from plcmotion import Controller
    from plcmotion.drives.cia402 import Cia402Link
    from plcmotion.s7_1500 import MC_Power, MC_Reset
    from plcmotion.s7_1500.technology.alarms import number
    from plcmotion.s7_1500.technology.tags import error_word

    from _cia402_rig import channel

    ctl = Controller(family="S7-1500")
    ctl.connect_drive("Axis_1", Cia402Link(channel=channel(), node_id=9, simulate=True, heartbeat_ms=20))
    ax = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1})
    try:
        power, reset = MC_Power(), MC_Reset()

        def cycles(n: int) -> None:
            for _ in range(n):
                power(Axis=ax, Enable=True, StartMode=1)
                reset(Axis=ax, Execute=False)
                ctl.step()
        cycles(20)
        assert power.Status
        ax.drive.simulated.inject_fault(EMCY_OVERCURRENT)
        cycles(5)
        assert [number(a) for a in ax.alarms] == [421]
        assert error_word(ax) & (1 << 4) and ax.StatusDrive.Error and not power.Status
        ax.drive.simulated.heartbeat(False)
        cycles(15)
        assert error_word(ax) & (1 << 7) and not ax.StatusDrive.CommunicationOK
        ax.drive.simulated.heartbeat(True)
        cycles(10)
        reset(Axis=ax, Execute=True)
        ctl.step()
        cycles(30)
        assert power.Status and not ax.alarms and ax.StatusDrive.CommunicationOK
    finally:
        ctl.close()
