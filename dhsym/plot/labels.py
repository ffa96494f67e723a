"""Placing frame-axis labels on a picture where they hide the fewest joints, links and labels.

Each label tries a few positions around its arrow tip, in display coordinates, and keeps the
one whose box overlaps least with what is already drawn.

>>> _overlap(_box((0, 0), 1, 1), _box((1, 1), 1, 1))
1
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class Label:
    """An axis label to place: its text, the tip it names, and the side it prefers."""

    text: str
    anchor: np.ndarray  # a point in the world frame
    direction: np.ndarray  # where the label prefers to sit, as a world direction from the anchor
    colour: str


def place_labels(ax, labels: list[Label], points: list, segments: list, flat: bool) -> None:
    """Put each axis label beside its tip where it covers the fewest labels, joints and lines."""
    if not labels:
        return
    from matplotlib.transforms import ScaledTranslation

    figure = ax.figure
    figure.draw_without_rendering()  # fixes the 3D projection and the axes' place on the figure
    to_display = _projector(ax, flat)
    pixel = figure.dpi / 72  # display pixels per point
    taken = [(_box(to_display(p), 6 * pixel, 6 * pixel), 1.0) for p in points]
    for start, end in segments:
        a, b = to_display(start), to_display(end)
        for t in np.linspace(0, 1, max(2, int(np.linalg.norm(b - a) / (4 * pixel)))):
            taken.append((_box(a + t * (b - a), 2.5 * pixel, 2.5 * pixel), 0.3))
    for label in labels:
        text = ax.text(*(label.anchor[:2] if flat else label.anchor), label.text, color=label.colour, fontsize=9,
                       ha="center", va="center", zorder=7,
                       bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
        size = text.get_window_extent()
        half = np.array([size.width, size.height]) / 2 + pixel
        anchor = to_display(label.anchor)
        heading = to_display(label.anchor + 1e-3 * label.direction) - anchor
        heading = heading / np.linalg.norm(heading) if np.linalg.norm(heading) > 1e-12 else np.array([0.7, 0.7])
        best, best_cost = None, np.inf
        for gap in (2, 6, 11, 17):
            for turn in (0, 35, -35, 70, -70, 110, -110, 145, -145, 180):
                angle = np.radians(turn)
                way = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]) @ heading
                reach = min(half[0] / max(abs(way[0]), 1e-9), half[1] / max(abs(way[1]), 1e-9))
                centre = anchor + way * (reach + gap * pixel)
                box = _box(centre, *half)
                cost = sum(weight * _overlap(box, other) for other, weight in taken) + 0.5 * abs(turn) + 3 * gap
                if cost < best_cost:
                    best, best_cost = (centre, box), cost
        centre, box = best
        taken.append((box, 1.0))
        shift = (centre - anchor) / figure.dpi
        text.set_transform(ax.transData + ScaledTranslation(shift[0], shift[1], figure.dpi_scale_trans))


def _projector(ax, flat: bool):
    if flat:
        return lambda point: ax.transData.transform(np.asarray(point)[:2])
    from mpl_toolkits.mplot3d import proj3d

    projection = ax.get_proj()

    def to_display(point):
        x, y, _ = proj3d.proj_transform(point[0], point[1], point[2], projection)
        return ax.transData.transform((x, y))

    return to_display


def _box(centre, half_width: float, half_height: float) -> tuple:
    return (centre[0] - half_width, centre[1] - half_height, centre[0] + half_width, centre[1] + half_height)


def _overlap(a: tuple, b: tuple) -> float:
    width = min(a[2], b[2]) - max(a[0], b[0])
    height = min(a[3], b[3]) - max(a[1], b[1])
    return width * height if width > 0 and height > 0 else 0.0
