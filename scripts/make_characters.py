#!/usr/bin/env python3
"""Writes the shipped characters, data/characters/NAME.bvh: T-pose rest frames (facing +Z, Y up, left = +X) of
five made-up bodies whose sizes, proportions, joint counts and naming schemes differ on purpose.

Run from the repository root: python3 scripts/make_characters.py. Lengths below are centimetres.
"""
import os

# name: scheme, unit, proportions (cm)
CHARACTERS = {
    # A child-sized fighter: big head, short legs. Bandai-style names.
    "kid": dict(scheme="bandai", unit="cm", ankle=6.0, foot=11.0, toe=5.0, shin=31.0, thigh=33.0, hip_half=7.0,
                hip_drop=5.0, spine=[11.0, 10.0], neck=[7.0], head=25.0, clavicle=(3.0, 9.0), upper_arm=20.0,
                forearm=18.0, hand=12.0),
    # Average build, CMU-style names with a hip joint, three spine and two neck joints.
    "scout": dict(scheme="cmu", unit="cm", ankle=7.5, foot=13.0, toe=6.0, shin=39.0, thigh=41.0, hip_half=9.0,
                  hip_drop=8.0, spine=[10.0, 10.0, 10.0], neck=[5.0, 5.0], head=24.0, clavicle=(2.0, 15.0),
                  upper_arm=27.0, forearm=24.0, hand=17.0),
    # A long-armed brawler, Mixamo-style names (mixamorig:), three spine joints.
    "brawler": dict(scheme="mixamo", unit="cm", ankle=8.0, foot=15.0, toe=7.0, shin=44.0, thigh=45.0, hip_half=10.0,
                    hip_drop=7.0, spine=[11.0, 12.0, 12.0], neck=[9.0], head=25.0, clavicle=(3.0, 17.0),
                    upper_arm=35.0, forearm=32.0, hand=20.0),
    # A 2.1 m giant with a long torso and short legs, Unreal-style names, written in metres.
    "giant": dict(scheme="unreal", unit="m", ankle=9.0, foot=18.0, toe=8.0, shin=46.0, thigh=48.0, hip_half=13.0,
                  hip_drop=8.0, spine=[18.0, 18.0, 21.0], neck=[12.0], head=28.0, clavicle=(3.0, 20.0),
                  upper_arm=36.0, forearm=32.0, hand=21.0),
    # A long-legged runner with a short torso. Bandai-style names.
    "runner": dict(scheme="bandai", unit="cm", ankle=8.0, foot=15.0, toe=7.0, shin=57.0, thigh=57.0, hip_half=9.0,
                   hip_drop=6.0, spine=[11.0, 11.0], neck=[8.0], head=24.0, clavicle=(2.0, 16.0), upper_arm=31.0,
                   forearm=27.0, hand=19.0),
}

NAMES = {
    "bandai": dict(pelvis="Hips", hip="", thigh="UpperLeg_{S}", shin="LowerLeg_{S}", foot="Foot_{S}", toe="Toes_{S}",
                   spine=["Spine", "Chest"], neck=["Neck"], head="Head", clavicle="Shoulder_{S}",
                   upper_arm="UpperArm_{S}", forearm="LowerArm_{S}", hand="Hand_{S}", side={"L": "L", "R": "R"}),
    "cmu": dict(pelvis="Hips", hip="{S}HipJoint", thigh="{Side}UpLeg", shin="{Side}Leg", foot="{Side}Foot",
                toe="{Side}ToeBase", spine=["LowerBack", "Spine", "Spine1"], neck=["Neck", "Neck1"], head="Head",
                clavicle="{Side}Shoulder", upper_arm="{Side}Arm", forearm="{Side}ForeArm", hand="{Side}Hand",
                side={"L": "L", "R": "R"}),
    "mixamo": dict(pelvis="mixamorig:Hips", hip="", thigh="mixamorig:{Side}UpLeg", shin="mixamorig:{Side}Leg",
                   foot="mixamorig:{Side}Foot", toe="mixamorig:{Side}ToeBase",
                   spine=["mixamorig:Spine", "mixamorig:Spine1", "mixamorig:Spine2"], neck=["mixamorig:Neck"],
                   head="mixamorig:Head", clavicle="mixamorig:{Side}Shoulder", upper_arm="mixamorig:{Side}Arm",
                   forearm="mixamorig:{Side}ForeArm", hand="mixamorig:{Side}Hand", side={"L": "L", "R": "R"}),
    "unreal": dict(pelvis="pelvis", hip="", thigh="thigh_{s}", shin="calf_{s}", foot="foot_{s}", toe="ball_{s}",
                   spine=["spine_01", "spine_02", "spine_03"], neck=["neck_01"], head="head", clavicle="clavicle_{s}",
                   upper_arm="upperarm_{s}", forearm="lowerarm_{s}", hand="hand_{s}", side={"L": "l", "R": "r"}),
}


