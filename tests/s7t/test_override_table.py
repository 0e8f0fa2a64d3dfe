"""The S7-Technology override policy (s7t/technology/override.py) against the manual's command interaction.

S7-Technology V4.1 §6.8 gives five matrices as figures the text does not carry; the expectations below are
written out by hand from what the text does say: the FB descriptions of §6.2, §6.3 and §6.7 ("Interaction of
commands", "Purpose", "Prerequisites", ErrorID tables), the legends of §6.8.1-§6.8.5 and the two examples of
§6.8.6.  Each rule names its manual lines (file 002, line numbers as in the catalogs); the cells the text
leaves open are the decisions of docs/s7t/decisions.md and are checked as decided there.  Nothing here is
taken from the code under test.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from plcmotion.kernel.job_queue import BufferMode, transition_velocity
from plcmotion.kernel.jobs import Job, JobKind
from plcmotion.kernel.policy import ABORT, KEEP, Activity, Judged, Ranked, Reject, Response
from plcmotion.s7t.technology import override as O

A, K = "A", "-"

BASIC_MOTIONS = ["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity",
                 "MC_MoveToEndPos"]
ALL_ACTIVE = list(O.COLUMNS)
SYNC_BASIC = [f"{fb} {s}" for fb in ("MC_GearIn", "MC_CamIn", "MC_GearOut", "MC_CamOut") for s in "wd"] + ["MC_Phasing"]
SYNC_SUPER = [f"{fb} {s}" for fb in ("MC_GearInSuperImposed", "MC_CamInSuperImposed", "MC_GearOutSuperImposed",
                                     "MC_CamOutSuperImposed") for s in "wd"] + ["MC_PhasingSuperImposed"]
# the FBs whose ErrorID table gives 8045 "MC_Stop active" (L12688, L13123, L13722, L14054, L14301, L14531,
# L14910, L15245, L15483, L15999, L16216, L16565, L16797, L17200, L17424, L17719, L17952, L18397; MC_Phasing's
# 8045 "no synchronous operation" L18164, which is what a stopped axis has)
STOP_8045 = ["MC_Home Mode 0/1", *BASIC_MOTIONS, "MC_MoveSuperImposed", "MC_SetTorqueLimit",
             *SYNC_BASIC, *SYNC_SUPER]
# the FBs whose ErrorID table gives 8056 "only commands that release the axis from the fixed stop"
# (L13166, L13775, L14107, L14353, L14574, L14963, L15296, L15530, L16045, L16617, L17247, L17776, L18207, L18439)
CLAMP_8056 = ["MC_SetTorqueLimit", "MC_GearIn w", "MC_GearIn d", "MC_CamIn w", "MC_CamIn d", "MC_Phasing",
              "MC_GearInSuperImposed w", "MC_GearInSuperImposed d", "MC_CamInSuperImposed w",
              "MC_CamInSuperImposed d", "MC_PhasingSuperImposed"]


def code(cell) -> str | int:
    """A cell as the manual would print it: A, -, or the ErrorID of a refusal."""
    if cell is ABORT:
        return A
    if cell is KEEP:
        return K
    if isinstance(cell, Reject):
        return O.ERROR_IDS[cell]
    raise AssertionError(f"not a fixed cell: {cell!r}")


# --- the rules R1-R20 of the catalog (part 2 §8.4), each from its manual lines -----------------------------
# (new, active) -> expected
RULES: dict[tuple[str, str], str | int] = {}


def rule(new, active, expected):
    for n in ([new] if isinstance(new, str) else new):
        for a in ([active] if isinstance(active, str) else active):
            RULES[(n, a)] = expected


# R1 MC_Power (L11986-11990): never aborted; Enable = TRUE aborts nothing; Enable = FALSE aborts all other
# commands - except MC_Stop, whose lock outlives a disable (L12815-12818) and whose CommandAborted only
# another MC_Stop sets (L12859-12861); a restarting TO is disabled already
rule("MC_Power Enable=TRUE", ALL_ACTIVE[:-1], K)
rule("MC_Power Enable=FALSE", [c for c in ALL_ACTIVE if c not in ("MC_Stop", "MC_Reset Restart")], A)
rule("MC_Power Enable=FALSE", "MC_Stop", K)
# R2 MC_Stop (L12786, L12808-12818, L12859-12861, L12873-12875): stops all motions; a new MC_Stop aborts the
# active one; while MC_Stop is active (Execute TRUE) motion commands are refused with 8045
rule("MC_Stop", [c for c in ALL_ACTIVE if c not in ("MC_Home Mode 2", "MC_ChangeDataset", "MC_SetTorqueLimit",
                                                     "MC_SetCharacteristic", "MC_Reset Restart")], A)
rule(STOP_8045, "MC_Stop", 0x8045)
# MC_Stop is no prerequisite of passive homing (L12459-12461: "no MC_Stop for Mode = 0 and 1" only), of
# MC_ChangeDataset (8045 causes L13376-13385) and of MC_SetCharacteristic (no 8045 in its table)
rule(["MC_Home Mode 2", "MC_Home Mode 3-7", "MC_ChangeDataset", "MC_SetCharacteristic", "MC_Reset"], "MC_Stop", K)
# R3 MC_Halt (L12991-12999, L13077-13078): stops all motions, overridden by every new motion command;
# a superimposed command started during MC_Halt runs superimposed (L13042-13045)
rule(["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_MoveToEndPos",
      "MC_Home Mode 0/1"], "MC_Halt", A)
rule("MC_Halt", ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_MoveToEndPos"], A)
rule("MC_MoveSuperImposed", "MC_Halt", K)
# R4/R5 override mode 0 (L13534-13537, L13874-13877, L14723-14726): the current motion is canceled
rule(["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity"],
     ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity"], A)
# R6 MC_MoveAdditive overrides the active command (L14148, L14253-14256)
rule("MC_MoveAdditive", ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_Halt"], A)
# R7 MC_MoveSuperImposed (L14397-14401): active positioning and synchronous operation go on; it replaces an
# active MC_MoveSuperImposed
rule("MC_MoveSuperImposed", ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity",
                             "MC_MoveToEndPos", *SYNC_BASIC, *SYNC_SUPER], K)
rule("MC_MoveSuperImposed", "MC_MoveSuperImposed", A)
# R8 MC_MoveToEndPos (L15029-15031): other motion commands override it before the end stop
rule(BASIC_MOTIONS[:-1], "MC_MoveToEndPos", A)
# ... active homing is refused while it is active (MC_Home 8045, L12695-12696)
rule("MC_Home Mode 0/1", ["MC_MoveToEndPos", "MC_MoveToEndPos InClamping"], 0x8045)
# R9 (L12585-12586): only in Mode 7 configuration are superimposing motions not canceled by basic motions
rule(["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_MoveToEndPos",
      "MC_Home Mode 0/1"], ["MC_MoveSuperImposed", *SYNC_SUPER], A)
# R10 (L16099-16101): MC_Halt, MC_Stop, MC_MoveRelative/Additive/Absolute/Velocity, MC_MoveToEndPos end the
# synchronous operation of the following axis
rule(["MC_Halt", "MC_Stop", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveAbsolute", "MC_MoveVelocity",
      "MC_MoveToEndPos"], SYNC_BASIC, A)
# R11 (L15749-15752, L16478-16485): a new MC_GearIn changes the running gearing - it replaces it once it drives
rule("MC_GearIn d", ["MC_GearIn d", "MC_GearIn w"], A)
rule("MC_GearInSuperImposed d", ["MC_GearInSuperImposed d", "MC_GearInSuperImposed w"], A)
# R12 (L16085-16087, L16660-16663, L17820-17823): basic and superimposed synchronism are independent
rule(["MC_GearOut w", "MC_GearOut d", "MC_CamOut w", "MC_CamOut d"], ["MC_MoveSuperImposed", *SYNC_SUPER], K)
rule(["MC_GearOutSuperImposed w", "MC_GearOutSuperImposed d", "MC_CamOutSuperImposed w",
      "MC_CamOutSuperImposed d"], SYNC_BASIC, K)
# R15 (§6.8.6 example 2) phasing is superimposed on the synchronous operation
rule("MC_Phasing", ["MC_GearIn d", "MC_CamIn d", "MC_GearOut w"], K)
rule("MC_PhasingSuperImposed", ["MC_GearInSuperImposed d", "MC_CamInSuperImposed d"], K)
# R16 (L15568-15570): a repeated MC_SetCharacteristic cancels the previous one
rule("MC_SetCharacteristic", "MC_SetCharacteristic", A)
# R17 (L21260-21261, L21381): the restarting TO accepts no command; a second MC_Reset gets 8045 - except MC_Stop,
# whose table (L12876-12985) has no 8045 and whose lock holds through the restart (decision D28)
rule([r for r in O.ROWS if r not in ("MC_Power Enable=FALSE", "MC_Stop")], "MC_Reset Restart", 0x8045)
rule("MC_Stop", "MC_Reset Restart", K)
# 8056: a clamped axis refuses what does not release it (list above); MC_Stop still stops (no 8056, L12876-12985)
rule(CLAMP_8056, "MC_MoveToEndPos InClamping", 0x8056)
rule("MC_Stop", "MC_MoveToEndPos InClamping", A)


@pytest.mark.parametrize("new, active", sorted(RULES))
def test_s7t_override_rules_of_the_fb_texts(new, active):
    """S7-Technology V4.1 §6.2/§6.3/§6.7 FB texts (catalog part 2 R1-R20): the cell of each (new, active)."""
    assert code(O.POLICY.cell(new, active)) == RULES[(new, active)], (new, active)


# --- §6.8.6 worked examples and the legends (Wa, S, Abort 2, Abort 3, Superimposed abort) --------------------
def _activity(cls, job=None):
    return Activity(cls, job, lambda t: None)


def test_s7t_override_example_1_waiting_abort():
    """S7-Technology V4.1 §6.8.6 example 1 (L24538-24545): MC_GearIn waits ("w"), a new MC_GearOut whose
    condition is not met ("w"): "Wa" - the GearOut waits, the GearIn is aborted when its condition is met."""
    assert O.POLICY.cell("MC_GearOut w", "MC_GearIn w") is KEEP
    assert O.POLICY.cell("MC_GearOut d", "MC_GearIn w") is ABORT


def test_s7t_override_example_2_superimposed():
    """S7-Technology V4.1 §6.8.6 example 2 (L24547-24553): MC_GearIn "d" (InGear) and MC_GearOut "w" active, a
    new MC_Phasing: "S" - superimposed, neither active command aborted."""
    actives = [_activity("MC_GearIn d"), _activity("MC_GearOut w")]
    assert [O.POLICY.decide("MC_Phasing", None, a) for a in actives] == [KEEP, KEEP]


def test_s7t_override_abort_2_and_abort_3_legends():
    """S7-Technology V4.1 §6.8.4 legend (L24392-24404): Abort 2 - a waiting command is canceled at once, an
    active one when the new command's condition is met; Abort 3 - the second active command is canceled at
    once, the first goes on.  Active: MC_GearIn "d" + MC_GearOut "w"; new: MC_GearIn (waiting)."""
    assert O.POLICY.cell("MC_GearIn w", "MC_GearOut w") is ABORT          # the second active one: at once
    assert O.POLICY.cell("MC_GearIn w", "MC_GearIn d") is KEEP            # the first goes on ...
    assert O.POLICY.cell("MC_GearIn d", "MC_GearIn d") is ABORT           # ... until the new one drives


def test_s7t_override_superimposed_abort_legend():
    """S7-Technology V4.1 §6.8.1 legend "Superimposed abort" (L24276-24281): the new motion runs superimposed;
    it is canceled when the active command's condition is met (the active row applied again)."""
    assert O.POLICY.cell("MC_Phasing", "MC_GearIn w") is KEEP
    assert O.POLICY.cell("MC_GearIn d", "MC_Phasing") is ABORT


