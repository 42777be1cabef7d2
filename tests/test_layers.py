"""The layer order of the acausal package, read from its source with ast (every import at any
depth, relative or absolute):

    core (0) → components (1) → models (1.5) → compiler (2) → simulation (3)
        → analysis | fmu | ocp (4: siblings that do not import each other)

A package imports only packages of a lower level. A single-file module directly under
src/acausal that imports no acausal package (acausal.errors) is a base leaf: any layer may
import it, and it imports nothing of acausal. One that imports packages is a top-level facade,
which no package imports. src/acausal/__init__.py may import anything. There is no import
cycle between packages.
"""
import ast
from pathlib import Path

import acausal

ROOT = Path(acausal.__file__).parent
LEVEL = {"core": 0, "components": 1, "models": 1.5, "compiler": 2, "simulation": 3,
         "analysis": 4, "fmu": 4, "ocp": 4}
PACKAGES = {p.name for p in ROOT.iterdir() if (p / "__init__.py").exists()}
MODULES = {p.stem for p in ROOT.glob("*.py")} - {"__init__"}


def unit_of(dotted: str) -> str:
    """The package or single-file module an 'acausal.x.y' name belongs to ('acausal' for
    the top-level __init__)."""
    parts = dotted.split(".")
    return parts[1] if len(parts) > 1 and parts[1] in PACKAGES | MODULES else "acausal"


def imports(path: Path):
    """(line, unit imported) for every acausal import in the file."""
    package = ["acausal", *path.relative_to(ROOT).parent.parts]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package[:len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            names = [f"{module}.{a.name}" for a in node.names] if module == "acausal" \
                else [module]
        else:
            continue
        for name in names:
            if name == "acausal" or name.startswith("acausal."):
                yield node.lineno, unit_of(name)


FILES = {path: (path.relative_to(ROOT).parts[0] if path.parent != ROOT else path.stem,
                list(imports(path))) for path in sorted(ROOT.rglob("*.py"))}
LEAVES = {unit for path, (unit, found) in FILES.items()
          if unit in MODULES and not any(target in PACKAGES for _, target in found)}


def allowed(unit: str, target: str) -> bool:
    """Whether a file of ``unit`` (a package, a single-file module or '__init__') may import
    ``target``."""
    if unit in LEAVES:
        return False
    if unit in PACKAGES:
        return target == unit or target in LEAVES or (
            target in PACKAGES and LEVEL[target] < LEVEL[unit])
    return True                                  # src/acausal/__init__.py and the facades


def violations():
    return [f"{path.relative_to(ROOT.parent)}:{line} {unit} -> {target}"
            for path, (unit, found) in FILES.items() for line, target in found
            if not allowed(unit, target)]


def cycles():
    """Import cycles between packages, each as 'a -> b -> ... -> a'."""
    edges = {p: {t for path, (u, found) in FILES.items() if u == p for _, t in found
                 if t in PACKAGES and t != p} for p in PACKAGES}
    found = set()

    def walk(chain):
        for nxt in sorted(edges[chain[-1]]):
            if nxt == chain[0]:
                found.add(" -> ".join(chain + [nxt]))
            elif nxt not in chain and nxt > chain[0]:      # each cycle once, from its least
                walk(chain + [nxt])
    for p in sorted(PACKAGES):
        walk([p])
    return sorted(found)


def test_every_package_has_a_level_and_errors_is_a_leaf():
    assert PACKAGES == set(LEVEL)
    assert "errors" in LEAVES


def test_imports_follow_the_layer_order():
    bad = violations()
    print("\n".join(bad))
    assert bad == []


def test_no_import_cycle_between_packages():
    found = cycles()
    print("\n".join(found))
    assert found == []
