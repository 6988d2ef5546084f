"""Run inside Blender: builds a humanoid the way an artist would in Blender, not the way kumite writes its
characters, and exports it with Blender's own glTF exporter. It stands in for a character a user brings:

- VRM / VRoid bone names (J_Bip_C_Hips, J_Bip_L_UpperArm, ...) under a Root bone on the floor;
- an A-pose (arms 45 degrees down), Z up, facing -Y (Blender's front), as Blender models it;
- modelled in centimetres under an armature object scaled 0.01 (as FBX imports from Maya and Mixamo are);
- a mesh of tapered limbs and a trunk, each vertex weighted to its bone and blended with the parent's near joints,
  bound with an Armature modifier; its own proportions (long legs, short arms), not those of the shipped five.

    blender -b --factory-startup --python scripts/blender_make_humanoid.py -- OUT.glb [--height 1.62]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_env  # noqa: E402,F401  numpy for the glTF add-on

import bmesh  # noqa: E402
import bpy  # noqa: E402
from mathutils import Vector

arguments = sys.argv[sys.argv.index("--") + 1:]
output = arguments[0]
height_m = float(arguments[arguments.index("--height") + 1]) if "--height" in arguments else 1.62
cm = height_m * 100.0 / 162.0  # the bones below are for a 162 cm figure

bpy.ops.wm.read_factory_settings(use_empty=True)

# Bones: name, parent, head, tail (centimetres, Z up, the character's left is +X, its front is -Y), radius.
arm = 1.0 / math.sqrt(2.0)  # A-pose: 45 degrees down
BONES = [
    ("Root", None, (0, 0, 0), (0, 0, 8), 0),
    ("J_Bip_C_Hips", "Root", (0, 0, 96), (0, 0, 106), 13),
    ("J_Bip_C_Spine", "J_Bip_C_Hips", (0, 0, 106), (0, 0, 118), 12),
    ("J_Bip_C_Chest", "J_Bip_C_Spine", (0, 0, 118), (0, 0, 130), 13),
    ("J_Bip_C_UpperChest", "J_Bip_C_Chest", (0, 0, 130), (0, 0, 140), 14),
    ("J_Bip_C_Neck", "J_Bip_C_UpperChest", (0, 0, 140), (0, 0, 148), 5),
    ("J_Bip_C_Head", "J_Bip_C_Neck", (0, -1, 148), (0, -1, 162), 9),
]
for side, x in (("L", 1.0), ("R", -1.0)):
    shoulder, elbow = (16 * x, 0, 137), (16 * x + 26 * arm * x, 0, 137 - 26 * arm)
    wrist = (elbow[0] + 23 * arm * x, 0, elbow[2] - 23 * arm)
    fist = (wrist[0] + 8 * arm * x, 0, wrist[2] - 8 * arm)
    BONES += [
        (f"J_Bip_{side}_Shoulder", "J_Bip_C_UpperChest", (3 * x, 0, 137), shoulder, 5),
        (f"J_Bip_{side}_UpperArm", f"J_Bip_{side}_Shoulder", shoulder, elbow, 4.5),
        (f"J_Bip_{side}_LowerArm", f"J_Bip_{side}_UpperArm", elbow, wrist, 3.8),
        (f"J_Bip_{side}_Hand", f"J_Bip_{side}_LowerArm", wrist, fist, 3.5),
        (f"J_Bip_{side}_UpperLeg", "J_Bip_C_Hips", (9 * x, 0, 96), (9 * x, 0, 52), 7.5),
        (f"J_Bip_{side}_LowerLeg", f"J_Bip_{side}_UpperLeg", (9 * x, 0, 52), (9 * x, 1, 9), 5.5),
        (f"J_Bip_{side}_Foot", f"J_Bip_{side}_LowerLeg", (9 * x, 1, 9), (9 * x, -11, 3), 4),
        (f"J_Bip_{side}_ToeBase", f"J_Bip_{side}_Foot", (9 * x, -11, 3), (9 * x, -17, 3), 3.5),
    ]

armature_data = bpy.data.armatures.new("Armature")
armature = bpy.data.objects.new("Armature", armature_data)
bpy.context.scene.collection.objects.link(armature)
armature.scale = (0.01, 0.01, 0.01)  # centimetres inside, metres outside
bpy.context.view_layer.objects.active = armature
bpy.ops.object.mode_set(mode="EDIT")
for name, parent, head, tail, _ in BONES:
    bone = armature_data.edit_bones.new(name)
    bone.head = Vector(head) * cm
    bone.tail = Vector(tail) * cm
    if parent:
        bone.parent = armature_data.edit_bones[parent]
        bone.use_connect = False
bpy.ops.object.mode_set(mode="OBJECT")

# The body: one tapered tube with closed ends per bone, weighted to it, blended with the parent near its head.
mesh_data = bpy.data.meshes.new("Body")
body = bpy.data.objects.new("Body", mesh_data)
bpy.context.scene.collection.objects.link(body)
mesh = bmesh.new()
weights = []  # per vertex: {bone: weight}
SEGMENTS, RINGS = 16, 8
for name, parent, head, tail, radius in BONES:
    if radius <= 0:
        continue
    a, b = Vector(head) * cm, Vector(tail) * cm
    axis = (b - a).normalized()
    u = axis.orthogonal().normalized()
    v = axis.cross(u)
    length = (b - a).length
    r = radius * cm
    rings, ring_weights = [], []
    for k in range(RINGS + 1):
        t = k / RINGS
        # Rounded ends: the radius falls off over the last 15% at each end; a little taper along the bone.
        end = min(t, 1 - t)
        rounding = math.sqrt(max(0.0, 1 - (max(0.0, 0.15 - end) / 0.15) ** 2))
        ring_radius = r * (1.0 - 0.15 * t) * max(0.2, rounding)
        centre = a + axis * (length * t + (-r * 0.5 if k == 0 else r * 0.5 if k == RINGS else 0.0))
        blend = 0.5 * max(0.0, 1.0 - t / 0.2) if parent and parent != "Root" else 0.0
        ring_weights.append({name: 1.0 - blend, parent: blend} if blend > 0 else {name: 1.0})
        ring = []
        for s in range(SEGMENTS):
            phi = 2 * math.pi * s / SEGMENTS
            ring.append(mesh.verts.new(centre + (u * math.cos(phi) + v * math.sin(phi)) * ring_radius))
            weights.append(ring_weights[-1])
        rings.append(ring)
    for k in range(RINGS):
        for s in range(SEGMENTS):
            s1 = (s + 1) % SEGMENTS
            mesh.faces.new((rings[k][s], rings[k][s1], rings[k + 1][s1], rings[k + 1][s]))
    for ring, cap_end, cap_weights in ((rings[0], a - axis * r * 0.5, ring_weights[0]), (rings[-1], b + axis * r * 0.5, ring_weights[-1])):
        pole = mesh.verts.new(cap_end)
        weights.append(cap_weights)
        for s in range(SEGMENTS):
            s1 = (s + 1) % SEGMENTS
            mesh.faces.new((ring[s1], ring[s], pole) if ring is rings[0] else (ring[s], ring[s1], pole))
mesh.verts.index_update()
bmesh.ops.recalc_face_normals(mesh, faces=mesh.faces)
mesh.to_mesh(mesh_data)
mesh.free()
for polygon in mesh_data.polygons:
    polygon.use_smooth = True
groups = {name: body.vertex_groups.new(name=name) for name, _, _, _, radius in BONES if radius > 0}
groups["Root"] = body.vertex_groups.new(name="Root")
for index, influences in enumerate(weights):
    for name, weight in influences.items():
        groups[name].add([index], weight, "REPLACE")
material = bpy.data.materials.new("Skin")
material.use_nodes = True
material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.85, 0.62, 0.45, 1.0)
mesh_data.materials.append(material)
body.parent = armature
modifier = body.modifiers.new("Armature", "ARMATURE")
modifier.object = armature

bpy.ops.export_scene.gltf(filepath=output, export_format="GLB", export_yup=True, export_skins=True, export_animations=False,
                          export_materials="EXPORT")
print(f"wrote {output}: {len(BONES)} bones, {len(mesh_data.vertices)} vertices, {len(mesh_data.polygons)} faces")
