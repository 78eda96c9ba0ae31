"""``complete``: each cluster completed into a solid, the unseen sides included
(:mod:`realsim.completion`); the objects' mesh files for compose are begun right after, by a forked
helper, while the next stages run (:func:`realsim.composition.object_meshes.begin`)."""

from realsim.completion import CompletionParams, complete_objects
from realsim.composition.object_meshes import begin
from realsim.scene import Scene
from realsim.stages.base import Stage


def complete(scene: Scene, params: CompletionParams = CompletionParams()) -> Scene:
    """:func:`realsim.completion.complete_objects`, then the objects' mesh files begun."""
    scene = complete_objects(scene, params)
    begin(scene)
    return scene


STAGE = Stage("complete", complete, CompletionParams, needs=("planes",))
