"""Issue 8, defect 7: the Python API refuses configuration that must not be accepted, with clear typed
errors (never OverflowError, AttributeError or a silent last-wins)."""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.kernel.axis import ConfigurationError


@pytest.mark.parametrize("servo, app, name", [
    (5e-324, 0.004, "servo_cycle"), (1e-300, 0.001, "servo_cycle"), (0.001, 1e300, "app_cycle"),
    (0.064, 0.128, "servo_cycle"), (0.001, float("nan"), "app_cycle"), (0.001, 10**400, "app_cycle"),
])
def test_kernel_cycles_out_of_range_are_a_value_error_defect_7(servo, app, name):
    with pytest.raises(ValueError, match=rf"^{name} = .*: a positive number of seconds in \["):
        Controller(servo_cycle=servo, app_cycle=app)


@pytest.mark.parametrize("version", [7.0, True, "7"])
def test_kernel_technology_version_must_be_an_integer_defect_7(version):
    with pytest.raises(ValueError, match="technology_version for S7-1200 must be 6 or 7"):
        Controller(technology_version=version)


@pytest.mark.parametrize("method, kw", [
    ("add_positioning_axis", {}), ("add_synchronous_axis", {}), ("add_external_encoder", {}),
    ("add_leading_axis_proxy", {}),
])
@pytest.mark.parametrize("params", [[("Actor.Type", 1)], "Actor.Type=1", 5])
def test_kernel_params_that_are_no_mapping_are_a_type_error_defect_7(method, kw, params):
    ctl = Controller(family="S7-1500T") if method != "add_positioning_axis" else Controller()
    with pytest.raises(TypeError, match=r"^(axis|external encoder|leading axis proxy) A: params must be a mapping"):
        getattr(ctl, method)("A", params, **kw)
    assert "A" not in ctl.axes and "A" not in ctl.objects


@pytest.mark.parametrize("value", [10**400, -10**400])
def test_kernel_huge_int_for_a_real_tag_is_a_configuration_error_defect_7(value):
    ctl = Controller()
    with pytest.raises(ConfigurationError) as err:
        ctl.add_positioning_axis("A", {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": value}})
    (issue,) = err.value.issues
    assert issue.path == "DynamicLimits.MaxVelocity" and issue.reason == ("too_high" if value > 0 else "too_low")
    assert "allowed: real in (0.0, 1000000000000.0]" in str(err.value)
    assert len(str(err.value)) < 300                   # a bounded excerpt of the 400 digits


def test_kernel_huge_int_for_an_integer_tag_is_a_configuration_error_defect_7():
    with pytest.raises(ConfigurationError, match="Actor.Type = 1000000.*allowed: one of 0, 1, 2"):
        Controller().add_positioning_axis("A", {"Actor.Type": 10**400})


@pytest.mark.parametrize("path, value", [("Actor.Type", 1.0), ("Sensor[1].ActiveHoming.Mode", 2.0),
                                         ("Actor.DriveParameter.PulsesPerDriveRevolution", 1000.0)])
def test_kernel_a_real_for_an_integer_tag_is_refused_defect_7(path, value):
    with pytest.raises(ConfigurationError, match=rf"an integer: write {int(value)}, not {value!r}"):
        Controller().add_positioning_axis("A", {path: value})


def test_kernel_a_dotted_and_a_nested_key_for_one_tag_name_both_defect_7():
    with pytest.raises(ConfigurationError) as err:
        Controller().add_positioning_axis("A", {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 1.0,
                                                "DynamicLimits": {"MaxVelocity": 2.0}})
    text = str(err.value)
    assert "params['DynamicLimits.MaxVelocity'] = 1.0" in text
    assert "params['DynamicLimits']['MaxVelocity'] = 2.0" in text and "set each tag once" in text


def test_kernel_two_spellings_of_the_manuals_for_one_tag_are_refused_defect_7():
    with pytest.raises(ConfigurationError, match="already set by PositionLimitsSW.Active = True"):
        Controller().add_positioning_axis("A", {"PositionLimitsSW.Active": True, "PositionLimits_SW.Active": False})


def test_kernel_a_mapping_that_contains_itself_is_a_configuration_error_defect_7():
    params: dict = {"Actor": {"Type": 1}}
    params["Plant"] = params
    with pytest.raises(ConfigurationError, match="nesting|levels"):
        Controller().add_positioning_axis("A", params)


def test_kernel_one_valid_axis_still_loads_with_dotted_and_nested_keys():
    axis = Controller().add_positioning_axis("A", {"Actor.Type": 1, "DynamicLimits": {"MaxVelocity": 200.0},
                                                   "Mechanics.LeadScrew": 10.0})
    assert axis.Actor.Type == 1 and axis.DynamicLimits.MaxVelocity == 200.0


@pytest.mark.parametrize("leading, error", [
    (5, TypeError), ("Master", TypeError), ([("Master",)], TypeError), ([3], TypeError), (["S"], ValueError),
])
def test_kernel_leading_values_of_a_synchronous_axis_are_checked_defect_7(leading, error):
    """A string is not a list of names (it was split into one-letter names), and an axis is not its own
    leading value (S7-1500T V5 §6.1.3: the possible leading values are other technology objects)."""
    ctl = Controller(family="S7-1500T")
    ctl.add_positioning_axis("Master")
    with pytest.raises(error, match="synchronous axis S: "):
        ctl.add_synchronous_axis("S", leading_values=leading)
    assert "S" not in ctl.axes


@pytest.mark.parametrize("kw", [{"interpolation_mode": 1.0}, {"boundary_conditions": 1.0},
                                {"interpolation_mode": True}])
def test_kernel_cam_settings_must_be_integers_defect_7(kw):
    with pytest.raises(ConfigurationError, match="InterpolationSettings"):
        Controller(family="S7-1500T").add_cam("C", [(0.0, 0.0), (1.0, 1.0)], **kw)


@pytest.mark.parametrize("points", [5, "abc", {"x": 1}])
def test_kernel_cam_points_that_are_no_list_are_a_type_error_defect_7(points):
    with pytest.raises(TypeError, match="cam C: points must be a list"):
        Controller(family="S7-1500T").add_cam("C", points)


def test_kernel_cam_value_beyond_lreal_is_kept_as_an_invalid_value_not_overflow_defect_5_7():
    """10**400 in a cam point or segment does not raise OverflowError: the cam TO keeps an invalid
    (infinite) value that MC_InterpolateCam reports."""
    cam = Controller(family="S7-1500T").add_cam("C", [(0.0, 0.0), (1.0, 10**400)],
                                                [{"xmin": 2.0, "xmax": 3.0, "a1": -10**400}])
    assert cam.Point[2].y == float("inf") and cam.Segment[1].a1 == float("-inf")
