"""The Panda's mesh assets are kept in process per file, and a changed file is read again."""

from __future__ import annotations

import os

import trimesh

from realsim.robot.model import _mesh_asset, panda_spec


def _asset(path):
    stat = path.stat()
    return _mesh_asset(str(path), stat.st_size, stat.st_mtime_ns)


def _vertices(stl: bytes) -> float:
    mesh = trimesh.load(trimesh.util.wrap_as_stream(stl), file_type="stl")
    return float(mesh.extents.max())


def test_obj_becomes_stl_and_a_rewritten_file_is_read_again(tmp_path):
    obj = tmp_path / "link.obj"
    obj.write_text(trimesh.exchange.obj.export_obj(trimesh.creation.box([0.1, 0.1, 0.1])))
    name, first = _asset(obj)
    assert name == "panda_link.stl" and abs(_vertices(first) - 0.1) < 1e-6
    assert _asset(obj)[1] is first  # kept: not read, converted or hashed again
    text = obj.read_text().replace("0.05", "0.07")  # same length, other content
    obj.write_text(text)
    stat = obj.stat()
    os.utime(obj, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))
    assert abs(_vertices(_asset(obj)[1]) - 0.14) < 1e-6
    png = tmp_path / "tex.png"
    png.write_bytes(b"not really a png")
    assert _asset(png) == ("panda_tex.png", b"not really a png")


def test_panda_spec_twice_gives_the_same_assets():
    _, first = panda_spec()
    _, second = panda_spec()
    assert first.keys() == second.keys() and all(first[k] == second[k] for k in first)
