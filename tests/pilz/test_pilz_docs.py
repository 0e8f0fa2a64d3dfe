"""The Pilz documentation: every example script runs (they assert their key results) and draws its plot, each
command page shows its script verbatim with the plot that script drew, and the index links every page (Pilz
V6.5 §1.1 ... §1.12).  tools/gen_pilz_plots.py renews the plots and the pages' copies of the scripts."""
from __future__ import annotations

import re
import runpy
from pathlib import Path
from types import SimpleNamespace

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs" / "pilz"
SCRIPTS = sorted((DOCS / "examples").glob("*.py"))
COMMANDS = ("MC_DoNothing", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_Stop",
            "MC_Home", "MC_CyclicSpeed", "MC_MoveSpeed", "MC_TorqueControl", "MC_CyclicPosition", "MC_Halt")
PNG = b"\x89PNG\r\n\x1a\n"
_EMBED = re.compile(r"<!-- example: (docs/pilz/examples/[\w.]+) -->\n```python\n(.*?)```\n<!-- end example -->",
                    re.DOTALL)


def test_pilz_docs_a_page_and_an_example_per_command():
    """Pilz V6.5 Tab. 1: commands 0 ... 11, each with a page and a runnable example."""
    assert sorted(p.stem for p in SCRIPTS) == sorted(COMMANDS)
    index = (DOCS / "index.md").read_text()
    for name in COMMANDS:
        page = (DOCS / "commands" / f"{name}.md").read_text()
        blocks = _EMBED.findall(page)
        assert [b[0] for b in blocks] == [f"docs/pilz/examples/{name}.py"]
        assert blocks[0][1] == (ROOT / blocks[0][0]).read_text(), f"{name}.md does not show the current script"
        assert f"(commands/{name}.md)" in index


def _tool() -> SimpleNamespace:
    """tools/gen_pilz_plots.py's functions (run as a module, not as the script)."""
    return SimpleNamespace(**runpy.run_path(str(ROOT / "tools" / "gen_pilz_plots.py"), run_name="gen_pilz_plots"))


@pytest.mark.parametrize("script", [*SCRIPTS, ROOT / "examples" / "pilz_drive.py"], ids=lambda p: p.stem)
def test_pilz_docs_example_runs(script, capsys, tmp_path, monkeypatch):
    """Pilz V6.5 §1.x: the example of each command does what its page says (the scripts assert it) and writes
    its plot, one PNG named after the command."""
    monkeypatch.setenv("PLCMOTION_DOCS_IMG", str(tmp_path))
    runpy.run_path(str(script), run_name="__main__")
    out = capsys.readouterr().out
    assert out.strip()
    if script.parent.name == "examples" and script.parent.parent == DOCS:
        png = tmp_path / f"{script.stem}.png"
        assert [p.name for p in tmp_path.iterdir()] == [png.name]
        assert png.read_bytes()[:8] == PNG and str(png) in out


@pytest.mark.parametrize("name", COMMANDS)
def test_pilz_docs_page_shows_the_plot_its_current_example_drew(name):
    """Pilz V6.5 §1.x: each command page shows a committed plot, and that plot was drawn by the script the
    page shows (the PNG carries the SHA-256 of the script; `PYTHONPATH=src python tools/gen_pilz_plots.py
    <command>` renews both after a change of the example)."""
    tool = _tool()
    page = (DOCS / "commands" / f"{name}.md").read_text()
    assert page == tool.page_text(name, page), f"{name}.md does not show its script and plot as the tool writes"
    assert f"](../img/{name}.png)" in page.split("<!-- end example -->", 1)[1]
    png = DOCS / "img" / f"{name}.png"
    assert png.read_bytes()[:8] == PNG
    assert tool.stamped(png) == tool.digest(DOCS / "examples" / f"{name}.py"), \
        f"docs/pilz/img/{name}.png was not drawn by the current example: run tools/gen_pilz_plots.py {name}"


def test_pilz_docs_links_resolve():
    """The links between the Pilz pages point at files that exist."""
    for page in [DOCS / "index.md", DOCS / "denials.md", DOCS / "decisions.md", *(DOCS / "commands").glob("*.md")]:
        for target in re.findall(r"\]\(([^)#:]+\.md)", page.read_text()):
            assert (page.parent / target).exists(), f"{page.name}: {target}"


def test_pilz_docs_index_snippets_run():
    """The code on docs/pilz/index.md runs in order and does what the page says (a relative move by 100 on the
    register, then MC_Home and MC_MoveAbsolute to 150)."""
    ns: dict = {}
    for block in re.findall(r"```python\n(.*?)```", (DOCS / "index.md").read_text(), re.DOTALL):
        exec(compile(block, "docs/pilz/index.md", "exec"), ns)     # noqa: S102 - our own page
    assert ns["move"].Done and ns["axis"].status.I96 == pytest.approx(150.0)
