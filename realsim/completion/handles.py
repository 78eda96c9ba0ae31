"""A handle seen on a round body (a mug's, a jug's) kept as convex parts welded to the revolved body.

Revolving the visible profile leaves out what lies off the circle of each height band: the points
the camera saw beyond the body's outside by more than a wall's width, gathered on one side of it,
are its handle when enough of them stand a centimetre beyond the body's widest radius. The camera sees one side of it; a handle is symmetric about the vertical plane
through the body's axis and its own middle, and the extreme angle its seen points reach away from
the camera is where the line of sight grazes it (the occluding contour lies in that plane), so
the seen points are mirrored about that plane. The handle is cut into height bands, each the hull
of its points (the loop's opening between the bands stays open); the lowest and the highest band
also take their points moved onto the body's outside: the arms that join the body.
"""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.hull import solid_hull

MIN_POINTS = 30  # fewer points off the body are noise, not a handle
GAP = 0.006  # m: a point this much beyond the body's outside is off the body
SECTOR_DEG = 60.0  # a handle's points lie within this angle of their median direction
BANDS = 4  # height bands of a handle (the top and bottom ones join the body)
REACH = 0.01  # m: a handle reaches this far beyond the body's widest radius


def _wrap(angle: np.ndarray) -> np.ndarray:
    return np.asarray((angle + np.pi) % (2 * np.pi) - np.pi)


def handle_pieces(points: np.ndarray, centre: np.ndarray, outside: tuple[np.ndarray, np.ndarray],
                  camera_xy: np.ndarray | None) -> list[trimesh.Trimesh]:
    """Convex pieces (world frame) of the handle seen among ``points`` off the round body about the
    vertical axis through ``centre`` whose outside radius over height is ``outside`` (heights, radii,
    ascending heights); none when too few points lie off the body or no camera is known."""
    if camera_xy is None or len(outside[0]) < 2:
        return []
    rel = points[:, :2] - centre
    body = np.interp(points[:, 2], *outside)
    off = np.linalg.norm(rel, axis=1) > body + GAP
    if off.sum() < MIN_POINTS:
        return []
    angle = np.arctan2(rel[:, 1], rel[:, 0])
    middle = float(np.angle(np.mean(np.exp(1j * angle[off]))))
    off &= np.abs(_wrap(angle - middle)) < np.radians(SECTOR_DEG / 2)
    if off.sum() < MIN_POINTS:
        return []
    reach = (np.linalg.norm(rel, axis=1) - np.maximum(body, float(np.max(outside[1]))))[off]
    if np.count_nonzero(reach > REACH) < MIN_POINTS:  # a lip or a bulge the profile missed, not a handle
        return []
    handle = points[off]
    # the mirror plane: the angle farthest from the camera's side the seen points reach
    toward = float(np.arctan2(camera_xy[1] - centre[1], camera_xy[0] - centre[0]))
    rel_angle = _wrap(angle[off] - middle)
    away = -float(np.sign(_wrap(np.array(toward - middle))))  # which way round is away from the camera
    plane = middle + float(np.percentile(away * rel_angle, 95)) * away
    away = away or 1.0
    normal = np.array([-np.sin(plane), np.cos(plane)])  # the plane holds the axis and the direction ``plane``
    mirrored = handle.copy()
    mirrored[:, :2] -= 2.0 * ((handle[:, :2] - centre) @ normal)[:, None] * normal[None, :]
    both = np.vstack([handle, mirrored])
    edges = np.linspace(float(handle[:, 2].min()), float(handle[:, 2].max()), BANDS + 1)
    band = np.clip(np.searchsorted(edges, both[:, 2], side="right") - 1, 0, BANDS - 1)
    pieces = []
    for b in range(BANDS):
        pts = both[band == b]
        if len(pts) < 4:
            continue
        if b in (0, BANDS - 1):  # an arm: joined to the body under it
            rel_b = pts[:, :2] - centre
            r = np.maximum(np.linalg.norm(rel_b, axis=1), 1e-9)
            inner = np.interp(pts[:, 2], *outside) - GAP / 2  # a little into the wall: welded
            pts = np.vstack([pts, np.column_stack([centre + rel_b * (inner / r)[:, None], pts[:, 2]])])
        piece = solid_hull(pts)
        if piece is not None:
            pieces.append(piece)
    return pieces
