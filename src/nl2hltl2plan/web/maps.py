"""What the page's map needs: the world picture (the same drawing as `plan -o`'s world.png, labels
placed by adjustText) and the frame that maps metres onto it, so the page draws robots over it.

The picture is drawn once per world and kept; drawing takes the matplotlib lock (matplotlib is not
thread-safe) in a thread, so the event loop stays free meanwhile.
"""

from __future__ import annotations

import functools
import io
import threading
from typing import Any

from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.world import World

_DRAWING = threading.Lock()
PAD_IN = 0.1


def object_state(world: World, oid: str) -> str:
    """An object's starting state in words (the map's hover text)."""
    o = world.objects[oid]
    words = ["movable" if o.pickupable else ("receptacle" if o.affordances.receptacle else "fixed")]
    if o.affordances.openable:
        words.append("open" if o.is_open else "closed")
    if o.affordances.toggleable:
        words.append("on" if o.is_on else "off")
    if o.parent:
        words.append(f"in/on {o.parent}")
    if oid in world.unreachable:
        words.append("unreachable")
    return ", ".join(words)


def geometry(world: World) -> dict[str, Any]:
    """Cells with their centres (m) and the present objects with their positions and states."""
    cells = [[r, c, *world.xz((r, c))] for r, c in sorted(world.cells)]
    objects = [
        {"id": o.id, "type": o.type, "x": o.xz[0], "z": o.xz[1], "movable": o.pickupable,
         "state": object_state(world, o.id)}
        for o in world.objects.values()
        if o.present
    ]  # fmt: skip
    return {"name": world.name, "cell_m": 0.25, "cells": cells, "objects": objects}


@functools.lru_cache(maxsize=16)
def cached_world(name: str) -> World:
    """The world of this name, loaded once."""
    return load_world(name)


@functools.lru_cache(maxsize=16)
def world_map(name: str) -> tuple[bytes, dict[str, float]]:
    """The world picture as SVG and its frame: axes limits (m) and the axes' box as fractions of the
    picture (left/right from the left edge, top/bottom from the top edge)."""
    import matplotlib.pyplot as plt

    from nl2hltl2plan.present.pictures import draw_world

    world = cached_world(name)
    with _DRAWING:
        fig = draw_world(world, title=world.name)
        try:
            fig.canvas.draw()
            renderer = fig.canvas.get_renderer()
            box = fig.get_tightbbox(renderer).padded(PAD_IN)  # inches
            ax = fig.axes[0]
            axes = ax.get_window_extent(renderer).transformed(fig.dpi_scale_trans.inverted())
            (x0, x1), (z0, z1) = ax.get_xlim(), ax.get_ylim()
            frame = {
                "x0": x0, "x1": x1, "z0": z0, "z1": z1,
                "left": (axes.x0 - box.x0) / box.width, "right": (axes.x1 - box.x0) / box.width,
                "top": (box.y1 - axes.y1) / box.height, "bottom": (box.y1 - axes.y0) / box.height,
                "aspect": box.width / box.height,
            }  # fmt: skip
            buf = io.BytesIO()
            fig.savefig(buf, format="svg", bbox_inches=box)
        finally:
            plt.close(fig)
    return buf.getvalue(), frame
