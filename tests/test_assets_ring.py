"""Open containers as a floor slab and a ring of wall slabs: few hulls, the cavity kept."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import trimesh

from realsim.assets.decompose import decompose
from realsim.assets.fidelity import parts_fidelity
from realsim.assets.params import AssetParams
from realsim.physics.sim_checks import ball_in_container_test

RIM, FOOT, HEIGHT, WALL = 0.075, 0.04, 0.055, 0.003


def _bowl() -> trimesh.Trimesh:
    """A thin-walled bowl: a flared profile revolved about z (outer wall up, inner wall down)."""
    z = np.linspace(0.0, HEIGHT, 12)
    outer = FOOT + (RIM - FOOT) * np.sqrt(z / HEIGHT)
    zi = np.linspace(HEIGHT, WALL, 12)
    inner = FOOT + (RIM - FOOT) * np.sqrt(zi / HEIGHT) - WALL
    profile = np.vstack([[0.0, 0.0], np.column_stack([outer, z]), np.column_stack([inner, zi]), [0.0, WALL]])
    return trimesh.creation.revolve(profile, sections=96)


def test_bowl_becomes_a_ring_that_keeps_its_cavity():
    bowl = _bowl()
    assert bowl.is_watertight
    params = AssetParams()
    hulls, info = decompose(bowl, params, open_container=True)
    assert info["method"] == "container_ring"
    # sectors from the rim's curvature: a slab strays half the sagitta r (1 - cos a/2) either way
    least = math.ceil(math.pi / math.acos(1 - 2 * params.target_p95 / RIM))
    assert least <= info["ring"]["sectors"] <= least + 3
    assert len(hulls) <= 2 * info["ring"]["sectors"] + 1 < 48
    assert all(len(h.vertices) <= params.max_hull_vertices for h in hulls)
    d95, _ = parts_fidelity(hulls, bowl)
    assert d95 <= params.target_p95
    ball = ball_in_container_test(SimpleNamespace(hulls=hulls, solid=bowl, size=bowl.extents))  # type: ignore[arg-type]
    assert ball["cavity_found"] and ball["inside"], ball


def test_a_solid_cup_is_not_a_ring():
    """A closed cylinder called a container has no thin wall: the ring fails its self-check."""
    can = trimesh.creation.cylinder(radius=0.04, height=0.1, sections=64)
    can.apply_translation([0, 0, 0.05])
    params = AssetParams(primitives=False, convex_volume_ratio=1.1, hull_budget=False)
    from realsim.assets.container_ring import container_ring

    ring = container_ring(can, params)
    assert ring is None or len(ring[1]) > 0  # never a bare ring for a solid: the rest goes to CoACD
