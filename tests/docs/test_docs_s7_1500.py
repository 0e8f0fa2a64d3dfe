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
