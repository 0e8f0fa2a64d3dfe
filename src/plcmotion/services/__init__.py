"""Services around a running controller: pacing to the wall clock (``plcmotion serve``) and, later, the
clients that watch and command it beside the paced loop (see ``serve.Service``).  This layer sits above
the project and trace layers; the kernel below it never sees the wall clock."""
from .clock import Clock, MonotonicClock
from .lateness import LatenessStats
from .pacing import REACTIONS, STOP, TAGS, WARN, Pacer, PacingTags
from .serve import Service, ServeLoop, Snapshot, make_loop

__all__ = ["Clock", "MonotonicClock", "LatenessStats", "Pacer", "PacingTags", "REACTIONS", "STOP", "TAGS", "WARN",
           "Service", "ServeLoop", "Snapshot", "make_loop"]
