"""How large a result will be, known before it is worked out or printed.

A chain whose axes are not parallel multiplies the size of its elements by about three per joint:
a general 9-link chain prints 600,000 characters, a 24-link one would print terabytes. These
estimates follow the product without building it: each element is represented by its size
(nodes of its expression tree), and a product of two matrices adds the sizes of the factors of
every non-zero term, as SymPy would build it. The contracted form (dhsym.core.simplify) is
estimated block by block, the raw form link by link; both come within a factor of two of the
real size, in milliseconds whatever the chain.

>>> from dhsym.io.library import load
>>> estimated_size(load("puma560").chain, 0, 6) < 1000 < estimated_size(load("iiwa7").chain, 0, 7)
True
"""
from __future__ import annotations

from typing import Protocol

import sympy

from .simplify import block_matrix, merge_steps, split_into_blocks
from .size import tree_size
from .transforms import product

Sizes = list  # 4×4 of ints: 0 for a zero element, else the size of its expression tree


class Steps(Protocol):
    """What an estimate reads of a chain (dhsym.core.chain.Chain, which imports this module): its
    rows, convention and fixed steps. A robot has none of them: its chain has."""

    rows: tuple
    convention: str
    base: tuple
    tool: tuple


def estimated_size(chain: Steps, start, end, raw: bool = False, memo: dict | None = None) -> int:
    """Estimated total size (expression-tree nodes) of the 3×4 upper part of {start}T{end}; `memo`
    keeps the sizes of the blocks seen, for estimates of spans that share them."""
    return span_size(chain, _step_index(chain, start), _step_index(chain, end), raw, memo)


def span_size(chain: Steps, start: int, end: int, raw: bool = False, memo: dict | None = None) -> int:
    """estimated_size between two positions in the chain's list of steps (either order)."""
    first, last = sorted((start, end))
    steps = _steps(chain)[first:last]
    if not raw:
        return contracted_size(steps, memo)
    matrices = []
    for lo, hi in _link_spans(chain, first, last):
        span = steps[lo - first:hi - first]
        # a link is one matrix (4 steps); a long base or tool is taken step by step, never multiplied out here
        matrices += [product(span)] if len(span) <= 4 else [product([step]) for step in span]
    return product_size(matrices)


def contracted_size(steps, memo: dict | None = None) -> int:
    """Estimated size of the contracted product of `steps` (dhsym.core.simplify.contract); `memo`
    (a dict) keeps each block's sizes, which depend on its steps alone."""
    memo = {} if memo is None else memo
    sizes = None
    for block in reversed(split_into_blocks(merge_steps(steps))):  # B1·(B2·(…·Bg)), as contract() does
        key = (tuple(block.lead), tuple(block.body))
        if key not in memo:
            memo[key] = _sizes(block_matrix(block))
        outer = memo[key]
        sizes = outer if sizes is None else _product_sizes(outer, sizes)
    return _total(sizes)


def product_size(matrices) -> int:
    """Estimated size of the plain product of `matrices` (4×4, multiplied left to right)."""
    sizes = None
    for matrix in matrices:
        sizes = _sizes(matrix) if sizes is None else _product_sizes(sizes, _sizes(matrix))
    return _total(sizes)


def _total(sizes) -> int:
    return sum(sum(row) for row in sizes[:3]) if sizes else 0


def _steps(chain: Steps) -> list:
    return list(chain.base) + [s for row in chain.rows for s in row.steps(chain.convention)] + list(chain.tool)


def _step_index(chain: Steps, frame) -> int:
    """Where frame `frame` sits in the chain's list of steps."""
    if frame == "base":
        return 0
    if frame == "tool":
        return len(_steps(chain))
    return len(chain.base) + 4 * int(frame)


def _link_spans(chain: Steps, first: int, last: int) -> list[tuple[int, int]]:
    """The step spans of the whole link (and base, tool) matrices between two frames."""
    bounds = sorted({0, len(chain.base), len(_steps(chain))} |
                    {len(chain.base) + 4 * k for k in range(chain.n + 1)})
    return [(lo, hi) for lo, hi in zip(bounds, bounds[1:]) if first <= lo and hi <= last and hi > lo]


def _sizes(matrix: sympy.Matrix) -> Sizes:
    memo: dict = {}
    return [[tree_size(matrix[r, c], memo) if matrix[r, c] != 0 else 0 for c in range(4)] for r in range(4)]


def _product_sizes(a: Sizes, b: Sizes) -> Sizes:
    """The sizes of a·b: each non-zero term a_rm·b_mc costs both sizes (a factor 1 costs nothing)."""
    result = []
    for r in range(4):
        row = []
        for c in range(4):
            terms = [(a[r][m], b[m][c]) for m in range(4) if a[r][m] and b[m][c]]
            row.append(sum(x + y + 1 if x > 1 and y > 1 else max(x, y) for x, y in terms) + (len(terms) > 1))
        result.append(row)
    return result
