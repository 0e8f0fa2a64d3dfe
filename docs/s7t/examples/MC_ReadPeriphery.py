"""MC_ReadPeriphery: read input bytes 4 and 5 of the technology I/O image while Enable is TRUE; DataValid
from the second call on (S7-Technology V4.1 §6.7.6)."""
from plcmotion import Controller
from plcmotion.s7t import MC_ReadPeriphery

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004, input_filter=0.0)
data = bytearray(2)
read = MC_ReadPeriphery()


@ctl.program
def ob1():
    read(Enable=True, InputOutput=False, ByteAddress=4, Data=data)


ctl.inputs["I4.0"] = True
ctl.inputs["I5.7"] = True
ctl.run(0.02)
assert read.DataValid and data == bytearray([0x01, 0x80])
print(f"IB4..IB5 = {data.hex()}")
