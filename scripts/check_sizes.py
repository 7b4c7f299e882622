"""Report modules over 600 lines and functions over 100 lines in src/ (the brief's limits).

python scripts/check_sizes.py            # exit 1 when a limit is exceeded
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

MAX_MODULE, MAX_FUNCTION = 600, 100


def main() -> int:
    root = Path(__file__).resolve().parents[1] / "src"
    problems = []
    for path in sorted(root.rglob("*.py")):
        text = path.read_text()
        rel = path.relative_to(root)
        n = len(text.splitlines())
        if n > MAX_MODULE:
            problems.append(f"{rel}: module has {n} lines (limit {MAX_MODULE})")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                length = (node.end_lineno or node.lineno) - node.lineno + 1
                if length > MAX_FUNCTION:
                    problems.append(
                        f"{rel}:{node.lineno}: {node.name} has {length} lines (limit {MAX_FUNCTION})"
                    )
    print("\n".join(problems) or "all modules and functions within the limits")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
