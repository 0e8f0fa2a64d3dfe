"""The hypothesis stateful machine: hypothesis chooses the dialect and set-up, then input changes, tag
writes and runs of application cycles; the runner checks every invariant after every cycle."""
from __future__ import annotations

import math
import random

from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, precondition, rule

from .gen import DIALECTS, Op, _PARAM_PATHS, _TAGS_1200, _TAGS_1500, catalog, generate
from .repro import script
from .runner import Run
from .values import GARBAGE, HUGE_INT, Ref, TagRefSpec, VarSpec

_REAL = st.one_of(st.floats(-1e4, 1e4, allow_nan=False), st.sampled_from(GARBAGE + (-1.0,)),
                  st.floats(allow_nan=True, allow_infinity=True), st.integers(-10 ** 6, 10 ** 6))
_BAD_INT = st.sampled_from((-1, 99, 32768, 1.0, 2.5, math.nan, HUGE_INT, None, "1"))


def _strategy(kind, objs: dict[str, list[str]]):
    if kind == "bool":
        return st.booleans()
    if isinstance(kind, tuple):
        return st.one_of(st.sampled_from(kind[1]), _BAD_INT)
    if kind in ("axis", "any_to", "slave", "master", "cam", "table"):
        names = (objs["all"] if kind == "any_to" else objs[kind]) or objs["axis"]
        return st.one_of(st.sampled_from([Ref(n) for n in names]),
                         st.sampled_from([None, "Axis_1", 5] + [Ref(n) for n in objs["all"]]))
    if kind == "ratio":
        return st.one_of(st.integers(-10, 10), st.sampled_from((2 ** 31, HUGE_INT, 1.5, math.nan, None)))
    if kind == "param":
        return st.builds(TagRefSpec, st.sampled_from(objs["axis"]), st.sampled_from(_PARAM_PATHS))
    if kind == "pvalue":
        return st.one_of(_REAL, st.booleans(), st.builds(VarSpec, st.sampled_from(("Real", "Int", "DInt", "Bool")),
                                                         st.none()))
    if kind == "pvar":
        return st.builds(VarSpec, st.sampled_from(("Real", "Int", "DInt", "UDInt", "Bool")), st.none())
    return _REAL


class FuzzMachine(RuleBasedStateMachine):
    """One controller per example; the rules drive it and the runner's invariants are asserted."""

    IGNORE: tuple[str, ...] = ()      # signature prefixes to look past (triage only; CI asserts everything)

    @initialize(dialect=st.sampled_from(DIALECTS), seed=st.integers(0, 2 ** 31 - 1))
    def setup(self, dialect: str, seed: int) -> None:
        ep = generate(seed, dialect)          # technology objects and instruction instances of a random episode
        ep.ops, ep.cycles = [], 0
        self.ep = ep
        self.run = Run(ep, ignore=self.IGNORE)
        self.cat = catalog(dialect)
        axes = [a["name"] for a in ep.axes]
        self.objs = {"axis": axes, "slave": [a["name"] for a in ep.axes if a["kind"] == "sync"],
                     "master": axes + [p["name"] for p in ep.proxies], "cam": [c["name"] for c in ep.cams],
                     "table": [t["name"] for t in ep.tables]}
        self.objs["all"] = self.objs["master"] + self.objs["cam"] + self.objs["table"]
        self._check()

    def _check(self) -> None:
        f = self.run.failure
        if f is not None:
            raise AssertionError(f"{f.kind} at {f.where}: {f.message}\n{f.detail}\n"
                                 f"reproducer:\n{script(self.ep, f)}")

    @rule(data=st.data())
    def set_input(self, data) -> None:
        fb = data.draw(st.sampled_from(self.ep.fbs), label="instance")
        kinds = self.cat[fb["cls"]]
        name = data.draw(st.sampled_from(sorted(kinds)), label="input")
        value = data.draw(_strategy(kinds[name], self.objs), label="value")
        op = Op(self.run.cycle, "in", fb["name"], name, value)
        self.ep.ops.append(op)
        self.run._apply(op)

    @rule(data=st.data())
    def toggle(self, data) -> None:
        fb = data.draw(st.sampled_from(self.ep.fbs), label="instance")
        bools = [k for k, kd in self.cat[fb["cls"]].items() if kd == "bool"]
        name = data.draw(st.sampled_from(bools), label="input")
        inst = self.run.fbs[fb["name"]]
        op = Op(self.run.cycle, "in", fb["name"], name, not bool(getattr(inst, name)))
        self.ep.ops.append(op)
        self.run._apply(op)

    @rule(data=st.data())
    def write_tag(self, data) -> None:
        axis = data.draw(st.sampled_from(self.objs["axis"]), label="axis")
        tags = _TAGS_1200 if self.ep.dialect.startswith("S7-1200") else _TAGS_1500
        path = data.draw(st.sampled_from(tags), label="tag")
        value = data.draw(st.booleans() if path.endswith("Active") else _REAL, label="value")
        op = Op(self.run.cycle, "tag", axis, path, value)
        self.ep.ops.append(op)
        self.run._apply(op)
        self._check()

    @precondition(lambda self: self.run.failure is None)
    @rule(n=st.integers(1, 40))
    def cycles(self, n: int) -> None:
        for _ in range(n):
            self.run.step(())
            self.run.cycle += 1
            self.ep.cycles = self.run.cycle
            if self.run.failure is not None:
                break
        self._check()
