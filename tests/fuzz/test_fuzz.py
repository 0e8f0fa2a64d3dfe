"""The fuzzer in CI (issue 8): a short fixed-seed campaign over every dialect and the hypothesis state
machine, derandomized; together well under 60 s.  Every invariant of tests/fuzz/__init__.py is asserted:
the test fails until the defects it finds are fixed (none is marked expected to fail).

Long runs: ``python -m tests.fuzz --episodes 100000 --jobs 2``; one episode: ``--replay SEED``.
"""
from __future__ import annotations

import warnings

import pytest
from hypothesis import HealthCheck, Phase, settings

from .campaign import campaign
from .gen import ALL_DIALECTS, generate
from .machine import FuzzMachine
from .repro import script

CI_EPISODES = 16           # per dialect: about 5-10 s each on a loaded 2-core machine
CI_SEED = 20260            # fixed: the same episodes on every run


@pytest.mark.parametrize("dialect", ALL_DIALECTS)
def test_fuzz_campaign_every_invariant(dialect):
    """Issue 8 (fuzzer): random instruction sequences with random and invalid inputs on S7-1200 V6/V7,
    S7-1500, S7-1500T and S7-Technology V4.1 (issue 11): no exception out of an instruction or the cycle,
    no STOP, no internal error,
    no NaN/inf setpoint or actual value, dynamics within the manual's limits, SW limits respected,
    Busy/Done/Error/CommandAborted exclusive, no instruction Busy forever at standstill."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = campaign(CI_EPISODES, CI_SEED, 1, dialect)
    if res.failures:
        lines = [f"{res.failed_episodes()} of {res.episodes} episodes failed, {len(res.failures)} distinct:"]
        for sig, items in res.failures.items():
            seed, f = items[0]
            lines.append(f"- {f.kind} at {f.where}: {f.message}\n  replay: python -m tests.fuzz --replay {seed} "
                         f"--dialect '{dialect}' --script")
        seed, f = next(iter(res.failures.values()))[0]
        lines.append("first reproducer (unshrunk):\n" + script(generate(seed, dialect), f))
        pytest.fail("\n".join(lines), pytrace=False)


TestFuzzMachine = FuzzMachine.TestCase
TestFuzzMachine.settings = settings(max_examples=10, stateful_step_count=20, deadline=None, derandomize=True,
                                    database=None, phases=[Phase.explicit, Phase.generate],
                                    suppress_health_check=list(HealthCheck), print_blob=False)
