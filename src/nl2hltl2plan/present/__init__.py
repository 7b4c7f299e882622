"""Presentation: the pictures (HTT, world map, trajectories, Gantt chart, handover and tabletop scenes)
and the files one run leaves behind (`present.outputs.write_outputs`). Nothing below this layer draws."""
