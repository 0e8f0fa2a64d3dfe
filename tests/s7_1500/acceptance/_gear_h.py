"""A small harness independent of the product's test rig: one controller, masters and following axes,
an MC_Power each, and a list of program steps called every application cycle."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_Power, MC_MoveVelocity

VIRTUAL = {"VirtualAxis": {"Mode": 1}}


def modulo(length=360.0):
    return {"Modulo": {"Enable": True, "Length": length, "StartValue": 0.0}}


def merge(a, b):
    out = dict(a)
    for k, v in b.items():
        out[k] = merge(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


class H:
    def __init__(self, masters=1, slaves=1, family="S7-1500T", mp=None, sp=None, leading=None):
        self.ctl = Controller(servo_cycle=0.001, app_cycle=0.004, family=family)
        self.masters = [self.ctl.add_positioning_axis(f"M{i+1}", mp or VIRTUAL) for i in range(masters)]
        names = leading if leading is not None else [m.name for m in self.masters]
        self.slaves = [self.ctl.add_synchronous_axis(f"S{i+1}", sp or VIRTUAL, leading_values=names)
                       for i in range(slaves)]
        self.power = {a.name: MC_Power() for a in self.masters + self.slaves}
        self.en = {a.name: True for a in self.masters + self.slaves}
        self.steps = []
        self.rows = []
        self.rec = None
        self.ctl.program(self._main)

    def _main(self):
        for a in self.masters + self.slaves:
            self.power[a.name](Axis=a, Enable=self.en[a.name])
        for s in self.steps:
            s()
        if self.rec is not None:
            self.rows.append(self.rec())

    @property
    def m(self):
        return self.masters[0]

    @property
    def s(self):
        return self.slaves[0]

    def enabled(self):
        return all(p.Status for p in self.power.values())

    def until(self, cond, timeout=5.0):
        return self.ctl.run_until(cond, timeout=timeout)

    def run(self, sec):
        self.ctl.run(sec)

    def step(self, n=1):
        for _ in range(n):
            self.ctl.step()

    def call(self, fb, inputs):
        """Call ``fb`` every cycle with ``inputs`` (a dict that the test may change)."""
        self.steps.append(lambda: fb(**inputs))
        return inputs

    def move_master(self, v, idx=0, wait=True):
        mv = MC_MoveVelocity()
        inp = {"Axis": self.masters[idx], "Execute": False, "Velocity": v, "Acceleration": 1e4, "Deceleration": 1e4,
               "Jerk": 0.0}
        self.steps.append(lambda: mv(**dict(inp, Execute=inp["Execute"] and self.enabled())))
        inp["Execute"] = True
        if wait:
            self.until(lambda: mv.InVelocity, 3.0)
        return mv, inp


def outputs_consistent(fb):
    """Generic rules: Error never TRUE with ErrorID 0; ErrorID 0 when no Error; at most one of the final outputs."""
    o = fb.outputs
    problems = []
    if o.get("Error") and not o.get("ErrorID"):
        problems.append("Error with ErrorID 0")
    if not o.get("Error") and o.get("ErrorID"):
        problems.append("ErrorID without Error")
    finals = [k for k in ("Done", "CommandAborted", "Error") if o.get(k)]
    if len(finals) > 1:
        problems.append(f"several final outputs {finals}")
    if o.get("Busy") and finals:
        problems.append(f"Busy together with {finals}")
    for k in ("InGear", "InSync", "StartSync"):
        if o.get(k) and not o.get("Busy"):
            problems.append(f"{k} without Busy")
    return problems
