"""``segment``: the objects standing on the supports, as point clusters (:mod:`realsim.perception.segment`)."""

from realsim.perception.segment_scene import SegmentParams, segment_scene
from realsim.stages.base import Stage

STAGE = Stage("segment", segment_scene, SegmentParams, needs=("points", "planes"))
