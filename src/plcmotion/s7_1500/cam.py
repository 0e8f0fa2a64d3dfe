"""Cam instructions of the S7-1500T (V5, §9.2): MC_InterpolateCam, MC_GetCamLeadingValue,
MC_GetCamFollowingValue.  The work is done by the cam TO at the next servo cycle; these instructions are
never aborted and abort nothing."""
from __future__ import annotations

from typing import Any, ClassVar

from .technology.cam_to import CamTO
from ..kernel.jobs import Job, JobKind
from .base import ExecuteInstruction, InstructionError, real

_OUT = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}


class _CamInstruction(ExecuteInstruction):
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (CamTO,)
    VALUES: ClassVar[dict[str, str]] = {}          # output -> key in job.extra

    def _axis(self, name: str = "Cam") -> Any:
        return super()._axis("Cam")

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_values", {})

    def _final_for(self, job: Job):
        object.__setattr__(self, "_values", {out: job.extra.get(key, 0.0) for out, key in self.VALUES.items()})
        return super()._final_for(job)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)
        if output == "Done":
            self._out(**self._values)

    def _clear_outputs(self) -> None:
        keep = {out: getattr(self, out) for out in self.VALUES}
        super()._clear_outputs()
        self._out(**keep)


class MC_InterpolateCam(_CamInstruction):  # noqa: N801
    """Interpolate a cam with its InterpolationSettings (not while the cam is in use)."""

    INPUTS = {"Cam": None, "Execute": False}
    OUTPUTS = dict(_OUT)

    def _start(self, cam: CamTO) -> Job:
        job = Job(JobKind.CAM_INTERPOLATE, owner=self)
        cam.submit(job)
        return job


class MC_GetCamLeadingValue(_CamInstruction):  # noqa: N801
    """The leading value of a cam for FollowingValue; of several, the one nearest ApproachLeadingValue."""

    INPUTS = {"Cam": None, "Execute": False, "FollowingValue": 0.0, "ApproachLeadingValue": 0.0}
    OUTPUTS = {**_OUT, "Value": 0.0}
    VALUES = {"Value": "value"}

    def _start(self, cam: CamTO) -> Job:
        y = real("FollowingValue", self.FollowingValue)
        approach = real("ApproachLeadingValue", self.ApproachLeadingValue)
        job = Job(JobKind.CAM_LEADING, position=y, owner=self, extra={"approach": approach})
        cam.submit(job)
        return job


class MC_GetCamFollowingValue(_CamInstruction):  # noqa: N801
    """The following value and its first and second derivative at LeadingValue (cam coordinates)."""

    INPUTS = {"Cam": None, "Execute": False, "LeadingValue": 0.0}
    OUTPUTS = {**_OUT, "Value": 0.0, "FirstDerivative": 0.0, "SecondDerivative": 0.0}
    VALUES = {"Value": "value", "FirstDerivative": "first", "SecondDerivative": "second"}

    def _start(self, cam: CamTO) -> Job:
        x = real("LeadingValue", self.LeadingValue)
        job = Job(JobKind.CAM_FOLLOWING, position=x, owner=self)
        cam.submit(job)
        return job


__all__ = ["MC_InterpolateCam", "MC_GetCamLeadingValue", "MC_GetCamFollowingValue", "InstructionError"]
