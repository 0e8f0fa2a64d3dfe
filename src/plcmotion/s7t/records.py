"""FB 453 MC_ReadRecord, FB 454 MC_WriteRecord, FB 455 MC_ReadDriveParameter and FB 456
MC_WriteDriveParameter (S7-Technology V4.1 §6.7.8-§6.7.11): acyclic data of the drives on DP(DRIVE).

``Address`` is the logical base address of the slave (``technology.dp_drive``: 256, 288, ... for the real
axes in DB-number order), ``InOut`` whether it is given as input or output address (both are the same
here).  ``Data`` is the ANY area: a ``bytearray`` the FB fills (read) or bytes it sends (write).  The record
FBs reach every data record of the slave the drive offers - record 47, the PROFIdrive parameter channel
(``drives.profidrive.parameter_model``); the drive-parameter FBs build the record-47 request from
ParameterNumber / SubIndex / NumberOfElements and give the drive's PROFIdrive error number as ErrorID
16#8100 + number.  Values in ``Data`` are big-endian as on the bus (REAL parameters as 4-byte floats).

Timing: the request leaves in the command slice after the next technology DB update and the answer comes
in the slice after the following one; Busy until then.  One drive-parameter command per drive at a time
(another one: 16#80C7), one write per data record (16#80C0).
"""
from __future__ import annotations

from ..drives.profidrive import parameter_model as PM
from ..kernel.jobs import Job
from . import fb_errors as FE
from .base import InstructionError, as_bool
from .service import ServiceInstruction, data_area, int_input
from .technology import dp_drive as DP
from .technology.device import TechnologyDevice

RECORD_MAX = 240               # bytes of one data record (§6.7.8, §6.7.9)
READ_PARAMETER_MAX = 240       # Data of MC_ReadDriveParameter
WRITE_PARAMETER_MAX = 228      # Data of MC_WriteDriveParameter
READ_ELEMENTS, WRITE_ELEMENTS = range(0, 235), range(0, 229)
WORD_RANGE = range(0, 65536)
INT_RANGE = range(-32768, 32768)
ADDRESS_NOT_AVAILABLE = 0x8091
#: the request takes one command slice to the drive, the answer one more
REQUEST_SLICES = 2


class _ShowsDataLength:
    """The reading FBs show DataLength (the bytes the answer filled) with Done."""

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)  # type: ignore[misc]
        if output == "Done":
            self._out(DataLength=self.__dict__.get("_length", 0))  # type: ignore[attr-defined]

    def _final_for(self, job: Job):
        object.__setattr__(self, "_length", job.extra.get("length", 0))
        return super()._final_for(job)  # type: ignore[misc]


class _RecordBase(ServiceInstruction):
    INPUTS = {"Execute": False, "InOut": False, "Address": 0, "RecordNumber": 0, "Data": None, "DoneFlag": 0}

    def _slave(self, device: TechnologyDevice) -> DP.Slave:
        as_bool(self, "InOut", self.InOut)
        address = int_input(self.Address, INT_RANGE)
        if address == DP.INTEGRATED_IO_ADDRESS:
            raise InstructionError(ADDRESS_NOT_AVAILABLE)           # integrated I/O: not on DP(DRIVE)
        slave = DP.bus(device).by_address(address)
        if slave is None:
            raise InstructionError(FE.INVALID_ADDRESS)
        return slave


class MC_ReadRecord(_ShowsDataLength, _RecordBase):  # noqa: N801 - instruction name of the manual
    """FB 453: read a data record of a DP(DRIVE) slave into Data; ``DataLength`` bytes were read."""

    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "DataLength": 0}

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        record = int_input(self.RecordNumber, range(0, 256))
        data = data_area(self.Data, writable=True, maximum=RECORD_MAX, too_long=FE.RECORD_TOO_LONG)
        slave = self._slave(device)

        def answer() -> None:
            if not slave.active:
                return self.complete(job, 0x80A0)                   # the slave does not answer
            if record != PM.RECORD:
                return self.complete(job, 0x80B0)
            resp = slave.parameters.read_record()
            if resp is None:
                return self.complete(job, 0x80C0)                   # no data yet: read again
            if len(resp) > len(data):
                return self.complete(job, 0x80B1)                   # Data shorter than the record
            data[:len(resp)] = resp
            job.extra["length"] = len(resp)
            self.complete(job)
        DP.bus(device).slices.after(REQUEST_SLICES, answer)


