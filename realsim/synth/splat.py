"""Write a SynthScene as a 3D Gaussian splat PLY (the INRIA 3DGS layout phone apps export).

Each splat is a flat Gaussian lying in the surface it was sampled on: two axes as wide as the
sample spacing, the third a tenth of it along the face normal, colour as the zeroth spherical
harmonic and a high opacity. A few faint splats float in the air around the scene, as trained
splats have; readers keep only splats with opacity >= 0.2.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from realsim.synth.forms import apply, sample_surface, world_to_capture
from realsim.synth.scene import SynthScene

SH_C0 = 0.28209479177387814  # zeroth spherical-harmonic band: rgb = 0.5 + SH_C0 * f_dc
FIELDS = ("x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2", "opacity",
          "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3")


def _logit(p: np.ndarray) -> np.ndarray:
    return np.log(p / (1.0 - p))


def _quaternions_taking_z_to(normals: np.ndarray) -> np.ndarray:
    """(N, 4) unit quaternions (w, x, y, z) rotating +z onto each unit normal."""
    z = np.array([0.0, 0.0, 1.0])
    axis = np.cross(np.broadcast_to(z, normals.shape), normals)
    q = np.column_stack([1.0 + normals[:, 2], axis])
    flipped = q[:, 0] < 1e-9  # a normal pointing straight down: half a turn about x
    q[flipped] = [0.0, 1.0, 0.0, 0.0]
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def write_splat(scene: SynthScene, path: Path, count: int = 200_000, seed: int = 0, noise: float = 0.002,
                floaters: float = 0.03, units: str = "m", up: str = "+z") -> tuple[dict[str, Any], np.ndarray]:
    """A splat of ``count`` surface Gaussians plus ``floaters`` x count faint ones (binary PLY).
    Returns the ground-truth entry and the object id of every written splat (-1 for floaters)."""
    pts, pick = sample_surface(scene, count, seed, noise)
    rng = np.random.default_rng([seed, 23])
    spacing = float(np.sqrt(scene.mesh.area_faces[np.unique(pick)].sum() / count))
    n_float = int(round(floaters * count))
    lo, hi = scene.mesh.bounds
    air = lo + rng.random((n_float, 3)) * (hi - lo)
    t_scale = world_to_capture(units, up)
    scale = float(np.linalg.norm(t_scale[:3, 0]))  # capture units per metre
    normals = scene.mesh.face_normals[pick] @ t_scale[:3, :3].T / scale
    rgb = scene.mesh.visual.vertex_colors[scene.mesh.faces[pick, 0], :3] / 255.0

    data = np.zeros(count + n_float, dtype=[(k, "<f4") for k in FIELDS])
    centres = apply(t_scale, np.vstack([pts, air]))
    data["x"], data["y"], data["z"] = centres.T
    colours = np.vstack([rgb, rng.random((n_float, 3))])
    for i in range(3):
        data[f"f_dc_{i}"] = (colours[:, i] - 0.5) / SH_C0
    data["opacity"] = np.r_[_logit(rng.uniform(0.6, 0.99, count)), _logit(rng.uniform(0.01, 0.15, n_float))]
    log_wide, log_thin = np.log(spacing * scale), np.log(0.1 * spacing * scale)
    data["scale_0"], data["scale_1"] = log_wide, log_wide
    data["scale_2"] = np.r_[np.full(count, log_thin), np.full(n_float, log_wide)]
    quats = np.vstack([_quaternions_taking_z_to(normals), np.tile([1.0, 0.0, 0.0, 0.0], (n_float, 1))])
    for i in range(4):
        data[f"rot_{i}"] = quats[:, i]
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(data)}\n"
              + "".join(f"property float {k}\n" for k in FIELDS) + "end_header\n")
    Path(path).write_bytes(header.encode("ascii") + data.tobytes())
    ids = np.r_[scene.face_object[pick], np.full(n_float, -1)]
    return {"file": Path(path).name, "form": "splat", "units": units, "up": up, "splats": int(len(data)),
            "floaters": n_float, "noise_m": noise, "capture_to_world": np.linalg.inv(t_scale)}, ids
