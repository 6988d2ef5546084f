#!/usr/bin/env python3
"""Writes data/characters/NAME.glb: a skinned glTF 2.0 body for each shipped character, from its BVH
(data/characters/NAME.bvh, written by make_characters.py): the same joints, names and rest pose (T-pose, facing +Z,
Y up, metres), and a mannequin body around them: one closed capsule per bone (a sphere-capped cylinder whose radius
depends on the body part and the character's height), skinned to the bone's joint, its first quarter blended with
the parent joint so elbows, knees, shoulders and hips bend without tearing. A distinct base colour each.

Run from the repository root: python3 scripts/make_character_bodies.py. Deterministic: the same BVH gives the same
bytes.
"""
import json
import math
import os
import re
import struct
import sys

# Linear RGBA, as glTF means them: each the colour the viewer showed before it lit in linear light (0.90, 0.45,
# 0.10 for the kid, ...), squared, so that the viewer (which shows linear colours with gamma 2) shows the same ones.
DISPLAY_COLOURS = {
    "kid": (0.90, 0.45, 0.10),
    "scout": (0.20, 0.60, 0.25),
    "brawler": (0.70, 0.12, 0.10),
    "runner": (0.15, 0.35, 0.80),
    "giant": (0.50, 0.25, 0.65),
}
COLOURS = {name: tuple(round(c * c, 4) for c in rgb) + (1.0,) for name, rgb in DISPLAY_COLOURS.items()}
UNITS = {"cm": 0.01, "m": 1.0}

# Capsule radius as a fraction of the standing height, by the part a bone's joint drives (first match of the
# lower-case joint name).
PART_RADII = [
    ("hipjoint", 0.055), ("forearm", 0.026), ("lowerarm", 0.026), ("upperarm", 0.031), ("hand", 0.022),
    ("arm", 0.031), ("shoulder", 0.03), ("clavicle", 0.03), ("upleg", 0.047), ("upperleg", 0.047), ("thigh", 0.047),
    ("lowerleg", 0.035), ("calf", 0.035), ("toe", 0.02), ("ball", 0.02), ("foot", 0.027), ("leg", 0.035),
    ("head", 0.058), ("neck", 0.03), ("spine1", 0.08), ("spine2", 0.08), ("spine_03", 0.08), ("chest", 0.08),
    ("spine", 0.075), ("lowerback", 0.075), ("hips", 0.075), ("pelvis", 0.075),
]
RINGS_PER_CAP, SEGMENTS, CYLINDER_RINGS = 4, 14, 3
BLEND_FRACTION = 0.25  # of a bone's length near its joint, blended with the parent joint


def read_bvh(path):
    """Joint names, parents, offsets (file units) and End Site offsets of a BVH hierarchy."""
    tokens = open(path).read().split()
    names, parents, offsets, end_sites = [], [], [], []
    stack, i = [], 0
    while i < len(tokens):
        token = tokens[i]
        if token in ("ROOT", "JOINT"):
            names.append(tokens[i + 1])
            parents.append(stack[-1] if stack else -1)
            stack.append(len(names) - 1)
            i += 2
        elif token == "End":
            i += 2  # "End Site"
            assert tokens[i] == "{" and tokens[i + 1] == "OFFSET"
            end_sites.append((stack[-1], [float(v) for v in tokens[i + 2:i + 5]]))
            i += 6  # { OFFSET x y z }
        elif token == "OFFSET":
            offsets.append([float(v) for v in tokens[i + 1:i + 4]])
            i += 4
        elif token == "}":
            stack.pop()
            i += 1
        elif token == "MOTION":
            break
        else:
            i += 1
    return names, parents, offsets, end_sites


def unit_of(path):
    """The shipped BVHs say their unit in make_characters.py; the giant is in metres, the others centimetres."""
    name = os.path.splitext(os.path.basename(path))[0]
    return UNITS["m" if name == "giant" else "cm"]


def radius_for(name, height):
    lower = re.sub(r"^.*:", "", name).lower()
    for key, fraction in PART_RADII:
        if key in lower:
            return fraction * height
    return 0.03 * height


