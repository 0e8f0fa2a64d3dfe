"""FB 450 MC_ReadPeriphery and FB 451 MC_WritePeriphery: the technology I/O image 0..63 (S7-Technology V4.1
§6.7.6, §6.7.7, §5.6).

The technology I/O image holds bytes 0..63 of inputs and of outputs; in plcmotion they are the
controller's digital image: input byte n bit b is ``ctl.inputs["In.b"]``, output byte n bit b
``ctl.outputs["Qn.b"]`` (byte 0 holds the integrated I/O of the CPU, which the MCDevice DB shows as
DIStatus / DOStatus).  ``Data`` is the ANY area: a ``bytearray`` to read into, bytes to write, at most 64
bytes and not beyond byte 63.

MC_ReadPeriphery reads while Enable is TRUE: the first call hands the command to the technology (Busy),
every later call delivers the image the technology took in the previous call (DataValid from the second
call on); InputOutput, ByteAddress and Data are taken at the rising edge of Enable.  MC_WritePeriphery
writes in the command slice after the next technology DB update, where its Done comes from (the second
call when OB1 and the DB update run at the same rate).
"""
from __future__ import annotations

from typing import Any

from ..kernel.jobs import Job
from . import fb_errors as FE
from .base import Instruction, InstructionError, as_bool
from .service import MAX_COMMANDS, ServiceInstruction, data_area, int_input, running
from .technology import dp_drive as DP
from .technology.device import TechnologyDevice, current

IMAGE_BYTES = 64


def read_image(ctl: Any, output: bool, start: int, length: int) -> bytes:
    """Bytes ``start`` .. ``start + length - 1`` of the technology input (or output) image."""
    image = ctl.outputs if output else ctl.inputs
    kind = "Q" if output else "I"
    return bytes(sum(int(bool(image[f"{kind}{n}.{b}"])) << b for b in range(8)) for n in range(start, start + length))


def write_image(ctl: Any, start: int, data: bytes) -> None:
    """Set output bytes ``start`` .. of the technology output image to ``data``."""
    for k, byte in enumerate(data):
        for b in range(8):
            ctl.outputs[f"Q{start + k}.{b}"] = bool(byte >> b & 1)


def _area(byte_address: Any, data: Any, *, writable: bool) -> tuple[int, Any]:
    start = int_input(byte_address, range(0, IMAGE_BYTES))
    area = data_area(data, writable=writable, maximum=IMAGE_BYTES, too_long=FE.INVALID_DATA_LENGTH)
    if start + len(area) > IMAGE_BYTES:
        raise InstructionError(FE.INVALID_DATA_LENGTH)             # beyond the image
    return start, area


class MC_ReadPeriphery(Instruction):  # noqa: N801 - instruction name of the manual
    """FB 450: read the technology I/O image continuously while Enable is TRUE."""

    INPUTS = {"Enable": False, "InputOutput": False, "ByteAddress": 0, "Data": None}
    OUTPUTS = {"DataValid": False, "Busy": False, "Error": False, "ErrorID": 0}

    def _reinit(self) -> None:
        super()._reinit()
        for name, value in (("_prev", False), ("_sample", None), ("_area", None), ("_device", None)):
            object.__setattr__(self, name, value)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        rise = enable and not self._prev
        object.__setattr__(self, "_prev", enable)
        if not enable:
            self._release()
            self._out(DataValid=False, Busy=False, Error=False, ErrorID=0)
            return
        if rise:
            self._release()
            try:
                self._take()
            except InstructionError as err:
                self._out(DataValid=False, Busy=False, Error=True, ErrorID=err.error_id)
                return
            self._out(DataValid=False, Busy=True, Error=False, ErrorID=0)
        if self._area is None:
            return                                         # the command was refused: Error stays
        device, (output, start, area) = self._device, self._area
        sample = self._sample
        if sample is not None:
            area[:] = sample
            self._out(DataValid=True)
        object.__setattr__(self, "_sample", read_image(device.ctl, output, start, len(area)))

    def _take(self) -> None:
        device = current()
        if device is None or device.ctl.mode != "RUN":
            raise InstructionError(FE.TECHNOLOGY_NOT_READY)
        output = as_bool(self, "InputOutput", self.InputOutput)
        start, area = _area(self.ByteAddress, self.Data, writable=True)
        work = running(device)
        if len(work) >= MAX_COMMANDS:
            raise InstructionError(FE.COMMAND_MEMORY_FULL)
        work.add(id(self))
        self._register(device)
        object.__setattr__(self, "_device", device)
        object.__setattr__(self, "_area", (output, start, area))
        object.__setattr__(self, "_sample", None)

    def _release(self) -> None:
        device = self._device
        if device is not None:
            running(device).discard(id(self))
        object.__setattr__(self, "_device", None)
        object.__setattr__(self, "_area", None)
        object.__setattr__(self, "_sample", None)


class MC_WritePeriphery(ServiceInstruction):  # noqa: N801
    """FB 451: write Data to the technology output image from ByteAddress on (one write per rising edge)."""

    INPUTS = {"Execute": False, "ByteAddress": 0, "Data": None, "DoneFlag": 0}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        start, area = _area(self.ByteAddress, self.Data, writable=False)
        data = bytes(area)

        def write() -> None:
            write_image(device.ctl, start, data)
            self.complete(job)
        DP.bus(device).slices.after(1, write)


__all__ = ["MC_ReadPeriphery", "MC_WritePeriphery", "read_image", "write_image", "IMAGE_BYTES"]
