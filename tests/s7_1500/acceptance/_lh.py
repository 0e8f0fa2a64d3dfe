"""Helpers for the leading-value audit tests (written from the S7-1500T V5 manual)."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_GearIn, MC_Power

VIRTUAL = {"VirtualAxis": {"Mode": 1}}
FINE = {"Sensor[1]": {"Parameter": {"DistancePerRevolution": 100.0, "StepsPerRevolution": 1 << 20}}}


def encoder_rig(extrapolation=None, plant=None, coupling="actual", servo_cycle=0.001, app_cycle=0.004,
                extra=None, followers=(("S", "actual"),)):
    """An external encoder (fine resolution) and followers geared 1:1 to it via MC_GearIn."""
    ctl = Controller(family="S7-1500T", servo_cycle=servo_cycle, app_cycle=app_cycle)
    cfg = {"Sensor": FINE, "Extrapolation": extrapolation or {}}
    if plant:
        cfg["Plant"] = plant
    if extra:
        cfg.update(extra)
    enc = ctl.add_external_encoder("Enc", cfg)
    fol = [ctl.add_synchronous_axis(name, VIRTUAL, leading_values=[("Enc", mode)]) for name, mode in followers]
    pe = MC_Power()
    pf = [MC_Power() for _ in fol]
    gears = [MC_GearIn() for _ in fol]
    state = {"gear": True}

    @ctl.program
    def main():
        pe(Axis=enc, Enable=True)
        for p, ax, g in zip(pf, fol, gears):
            p(Axis=ax, Enable=True)
            g(Master=enc, Slave=ax, Execute=state["gear"] and pe.Status and p.Status)
    return ctl, enc, fol, gears, state


def check_error_outputs(*instances):
    """Error is never TRUE with ErrorID 0 (and an ErrorID is shown only with Error)."""
    for i in instances:
        if getattr(i, "Error", False):
            assert i.ErrorID != 0, f"{type(i).__name__}: Error TRUE with ErrorID 0"