# --- "Abort direction" (§6.2.11, L15029-15041) ---------------------------------------------------------------
def _end_pos(side, clamped=True, at=100.0):
    job = Job(JobKind.VELOCITY, velocity=5.0 * side, extra={"fb": "MC_MoveToEndPos", "heading": side,
                                                           "clamped": clamped})
    job.target = at
    return job


@pytest.mark.parametrize("new, expected", [
    (Job(JobKind.RELATIVE, position=-5.0), A),                 # away from a stop on the positive side
    (Job(JobKind.RELATIVE, position=5.0), 0x8056),             # toward it
    (Job(JobKind.ABSOLUTE, position=50.0), A),
    (Job(JobKind.ABSOLUTE, position=150.0), 0x8056),
    (Job(JobKind.VELOCITY, velocity=-10.0), A),
    (Job(JobKind.VELOCITY, velocity=10.0), 0x8056),
    (Job(JobKind.HALT), 0x8056),                               # MC_Halt lists 8056 (L13166-13172)
])
def test_s7t_override_clamped_axis_accepts_only_release(new, expected):
    """S7-Technology V4.1 §6.2.11 (L15032-15035) and ErrorID 8056 (L13775-13781): clamped, only commands that
    move the axis away from the end stop; they abort MC_MoveToEndPos ("Abort direction")."""
    running = _activity(O.instruction(_end_pos(+1)), _end_pos(+1))
    assert running.cls == "MC_MoveToEndPos InClamping"
    assert code(O.POLICY.decide(O.instruction(new), new, running)) == expected


