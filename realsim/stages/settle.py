"""``settle``: simulate to rest and write the keyframe in which everything already rests
(:mod:`realsim.composition.settle`)."""

from realsim.composition.settle import SettleParams, settle_scene
from realsim.stages.base import Stage

STAGE = Stage("settle", settle_scene, SettleParams, needs=("spec",))
