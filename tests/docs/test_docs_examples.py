"""Smoke tests of the documentation: every script in docs/examples/ runs and writes its plot, the pages
show those scripts verbatim and the parameter tables of the manual match the instruction classes, the
links between the pages resolve, and the analog drive example project runs through the CLI.

The pages embed their example between ``<!-- example: docs/examples/X.py -->`` and
``<!-- end example -->``; after editing a script, refresh the pages with
``python tests/docs/test_docs_examples.py``.
"""
from __future__ import annotations

import re
import runpy
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
EXAMPLES = sorted((DOCS / "examples").glob("*.py"))
INSTRUCTIONS = ("MC_Power", "MC_Reset", "MC_Home", "MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative",
                "MC_MoveVelocity", "MC_MoveJog", "MC_CommandTable")
PNG = b"\x89PNG\r\n\x1a\n"
_EMBED = re.compile(r"(<!-- example: (docs/examples/[\w.]+) -->\n)(.*?)(<!-- end example -->)", re.DOTALL)


def _block(script: Path) -> str:
    return "```python\n" + script.read_text() + "```\n"


def sync_pages() -> list[Path]:
    """Rewrite the embedded example of every page from its script; returns the pages changed."""
    changed = []
    for page in sorted((DOCS / "instructions").glob("*.md")):
        text = page.read_text()
        new = _EMBED.sub(lambda m: m.group(1) + _block(ROOT / m.group(2)) + m.group(4), text)
        if new != text:
            page.write_text(new)
            changed.append(page)
    return changed


# --- the example scripts ---------------------------------------------------------------------------
def test_docs_there_is_an_example_per_instruction():
    assert [p.stem for p in EXAMPLES] == sorted(INSTRUCTIONS)


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.stem)
def test_docs_example_runs_and_writes_its_plot(script, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("PLCMOTION_DOCS_IMG", str(tmp_path))
    runpy.run_path(str(script), run_name="__main__")      # the scripts assert their key results
    png = tmp_path / f"{script.stem}.png"
    assert png.read_bytes()[:8] == PNG
    assert [p.name for p in tmp_path.iterdir()] == [png.name]
    assert str(png) in capsys.readouterr().out


# --- the pages -------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", INSTRUCTIONS)
def test_docs_page_shows_its_plot_and_its_example(name):
    page = DOCS / "instructions" / f"{name}.md"
    text = page.read_text()
    assert f"](../img/{name}.png)" in text
    assert (DOCS / "img" / f"{name}.png").read_bytes()[:8] == PNG      # the committed plot
    blocks = _EMBED.findall(text)
    assert [b[1] for b in blocks] == [f"docs/examples/{name}.py"]
    assert blocks[0][2] == _block(ROOT / blocks[0][1]), \
        f"{page.name} does not show the current script; run: python tests/docs/test_docs_examples.py"
    assert f"(instructions/{name}.md)" in (DOCS / "index.md").read_text()


def _manual_value(text: str):
    """A 'Default value' cell of the manual's parameter tables as a Python value."""
    if text == "-":
        return None
    if text in ("TRUE", "FALSE"):
        return text == "TRUE"
    if text.startswith("16#"):
        return int(text[3:], 16)
    return float(text) if "." in text else int(text)


@pytest.mark.parametrize("name", INSTRUCTIONS)
def test_docs_parameter_table_matches_the_instruction(name):
    """Names, declarations and default values in the page are those of the class (and of S7-1200 V6 §11.1)."""
    import plcmotion.s7_1200 as s7

    cls = getattr(s7, name)
    section = (DOCS / "instructions" / f"{name}.md").read_text().split("## Parameters", 1)[1].split("\n## ", 1)[0]
    rows = [[c.strip() for c in line.strip().strip("|").split("|")] for line in section.splitlines()
            if line.startswith("| ") and line.count("|") >= 6]
    table = {r[0]: (r[1], _manual_value(r[3])) for r in rows if r[1] in ("INPUT", "OUTPUT")}
    expected = {**{k: ("INPUT", v) for k, v in cls.INPUTS.items()},
                **{k: ("OUTPUT", v) for k, v in cls.OUTPUTS.items()}}
    assert set(table) == set(expected)
    for key, (decl, value) in expected.items():
        assert table[key][0] == decl, key
        assert table[key][1] == value and type(table[key][1]) is type(value), (key, table[key][1], value)


def test_docs_links_between_the_pages_resolve():
    pages = [DOCS / "index.md", *sorted((DOCS / "instructions").glob("*.md"))]
    for page in pages:
        for target in re.findall(r"\]\(([^)\s]+)\)", page.read_text()):
            if "://" in target:
                continue
            path = target.split("#", 1)[0]
            assert (page.parent / path).exists(), f"{page.relative_to(ROOT)}: broken link {target}"


# --- the analog drive example project --------------------------------------------------------------
def test_docs_analog_drive_example_runs_through_the_cli(tmp_path, capsys):
    from plcmotion.cli import main
    from plcmotion.trace import read_csv

    examples = ROOT / "examples"
    assert main(["check", str(examples / "analog_drive.toml")]) == 0
    assert "Slide (analog)" in capsys.readouterr().out
    csv, png = tmp_path / "slide.csv", tmp_path / "slide.png"
    code = main(["run", str(examples / "analog_drive.toml"), str(examples / "analog_drive_program.py"),
                 "--duration", "15", "--trace", str(csv), "--plot", str(png), "--quiet"])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "mode RUN" in out and "homed True" in out and "no error" in out
    columns, rows = read_csv(csv)
    data = dict(zip(columns, rows.T))
    assert data["Slide.StatusBits.HWLimitMinActive"].max() == 1.0      # homing turned back at the switch
    assert data["Slide.StatusBits.Error"].max() == 0.0
    assert data["Slide.Position"].max() == pytest.approx(400.0)       # the positioning move
    assert png.read_bytes()[:8] == PNG


if __name__ == "__main__":
    for p in sync_pages():
        print(f"updated {p.relative_to(ROOT)}")
    sys.exit(0)
