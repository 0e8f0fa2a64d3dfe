"""The layers of docs/architecture.md (issue 9): the kernel knows no family and imports nothing above it.

The import rules are import-linter contracts in pyproject.toml; this test runs them, so the README's test
command checks them.  Two rules import-linter cannot express are checked here from the source: no kernel
code names a family, and the kernel's modules do not import each other in a circle."""
from __future__ import annotations

import ast
import pathlib

import pytest

import plcmotion
from plcmotion import Controller
from plcmotion.kernel import family as families

SRC = pathlib.Path(plcmotion.__file__).resolve().parent      # the package under test (installed or not)
ROOT = pathlib.Path(__file__).resolve().parents[1]           # the repository with pyproject.toml
FAMILY_NAMES = ("S7-1200", "S7-1500", "S7-1500T", "S7-Technology", "Pilz")


def test_import_contracts_hold():
    from importlinter.application import use_cases as lint   # a test dependency (pyproject: test extra)
    assert (ROOT / "pyproject.toml").exists(), "the tests run from the repository"
    from importlinter.configuration import configure

    configure()                                       # what the lint-imports command does first
    assert lint.lint_imports(config_filename=str(ROOT / "pyproject.toml"), no_logo=True, cache_dir=None), \
        "an import breaks the layers (run lint-imports for the details)"


def _code_strings(tree: ast.AST) -> list[tuple[int, str]]:
    """String constants of the code, without docstrings and ``doc=`` texts (they may cite a manual)."""
    docstrings = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.keyword) and node.arg == "doc":
            docstrings.update(id(n) for n in ast.walk(node.value))
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                docstrings.add(id(first.value))
    return [(n.lineno, n.value) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]


def test_no_kernel_code_names_a_family():
    found = []
    for path in sorted((SRC / "kernel").rglob("*.py")):
        for line, text in _code_strings(ast.parse(path.read_text(encoding="utf-8"))):
            if any(name in text for name in FAMILY_NAMES):
                found.append(f"{path.relative_to(SRC)}:{line}: {text!r}")
    assert not found, "\n".join(found)


def _kernel_import_graph() -> dict[str, set[str]]:
    """Kernel module -> kernel modules it imports, at top level, in functions and under TYPE_CHECKING."""
    kernel = SRC / "kernel"
    names = {p.stem for p in kernel.glob("*.py")} - {"__init__"}
    graph: dict[str, set[str]] = {n: set() for n in names}
    for n in names:
        for node in ast.walk(ast.parse((kernel / f"{n}.py").read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                targets = [node.module] if node.module else [a.name for a in node.names]
                graph[n].update(t.split(".")[0] for t in targets if t and t.split(".")[0] in names)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    out: list[set[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(comp)

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


# Kernel modules still in an import circle, all through ``self`` annotations of the axis mixins
# (``if TYPE_CHECKING: from .axis import PositioningAxis``) and the axis <-> runtime back-reference.  The
# composition of the axis from components (issue 9, item 3) removes them; until then the circle must not grow.
KNOWN_CIRCLE = {"axis", "command_table", "config", "fault_injection", "homing", "runtime", "switches",
                "table_run", "tags"}


def test_kernel_import_circles_do_not_grow():
    cycles = _cycles(_kernel_import_graph())
    grown = [sorted(c - KNOWN_CIRCLE) for c in cycles if not c <= KNOWN_CIRCLE]
    assert not grown, f"new kernel modules in an import circle: {grown}"
    assert len(cycles) <= 1, [sorted(c) for c in cycles]


def test_cycle_finder_sees_a_circle_through_type_checking_imports():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycles(graph) == [{"a", "b", "c"}]


def test_families_register_their_objects():
    """Controller(family=...) takes the registered families; each offers what its manual has."""
    assert families.names()[:3] == ("S7-1200", "S7-1500", "S7-1500T")
    assert Controller().family == "S7-1200"
    assert families.offering(families.CAM) == ("S7-1500T",)
    assert families.offering(families.COMMAND_TABLE) == ("S7-1200",)
    with pytest.raises(ValueError, match="family must be one of S7-1200, S7-1500, S7-1500T"):
        Controller(family="S7-300")


def test_a_new_family_is_a_registration_not_a_kernel_edit():
    """A family registered from outside the kernel creates its objects through Controller.add_* and puts
    its version rules and optional features in force."""
    from plcmotion.kernel.axis import PositioningAxis

    made = []

    def axis(ctl, name, flat, where):
        made.append((name, dict(flat), where))
        return ctl.new_axis(PositioningAxis, name, flat, where)

    fam = families.register(families.Family(
        "Test-Family", versions=(1, 2), default_version=2, factories={families.POSITIONING_AXIS: axis},
        rules=lambda v: frozenset({families.PULSE_SLICE_TIME}) if v >= 2 else frozenset()))
    try:
        ctl = Controller(family="Test-Family")
        assert ctl.technology_version == 2 and families.PULSE_SLICE_TIME in ctl.rules
        a = ctl.add_positioning_axis("A", {"DynamicLimits.MaxVelocity": 100.0})
        assert made == [("A", {"DynamicLimits.MaxVelocity": 100.0}, "axis A")] and ctl.axes["A"] is a
        with pytest.raises(ValueError, match="a cam needs a controller of family S7-1500T"):
            ctl.add_cam("C")
        with pytest.raises(ValueError, match="technology_version for Test-Family must be 1 or 2"):
            Controller(family="Test-Family", technology_version=3)
    finally:
        families._REGISTRY.pop(fam.name)
