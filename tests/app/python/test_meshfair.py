# SPDX-License-Identifier: MIT
# Copyright 2026 the MeshFair authors.
#
# The meshfair Python module against meshfair-cli: the same positions bit for bit on the
# same inputs, the Session's steps, (V, F) in both face layouts, and errors as Python
# exceptions with the core's messages. Run by ctest (python_module) with PYTHONPATH at the
# built module, MESHFAIR_CLI and MESHFAIR_ASSETS set.
import json
import os
import re
import subprocess
import threading
import time
import warnings

import numpy as np
import pytest

import meshfair

CLI = os.environ["MESHFAIR_CLI"]
ASSETS = os.environ["MESHFAIR_ASSETS"]
BUNNY = os.path.join(ASSETS, "bunny.obj")
DENOISE = os.path.join(ASSETS, "recipes", "denoise.json")


def cli_smooth(tmp_path, mesh_path, recipe_text, name="out.obj"):
    """meshfair-cli smooth's positions (read back exactly: OBJ holds shortest round-trip
    decimals)."""
    recipe = tmp_path / "recipe.json"
    recipe.write_text(recipe_text)
    out = tmp_path / name
    subprocess.run([CLI, "smooth", str(mesh_path), "-o", str(out), "--recipe", str(recipe),
                    "-q"], check=True)
    return meshfair.read(str(out))[0]


def noisy_bunny(tmp_path):
    path = tmp_path / "noisy.obj"
    subprocess.run([CLI, "noise", BUNNY, "-o", str(path), "--sigma", "0.3", "--seed", "1"],
                   check=True, stdout=subprocess.DEVNULL)
    return path


def quad_grid(n=12):
    """An open n x n grid of quads with a bump: (V, F) with F an (m, 4) array."""
    ij = np.array([(i, j) for j in range(n + 1) for i in range(n + 1)], dtype=float)
    z = 0.3 * np.exp(-((ij[:, 0] - n / 2) ** 2 + (ij[:, 1] - n / 2) ** 2) / 8)
    V = np.column_stack([ij, z])
    F = np.array([(j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
                   (j + 1) * (n + 1) + i) for j in range(n) for i in range(n)])
    return V, F


def test_smooth_gives_the_cli_positions_bit_for_bit(tmp_path):
    path = noisy_bunny(tmp_path)
    V, F = meshfair.read(str(path))
    text = open(DENOISE).read()
    expected = cli_smooth(tmp_path, path, text)
    # The recipe as JSON text and as the dict json.loads gives.
    assert np.array_equal(meshfair.smooth(V, F, text), expected)
    assert np.array_equal(meshfair.smooth(V, F, json.loads(text)), expected)
    assert not np.array_equal(expected, V)


def test_polygon_faces_as_offsets_and_indices(tmp_path):
    # A quad grid with one quad split in two triangles: mixed sizes come back as
    # (offsets, indices) and smooth as the CLI smooths the same file.
    V, F = quad_grid()
    faces = [list(f) for f in F[1:]] + [[F[0][0], F[0][1], F[0][2]], [F[0][0], F[0][2], F[0][3]]]
    offsets = np.cumsum([0] + [len(f) for f in faces])
    indices = np.concatenate(faces)
    path = tmp_path / "mixed.off"
    meshfair.write(str(path), V, (offsets, indices))
    V2, F2 = meshfair.read(str(path))
    assert isinstance(F2, tuple)
    assert np.array_equal(F2[0], offsets) and np.array_equal(F2[1], indices)
    assert np.array_equal(V2, V)
    recipe = {"iterations": 30, "soft": {"vertices": [0, 12], "mu": 2.0}}
    expected = cli_smooth(tmp_path, path, json.dumps(recipe))
    assert np.array_equal(meshfair.smooth(V2, F2, recipe), expected)


def test_uniform_faces_read_as_one_array_and_round_trip_in_every_format(tmp_path):
    V, F = quad_grid(5)
    for ext in ("obj", "off", "ply"):
        path = tmp_path / ("grid." + ext)
        meshfair.write(str(path), V, F)
        V2, F2 = meshfair.read(str(path))
        assert F2.shape == F.shape and np.array_equal(F2, F), ext
        assert np.array_equal(V2, V), ext


