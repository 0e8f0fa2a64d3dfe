"""The S7-1500 documentation: its example scripts run, its ErrorID table matches the code, its links resolve."""
import re
import runpy
from pathlib import Path

import pytest

from plcmotion.s7_1500 import errors as E

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs" / "s7_1500"


@pytest.mark.parametrize("script", sorted((DOCS / "examples").glob("*.py")), ids=lambda p: p.stem)
def test_docs_example_runs(script, capsys):
    runpy.run_path(str(script), run_name="__main__")          # the scripts assert their key results
    assert capsys.readouterr().out


def test_docs_errorid_page_lists_every_code():
    text = (DOCS / "errorids.md").read_text()
    for code, meaning in E.table():
        assert f"| 16#{code:04X} | {meaning} |" in text


def test_docs_links_resolve():
    for page in DOCS.glob("*.md"):
        for target in re.findall(r"\]\(([^)#]+)\)", page.read_text()):
            if not target.startswith("http"):
                assert (page.parent / target).exists(), f"{page.name}: {target}"


def test_docs_errorid_page_is_generated_from_the_table():
    """docs/s7_1500/errorids.md is tools/gen_s7_1500_errorids.py's output for the table the instructions use
    (run `PYTHONPATH=src python tools/gen_s7_1500_errorids.py` after changing it)."""
    render = runpy.run_path(str(ROOT / "tools" / "gen_s7_1500_errorids.py"))["render"]
    assert (DOCS / "errorids.md").read_text(encoding="utf-8") == render()
    for c in E.CODES:                           # each code names the instructions that give it, or why none does
        assert bool(E.instructions_of(c.number)) != bool(c.unreachable), hex(c.number)
