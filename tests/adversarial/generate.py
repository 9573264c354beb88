#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the adversarial input files of tests/adversarial/ (maintainer tool; the files
# are committed, so neither CI nor the tests run this). Each file is built here per its
# format's rules, byte for byte, so binary files are reviewable as code. The expected
# outcome of every file (exit code and message, or the output's hash) lives in
# expected.tsv, reviewed by hand; this script only writes inputs.
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = {}


def put(path, data):
    if isinstance(data, str):
        data = data.encode("latin-1")
    assert path not in FILES, path
    FILES[path] = data


TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
QUAD = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"

# ---- OBJ ---------------------------------------------------------------------------
put("obj/empty.obj", "")
put("obj/comments_only.obj", "# nothing but a comment\n# and another\n")
put("obj/vertex_missing_z.obj", TRI + "v 1 1\nf 1 2 3\n")
put("obj/truncated_mid_number.obj", TRI + "f 1 2 3\nv 0.5 0.5 1e")
put("obj/truncated_face.obj", TRI + "f 1 2")
put("obj/index_zero.obj", TRI + "f 0 1 2\n")
put("obj/negative_past_start.obj", TRI + "f -1 -2 -4\n")
put("obj/index_past_end.obj", TRI + "f 1 2 4\n")
put("obj/index_20_digits.obj", TRI + "f 1 2 99999999999999999999\n")
put("obj/coordinate_1e400.obj", "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n")
put("obj/coordinate_nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")
put("obj/coordinate_inf.obj", "v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n")
put("obj/coordinate_abc.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n")
put("obj/index_abc.obj", TRI + "f 1 2 x\n")
put("obj/face_0_vertices.obj", TRI + "f\n")
put("obj/face_1_vertex.obj", TRI + "f 1\n")
put("obj/face_2_vertices.obj", TRI + "f 1 2\n")
put("obj/face_repeated_consecutive.obj", QUAD + "f 1 2 2 3 4\n")
put("obj/face_repeated_pinched.obj", QUAD + "f 1 2 1 3\n")
put("obj/face_collapses_to_2.obj", TRI + "f 1 2 2 1\n")
put("obj/crlf.obj", (QUAD + "f 1 2 3 4\n").replace("\n", "\r\n"))
put("obj/cr_only.obj", (QUAD + "f 1 2 3 4\n").replace("\n", "\r"))
put("obj/bom.obj", b"\xef\xbb\xbf" + (QUAD + "f 1 2 3 4\n").encode())
put("obj/nul_byte.obj", "v 0 0 0\nv 1 0\x00 0\nv 0 1 0\nf 1 2 3\n")
put("obj/no_final_newline.obj", QUAD + "f 1 2 3 4")
put("obj/long_comment_line.obj", "# " + "x" * 65536 + "\n" + TRI + "f 1 2 3\n")
put("obj/long_face_line.obj",
    "".join("v %d %d 0\n" % (i % 100, i // 100) for i in range(2000)) +
    "f " + " ".join(str(i + 1) for i in range(2000)) + "\n")
put("obj/many_tokens_one_line.obj", TRI + "f 1 2 3" + " " * 40000 + "\n" + "v" + " 1" * 20000 + "\n")
put("obj/negative_indices.obj", TRI + "v 1 1 0\nf -4 -3 -1 -2\n")
put("obj/vt_vn_groups_materials.obj",
    "mtllib does-not-exist.mtl\no thing\ng part\nusemtl red\ns 1\n" + QUAD +
    "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/1/1\n")
put("obj/point_cloud.obj", TRI + "v 2 2 2\n")
put("obj/isolated_vertex.obj", TRI + "v 9 9 9\nf 1 2 3\n")
put("obj/lines_and_points.obj", QUAD + "l 1 2\np 3\nf 1 2 3 4\n")
put("obj/unknown_keyword.obj", QUAD + "frobnicate 1 2\nf 1 2 3 4\n")
put("obj/vertex_colour_columns.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n")
put("obj/forward_reference.obj", "f 1 2 3\n" + TRI)
put("obj/binary_garbage.obj", bytes(range(256)) * 4)
# Texture coordinate and normal indices are checked as vertex indices are.
put("obj/vt_index_past_end.obj", TRI + "vt 0 0\nf 1/1 2/1 3/2\n")
put("obj/vn_index_before_start.obj", TRI + "vn 0 0 1\nf 1//1 2//1 3//-2\n")
put("obj/vn_two_values.obj", TRI + "vn 0 1\nf 1 2 3\n")
put("obj/corner_four_indices.obj", TRI + "vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n")
put("obj/vt_some_corners.obj", TRI + "vt 0 0\nf 1/1 2 3/1\n")

# ---- OFF ---------------------------------------------------------------------------
OFF_QUAD = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
put("off/empty.off", "")
# Face colours of different kinds (none, r g b a, an index): noted and not kept.
put("off/face_colours_mixed.off",
    "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3 255 0 0 255\n3 1 2 3 4\n")
put("off/header_only.off", "OFF\n")
put("off/missing_counts.off", "OFF\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n")
put("off/counts_on_header_line.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off/negative_count.off", "OFF\n-3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off/zero_counts.off", "OFF\n0 0 0\n")
put("off/count_1e12.off", "OFF\n1000000000000 1 0\n0 0 0\n")
put("off/count_20_digits.off", "OFF\n99999999999999999999 1 0\n0 0 0\n")
put("off/counts_lie_more_vertices.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
put("off/counts_lie_fewer_faces.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
put("off/counts_lie_more_faces.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
put("off/truncated_mid_vertex.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1")
put("off/truncated_mid_face.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1")
# (a trailing comment makes room, so the byte-count check passes and the face is read)
put("off/face_0_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n# padding\n")
put("off/face_2_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n# padding\n")
put("off/truncated_padded.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n" + " " * 60 + "\n")
put("off/face_size_lies.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n5 0 1 2 3\n")
put("off/face_repeated_index.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n5 0 1 1 2 3\n")
put("off/index_past_end.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")
put("off/index_negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n")
put("off/index_20_digits.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999999999999\n")
put("off/coordinate_1e400.off", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n")
put("off/coordinate_nan.off", "OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n")
put("off/coordinate_inf.off", "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n")
# finite, so accepted; smoothing refuses it (squared distances would overflow)
put("off/coordinate_1e300.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1e300\n3 0 1 2\n")
put("off/coordinate_abc.off", "OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n")
put("off/coff_colour_columns.off",
    "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n")
put("off/face_colour_columns.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 0 0\n")
put("off/comments_everywhere.off",
    "# leading comment\nOFF # header comment\n# counts next\n3 1 0\n0 0 0 # v0\n\n1 0 0\n"
    "# between\n0 1 0\n3 0 1 2 # face\n")
put("off/crlf.off", OFF_QUAD.replace("\n", "\r\n"))
put("off/cr_only.off", OFF_QUAD.replace("\n", "\r"))
put("off/bom.off", b"\xef\xbb\xbf" + OFF_QUAD.encode())
put("off/nul_byte.off", "OFF\n3 1 0\n0 0 0\n1 0 \x00\n0 1 0\n3 0 1 2\n")
put("off/long_line.off", "OFF\n3 1 0\n0 0 0" + " " * 70000 + "\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off/noff_normals.off",
    "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n")
put("off/binary_off.off", b"OFF BINARY\n" + struct.pack(">iii", 3, 1, 0) + b"\x00" * 36)
put("off/no_header_keyword.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off/point_cloud.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")

# ---- PLY ---------------------------------------------------------------------------
def ply_header(fmt, vertices, faces, vertex_props="property double x\nproperty double y\n"
               "property double z\n", face_prop="property list uchar int vertex_indices\n",
               extra=""):
    h = "ply\nformat %s 1.0\n" % fmt
    h += "element vertex %s\n" % vertices + vertex_props
    if faces is not None:
        h += "element face %s\n" % faces + face_prop
    return h + extra + "end_header\n"


PTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]


def ascii_body(points=PTS, faces=((0, 1, 2, 3),)):
    s = "".join("%g %g %g\n" % p for p in points)
    return s + "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)


def binary_body(order, points=PTS, faces=((0, 1, 2, 3),)):
    b = b"".join(struct.pack(order + "ddd", *p) for p in points)
    for f in faces:
        b += struct.pack(order + "B", len(f)) + struct.pack(order + "%di" % len(f), *f)
    return b


ASCII_OK = ply_header("ascii", 4, 1) + ascii_body()
put("ply/empty.ply", "")
put("ply/magic_only.ply", "ply\n")
put("ply/no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n")
put("ply/end_header_misspelled.ply", ASCII_OK.replace("end_header", "end_headr"))
put("ply/end_header_trailing_text.ply", ASCII_OK.replace("end_header", "end_header please"))
put("ply/end_header_no_newline.ply", ply_header("ascii", 0, None)[:-1])
put("ply/unknown_format.ply", ASCII_OK.replace("format ascii", "format binary_middle_endian"))
put("ply/unknown_version.ply", ASCII_OK.replace("ascii 1.0", "ascii 2.0"))
put("ply/missing_z.ply", ply_header("ascii", 3, 1, "property float x\nproperty float y\n")
    + "0 0\n1 0\n0 1\n3 0 1 2\n")
put("ply/count_1e12.ply", ply_header("binary_little_endian", 1000000000000, 0) + "\0" * 24)
put("ply/count_negative.ply", ply_header("ascii", -4, 1) + ascii_body())
put("ply/count_20_digits.ply", ply_header("ascii", "99999999999999999999", 1) + ascii_body())
put("ply/counts_lie_more.ply", ply_header("ascii", 5, 1) + ascii_body())
put("ply/counts_lie_fewer.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((0, 1, 2), (0, 2, 3))))
put("ply/binary_trailing_bytes.ply", ply_header("binary_little_endian", 4, 1) +
    binary_body("<").decode("latin-1") + "TRAILING")
put("ply/binary_trailing_padding.ply", ply_header("binary_little_endian", 4, 1).encode() +
    binary_body("<") + b"\n\0\0\0")
put("ply/truncated_header.ply", ASCII_OK[:30])
put("ply/truncated_vertex_ascii.ply", ply_header("ascii", 4, 1) + "0 0 0\n1 0 0\n1 1")
put("ply/truncated_vertex_binary.ply",
    ply_header("binary_little_endian", 4, 1).encode() + binary_body("<")[:60])
put("ply/truncated_face_binary.ply",
    ply_header("binary_little_endian", 4, 1).encode() + binary_body("<")[:-6])
put("ply/list_count_past_data.ply",
    ply_header("binary_little_endian", 4, 1).encode() + binary_body("<")[:96] + b"\xff" +
    struct.pack("<4i", 0, 1, 2, 3))
put("ply/wrong_endianness.ply",
    ply_header("binary_little_endian", 4, 1).encode() + binary_body(">"))
put("ply/binary_le.ply", ply_header("binary_little_endian", 4, 1).encode() + binary_body("<"))
put("ply/binary_be.ply", ply_header("binary_big_endian", 4, 1).encode() + binary_body(">"))
put("ply/binary_nan.ply", ply_header("binary_little_endian", 4, 1).encode() +
    binary_body("<", points=[(0, 0, 0), (1, float("nan"), 0), (1, 1, 0), (0, 1, 0)]))
put("ply/binary_inf.ply", ply_header("binary_big_endian", 4, 1).encode() +
    binary_body(">", points=[(0, 0, 0), (1, 0, 0), (float("inf"), 1, 0), (0, 1, 0)]))
put("ply/two_vertex_elements.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
    "property float z\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
    "end_header\n0 0 0\n1 1 1\n")
put("ply/coordinate_1e400.ply", ply_header("ascii", 4, 1) + ascii_body().replace("1 1 0", "1 1e400 0"))
put("ply/coordinate_nan.ply", ply_header("ascii", 4, 1) + ascii_body().replace("1 1 0", "1 nan 0"))
put("ply/coordinate_abc.ply", ply_header("ascii", 4, 1) + ascii_body().replace("1 1 0", "1 abc 0"))
put("ply/index_20_digits.ply", ply_header("ascii", 4, 1) +
    ascii_body().replace("4 0 1 2 3", "4 0 1 2 99999999999999999999"))
put("ply/index_past_end.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((0, 1, 4),)))
put("ply/index_negative.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((0, -1, 2),)))
put("ply/face_0_vertices.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((),)))
put("ply/face_2_vertices.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((0, 1),)))
put("ply/face_repeated_index.ply", ply_header("ascii", 4, 1) + ascii_body(faces=((0, 1, 1, 2, 3),)))
put("ply/property_before_element.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n")
put("ply/unknown_property_type.ply",
    ASCII_OK.replace("property double z", "property quaternion z"))
put("ply/list_count_float.ply",
    ASCII_OK.replace("list uchar int", "list float int"))
put("ply/crlf.ply", ASCII_OK.replace("\n", "\r\n"))
put("ply/cr_only.ply", ASCII_OK.replace("\n", "\r"))
put("ply/bom.ply", b"\xef\xbb\xbf" + ASCII_OK.encode())
put("ply/nul_in_ascii_body.ply", ply_header("ascii", 4, 1) + ascii_body().replace("1 1 0", "1 \x00 0"))
put("ply/comments_obj_info_extra_element.ply",
    "ply\nformat ascii 1.0\ncomment made by hand\nobj_info generated\n" +
    ply_header("ascii", 4, 1, extra="element edge 1\nproperty int vertex1\nproperty int vertex2\n")
    .split("format ascii 1.0\n", 1)[1] + ascii_body() + "0 1\n")
put("ply/vertex_index_alias_uint.ply",
    ply_header("binary_little_endian", 4, 1, face_prop="property list uint8 uint32 vertex_index\n")
    .encode() + binary_body("<"))
put("ply/long_line.ply", ply_header("ascii", 4, 1) + ascii_body().replace("0 0 0\n", "0 0 0" + " " * 70000 + "\n", 1))
put("ply/point_cloud.ply", ply_header("ascii", 4, None) + ascii_body(faces=()))
# Triangle strips (Stanford's range scans): one list per row, -1 between strips.
STRIPS = "element tristrips 1\nproperty list int int vertex_indices\n"
put("ply/tristrips_ascii.ply", ply_header("ascii", 4, None, extra=STRIPS) +
    ascii_body(faces=()) + "9 0 1 3 2 -1 0 1 1 2\n")
for name, order, fmt in (("le", "<", "binary_little_endian"), ("be", ">", "binary_big_endian")):
    strip = (0, 1, 3, 2, -1, 0, 1, 1, 2)
    put("ply/tristrips_binary_%s.ply" % name,
        ply_header(fmt, 4, None, extra=STRIPS).encode() + binary_body(order, faces=()) +
        struct.pack(order + "i", len(strip)) + struct.pack(order + "%di" % len(strip), *strip))
put("ply/tristrips_index_past_end.ply", ply_header("ascii", 4, None, extra=STRIPS) +
    ascii_body(faces=()) + "4 0 1 2 4\n")
put("ply/tristrips_index_negative.ply", ply_header("ascii", 4, None, extra=STRIPS) +
    ascii_body(faces=()) + "4 0 1 -5 2\n")
put("ply/tristrips_only_restarts.ply", ply_header("ascii", 4, None, extra=STRIPS) +
    ascii_body(faces=()) + "3 -1 -1 -1\n")
put("ply/tristrips_uint_restart.ply",
    ply_header("ascii", 4, None,
               extra="element tristrips 1\nproperty list uchar uint vertex_indices\n") +
    ascii_body(faces=()) + "7 0 1 2 4294967295 0 2 3\n")
put("ply/tristrips_and_faces.ply", ply_header("ascii", 4, 1, extra=STRIPS) +
    ascii_body(faces=((0, 1, 2),)) + "3 0 2 3\n")
# Faces with a property of their own and strips, whose triangles have none: noted, dropped.
put("ply/tristrips_and_face_property.ply",
    ply_header("ascii", 4, 1, face_prop="property list uchar int vertex_indices\n"
               "property uchar flags\n", extra=STRIPS) +
    ascii_body(faces=()) + "3 0 1 2 7\n3 0 2 3\n")
# Attributes that are NaN or infinite (a scanner's missing values) are kept; coordinates
# that are not finite are refused.
put("ply/attribute_nan_ascii.ply",
    ply_header("ascii", 4, 1, vertex_props="property double x\nproperty double y\n"
               "property double z\nproperty float confidence\n") +
    "0 0 0 nan\n1 0 0 -inf\n1 1 0 inf\n0 1 0 0.5\n4 0 1 2 3\n")

# ---- STL ---------------------------------------------------------------------------
def stl_binary(triangles, header=b"binary STL written by hand", count=None, attr=0):
    h = header.ljust(80, b"\0")[:80]
    b = h + struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        b += struct.pack("<3f", 0, 0, 1)
        for p in t:
            b += struct.pack("<3f", *p)
        b += struct.pack("<H", attr)
    return b


TRIS = [((0, 0, 0), (1, 0, 0), (1, 1, 0)), ((0, 0, 0), (1, 1, 0), (0, 1, 0))]


def stl_ascii(triangles=TRIS, name="square", end=True):
    s = "solid %s\n" % name
    for t in triangles:
        s += "  facet normal 0 0 1\n    outer loop\n"
        s += "".join("      vertex %s %s %s\n" % p for p in t)
        s += "    endloop\n  endfacet\n"
    return s + ("endsolid %s\n" % name if end else "")


put("stl/empty.stl", "")
put("stl/binary.stl", stl_binary(TRIS))
put("stl/binary_starting_with_solid.stl", stl_binary(TRIS, header=b"solid square"))
put("stl/binary_zero_triangles.stl", stl_binary([]))
put("stl/binary_count_too_high.stl", stl_binary(TRIS, count=3))
put("stl/binary_count_too_low.stl", stl_binary(TRIS, count=1))
put("stl/binary_count_max_in_tiny_file.stl", stl_binary(TRIS, count=0xFFFFFFFF))
put("stl/binary_solid_header_wrong_count.stl", stl_binary(TRIS, header=b"solid square", count=7))
put("stl/binary_truncated_header.stl", stl_binary(TRIS)[:50])
put("stl/binary_nan.stl", stl_binary([((0, 0, 0), (float("nan"), 0, 0), (1, 1, 0))]))
put("stl/binary_degenerate_facet.stl", stl_binary([((0, 0, 0), (0, 0, 0), (1, 1, 0))] + TRIS))
put("stl/binary_attribute_bytes.stl", stl_binary(TRIS, attr=0x7C1F))
put("stl/ascii.stl", stl_ascii())
put("stl/ascii_missing_endsolid.stl", stl_ascii(end=False))
put("stl/ascii_truncated_in_facet.stl", stl_ascii()[:120])
put("stl/ascii_solid_only.stl", "solid\n")
put("stl/ascii_two_vertices.stl", stl_ascii([((0, 0, 0), (1, 0, 0))]))
put("stl/ascii_four_vertices.stl", stl_ascii([((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0))]))
put("stl/ascii_coordinate_1e400.stl", stl_ascii([((0, 0, 0), ("1e400", 0, 0), (1, 1, 0))]))
put("stl/ascii_coordinate_nan.stl", stl_ascii([((0, 0, 0), ("nan", 0, 0), (1, 1, 0))]))
put("stl/ascii_coordinate_abc.stl", stl_ascii([((0, 0, 0), ("abc", 0, 0), (1, 1, 0))]))
put("stl/ascii_crlf.stl", stl_ascii().replace("\n", "\r\n"))
put("stl/ascii_cr_only.stl", stl_ascii().replace("\n", "\r"))
put("stl/ascii_bom.stl", b"\xef\xbb\xbf" + stl_ascii().encode())
put("stl/ascii_nul_byte.stl", stl_ascii().replace("endloop\n  endfacet\nendsolid", "endl\x00op\n  endfacet\nendsolid"))
put("stl/ascii_long_name.stl", stl_ascii(name="n" * 70000))
put("stl/ascii_two_solids.stl", stl_ascii(name="a") + stl_ascii(TRIS[:1], name="b"))
put("stl/ascii_uppercase_keywords.stl", stl_ascii().upper())
put("stl/neither_ascii_nor_binary.stl", "this is not an STL file at all, just words\n" * 3)

# ---- recipes (applied to recipe/square.obj) ------------------------------------------
put("recipe/square.obj", QUAD + "v 0.5 0.5 0.3\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n")
put("recipe/empty.json", "")
put("recipe/not_json.json", "iterations: 10\n")
put("recipe/truncated.json", '{"iterations": 10, "soft": {"mu": ')
put("recipe/unknown_key.json", '{"iterations": 10, "smoothness": 3}\n')
put("recipe/wrong_type.json", '{"iterations": "ten"}\n')
put("recipe/number_1e400.json", '{"lambda": 1e400}\n')
put("recipe/nan_literal.json", '{"lambda": NaN}\n')
put("recipe/negative_iterations.json", '{"iterations": -5}\n')
put("recipe/index_20_digits.json",
    '{"hard": {"vertices": [99999999999999999999]}}\n')
put("recipe/index_past_end.json", '{"hard": {"vertices": [5]}}\n')
put("recipe/deep_nesting.json", '{"hard": {"vertices": ' + "[" * 100000 + "]" * 100000 + "}}\n")
put("recipe/nul_byte.json", '{"iterations": 1\x00}\n')


def main():
    for path, data in FILES.items():
        full = os.path.join(HERE, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "wb") as f:
            f.write(data)
    print("wrote %d files" % len(FILES))


if __name__ == "__main__":
    main()
