"""realsim: turn a captured real scene into a settled MuJoCo simulation."""

import os

# MuJoCo picks its GL backend when first imported: offscreen EGL works on CPU-only machines.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
