"""Knobs of the object-asset stage (normalization and convex decomposition)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class AssetParams:
    """Decomposition and normalization parameters; the defaults are tuned on the YCB scans.

    CoACD runs on a quadric-decimated copy of the watertight solid with its own (slow, O(n^2))
    hull merging off; the many small parts are then merged greedily here by how much volume a
    merge adds, which preserves cavities and is much faster.
    """

    # --- normalization
    rescale_implausible: bool = True
    plausible_margin: float = 1.6  # accept [min / margin, max * margin] of the size table
    # --- solid
    voxel_fallback_pitch: float = 0.003  # m, voxel fill when the mesh can't be made manifold
    # --- primitives: a box, upright cylinder or sphere when it is as faithful as hulls
    primitives: bool = True
    primitive_tolerance: float = 0.003  # m, two-way p95 surface distance of the primitive
    # --- convex shortcut: a single hull when it is already faithful
    convex_volume_ratio: float = 0.90  # solid volume / hull volume at least this ...
    convex_tolerance: float = 0.0025  # ... and p95 hull-surface-to-scan distance (m) at most this
    # --- open containers: a floor slab and a ring of wall slabs when faithful (few hulls, cavity kept)
    container_ring: bool = True
    # --- CoACD
    decimate_faces: int = 1500
    threshold: float = 0.05
    preprocess_mode: str = "auto"  # used only when the decimated solid is not watertight
    preprocess_resolution: int = 30
    resolution: int = 500
    mcts_iterations: int = 20
    mcts_nodes: int = 10
    mcts_max_depth: int = 2
    seed: int = 0
    # --- self-check: re-run CoACD with a lower threshold when the parts are not faithful enough
    refine_attempts: int = 1
    target_p95: float = 0.0038  # m, two-way 95th percentile surface distance (the fidelity bar is 4 mm)
    target_iou: float = 0.85  # volume IoU (objects without an open cavity)
    # --- hull post-processing
    max_hulls: int = 48
    hull_budget: bool = True  # merge further while the self-check holds (fewer hulls, cheaper contacts)
    hull_budgets: tuple[int, ...] = (40, 32, 28, 24, 20, 16, 12, 8, 6, 4, 3, 2, 1)
    merge_tolerance: float = 0.0015  # m: merge two parts while the merged hull stays this close to them
    min_hull_thickness: float = 0.0005  # m: thinner hulls are thickened to this
    max_hull_vertices: int = 64