@pytest.mark.parametrize("distance, expected", [(1.0, K), (-1.0, 0x8056)])
def test_s7t_override_clamped_axis_and_superimposed_motion(distance, expected):
    """S7-Technology V4.1 §6.2.9 ErrorID 8056 (L14574-14580): MC_MoveSuperImposed toward the stop is refused;
    away it runs superimposed (L14397)."""
    new = Job(JobKind.SUPERIMPOSED, position=distance)
    running = _activity("MC_MoveToEndPos InClamping", _end_pos(-1, at=-20.0))   # the stop on the negative side
    assert code(O.POLICY.decide("MC_MoveSuperImposed", new, running)) == expected


@pytest.mark.parametrize("clamped, reverse, expected", [
    (False, False, A), (False, True, 0x0029), (True, False, A), (True, True, 0x8045)])
def test_s7t_override_end_pos_on_end_pos(clamped, reverse, expected):
    """S7-Technology V4.1 §6.2.11 (L15040-15041, warning 0029 L15186-15191, 8045 L15247-15249): a new
    MC_MoveToEndPos overrides an active one only in the same effective direction."""
    active = _end_pos(+1, clamped=clamped)
    new = _end_pos(-1 if reverse else +1, clamped=False)
    assert code(O.POLICY.decide("MC_MoveToEndPos", new, _activity(O.instruction(active), active))) == expected
    assert (expected in O.WARNINGS) is (expected == 0x0029)


