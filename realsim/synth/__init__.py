"""Ground-truth capture generator: real YCB scans on tables, counters and floors, in every capture form.

A tool for tests, benches and ``realsim example``; no conversion module imports it. The bundled
primitive tabletop (``realsim example DEST`` without ``--layout``) is :mod:`realsim.synth.tabletop`.

Build a scene (world frame: right-handed, Z up, metres, floor top at z = 0)::

    from realsim.synth import SceneSpec, make_scene, write_all
    scene = make_scene(SceneSpec(layout="table",            # "table" | "counter" | "floor" | "rooms" (2-3 tables)
                                 objects=("025_mug", "003_cracker_box", "005_tomato_soup_can"),  # or None:
                                 n_objects=4,               #   n_objects drawn from DEFAULT_OBJECTS
                                 stacked=True,              # one object on a flat-topped one (boxes lie flat)
                                 touching=True,             # two objects in contact side by side
                                 seed=0))
    scene.supports      # [GtSupport(name, kind, height, center, size, yaw, thickness)], floor first
    scene.objects       # [GtObject(id 1..K, name, mesh_file, pose 4x4 file->world, support, resting_on, touching)]
    scene.objects[0].mesh()          # the object's surface in the world (trimesh)
    scene.mesh                       # merged world mesh (vertex colours); scene.face_object: id per face
    scene.label_points(world_pts)    # ground-truth object id (0 none) of any world points

Write capture forms (each returns its ``ground_truth.json`` entry with ``capture_to_world``)::

    write_all(scene, dest, forms=("view", "sequence", "cloud", "mesh"), cloud_points=200_000, frames=30)
    # dest/view.pcd          organized 640x480 Kinect-like view, optical frame (+y down), mOSD label field
    # dest/sequence/         RGB-D sweep, Stray Scanner layout (rgb/, depth/ uint16 mm, camera_matrix.csv,
    #                        odometry.csv with ARKit poses, Y up); realsim.perception.rgbd reads it
    # dest/cloud.ply         unorganized cloud of the visible surfaces, 2 mm noise, Z up, metres
    #                        (+ cloud_labels.npy: object id per point)
    # dest/mesh.glb          the merged mesh, glTF Y-up millimetres, vertex colours
    # dest/splat.ply         3D Gaussian splat (3DGS PLY) of the visible surfaces, 3 % faint floaters
    #                        (+ splat_labels.npy: object id per splat, -1 floaters); forms="...,splat"
    # dest/ground_truth.json supports, objects (id, name, pose, mesh_file, resting_on, touching), forms
    write_point_cloud(scene, path, count=1_000_000, units="cm", up="+y")   # any density, units, up
    write_mesh(scene, path, units="m", up="+z")                             # .glb, .obj, .ply
    write_splat(scene, path, count=200_000)                                 # realsim.synth.splat
    sample_cloud(scene, count) -> (points, colours, object ids)            # in memory, world frame
    render(scene, look_at(eye, target)) -> Frame(color, depth, part, object_id)   # one ray-cast view
"""

from realsim.synth.camera import Camera, Frame, backproject, kinect_noise, kinect_view, look_at, orbit, out_of_view, render
from realsim.synth.forms import (
    ground_truth,
    sample_cloud,
    visible_faces,
    world_to_capture,
    write_all,
    write_mesh,
    write_organized_view,
    write_point_cloud,
    write_rgbd_sequence,
)
from realsim.synth.scene import (
    DEFAULT_OBJECTS,
    LAYOUTS,
    GtObject,
    GtSupport,
    SceneSpec,
    SynthScene,
    make_scene,
    ycb_root,
)
from realsim.synth.splat import write_splat

__all__ = [
    "Camera", "Frame", "backproject", "kinect_noise", "kinect_view", "look_at", "orbit", "out_of_view", "render",
    "ground_truth", "sample_cloud", "visible_faces", "world_to_capture", "write_all", "write_mesh",
    "write_organized_view", "write_point_cloud", "write_rgbd_sequence", "write_splat",
    "DEFAULT_OBJECTS", "LAYOUTS", "GtObject", "GtSupport", "SceneSpec", "SynthScene", "make_scene", "ycb_root",
]
