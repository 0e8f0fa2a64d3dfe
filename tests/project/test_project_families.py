"""Project files of a family the loader does not know by name (issue 9: a new family is a new package).

Each test registers a throw-away family whose factories and schemas are borrowed from a registered one,
loads a TOML project with it and removes it again, so nothing in ``plcmotion.project`` names the family.
"""
from __future__ import annotations

import textwrap
from dataclasses import replace

import pytest

from plcmotion.kernel import family as families
from plcmotion.project import ProjectError, check_project, load_project

NAME = "Test-Project-Family"


def _write(tmp_path, text: str):
    path = tmp_path / "p.toml"
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def _register(base: str, kinds: tuple[str, ...], *, name: str = NAME) -> families.Family:
    """A family offering ``kinds`` with the factories and schemas of the registered family ``base``."""
    known = families.lookup(base)
    return families.register(replace(
        known, name=name, versions=(3,), default_version=3,
        factories={k: known.factories[k] for k in kinds},
        schemas={k: known.schemas[k] for k in kinds if k in known.schemas}))


@pytest.fixture
def sync_family():
    fam = _register("S7-1500T", (families.POSITIONING_AXIS, families.SYNCHRONOUS_AXIS))
    try:
        yield fam
    finally:
        families._REGISTRY.pop(fam.name)


def test_project_a_registered_family_loads_its_axes(tmp_path, sync_family):
    """The axis types, the tag schema and the factories come from the family's registration."""
    ctl = load_project(_write(tmp_path, f"""
        [controller]
        family = "{NAME}"

        [axes.Master]
        "DynamicDefaults.Velocity" = 50.0

        [axes.Follower]
        type = "synchronous"
        leading_values = ["Master"]
    """))
    assert ctl.family == NAME and ctl.technology_version == 3
    assert set(ctl.axes) == {"Master", "Follower"}
    assert ctl.axes["Master"].tag("DynamicDefaults.Velocity") == 50.0
    assert hasattr(ctl.axes["Follower"], "possible_leading_values")


def test_project_a_registered_family_checks_types_versions_and_tags(tmp_path, sync_family):
    """What the family lacks is a message: a type without a schema, a version it does not have, a tag its
    schema does not know."""
    problems = check_project(_write(tmp_path, f"""
        [controller]
        family = "{NAME}"
        technology_version = 5

        [axes.Encoder]
        type = "external_encoder"

        [axes.Axis_1.DynamicLimits]
        MaxVelocty = 100.0
    """))
    text = "\n".join(problems)
    assert 'controller.technology_version = 5: allowed: 3' in text
    assert 'axes.Encoder.type = "external_encoder": allowed: one of "positioning", "synchronous"' in text
    assert "axes.Axis_1.DynamicLimits.MaxVelocty: unknown parameter" in text


def test_project_cams_name_the_families_that_offer_them(tmp_path):
    """The "cams need family" message lists the registered families with a cam factory."""
    fam = _register("S7-1500T", (families.POSITIONING_AXIS, families.CAM))
    try:
        problems = check_project(_write(tmp_path, """
            [controller]
            family = "S7-1500"

            [cams.Knife]
            points = [[0.0, 0.0], [360.0, 10.0]]
        """))
    finally:
        families._REGISTRY.pop(fam.name)
    assert any(f'cams: cams need family = "S7-1500T" or "{NAME}" in [controller]' in p for p in problems), problems


def test_project_the_default_family_is_the_first_registered(tmp_path, sync_family, monkeypatch):
    """A file without ``family`` gets the registry's default family; objects it lacks name the families
    that offer them."""
    monkeypatch.setattr(families, "_REGISTRY", {NAME: sync_family, **families._REGISTRY})
    ctl = load_project(_write(tmp_path, """
        [axes.Axis_1]
        type = "synchronous"
    """))
    assert ctl.family == NAME and ctl.technology_version == 3
    with pytest.raises(ProjectError) as exc:
        load_project(_write(tmp_path, """
            [axes.Encoder]
            type = "external_encoder"
        """))
    assert exc.value.problems == [
        f"{tmp_path / 'p.toml'}: controller.family is not set, so {NAME} is assumed, but the file has "
        'external encoders: set family = "S7-1500T" in [controller]']
