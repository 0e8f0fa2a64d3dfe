"""Rename test functions to the project's convention ``test_<scope>_<subject>`` and fix references to them.

The scope is the sub-folder of ``tests/`` a test module sits in (``tests/s7_1500/acceptance/x.py`` -> ``s7_1500``);
a module directly in ``tests/`` uses its own name (``tests/test_architecture.py`` -> ``architecture``). The scope
prefix keeps the names of different manual families apart: ``test_s7_1500_...`` and a later ``test_s7t_...`` never
collide, however alike their subjects are.

What is renamed: every test pytest collects, i.e. a module-level ``def test_...`` in a ``test_*.py`` module or a
method ``test_...`` of a class ``Test...``; a function decorated as a fixture is not a test and keeps its name. A
name that already starts with its scope (``test_s7_1200_...`` in ``tests/s7_1200/``) is left alone; one that starts
with the singular of its scope (``test_drive_...`` in ``tests/drives/``) gets the scope in place of that word, so
nothing is doubled.

References are found without a record of earlier runs: a word ``test_x`` in any text file of the checkout (tests,
docs, .ci, tools) that is no longer the name of anything (no function, class or module of that name, no variable
of that name in the same module), but whose conforming form ``test_<scope>_x`` is a test, is rewritten to it.
Where several scopes hold such a test, the test of the referencing module itself wins, then the one of the
module's own scope, then the one whose ``tests/<scope>/`` path is on the same line; otherwise the reference is
reported and left alone.  So the script can be run again after merging branches that still use old names: it is
idempotent and only ever touches names that no longer exist.  (A ``pytest -k`` expression that matches a part of
a name is no name and is not rewritten.)

Usage:  python tools/rename_tests.py [--check] [ROOT]
        --check: change nothing, list what would change, exit 1 if anything would.
        Exit 2 after renaming if a problem was reported (a collision, an ambiguous reference, a broken module).
"""
from __future__ import annotations

import argparse
import ast
import re
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

#: A scope whose singular form may already open a name (``test_drive_...`` in tests/drives/).
SINGULAR = {"drives": "drive", "cams": "cam", "docs": "doc"}
#: Text files whose references are fixed (besides the Python files); files without a suffix under .ci/ too.
TEXT_SUFFIXES = {".py", ".md", ".rst", ".txt", ".toml", ".cfg", ".ini", ".yml", ".yaml", ".sh"}
WORD = re.compile(r"(?<![\w./])test_\w+\b(?!\.\w)")


def scope_of(rel: Path) -> str:
    """The scope of a test module given by its path relative to tests/."""
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem.removeprefix("test_")


def conforming(name: str, scope: str) -> str:
    """The conventional form of test *name* in *scope* (the name itself if it already conforms)."""
    if name.startswith(f"test_{scope}_"):
        return name
    singular = SINGULAR.get(scope)
    if singular and name.startswith(f"test_{singular}_"):
        return f"test_{scope}_" + name[len(singular) + 6:]
    return f"test_{scope}_" + name[5:]


def old_forms(name: str, scope: str) -> list[str]:
    """Names *name* (conforming in *scope*) may have had before the convention."""
    rest = name[len(scope) + 6:]
    forms = [f"test_{rest}"]
    if scope in SINGULAR:
        forms.append(f"test_{SINGULAR[scope]}_{rest}")
    return forms


def _is_fixture(node: ast.AST) -> bool:
    return any("fixture" in ast.unparse(d) for d in node.decorator_list)


@dataclass
class Module:
    path: Path
    rel: Path                       # relative to tests/
    scope: str
    text: str
    tests: list[ast.FunctionDef] = field(default_factory=list)
    defs: set[str] = field(default_factory=set)    # functions and classes test_... it defines (tests, fixtures)
    bound: set[str] = field(default_factory=set)   # other names test_... it binds (variables, arguments, imports)
    final: list[str] = field(default_factory=list)  # the names of its tests after renaming


def collected_tests(tree: ast.Module) -> list[ast.FunctionDef]:
    """The functions pytest collects as tests: module level, or methods of a class Test*."""
    found = []
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            found.append(node)
        elif isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
            found += [n for n in node.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]
    return [n for n in found if n.name.startswith("test_") and not _is_fixture(n)]


def load_modules(root: Path, problems: list[str], broken: set[Path]) -> list[Module]:
    modules = []
    for path in sorted((root / "tests").rglob("*.py")):
        if "__pycache__" in path.parts:
            continue
        rel = path.relative_to(root / "tests")
        text = path.read_text(encoding="utf-8")
        mod = Module(path, rel, scope_of(rel), text)
        if "test_" in text:
            try:
                tree = ast.parse(text, filename=str(path))
            except SyntaxError as exc:          # e.g. merge conflict markers: leave the file alone
                problems.append(f"tests/{rel}:{exc.lineno}: not valid Python, skipped ({exc.msg})")
                broken.add(path)
                continue
            if path.name.startswith("test_") or path.name.endswith("_test.py"):
                mod.tests = collected_tests(tree)
            for node in ast.walk(tree):
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                    mod.defs.add(node.name)
                elif isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
                    mod.bound.add(node.id)
                elif isinstance(node, ast.arg):
                    mod.bound.add(node.arg)
                elif isinstance(node, ast.alias):
                    mod.bound.add(node.asname or node.name.split(".")[0])
            mod.defs = {n for n in mod.defs if n.startswith("test_")}
            mod.bound = {n for n in mod.bound if n.startswith("test_")}
        modules.append(mod)
    return modules


