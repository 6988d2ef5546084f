"""Run inside Blender: imports a glTF file with Blender's own importer and writes its armature's rest joint
positions (world, glTF axes: Y up, metres), its meshes' vertex and polygon counts and its actions' frame counts as
JSON; with --frames, also every joint's posed position at those frames of the animation.

    blender -b --factory-startup --python scripts/blender_gltf_joints.py -- IN.glb OUT.json [--fps 30] [--frames 0,12,40]

--fps sets the scene's frame rate before the import (Blender's importer turns seconds into frames with it), so a
recording at 30 Hz imported at --fps 30 has frame k of the animation at Blender frame k + the action's start.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_env  # noqa: E402,F401  numpy for the glTF add-on

import bpy  # noqa: E402

arguments = sys.argv[sys.argv.index("--") + 1:]
source, output = arguments[:2]
fps = float(arguments[arguments.index("--fps") + 1]) if "--fps" in arguments else None
frames = [int(f) for f in arguments[arguments.index("--frames") + 1].split(",")] if "--frames" in arguments else []

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
if fps:
    scene.render.fps = int(round(fps))
    scene.render.fps_base = scene.render.fps / fps
bpy.ops.import_scene.gltf(filepath=source)


def gltf_axes(v):
    return [v.x, v.z, -v.y]  # Blender is Z up: back to glTF's Y up


joints, meshes, actions, posed = {}, [], {}, {}
armature = None
for obj in scene.objects:
    if obj.type == "ARMATURE":
        armature = obj
        for bone in obj.data.bones:
            joints[bone.name] = gltf_axes(obj.matrix_world @ bone.head_local)
    elif obj.type == "MESH":
        meshes.append({"name": obj.name, "vertices": len(obj.data.vertices), "polygons": len(obj.data.polygons),
                       "skinned": any(m.type == "ARMATURE" for m in obj.modifiers), "groups": len(obj.vertex_groups)})
start = None
for action in bpy.data.actions:
    first, last = action.frame_range
    start = first if start is None else min(start, first)
    keys = max((len(curve.keyframe_points) for curve in action.fcurves), default=0)
    actions[action.name] = {"frames": int(round(last - first)) + 1, "first": first, "last": last, "keys": keys}
if armature is not None and frames:
    for frame in frames:
        scene.frame_set(int(round((start or 0) + frame)))
        posed[str(frame)] = {bone.name: gltf_axes(armature.matrix_world @ bone.head) for bone in armature.pose.bones}
with open(output, "w") as stream:
    json.dump({"joints": joints, "meshes": meshes, "actions": actions, "posed": posed}, stream)
