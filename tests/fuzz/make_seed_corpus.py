#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the seed corpora of the fuzz targets into tests/fuzz/corpus/<target>/ (docs/fuzzing.md).

Small real inputs, each a valid one the target accepts: shipped scenes, the shipped OBJ meshes and
one cube in each other format assimp reads for the loader (ASCII and binary STL and PLY, glTF with
an embedded buffer, GLB), pose recordings, opentrack datagrams and ABI structs. Deterministic: run
it again and nothing changes.
"""
import base64
import json
import pathlib
import shutil
import struct

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"

SCENES = ["wall_push", "ball_drop", "hull_rest", "chair", "notepad", "tracked_notepad", "staircase",
          "checks/spinning_rod", "checks/incline_roll", "checks/momentum_pair", "checks/thin_wall",
          "checks/stack10"]

# A unit cube: 8 corners, 12 outward (counter-clockwise) triangles.
CUBE_V = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)]
CUBE_T = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
          (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
MESH_FORMAT = {"obj": 0, "stl": 1, "ply": 2, "gltf": 3, "glb": 4}   # mesh_import_fuzz.cpp


def normal(t):
    a, b, c = (CUBE_V[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def stl_ascii():
    out = ["solid cube"]
    for t in CUBE_T:
        out.append("facet normal %g %g %g" % normal(t))
        out.append(" outer loop")
        out += [" vertex %g %g %g" % CUBE_V[i] for i in t]
        out += [" endloop", "endfacet"]
    return ("\n".join(out + ["endsolid cube"]) + "\n").encode()


def stl_binary():
    out = b"cube".ljust(80, b"\0") + struct.pack("<I", len(CUBE_T))
    for t in CUBE_T:
        out += struct.pack("<3f", *normal(t)) + b"".join(struct.pack("<3f", *CUBE_V[i]) for i in t) + b"\0\0"
    return out


def ply(binary):
    head = ["ply", "format binary_little_endian 1.0" if binary else "format ascii 1.0",
            "element vertex %d" % len(CUBE_V), "property float x", "property float y", "property float z",
            "element face %d" % len(CUBE_T), "property list uchar int vertex_indices", "end_header"]
    out = ("\n".join(head) + "\n").encode()
    if binary:
        out += b"".join(struct.pack("<3f", *v) for v in CUBE_V)
        out += b"".join(struct.pack("<B3i", 3, *t) for t in CUBE_T)
    else:
        out += ("".join("%g %g %g\n" % v for v in CUBE_V) + "".join("3 %d %d %d\n" % t for t in CUBE_T)).encode()
    return out


def gltf_parts():
    positions = b"".join(struct.pack("<3f", *v) for v in CUBE_V)
    indices = b"".join(struct.pack("<3H", *t) for t in CUBE_T)
    data = positions + indices
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "cube"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(CUBE_V), "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5123, "count": 3 * len(CUBE_T), "type": "SCALAR"}],
    }
    return doc, data


def gltf():
    doc, data = gltf_parts()
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return json.dumps(doc, separators=(",", ":")).encode()


def glb():
    doc, data = gltf_parts()
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


HEADER = "time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons"


def recording(rows):
    return HEADER + "\n" + "".join(",".join(str(c) for c in r) + "\n" for r in rows)


def pose_sample(sensor, flags, position, orientation, velocity=(0, 0, 0), angular=(0, 0, 0)):
    return (struct.pack("<IIQqIIQ", 6, 1, 144, 1_000_000, sensor, flags, 7) +
            struct.pack("<13d", *position, *orientation, *velocity, *angular))


def force_command(sensor, force, torque):
    return struct.pack("<IIQqII", 8, 1, 80, 1_000_000, sensor, 0) + struct.pack("<6d", *force, *torque)


def write(target, name, data):
    path = CORPUS / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data if isinstance(data, bytes) else data.encode())


def main():
    for target in ["scene_loader_fuzz", "mesh_import_fuzz", "pose_csv_fuzz", "opentrack_datagram_fuzz",
                   "plugin_validation_fuzz"]:
        shutil.rmtree(CORPUS / target, ignore_errors=True)
    for scene in SCENES:
        write("scene_loader_fuzz", scene.replace("/", "_") + ".json", (ROOT / "scenes" / (scene + ".json")).read_bytes())

    obj = bytes([MESH_FORMAT["obj"]])
    for mesh in ["chair", "staircase"]:
        write("mesh_import_fuzz", mesh + ".obj", obj + (ROOT / "scenes" / "meshes" / (mesh + ".obj")).read_bytes())
    cube_obj = "".join("v %g %g %g\n" % v for v in CUBE_V) + "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in CUBE_T)
    write("mesh_import_fuzz", "cube.obj", obj + cube_obj.encode())
    write("mesh_import_fuzz", "cube_ascii.stl", bytes([MESH_FORMAT["stl"]]) + stl_ascii())
    write("mesh_import_fuzz", "cube_binary.stl", bytes([MESH_FORMAT["stl"]]) + stl_binary())
    write("mesh_import_fuzz", "cube_ascii.ply", bytes([MESH_FORMAT["ply"]]) + ply(False))
    write("mesh_import_fuzz", "cube_binary.ply", bytes([MESH_FORMAT["ply"]]) + ply(True))
    write("mesh_import_fuzz", "cube.gltf", bytes([MESH_FORMAT["gltf"]]) + gltf())
    write("mesh_import_fuzz", "cube.glb", bytes([MESH_FORMAT["glb"]]) + glb())

    # First line: extra replay options; then the recording (pose_csv_fuzz.cpp).
    s = 0.7071067811865476
    two_sensors = [(0, 0, 0.1, 0.2, 1.2, 0, 0, 0, 1, 0), (0, 1, -0.5, 0, 1.0, 0, 0, s, s, 1),
                   (10_000_000, 0, 0.11, 0.2, 1.2, 0, 0, 0.0499791692706783, 0.99875026039496628, 3),
                   (10_000_000, 1, -0.5, 0.01, 1.0, 0, 0, s, s, 0),
                   (20_000_000, 0, 0.12, 0.21, 1.19, 0, 0, 0.099833416646828155, 0.99500416527802582, 0)]
    write("pose_csv_fuzz", "two_sensors.txt", "\n" + recording(two_sensors))
    write("pose_csv_fuzz", "two_sensors_loop.txt", "loop=1,offset=0.25\n" + recording(two_sensors))
    write("pose_csv_fuzz", "one_sample_crlf.txt", "\n" + recording([(5, 0, 1, 2, 3, 0, 0, 0, 1, 0)]).replace("\n", "\r\n"))
    write("pose_csv_fuzz", "large_values.txt",
          "\n" + recording([(-4_000_000_000_000_000_000, 0, 1e5, -1e5, 0, 1, 0, 0, 0, 18446744073709551615),
                            (4_000_000_000_000_000_000, 0, -1e5, 1e5, 0, 0, 1, 0, 0, 0)]))

    # Six doubles: TX, TY, TZ [cm], yaw, pitch, roll [deg] (opentrack_datagram.h).
    for name, values in [("centre", (0, 0, 0, 0, 0, 0)), ("turned", (10, 20, -30, 90, 0, 0)),
                         ("tilted", (-1.5, 2.25, 60, -170, 45.5, 30)), ("gimbal", (0, 0, 0, 10, 90, -10))]:
        write("opentrack_datagram_fuzz", name + ".bin", struct.pack("<6d", *values))
    write("opentrack_datagram_fuzz", "short.bin", struct.pack("<6d", 1, 2, 3, 4, 5, 6)[:47])

    # sensor, sensor count, mode (bit 0: fix header, bit 1: force), then the struct (plugin_validation_fuzz.cpp).
    full = 0x3F
    write("plugin_validation_fuzz", "pose_valid.bin", struct.pack("<IIB", 0, 1, 0) +
          pose_sample(0, full, (0.1, 0.2, 1.2), (0, 0, 0.38268343236508978, 0.92387953251128674), (0.5, 0, 0), (0, 0, 1)))
    write("plugin_validation_fuzz", "pose_position_only.bin", struct.pack("<IIB", 2, 3, 1) +
          pose_sample(2, 0x2, (1, 2, 3), (0, 0, 0, 0)))
    write("plugin_validation_fuzz", "pose_unnormalised.bin", struct.pack("<IIB", 1, 4, 0) +
          pose_sample(1, 0x3, (0, 0, 0), (0, 0, 0, 1.005)))
    write("plugin_validation_fuzz", "force_valid.bin", struct.pack("<IIB", 0, 1, 2) + force_command(0, (1, -2, 3), (0, 0.1, 0)))
    write("plugin_validation_fuzz", "force_no_sensors.bin", struct.pack("<IIB", 0, 0, 3) + force_command(0, (0, 0, -9.81), (0, 0, 0)))

    # The inputs behind the findings of docs/fuzzing.md, kept so that every run replays them.
    write("pose_csv_fuzz", "finding_span_beyond_int64.txt",
          "loop=1\n" + recording([(-8_000_000_000_000_000_000, 0, 0, 0, 0, 0, 0, 0, 1, 0),
                                  (4_000_000_000_000_000_000, 0, 12, 0, 0, 0, 0, 0, 1, 0)]))
    write("pose_csv_fuzz", "finding_position_1e308.txt",
          "\n" + recording([(0, 0, "1e308", 0, 0, 0, 0, 0, 1, 0), (10, 0, "-1e308", 0, 0, 0, 0, 0, 1, 0)]))
    write("mesh_import_fuzz", "finding_ply_without_end_header.ply", bytes([MESH_FORMAT["ply"]]) +
          b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
          b"0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
    chair = (ROOT / "scenes" / "meshes" / "chair.obj").read_text().split("\n")
    chair[9:11] = ["v 0.2250450000"]   # a vertex with one coordinate: assimp leaks (tests/fuzz/lsan.supp)
    write("mesh_import_fuzz", "finding_obj_one_coordinate.obj", obj + "\n".join(chair).encode())
    scene = json.loads((ROOT / "scenes" / "checks" / "spinning_rod.json").read_text())
    rod = scene["bodies"][1]["shape"]["box"]
    rod["half_ext\nts"] = rod.pop("half_extents")   # a key with a line break: the message stayed one line?
    write("scene_loader_fuzz", "finding_line_break_in_key.json", json.dumps(scene, indent=1))


if __name__ == "__main__":
    main()
