"""Object assets: load any object mesh and make it a stable, faithful simulated object."""

from realsim.assets.loading import label_from_path, load_object_mesh
from realsim.assets.params import AssetParams
from realsim.assets.prepare import PreparedObject, prepare_object, prepare_objects

__all__ = ["AssetParams", "PreparedObject", "label_from_path", "load_object_mesh", "prepare_object", "prepare_objects"]
