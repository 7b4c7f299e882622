"""`python -m nl2hltl2plan ...` runs the console script (useful from a worktree with PYTHONPATH=src)."""

from nl2hltl2plan.cli.main import main

raise SystemExit(main())
