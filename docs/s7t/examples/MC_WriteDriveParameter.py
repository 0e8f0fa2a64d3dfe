"""MC_WriteDriveParameter: write p1082 (maximum speed, REAL) of the drive at logical base address 256; a value
below the parameter's limit is refused by the drive with 16#8102 (S7-Technology V4.1 §6.7.11)."""
import struct

from plcmotion import Controller
from plcmotion.s7t import MC_WriteDriveParameter

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
ctl.add_positioning_axis("Axis1", {})
good, bad = MC_WriteDriveParameter(), MC_WriteDriveParameter()


@ctl.program
def ob1():
    good(Execute=True, Address=256, ParameterNumber=1082, Data=struct.pack(">f", 4500.0))
    bad(Execute=good.Done, Address=256, ParameterNumber=1082, Data=struct.pack(">f", -1.0))


ctl.run(0.1)
assert good.Done and bad.Error and bad.ErrorID == 0x8102
print(f"p1082 = 4500.0 written; -1.0 refused with 16#{bad.ErrorID:04X}")
