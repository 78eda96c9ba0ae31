"""An unorganized capture's backdrop, built by a thread begun before completion.

Ball pivoting (Open3D, most of the backdrop's time) releases the GIL, so a thread builds the
backdrop while completion and the ``objects`` stage run. Compose takes that work only when
everything it read is still the same (points, colours, which points are background, the spacing,
the viewpoint and the parameters), value for value; else the thread's work is dropped and the
backdrop is built again, so the output never depends on it. No process is forked by the thread.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.composition.appearance import AppearanceParams, support_top
from realsim.composition.backdrop import Backdrop, BackdropParams, build_cloud_backdrop
from realsim.geometry import inside_convex_polygon
from realsim.parallel import worker_count
from realsim.scene import Scene, SupportPlane

UNCOLOURED = 0.6  # grey of a capture without colours
VIEW_HEIGHT = 1.2  # m above the observed supports' centre: where a viewer of the backdrop stands

Top = tuple[SupportPlane, trimesh.Trimesh, np.ndarray]  # an observed support, its top mesh, the indices of its points


@dataclass(frozen=True)
class CloudBackdropInputs:
    """Everything :func:`build_cloud_backdrop` reads: the background's points and colours (copies:
    neither an object nor an observed support's top), the spacing, the viewpoint, the parameters."""

    points: np.ndarray
    colors: np.ndarray
    spacing: float
    viewpoint: np.ndarray
    params: BackdropParams

    def build(self) -> Backdrop | None:
        """The backdrop of these inputs."""
        keep = np.ones(len(self.points), bool)
        return build_cloud_backdrop(self.points, self.colors, keep, self.spacing, self.viewpoint, self.params)

    def same(self, other: CloudBackdropInputs) -> bool:
        """Whether ``other`` holds the same values (then its backdrop is this one's)."""
        arrays = ((self.points, other.points), (self.colors, other.colors), (self.viewpoint, other.viewpoint))
        return self.params == other.params and np.array_equal(self.spacing, other.spacing, equal_nan=True) and all(
            a.shape == b.shape and a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True) for a, b in arrays)


@dataclass(frozen=True)
class CloudLayers:
    """An unorganized capture's points and colours (0-1; grey without colours), its observed support
    tops (each with the points on it that no object holds) and what its backdrop is built from."""

    points: np.ndarray
    colors: np.ndarray
    tops: list[Top]
    backdrop: CloudBackdropInputs


def cloud_layers(scene: Scene, appearance: AppearanceParams, backdrop: BackdropParams) -> CloudLayers:
    """The :class:`CloudLayers` of ``scene``: the backdrop's points are those neither an object nor on a top."""
    assert scene.points is not None and scene.labels is not None
    points = np.asarray(scene.points, float)
    colors = np.asarray(scene.colors, float) if scene.colors is not None else np.full(points.shape, UNCOLOURED)  # geometry only: grey
    background = scene.labels <= 0
    tops: list[Top] = []
    for plane in [p for p in scene.planes if p.observed]:
        near = background & (np.abs(np.nan_to_num(points[:, 2], nan=1e9) - plane.height) < appearance.support_tolerance)
        idx = np.flatnonzero(near)
        on = idx[inside_convex_polygon(points[idx, :2], np.asarray(plane.polygon, float))]
        background[on] = False
        if len(on) >= 3:
            tops.append((plane, support_top(plane, appearance.support_cell, appearance.top_lift), on))
    observed = [p for p in scene.planes if p.observed] or list(scene.planes)
    centre = np.array([*np.mean([p.rect_center for p in observed], axis=0), max(p.height for p in observed)]) if observed \
        else np.nanmean(points, axis=0)
    spacing = scene.capture.point_spacing or float("nan")
    inputs = CloudBackdropInputs(points[background], colors[background], float(spacing), centre + [0.0, 0.0, VIEW_HEIGHT], backdrop)
    return CloudLayers(points, colors, tops, inputs)


class _Build(threading.Thread):
    """One backdrop built beside the main thread; ``result`` once joined (``failed`` if it raised)."""

    def __init__(self, inputs: CloudBackdropInputs) -> None:
        super().__init__(name="realsim-backdrop", daemon=True)
        self.inputs = inputs
        self.result: Backdrop | None = None
        self.failed = False

    def run(self) -> None:
        try:
            self.result = self.inputs.build()
        except BaseException:  # built again by the caller, which raises it with its own traceback
            self.failed = True


_begun: list[_Build] = []  # at most one


def begin(scene: Scene, appearance: AppearanceParams = AppearanceParams(), backdrop: BackdropParams = BackdropParams()) -> None:
    """Start building the backdrop of ``scene`` as it is now (an unorganized capture with labels and
    supports; anything else, or one core allowed by ``$REALSIM_WORKERS``: nothing) with these parameters."""
    _begun.clear()  # an earlier conversion's work not taken: dropped (its thread ends on its own)
    if scene.points is None or scene.labels is None or scene.grid_shape is not None or not scene.planes or worker_count(2) < 2:
        return
    if not (appearance.enabled and backdrop.enabled):
        return
    build = _Build(cloud_layers(scene, appearance, backdrop).backdrop)
    build.start()
    _begun.append(build)


def cloud_backdrop(inputs: CloudBackdropInputs) -> Backdrop | None:
    """The backdrop of ``inputs``: the one begun by :func:`begin` when it read the same, else built now."""
    if _begun:
        build = _begun.pop()
        if build.inputs.same(inputs):
            build.join()
            if not build.failed:
                return build.result
    return inputs.build()
