"""The Panda's meshes processed by MuJoCo ahead of the robot stage, by a thread begun after ``load``.

MuJoCo keeps every mesh it processes in its process-wide asset cache, keyed by the mesh's path
(model folder, mesh folder, file name) and content. The first compile of a scene holding the Panda
(the robot stage's) processes the Panda's meshes on its compile threads (0.25 s CPU of a 640 x 480
scan's conversion). A thread compiling the Panda alone under the scene's mesh folder while the
capture's own stages run (segmentation leaves the second core idle) fills that cache, and the
robot stage's compile takes the processed meshes from it: the same model either way (the written
scene's compile check is served from the same cache already). The thread also builds the pose
search's input-independent IK model (:func:`realsim.composition.robot_placement.bare_panda`, kept
per process). MuJoCo releases the GIL while it compiles. The thread's failures are ignored: the
robot stage meets them itself.
"""

from __future__ import annotations

import threading

from realsim.composition.compose import ComposeParams, new_spec
from realsim.composition.robot_placement import prepare_search
from realsim.parallel import worker_count
from realsim.robot.model import panda_spec

_begun: list[threading.Thread] = []  # at most one


def _compile_panda(modelfiledir: str, meshdir: str) -> None:
    try:
        child, _ = panda_spec()
        child.modelfiledir, child.meshdir = modelfiledir, meshdir  # as attach_robot resolves them in the scene
        child.compiler.usethread = False  # one thread, on the idle core: no compile threads beside the main one
        child.compile()
        prepare_search()
    except Exception:  # no Menagerie, a damaged mesh: the robot stage reports it
        pass


def begin(enabled: bool = True) -> None:
    """Start compiling the Panda in a thread (when the robot will be ``enabled`` and more than one
    core may be used, see :func:`realsim.parallel.worker_count`), under the mesh folders of the
    scenes compose makes (:func:`realsim.composition.compose.new_spec`)."""
    finish()  # an earlier conversion's thread is done before another begins
    if not enabled or worker_count(2) < 2:
        return
    spec = new_spec(ComposeParams())
    thread = threading.Thread(target=_compile_panda, args=(spec.modelfiledir, spec.meshdir), name="realsim-panda-meshes")
    thread.start()
    _begun.append(thread)


def finish() -> None:
    """Wait for the thread begun by :func:`begin`, if any (before compiling the Panda: its meshes are
    then cached, never processed twice at once)."""
    while _begun:
        _begun.pop().join()
