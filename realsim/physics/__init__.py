"""Physical properties of objects: size/material tables, the manifest and its estimator."""

from realsim.physics.manifest import ObjectManifest, estimate_manifest, estimate_mass
from realsim.physics.mujoco_params import solref_from_restitution
from realsim.physics.size_table import lookup, material

__all__ = ["ObjectManifest", "estimate_manifest", "estimate_mass", "lookup", "material", "solref_from_restitution"]
