"""Helpers for the audit tests (independent of the product's own test helpers)."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_Power

V = {"VirtualAxis": {"Mode": 1}}
DYN = {"DynamicDefaults": {"Velocity": 100.0, "Acceleration": 500.0, "Deceleration": 800.0, "Jerk": 0.0,
                           "EmergencyDeceleration": 4000.0},
       "DynamicLimits": {"MaxVelocity": 1000.0, "Velocity": 1000.0, "MaxAcceleration": 5000.0,
                         "MaxDeceleration": 6000.0, "MaxJerk": 0.0}}


def merge(*dicts):
    out = {}
    for d in dicts:
        for k, v in d.items():
            if isinstance(v, dict) and isinstance(out.get(k), dict):
                out[k] = merge(out[k], v)
            else:
                out[k] = v
    return out


class AxisRig:
    """One S7-1500 positioning axis, enabled by MC_Power; ``steps`` are called every application cycle;
    ``rec`` collects one dict per cycle from ``record``."""

    def __init__(self, params=None, *, family="S7-1500", virtual=True, synchronous=False, stop_mode=0,
                 enable=True):
        self.ctl = Controller(family=family)
        cfg = merge(V if virtual else {}, DYN, params or {})
        if synchronous:
            self.axis = self.ctl.add_synchronous_axis("Axis", cfg)
        else:
            self.axis = self.ctl.add_positioning_axis("Axis", cfg)
        self.power = MC_Power()
        self.en = {"on": enable, "stop_mode": stop_mode}
        self.steps = []
        self.rec = []
        self.record = None

        @self.ctl.program
        def main():
            self.power(Axis=self.axis, Enable=self.en["on"], StopMode=self.en["stop_mode"])
            for s in self.steps:
                s()
            if self.record is not None:
                self.rec.append(self.record())
        if enable:
            self.ctl.run_until(lambda: self.power.Status, timeout=2.0)

    def call(self, fb, **inputs):
        """Call ``fb`` every cycle with ``inputs`` (a dict that the test may change)."""
        self.steps.append(lambda: fb(Axis=self.axis, **inputs))
        return inputs

    def run_until(self, cond, timeout=5.0):
        return self.ctl.run_until(cond, timeout=timeout)

    def run(self, s):
        self.ctl.run(s)

    def step(self, n=1):
        for _ in range(n):
            self.ctl.step()

    def home(self, pos=0.0):
        from plcmotion.s7_1500 import MC_Home
        h = MC_Home()
        inp = self.call(h, Execute=True, Mode=0, Position=pos)
        self.run_until(lambda: h.Done, 1.0)
        inp["Execute"] = False
        self.step()
        return h
