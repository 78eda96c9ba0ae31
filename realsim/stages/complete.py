"""``complete``: each cluster completed into a solid, the unseen sides included
(:mod:`realsim.completion`)."""

from realsim.completion import CompletionParams, complete_objects
from realsim.stages.base import Stage

STAGE = Stage("complete", complete_objects, CompletionParams, needs=("planes",))
