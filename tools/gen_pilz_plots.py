"""Run the Pilz command examples, write their plots to docs/pilz/img/<command>.png and put the current
script and its plot on the command page docs/pilz/commands/<command>.md.

    PYTHONPATH=src python tools/gen_pilz_plots.py                   # every command
    PYTHONPATH=src python tools/gen_pilz_plots.py MC_Stop MC_Halt   # some

Each PNG carries the SHA-256 of the script that drew it (a PNG text chunk ``plcmotion-example``), so
tests/pilz/test_pilz_docs.py can tell that the committed plot is the one the current example produces.
"""
from __future__ import annotations

import hashlib
import os
import re
import struct
import subprocess
import sys
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "pilz"
IMG = DOCS / "img"
KEY = b"plcmotion-example"
_EMBED = re.compile(r"(<!-- example: (docs/pilz/examples/[\w.]+) -->\n```python\n)(.*?)(```\n<!-- end example -->\n)"
                    r"(\n?!\[[^\]]*\]\(\.\./img/[\w.]+\)\n)?", re.DOTALL)


def digest(script: Path) -> str:
    return hashlib.sha256(script.read_bytes()).hexdigest()


def stamp(png: Path, value: str) -> None:
    """Insert a tEXt chunk KEY = value after the IHDR chunk of ``png``."""
    data = png.read_bytes()
    ihdr_end = 8 + 8 + struct.unpack(">I", data[8:12])[0] + 4
    body = b"tEXt" + KEY + b"\0" + value.encode("ascii")
    chunk = struct.pack(">I", len(body) - 4) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    png.write_bytes(data[:ihdr_end] + chunk + data[ihdr_end:])


def stamped(png: Path) -> str | None:
    """The value of the KEY text chunk of ``png`` (None: not stamped)."""
    data = png.read_bytes()
    pos = 8
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"tEXt":
            key, _, value = data[pos + 8:pos + 8 + length].partition(b"\0")
            if key == KEY:
                return value.decode("ascii")
        pos += 12 + length
    return None


def page_text(name: str, text: str) -> str:
    """The page with the current script of ``name`` embedded and its plot shown below it."""
    script = DOCS / "examples" / f"{name}.py"

    def embed(m: re.Match) -> str:
        return (f"{m.group(1)}{script.read_text()}{m.group(4)}\n"
                f"![{name}: position, velocity and status timeline](../img/{name}.png)\n")
    return _EMBED.sub(embed, text, count=1)


def build(name: str) -> None:
    script = DOCS / "examples" / f"{name}.py"
    env = {**os.environ, "PLCMOTION_DOCS_IMG": str(IMG)}
    subprocess.run([sys.executable, str(script)], check=True, env=env, cwd=ROOT)
    stamp(IMG / f"{name}.png", digest(script))
    page = DOCS / "commands" / f"{name}.md"
    page.write_text(page_text(name, page.read_text()))


def main(argv: list[str]) -> None:
    names = argv or sorted(p.stem for p in (DOCS / "examples").glob("*.py"))
    for name in names:
        build(name)


if __name__ == "__main__":
    main(sys.argv[1:])