# --- Mode 0/1/2 (§6.2.6, §6.2.7, §6.2.10; catalog part 2 §8.5) --------------------------------------------
def test_s7t_override_mode_maps_to_buffer_modes():
    """S7-Technology V4.1 §6.2.6 Mode (L13534-13545): 0 override, 1 append (stop at the transition), 2 overlay;
    the overlay passes the old target at the lower of the two velocities, at 0 when the direction reverses."""
    assert [O.POLICY.buffer_mode(m) for m in (0, 1, 2)] == [BufferMode.ABORTING, BufferMode.BUFFERED,
                                                            BufferMode.BLENDING_LOW]
    assert transition_velocity(O.POLICY.buffer_mode(2), 50.0, 15.0, reverses=False) == 15.0
    assert transition_velocity(O.POLICY.buffer_mode(2), 10.0, 15.0, reverses=False) == 10.0
    assert transition_velocity(O.POLICY.buffer_mode(2), 50.0, 15.0, reverses=True) == 0.0
    assert transition_velocity(O.POLICY.buffer_mode(1), 50.0, 15.0, reverses=False) == 0.0
    with pytest.raises(ValueError):
        O.POLICY.buffer_mode(3)
    assert O.POLICY.queue_depth == 1                          # one command appended (8005 beyond)


