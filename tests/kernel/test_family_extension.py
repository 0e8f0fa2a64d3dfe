"""A family's controller-wide runtime state (``Family.setup`` -> ``Controller.extension``), without any dialect.

A small test family registers a setup function; the controller makes its state once, keeps it as
``ctl.extension`` and restarts it with the controller (STOP -> RUN, POWER OFF -> ON).  A family without a
setup leaves ``extension`` None.
"""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.kernel import family as families


class _State:
    def __init__(self, ctl):
        self.ctl = ctl
        self.restarts: list[str] = []

    def reinitialize(self, reason: str) -> None:
        self.restarts.append(reason)


class _NoRestart:
    def __init__(self, ctl):
        self.ctl = ctl


@pytest.fixture(scope="module", autouse=True)
def extension_families():
    made = [families.register(families.Family("Kernel-Extension-Test", versions=(1,), default_version=1,
                                              factories={}, setup=_State)),
            families.register(families.Family("Kernel-Extension-Plain", versions=(1,), default_version=1,
                                              factories={}, setup=_NoRestart)),
            families.register(families.Family("Kernel-Extension-None", versions=(1,), default_version=1,
                                              factories={}))]
    yield
    for fam in made:
        families._REGISTRY.pop(fam.name)


def test_kernel_extension_is_made_once_per_controller():
    """Each controller gets its own state object from the family's setup, made with the controller."""
    a, b = Controller(family="Kernel-Extension-Test"), Controller(family="Kernel-Extension-Test")
    assert isinstance(a.extension, _State) and a.extension.ctl is a
    assert b.extension is not a.extension


def test_kernel_extension_restarts_with_the_controller():
    """STOP -> RUN and POWER OFF -> ON restart the family's state with the reason, like every object."""
    ctl = Controller(family="Kernel-Extension-Test")
    ctl.stop()
    ctl.start()
    ctl.power_cycle()
    assert ctl.extension.restarts == ["startup", "power"]


def test_kernel_extension_without_reinitialize_or_setup():
    """State without a restart method is kept as it is; a family without setup has no extension."""
    plain = Controller(family="Kernel-Extension-Plain")
    state = plain.extension
    plain.power_cycle()
    assert plain.extension is state and plain.mode == "RUN"
    assert Controller(family="Kernel-Extension-None").extension is None
