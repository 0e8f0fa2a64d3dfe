"""PLCopen-style function blocks over the command register of a Pilz drive axis.

The motion core has one command channel per axis and no per-instance outputs (Pilz V6.5 §1).  Each block
here drives that channel as a program would: at the rising edge of its Execute it writes its inputs into the
register (I401 command, I403 ... I431 set values, I400 motion ID) and gives the register's Execute I402 a
rising edge - a call later if I402 was still high from another command, so that the motion core sees the edge.
It then follows *its* command (the one the core created at that edge) and derives the PLCopen outputs:

* Busy from its start until it ends; Active while it is the core's current command and moves the axis;
* Done (InVelocity / InTorque for the velocity and torque commands) from the status word I92 of its command;
  the commands that go on after I92 (MC_MoveVelocity, MC_MoveSpeed, MC_TorqueControl and the cyclic commands,
  whose I92 only acknowledges the start) stay Busy and Active with that output TRUE until replaced;
* Error with ErrorID = I90 when the core denied or cancelled it (I91);
* CommandAborted when a later command took the channel over before it was Done (a command it waited for
  with BufferMode 1 - "start at the end" - still ends Done when its motion ended).

While its command is current the block mirrors Execute into I402 (MC_Stop and MC_Halt hold the axis while
Execute is TRUE, §1.6.4) and writes the set values the core reads every cycle (velocity of MC_MoveSpeed and of
MC_MoveVelocity with ContinuousUpdate, cyclic set values, torque and override).  Done / Error / CommandAborted
stay TRUE while Execute is TRUE, else for one call.  ErrorID 100: the Axis input is no Pilz drive axis; 101:
the register refused an input value (wrong type, not finite): both before any command starts.
"""
from __future__ import annotations

from typing import Any, ClassVar

from ..fb import Instruction, as_bool
from ..kernel.jobs import JobState
from .technology import command as C
from .technology.axis import DriveAxis
from .technology.registers import RegisterError

#: ErrorIDs of the wrappers themselves (beside the motion core's I90 causes): decisions.md
NOT_A_DRIVE_AXIS, INPUT_REFUSED = 100, 101

_OUT = {"Done": False, "Busy": False, "Active": False, "CommandAborted": False, "Error": False, "ErrorID": 0}


