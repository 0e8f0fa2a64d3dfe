"""MC_ReadPeriphery: read input bytes 4 and 5 of the technology I/O image while Enable is TRUE; DataValid
from the second call on (S7-Technology V4.1 §6.7.6).
Writes docs/img/s7t/MC_ReadPeriphery.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ReadPeriphery
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004, input_filter=0.0)
data = bytearray(2)
read = MC_ReadPeriphery()


@ctl.program
def ob1():
    read(Enable=True, InputOutput=False, ByteAddress=4, Data=data)


trace = Trace(ctl, {
    "read.Busy": lambda: read.Busy, "read.DataValid": lambda: read.DataValid,
    "IB4 (Data[0])": lambda: data[0], "IB5 (Data[1])": lambda: data[1],
}).start()
ctl.inputs["I4.0"] = True
ctl.inputs["I5.7"] = True
ctl.run(0.02)
trace.stop()
assert read.DataValid and data == bytearray([0x01, 0x80])
print(f"IB4..IB5 = {data.hex()}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ReadPeriphery.png", title="MC_ReadPeriphery: read input bytes 4..5 while Enable")
print(f"wrote {out / 'MC_ReadPeriphery.png'}")
