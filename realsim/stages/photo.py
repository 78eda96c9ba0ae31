"""``photo`` and ``photo_backdrop``: Claude describes a photo as a scene spec for the text stage;
the photo is kept and shown behind the table (:mod:`realsim.understanding.photo_scene`)."""

from realsim.stages.base import Stage
from realsim.understanding.photo_scene import BackdropParams, PhotoParams, photo_backdrop, photo_scene

STAGE = Stage("photo", photo_scene, PhotoParams)
BACKDROP_STAGE = Stage("photo_backdrop", photo_backdrop, BackdropParams, needs=("spec",))
