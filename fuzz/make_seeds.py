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

# The reader process (fuzz_reader): the first byte picks the format (fuzz_reader.cpp's
# kExtensions), the rest is the file. EnSight Gold geometry (the case file names it):
# ASCII with and without ids, nsided and nfaced blocks, a structured block, C binary in
# both byte orders.
EXT = {e: i for i, e in enumerate([".geo", ".vtk", ".vtp", ".vtu", ".e", ".stl", ".ply", ".obj", ".pvd", ".cgns"])}


def reader_seed(name, data):
    ext = "." + name.rsplit(".", 1)[1]
    seed("fuzz_reader", name, bytes([EXT[ext]]) + (data if isinstance(data, bytes) else data.encode()))


ens_coords = "".join("%g\n" % v for v in (0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0))
ens_head = "square\ngeometry\nnode id %s\nelement id %s\nextents\n0 1\n0 1\n0 0\npart\n1\nsquare\n"
reader_seed("ascii.geo", ens_head % ("off", "off") + "coordinates\n4\n" + ens_coords +
            "tria3\n2\n1 2 3\n1 3 4\nquad4\n1\n1 2 3 4\n")
reader_seed("ascii_ids.geo", ens_head % ("given", "given") + "coordinates\n4\n11\n12\n13\n14\n" +
            ens_coords + "tria3\n2\n7\n8\n1 2 3\n1 3 4\n")
reader_seed("nsided_nfaced.geo", ens_head % ("off", "off") + "coordinates\n4\n" + ens_coords +
            "nsided\n1\n4\n1 2 3 4\nnfaced\n1\n2\n3\n3\n1 2 3\n1 3 4\n")
reader_seed("block.geo", ens_head % ("off", "off") + "block iblanked\n2 2 1\n" + ens_coords + "1\n1\n1\n1\n")


def ens_binary(order, nodes=4, elements=2):
    s80 = lambda t: t.encode().ljust(80, b"\0")
    i32 = lambda *v: struct.pack(order + "%di" % len(v), *v)
    return (s80("C Binary") + s80("square") + s80("geometry") + s80("node id off") + s80("element id off") +
            s80("part") + i32(1) + s80("square") + s80("coordinates") + i32(nodes) +
            struct.pack(order + "12f", 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0) + s80("tria3") + i32(elements) +
            i32(1, 2, 3, 1, 3, 4))


reader_seed("binary_le.geo", ens_binary("<"))
reader_seed("binary_be.geo", ens_binary(">"))
# Legacy .vtk (new and old cell layouts), VTK XML, STL, PLY, OBJ, a .pvd naming a file.
vtk_points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n"
reader_seed("poly.vtk", "# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n" + vtk_points +
            "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 3 6\nCONNECTIVITY vtktypeint64\n0 1 2 0 2 3\n"
            "POINT_DATA 4\nVECTORS U float\n1 0 0 1 0 0 1 0 0 1 0 0\n")
reader_seed("old.vtk", "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + vtk_points +
            "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n9\n")
reader_seed("tri.vtp", '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
            '<PolyData><Piece NumberOfPoints="3" NumberOfPolys="1">\n<PointData><DataArray type="Float32" '
            'Name="U" NumberOfComponents="3" format="ascii">1 0 0 1 0 0 1 0 0</DataArray></PointData>\n'
            '<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0'
            '</DataArray></Points>\n<Polys><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2'
            '</DataArray>\n<DataArray type="Int32" Name="offsets" format="ascii">3</DataArray></Polys>\n'
            '</Piece></PolyData></VTKFile>\n')
reader_seed("tri.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
            "endloop\nendfacet\nendsolid t\n")
reader_seed("tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
reader_seed("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
reader_seed("steps.pvd", '<VTKFile type="Collection"><Collection><DataSet timestep="0" file="input.vtp"/>'
            '</Collection></VTKFile>')
# Regressions: what the retired pre-parsers refused (counts beyond the file that kept VTK's
# EnSight reader looping; old-layout legacy cell lists VTK walked unchecked).
reader_seed("regress_coordinates_beyond_file.geo", ens_head % ("off", "off") +
            "coordinates\n100000000\n" + ens_coords + "tria3\n1\n1 2 3\n")
reader_seed("regress_nsided_missing_line.geo", ens_head % ("off", "off") + "coordinates\n4\n" +
            ens_coords + "nsided\n2\n4\n4\n1 2 3 4\n#\n")
reader_seed("regress_binary_elements_beyond_file.geo", ens_binary(">", elements=5000))
reader_seed("regress_binary_shorter_than_a_string.geo", "C Binary\n")
reader_seed("regress_old_cell_count.vtk", "# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n" +
            vtk_points + "POLYGONS 1 5\n4 0 x 2 3\n")

# Camera path JSON.
seed("fuzz_camera_path", "path.json", json.dumps({"keyframes": [
    {"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 30},
    {"frame": 60, "eye": [5, 0, 0]}]}))
seed("fuzz_camera_path", "empty.json", '{"keyframes": []}')

# Dye files: a list of sources, or {"sources": [...]}.
seed("fuzz_dye_file", "sources.json", json.dumps([
    {"point": [0, 0, 1], "radius": 0.1, "color": "red", "start": 0, "stop": 30},
    {"point": [1, 2, 0], "color": "#00ff00"}, {"point": [0, 1, 0], "color": [0.2, 0.4, 1]}]))
seed("fuzz_dye_file", "object.json", '{"sources": [{"point": [0, 0, 1], "start": 5}]}')

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

# CGNS (HDF5 and ADF, binary): the files fuzz/cgns/ holds, written with Debian's libcgns by
# `flowsurf_make_cgns_cases fuzz/cgns --fuzz-seeds` (tests/cgns): valid cases and hostile
# variants (cut short, a zone, section or BC range of two billion).
cgns_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cgns")
for name in sorted(os.listdir(cgns_dir)):
    if name.endswith(".cgns"):
        with open(os.path.join(cgns_dir, name), "rb") as f:
            reader_seed(name, f.read())

# Option values: first byte picks the parser (see fuzz_options.cpp).
for i, text in enumerate(["640x480", "1, 0, 0.5", "#1c1c21", "0.25", "isa", "on", "12", "1e9", "nan"]):
    seed("fuzz_options", "value%d" % i, bytes([i % 5 + 5 * i]) + text.encode())
