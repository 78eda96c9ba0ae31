"""The stages a pipeline YAML can name, one thin adapter module each over the algorithm it runs.

Following one object from the capture to its MJCF body reads as these names in order::

    load -> planes -> segment -> complete -> objects -> compose -> robot -> settle -> write

(``text`` or ``photo`` + ``text`` instead of planes..objects for descriptions and photos).
"""

from realsim.stages import complete, compose, load, objects, photo, planes, robot, segment, settle, text, write
from realsim.stages.base import Stage
from realsim.stages.write import WriteParams

STAGES: dict[str, Stage] = {s.name: s for s in (
    load.STAGE, planes.STAGE, segment.STAGE, complete.STAGE, text.STAGE, photo.STAGE, photo.BACKDROP_STAGE, objects.STAGE,
    compose.STAGE, robot.STAGE, settle.STAGE, write.STAGE,
)}

__all__ = ["STAGES", "Stage", "WriteParams"]
