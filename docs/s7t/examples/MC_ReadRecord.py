"""MC_WriteRecord + MC_ReadRecord: a PROFIdrive parameter request in data record 47 of the drive at logical
base address 256 (read p2000, the reference speed) and its answer (S7-Technology V4.1 §6.7.8, §6.7.9)."""
import struct

from plcmotion import Controller
from plcmotion.s7t import MC_ReadRecord, MC_WriteRecord

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
ctl.add_positioning_axis("Axis1", {"Drive": {"ReferenceSpeed": 3000.0}})
# reference 1, request 1 (read value), axis 0, one parameter: attribute 16#10, 1 element, p2000 index 0
request = bytes([1, 0x01, 0, 1, 0x10, 1]) + struct.pack(">HH", 2000, 0)
answer = bytearray(16)
write, read = MC_WriteRecord(), MC_ReadRecord()


@ctl.program
def ob1():
    write(Execute=True, Address=256, RecordNumber=47, Data=request)
    read(Execute=write.Done, Address=256, RecordNumber=47, Data=answer)


ctl.run(0.1)
assert read.Done and read.DataLength == 10
assert struct.unpack(">f", answer[6:10])[0] == 3000.0
print(f"record 47 answer: {answer[:read.DataLength].hex()}")
