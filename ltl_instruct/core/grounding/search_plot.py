"""A picture of a search: the area the camera saw, the path driven, the views, what was found.

Top-down, over the scene as the plan pictures draw it (:mod:`ltl_instruct.core.planning.plot`):
obstacles grey, the scene's objects outlined in blue; the cells seen shaded green, the
search path black from the start (a square) with a dot at every panorama, and the
instances the task's descriptors resolved to outlined in red. Matplotlib's Agg backend.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Union

from ltl_instruct.core.grounding.search import SearchResult
from ltl_instruct.core.planning.occupancy import world_from_scene
from ltl_instruct.core.planning.plot import _draw_static, _wrap, save_png
from ltl_instruct.core.world.scene import Scene


def _draw_seen(ax: Any, result: SearchResult) -> None:
    from matplotlib.colors import ListedColormap
    g = result.grid
    extent = (g.origin[0], g.origin[0] + g.shape[0] * g.cell, g.origin[1], g.origin[1] + g.shape[1] * g.cell)
    ax.imshow(result.seen.T.astype(float), origin='lower', extent=extent, interpolation='nearest',
              cmap=ListedColormap(['#ffffff', '#c8ecc8']), vmin=0, vmax=1, zorder=1)


def _draw_found(ax: Any, result: SearchResult) -> None:
    from matplotlib.patches import Rectangle
    for text, g in result.referent_map.groundings.items():
        for inst in g.instances:
            lo = (inst.center[0] - inst.size[0] / 2, inst.center[1] - inst.size[1] / 2)
            ax.add_patch(Rectangle(lo, inst.size[0], inst.size[1], facecolor='none',
                                   edgecolor='tab:red' if g.required else 'tab:orange', lw=1.6, zorder=5))
            ax.annotate(text, (inst.center[0], inst.center[1]), fontsize=7, color='darkred',
                        xytext=(3, -9), textcoords='offset points', zorder=7)


def render_search(result: SearchResult, scene: Scene, out: Union[str, Path],
                  title: Optional[str] = None) -> Path:
    """Draw a search into a PNG file and return its path."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    w, h = (scene.bounds_max[k] - scene.bounds_min[k] for k in range(2))
    fig, ax = plt.subplots(figsize=(8, min(8 * h / max(w, 1e-6), 12) + 0.8))
    _draw_static(ax, world_from_scene(scene), scene)
    _draw_seen(ax, result)
    p = result.path
    ax.plot(p[:, 0], p[:, 1], color='black', lw=1.4, zorder=4)
    views = {(round(v[0], 3), round(v[1], 3)) for v in result.views}
    ax.plot([v[0] for v in views], [v[1] for v in views], 'o', color='black', ms=3, zorder=4)
    ax.plot(p[0, 0], p[0, 1], 's', color='black', ms=7, zorder=4)
    _draw_found(ax, result)
    head = f'{title}\n' if title else ''
    ax.set_title(_wrap(f'{head}search: {len(result.views)} views, {result.travel:.1f} m travelled, '
                       f'{result.area_seen:.1f} m² seen, ended {result.reason}'), fontsize=8)
    fig.tight_layout()
    return save_png(fig, out, dpi=110)
