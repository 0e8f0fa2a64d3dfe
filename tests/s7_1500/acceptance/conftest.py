"""Acceptance-style tests of the S7-1500T synchronous operation, written from the manual
(S7-1500/S7-1500T Synchronous operation functions V5) by reviewers who did not read the implementation."""
import os
import sys

HERE = os.path.dirname(__file__)
sys.path.insert(0, HERE)                          # the helper modules of this directory
sys.path.insert(0, os.path.dirname(HERE))         # tests/: _s7_1500_rig
