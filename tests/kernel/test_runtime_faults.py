"""Issue 8 defect 6: user program faults and the cycle-time watchdog.

Rule (Controller.step, plcmotion.kernel.watchdog): whatever a user program or servo hook raises - any BaseException, also one whose
``__str__`` raises - puts the controller in STOP with the reason; nothing but KeyboardInterrupt leaves
``step()``, and KeyboardInterrupt only after the controller went to STOP.  A program that runs longer than
``cycle_watchdog`` x application cycle (wall clock) is an overrun: reported, and with ``cycle_watchdog_stop``
the controller goes to STOP as a CPU does when its maximum cycle time is exceeded (S7-1200 V6 §2.2.7.3
gives an overflow of the motion OBs the same reaction).
"""
from __future__ import annotations

import time
import warnings

import pytest

from plcmotion import Controller, ControllerStopped, ProgramErrorWarning
from plcmotion.kernel.watchdog import CycleOverrunWarning
from plcmotion.s7_1200 import MC_Power


class Unprintable(Exception):
    def __str__(self) -> str:
        raise ValueError("no text for you")


class UnprintableBase(Exception):
    def __str__(self) -> str:
        raise SystemExit("str() exits")


def _enabled_controller():
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1")
    power = MC_Power(Axis=axis, Enable=True)
    ctl.program(power)
    ctl.run(0.02)
    assert axis.StatusBits.Enable
    return ctl, axis


@pytest.mark.parametrize("exc", [Unprintable(), UnprintableBase(), SystemExit(0), SystemExit("bye"),
                                 GeneratorExit(), BaseException("plain base")],
                         ids=["str-raises", "str-raises-SystemExit", "sys.exit(0)", "sys.exit(text)",
                              "GeneratorExit", "BaseException"])
def test_kernel_defect6_any_program_exception_stops_the_controller(exc):
    """Defect 6: a program raising an exception whose __str__ raises, SystemExit, GeneratorExit or another
    BaseException: step() returns, the controller is in STOP with the program's name and the exception type
    in stop_reason, the axis lost its enable (S7-1200 V6 §2.2.7.4) and a ProgramErrorWarning says so."""
    ctl, axis = _enabled_controller()

    @ctl.program
    def faulty():
        raise exc

    with pytest.warns(ProgramErrorWarning, match="STOP"):
        ctl.step()
    assert ctl.mode == "STOP"
    assert "faulty" in ctl.stop_reason and type(exc).__name__ in ctl.stop_reason
    assert not axis.StatusBits.Enable
    t = ctl.time
    ctl.step()                                           # goes on in STOP: servo cycles, no programs
    assert ctl.time > t and ctl.mode == "STOP"
    with pytest.raises(ControllerStopped):
        ctl.run_until(lambda: False, timeout=1.0)


def test_kernel_defect6_keyboard_interrupt_reaches_the_user_after_stop():
    """Defect 6: Ctrl-C while a program runs: the controller goes to STOP first (the program was cut off
    half-way), then KeyboardInterrupt reaches the person at the terminal."""
    ctl, axis = _enabled_controller()

    @ctl.program
    def interrupted():
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ctl.step()
    assert ctl.mode == "STOP" and "KeyboardInterrupt" in ctl.stop_reason
    assert not axis.StatusBits.Enable


@pytest.mark.parametrize("exc", [Unprintable(), SystemExit(3), GeneratorExit()],
                         ids=["str-raises", "SystemExit", "GeneratorExit"])
def test_kernel_defect6_servo_hook_faults_stop_the_controller(exc):
    """Defect 6 (`_run_hooks`): a servo hook is user code too; any exception from it -> STOP with reason."""
    ctl, axis = _enabled_controller()

    def hook(t):
        raise exc

    ctl.on_post_servo(hook)
    with pytest.warns(ProgramErrorWarning):
        ctl.step()
    assert ctl.mode == "STOP" and type(exc).__name__ in ctl.stop_reason and "hook" in ctl.stop_reason
    assert not axis.StatusBits.Enable


