"""Write docs/plan.schema.json from the pydantic model of a plan (`worlds.plan.plan_json_schema`).

    python scripts/plan_schema.py          # rewrite the committed schema
    python scripts/plan_schema.py --check  # exit 1 when the committed schema differs from the model

tests/pictures/test_formats.py runs the same comparison.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from nl2hltl2plan.worlds.plan import plan_json_schema

SCHEMA = Path(__file__).resolve().parents[1] / "docs" / "plan.schema.json"


def rendered() -> str:
    return json.dumps(plan_json_schema(), indent=2, ensure_ascii=False) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="compare only; exit 1 on a difference")
    args = ap.parse_args()
    if args.check:
        same = SCHEMA.exists() and SCHEMA.read_text() == rendered()
        print(
            "docs/plan.schema.json matches the model"
            if same
            else "docs/plan.schema.json differs from the model"
        )
        sys.exit(0 if same else 1)
    SCHEMA.write_text(rendered())
    print(f"wrote {SCHEMA}")


if __name__ == "__main__":
    main()