APPEND_RULES = {
    # 8055 (L13765-13773, L14097-14103, L14953-14961): a basic or superimposed synchronization command, MC_Halt
    **{(n, a): 0x8055 for n in O.APPENDABLE for a in [*SYNC_BASIC, *SYNC_SUPER, "MC_Halt"]},
    # L14636-14638: MC_MoveVelocity is never appended to an active MC_MoveVelocity
    ("MC_MoveVelocity", "MC_MoveVelocity"): 0x8055,
    # 8045 while MC_Stop is active (L13722, L14054, L14910)
    **{(n, "MC_Stop"): 0x8045 for n in O.APPENDABLE},
    # the manual's append example (L14849-14862): MC_MoveVelocity appended to a MC_MoveRelative
    ("MC_MoveVelocity", "MC_MoveRelative"): None,
    ("MC_MoveAbsolute", "MC_MoveRelative"): None, ("MC_MoveRelative", "MC_MoveAbsolute"): None,
    ("MC_MoveAbsolute", "MC_MoveVelocity"): None,
}


@pytest.mark.parametrize("new, active", sorted(APPEND_RULES))
def test_s7t_override_appending_rules(new, active):
    """S7-Technology V4.1 §6.2.6/§6.2.7/§6.2.10 "Prerequisites" for Mode = 1, 2 and ErrorIDs 8055/8045."""
    job = Job({"MC_MoveAbsolute": JobKind.ABSOLUTE, "MC_MoveRelative": JobKind.RELATIVE,
               "MC_MoveVelocity": JobKind.VELOCITY}[new])
    refusal = O.POLICY.append_refusal(job, [_activity(active)])
    assert (None if refusal is None else O.ERROR_IDS[refusal]) == APPEND_RULES[(new, active)]


# --- job classes -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("job, cls", [
    (Job(JobKind.ABSOLUTE), "MC_MoveAbsolute"), (Job(JobKind.RELATIVE), "MC_MoveRelative"),
    (Job(JobKind.RELATIVE, extra={"fb": "MC_MoveAdditive"}), "MC_MoveAdditive"),
    (Job(JobKind.VELOCITY), "MC_MoveVelocity"), (Job(JobKind.HALT), "MC_Halt"), (Job(JobKind.STOP), "MC_Stop"),
    (Job(JobKind.SUPERIMPOSED), "MC_MoveSuperImposed"), (Job(JobKind.HOME_ACTIVE), "MC_Home Mode 0/1"),
    (Job(JobKind.HOME_PASSIVE), "MC_Home Mode 2"), (Job(JobKind.HOME_DIRECT), "MC_Home Mode 3-7"),
    (Job(JobKind.HOME_CANCEL), "MC_Home Mode 8"), (Job(JobKind.GEAR_IN), "MC_GearIn d"),
    (Job(JobKind.GEAR_IN_POS), "MC_GearIn w"), (Job(JobKind.CAM_IN, start_sync=True), "MC_CamIn d"),
    (Job(JobKind.CAM_IN), "MC_CamIn w"), (Job(JobKind.PHASING), "MC_Phasing"),
    (Job(JobKind.VELOCITY, extra={"fb": "MC_MoveToEndPos"}), "MC_MoveToEndPos"),
    (Job(JobKind.VELOCITY, extra={"fb": "MC_MoveToEndPos", "clamped": True}), "MC_MoveToEndPos InClamping"),
    (Job(JobKind.GEAR_IN, extra={"fb": "MC_GearOut"}), "MC_GearOut d"),
    (Job(JobKind.GEAR_IN_POS, extra={"fb": "MC_GearOutSuperImposed"}), "MC_GearOutSuperImposed w"),
])
def test_s7t_override_job_classes(job, cls):
    assert O.instruction(job) == cls


