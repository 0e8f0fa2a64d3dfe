"""Offline cam tools: build cams from elements and VDI 2143 transitions, export/import point lists, plot.

Outer layer on top of :mod:`plcmotion.kernel.cam` (S7-1500T V5 §6.2): nothing in the kernel imports it.
"""
from .builder import (COEFFICIENT_LIMIT, CONTINUITY, SEGMENT_FIELDS, CamBuilder, CamCapacityError,
                      CamCoefficientError, CamDefinition, TransitionInfo)
from .io import PointListError, export_points, import_points
from .plot import plot_cam
from .vdi import Characteristics, MotionLaw, UnsupportedTransitionError, characteristic_values, transition_law

__all__ = ["COEFFICIENT_LIMIT", "CONTINUITY", "SEGMENT_FIELDS", "CamBuilder", "CamCapacityError",
           "CamCoefficientError", "CamDefinition", "Characteristics", "MotionLaw", "PointListError", "TransitionInfo",
           "UnsupportedTransitionError", "characteristic_values", "export_points", "import_points", "plot_cam",
           "transition_law"]
