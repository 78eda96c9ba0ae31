"""Completed bodies rest as they were seen: leaning neighbours parted, bodies seated on sloping
tops, bases that hold the centre of mass (generated ground truth, exact geometry)."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.balance import base_polygon, brace, centre_of_mass
from realsim.completion.overlaps import part_overlapping
from realsim.completion.params import CompletionParams
from realsim.completion.stacking import bottom_up, seat_on, sloping_top
from realsim.completion.stage import stacking_levels
from realsim.geometry import inside_convex_polygon
from realsim.scene import SceneObject


def _object(oid: int, mesh: trimesh.Trimesh) -> SceneObject:
    lo, hi = mesh.bounds
    base = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    local = mesh.copy()
    local.apply_translation(-base)
    return SceneObject(oid, f"obj{oid}", "object", base, np.array([1.0, 0, 0, 0]), local.extents, support_id=1,
                       visual=local, collision=[local])


def _depth_inside(mesh: trimesh.Trimesh, points: np.ndarray) -> np.ndarray:
    """How far each point lies inside the convex ``mesh`` (negative: outside by that much)."""
    return np.asarray(-np.max(np.einsum("fk,nfk->nf", mesh.face_normals, points[:, None, :] - mesh.triangles[None, :, 0, :]), axis=1))


def _top_points(a: np.ndarray, b: np.ndarray, slope: float, n: int = 30) -> np.ndarray:
    """Points on the plane z = slope * x + b[2] over the rectangle a..b (xy)."""
    x, y = np.meshgrid(np.linspace(a[0], b[0], n), np.linspace(a[1], b[1], n))
    return np.column_stack([x.ravel(), y.ravel(), slope * x.ravel() + b[2]])


def test_a_body_leaning_on_a_box_is_parted_along_the_plane_touching_it() -> None:
    # A 4 cm tall box (x 0.1..0.3) and a tilted slab seen on top, its near end on the table
    # (x 0..0.2): extruded down to the table, the slab's hull runs through the box.
    box = trimesh.creation.box(bounds=np.array([[0.1, 0.0, 0.0], [0.3, 0.2, 0.04]]))
    seen = _top_points(np.array([0.0, 0.02]), np.array([0.2, 0.18, 0.02]), 0.25)
    floor = seen.copy()
    floor[:, 2] = 0.0
    slab = trimesh.convex.convex_hull(np.vstack([seen, floor]))
    objects = [_object(1, box), _object(2, slab)]
    done = {1: box, 2: slab}
    part_overlapping(objects, done, {1: box.vertices, 2: seen}, CompletionParams(), {})
    assert done[1].volume == np.float64(box.volume)  # the box, seen whole, is not cut
    assert _depth_inside(done[1], np.asarray(done[2].vertices)).max() < 1e-4  # no longer through the box
    assert _depth_inside(done[2], seen).min() > -0.003  # every seen point still on or in the body
    assert done[2].volume > 0.4 * slab.volume


def test_a_body_curved_round_a_neighbour_gives_way_piece_by_piece() -> None:
    # A can seen all round (radius 5 cm) and a body of five tiles curved round it (a banana lying
    # against a pitcher); the middle tile's hidden far side pokes 1 cm into the can. No plane touching
    # the can keeps the curved body's seen tops (their hull wraps the can), so only the poking tile is cut.
    can = trimesh.creation.cylinder(radius=0.05, height=0.1, sections=48)
    can.apply_translation([0.0, 0.0, 0.05])
    angle = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    can_seen = np.column_stack([0.05 * np.cos(angle), 0.05 * np.sin(angle), np.full(200, 0.05)])
    tiles, tops = [], []
    for k, a in enumerate(np.radians([-60.0, -30.0, 0.0, 30.0, 60.0])):
        inner = 0.04 if k == 2 else 0.06
        ring = [(r * np.cos(a + da), r * np.sin(a + da)) for r in (inner, 0.08) for da in (-0.2, 0.2)]
        tiles.append(trimesh.convex.convex_hull(np.array([(x, y, z) for x, y in ring for z in (0.0, 0.03)])))
        r, da = np.meshgrid(np.linspace(0.065, 0.08, 5), np.linspace(-0.15, 0.15, 5))
        tops.append(np.column_stack([(r * np.cos(a + da)).ravel(), (r * np.sin(a + da)).ravel(), np.full(r.size, 0.03)]))
    seen = np.vstack(tops)
    body = trimesh.convex.convex_hull(np.vstack([t.vertices for t in tiles]))
    objects = [_object(1, can), _object(2, body)]
    done, pieces = {1: can, 2: body}, {2: list(tiles)}
    part_overlapping(objects, done, {1: can_seen, 2: seen}, CompletionParams(), pieces)
    assert done[1] is can  # the can, seen all round, is not cut
    assert len(pieces[2]) == 5 and all(pieces[2][k] is tiles[k] for k in (0, 1, 3, 4))  # only the poking tile changed
    assert max(_depth_inside(can, np.asarray(p.vertices)).max() for p in pieces[2]) < 1e-4  # none in the can
    assert min(max(_depth_inside(p, seen)[i] for p in pieces[2]) for i in range(len(seen))) > -0.003  # every seen top kept (within the noise)
    assert len(objects[1].collision) == 5


def test_a_body_on_a_sloping_top_is_seated_along_it() -> None:
    book = trimesh.convex.convex_hull(np.vstack([_top_points(np.array([0.0, 0.0]), np.array([0.3, 0.2, 0.02]), 0.1),
                                                 [[0, 0, 0], [0.3, 0, 0], [0, 0.2, 0], [0.3, 0.2, 0]]]))
    upper = _top_points(np.array([0.05, 0.05]), np.array([0.15, 0.15, 0.08]), 0.1, 10)
    plane = sloping_top(book, upper)
    assert plane is not None and abs(plane[0] - 0.1) < 1e-6 and abs(plane[1]) < 1e-6
    base_z = float(plane @ [0.15, 0.15, 1.0])  # the top's highest point under the upper body
    flat = trimesh.convex.convex_hull(np.vstack([upper, upper * [1, 1, 0] + [0, 0, base_z]]))
    seated = seat_on(plane, 0.0, base_z, [flat], 0.0)[0]
    low = seated.vertices[seated.vertices[:, 2] < base_z - 1e-6]
    assert len(low) >= 2 and np.allclose(low[:, 2], low[:, 0] * plane[0] + plane[2], atol=1e-9)  # its base lies on the top
    level = trimesh.creation.box(bounds=np.array([[0, 0, 0], [0.3, 0.2, 0.05]]))
    assert sloping_top(level, upper) is None  # a level top keeps the flat base


def test_a_base_that_does_not_hold_the_centre_of_mass_is_completed_under_it() -> None:
    # An overhanging wedge: its base is a 2 cm strip, its mass mostly beyond it.
    pts = np.array([[0, 0, 0], [0.02, 0, 0], [0, 0.05, 0], [0.02, 0.05, 0],
                    [0, 0, 0.06], [0.12, 0, 0.06], [0, 0.05, 0.06], [0.12, 0.05, 0.06]], float)
    obj = _object(1, trimesh.convex.convex_hull(pts))
    polygon = base_polygon(obj.collision)
    assert polygon is not None and not inside_convex_polygon(centre_of_mass(obj.collision)[None, :2], polygon)[0]
    assert brace(obj, 0.005)
    polygon = base_polygon(obj.collision)
    assert polygon is not None and inside_convex_polygon(centre_of_mass(obj.collision)[None, :2], polygon, -0.004)[0]
    assert obj.visual is obj.collision[0]
    assert not brace(obj, 0.005)  # it stands: nothing more to do


def test_a_narrow_body_is_braced_on_a_foot_no_wider_than_its_margin_needs() -> None:
    # A 12 cm prism lying along x on a 6 mm strip (a marker's contact): its centre of mass is over the
    # strip but within the 5 mm margin of its edges. The foot holds it 5 mm inside, and is not the
    # 2 cm disc a marker's 19 mm section would rest on.
    pts = np.array([[x, y, z] for x in (0.0, 0.12) for y, z in ((-0.003, 0.0), (0.003, 0.0), (-0.009, 0.01), (0.009, 0.01), (0.0, 0.019))])
    obj = _object(1, trimesh.convex.convex_hull(pts))
    assert brace(obj, 0.005)
    polygon = base_polygon(obj.collision)
    com = centre_of_mass(obj.collision)
    assert polygon is not None and inside_convex_polygon(com[None, :2], polygon, -0.005)[0]
    assert np.ptp(polygon[:, 1]) < 3 * 0.005  # about 1.25 margins each side of the centre of mass


def test_stacking_levels_never_put_an_object_with_what_it_rests_on() -> None:
    """Objects are completed a level at a time (in parallel within one): each level holds no object
    and its supporter, the order is kept, and a stack three high takes three levels."""
    def obj(oid: int, on: int | None) -> SceneObject:
        return SceneObject(oid, f"obj{oid}", "object", np.zeros(3), np.array([1.0, 0, 0, 0]), np.full(3, 0.1), resting_on=on)

    objects = [obj(1, None), obj(2, None), obj(3, 1), obj(4, 7), obj(5, 3), obj(6, 2)]  # 7 is no object: 4 is a root
    order = bottom_up(objects)
    levels = stacking_levels(order)
    assert [o.id for level in levels for o in level] == [o.id for o in order]
    assert [[o.id for o in level] for level in levels] == [[1, 2, 4], [3, 6], [5]]
    for level in levels:
        assert not {o.resting_on for o in level} & {o.id for o in level}