def rename_definitions(mod: Module, problems: list[str]) -> dict[str, str]:
    """Rename the non-conforming test definitions of *mod* in its text; return old -> new."""
    taken = mod.defs | mod.bound
    renames: dict[str, str] = {}
    lines = mod.text.splitlines(keepends=True)
    for node in mod.tests:
        new = conforming(node.name, mod.scope)
        if new == node.name:
            continue
        if node.name == f"test_{mod.scope}":
            problems.append(f"tests/{mod.rel}:{node.lineno}: {node.name} is only its scope; give it a subject")
            continue
        if new in taken or new in renames.values():
            problems.append(f"tests/{mod.rel}:{node.lineno}: {node.name} -> {new} collides with an existing name")
            continue
        line = lines[node.lineno - 1]
        head = re.compile(rf"(\bdef\s+){re.escape(node.name)}\b")
        lines[node.lineno - 1], count = head.subn(rf"\g<1>{new}", line, count=1)
        if count != 1:
            problems.append(f"tests/{mod.rel}:{node.lineno}: could not find 'def {node.name}' on its line")
            continue
        renames[node.name] = new
    mod.text = "".join(lines)
    return renames


def text_files(root: Path) -> list[Path]:
    try:
        out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=root,
                             capture_output=True, text=True, check=True).stdout.split("\n")
        paths = [root / p for p in out if p]
    except (OSError, subprocess.CalledProcessError):
        paths = [p for p in root.rglob("*") if ".git" not in p.parts and ".venv" not in p.parts]
    return [p for p in paths
            if p.is_file() and (p.suffix in TEXT_SUFFIXES or (p.suffix == "" and p.parent.name == ".ci"))
            and "golden" not in p.relative_to(root).parts[:2]]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("root", nargs="?", default=Path(__file__).resolve().parent.parent, type=Path)
    ap.add_argument("--check", action="store_true", help="change nothing; exit 1 if anything would change")
    args = ap.parse_args(argv)
    root: Path = args.root.resolve()
    problems: list[str] = []

    broken: set[Path] = set()
    modules = load_modules(root, problems, broken)
    by_path = {m.path: m for m in modules}
    renamed = 0
    for mod in modules:
        renames = rename_definitions(mod, problems)
        mod.final = [renames.get(n.name, n.name) for n in mod.tests]
        for old, new in renames.items():
            print(f"tests/{mod.rel}: {old} -> {new}")
            renamed += 1
            mod.defs.discard(old)
            mod.defs.add(new)

    # Names that exist: every test_ identifier of any module, and the test modules themselves.
    # Names that exist anywhere: functions and classes test_... (tests, fixtures, helpers) and the modules; a
    # name a module binds otherwise (a variable test_x) exists only in that module.
    known = set().union(*(m.defs for m in modules)) | {m.path.stem for m in modules}
    # Old form -> the conforming tests it may now be: {scope: {new names}} with the module of each.
    targets: dict[str, list[tuple[str, str, Path]]] = {}
    for mod in modules:
        for name in mod.final:
            if name.startswith(f"test_{mod.scope}_"):
                for old in old_forms(name, mod.scope):
                    if old not in known:
                        targets.setdefault(old, []).append((name, mod.scope, mod.path))

    changed: dict[Path, str] = {m.path: m.text for m in modules if m.text != m.path.read_text(encoding="utf-8")}
    refs = 0
    for path in text_files(root):
        if path in broken:
            continue
        text = changed.get(path) or (by_path[path].text if path in by_path else path.read_text(encoding="utf-8"))
        if "test_" not in text:
            continue
        rel = path.relative_to(root)
        own_scope = scope_of(rel.relative_to("tests")) if rel.parts[0] == "tests" and len(rel.parts) > 1 else None

        def fix(m: re.Match, path=path, rel=rel, own_scope=own_scope, text=text) -> str:
            nonlocal refs
            old = m.group(0)
            cands = targets.get(old)
            if not cands or (path in by_path and old in by_path[path].bound):
                return old
            pick = [c for c in cands if c[2] == path] or [c for c in cands if c[1] == own_scope]
            if not pick:
                end = text.find("\n", m.end())
                line = text[text.rfind("\n", 0, m.start()) + 1:end if end >= 0 else len(text)]
                pick = [c for c in cands if f"tests/{c[1]}/" in line]
            news = {c[0] for c in (pick or cands)}
            if len(news) != 1:
                problems.append(f"{rel}: reference {old} is ambiguous ({', '.join(sorted(news))}); left alone")
                return old
            new = news.pop()
            print(f"{rel}: reference {old} -> {new}")
            refs += 1
            return new

        new_text = WORD.sub(fix, text)
        if new_text != text:
            changed[path] = new_text

    for problem in problems:
        print("PROBLEM:", problem, file=sys.stderr)
    print(f"{renamed} test(s) renamed, {refs} reference(s) fixed, {len(changed)} file(s) "
          f"{'would change' if args.check else 'changed'}, {len(problems)} problem(s)")
    if args.check:
        return 1 if changed or problems else 0
    for path, text in changed.items():
        path.write_text(text, encoding="utf-8")
    return 2 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
