"""sweep's Python module: arrays as views (shapes, dtypes, no copies, lifetimes), curves evaluated
at numpy parameters, edits that save one line, errors with their place, renders and exports."""
import gc

import numpy as np
import pytest

import sweep


def test_a_surface_is_float32_and_uint32_arrays_in_the_vbo_layout(wineglass):
    doc = sweep.load(wineglass)
    (glass,) = doc.surfaces()
    assert (glass.name, glass.kind) == ("wineglass", "srev")
    assert glass.positions.shape == (glass.vertex_count, 3) and glass.positions.dtype == np.float32
    assert glass.normals.shape == glass.positions.shape and glass.normals.dtype == np.float32
    assert glass.indices.shape == (glass.triangle_count, 3) and glass.indices.dtype == np.uint32
    assert glass.indices.max() < glass.vertex_count
    np.testing.assert_allclose(np.linalg.norm(glass.normals, axis=1), 1.0, atol=1e-5)
    assert not glass.positions.flags.writeable


def test_arrays_are_views_of_the_documents_memory_not_copies(wineglass):
    doc = sweep.load(wineglass)
    a = doc.surface("wineglass").positions
    b = doc.surfaces()[0].positions
    assert np.shares_memory(a, b)  # two requests, one buffer
    assert a.ctypes.data == b.ctypes.data
    assert not isinstance(a.base, np.ndarray)  # the base is the owner's capsule, not a copy
    curve = doc.curve("profile")
    assert np.shares_memory(curve.positions, curve.frames)  # positions are a strided view of the frames


def test_a_view_keeps_its_memory_alive_after_the_document_and_through_edits(wineglass):
    doc = sweep.load(wineglass)
    positions = doc.surface("wineglass").positions
    before = positions.copy()
    doc.set_point("profile", 6, (-1.06, 1.1))
    np.testing.assert_array_equal(positions, before)  # the old view still shows the old mesh
    assert not np.array_equal(doc.surface("wineglass").positions, before)  # the new one moved
    del doc
    gc.collect()
    np.testing.assert_array_equal(positions, before)


def test_a_curve_evaluates_at_a_numpy_array_of_parameters_with_orthonormal_frames(wineglass):
    doc = sweep.load(wineglass)
    low, high = doc.curve_range("profile")
    t = np.linspace(low, high, 10001)
    positions, frames = doc.evaluate_curve("profile", t)
    assert positions.shape == (t.size, 3) and frames.shape == (t.size, 4, 3)
    T, N, B = frames[:, 1], frames[:, 2], frames[:, 3]
    np.testing.assert_allclose(np.einsum("ij,ij->i", T, N), 0.0, atol=1e-9)
    np.testing.assert_allclose(np.cross(T, N), B, atol=1e-9)  # right-handed
    np.testing.assert_allclose(B, np.tile([0.0, 0.0, 1.0], (t.size, 1)), atol=1e-12)  # a 2D curve: B = +z
    np.testing.assert_allclose(doc.curve_points("profile", t), positions, atol=1e-12)
    samples = doc.curve("profile")
    np.testing.assert_allclose(samples.positions[[0, -1]], positions[[0, -1]], atol=1e-12)
    with pytest.raises(sweep.SwpError, match="outside curve 'profile'"):
        doc.curve_points("profile", np.array([high + 1.0]))


def test_an_edit_saves_exactly_one_line_and_undo_gives_the_file_back(wineglass):
    original = wineglass.read_text()
    doc = sweep.load(wineglass)
    assert not doc.modified
    doc.set_point("profile", 6, (-1.06, 1.1))
    assert doc.modified and doc.can_undo
    doc.save(wineglass)
    after = wineglass.read_text()
    changed = [(a, b) for a, b in zip(original.splitlines(), after.splitlines()) if a != b]
    assert len(original.splitlines()) == len(after.splitlines())
    assert changed == [("[-1.164785 1.105511]", "[-1.060000 1.100000]")]
    assert doc.undo() and doc.text() == original
    assert doc.redo() and doc.text() == after


def test_a_bad_edit_changes_nothing_and_says_why(wineglass):
    doc = sweep.load(wineglass)
    with pytest.raises(sweep.SwpError, match="point 99 is out of range: curve 'profile' has 26 points"):
        doc.set_point("profile", 99, (0.0, 0.0))
    with pytest.raises(sweep.SwpError, match="unknown field 'colour'"):
        doc.set_field("profile", "colour", 1.0)
    assert not doc.modified and not doc.can_undo
    doc.set_field("profile", "steps", 4)
    assert doc.curve("profile").positions.shape[0] < 185