def test_arrays_as_trimesh_gives_them(tmp_path):
    # trimesh hands float64 (n, 3) vertices and int64 (m, 3) faces; float32 and int32
    # arrays, and non-contiguous ones, are converted.
    V, F = meshfair.read(BUNNY)
    expected = meshfair.smooth(V, F, {"iterations": 4})
    assert np.array_equal(meshfair.smooth(V, F.astype(np.int32), {"iterations": 4}), expected)
    assert np.array_equal(meshfair.smooth(np.asfortranarray(V), F, {"iterations": 4}), expected)
    assert meshfair.smooth(V.astype(np.float32), F, {"iterations": 4}).dtype == np.float64


def test_session_steps_give_smooth_positions(tmp_path):
    V, F = meshfair.read(BUNNY)
    recipe = {"iterations": 7, "hard": {"vertices": [0, 100]}, "centroid": {"faces": "all"}}
    s = meshfair.Session(V, F, recipe)
    before = s.energy()
    assert set(before) == {"edge", "soft", "centroid", "normal", "normal_smoothing",
                           "normal_soft", "bending", "total"}
    assert np.array_equal(s.positions, V)
    s.step(3)
    s.step()
    s.step(3)
    assert np.array_equal(s.positions, meshfair.smooth(V, F, recipe))
    assert s.energy()["total"] < before["total"]


def test_session_hard_targets_move_the_pins():
    V, F = meshfair.read(BUNNY)
    s = meshfair.Session(V, F, {"hard": {"vertices": [0, 100]}})
    targets = V[[0, 100]] + [0.0, 0.0, 0.05]
    s.set_hard_targets(targets)
    assert np.array_equal(s.positions[[0, 100]], targets)
    s.step(5)
    assert np.array_equal(s.positions[[0, 100]], targets)
    with pytest.raises(ValueError, match="expected 6 values"):
        s.set_hard_targets(V[:3])
    with pytest.raises(ValueError, match="finite"):
        s.set_hard_targets(np.full((2, 3), np.nan))


def test_session_solve_gives_the_direct_minimizer_again_after_new_targets(tmp_path):
    V, F = meshfair.read(BUNNY)
    recipe = {"method": "direct", "hard": {"vertices": [0, 100]}}
    s = meshfair.Session(V, F, recipe)
    first = s.solve()
    assert first["iterations"] <= 2 and first["stopped_by_tolerance"]
    assert first["relative_gradient"][-1] <= 1e-12
    # New targets: the session's factorization solves again, and gives what a new
    # session (a new factorization) gives from the same start.
    targets = V[[0, 100]] + [0.0, 0.0, 0.05]
    s.set_hard_targets(targets)
    start = s.positions
    again = s.solve()
    assert again["relative_gradient"][-1] <= 1e-12
    assert np.array_equal(s.positions[[0, 100]], targets)
    fresh = meshfair.Session(start, F, {"method": "direct", "hard": {"vertices": [0, 100]}})
    fresh.solve()
    assert np.allclose(s.positions, fresh.positions, rtol=0, atol=1e-9)
    assert not np.allclose(s.positions, start, rtol=0, atol=1e-6)


def test_errors_are_python_exceptions_with_the_core_messages(tmp_path):
    V, F = meshfair.read(BUNNY)
    with pytest.raises(ValueError, match=r"soft\.vertices\[1\]: vertex 99999 is out of range"):
        meshfair.smooth(V, F, {"soft": {"vertices": [1, 99999]}})
    with pytest.raises(ValueError, match="unknown key"):
        meshfair.smooth(V, F, '{"iterationz": 3}')
    with pytest.raises(ValueError, match="index 5 is 34835, not a vertex of V"):
        bad = F.copy()
        bad[1, 2] = len(V)
        meshfair.smooth(V, bad)
    with pytest.raises(ValueError, match="must be an \\(n, 3\\) array"):
        meshfair.smooth(V[:, :2], F)
    with pytest.raises(ValueError, match="non-finite|finite"):
        W = V.copy()
        W[7, 1] = np.inf
        meshfair.smooth(W, F)
    bad_file = tmp_path / "bad.obj"
    bad_file.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
    with pytest.raises(ValueError, match=r"bad\.obj:4:7: vertex index 4 is past the last"):
        meshfair.read(str(bad_file))
    # A write that cannot happen raises OSError (a missing directory) or ValueError (an
    # unknown format), and an existing file stays whole.
    with pytest.raises(OSError, match="missing"):
        meshfair.write(str(tmp_path / "missing" / "out.obj"), V, F)
    target = tmp_path / "kept.xyz"
    target.write_text("the old file\n")
    with pytest.raises(ValueError, match="unknown mesh format"):
        meshfair.write(str(target), V, F)
    assert target.read_text() == "the old file\n"


