"""The layers of docs/architecture.md (issue 9): the kernel knows no family and imports nothing above it.

The import rules are import-linter contracts in pyproject.toml; this test runs them, so the README's test
command checks them.  Two rules import-linter cannot express are checked here from the source: no kernel
code names a family, and the kernel's modules do not import each other in a circle."""
from __future__ import annotations

import ast
import pathlib
import re

import pytest

import plcmotion
from plcmotion import Controller
from plcmotion.kernel import family as families

SRC = pathlib.Path(plcmotion.__file__).resolve().parent      # the package under test (installed or not)
ROOT = pathlib.Path(__file__).resolve().parents[1]           # the repository with pyproject.toml
FAMILY_NAMES = ("S7-1200", "S7-1500", "S7-1500T", "S7-Technology", "Pilz")


def test_architecture_import_contracts_hold():
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


def test_architecture_no_kernel_code_names_a_family():
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


def test_architecture_kernel_has_no_import_circle():
    """Issue 9, "Done when": no import circle among the kernel's modules, ``TYPE_CHECKING`` imports counted.
    The axis's components type their host with a Protocol of their own module, and the axis and the sync
    stage see the controller as ``protocols.ServoHost``, so no kernel module needs to import the axis or
    the runtime back."""
    cycles = _cycles(_kernel_import_graph())
    assert not cycles, f"kernel modules in an import circle: {[sorted(c) for c in cycles]}"


def test_architecture_cycle_finder_sees_a_circle_through_type_checking_imports():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycles(graph) == [{"a", "b", "c"}]


def test_architecture_families_register_their_objects():
    """Controller(family=...) takes the registered families; each offers what its manual has."""
    assert families.names()[:3] == ("S7-1200", "S7-1500", "S7-1500T")
    assert Controller().family == "S7-1200"
    assert families.offering(families.CAM) == ("S7-1500T",)
    assert families.offering(families.COMMAND_TABLE) == ("S7-1200",)
    with pytest.raises(ValueError, match="family must be one of S7-1200, S7-1500, S7-1500T"):
        Controller(family="S7-300")


def test_architecture_a_new_family_is_a_registration_not_a_kernel_edit():
    """A family registered from outside the kernel creates its objects through Controller.add_* and puts
    its version rules and optional features in force."""
    from plcmotion.s7_1200.technology.axis import PositioningAxis     # an axis class with a schema

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


# --- test naming (issue 9, item 7) -----------------------------------------------------------------------------
# Every test is named test_<scope>_<subject>, the scope being its sub-folder of tests/ (a module directly in tests/
# uses its own name), so the tests of different families never share a name.  A manual section cited by a test
# names the manual, because §-numbers of different manuals collide (S7-1500T V5 §9.3 is not S7-Technology §9.3).
# tools/rename_tests.py brings names (and references to them) into this form.

TESTS = ROOT / "tests"
# A short manual name ("S7-1200 V6", "S7-1500T V5", "S7-Technology V4.1", "Pilz") or a standard with its own
# numbering.
MANUAL_NAME = re.compile(r"S7-1200|S7-1500|S7-Technology|Pilz|PLCopen|PROFIdrive|OPC UA|IEC 61131|VDI 2143")
SECTION_IN_TEXT = re.compile(r"§\s*[0-9A-Z]")
# _s9_3_1, _sA_2 or a bare _5_4_4_3 in a name; the family names s7_1200/s7_1500 are no sections.
SECTION_IN_NAME = re.compile(r"(?:^|_)(?:s(?!7_1[25]00(?:_|$))(?:\d+|A)(?:_\d+)+|\d+(?:_\d+){2,})(?=_|$)")


def _test_modules() -> list[tuple[str, pathlib.Path, ast.Module]]:
    """(scope, path, tree) of every test module under tests/."""
    out = []
    for path in sorted(TESTS.rglob("test_*.py")):
        rel = path.relative_to(TESTS)
        scope = rel.parts[0] if len(rel.parts) > 1 else rel.stem.removeprefix("test_")
        out.append((scope, path, ast.parse(path.read_text(encoding="utf-8"))))
    return out


def _collected_tests(tree: ast.Module) -> list[ast.FunctionDef]:
    """What pytest collects: module-level test functions and test methods of Test* classes, no fixtures."""
    found = []
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            found.append(node)
        elif isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
            found += [n for n in node.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]
    return [n for n in found if n.name.startswith("test")
            and not any("fixture" in ast.unparse(d) for d in n.decorator_list)]


