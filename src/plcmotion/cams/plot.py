"""Plot a cam: position, velocity, acceleration and jerk on four axes sharing the leading value, the
curves an engineer checks in the cam editor (S7-1500T V5 §6.2.2, §6.2.3.1, §6.2.5.5).

Uses matplotlib's Agg canvas directly (no pyplot state, no display needed).
"""
from __future__ import annotations

import os
from typing import Any

import numpy as np

from ..kernel.cam import CamCurve
from .io import _curve


def _marks(cam: Any, curve: CamCurve) -> tuple[list[tuple[float, float]], list[float]]:
    """Points and segment boundaries to mark: from a definition or a cam TO, else the curve's pieces."""
    if hasattr(cam, "points") and hasattr(cam, "segments") and not callable(cam.points):
        pts, segs = list(cam.points), list(cam.segments)
    elif hasattr(cam, "valid_points"):
        pts, segs = cam.valid_points(), cam.valid_segments()
    else:
        return [], [float(v) for v in curve.bp]
    return pts, sorted({float(v) for s in segs for v in (s.xmin, s.xmax)})


def plot_cam(curve_or_definition: Any, path: str | os.PathLike | None = None, n: int = 2000,
             scale_x: float = 1.0, leading_velocity: float | None = None, *, scale_y: float = 1.0,
             title: str | None = None, show_points: bool = True, show_boundaries: bool = True,
             figsize: tuple[float, float] = (9.0, 10.0), dpi: int = 100):
    """Figure with four stacked axes: position, velocity, acceleration, jerk.

    ``scale_x``/``scale_y`` scale leading and following values (like MasterScaling/SlaveScaling of
    MC_CamIn, §6.2.5.5).  With ``leading_velocity`` (constant, leading units/s) the derivatives are
    time derivatives v = f' xdot, a = f'' xdot^2, j = f''' xdot^3; otherwise derivatives with respect to
    the leading value.  Points are marked on the position axis, segment boundaries as dotted lines.
    Saves a PNG when ``path`` is given; returns the matplotlib Figure.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    curve = _curve(curve_or_definition)
    if not n >= 2:
        raise ValueError(f"n must be at least 2, got {n!r}")
    if not scale_x > 0 or scale_y == 0:
        raise ValueError("scale_x must be > 0 and scale_y non-zero")
    x = np.linspace(curve.start, curve.end, int(n))
    f, d1, d2, d3 = curve.evaluate(x, 3)
    rate = 1.0 if leading_velocity is None else float(leading_velocity)
    ys = [f * scale_y] + [d * scale_y / scale_x ** k * rate ** k for k, d in ((1, d1), (2, d2), (3, d3))]
    if leading_velocity is None:
        names = ["position f", "velocity f'", "acceleration f''", "jerk f'''"]
    else:
        names = ["position", "velocity [/s]", "acceleration [/s²]", "jerk [/s³]"]
    fig = Figure(figsize=figsize, dpi=dpi)
    FigureCanvasAgg(fig)
    axes = fig.subplots(4, 1, sharex=True)
    pts, bounds = _marks(curve_or_definition, curve)
    for ax, y, name, color in zip(axes, ys, names, ("C0", "C1", "C2", "C3")):
        ax.plot(x * scale_x, y, color=color, lw=1.2)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
        if show_boundaries:
            for b in bounds:
                ax.axvline(b * scale_x, color="0.5", lw=0.6, ls=":")
    if show_points and pts:
        px = np.array([p[0] for p in pts])
        axes[0].plot(px * scale_x, np.array([p[1] for p in pts]) * scale_y, "o", ms=3, color="k",
                     label="points")
        axes[0].legend(loc="best", fontsize="small")
    axes[-1].set_xlabel("leading value" + (f" (x {scale_x:g})" if scale_x != 1.0 else ""))
    fig.suptitle(title or "cam")
    fig.tight_layout()
    if path is not None:
        fig.savefig(os.fspath(path), format="png")
    return fig


__all__ = ["plot_cam"]
