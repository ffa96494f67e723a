"""Packing a slide's blocks into beamer frames by estimated height (in pt).

What fits an empty frame is never split. Rows of elements are split between columns if they
can be, else between elements, else between lines, so that a matrix column of elements stays
on one frame when it fits one; the rows that share a frame form one ``aligned`` display. A
block marked `keep_with_next` ("where" before the legend) moves to the next frame with what
follows it. A frame after the first may start with a block's `alone` form (its own title).

>>> from dhsym.latex.layout import Block, Rows
>>> columns = [[[("r &= x", 16.6)]] * 3] * 4  # 4 columns of 3 elements, each one line high
>>> frames = pack([Block("a display", 40.0), Rows(columns)], capacity=140.0)
>>> [len(frame) for frame in frames], frames[1][0].latex.count("&=")
([2, 1, 1], 6)
"""
from __future__ import annotations

from .layout import ALIGNED_ROW, FIRST_DISPLAY, NEXT_DISPLAY, Block, Rows, aligned_display, lines_under


def pack(items: list, capacity: float) -> list[list[Block]]:
    """Blocks and `Rows` into frames of `capacity` pt. What fits an empty frame is never split;
    the rows of one `Rows` that share a frame form one `aligned` display."""
    frames = _Frames(capacity)
    for position, item in enumerate(items):
        if isinstance(item, Rows):
            frames.fresh_run = True
            _place(frames, item.columns, level=0)
            continue
        whole, least = _kept_height(items, position, capacity)
        room = frames.room(rows=False)
        if not frames.empty and (least > room or room < whole <= capacity - FIRST_DISPLAY):
            frames.new()
        frames.frames[-1].append(item)
    return frames.blocks()


def _place(frames: _Frames, node, level: int) -> None:
    """The lines under `node` (level 0: all columns, 1: a column, 2: an element, 3: a line)."""
    lines = lines_under(node, level)
    height = sum(line[1] for line in lines)
    if height <= frames.room(rows=True):
        frames.add_rows(lines)
    elif not frames.empty and (height <= frames.capacity - FIRST_DISPLAY or level == 3):
        frames.new()
        frames.add_rows(lines)
    elif level == 3:
        frames.add_rows(lines)  # one line taller than a frame: nothing smaller to move
    else:
        for child in node:
            _place(frames, child, level + 1)


def _kept_height(items, position: int, capacity: float) -> tuple[float, float]:
    """(whole, least): the height of a block with all that must follow it on its frame, and
    with only the first column of the rows among them ("where" stays with its legend)."""
    whole, least = 0.0, None
    for item in items[position:]:
        if isinstance(item, Rows) and least is None:  # _place keeps a column together if it can
            column = sum(line[1] for line in lines_under(item.columns[0], 1))
            least = whole + NEXT_DISPLAY + (column if column <= capacity - FIRST_DISPLAY else ALIGNED_ROW)
        whole += item.height + (NEXT_DISPLAY if isinstance(item, Rows) or item.is_display else 0.0)
        if not item.keep_with_next:
            break
    return whole, whole if least is None else least


class _Frames:
    """Frames being filled, each a list of Blocks and of runs of aligned lines."""

    def __init__(self, capacity: float):
        self.capacity, self.frames, self.fresh_run = capacity, [[]], False

    @property
    def empty(self) -> bool:
        return not self.frames[-1]

    def room(self, rows: bool) -> float:
        used, entries = 0.0, self.frames[-1]
        for n, entry in enumerate(entries):
            run = isinstance(entry, list)
            height = sum(line[1] for line in entry) if run else entry.height
            used += height + (NEXT_DISPLAY if n else FIRST_DISPLAY) * (run or entry.is_display)
        joins_run = rows and entries and isinstance(entries[-1], list) and not self.fresh_run
        return self.capacity - used - (0.0 if joins_run else NEXT_DISPLAY if entries else FIRST_DISPLAY)

    def new(self) -> None:
        self.frames.append([])
        self.fresh_run = True

    def add_rows(self, lines) -> None:
        if self.fresh_run or not (self.frames[-1] and isinstance(self.frames[-1][-1], list)):
            self.frames[-1].append([])
        self.fresh_run = False
        self.frames[-1][-1].extend(lines)

    def blocks(self) -> list[list[Block]]:
        out = []
        for number, entries in enumerate(f for f in self.frames if f):
            blocks = [aligned_display(entry) if isinstance(entry, list) else entry for entry in entries]
            if number and blocks[0].alone:
                blocks[0] = Block(blocks[0].alone[1], blocks[0].height, blocks[0].is_display, alone=blocks[0].alone)
            out.append(blocks)
        return out