class MC_WriteRecord(_RecordBase):  # noqa: N801
    """FB 454: write Data as a data record to a DP(DRIVE) slave."""

    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        record = int_input(self.RecordNumber, range(0, 256))
        data = bytes(data_area(self.Data, writable=False, maximum=RECORD_MAX, too_long=FE.RECORD_TOO_LONG))
        slave = self._slave(device)
        if record in slave.busy_records:
            raise InstructionError(0x80C0)                          # the previous write is still busy
        slave.busy_records.add(record)

        def answer() -> None:
            slave.busy_records.discard(record)
            if not slave.active:
                return self.complete(job, 0x80A1)
            if record != PM.RECORD:
                return self.complete(job, 0x80B0)
            slave.parameters.write_record(data)
            self.complete(job)
        DP.bus(device).slices.after(REQUEST_SLICES, answer)


class _DriveParameterBase(ServiceInstruction):
    INPUTS = {"Execute": False, "InOut": False, "Address": 0, "ParameterNumber": 0, "SubIndex": 0,
              "NumberOfElements": 0, "Data": None, "DoneFlag": 0}
    ELEMENTS = READ_ELEMENTS
    WRITE = False

    def _address(self, device: TechnologyDevice) -> tuple[int, int, int, DP.Slave]:
        number = int_input(self.ParameterNumber, WORD_RANGE)
        sub = int_input(self.SubIndex, WORD_RANGE)
        count = int_input(self.NumberOfElements, self.ELEMENTS)
        as_bool(self, "InOut", self.InOut)
        address = int_input(self.Address, INT_RANGE)
        if address == DP.INTEGRATED_IO_ADDRESS:
            raise InstructionError(ADDRESS_NOT_AVAILABLE)
        slave = DP.bus(device).by_address(address)
        if slave is None:
            raise InstructionError(FE.INVALID_ADDRESS)
        if slave.drive_request:
            raise InstructionError(0x80C7)                          # one request per drive at a time
        return number, (sub if count else 0), count, slave

    def _send(self, device: TechnologyDevice, job: Job, slave: DP.Slave, request: bytes, finish) -> None:
        slave.drive_request = True

        def answer() -> None:
            slave.drive_request = False
            if not slave.active:
                return self.complete(job, 0x80A1 if self.WRITE else 0x80A0)
            error, values = PM.response_values(slave.parameters.process(request))
            if error is not None:
                return self.complete(job, 0x8100 + error)
            finish(values)
        DP.bus(device).slices.after(REQUEST_SLICES, answer)


class MC_ReadDriveParameter(_ShowsDataLength, _DriveParameterBase):  # noqa: N801
    """FB 455: read a drive parameter (NumberOfElements = 0: not indexed; n > 0: n elements from SubIndex)
    into Data; ``DataLength`` bytes."""

    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "DataLength": 0}

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        data = data_area(self.Data, writable=True, maximum=READ_PARAMETER_MAX, too_long=FE.RECORD_TOO_LONG)
        number, sub, count, slave = self._address(device)
        request = PM.ParameterModel.request(1, PM.READ, number, sub, count)

        def finish(values: bytes) -> None:
            if len(values) > len(data):
                return self.complete(job, FE.INVALID_DATA_LENGTH)   # Data too short for the values
            data[:len(values)] = values
            job.extra["length"] = len(values)
            self.complete(job)
        self._send(device, job, slave, request, finish)


class MC_WriteDriveParameter(_DriveParameterBase):  # noqa: N801
    """FB 456: write Data (the values, big-endian, of the parameter's data type) to a drive parameter."""

    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}
    ELEMENTS = WRITE_ELEMENTS
    WRITE = True

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        data = bytes(data_area(self.Data, writable=False, maximum=WRITE_PARAMETER_MAX,
                               too_long=FE.RECORD_TOO_LONG))
        number, sub, count, slave = self._address(device)
        data_type = slave.parameters.type_of(number)
        if data_type is not None:
            size = PM.DriveParameter(number, data_type).size
            if len(data) != size * max(count, 1):
                raise InstructionError(FE.INVALID_DATA_FORMAT)      # Data does not hold the values
        request = PM.ParameterModel.request(1, PM.CHANGE, number, sub, count, data, data_type or 0)
        self._send(device, job, slave, request, lambda values: self.complete(job))


__all__ = ["MC_ReadRecord", "MC_WriteRecord", "MC_ReadDriveParameter", "MC_WriteDriveParameter", "RECORD_MAX",
           "READ_PARAMETER_MAX", "WRITE_PARAMETER_MAX"]
