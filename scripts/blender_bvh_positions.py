"""Joint world positions of a BVH capture, as computed by Blender's own BVH importer.

Run inside Blender (3.x), e.g.:

    blender -b --factory-startup --python scripts/blender_bvh_positions.py -- \
        IN.bvh OUT.json [--frames N] [--frame-list 0-29,-1]

The capture is imported as an armature with the stock importer (io_anim_bvh) using the
same settings as File > Import > Motion Capture (.bvh) would with: global_scale 1.0,
rotate_mode 'NATIVE', axis_forward '-Z', axis_up 'Y', use_fps_scale False, frame_start 1.
For every requested BVH frame (0-based MOTION row) the scene is set to the matching
Blender frame (frame_start + row) and the world-space head of every pose bone
(armature.matrix_world @ pose_bone.head) is taken, the importer's Y-up -> Z-up axis
conversion is undone, and the result is written - in the BVH file's own axes and length
unit (no unit scaling at all) - as

    {"joint_names": [...], "frames": {"0": [[x, y, z], ...], ...}, ...}

with joints in BVH file order (ROOT/JOINT order; End Sites excluded).  Extra keys:
"blender_names" (bone names, which can differ: spaces joined with '_', duplicates
renamed), "frame_count", "frame_time", "unit": "file", "source".

The installed importer opens the file with mode 'rU', which Python 3.11 rejects; rather
than touching the system file, this script loads a patched in-memory copy of the module.

Options (after "--"):
  --frames N          only the first N frames (default: every frame)
  --frame-list LIST   explicit 0-based frames, e.g. "0-29,100,-1" (negative = from the end);
                      combined with --frames when both are given
  --frame-start F     Blender frame of BVH row 0 (default 1, as the importer's default)
  --no-trim           import the whole motion even when only a few frames are asked for
                      (by default the MOTION block handed to Blender is cut down to the
                      requested rows, which keeps the import fast on long captures; every
                      row is imported independently, so the positions are the same)
Exit status: 0 on success, 2 on bad usage / unreadable input, 3 when the importer fails.
"""

import importlib.util
import json
import os
import re
import sys
import tempfile
import traceback

import bpy
from bpy_extras.io_utils import axis_conversion

IMPORTER_NAME = "kumite_patched_import_bvh"


def fail(code, msg):
    sys.stderr.write("blender_bvh_positions: %s\n" % msg)
    sys.stderr.flush()
    # sys.exit inside --python does not always stop Blender with the right status;
    # os._exit does (after flushing our streams).
    sys.stdout.flush()
    os._exit(code)


def script_args():
    argv = sys.argv
    return argv[argv.index("--") + 1:] if "--" in argv else []


def parse_args(args):
    opts = {"frames": None, "frame_list": None, "frame_start": 1, "trim": True}
    pos = []
    i = 0
    while i < len(args):
        a = args[i]
        if a in ("--frames", "--frame-list", "--frame-start"):
            if i + 1 >= len(args):
                fail(2, "%s needs a value" % a)
            v = args[i + 1]
            i += 2
            if a == "--frames":
                try:
                    opts["frames"] = int(v)
                except ValueError:
                    fail(2, "--frames takes a number of frames, got %r" % v)
                if opts["frames"] < 0:
                    fail(2, "--frames must be >= 0")
            elif a == "--frame-list":
                opts["frame_list"] = v
            else:
                opts["frame_start"] = max(1, int(v))
            continue
        if a == "--no-trim":
            opts["trim"] = False
        elif a in ("-h", "--help"):
            print(__doc__)
            os._exit(0)
        elif a.startswith("--"):
            fail(2, "unknown option %s" % a)
        else:
            pos.append(a)
        i += 1
    if len(pos) != 2:
        fail(2, "usage: blender -b --factory-startup --python blender_bvh_positions.py -- "
                "IN.bvh OUT.json [--frames N] [--frame-list LIST]")
    opts["input"], opts["output"] = pos
    return opts


