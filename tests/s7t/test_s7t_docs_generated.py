"""docs/s7t/errorids.md and docs/s7t/parameters.md are generated from the S7-Technology V4.1 tables
(tools/gen_s7t_docs.py); the committed pages must equal the generator's output."""
from __future__ import annotations

import importlib.util
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _tool():
    spec = importlib.util.spec_from_file_location("gen_s7t_docs", ROOT / "tools" / "gen_s7t_docs.py")
    tool = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = tool
    try:
        spec.loader.exec_module(tool)
    finally:
        del sys.modules[spec.name]
    return tool


def test_s7t_docs_equal_the_generated_pages():
    """Run `PYTHONPATH=src python tools/gen_s7t_docs.py` after changing a table."""
    for rel, text in _tool().render().items():
        assert (ROOT / rel).read_text(encoding="utf-8") == text, f"{rel} is out of date"


def test_s7t_docs_list_every_code_and_parameter():
    """S7-Technology V4.1 §6, §7.12, §9.4: the pages carry each FB code, each TDB table and all 318 parameters."""
    errorids = (ROOT / "docs/s7t/errorids.md").read_text(encoding="utf-8")
    params = (ROOT / "docs/s7t/parameters.md").read_text(encoding="utf-8")
    assert "| 16#8055 | Latching motion not allowed in current state |" in errorids
    assert "#### FB 463 MC_WriteCamTrackData" in errorids and "### Synchronization axis (§7.12.2)" in errorids
    assert params.count("\n| ") - params.count("\n| No. ") - params.count("\n| Value |") - params.count(
        "\n| --- ") == 318 + 195
    assert "| 4142 | – | `override.velocity` | Setpoints.Override.Velocity | REAL | 0.0 | 200.0 | RW |" in params
