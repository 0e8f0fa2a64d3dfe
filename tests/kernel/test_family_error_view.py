"""How a summary names the errors of an object: ``kernel.family.error_texts`` asks the family's
``error_view`` where it has one, else names each alarm with ``describe_fault`` (or the alarm's own text)."""
from __future__ import annotations

from types import SimpleNamespace

from plcmotion.kernel import family as families
from plcmotion.kernel import faults as F
from plcmotion.kernel.faults import Reaction


def _family(**kw) -> families.Family:
    return families.Family("Kernel-ErrorView-Test", versions=(1,), default_version=1, factories={}, **kw)


ALARM = F.alarm(F.FOLLOWING_ERROR, "", Reaction.REMOVE_ENABLE)


def test_kernel_error_texts_of_the_alarms():
    """Without an error view: one text per alarm, the family's description first; none without alarms."""
    obj = SimpleNamespace(alarms=[ALARM])
    assert families.error_texts(_family(), obj) == [str(ALARM)]
    assert families.error_texts(_family(describe_fault=lambda f: "alarm 7"), obj) == [f"alarm 7 [{ALARM}]"]
    assert families.error_texts(_family(), SimpleNamespace(alarms=[])) == []


def test_kernel_error_texts_from_the_family_error_view():
    """The family's view wins: it may show errors the object keeps beside the kernel's alarms (an object
    without alarms may still have an error), and it may show none although an alarm is pending."""
    record = SimpleNamespace(alarms=[], record=["error 42"])
    fam = _family(describe_fault=lambda f: "unused", error_view=lambda o: o.record)
    assert families.error_texts(fam, record) == ["error 42"]
    assert families.error_texts(_family(error_view=lambda o: []), SimpleNamespace(alarms=[ALARM])) == []
