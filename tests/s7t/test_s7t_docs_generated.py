"""docs/s7t/errorids.md and docs/s7t/parameters.md are generated from the S7-Technology V4.1 tables
(tools/gen_s7t_docs.py, part "tables"); the committed pages must equal the generator's output."""
from __future__ import annotations

import pathlib

from _s7t_tools import tool

ROOT = pathlib.Path(__file__).resolve().parents[2]




def test_s7t_docs_equal_the_generated_pages():
    """Run `PYTHONPATH=src python -m tools.gen_s7t_docs tables` after changing a table."""
    for rel, text in tool("gen_s7t_docs").render("tables").items():
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


def test_s7t_docs_one_generator_checks_every_page(capsys):
    """S7-Technology V4.1 §6, §7.12, §9.4 pages: the one generator knows the three parts (tables, core
    instructions, basic-function FBs); `--check` finds every committed page up to date, `--check` on a part
    checks only that part's pages, and an unknown part is refused."""
    gen = tool("gen_s7t_docs")
    everything = gen.render()
    assert set(everything) == {rel for part in gen.PARTS for rel in gen.render(part)}
    assert {"docs/s7t/errorids.md", "docs/s7t/instructions/MC_Power.md",
            "docs/s7t/instructions/MC_ReadSysParameter.md"} <= set(everything)
    assert gen.main(["--check"]) == 0
    assert gen.main(["--check", "basic"]) == 0
    try:
        gen.main(["--check", "nothing"])
    except SystemExit as exc:
        assert exc.code == 2
    else:
        raise AssertionError("an unknown part must be refused")
    assert "unknown part 'nothing'" in capsys.readouterr().err
