"""What the S7-Technology page definitions share: the checkout root and the Markdown table cells.

The pages are written by the one generator ``tools/gen_s7t_docs.py``; the page definitions are
``gen_s7t_docs`` itself (ErrorIDs, parameters), ``gen_s7t_instruction_docs`` (the core instructions) and
``gen_s7t_basic_docs`` (the basic-function FBs of §6.7).
"""
from __future__ import annotations

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
if str(ROOT / "src") not in sys.path:          # run from a checkout without installing
    sys.path.insert(0, str(ROOT / "src"))


def cell(text: object) -> str:
    """A Markdown table cell: ``|`` escaped, a line break as a space."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def row(*cells: object) -> str:
    return "| " + " | ".join(cell(c) for c in cells) + " |"


__all__ = ["ROOT", "cell", "row"]
