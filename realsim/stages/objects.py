"""``objects``: every object made physics-ready (hulls or primitives, visual mesh, manifest) and
placed (:mod:`realsim.composition.objects`, :mod:`realsim.assets`, :mod:`realsim.understanding`)."""

from realsim.composition.objects import ObjectsParams, prepare_scene_objects
from realsim.stages.base import Stage

STAGE = Stage("objects", prepare_scene_objects, ObjectsParams)
