"""A Hypothesis property over a Python planner, checked by antkit.check_stc: the Python twin of
tests/cmake_export/property.cpp, as a user of the package would write it. And a planted bug that the
property must find and shrink to the smallest map that shows it."""
import numpy as np
from hypothesis import given, find, settings
from hypothesis import strategies as st

import antkit

DIRS = [(1, 0), (0, -1), (-1, 0), (0, 1)]  # E, N, W, S (y down)


def spanning_tree(cells, start, dirs=DIRS):
    """Depth-first spanning tree of the free cells 4-connected to `start` (x, y): its edges."""
    h, w = cells.shape
    seen, edges, stack = {start}, [], [start]
    while stack:
        x, y = stack.pop()
        for dx, dy in dirs:
            n = (x + dx, y + dy)
            if 0 <= n[0] < w and 0 <= n[1] < h and cells[n[1], n[0]] and n not in seen:
                seen.add(n)
                edges.append(((x, y), n))
                stack.append(n)
    return seen, edges


def stc_planner(cells, start, dirs=DIRS):
    """Spanning Tree Coverage: each cell's 2 x 2 sub-cells form a 4-cycle; along every tree edge
    the two cycles are cut open on the shared side and joined across it, which leaves one cycle
    through every sub-cell of the tree (Gabriely and Rimon). The tour follows it from the start
    cell's top-left sub-cell and stops next to it."""
    tree, edges = spanning_tree(cells, start, dirs)
    adj = {}

    def link(a, b):
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)

    def unlink(a, b):
        adj[a].discard(b)
        adj[b].discard(a)

    for cx, cy in tree:
        tl, tr, bl, br = (2 * cx, 2 * cy), (2 * cx + 1, 2 * cy), (2 * cx, 2 * cy + 1), (2 * cx + 1, 2 * cy + 1)
        link(tl, tr), link(tr, br), link(br, bl), link(bl, tl)
    for (ax, ay), (bx, by) in edges:
        if ax > bx or ay > by:
            (ax, ay), (bx, by) = (bx, by), (ax, ay)
        if bx == ax + 1:  # b east of a: a's right side, b's left side
            a1, a2 = (2 * ax + 1, 2 * ay), (2 * ax + 1, 2 * ay + 1)
            b1, b2 = (2 * bx, 2 * by), (2 * bx, 2 * by + 1)
        else:  # b south of a: a's bottom side, b's top side
            a1, a2 = (2 * ax, 2 * ay + 1), (2 * ax + 1, 2 * ay + 1)
            b1, b2 = (2 * bx, 2 * by), (2 * bx + 1, 2 * by)
        unlink(a1, a2), unlink(b1, b2), link(a1, b1), link(a2, b2)
    first = (2 * start[0], 2 * start[1])
    tour, prev, here = [first], None, first
    while True:
        nxt = min(n for n in adj[here] if n != prev)  # degree 2: the one not come from
        if nxt == first:
            return np.array(tour, dtype=np.int64)
        tour.append(nxt)
        prev, here = here, nxt


@st.composite
def cell_maps(draw, max_side=8):
    """A map of robot-sized cells (True = free) and a free start cell."""
    w = draw(st.integers(1, max_side))
    h = draw(st.integers(1, max_side))
    cells = np.array(draw(st.lists(st.booleans(), min_size=w * h, max_size=w * h))).reshape(h, w)
    free = np.argwhere(cells)
    if len(free) == 0:
        cells[0, 0] = True
        free = np.argwhere(cells)
    y, x = free[draw(st.integers(0, len(free) - 1))]
    return cells, (int(x), int(y))


def check(planner, case, cells_mode):
    cells, start = case
    tour = planner(cells, start)
    if cells_mode:  # the planner's own convention: the map and the start in cells
        return antkit.check_stc(antkit.Map.from_array(cells), tour, start=start, cells=True)
    sub = antkit.Map.from_array(np.kron(cells, np.ones((2, 2), dtype=bool)))
    return antkit.check_stc(sub, tour, start=(2 * start[0], 2 * start[1]))


@settings(max_examples=500)
@given(cell_maps(), st.booleans())
def test_the_planner_covers_every_reachable_subcell_exactly_once(case, cells_mode):
    r = check(stc_planner, case, cells_mode)
    assert r.ok, r.first_violation
    assert r.covered == 4 * len(spanning_tree(*case)[0])


def buggy_planner(cells, start):
    """The planted bug: the tree never grows north (N left out of the directions)."""
    return stc_planner(cells, start, dirs=[(1, 0), (-1, 0), (0, 1)])


def test_the_property_finds_and_shrinks_the_planted_bug():
    found = find(
        st.tuples(cell_maps(), st.booleans()),
        lambda c: not check(buggy_planner, c[0], c[1]).ok,
        settings=settings(max_examples=2000, database=None),
    )
    (cells, start), cells_mode = found
    # The smallest map that shows it: two free cells, one above the other, starting below.
    assert int(cells.sum()) == 2, cells
    (y0, x0), (y1, x1) = np.argwhere(cells)
    assert x0 == x1 and y1 == y0 + 1 and start == (int(x1), int(y1))
    r = check(buggy_planner, (cells, start), cells_mode)
    assert not r.ok and r.missed == 4
    assert r.first_violation["rule"] == "4 length"  # 4 positions where 8 were due