def load_patched_importer():
    """The stock io_anim_bvh.import_bvh module with open(..., 'rU') replaced by 'r'."""
    path = None
    try:
        import io_anim_bvh  # the add-on package (its __init__ only registers operators)
        path = os.path.join(os.path.dirname(io_anim_bvh.__file__), "import_bvh.py")
    except Exception:
        for base in bpy.utils.script_paths():
            cand = os.path.join(base, "addons", "io_anim_bvh", "import_bvh.py")
            if os.path.isfile(cand):
                path = cand
                break
    if not path or not os.path.isfile(path):
        fail(3, "cannot find Blender's io_anim_bvh/import_bvh.py")
    with open(path, encoding="utf-8") as fh:
        src = fh.read()
    src = src.replace("open(file_path, 'rU')", "open(file_path, 'r')")
    src = src.replace("'rU'", "'r'")
    spec = importlib.util.spec_from_loader(IMPORTER_NAME, loader=None, origin=path)
    mod = importlib.util.module_from_spec(spec)
    mod.__file__ = path
    exec(compile(src, path, "exec"), mod.__dict__)
    sys.modules[IMPORTER_NAME] = mod
    return mod


def read_lines(path):
    with open(path, "r", encoding="utf-8", errors="replace", newline=None) as fh:
        lines = fh.read().splitlines()
    if len(lines) == 1 and "\r" in lines[0]:
        lines = lines[0].split("\r")
    return lines


def scan_bvh(lines):
    """Joint names in file order and the index of the first motion row line.

    Also returns the joint-name line indices, so duplicates can be renamed.
    """
    joints = []  # (line index, name as in file)
    motion_line = None
    rot_problems = []
    last_joint = None
    for i, line in enumerate(lines):
        toks = line.split()
        if not toks:
            continue
        key = toks[0].lower()
        if key in ("root", "joint"):
            name = " ".join(toks[1:])
            joints.append((i, name))
            last_joint = name
        elif key == "channels" and last_joint is not None:
            rots = [t for t in toks[2:] if t.lower().endswith("rotation")]
            if len(rots) not in (0, 3):
                rot_problems.append("%s (%d rotation channels)" % (last_joint, len(rots)))
        elif key == "motion":
            motion_line = i
            break
    if motion_line is None:
        fail(2, "no MOTION section")
    # Header: "Frames: n" then "Frame Time: dt", then rows (blank lines are skipped by
    # the importer as well).
    j = motion_line + 1
    header = 0
    while j < len(lines) and header < 2:
        if lines[j].split():
            header += 1
        j += 1
    rows = [k for k in range(j, len(lines)) if lines[k].split()]
    return joints, motion_line, j, rows, rot_problems


def parse_frame_spec(spec, n):
    out = []
    for part in spec.split(","):
        part = part.strip()
        if not part:
            continue
        m = re.fullmatch(r"(-?\d+)-(-?\d+)", part)
        if m:
            a, b = int(m.group(1)), int(m.group(2))
            a = a + n if a < 0 else a
            b = b + n if b < 0 else b
            out.extend(range(a, b + 1))
        else:
            v = int(part)
            out.append(v + n if v < 0 else v)
    return out


