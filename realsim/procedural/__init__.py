"""Procedural object assets built with manifold3d CSG (mugs, bowls, cans, drawer cabinets, ...)."""

from realsim.procedural.generate import Generated, Joint, Part, generate, kind_for, size_range, write_ply
from realsim.procedural.text_to_3d import TextTo3D, available_backends, get_backend, register_backend

__all__ = ["Generated", "Joint", "Part", "TextTo3D", "available_backends", "generate", "get_backend", "kind_for", "register_backend", "size_range", "write_ply"]