class Joint:
    def __init__(self, name, offset, children=None, end=None):
        self.name, self.offset, self.children, self.end = name, offset, children or [], end


def side_name(pattern, side):
    return pattern.format(S=side, s=side.lower(), Side="Left" if side == "L" else "Right")


def build(c, names):
    sign = {"L": 1.0, "R": -1.0}
    leg_chains = []
    for side in ("L", "R"):
        x = sign[side] * c["hip_half"]
        toe = Joint(side_name(names["toe"], side), (0.0, -0.8 * c["ankle"], c["foot"]), end=(0.0, -0.2 * c["ankle"], c["toe"]))
        foot = Joint(side_name(names["foot"], side), (0.0, -c["shin"], 0.0), [toe])
        shin = Joint(side_name(names["shin"], side), (0.0, -c["thigh"], 0.0), [foot])
        if names["hip"]:
            thigh = Joint(side_name(names["thigh"], side), (x, -c["hip_drop"], 0.0), [shin])
            leg_chains.append(Joint(side_name(names["hip"], side), (0.0, 0.0, 0.0), [thigh]))
        else:
            leg_chains.append(Joint(side_name(names["thigh"], side), (x, -c["hip_drop"], 0.0), [shin]))
    arm_chains = []
    for side in ("L", "R"):
        s = sign[side]
        hand = Joint(side_name(names["hand"], side), (s * c["forearm"], 0.0, 0.0), end=(s * c["hand"], 0.0, 0.0))
        forearm = Joint(side_name(names["forearm"], side), (s * c["upper_arm"], 0.0, 0.0), [hand])
        upper = Joint(side_name(names["upper_arm"], side), (s * c["clavicle"][1], 0.0, 0.0), [forearm])
        arm_chains.append(Joint(side_name(names["clavicle"], side), (s * 1.0, c["clavicle"][0], 0.0), [upper]))
    head = Joint(names["head"], (0.0, c["neck"][-1], 0.0), end=(0.0, c["head"], 0.0))
    node = head
    for name, length in reversed(list(zip(names["neck"], [c["spine"][-1]] + c["neck"][:-1]))):
        node = Joint(name, (0.0, length, 0.0), [node])
    chest_children = [node] + arm_chains
    spine_lengths = [0.0] + c["spine"][:-1]
    chest = Joint(names["spine"][-1], (0.0, spine_lengths[-1], 0.0), chest_children)
    node = chest
    for name, length in reversed(list(zip(names["spine"][:-1], spine_lengths[:-1]))):
        node = Joint(name, (0.0, length if length else 0.0, 0.0), [node])
    pelvis_height = c["ankle"] + c["shin"] + c["thigh"] + c["hip_drop"]
    # The first spine joint sits a little above the pelvis.
    node.offset = (0.0, 2.0, 0.0)
    return Joint(names["pelvis"], (0.0, pelvis_height, 0.0), leg_chains + [node]), pelvis_height


def write(root, pelvis_height, unit, path):
    scale = 0.01 if unit == "m" else 1.0
    lines = ["HIERARCHY"]
    channels = []

    def number(v):
        text = "%.6f" % (v * scale)
        return text.rstrip("0").rstrip(".") if "." in text else text

    def emit(joint, depth, is_root):
        pad = "\t" * depth
        lines.append(pad + ("ROOT " if is_root else "JOINT ") + joint.name)
        lines.append(pad + "{")
        lines.append(pad + "\tOFFSET " + " ".join(number(v) for v in joint.offset))
        if is_root:
            lines.append(pad + "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation")
            channels.extend([0.0, pelvis_height * scale, 0.0, 0.0, 0.0, 0.0])
        else:
            lines.append(pad + "\tCHANNELS 3 Zrotation Xrotation Yrotation")
            channels.extend([0.0, 0.0, 0.0])
        for child in joint.children:
            emit(child, depth + 1, False)
        if joint.end is not None:
            lines.append(pad + "\tEnd Site")
            lines.append(pad + "\t{")
            lines.append(pad + "\t\tOFFSET " + " ".join(number(v) for v in joint.end))
            lines.append(pad + "\t}")
        lines.append(pad + "}")

    emit(root, 0, True)
    lines += ["MOTION", "Frames: 1", "Frame Time: 0.0333333", " ".join(("%.6f" % v).rstrip("0").rstrip(".") for v in channels)]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "characters")
    os.makedirs(folder, exist_ok=True)
    for name, c in CHARACTERS.items():
        root, pelvis_height = build(c, NAMES[c["scheme"]])
        write(root, pelvis_height, c["unit"], os.path.join(folder, name + ".bvh"))
        print("wrote", os.path.join("data", "characters", name + ".bvh"))


if __name__ == "__main__":
    main()
