"""A lying body's hidden underside is its upper side mirrored below its widest level, bounded by the support."""

from __future__ import annotations

import numpy as np

from realsim.completion.extrusion import complete_hull
from realsim.completion.underside import underside_floors

SLAB, SHARE, EDGE = 0.025, 0.5, 0.002


def _floors(points: np.ndarray, top_z: float) -> np.ndarray | None:
    return underside_floors(points, 0.0, top_z, SLAB, SHARE, EDGE)


def test_a_lying_cylinder_is_round_below_its_widest_level_not_its_bounding_box() -> None:
    r, length = 0.02, 0.16  # a bottle on its side, axis along y, resting on the support at z = 0
    a, y = np.meshgrid(np.linspace(-0.3, np.pi + 0.3, 120), np.linspace(-length / 2, length / 2, 50))
    seen = np.column_stack([r * np.cos(a).ravel(), y.ravel(), r + r * np.sin(a).ravel()])  # the upper side, past both widest lines
    floors = _floors(seen, 2 * r)
    assert floors is not None
    truth = np.pi * r * r * length
    extruded = complete_hull(seen, 0.0, 2 * r)[0].volume
    mirrored = complete_hull(seen, 0.0, 2 * r, floors=floors)[0].volume
    assert extruded > 1.13 * truth  # straight down: its lower half a rectangle ((pi / 2 + 2) / pi)
    assert abs(mirrored - truth) < 0.03 * truth
    upper = seen[seen[:, 2] > 1.3 * r]  # seen only above its widest level: it may widen down to the support
    unseen = _floors(upper, 2 * r)
    assert unseen is not None and np.allclose(unseen, 0.0)


def test_a_box_lying_flat_stays_a_box() -> None:
    x, y = np.meshgrid(np.linspace(-0.05, 0.05, 41), np.linspace(-0.08, 0.08, 41))
    top = np.column_stack([x.ravel(), y.ravel(), np.full(x.size, 0.04)])  # a 10 x 16 x 4 cm box
    front = np.column_stack([np.full(x.size, -0.05), y.ravel(), 0.04 * (x.ravel() + 0.05) / 0.1])  # its near face, seen vertical
    for seen in (np.vstack([top, front]), top):  # with its side seen and with only its top
        floors = _floors(seen, 0.04)
        assert floors is not None
        assert abs(complete_hull(seen, 0.0, 0.04, floors=floors)[0].volume - 0.1 * 0.16 * 0.04) < 1e-6


def test_a_side_flaring_down_to_the_support_is_extruded_and_an_upright_body_is_left_alone() -> None:
    u, y = np.meshgrid(np.linspace(-1.0, 1.0, 81), np.linspace(-0.08, 0.08, 41))
    ridge = np.column_stack([0.05 * u.ravel(), y.ravel(), 0.03 * (1 - np.abs(u.ravel()))])  # a prism lying on its wide face
    floors = _floors(ridge, 0.03)
    assert floors is not None and np.allclose(floors, 0.0)  # widest at the support: no underside to mirror
    z, a = np.meshgrid(np.linspace(0.0, 0.2, 40), np.linspace(0, np.pi, 40))
    upright = np.column_stack([0.03 * np.cos(a).ravel(), 0.03 * np.sin(a).ravel(), z.ravel()])  # a can standing
    assert _floors(upright, 0.2) is None


def _turned_oval(turn_deg: float, a: float = 0.048, b: float = 0.033, length: float = 0.16) -> tuple[np.ndarray, np.ndarray]:
    """An oval bottle lying on its flank, its section turned ``turn_deg`` about its long axis (y), resting
    on z = 0: all its surface points and those a camera above and toward -x (45 degrees down) sees above
    the lowest 8 mm (the band segmentation gives to the support)."""
    u, y = np.meshgrid(np.linspace(0, 2 * np.pi, 120, endpoint=False), np.linspace(-length / 2, length / 2, 12))
    turn = np.radians(turn_deg)
    x0, z0 = a * np.cos(u), b * np.sin(u)
    x, z = x0 * np.cos(turn) - z0 * np.sin(turn), x0 * np.sin(turn) + z0 * np.cos(turn)
    nx0, nz0 = np.cos(u) / a, np.sin(u) / b
    nx, nz = nx0 * np.cos(turn) - nz0 * np.sin(turn), nx0 * np.sin(turn) + nz0 * np.cos(turn)
    surface = np.column_stack([x.ravel(), y.ravel(), (z - z.min()).ravel()])
    seen = ((nz - nx).ravel() > 0) & (surface[:, 2] > 0.008)
    return surface, surface[seen]


def _iou(completed: np.ndarray, truth: np.ndarray) -> float:
    from scipy.spatial import Delaunay

    lo, hi = truth.min(axis=0) - 0.02, truth.max(axis=0) + 0.02
    grid = np.stack(np.meshgrid(*[np.arange(a, b, 0.004) for a, b in zip(lo, hi)], indexing="ij"), axis=-1).reshape(-1, 3)
    a, b = Delaunay(completed).find_simplex(grid) >= 0, Delaunay(truth).find_simplex(grid) >= 0
    return float(np.count_nonzero(a & b) / np.count_nonzero(a | b))


def test_a_turned_oval_lying_has_its_far_side_imaged_through_its_centre_not_walled_down_to_the_support() -> None:
    truth, seen = _turned_oval(35.0)
    top = float(seen[:, 2].max())
    walled, imaged = (underside_floors(seen, 0.0, top, SLAB, SHARE, EDGE, central) for central in (False, True))
    assert walled is not None and imaged is not None
    far = seen[:, 0] > np.percentile(seen[:, 0], 90)  # the far side's top, seen only above where the line of sight grazes it
    assert np.median(walled[far]) < 0.005 < 0.02 < np.median(imaged[far])  # walled down to the support / floored at its image
    ious = [_iou(np.asarray(complete_hull(seen, 0.0, top, floors=f)[0].vertices), truth) for f in (walled, imaged)]
    assert ious[1] > ious[0] + 0.02


def test_an_upright_section_lying_is_mirrored_as_before() -> None:
    _, seen = _turned_oval(0.0)  # its top over its middle: not turned
    top = float(seen[:, 2].max())
    before, after = (underside_floors(seen, 0.0, top, SLAB, SHARE, EDGE, central) for central in (False, True))
    assert before is not None and after is not None and np.allclose(before, after)
