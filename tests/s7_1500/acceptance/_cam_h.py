"""Helpers: a controller with a cam, and running Execute-type instructions to completion."""
from plcmotion import Controller
from plcmotion.s7_1500 import MC_InterpolateCam

HUMP = [(0, 0), (90, 40), (180, 100), (270, 40), (360, 0)]


def cam_rig(points=HUMP, segments=(), **settings):
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam", points, segments=segments, **settings)
    return ctl, cam


def run_fb(ctl, fb, cycles=10, **inputs):
    """Rising edge, then call once per servo cycle until Done or Error. Returns a list of output snapshots."""
    trace = []
    fb(Execute=False, **inputs)
    fb(Execute=True, **inputs)
    trace.append({k: getattr(fb, k) for k in ("Done", "Busy", "Error", "ErrorID")})
    for _ in range(cycles):
        if fb.Done or fb.Error:
            break
        ctl.step()
        fb(Execute=True, **inputs)
        trace.append({k: getattr(fb, k) for k in ("Done", "Busy", "Error", "ErrorID")})
    return trace


def interpolate(ctl, cam):
    fb = MC_InterpolateCam()
    run_fb(ctl, fb, Cam=cam)
    assert fb.Done, (fb.Error, hex(fb.ErrorID))
    return fb


def check_outputs_consistent(trace):
    for row in trace:
        assert not (row["Error"] and row["ErrorID"] == 0), row
        assert sum(bool(row[k]) for k in ("Done", "Busy", "Error")) <= 1, row


# ---------------------------------------------------------------------------------------------------
from plcmotion.s7_1500 import MC_CamIn, MC_MoveVelocity  # noqa: E402
from _s7_1500_rig import Rig  # noqa: E402

CAMIN_OUT = ("StartSync", "InSync", "Busy", "CommandAborted", "Error", "ErrorID", "EndOfProfile")


class Camming:
    """A master (virtual) driven by MC_MoveVelocity, a following axis and MC_CamIn instances.
    Everything is recorded once per application cycle in ``log``."""

    def __init__(self, cams=None, mode=0, boundary=0, slave_params=None, master_params=None, n_camin=1):
        self.rig = rig = Rig(slave_params=slave_params, master_params=master_params)
        self.ctl = rig.ctl
        cams = cams if cams is not None else {"Cam": HUMP}
        self.cams = {n: rig.ctl.add_cam(n, pts, interpolation_mode=mode, boundary_conditions=boundary)
                     for n, pts in cams.items()}
        self.mv = MC_MoveVelocity()
        self.mvin = {"Execute": False, "Velocity": 0.0}
        self.ci = [MC_CamIn() for _ in range(n_camin)]
        self.ciin = [{"Execute": False} for _ in range(n_camin)]
        self.extra_steps = []
        rig.steps.append(lambda: self.mv(Axis=rig.master, **self.mvin))
        for fb, inp in zip(self.ci, self.ciin):
            rig.steps.append(lambda fb=fb, inp=inp: fb(Master=rig.master, Slave=rig.slave, **inp))
        rig.steps.append(lambda: [s() for s in self.extra_steps])
        rig.record = self._row
        rig.run_until(rig.enabled, timeout=1.0)
        for cam in self.cams.values():
            interpolate(self.ctl, cam)
        self.rig.log.clear()

    @property
    def m(self):
        return float(self.ctl.bank.sp_p[self.rig.master.index])

    @property
    def s(self):
        return float(self.ctl.bank.sp_p[self.rig.slave.index])

    def _row(self):
        sl = self.rig.slave
        row = {"t": self.ctl.time, "m": self.m, "s": self.s,
               "X21": bool(sl.StatusWord.X21), "X22": bool(sl.StatusWord.X22),
               "FS": sl.StatusSynchronizedMotion.FunctionState,
               "WFS": sl.StatusSynchronizedMotion.WaitingFunctionState}
        for i, fb in enumerate(self.ci):
            for k in CAMIN_OUT:
                row[f"{k}{i}"] = getattr(fb, k)
        return row

    def move(self, v, settle=True):
        self.mvin["Execute"] = False
        self.run(0.008)
        self.mvin.update(Execute=True, Velocity=float(v))
        if settle:
            self.rig.run_until(lambda: self.mv.InVelocity, timeout=5.0)

    def cam_in(self, i=0, cam="Cam", **inputs):
        self.ciin[i].clear()
        self.ciin[i].update(Execute=False)
        self.run(0.008)
        self.ciin[i].update(Execute=True, Cam=self.cams[cam], **inputs)
        self.run(0.008)

    def run(self, seconds):
        self.rig.run(seconds)

    def until(self, cond, timeout=5.0):
        return self.rig.run_until(cond, timeout=timeout)

    def check_log(self):
        """Manual §9.1 conventions: Error never with ErrorID 0; Busy/CommandAborted/Error/EndOfProfile
        (non-cyclic end) exclusive; InSync implies Busy."""
        for r in self.rig.log:
            for i in range(len(self.ci)):
                assert not (r[f"Error{i}"] and r[f"ErrorID{i}"] == 0), r
                assert not (r[f"InSync{i}"] and not r[f"Busy{i}"]), r
                assert sum(bool(r[f"{k}{i}"]) for k in ("Busy", "CommandAborted", "Error")) <= 1, r
                assert not (r[f"CommandAborted{i}"] and r[f"EndOfProfile{i}"] and not r[f"Busy{i}"]), r


def flin(points, u):
    """Linear cam (InterpolationMode 0) reference: piecewise-linear through the points."""
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return float(np.interp(u, xs, ys))


import numpy as np  # noqa: E402
