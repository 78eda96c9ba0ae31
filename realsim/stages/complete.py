"""``complete``: each cluster completed into a solid, the unseen sides included
(:mod:`realsim.completion`); the objects' mesh files for compose are begun right after, by a forked
helper, while the next stages run."""

from realsim.completion import CompletionParams, complete_and_begin_meshes
from realsim.stages.base import Stage

STAGE = Stage("complete", complete_and_begin_meshes, CompletionParams, needs=("planes",))
