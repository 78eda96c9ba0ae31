"""``text``: a description (or a photo's scene spec) built from procedural objects and arranged
as described (:mod:`realsim.text`)."""

from realsim.stages.base import Stage
from realsim.text.stage import TextParams, text_scene

STAGE = Stage("text", text_scene, TextParams)
