"""``planes``: the support surfaces (floor, tables, counters) found by seeded RANSAC, gravity
levelled on the dominant one (:mod:`realsim.planes`)."""

from realsim.planes import PlaneParams, detect_planes
from realsim.stages.base import Stage

STAGE = Stage("planes", detect_planes, PlaneParams, needs=("points",))