class MotionCommand(Instruction):
    """Base of the wrappers: ``COMMAND`` is the I401 number, ``LATCHED`` maps inputs to the register
    parameters written at the start, ``CYCLIC`` those written on every call while the command is current."""

    COMMAND: ClassVar[int] = C.DO_NOTHING
    LATCHED: ClassVar[dict[str, str]] = {}
    CYCLIC: ClassVar[dict[str, str]] = {}
    DONE: ClassVar[str] = "Done"
    #: the command goes on after its I92 (velocity, cyclic and torque commands): the block stays Busy
    CONTINUOUS: ClassVar[bool] = False
    INPUTS = {"Axis": None, "Execute": False, "MotionID": 0}
    OUTPUTS = dict(_OUT)

    def _reinit(self) -> None:
        super()._reinit()
        for name, value in (("_prev", False), ("_state", "idle"), ("_cmd", None), ("_starts", 0),
                            ("_final", None), ("_shown", False)):
            object.__setattr__(self, name, value)

    # --- evaluation -------------------------------------------------------------------------------------------
    def _evaluate(self) -> None:
        execute = as_bool(self, "Execute", self.Execute)
        edge = execute and not self._prev
        object.__setattr__(self, "_prev", execute)
        if edge:
            self._begin()
        if self._state == "arming":
            self._arm()
        elif self._state == "sent":
            self._acknowledged()
        if self._state == "running":
            self._follow(execute)
        elif self._owns_register() and self.COMMAND in (C.STOP, C.HALT):
            self.Axis.registers.I402 = execute     # MC_Stop / MC_Halt hold the axis while Execute is TRUE
        self._show(execute)

    def _set(self, **values: Any) -> None:
        self.__dict__.update(values)

    def _begin(self) -> None:
        self._out(**_OUT)
        self._set(_cmd=None, _final=None, _shown=False)
        axis = self.Axis
        if not isinstance(axis, DriveAxis):
            self._set(_final=("Error", NOT_A_DRIVE_AXIS), _state="ended")
            return
        self._register(axis)
        self._set(_state="arming")
        self._out(Busy=True)

    def _arm(self) -> None:
        """Write the command and give I402 a rising edge (a call later if it is still high)."""
        axis: DriveAxis = self.Axis
        regs = axis.registers
        claimed = axis.core.claimed
        if claimed is not None and claimed[1] is not self and (
                claimed[0] == axis.ctl.app_cycles or claimed[1]._holding()):
            return                  # another block uses the register this cycle, or MC_Stop holds it: wait
        if regs.I402 or axis.core.execute_seen:
            regs.I402 = False                       # the core must see Execute low for a cycle first
            axis.core.claimed = (axis.ctl.app_cycles, self)
            return
        try:
            for name, reg in {**self.LATCHED, **self.CYCLIC}.items():
                regs.write(reg, getattr(self, name))
            regs.I400 = self.MotionID
            regs.I401 = self.COMMAND
        except RegisterError:
            self._set(_final=("Error", INPUT_REFUSED), _state="ended")
            return
        regs.I402 = True
        axis.core.claimed = (axis.ctl.app_cycles, self)
        self._set(_state="sent", _starts=axis.core.starts)
        self._out(Busy=True)

    def _acknowledged(self) -> None:
        core = self.Axis.core
        if core.starts > self._starts:
            self._set(_cmd=core.command, _state="running")

    def _follow(self, execute: bool) -> None:
        axis: DriveAxis = self.Axis
        core = axis.core
        cmd = self._cmd
        if core.command is not cmd:
            # a later command took the channel over
            job = cmd.job
            # a continuous command (InVelocity) has no Done of its own: replaced, it is aborted
            ended_done = (job is not None and job.state == JobState.DONE) or (cmd.done and not self.CONTINUOUS)
            self._set(_final=("Done" if ended_done else "CommandAborted", 0), _state="ended")
            return
        if self._owns_register():
            axis.registers.I402 = execute
        if cmd.denied is not None or cmd.cancelled is not None:
            self._set(_final=("Error", int(cmd.denied if cmd.denied is not None else cmd.cancelled)),
                      _state="ended")
            return
        try:
            for name, reg in self.CYCLIC.items():
                axis.registers.write(reg, getattr(self, name))
        except RegisterError:
            pass                                    # the last valid set value stays
        if self.CONTINUOUS:
            self._out(**{self.DONE: cmd.done})      # InVelocity follows I92 while the command runs (Tab. 15)
        elif cmd.done:
            self._set(_final=("Done", 0), _state="ended")
            return
        job = cmd.job
        self._out(Active=(job is None or job.active) and cmd.denied is None and not cmd.waiting)

    def _holding(self) -> bool:
        """An MC_Stop block holds the command register while its Execute is TRUE (§1.6.4)."""
        return self.COMMAND == C.STOP and bool(self._prev) and self._owns_register()

    def _owns_register(self) -> bool:
        """This block wrote the last command and no other block has claimed the register since."""
        if self._cmd is None:
            return False
        core = self.Axis.core
        claimed = core.claimed
        return core.command is self._cmd and claimed is not None and claimed[1] is self

    def _show(self, execute: bool) -> None:
        final = self._final
        if self._state != "ended" or final is None:
            return
        if self.__dict__.get("_shown") and not execute:
            self._out(**_OUT, **({self.DONE: False} if self.DONE != "Done" else {}))
            self._set(_final=None)
            return
        name, error_id = final
        values = {k: False for k in ("Busy", "Active", "Done", "CommandAborted", "Error")}
        if self.DONE != "Done":
            values[self.DONE] = False
        values[name] = True
        values["ErrorID"] = error_id
        self._out(**values)
        self._set(_shown=True)


def _fb(name: str, command: int, inputs: dict[str, Any], latched: dict[str, str], cyclic: dict[str, str] = {},
        done: str = "Done", doc: str = "", continuous: bool = False) -> type:
    outputs = dict(_OUT)
    if done != "Done":
        outputs[done] = False
    cls = type(name, (MotionCommand,), {
        "COMMAND": command, "LATCHED": latched, "CYCLIC": cyclic, "DONE": done, "__doc__": doc,
        "CONTINUOUS": continuous or done != "Done",
        "INPUTS": {**MotionCommand.INPUTS, **inputs}, "OUTPUTS": outputs})
    return cls


_PROFILE = {"Velocity": 0.0, "Acceleration": 0.0, "Deceleration": 0.0, "Jerk": 0.0}
_PROFILE_REG = {"Velocity": "I404", "Acceleration": "I405", "Deceleration": "I406", "Jerk": "I407"}
_POSITIONING = {**_PROFILE, "BufferMode": 0, "BrakeAtEnd": False, "EndVelocity": 0.0}
_POSITIONING_REG = {**_PROFILE_REG, "BufferMode": "I409", "BrakeAtEnd": "I410", "EndVelocity": "I429"}

