#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets: one small valid (and a few edge-case)
input per format, into DIR/<target>/. Usage: make_seeds.py DIR"""
import json
import os
import struct
import sys

out = sys.argv[1]


def seed(target, name, data):
    os.makedirs(os.path.join(out, target), exist_ok=True)
    with open(os.path.join(out, target, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# PLY: ASCII, binary little and big endian, with normals and an extra element.
ply_ascii = """ply
format ascii 1.0
comment seed
element vertex 4
property float x
property float y
property float z
property float nx
property float ny
property float nz
element face 2
property list uchar int vertex_indices
element edge 1
property int vertex1
property int vertex2
end_header
0 0 0 0 0 1
1 0 0 0 0 1
1 1 0 0 0 1
0 1 0 0 0 1
3 0 1 2
4 0 1 2 3
0 1
"""
seed("fuzz_ply", "ascii.ply", ply_ascii)
for fmt, tag in (("<", "binary_little_endian"), (">", "binary_big_endian")):
    head = ("ply\nformat %s 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar uint vertex_index\nend_header\n" % tag).encode()
    body = b"".join(struct.pack(fmt + "fff", *p) for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0)))
    body += struct.pack(fmt + "BIII", 3, 0, 1, 2)
    seed("fuzz_ply", tag + ".ply", head + body)
# Regressions: inputs a fuzz run once stopped on, kept so every run tries them again.
seed("fuzz_ply", "regress_empty_element_huge_count.ply",  # hung: 2^64-1 items of no properties
     "ply\nformat binary_little_endian 1.0\nelement junk 18446744073709551615\nelement vertex 1\n"
     "property float x\nproperty float y\nproperty float z\nend_header\n" + "\0" * 12)

# OBJ: vertices, normals, texture coordinates, faces with every index form, negatives.
seed("fuzz_obj", "quad.obj", "# seed\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
     "f 1 2 3\nf 1//1 3//1 4//1\nf 1/1/1 2/1/1 3/1/1\nf -4 -3 -2 -1\ng group\no obj\ns off\n")
seed("fuzz_obj", "bad.obj", "v 0 0\nf 1 2 9\n")

# Camera path JSON.
seed("fuzz_camera_path", "path.json", json.dumps({"keyframes": [
    {"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 30},
    {"frame": 60, "eye": [5, 0, 0]}]}))
seed("fuzz_camera_path", "empty.json", '{"keyframes": []}')

# Config JSON: the keys are option names without dashes.
seed("fuzz_config", "config.json", json.dumps({
    "method": "hybrid", "size": "320x240", "alpha": 0.1, "frames": 10, "edge-fill": "gray",
    "background": "gray", "kernel": "hann", "normalize": "off", "up": "0,0,1"}))
seed("fuzz_config", "nested.json", '{"size": [1, 2], "alpha": "x", "unknown": {}}')

# Viewer event logs.
seed("fuzz_event_log", "session.log", """# flowsurf events 1
at 0 set method hybrid
at 10 mouse-down left shift
at 10 mouse-move 400 300
at 25 mouse-up left
at 30 scroll -2
at 31 key r
at 90 screenshot out/a.png
at 91 resize 640 480
at 92 quit
""")

# Option values: first byte picks the parser (see fuzz_options.cpp).
for i, text in enumerate(["640x480", "1, 0, 0.5", "#1c1c21", "0.25", "isa", "on", "12", "1e9", "nan"]):
    seed("fuzz_options", "value%d" % i, bytes([i % 5 + 5 * i]) + text.encode())
