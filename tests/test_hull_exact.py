"""realsim.completion.hull.trimesh_hull gives trimesh's convex hull, array for array, faster."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.hull import extreme_points, triangles_and_areas, trimesh_hull
from realsim.completion.neighbours import clip_convex


def _same(a: trimesh.Trimesh, b: trimesh.Trimesh) -> bool:
    return (np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)
            and np.array_equal(a.face_normals, b.face_normals) and a.volume == b.volume and np.array_equal(a.centroid, b.centroid))


def test_the_hull_is_trimeshs_on_clouds_boxes_and_clipped_pieces() -> None:
    rng = np.random.default_rng(5)
    for trial in range(150):
        pts = rng.normal(size=(int(rng.integers(6, 150)), 3)) * rng.uniform(0.005, 0.1, 3)
        if trial % 3 == 0:  # repeated and nearly repeated points (trimesh merges them: its own path)
            pts = np.vstack([pts, pts[:4], pts[:3] + 1e-10])
        ours, theirs = trimesh_hull(pts), trimesh.convex.convex_hull(pts)
        assert _same(theirs, ours) if theirs.is_watertight else ours.is_watertight, trial  # an open one is closed (see below)
    box = trimesh.creation.box([0.1, 0.06, 0.2])  # coplanar faces: Qhull's triangulation kept
    assert _same(trimesh.convex.convex_hull(box.vertices), trimesh_hull(box.vertices))
    piece = trimesh.creation.icosphere(2, 0.05)
    for k in range(20):  # what the free-space cuts make: hulls of clipped convex pieces
        normal = rng.normal(size=3)
        normal /= np.linalg.norm(normal)
        cut = clip_convex(piece, normal, float(rng.uniform(-0.03, 0.01)))
        if cut is not None:
            v = np.asarray(cut.vertices)
            assert _same(trimesh.convex.convex_hull(v), trimesh_hull(v)), k


def test_triangles_and_areas_are_trimeshs_bit_for_bit() -> None:
    rng = np.random.default_rng(8)
    meshes = [trimesh_hull(rng.normal(size=(int(rng.integers(5, 120)), 3)) * rng.uniform(0.005, 0.1, 3)) for _ in range(60)]
    meshes += [trimesh.creation.icosphere(2, 0.05), trimesh.creation.box([0.1, 0.06, 0.2])]
    for k, mesh in enumerate(meshes):
        tri, area = triangles_and_areas(mesh)
        fresh = trimesh.Trimesh(mesh.vertices.copy(), mesh.faces.copy(), process=False)
        assert np.array_equal(tri, fresh.triangles) and np.array_equal(area, fresh.area_faces), k


def test_extreme_points_hold_every_directions_maximum_bit_for_bit() -> None:
    """The points kept give the same max of n . x as all of them, for 3D directions and for lines in
    the perspective image (what the free-space cuts ask); points well inside are dropped, a flat set kept."""
    rng = np.random.default_rng(11)
    for trial in range(30):
        pts = rng.normal(size=(int(rng.integers(20, 3000)), 3)) * rng.uniform(0.005, 0.1, 3) + [0.0, 0.0, 0.8]
        if trial % 3 == 0:  # points on the hull's faces too (a box's seen sides)
            pts = np.vstack([pts, rng.uniform(-0.05, 0.05, (500, 3)) * [1, 1, 0] + [0, 0, pts[:, 2].max()]])
        kept = extreme_points(pts)
        assert len(kept) < len(pts) or len(pts) <= 16
        normals = rng.normal(size=(190, 3))
        assert np.array_equal((pts @ normals.T).max(axis=0), (kept @ normals.T).max(axis=0)), trial
        image, image_kept = pts[:, :2] / pts[:, 2:], kept[:, :2] / kept[:, 2:]
        lines = rng.normal(size=(72, 2))
        assert np.array_equal((image @ lines.T).max(axis=0), (image_kept @ lines.T).max(axis=0)), trial
    flat = np.column_stack([rng.uniform(size=(50, 2)), np.zeros(50)])
    assert len(extreme_points(flat)) == 50


def test_cross_and_kept_normals_are_trimeshs_bit_for_bit() -> None:
    """The edge cross products are trimesh's (numpy's) bits; the hull keeps the face normals it was
    built with exactly when trimesh's constructor would (a wrong normal is dropped, then recomputed)."""
    from trimesh import triangles

    from realsim.completion.hull import _cross, _normals_match

    rng = np.random.default_rng(8)
    tri = rng.normal(size=(500, 3, 3)) * rng.uniform(1e-6, 10.0, size=(500, 1, 1))
    assert _cross(tri).tobytes() == triangles.cross(tri).tobytes()
    for trial in range(40):
        mesh = trimesh_hull(rng.normal(size=(int(rng.integers(5, 80)), 3)))
        normals = np.array(mesh.face_normals)
        if trial % 2:
            normals[int(rng.integers(0, min(20, len(normals))))] *= -1.0
        built = trimesh.Trimesh(mesh.vertices, mesh.faces, face_normals=normals, process=False, validate=False)
        assert _normals_match(np.asarray(mesh.vertices), np.asarray(mesh.faces), normals) == ("face_normals" in built._cache), trial


def test_a_piece_cut_just_past_its_corner_is_closed() -> None:
    """A cut plane passing a hair from a vertex gives near-collinear corners; trimesh's repair drops the
    sliver triangle between them and leaves the hull open (a concatenated body is then no volume, so
    its inertia falls back to its box): trimesh_hull keeps it closed."""
    from realsim.completion.neighbours import kept_points, unique_edges

    rng = np.random.default_rng(0)
    opened = 0
    for trial in range(40):
        box = trimesh.creation.box(rng.uniform(0.02, 0.2, 3))
        piece = trimesh.convex.convex_hull(np.vstack([box.vertices, rng.normal(size=(20, 3)) * 0.03]))
        for _ in range(3):
            normal = rng.normal(size=3)
            normal /= np.linalg.norm(normal)
            corner = piece.vertices[rng.integers(len(piece.vertices))]
            offset = corner @ normal - 1e-6 * rng.random() * np.ptp(piece.vertices @ normal)
            pts = kept_points(np.asarray(piece.vertices), unique_edges(piece.faces), -normal, -offset)
            if len(pts) < 4:
                break
            opened += not trimesh.convex.convex_hull(pts).is_watertight
            piece = trimesh_hull(pts)
            if len(piece.faces) == 0:  # flat: nothing left (clip_convex gives None)
                break
            assert piece.is_watertight and piece.is_volume, trial
    assert opened >= 3  # the case arose (trimesh's own hull was open)