def test_kernel_defect6_keyboard_interrupt_in_a_servo_hook():
    ctl, _ = _enabled_controller()
    ctl.on_pre_servo(lambda t: (_ for _ in ()).throw(KeyboardInterrupt()))
    with pytest.raises(KeyboardInterrupt):
        ctl.step()
    assert ctl.mode == "STOP" and "KeyboardInterrupt" in ctl.stop_reason


# --- cycle-time watchdog ------------------------------------------------------------------------------------
def test_kernel_defect6_watchdog_reports_a_slow_program_and_keeps_virtual_time():
    """Defect 6: a program that takes longer than cycle_watchdog x app_cycle (wall clock) is counted and
    warned about; by default the controller stays in RUN and virtual time is unaffected (deterministic)."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.002, cycle_watchdog=15.0)   # limit 30 ms
    assert ctl.watchdog.limit == pytest.approx(0.03)
    slow = {"on": False}

    @ctl.program
    def main():
        if slow["on"]:
            time.sleep(0.06)

    ctl.run(0.01)
    assert ctl.cycle_overruns == 0 and ctl.last_overrun is None
    slow["on"] = True
    with pytest.warns(CycleOverrunWarning, match="overrun"):
        ctl.step()
    assert ctl.cycle_overruns == 1
    last = ctl.last_overrun
    assert last.duration >= 0.06 and last.limit == pytest.approx(0.03) and not last.injected
    assert last.time == pytest.approx(0.01)
    assert ctl.mode == "RUN"
    assert ctl.time == pytest.approx(0.012)           # virtual time: one application cycle, as always


def test_kernel_defect6_watchdog_stop_like_s7_overflow():
    """A CPU goes to STOP when its cycle time is exceeded (S7-1200 V6 §2.2.7.3, Overflows, for the motion
    OBs).  With cycle_watchdog_stop=True an
    overrun does the same: STOP with the reason, axes disabled."""
    ctl = Controller(cycle_watchdog=5.0, cycle_watchdog_stop=True)          # limit 20 ms
    axis = ctl.add_positioning_axis("Axis_1")
    ctl.program(MC_Power(Axis=axis, Enable=True))
    ctl.run(0.02)
    assert axis.StatusBits.Enable
    ctl.program(lambda: time.sleep(0.05))
    with pytest.warns(CycleOverrunWarning):
        ctl.step()
    assert ctl.mode == "STOP" and "cycle time" in ctl.stop_reason
    assert ctl.cycle_overruns == 1
    assert not axis.StatusBits.Enable


def test_kernel_defect6_watchdog_off():
    ctl = Controller(cycle_watchdog=None)
    ctl.program(lambda: time.sleep(0.01))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ctl.step()
    assert ctl.cycle_overruns == 0 and ctl.watchdog.limit is None
    with pytest.raises(ValueError, match="watchdog"):
        ctl.inject_cycle_overrun()


@pytest.mark.parametrize("off", [0, None])
def test_kernel_defect6_watchdog_stop_without_a_watchdog_is_refused(off):
    """Issue 8 review: STOP on overruns with the watchdog off was accepted and silently did nothing."""
    with pytest.raises(ValueError, match="cycle_watchdog_stop = True needs a cycle watchdog"):
        Controller(cycle_watchdog=off, cycle_watchdog_stop=True)
    assert Controller(cycle_watchdog=off, cycle_watchdog_stop=False).watchdog.limit is None


@pytest.mark.parametrize("value", [0.5, -1.0, float("nan"), float("inf"), "10", True, 1e9])
def test_kernel_defect6_watchdog_multiple_validated(value):
    with pytest.raises(ValueError, match="cycle_watchdog"):
        Controller(cycle_watchdog=value)


def test_kernel_defect11_injected_cycle_overrun_is_deterministic():
    """Defect 11 (application-cycle overrun for virtual commissioning): inject_cycle_overrun(n) makes the next
    n application cycles count as overruns, whatever the wall clock says; with cycle_watchdog_stop the
    controller goes to STOP at the first one."""
    ctl = Controller(cycle_watchdog=10.0)
    ticks = []
    ctl.program(lambda: ticks.append(ctl.time))
    ctl.run(0.008)
    ctl.inject_cycle_overrun(cycles=3)
    with pytest.warns(CycleOverrunWarning):
        ctl.run(0.02)                                 # 5 application cycles, the first 3 overrun
    assert ctl.cycle_overruns == 3 and ctl.mode == "RUN"
    assert ctl.last_overrun.injected and ctl.last_overrun.time == pytest.approx(0.016)
    assert ctl.last_overrun.duration > ctl.watchdog.limit
    assert len(ticks) == 7                            # the programs ran in every cycle

    stopping = Controller(cycle_watchdog=10.0, cycle_watchdog_stop=True)
    axis = stopping.add_positioning_axis("Axis_1")
    stopping.program(MC_Power(Axis=axis, Enable=True))
    stopping.run(0.02)
    stopping.inject_cycle_overrun(duration=0.5)
    with pytest.warns(CycleOverrunWarning):
        stopping.step()
    assert stopping.mode == "STOP" and "500 ms" in stopping.stop_reason
    assert stopping.last_overrun.duration == 0.5
    assert not axis.StatusBits.Enable


@pytest.mark.parametrize("kw", [{"cycles": 0}, {"cycles": 1.5}, {"duration": 0.01}, {"duration": float("nan")}])
def test_kernel_defect11_inject_cycle_overrun_validated(kw):
    ctl = Controller(cycle_watchdog=10.0)             # limit 40 ms: 10 ms would be no overrun
    with pytest.raises(ValueError):
        ctl.inject_cycle_overrun(**kw)


def test_kernel_defect6_watchdog_from_project_file(tmp_path):
    from plcmotion.project import ProjectError, load_project

    good = tmp_path / "p.toml"
    good.write_text("[controller]\ncycle_watchdog = 3\ncycle_watchdog_stop = true\n")
    ctl = load_project(good)
    assert ctl.watchdog.limit == pytest.approx(0.012) and ctl.watchdog.stop is True
    off = tmp_path / "off.toml"
    off.write_text("[controller]\ncycle_watchdog = 0\n")
    assert load_project(off).watchdog.limit is None
    for text in ("cycle_watchdog = 0.5", "cycle_watchdog = \"x\"", "cycle_watchdog_stop = 1"):
        bad = tmp_path / "bad.toml"
        bad.write_text("[controller]\n" + text + "\n")
        with pytest.raises(ProjectError, match="controller.cycle_watchdog"):
            load_project(bad)


def test_kernel_defect6_hook_fault_with_warnings_as_errors_is_not_an_internal_error():
    """With a filter that turns warnings into errors, a faulty hook's ProgramErrorWarning reaches the caller;
    the controller is in STOP for the hook, not for an 'internal error in the servo cycle'."""
    ctl, _ = _enabled_controller()
    ctl.on_post_servo(lambda t: 1 / 0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ProgramErrorWarning)
        with pytest.raises(ProgramErrorWarning):
            ctl.step()
    assert ctl.mode == "STOP" and "ZeroDivisionError" in ctl.stop_reason
    assert "internal error" not in ctl.stop_reason
    ctl.start()
    ctl.step()
    assert ctl.mode == "RUN"


def test_kernel_defect6_watchdog_default_reports_only():
    """Default: watchdog time 100 application cycles (0.4 s at 4 ms), report only (virtual time and the
    controller's mode never depend on the wall clock unless cycle_watchdog_stop is chosen)."""
    ctl = Controller()
    assert ctl.watchdog.limit == pytest.approx(0.4) and ctl.watchdog.stop is False
    ctl.inject_cycle_overrun()
    with pytest.warns(CycleOverrunWarning, match="800 ms"):
        ctl.step()
    assert ctl.mode == "RUN" and ctl.cycle_overruns == 1