MC_MoveAbsolute = _fb("MC_MoveAbsolute", C.MOVE_ABSOLUTE, {"Position": 0.0, "Direction": 0, **_POSITIONING},
                      {"Position": "I403", "Direction": "I411", **_POSITIONING_REG},
                      doc="Command 1 (Pilz V6.5 §1.2): move to Position; Direction I411 on an endless axis.")
MC_MoveRelative = _fb("MC_MoveRelative", C.MOVE_RELATIVE, {"Distance": 0.0, **_POSITIONING},
                      {"Distance": "I403", **_POSITIONING_REG},
                      doc="Command 2 (§1.3): move Distance from the actual position at the start.")
MC_MoveAdditive = _fb("MC_MoveAdditive", C.MOVE_ADDITIVE, {"Distance": 0.0, **_POSITIONING},
                      {"Distance": "I403", **_POSITIONING_REG},
                      doc="Command 3 (§1.4): move Distance from the last valid set position.")
MC_MoveVelocity = _fb("MC_MoveVelocity", C.MOVE_VELOCITY,
                      {**_PROFILE, "BufferMode": 0, "ContinuousUpdate": 0},
                      {**_PROFILE_REG, "BufferMode": "I409", "ContinuousUpdate": "I424"},
                      done="InVelocity",
                      doc="Command 4 (§1.5): signed Velocity with position control; ContinuousUpdate = I424.")
MC_Stop = _fb("MC_Stop", C.STOP, {"Deceleration": 0.0, "Jerk": 0.0, "BrakeAtEnd": False},
              {"Deceleration": "I406", "Jerk": "I407", "BrakeAtEnd": "I410"},
              doc="Command 5 (§1.6): stop; other commands are denied until standstill and Execute = FALSE.")
MC_Home = _fb("MC_Home", C.HOME, {}, {}, doc="Command 6 (§1.7): reference with the method of I30 / A586.")
MC_CyclicSpeed = _fb("MC_CyclicSpeed", C.CYCLIC_SPEED, {"Velocity": 0.0}, {}, {"Velocity": "I426"},
                     doc="Command 7 (§1.8): follow Velocity, written to I426 on every call; Done = I92 (started).",
                     continuous=True)
MC_MoveSpeed = _fb("MC_MoveSpeed", C.MOVE_SPEED,
                   {"Velocity": 0.0, "Acceleration": 0.0, "Deceleration": 0.0, "Jerk": 0.0, "BufferMode": 0},
                   {"Jerk": "I407", "BufferMode": "I409"},
                   {"Velocity": "I426", "Acceleration": "I216", "Deceleration": "I217"}, done="InVelocity",
                   doc="Command 8 (§1.9): velocity control at Velocity (taken cyclically unless I119 = 1).")
MC_TorqueControl = _fb("MC_TorqueControl", C.TORQUE_CONTROL,
                       {"Torque": 0.0, "TorqueRampUp": 0.0, "TorqueRampDown": 0.0, "BufferMode": 0},
                       {"BufferMode": "I409"},
                       {"Torque": "I428", "TorqueRampUp": "I430", "TorqueRampDown": "I431"},
                       done="InTorque", doc="Command 9 (§1.10): torque/force control; InTorque = I92.")
MC_CyclicPosition = _fb("MC_CyclicPosition", C.CYCLIC_POSITION, {"Position": 0.0}, {}, {"Position": "I421"},
                        doc="Command 10 (§1.11): follow Position, written to I421 on every call; Done = I92.",
                        continuous=True)
MC_Halt = _fb("MC_Halt", C.HALT, {"Deceleration": 0.0, "Jerk": 0.0, "BrakeAtEnd": False},
              {"Deceleration": "I406", "Jerk": "I407", "BrakeAtEnd": "I410"},
              doc="Command 11 (§1.12): stop; a later command may take over before standstill.")

__all__ = ["INPUT_REFUSED", "MC_CyclicPosition", "MC_CyclicSpeed", "MC_Halt", "MC_Home", "MC_MoveAbsolute",
           "MC_MoveAdditive", "MC_MoveRelative", "MC_MoveSpeed", "MC_MoveVelocity", "MC_Stop", "MC_TorqueControl",
           "MotionCommand", "NOT_A_DRIVE_AXIS"]
