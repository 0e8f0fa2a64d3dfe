"""CPU-time bench: the same scenarios as bench/axes.py and bench/sync.py, timed with process_time
(less sensitive to other processes on the machine than wall clock). Run with PYTHONPATH=<tree>/src from
<tree> so that its bench/ is imported."""
import sys, time, importlib.util, pathlib
root = pathlib.Path.cwd()
def load(name):
    spec = importlib.util.spec_from_file_location(name, root / "bench" / f"{name}.py")
    m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m); return m
kind, n, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
if kind == "axes":
    m = load("axes"); ctl = m.build(n, "servo"); ctl.run(0.1)
else:
    m = load("sync"); ctl, _ = m.build(n, "servo"); ctl.run(0.1)
t0 = time.process_time(); ctl.run(seconds); cpu = time.process_time() - t0
print(f"{kind} {n} rtf_cpu={seconds / cpu:.3f}")
