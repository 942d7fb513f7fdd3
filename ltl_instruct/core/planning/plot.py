"""A picture of a plan that shows at a glance that the path keeps the task's constraints.

The first panel is a top-down view of the whole plan: obstacles (grey), labelled
objects, the path coloured by segment and the skill steps. Then one panel per
navigation segment with its task progression map (goal green, avoid red, allowed
white), the obstacles and that segment's path. A drone plan adds a side view (x, z).
Uses matplotlib's Agg backend (no display needed).
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np

from ltl_instruct.core.errors import InvalidInputError

from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.regions import TaskProgressionMap
from ltl_instruct.core.planning.taskplan import NAVIGATE, TaskPlan
from ltl_instruct.core.world.scene import Scene

MAX_SEGMENT_PANELS = 8


def _colours(n: int) -> list:
    import matplotlib
    cmap = matplotlib.colormaps['tab10']
    return [cmap(i % 10) for i in range(max(n, 1))]


def _draw_static(ax, world: PlanningWorld, scene: Optional[Scene], view: str = 'xy') -> None:
    from matplotlib.patches import Rectangle
    a, b = (0, 1) if view == 'xy' else (0, 2)
    boxes = scene.blocking_boxes() if scene is not None else world.obstacles
    for box in boxes:
        lo, hi = box.lo, box.hi
        ax.add_patch(Rectangle((lo[a], lo[b]), hi[a] - lo[a], hi[b] - lo[b], facecolor='0.55',
                               edgecolor='0.3', lw=0.5, zorder=2))
    if scene is not None:
        for o in scene.objects:
            c = o.center
            if o.size is not None:
                lo, hi = o.box.lo, o.box.hi  # type: ignore[union-attr]
                ax.add_patch(Rectangle((lo[a], lo[b]), hi[a] - lo[a], hi[b] - lo[b], facecolor='none',
                                       edgecolor='tab:blue', lw=0.8, zorder=3))
            ax.plot(c[a], c[b], marker='.', color='tab:blue', ms=4, zorder=3)
            ax.annotate(o.label, (c[a], c[b]), fontsize=6, color='navy', xytext=(2, 2),
                        textcoords='offset points', zorder=6)
        lo_s, hi_s = scene.bounds_min, scene.bounds_max
    else:
        lo_s = tuple(world.bounds_min) + (0.0,) * (3 - world.dims)
        hi_s = tuple(world.bounds_max) + (1.0,) * (3 - world.dims)
    ax.set_xlim(lo_s[a], hi_s[a])
    ax.set_ylim(lo_s[b], hi_s[b])
    ax.set_aspect('equal')
    ax.tick_params(labelsize=6)


def _draw_tpsm(ax, tpsm: TaskProgressionMap, world: PlanningWorld, z: float) -> None:
    from matplotlib.colors import ListedColormap
    lo = np.asarray(world.bounds_min[:2])
    hi = np.asarray(world.bounds_max[:2])
    spacing = max(float(np.max(hi - lo)) / 240.0, 0.03)
    xs = np.arange(lo[0], hi[0] + 1e-9, spacing)
    ys = np.arange(lo[1], hi[1] + 1e-9, spacing)
    gx, gy = np.meshgrid(xs, ys, indexing='xy')
    pts = np.column_stack([gx.ravel(), gy.ravel()])
    if world.dims == 3:
        pts = np.column_stack([pts, np.full(len(pts), z)])
    values = tpsm.classify(pts).reshape(gx.shape).astype(float)
    cmap = ListedColormap(['#f4a3a3', '#ffffff', '#9fdf9f'])
    ax.imshow(values, origin='lower', extent=(xs[0], xs[-1], ys[0], ys[-1]), cmap=cmap, vmin=-1, vmax=1,
              interpolation='nearest', zorder=1)


def render_plan(plan: TaskPlan, world: PlanningWorld, out: Union[str, Path],
                scene: Optional[Scene] = None, title: Optional[str] = None) -> Path:
    """Draw a plan into a PNG file and return its path."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    nav = [s for s in plan.steps if s.kind == NAVIGATE and s.request is not None]
    shown = nav[:MAX_SEGMENT_PANELS]
    panels = 1 + (1 if plan.dims == 3 else 0) + len(shown)
    cols = min(3, panels)
    rows = int(math.ceil(panels / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.4 * rows), squeeze=False)
    flat = list(axes.ravel())
    colours = _colours(len(nav))
    ax = flat[0]
    _draw_static(ax, world, scene)
    for i, step in enumerate(nav):
        w = step.waypoints
        ax.plot(w[:, 0], w[:, 1], '-', color=colours[i], lw=1.8, zorder=4,
                label=f'{i + 1}: {step.state_before}->{step.state_after}')
    for step in plan.steps:
        if step.kind != NAVIGATE:
            p = step.end
            ax.plot(p[0], p[1], marker='*', color='k', ms=10, zorder=5)
            ax.annotate(step.skill, (p[0], p[1]), fontsize=6, xytext=(4, -8), textcoords='offset points',
                        zorder=6)
    ax.plot(plan.start[0], plan.start[1], 'ko', ms=5, zorder=5)
    ax.set_title(title or plan.formula, fontsize=8)
    if nav:
        ax.legend(fontsize=6, loc='upper right')
    k = 1
    if plan.dims == 3:
        side = flat[k]
        k += 1
        _draw_static(side, world, scene, view='xz')
        for i, step in enumerate(nav):
            side.plot(step.waypoints[:, 0], step.waypoints[:, 2], '-', color=colours[i], lw=1.8, zorder=4)
        if world.dims == 3:
            side.axhline(world.bounds_min[2], color='0.5', ls=':', lw=0.8)
            side.axhline(world.bounds_max[2], color='0.5', ls=':', lw=0.8)
        side.set_title('side view (x, z); dotted: altitude band', fontsize=8)
    for i, step in enumerate(shown):
        a = flat[k]
        k += 1
        req = step.request
        assert req is not None
        tpsm = TaskProgressionMap(req.goal, req.allowed, req.regions, req.dims)
        z = float(step.waypoints[-1][2]) if plan.dims == 3 else 0.0
        _draw_tpsm(a, tpsm, world, z)
        _draw_static(a, world, scene)
        a.plot(step.waypoints[:, 0], step.waypoints[:, 1], '-', color=colours[i], lw=2.0, zorder=4)
        a.plot(step.waypoints[0, 0], step.waypoints[0, 1], 'ko', ms=4, zorder=5)
        a.set_title(_wrap(f'segment {i + 1}: {step.state_before}->{step.state_after}  goal: {step.goal}  '
                          f'(green goal, red avoid)'), fontsize=7)
    for a in flat[k:]:
        a.axis('off')
    fig.tight_layout()
    return save_png(fig, out, dpi=110)