def capsule(a, b, radius):
    """Vertices (position, normal, t along a->b in 0..1) and triangles of a closed capsule around segment a-b."""
    axis = [b[k] - a[k] for k in range(3)]
    length = math.sqrt(sum(v * v for v in axis))
    if length < 1e-9:
        axis, length = [0.0, 1.0, 0.0], 0.0
    else:
        axis = [v / length for v in axis]
    helper = [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 0.0, 1.0]
    u = cross(axis, helper)
    u = normalise(u)
    v = cross(axis, u)
    rings = []  # (centre offset along the axis, ring radius, normal's axis component, t)
    for k in range(RINGS_PER_CAP):  # cap at a, from the pole
        angle = math.pi / 2 * (1 - k / RINGS_PER_CAP)
        rings.append((-radius * math.sin(angle), radius * math.cos(angle), -math.sin(angle)))
    for k in range(CYLINDER_RINGS + 1):
        rings.append((length * k / CYLINDER_RINGS, radius, 0.0))
    for k in range(1, RINGS_PER_CAP + 1):
        angle = math.pi / 2 * k / RINGS_PER_CAP
        rings.append((length + radius * math.sin(angle), radius * math.cos(angle), math.sin(angle)))
    vertices = [(list(a), [-axis[0], -axis[1], -axis[2]], 0.0)]  # pole at a
    for along, ring_radius, normal_axis in rings:
        for s in range(SEGMENTS):
            phi = 2 * math.pi * s / SEGMENTS
            radial = [math.cos(phi) * u[k] + math.sin(phi) * v[k] for k in range(3)]
            position = [a[k] + axis[k] * along + radial[k] * ring_radius for k in range(3)]
            scale = math.sqrt(max(0.0, 1 - normal_axis * normal_axis))
            normal = normalise([radial[k] * scale + axis[k] * normal_axis for k in range(3)])
            t = min(1.0, max(0.0, along / length)) if length > 0 else 0.0
            vertices.append((position, normal, t))
    vertices.append(([b[k] + axis[k] * radius for k in range(3)], list(axis), 1.0))  # pole at b
    triangles = []
    for s in range(SEGMENTS):
        triangles.append((0, 1 + (s + 1) % SEGMENTS, 1 + s))
    for r in range(len(rings) - 1):
        for s in range(SEGMENTS):
            i0, i1 = 1 + r * SEGMENTS + s, 1 + r * SEGMENTS + (s + 1) % SEGMENTS
            j0, j1 = i0 + SEGMENTS, i1 + SEGMENTS
            triangles += [(i0, i1, j1), (i0, j1, j0)]
    last_ring, pole = 1 + (len(rings) - 1) * SEGMENTS, len(vertices) - 1
    for s in range(SEGMENTS):
        triangles.append((pole, last_ring + s, last_ring + (s + 1) % SEGMENTS))
    return vertices, triangles


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalise(a):
    n = math.sqrt(sum(v * v for v in a))
    return [v / n for v in a] if n > 0 else a


def body(names, parents, offsets, end_sites, scale):
    """World rest positions (metres) and the mannequin's vertices, normals, joints, weights and triangles."""
    world = []
    for j, parent in enumerate(parents):
        offset = [value * scale for value in offsets[j]]
        world.append(offset if parent < 0 else [world[parent][k] + offset[k] for k in range(3)])
    tips = [[world[joint][k] + offset[k] * scale for k in range(3)] for joint, offset in end_sites]
    height = max(p[1] for p in world + tips) - min(p[1] for p in world + tips)  # feet to head top
    segments = []  # (joint, start, end)
    children = {j: [c for c, p in enumerate(parents) if p == j] for j in range(len(names))}
    for j in range(len(names)):
        for child in children[j]:
            segments.append((j, world[j], world[child], False))
    for joint, offset in end_sites:
        segments.append((joint, world[joint], [world[joint][k] + offset[k] * scale for k in range(3)], True))
    segments = [segment if len(segment) == 4 else segment + (False,) for segment in segments]
    positions, normals, joints, weights, triangles = [], [], [], [], []
    for joint, start, end, tip in segments:
        # Nothing below the floor: a segment lower than its radius (a foot) is lifted to stand on it, like a shoe
        # around the bones. A tip (head top, finger and toe ends) ends at its End Site, not a radius past it.
        radius = radius_for(names[joint], height)
        start, end = [start[0], max(start[1], radius), start[2]], [end[0], max(end[1], radius), end[2]]
        if tip:
            direction = [end[k] - start[k] for k in range(3)]
            length = math.sqrt(sum(v * v for v in direction))
            if length > 2 * radius:
                end = [end[k] - direction[k] / length * radius for k in range(3)]
        vertices, faces = capsule(start, end, radius)
        base = len(positions)
        parent = parents[joint]
        for position, normal, t in vertices:
            positions.append(position)
            normals.append(normal)
            blend = 0.5 * max(0.0, 1.0 - t / BLEND_FRACTION) if parent >= 0 else 0.0
            if blend > 0.0:
                joints.append((joint, parent, 0, 0))
                weights.append((1.0 - blend, blend, 0.0, 0.0))
            else:
                joints.append((joint, 0, 0, 0))
                weights.append((1.0, 0.0, 0.0, 0.0))
        triangles += [(base + a, base + b, base + c) for a, b, c in faces]
    return world, positions, normals, joints, weights, triangles


