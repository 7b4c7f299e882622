"""The states an object can be in, as one flag set: the simulator, its effects (SMART-LLM's
vocabulary), the goal checker and the planner all read these bits.

>>> ObjectState.OPEN | ObjectState.ON
<ObjectState.OPEN|ON: 6>
>>> [FLAG_NAMES[b] for b in FLAG_NAMES if (HOT | COLD) & b]
['hot', 'cold']
"""

from __future__ import annotations

from enum import IntFlag


class ObjectState(IntFlag):
    PRESENT = 1  # in the world (a sliced object is replaced by its slices)
    OPEN = 2
    ON = 4  # switched on
    CLEAN = 8
    HOT = 16
    COLD = 32
    BROKEN = 64  # SMART-LLM's vocabulary: break, cook, fill
    COOKED = 128
    FILLED = 256


# Plain ints for the simulator's and planner's inner loops (an IntFlag operation costs a method call).
PRESENT, OPEN, ON, CLEAN, HOT, COLD, BROKEN, COOKED, FILLED = (int(flag) for flag in ObjectState)
FLAG_NAMES: dict[int, str] = {int(flag): str(flag.name).lower() for flag in ObjectState}