def test_errors_carry_file_line_and_column(tmp_path):
    with pytest.raises(sweep.SwpError) as bad:
        sweep.parse("bez2 a 4 4\n[0 0] [1 oops]\n", "bad.swp")
    assert (bad.value.file, bad.value.line, bad.value.column) == ("bad.swp", 2, 10)
    assert str(bad.value) == "bad.swp:2:10: expected a number (y of point 2 of 4), found 'oops'"
    with pytest.raises(sweep.SwpError) as missing:
        sweep.load(tmp_path / "none.swp")
    assert missing.value.line == 0 and "none.swp" in str(missing.value)


def test_render_is_a_picture_of_the_model(wineglass):
    doc = sweep.load(wineglass)
    image = doc.render(160, 120)
    assert image.shape == (120, 160, 4) and image.dtype == np.uint8
    colours = np.unique(image[..., :3].reshape(-1, 3), axis=0)
    assert len(colours) > 50  # shaded, not a flat background
    assert not np.array_equal(image[60, 80], image[0, 0])  # the glass at the centre, background in the corner
    assert doc._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    same = sweep.compare_images(image, doc.render(160, 120))
    assert same["matches"] and same["summary"] == "identical"


def test_render_refuses_a_colour_it_does_not_know(wineglass):
    doc = sweep.load(wineglass)
    with pytest.raises(sweep.SwpError, match="color must be material, gaussian, mean, normals or uv, not 'red'"):
        doc.render(16, 12, color="red")
    assert doc.render(16, 12, color="normals").shape == (12, 16, 4)


def test_export_writes_what_sweep_export_writes(wineglass, tmp_path):
    files = sweep.load(wineglass).export(tmp_path / "out", "obj")
    assert [f.name for f in files] == ["out_wineglass.obj"]  # no material clause: no MTL
    text = (tmp_path / "out_wineglass.obj").read_text()
    assert text.count("\nv ") == 16650


OPEN_TUBE = "circ ring 16 0.3\nbez3 path 4 4\n[0 0 0]\n[0 1 0]\n[0 2 0]\n[0 3 0]\ngcyl tube ring path\n"


def test_check_print_names_the_surface_its_line_and_where(tmp_path):
    found = sweep.parse(OPEN_TUBE, "tube.swp").check_print(height=30)
    assert [(f.check, f.object, f.line, f.fails) for f in found] == [("open", "tube", 7, True)]
    assert found[0].message == (
        "tube.swp:7:1: warning: surface 'tube' is open: 2 holes (32 boundary edges); a printer needs a closed solid")
    assert 0.0 <= found[0].where[1] <= 3.0  # model coordinates, on the tube
    assert sweep.parse(OPEN_TUBE.replace("path\n", "path caps\n"), "t.swp").check_print(height=30) == []
    thin = sweep.parse(OPEN_TUBE.replace("path\n", "path caps\n"), "t.swp").check_print(height=30, min_wall=7)
    assert [f.check for f in thin] == ["thin-wall"]
    with pytest.raises(sweep.SwpError, match="thinnest wall is a positive number"):
        sweep.parse(OPEN_TUBE, "t.swp").check_print(min_wall=0)


def test_export_3mf_and_one_merged_stl(wineglass, tmp_path):
    doc = sweep.load(wineglass)
    assert [f.name for f in doc.export(tmp_path / "g", "3mf", height=80)] == ["g.3mf"]
    assert [f.name for f in doc.export(tmp_path / "m", "stl", height=80, merge=True)] == ["m.stl"]
    stl = (tmp_path / "m.stl").read_bytes()
    corners = np.frombuffer(stl[84:], dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]))
    heights = corners["v"][..., 2]
    assert abs(heights.min()) < 1e-4 and abs(heights.max() - 80.0) < 1e-3  # z up, on the plate, 80 mm tall


def test_check_snapshot_names_the_objects_that_changed(wineglass, tmp_path):
    doc = sweep.load(wineglass)
    first = sweep.check_snapshot(doc, tmp_path / "refs", "glass")
    assert (first.status, first.passed) == ("new", False)
    assert sweep.check_snapshot(doc, tmp_path / "refs", "glass").status == "pass"
    doc.set_point("profile", 6, (-1.214785, 1.105511))
    moved = sweep.check_snapshot(doc, tmp_path / "refs", "glass")
    assert (moved.status, moved.passed) == ("FAIL", False)
    assert moved.changed_objects == ["profile", "wineglass"]
    assert any(line.startswith("wineglass: ") and "its mesh moved up to 0.03" in line for line in moved.objects)
