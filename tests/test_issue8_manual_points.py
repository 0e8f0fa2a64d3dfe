"""Issue 8, manual points of S7-1200 found wrong: the input filter timed from the switch edge (decision 33,
S7-1200 V6 §5.4.4.5), Simulation.Mode written with MC_WriteParam (V6 §12.9.19) and the V7 tags
StatusSensor[1].* / ErrorBits.AdaptionError (V7 §12.9.20, §12.9.22)."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from test_s7_1200_homing import SERVO, Bench

from plcmotion.s7_1200 import MC_MoveVelocity


# --- decision 33: the input filter runs from the edge ------------------------------------------------------
@settings(max_examples=12)
@given(filt=st.sampled_from([0.0004, 0.001, 0.0025, 0.0064, 0.0095]),
       velocity=st.floats(min_value=1.0, max_value=40.0), start=st.floats(min_value=99.0, max_value=99.5))
def test_decision33_filtered_input_changes_within_filter_plus_one_servo_cycle(filt, velocity, start):
    """S7-1200 V6 §5.4.4.5 (input filter, 6.4 ms by default), decision 33: the homing switch input (as the CPU
    sees it, ``ctl.inputs``) changes in the first servo cycle at or after switch edge + filter time, i.e.
    filter time + [0, 1) servo cycle after the load crossed the end of the switch - for any filter time and
    any phase of the edge between two servo cycles (issue 8: 7.75 ms with the default 6.4 ms filter)."""
    b = Bench(actor=1, extra={"Plant.InitialPosition": start}, cam_filter=filt)
    rows: list[tuple[float, float, bool]] = []
    b.ctl.on_post_servo(lambda t: rows.append((t, b.axis.drive.mechanical_position(), b.ctl.inputs["I0.0"])))
    b.start(MC_MoveVelocity(), Velocity=velocity)
    b.until(lambda: bool(rows) and rows[-1][2], 2.0, "the filtered homing switch input came on")
    k = next(i for i, r in enumerate(rows) if r[1] >= 100.0)        # first sample on the switch
    (t0, x0, _), (t1, x1, _) = rows[k - 1], rows[k]
    edge = t0 + (t1 - t0) * (100.0 - x0) / (x1 - x0)               # where the load crossed the switch end
    seen = next(r[0] for r in rows if r[2])                         # first servo cycle that sees it
    assert filt - 1e-9 <= seen - edge < filt + SERVO, (seen - edge, filt)
