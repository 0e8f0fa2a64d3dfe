"""The simulated machine's ``Plant.*`` parameters for fixed end stops, drive inertia and the hydraulic
cylinder (``kernel/plant_schema.py``): configuration errors name the tag.

S7-Technology V4.1 §6.2.11 (fixed end stop for MC_MoveToEndPos), §3.1.4 (hydraulic cylinder).
"""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.drives import CylinderSpec
from plcmotion.kernel.errors import ConfigurationError
from plcmotion.kernel.plant_schema import CYLINDER_PARAMS, cylinder_spec


def test_kernel_plant_end_stops_reach_the_drive_spec():
    """S7-Technology V4.1 §6.2.11: the end stops of the axis's machine are in its drive specification."""
    axis = Controller().add_positioning_axis("Axis_1", {"Actor.Type": 1, "Plant.EndStopMinPosition": -10.0,
                                                        "Plant.EndStopMaxPosition": 40.0, "Plant.Inertia": 0.02})
    plant = axis.config.drive.plant
    assert (plant.end_stop_min, plant.end_stop_max, plant.inertia) == (-10.0, 40.0, 0.02)


@pytest.mark.parametrize("params, tag", [
    ({"Plant.EndStopMaxPosition": -1.0}, "Plant.InitialPosition"),
    ({"Plant.EndStopMinPosition": 5.0, "Plant.EndStopMaxPosition": 5.0, "Plant.InitialPosition": 5.0},
     "Plant.EndStopMinPosition"),
])
def test_kernel_plant_end_stops_that_do_not_fit_are_a_configuration_error(params, tag):
    """S7-Technology V4.1 §6.2.11: the load must start between its end stops, which leave it room."""
    with pytest.raises(ConfigurationError) as err:
        Controller().add_positioning_axis("Axis_1", {"Actor.Type": 1, **params})
    assert [issue.path for issue in err.value.issues] == [tag]


def test_kernel_plant_cylinder_parameters_build_the_cylinder_spec():
    """S7-Technology V4.1 §3.1.4: the cylinder parameters' start values are the default cylinder; a stroke
    without room names its tag."""
    values = {p.path: p.start for p in CYLINDER_PARAMS}
    assert cylinder_spec(values) == CylinderSpec()
    with pytest.raises(ConfigurationError) as err:
        cylinder_spec({**values, "Plant.Cylinder.StrokeMin": 600.0})
    assert [issue.path for issue in err.value.issues] == ["Plant.Cylinder.StrokeMin"]
