"""The documentation generator of the checkout's ``tools`` package, for the tests of the generated pages."""
from __future__ import annotations

import importlib
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[2]


def tool(name: str) -> ModuleType:
    """``tools.<name>`` of this checkout (the generator ``gen_s7t_docs`` or one of its page definitions)."""
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    return importlib.import_module(f"tools.{name}")
