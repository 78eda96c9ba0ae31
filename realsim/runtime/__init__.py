"""The session layer: a loaded scene (:class:`Sim`), sentences and programs run in it.

    sim = Sim.load("out/kitchen")
    record = run_command(sim, "put the mug in the bowl", planner="rules")
    print(record.summary()); write_log(record)

Every run starts from keyframe "initial"; the scene folder is never written to (except the run
logs under ``<scene>/runs/``).
"""

from realsim.runtime.primitives import ProgramAPI
from realsim.runtime.session import RunRecord, next_log_path, run_command, run_program, write_log
from realsim.runtime.sim import Sim
from realsim.runtime.video import VideoRecorder, probe

__all__ = ["ProgramAPI", "RunRecord", "Sim", "VideoRecorder", "next_log_path", "probe", "run_command", "run_program", "write_log"]