def test_architecture_every_test_is_named_after_its_scope():
    wrong = [f"{path.relative_to(ROOT)}:{node.lineno}: {node.name} (want test_{scope}_...)"
             for scope, path, tree in _test_modules() for node in _collected_tests(tree)
             if not node.name.startswith(f"test_{scope}_")]
    assert not wrong, "run tools/rename_tests.py:\n" + "\n".join(wrong)


def test_architecture_a_cited_section_names_its_manual():
    """A test citing a § (in its name or docstring) names the manual in its docstring or its module's."""
    unnamed = []
    for _, path, tree in _test_modules():
        if MANUAL_NAME.search(ast.get_docstring(tree) or ""):
            continue
        for node in _collected_tests(tree):
            doc = ast.get_docstring(node) or ""
            if (SECTION_IN_TEXT.search(doc) or SECTION_IN_NAME.search(node.name)) and not MANUAL_NAME.search(doc):
                unnamed.append(f"{path.relative_to(ROOT)}:{node.lineno}: {node.name}")
    assert not unnamed, "say which manual the section is from (e.g. 'S7-1500T V5 §9.3.1'):\n" + "\n".join(unnamed)


@pytest.mark.parametrize("name, cites", [
    ("test_s7_1500_cam_in_rejections_s9_1_5", True), ("test_cams_header_sA_2_4", True),
    ("test_s7_1200_braking_never_passes_limit_5_4_4_3", True), ("test_s7_1500_s7_1200_instructions", False),
    ("test_drives_s1_to_s2_needs_on_reset", False), ("test_kernel_defect_5_7", False)])
def test_architecture_section_in_a_test_name(name, cites):
    assert bool(SECTION_IN_NAME.search(name)) is cites


def test_architecture_rename_tool_renames_tests_and_references_once(tmp_path):
    """tools/rename_tests.py on a small checkout: scope prefix added (not doubled, the singular of the scope
    replaced), fixtures and helpers kept, references rewritten; a second run changes nothing."""
    import importlib.util
    import sys

    spec = importlib.util.spec_from_file_location("rename_tests", ROOT / "tools" / "rename_tests.py")
    tool = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = tool                      # its dataclasses look their module up
    try:
        spec.loader.exec_module(tool)
    finally:
        del sys.modules[spec.name]
    files = {
        "tests/drives/test_x.py": ('import pytest\n\n@pytest.fixture\ndef test_data():\n    return 1\n\n\n'
                                   'def helper():\n    pass\n\n\n'
                                   'def test_speed(test_data):\n    """See test_drive_ready."""\n'
                                   '\n\ndef test_drive_ready():\n    pass\n\n\ndef test_drives_done():\n    pass\n\n\n'
                                   'class TestGroup:\n    def test_inner(self):\n        pass\n'),
        "tests/s7_1500/acceptance/test_y.py": "def test_s7_1200_axis_is_refused():\n    test_speed = 1\n",
        "tests/test_top.py": "def test_speed():\n    pass\n",
        "docs/notes.md": ("run `pytest -k test_inner`; see test_drive_ready, tests/drives/test_x.py::test_speed,"
                          " test_x.py and test_data\n"),
    }
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text, encoding="utf-8")
    assert tool.main([str(tmp_path)]) == 0
    drives = (tmp_path / "tests/drives/test_x.py").read_text(encoding="utf-8")
    for name in ("def test_data(", "def helper(", "def test_drives_speed(test_data)", '"""See test_drives_ready."""',
                 "def test_drives_ready(", "def test_drives_done(", "def test_drives_inner(self)"):
        assert name in drives
    assert "def test_s7_1500_s7_1200_axis_is_refused():\n    test_speed = 1\n" == \
        (tmp_path / "tests/s7_1500/acceptance/test_y.py").read_text(encoding="utf-8")
    assert "def test_top_speed():" in (tmp_path / "tests/test_top.py").read_text(encoding="utf-8")
    assert (tmp_path / "docs/notes.md").read_text(encoding="utf-8") == (
        "run `pytest -k test_drives_inner`; see test_drives_ready, tests/drives/test_x.py::test_drives_speed,"
        " test_x.py and test_data\n")
    before = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    assert tool.main([str(tmp_path), "--check"]) == 0 and tool.main([str(tmp_path)]) == 0
    assert before == {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