def glb(name, names, parents, offsets, world, positions, normals, joints, weights, triangles, scale, colour):
    binary = bytearray()
    views, accessors = [], []

    def add(data, target=None):
        while len(binary) % 4:
            binary.append(0)
        view = {"buffer": 0, "byteOffset": len(binary), "byteLength": len(data)}
        if target:
            view["target"] = target
        binary.extend(data)
        views.append(view)
        return len(views) - 1

    def accessor(view, component, count, kind, **extra):
        accessors.append(dict(bufferView=view, componentType=component, count=count, type=kind, **extra))
        return len(accessors) - 1

    f32 = lambda values: struct.pack("<%df" % len(values), *values)
    position_values = [c for p in positions for c in p]
    mins = [min(p[k] for p in positions) for k in range(3)]
    maxs = [max(p[k] for p in positions) for k in range(3)]
    position = accessor(add(f32(position_values), 34962), 5126, len(positions), "VEC3", min=mins, max=maxs)
    normal = accessor(add(f32([c for n in normals for c in n]), 34962), 5126, len(normals), "VEC3")
    joint = accessor(add(struct.pack("<%dH" % (4 * len(joints)), *[c for j in joints for c in j]), 34962), 5123, len(joints), "VEC4")
    weight = accessor(add(f32([c for w in weights for c in w]), 34962), 5126, len(weights), "VEC4")
    index_values = [i for t in triangles for i in t]
    index_type, index_format = (5123, "H") if len(positions) < 65536 else (5125, "I")
    indices = accessor(add(struct.pack("<%d%s" % (len(index_values), index_format), *index_values), 34963), index_type, len(index_values), "SCALAR")
    inverse_binds = []
    for p in world:  # rest rotations are identity: the inverse bind matrix only moves the joint to the origin
        inverse_binds += [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -p[0], -p[1], -p[2], 1]
    inverse_bind = accessor(add(f32(inverse_binds)), 5126, len(world), "MAT4")

    nodes = []
    for j, joint_name in enumerate(names):
        node = {"name": joint_name, "translation": [round(v * scale, 9) for v in offsets[j]]}
        kids = [c for c, p in enumerate(parents) if p == j]
        if kids:
            node["children"] = kids
        nodes.append(node)
    nodes.append({"name": name + "_body", "mesh": 0, "skin": 0})
    document = {
        "asset": {"version": "2.0", "generator": "kumite scripts/make_character_bodies.py"},
        "scene": 0,
        "scenes": [{"name": name, "nodes": [0, len(nodes) - 1]}],
        "nodes": nodes,
        "meshes": [{"name": name + "_body", "primitives": [{
            "attributes": {"POSITION": position, "NORMAL": normal, "JOINTS_0": joint, "WEIGHTS_0": weight},
            "indices": indices, "material": 0, "mode": 4}]}],
        "materials": [{"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(colour), "metallicFactor": 0.0,
                                                               "roughnessFactor": 0.7}}],
        "skins": [{"name": name, "joints": list(range(len(names))), "skeleton": 0, "inverseBindMatrices": inverse_bind}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": 0}],
    }
    while len(binary) % 4:
        binary.append(0)
    document["buffers"][0]["byteLength"] = len(binary)
    text = json.dumps(document, separators=(",", ":"), sort_keys=True).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(binary), b"BIN\0") + bytes(binary))


def main():
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "characters")
    for name in sorted(COLOURS):
        path = os.path.join(folder, name + ".bvh")
        names, parents, offsets, end_sites = read_bvh(path)
        scale = unit_of(path)
        world, positions, normals, joints, weights, triangles = body(names, parents, offsets, end_sites, scale)
        data = glb(name, names, parents, offsets, world, positions, normals, joints, weights, triangles, scale, COLOURS[name])
        out = os.path.join(folder, name + ".glb")
        with open(out + ".tmp", "wb") as stream:
            stream.write(data)
        os.replace(out + ".tmp", out)
        print("%s: %d joints, %d vertices, %d triangles, %d bytes" % (out, len(names), len(positions), len(triangles), len(data)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
