"""Perception: reading a capture (clouds, meshes, RGB-D sequences, USD), its scale and frame, the
support planes, and the objects standing on them."""
