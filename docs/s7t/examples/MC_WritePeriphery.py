"""MC_WritePeriphery: write output byte 8 of the technology I/O image cyclically, retriggered with
Execute := NOT Busy AND NOT Error (S7-Technology V4.1 §6.7.7)."""
from plcmotion import Controller
from plcmotion.s7t import MC_WritePeriphery

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
write = MC_WritePeriphery()
counter = [0]


@ctl.program
def ob1():
    counter[0] = (counter[0] + 1) & 0xFF
    write(Execute=not write.Busy and not write.Error, ByteAddress=8, Data=bytes([counter[0]]))


ctl.run(0.1)
byte = sum(ctl.outputs[f"Q8.{b}"] << b for b in range(8))
assert not write.Error and byte != 0
print(f"QB8 = {byte}")