def check_output_path(out: Union[str, Path]) -> Path:
    """Return ``out`` as a path if a file can be written there, else raise ``INVALID_INPUT``.

    The path is used as given: no suffix is added and no directory is created, so
    the folder must exist already.
    """
    path = Path(out)
    if not str(out) or path.is_dir():
        raise InvalidInputError(f'cannot write {str(out)!r}: not a file path', details={'file': str(out)})
    parent = path.parent
    if not parent.is_dir():
        raise InvalidInputError(f'cannot write {path}: the folder {parent} does not exist',
                                details={'file': str(path)})
    return path


def save_png(fig: Any, out: Union[str, Path], dpi: int) -> Path:
    """Write ``fig`` as PNG to exactly ``out`` and close it; a failed write is ``INVALID_INPUT``."""
    import matplotlib.pyplot as plt
    path = check_output_path(out)
    try:
        fig.savefig(path, dpi=dpi, format='png')   # format given: matplotlib adds no suffix
    except OSError as e:
        raise InvalidInputError(f'cannot write {path}: {e.strerror or e}',
                                details={'file': str(path)}) from None
    finally:
        plt.close(fig)
    return path


def _wrap(text: str, width: int = 70) -> str:
    lines: list[str] = []
    while len(text) > width:
        cut = text.rfind(' ', 0, width)
        cut = cut if cut > 0 else width
        lines.append(text[:cut])
        text = text[cut:].lstrip()
    lines.append(text)
    return '\n'.join(lines[:4])


def render_points(values: Sequence[int]) -> dict:
    """Count the goal / avoid / neutral values of a rendered TPSM (for reports)."""
    v = np.asarray(values)
    return {'goal': int((v == 1).sum()), 'avoid': int((v == -1).sum()), 'neutral': int((v == 0).sum())}
