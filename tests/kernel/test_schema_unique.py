"""``kernel.schema.Param.unique``: a tag whose value no two objects of one controller may share (a DB number).
The kernel only carries the flag; the project loader checks it across the tables of a file."""
from __future__ import annotations

from plcmotion.kernel.schema import INT, R, AxisSchema, Param


def test_kernel_schema_param_is_not_unique_unless_declared():
    schema = AxisSchema("test object", [Param("Number", INT, None, R, (), 1, 10, optional=True, unique=True),
                                        Param("Other", INT, 1, R, (), 1, 10)])
    assert schema.params["Number"].unique and not schema.params["Other"].unique
    cfg, issues = schema.validate({"Number": 3})
    assert not issues and cfg["Number"] == 3          # the flag does not change the checks of one object
