"""A live browser viewer of a converted scene (viser): physics in real time, commands in a text box."""

from realsim.viewer.commands import NEEDS_RUNTIME, on_command
from realsim.viewer.frames import configure_up, to_viser
from realsim.viewer.server import LiveSim, Viewer, load_live_sim, serve

__all__ = ["LiveSim", "NEEDS_RUNTIME", "Viewer", "configure_up", "load_live_sim", "on_command", "serve", "to_viser"]
