"""The one place where MuJoCo's frame meets the browser's.

MuJoCo is right-handed, Z up, metres, quaternions (w, x, y, z). three.js is Y up, but viser
keeps its scene Z up by default and rotates it into three.js itself; :func:`configure_up`
pins that choice (``set_up_direction("+z")``) so that poses pass through unchanged. Every pose
the viewer sends goes through :func:`to_viser`.
"""

from __future__ import annotations

import numpy as np

UP_DIRECTION = "+z"


def configure_up(server) -> None:
    """Make the viser scene Z-up (MuJoCo's world frame); viser maps it to three.js's Y-up."""
    server.scene.set_up_direction(UP_DIRECTION)


def to_viser(pos: np.ndarray, quat_wxyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A MuJoCo pose (world frame, quaternion w,x,y,z) as a viser pose (position, wxyz).

    With the scene Z-up (see :func:`configure_up`) this is the identity up to dtype and
    quaternion normalisation; viser's own wxyz order matches MuJoCo's.
    """
    q = np.asarray(quat_wxyz, dtype=np.float64)
    q = q / max(float(np.linalg.norm(q)), 1e-12)
    return np.asarray(pos, dtype=np.float64).copy(), q
