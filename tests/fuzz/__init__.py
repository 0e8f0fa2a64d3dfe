"""plcmotion's fuzzer (issue 8): random instruction sequences against every dialect, invariants checked
after every application cycle (and the setpoint dynamics in every servo cycle).

Modules: ``values`` (input values and their source form), ``gen`` (random episodes: controller, technology
objects, instruction instances, timed input changes and tag writes), ``runner`` (executes an episode and
checks the invariants), ``repro`` (shrinking, reproducer scripts, the FB call log), ``campaign`` (seeded
multi-process campaigns), ``machine`` (the hypothesis RuleBasedStateMachine), ``test_fuzz`` (the CI run),
``__main__`` (``python -m tests.fuzz``).

What is driven
--------------
Dialects S7-1200 V6, S7-1200 V7 (``technology_version=7``), S7-1500 and S7-1500T (S7-Technology: below);
1-2 positioning axes
(S7-1200: Actor.Type 0 analog, 1 PROFIdrive, 2 PTO, optionally simulated, homing switch; S7-1500: real
analog/PROFIdrive, virtual or simulated), up to 2 following axes, cams (linear, cubic, Bézier, with and
without boundary conditions), a command table, a leading axis proxy whose telegrams are sometimes NaN,
1e300, far ahead or missing; modulo axes, SW limit switches.  Instruction inputs get plausible values
mostly and otherwise NaN, ±inf, ±1e300, 1e-300, ints beyond the float range (10**400), None, str, lists,
out-of-range INT selectors; Execute/Enable/Jog toggles; Axis/Master/Slave/Cam rewired while busy;
MC_ChangeDynamic, direct writes of DynamicDefaults/DynamicLimits/Override/SW limit tags mid-motion;
MC_WriteParam/MC_ReadParam with random tag paths and values.  BOOL inputs only get booleans: a non-boolean
at a BOOL input raises TypeError by design (a programming error, as a PLC would not compile it; fb.py);
likewise a direct tag write of a non-number to a REAL tag may raise TypeError/TagAccessError.

Invariants and their scope
--------------------------
1. exception: no exception escapes an instruction call, a tag write of a number, or ``Controller.step()``.
2. stop: the controller stays in RUN (the harness calls the instructions itself and registers no program,
   so every STOP, e.g. "internal error in the servo cycle", is a failure).
3. internal: no instruction shows ErrorID 16#8FFF and no axis records an internal error
   (``PositioningAxis.last_internal_error``: a kernel exception isolated to one axis).
   S7-1500/S7-1500T (kind "errorid"): an instruction's ErrorID is 0 or a code of the CPU's list that
   instruction can give (``plcmotion.s7_1500.errors.INSTRUCTION_CODES``), and Error never shows 0.
4. nonfinite: every servo cycle, the bank arrays sp_p, sp_v, sp_a, act_p, act_v, cmd_v, fe
   (kernel/bank.py) are finite for the episode's axes; after each application cycle the tags Position,
   Velocity, ActualPosition, ActualVelocity are finite.
5. velocity / acceleration / jerk: the peak over the servo cycles of |setpoint velocity| stays within the
   largest DynamicLimits.MaxVelocity the axis had (tag or effective value; +0.1 % + 1e-6), |setpoint
   acceleration| within the largest acceleration the axis was configured with (S7-1200: DynamicDefaults
   Acceleration/Deceleration/EmergencyDeceleration, incl. values set by MC_ChangeDynamic or writes;
   S7-1500: DynamicLimits.MaxAcceleration/MaxDeceleration and DynamicDefaults.EmergencyDeceleration, since
   an emergency stop may brake harder than MaxDeceleration), |setpoint jerk| within the largest jerk
   (S7-1200 DynamicDefaults.Jerk, S7-1500 DynamicLimits.MaxJerk) unless a jerk of 0 (no jerk limitation)
   was in force at some time.  Scope: only while the axis is enabled (or, for the velocity only, stopping
   after a disable: S7-1200 StopMode 1 is an immediate stop without deceleration bound) and position
   setpoints are generated
   (not while the setpoint follows the actual value); not for an axis in synchronous operation (waiting,
   synchronizing, synchronous, phasing, leading value additive, simulated synchronous motion) or with a
   superimposed motion - a following axis follows its leading value (S7-1500T decision 49: "the
   synchronous motion is limited only by the drive"), and a superimposed motion adds to the basic one;
   after such a coupling ends, not until the setpoint velocity is back within MaxVelocity (braking from
   the synchronous velocity).  The bounds are the largest values ever configured, so the check catches
   runaways (defect 1: 16-128 x MaxVelocity), not a slightly wrong ramp.
6. swlimit: on a homed, non-modulo axis with effective SW limits, not in synchronous operation, the
   setpoint and actual positions go beyond a limit by at most the braking distance from the velocity the
   axis had when last inside (v^2 / 2a with the smallest of Deceleration/EmergencyDeceleration
   (S7-1200) or MaxDeceleration/EmergencyDeceleration (S7-1500), plus two application cycles, the jerk
   build-up time, the drive's off ramp (Plant.OffRampTime: a PROFIdrive/analog axis loses its enable at
   the limit, decision 21) and the following error; +10 % for the approximations of this bound).  Limits
   changed while outside and coordinate jumps (homing) are not judged.
7. exclusive: on every instruction with Done or CommandAborted outputs, at most one of Done,
   CommandAborted, Error is TRUE and never together with Busy (PLCopen; S7-1200 V6 §9.5.2-§9.5.4); InVelocity,
   InGear and InSync only with Busy and without Error/CommandAborted.  MC_Power and the Enable-type
   instructions (MC_ReadParam, MC_LeadingValueAdditive, MC_SynchronizedMotionSimulation) are exempt: their
   Error may come with Busy.
8. stuck (bounded): MC_MoveAbsolute/-Relative, MC_Halt, MC_Reset, MC_MoveSuperimposed, MC_Phasing*,
   the cam instructions, MC_ChangeDynamic and MC_WriteParam are not Busy for more than 2.5 s of virtual time
   while all axes their job started on stand still (setpoint velocity and acceleration exactly 0, actual
   velocity below 1e-6) and the override is
   not 0 %.  After the last cycle an episode runs on (without new operations) while such an instruction
   is Busy at standstill, up to that bound.  Not checked: instructions that may wait legitimately (MC_Home
   passive modes, MC_GearInPos/MC_CamIn waiting for the leading axis, MC_CommandTable wait steps,
   velocity and jog commands, MC_Stop holding the axis while Execute is TRUE).
9. setup: a generated configuration (always within the documented ranges) is accepted.

S7-Technology (``gen_s7t``, only with ``--dialect S7-Technology``: seeds without a dialect draw from the
four dialects above as before, so old seeds give the same episodes): 1-4 speed-controlled, positioning and
synchronization axes, real or virtual, modulo, SW limits on/off, "Homing required" YES/NO; MC_Power (Mode,
StopMode, QOutputValue), MC_Reset (with/without Restart, also on the MCDevice DB), MC_Stop (held),
MC_Halt, MC_MoveAbsolute/-Relative/-Additive/-SuperImposed/-Velocity with Mode/Direction/DoneFlag in and
out of range, ``Axis`` as object, as DB number (valid, MCDevice, none, wrong type); rapid Execute and
MC_Power toggling, appended and overlaid commands.  The invariants above apply with the family's tags
(TypeOfAxis.MaxVelocity/MaxAcceleration/MaxJerk.maximum, EmergencyRampGenerator.maxDeceleration,
swlimit.*), and instead of 4. and 7.: the REAL members of the technology DB are finite after every cycle;
at most one of Done/CommandAborted/Error (MC_MoveVelocity: InVelocity without Busy counts as Done), none
with Busy (S7-Technology V4.1 §5.8); 10. errorid: ErrorID is 0 or a code of the FB's table of §6
(``plcmotion.s7t.fb_errors.fb_codes``), Error only with an 16#8xxx code; 16#8001 (internal error) is a
failure of kind "internal"; 6. also strictly: a generated setpoint does not pass an effective SW limit
switch at all (§4.5.7.3: the axis travels up to the switch).

S7-Technology part 1 beyond the motion commands (``gen_s7t_objects``, ``gen_s7t_values``, ``gen_s7t_scenarios``):
hydraulic axes on Q and P/Q valves (force limit, output limits 1401/1402, load force, valve overlap) with cam
disks as valve profiles; homing configurations (homingMode 22/23/24/88, passive modes, reference cam and
external zero mark inputs, zero marks, distance monitoring) on the simulated plant near the start; 2-4 data
sets with every changeMode; fixed end stops with recognitionMode 105-107 on telegrams 102/105/106; the FBs
MC_Home (Mode 0-9), MC_ChangeDataset, MC_MoveToEndPos, MC_SetTorqueLimit, MC_SetCharacteristic,
MC_ReadSysParameter / MC_WriteParameter (numbers of §9.4 and invalid ones, values in and out of range, NaN,
inf, huge, ENUM codes), MC_Read/WritePeriphery, MC_Read/WriteRecord, MC_Read/WriteDriveParameter (valid and
wrong addresses, empty / short / long / read-only / missing areas), MC_ActivateTO and MC_ActivateDPSlave
(deactivation while moving, commands to a deactivated object).  Further invariants (``oracle_s7t``):
11. exclusive: MC_ReadPeriphery DataValid only with Busy and without Error (§6.7.6); MC_MoveToEndPos
InClamping only with Busy, without Error/CommandAborted (§6.2.11);
12. nonfinite: MC_ReadSysParameter.Value is finite; a hydraulic axis's valve output and cylinder force are
finite;
13. errorid: MC_ActivateTO / MC_ActivateDPSlave Status is one of the manual's (§6.7.2, §6.7.3); a read record /
drive parameter is Done with DataLength within its Data area;
14. dataset: at the rising Done of MC_ChangeDataset the data set it was started with is in force (§6.2.5);
15. homing: at the rising Done of MC_Home Mode 0, 1, 2, 3 or 5 the axis is homed (§6.2.2);
16. activation: a deactivated axis is disabled and its setpoint velocity is 0 (§6.7.2);
17. hydraulic: the valve output stays within the effective manipulated variable limits (1401/1402, one
count of the output word of tolerance); stuck: the §6.7 FBs, MC_SetTorqueLimit and MC_SetCharacteristic are
not Busy longer than 2.5 s.

Not checked (yet): HW limit switches, physical drive behaviour (the simulated drive's actual values are
only required to be finite), following error or positioning monitoring alarms, the exact ramps of the
manual's function charts (the acceptance tests do that), user programs (the harness has none).
"""
