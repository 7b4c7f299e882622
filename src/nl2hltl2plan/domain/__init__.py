"""The vocabulary every stage shares, below the worlds: the state an object can be in (`object_state`),
the task ontology: kinds of base task, their slots, states and goals (`task_kinds`), and one action
of a plan as the planner reports it (`plan_events.PlanEvent`).
The action atom itself lives in `logic.atom` (a spec's leaves are made of atoms)."""
