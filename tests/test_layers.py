"""The stages import downwards only (docs/CONTRACTS.md) and only logic/spot_backend.py imports Spot."""

import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "src" / "nl2hltl2plan"
ALLOWED = {
    "logic": set(),
    "worlds": {"logic"},
    "planning": {"logic", "worlds"},
    "language": {"logic", "worlds"},
    "evaluation": {"logic", "worlds", "planning", "language"},
    "cli": {"logic", "worlds", "planning", "language", "evaluation"},
}


def imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text())
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
    return names


def test_stages_import_downwards_only():
    bad = []
    for stage, allowed in ALLOWED.items():
        for path in (PKG / stage).rglob("*.py"):
            for name in imports(path):
                parts = name.split(".")
                if parts[0] == "nl2hltl2plan" and len(parts) > 1 and parts[1] in ALLOWED:
                    if parts[1] != stage and parts[1] not in allowed:
                        bad.append(f"{path.relative_to(PKG)} imports {name}")
    assert not bad, "\n".join(bad)


def test_only_spot_backend_imports_spot():
    users = [
        str(p.relative_to(PKG))
        for p in PKG.rglob("*.py")
        if any(n == "spot" or n.startswith("spot.") for n in imports(p))
    ]
    assert users == ["logic/spot_backend.py"]