def test_what_a_reader_skips_is_warned_of(tmp_path):
    # The notes meshfair-cli prints reach Python as meshfair.ReadNote warnings, and so do
    # the attributes (V, F) cannot hold.
    path = tmp_path / "textured.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nl 1 2\n")
    with pytest.warns(meshfair.ReadNote) as caught:
        V, F = meshfair.read(str(path))
    assert F.shape == (1, 3)
    messages = [str(w.message) for w in caught]
    assert any(re.search(r"textured\.obj': ignored 1 line", m) for m in messages)
    assert any(re.search(r"textured\.obj': not returned .*: texture coordinates: 3 vt on 3 corners", m)
               for m in messages)
    assert issubclass(meshfair.ReadNote, UserWarning)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a file without notes warns of nothing
        meshfair.read(BUNNY)


def newell(V, F):
    """Each face's Newell vector (triangles: its area vector times 2)."""
    P = V[F]
    return np.cross(P, np.roll(P, -1, axis=1)).sum(axis=1)


def turned_over(V, W, F):
    """Faces of (V, F) whose normals W turns more than 90 degrees, among those within 60
    degrees of the surface around them in V (the Newell vectors of the faces sharing a vertex
    with them, each once per shared vertex): docs/math.md, "Faces never turned over"."""
    own = newell(V, F)
    at_vertex = np.zeros_like(V)
    for k in range(F.shape[1]):
        np.add.at(at_vertex, F[:, k], own)
    around = at_vertex[F].sum(axis=1)
    agree = (own * around).sum(axis=1) > 0.5 * np.linalg.norm(own, axis=1) * np.linalg.norm(
        around, axis=1)
    return agree & ((own * newell(W, F)).sum(axis=1) <= 0)


def test_every_preset_takes_an_open_scan_and_says_how_its_volume_is_kept(tmp_path):
    # The noisy bunny's base cut away: an open scan (its unused vertices kept, isolated).
    path = noisy_bunny(tmp_path)
    V, F = meshfair.read(str(path))
    height = V[F].mean(axis=1)[:, 1]
    F = F[height > height.min() + 0.25 * (height.max() - height.min())]
    scan = tmp_path / "scan.obj"
    meshfair.write(str(scan), V, F)
    # fair-region fairs a region: on the whole scan, nothing holds it, and it says so.
    fair = open(os.path.join(ASSETS, "recipes", "fair-region.json")).read()
    with pytest.raises(ValueError, match="is held by nothing"):
        meshfair.smooth(V, F, fair)
    for name in ["denoise", "relax", "combined"]:
        text = open(os.path.join(ASSETS, "recipes", name + ".json")).read()
        with pytest.warns(meshfair.SolverNote) as caught:
            W = meshfair.smooth(V, F, text)
        assert any("capped by fans from the loops' centroids" in str(w.message) for w in caught)
        assert np.array_equal(W, cli_smooth(tmp_path, scan, text, name + ".obj"))
        turned = turned_over(V, W, F)
        assert not turned.any(), (name, int(turned.sum()))
        with warnings.catch_warnings(record=True) as kept:
            warnings.simplefilter("always")
            session = meshfair.Session(V, F, text)
        assert session.notes == [str(w.message) for w in kept]
    assert issubclass(meshfair.SolverNote, UserWarning)


def test_a_long_smooth_lets_other_python_threads_run():
    # docs/python.md: smooth releases the GIL. This thread notes the time at every turn of
    # a loop while another thread smooths the bunny; were the GIL held during the smooth,
    # the loop would stop for all of it (its longest pause would be the smooth's time).
    V, F = meshfair.read(BUNNY)
    done = threading.Event()
    took = {}

    def work():
        start = time.perf_counter()
        meshfair.smooth(V, F, {"iterations": 3000})
        took["smooth"] = time.perf_counter() - start
        done.set()

    worker = threading.Thread(target=work)
    last, longest_pause = time.perf_counter(), 0.0  # before start(), which waits for the GIL
    worker.start()
    while True:
        stop = done.is_set()  # before the time: a pause that ends the loop counts too
        now = time.perf_counter()
        longest_pause = max(longest_pause, now - last)
        last = now
        if stop:
            break
    worker.join()
    assert took["smooth"] > 0.1
    assert longest_pause < took["smooth"] / 4
