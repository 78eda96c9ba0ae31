"""``planes``: the support surfaces (floor, tables, counters) found by seeded RANSAC, gravity
levelled on the dominant one (:mod:`realsim.perception.planes`)."""

from realsim.perception.planes import PlaneParams, detect_planes
from realsim.stages.base import Stage

STAGE = Stage("planes", detect_planes, PlaneParams, needs=("points",))