def test_s7t_override_unknown_job_is_named():
    with pytest.raises(ValueError, match="S7-Technology"):
        O.instruction(Job(JobKind.TABLE))


def test_s7t_override_error_ids_of_kernel_refusals():
    """S7-Technology V4.1 ErrorIDs 8005 (command memory full, L26815-26833) and 8055 for the job queue's own
    refusals; unrelated faults have none here."""
    from plcmotion.kernel import faults as F
    assert O.error_id(F.reject(F.QUEUE_FULL, "1")) == 0x8005
    assert O.error_id(F.reject(F.NOT_APPENDABLE, "home_active")) == 0x8055
    assert O.error_id(O.STOP_ACTIVE.fault()) == 0x8045
    assert O.error_id(F.reject(F.NOT_ENABLED)) is None


# --- invariants ----------------------------------------------------------------------------------------------
@given(st.sampled_from(O.ROWS), st.sampled_from(O.COLUMNS))
def test_s7t_override_every_pair_has_a_cell(new, active):
    """Every (new, active) pair of the §6.8 tables has a cell written in the table (none falls back to the
    policy's default), of a kind the kernel applies."""
    assert active in O.TABLE[new]
    assert isinstance(O.TABLE[new][active], (Response, Reject, Judged, Ranked))


_FLOATS = st.floats(allow_nan=True, allow_infinity=True)


@given(st.sampled_from(O.ROWS), st.sampled_from(O.COLUMNS),
       st.sampled_from([JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.HALT, JobKind.SUPERIMPOSED]),
       _FLOATS, _FLOATS, st.sampled_from([-1, 0, 1]), _FLOATS, st.booleans())
def test_s7t_override_every_decision_is_defined(new, active, kind, position, velocity, side, at, with_job):
    """Whatever the jobs (also NaN or infinite inputs, no job at all): a decision is ABORT, KEEP or a Reject
    with an ErrorID; a clamped axis is never released toward its stop."""
    new_job = Job(kind, position=position, velocity=velocity) if with_job else None
    run = _end_pos(side, at=at) if active.startswith("MC_MoveToEndPos") else None
    answer = O.POLICY.decide(new, new_job, _activity(active, run))
    assert answer in (ABORT, KEEP) or answer in O.ERROR_IDS
    if active == "MC_MoveToEndPos InClamping" and answer is ABORT and new != "MC_Power Enable=FALSE" \
            and new != "MC_Stop" and new != "MC_MoveToEndPos":
        way = O.heading(new_job, at)
        assert side != 0 and way == -side and not math.isnan(way)


def test_s7t_override_kernel_class_names_are_the_synchronous_rows():
    """Kernel code that starts a coupling or reports one names it by the kernel's classes (gear_in,
    sync_active, sync_waiting, phasing); for the S7-Technology policy they are MC_GearIn "d"/"w" and
    MC_Phasing, as rows and as columns."""
    from plcmotion.kernel import policy as P
    for kernel_name, ours in ((P.GEAR_IN, "MC_GearIn d"), (P.SYNC_ACTIVE, "MC_GearIn d"),
                              (P.SYNC_WAITING, "MC_GearIn w"), (P.PHASING, "MC_Phasing")):
        for other in O.COLUMNS:
            assert O.POLICY.cell(kernel_name, other) == O.POLICY.cell(ours, other), (kernel_name, other)
        for row in O.ROWS:
            assert O.POLICY.cell(row, kernel_name) == O.POLICY.cell(row, ours), (row, kernel_name)