def main():
    opts = parse_args(script_args())
    in_path = os.path.abspath(opts["input"])
    if not os.path.isfile(in_path):
        fail(2, "no such file: %s" % in_path)

    lines = read_lines(in_path)
    joints, motion_line, first_row_line, row_lines, rot_problems = scan_bvh(lines)
    if rot_problems:
        # The stock importer cannot express these (KeyError on the rotation order, and
        # a missing channel would read line[-1]).
        fail(3, "Blender's BVH importer cannot handle joints with 1 or 2 rotation channels: "
                + ", ".join(rot_problems))
    n_rows = len(row_lines)
    bvh_names = [nm for _, nm in joints]

    # Frames wanted.
    wanted = list(range(n_rows))
    if opts["frame_list"] is not None:
        wanted = parse_frame_spec(opts["frame_list"], n_rows)
    if opts["frames"] is not None:
        if opts["frame_list"] is None:
            wanted = list(range(min(opts["frames"], n_rows)))
        else:
            wanted = sorted(set(wanted) | set(range(min(opts["frames"], n_rows))))
    bad = [f for f in wanted if f < 0 or f >= n_rows]
    if bad:
        fail(2, "frame(s) %s out of range (file has %d motion rows)" % (bad[:5], n_rows))
    wanted = sorted(set(wanted))

    # The importer keys its nodes by name: duplicate names would silently drop joints
    # (and then crash).  Give duplicates unique names in a temporary copy; spaces in
    # names are joined with '_' by the importer itself, which we mirror for lookup.
    seen = {}
    new_lines = list(lines)
    importer_names = []
    for (li, name) in joints:
        base = "_".join(name.split())
        nm = base
        k = seen.get(base, 0)
        while nm in importer_names:
            k += 1
            nm = "%s.dup%03d" % (base, k)
        seen[base] = k
        importer_names.append(nm)
        if nm != base:
            toks = new_lines[li].split()
            indent = new_lines[li][:len(new_lines[li]) - len(new_lines[li].lstrip())]
            new_lines[li] = "%s%s %s" % (indent, toks[0], nm)

    # Rows handed to Blender: optionally only the wanted ones (row r of the trimmed file
    # is BVH frame wanted[r]).
    if opts["trim"] and len(wanted) < n_rows:
        kept = [row_lines[f] for f in wanted]
        row_of_frame = {f: r for r, f in enumerate(wanted)}
    else:
        kept = row_lines
        row_of_frame = {f: f for f in wanted}
    header = new_lines[:motion_line]
    body = ["MOTION", "Frames: %d" % len(kept)]
    # keep the original Frame Time line
    ft = None
    for k in range(motion_line + 1, first_row_line):
        t = lines[k].split()
        if t and t[0].lower() == "frame":
            ft = lines[k].strip()
    body.append(ft if ft else "Frame Time: 0.0333333")
    tmpdir = tempfile.mkdtemp(prefix="kumite_blender_")
    tmp_bvh = os.path.join(tmpdir, "in.bvh")
    with open(tmp_bvh, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(header + body) + "\n")
        for k in kept:
            fh.write(lines[k] + "\n")

    imp = load_patched_importer()
    context = bpy.context
    scene = context.scene
    # Empty scene (factory startup has a cube, camera, light).
    for ob in list(scene.objects):
        bpy.data.objects.remove(ob, do_unlink=True)

    frame_start = opts["frame_start"]
    global_matrix = axis_conversion(from_forward="-Z", from_up="Y").to_4x4()
    try:
        bvh_nodes, bvh_frame_time, bvh_frame_count = imp.read_bvh(
            context, tmp_bvh, rotate_mode="NATIVE", global_scale=1.0)
        arm_ob = imp.bvh_node_dict2armature(
            context, "bvh", bvh_nodes, bvh_frame_time,
            rotate_mode="NATIVE", frame_start=frame_start, IMPORT_LOOP=False,
            global_matrix=global_matrix, use_fps_scale=False)
    except Exception:
        traceback.print_exc()
        fail(3, "Blender's BVH importer failed on %s" % in_path)

    nodes_in_order = imp.sorted_nodes(bvh_nodes)
    if [n.name for n in nodes_in_order] != importer_names:
        fail(3, "importer joint list differs from the file's: %r vs %r"
             % ([n.name for n in nodes_in_order][:10], importer_names[:10]))

    pose_bones = arm_ob.pose.bones
    bone_names = []
    for nm in importer_names:
        if nm in pose_bones:
            bone_names.append(nm)
            continue
        # Blender truncates names to 63 bytes.
        cut = nm.encode("utf-8")[:63].decode("utf-8", "ignore")
        if cut in pose_bones and cut not in bone_names:
            bone_names.append(cut)
            continue
        fail(3, "no pose bone for joint %r" % nm)
    if len(pose_bones) != len(importer_names):
        fail(3, "armature has %d bones, file has %d joints" % (len(pose_bones), len(importer_names)))

    inv_global = global_matrix.inverted()
    frames_out = {}
    for f in wanted:
        scene.frame_set(frame_start + row_of_frame[f])
        mw = arm_ob.matrix_world
        pts = []
        for bn in bone_names:
            p = inv_global @ (mw @ pose_bones[bn].head)
            pts.append([float(p.x), float(p.y), float(p.z)])
        frames_out[str(f)] = pts

    doc = {
        "source": in_path,
        "unit": "file",
        "joint_names": bvh_names,
        "blender_names": bone_names,
        "frame_count": n_rows,
        "frame_time": bvh_frame_time,
        "frame_start": frame_start,
        "frames": frames_out,
    }
    out_path = os.path.abspath(opts["output"])
    with open(out_path, "w", encoding="utf-8") as fh:
        json.dump(doc, fh)
    try:
        os.remove(tmp_bvh)
        os.rmdir(tmpdir)
    except OSError:
        pass
    print("blender_bvh_positions: %d joints x %d frames -> %s"
          % (len(bone_names), len(wanted), out_path))


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except Exception:
        traceback.print_exc()
        fail(3, "unexpected error")
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)
