"""MC_WritePeriphery: write output byte 8 of the technology I/O image cyclically, retriggered with
Execute := NOT Busy AND NOT Error (S7-Technology V4.1 §6.7.7).
Writes docs/img/s7t/MC_WritePeriphery.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_WritePeriphery
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
write = MC_WritePeriphery()
counter = [0]


@ctl.program
def ob1():
    counter[0] = (counter[0] + 1) & 0xFF
    write(Execute=not write.Busy and not write.Error, ByteAddress=8, Data=bytes([counter[0]]))


trace = Trace(ctl, {
    "write.Busy": lambda: write.Busy, "write.Done": lambda: write.Done, "write.Error": lambda: write.Error,
    "Data[0] (counter)": lambda: counter[0],
    "QB8": lambda: sum(ctl.outputs[f"Q8.{b}"] << b for b in range(8)),
}).start()
ctl.run(0.1)
trace.stop()
byte = sum(ctl.outputs[f"Q8.{b}"] << b for b in range(8))
assert not write.Error and byte != 0
print(f"QB8 = {byte}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_WritePeriphery.png", title="MC_WritePeriphery: cyclic write of output byte 8")
print(f"wrote {out / 'MC_WritePeriphery.png'}")
