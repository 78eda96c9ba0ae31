"""Export a converted scene: self-contained MJCF (whole scene or one file per object) and USD."""

from realsim.export.mjcf import ObjectExport, export_mjcf, export_objects, object_bodies, relocate_assets
from realsim.export.usd import ROBOT_NOTE, UsdExport, export_usd

__all__ = ["ObjectExport", "UsdExport", "ROBOT_NOTE", "export_mjcf", "export_objects", "export_usd", "object_bodies", "relocate_assets"]
