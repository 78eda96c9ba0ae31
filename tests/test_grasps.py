"""Grasp candidates from surface points and normals: what the hand may pinch, and where."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from realsim.procedural import shapes
from realsim.robot.grasps import DOWN, MAX_WIDTH, antipodal, grasp_candidates, rim_candidates, top_down_candidates

BASE = np.array([0.0, 0.6])  # the robot's xy, behind the objects


def _surface(mesh: trimesh.Trimesh, count: int = 6000) -> tuple[np.ndarray, np.ndarray]:
    pts, faces = trimesh.sample.sample_surface(mesh, count, seed=0)
    return pts, mesh.face_normals[faces]


def test_off_centre_chord_of_a_round_body_is_not_antipodal() -> None:
    pts, nrm = _surface(trimesh.creation.cylinder(radius=0.03, height=0.1, sections=64))
    closing = np.array([1.0, 0.0, 0.0])
    proj_c = pts @ closing
    for offset, expected in ((0.0, True), (0.01, True), (0.03, False)):  # pad edge 0 / 0 / 37 degrees off
        slab = (np.abs(pts[:, 1] - offset) < 0.012) & (pts[:, 2] > 0.0)
        assert antipodal(nrm, slab, proj_c, closing, DOWN) is expected, offset
    # a box pinched anywhere across its faces is fine
    pts, nrm = _surface(trimesh.creation.box(extents=[0.05, 0.12, 0.1]))
    slab = (np.abs(pts[:, 1] - 0.04) < 0.012) & (pts[:, 2] > 0.0)
    assert antipodal(nrm, slab, pts @ closing, closing, DOWN)


def test_top_grasps_of_a_can_close_through_its_axis() -> None:
    pts, nrm = _surface(shapes.to_trimesh(shapes.can(0.12, 0.066)))
    cands = top_down_candidates(pts, 0.0, normals=nrm)
    assert cands
    assert np.linalg.norm(cands[0].pos[:2]) < 0.002  # the best one closes through the axis
    for c in cands:  # no slice is so far off the axis that the pads meet the curve at a slant
        assert np.linalg.norm(c.pos[:2]) < 0.022, c.pos
        assert c.width == pytest.approx(0.066, abs=0.008)


def test_open_containers_get_rim_grasps_and_closed_ones_do_not() -> None:
    mug_pts, mug_nrm = _surface(shapes.to_trimesh(shapes.mug(0.095, 0.085)), 12000)
    rims = rim_candidates(mug_pts, 0.0, normals=mug_nrm)
    assert len(rims) >= 6
    assert all(c.width < 0.025 for c in rims)
    assert all(abs(np.linalg.norm(c.pos[:2]) - 0.040) < 0.008 for c in rims)  # on the wall, 42.5 mm out
    best = grasp_candidates(mug_pts, 0.0, BASE, normals=mug_nrm)[0]
    assert best.kind == "rim"  # an 85 mm mug is too wide to pinch across
    bowl_pts, bowl_nrm = _surface(shapes.to_trimesh(shapes.bowl(0.06, 0.16)), 12000)
    assert len(rim_candidates(bowl_pts, 0.0, normals=bowl_nrm)) >= 6
    for closed in (shapes.can(0.12, 0.066), shapes.jar(0.12, 0.08), shapes.box(0.1, 0.06, 0.15)):
        pts, nrm = _surface(shapes.to_trimesh(closed))
        assert rim_candidates(pts, 0.0, normals=nrm) == []


def test_flat_faces_allow_a_wider_pinch_than_round_ones() -> None:
    box_pts, box_nrm = _surface(shapes.to_trimesh(shapes.box(0.17, 0.075, 0.22)))
    wide = top_down_candidates(box_pts, 0.0, normals=box_nrm)
    assert wide and all(MAX_WIDTH < c.width < 0.077 for c in wide)
    cyl_pts, cyl_nrm = _surface(trimesh.creation.cylinder(radius=0.0375, height=0.2, sections=64))
    assert all(c.width <= MAX_WIDTH for c in top_down_candidates(cyl_pts, 0.0, normals=cyl_nrm))  # only narrower chords
    assert all(c.width <= MAX_WIDTH for c in top_down_candidates(box_pts, 0.0))  # without normals the flat faces cannot be checked


def test_statics_rejects_a_heavy_tray_pinched_by_its_rim() -> None:
    """A 1.1 kg tray held at its rim 0.2 m from its centre twists out of a 70 N pinch; a mug by
    its rim (0.33 kg, 4 cm) does not; a pinch straight above the centre of mass never twists."""
    from realsim.robot.grasps import GraspCandidate, frame_from, twist_check

    down = np.array([0.0, 0.0, -1.0])
    rim = GraspCandidate("rim", np.array([0.2, 0.0, 0.02]), frame_from(down, np.array([1.0, 0.0, 0.0])), 0.01, 1.0)
    ok, need, can = twist_check(rim, np.array([0.0, 0.0, 0.01]), 1.1, 0.8, 70.0)
    assert not ok and need == pytest.approx(1.1 * 9.81 * 0.2, rel=0.02) and can < 1.0
    mug_rim = GraspCandidate("rim", np.array([0.04, 0.0, 0.08]), rim.rot, 0.005, 1.0)
    assert twist_check(mug_rim, np.array([0.0, 0.0, 0.04]), 0.33, 0.8, 70.0)[0]
    # the closing axis along the lever arm: no twist about the fingers
    along = GraspCandidate("rim", np.array([0.2, 0.0, 0.02]), frame_from(down, np.array([0.0, 1.0, 0.0])), 0.01, 1.0)
    assert not twist_check(along, np.array([0.0, 0.0, 0.01]), 1.1, 0.8, 70.0)[0]
    above = GraspCandidate("top", np.array([0.0, 0.0, 0.05]), rim.rot, 0.05, 1.0)
    assert twist_check(above, np.array([0.0, 0.0, 0.01]), 1.1, 0.8, 70.0)[1] < 1e-9
