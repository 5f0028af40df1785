"""linemap.Map: cells as numpy arrays, checked; pickling; nav_msgs/OccupancyGrid
fields both ways, against hand-made arrays."""
import array

import numpy as np
import pytest

linemap = pytest.importorskip("linemap")

F, O, U = 0, 1, 2  # the library's Cell values, written out


def test_cell_constants_are_the_library_values():
    assert (linemap.FREE, linemap.OCCUPIED, linemap.UNKNOWN) == (F, O, U)


def test_map_keeps_cells_resolution_and_origin():
    cells = np.array([[F, O, U], [O, O, F]], dtype=np.uint8)
    m = linemap.Map(cells, resolution=0.1, origin=(1.5, -2.0, 0.25))
    assert m.cells is cells  # kept, not copied
    assert (m.width, m.height) == (3, 2)
    assert m.resolution == 0.1
    assert m.origin == (1.5, -2.0, 0.25)
    m.origin = (3, 4)  # yaw defaults to 0
    assert m.origin == (3.0, 4.0, 0.0)


@pytest.mark.parametrize("dtype", [np.int8, np.int64, np.uint16, np.float64, np.bool_])
def test_cells_of_another_dtype_are_refused(dtype):
    with pytest.raises(TypeError, match="uint8"):
        linemap.Map(np.zeros((2, 2), dtype=dtype))


def test_cells_that_are_not_an_array_are_refused():
    with pytest.raises(TypeError, match="numpy array"):
        linemap.Map([[0, 1], [1, 0]])


@pytest.mark.parametrize("shape", [(4,), (2, 2, 2), ()])
def test_cells_of_another_shape_are_refused(shape):
    with pytest.raises(ValueError, match="2-D"):
        linemap.Map(np.zeros(shape, dtype=np.uint8))


def test_cell_values_other_than_the_three_states_are_refused():
    cells = np.zeros((3, 4), dtype=np.uint8)
    cells[2, 1] = 3
    with pytest.raises(ValueError, match=r"Map.cells\[2, 1\] is 3"):
        linemap.Map(cells)
    m = linemap.Map(np.zeros((3, 4), dtype=np.uint8))
    with pytest.raises(ValueError, match=r"\[2, 1\] is 3"):
        m.cells = cells


def test_values_written_into_the_array_later_are_refused_on_use():
    m = linemap.Map(np.zeros((3, 4), dtype=np.uint8))
    m.cells[1, 3] = 200
    with pytest.raises(ValueError, match=r"\[1, 3\] is 200"):
        linemap.encode(m)
    with pytest.raises(ValueError, match=r"\[1, 3\] is 200"):
        m.to_occupancy_grid()


@pytest.mark.parametrize("resolution", [0.0, -0.05, float("nan"), float("inf")])
def test_bad_resolution_is_refused(resolution):
    with pytest.raises(ValueError, match="resolution"):
        linemap.Map(np.zeros((1, 1), dtype=np.uint8), resolution=resolution)


@pytest.mark.parametrize("origin", [(1,), (1, 2, 3, 4), (0, float("nan")), "xy", ("a", "b")])
def test_bad_origin_is_refused(origin):
    with pytest.raises(ValueError, match="origin"):
        linemap.Map(np.zeros((1, 1), dtype=np.uint8), origin=origin)


def test_strided_cells_are_read_as_viewed():
    base = np.array([[F, O, U, O], [U, F, F, O]], dtype=np.uint8)
    view = base[:, ::2]  # columns 0 and 2: not contiguous
    m = linemap.Map(view, resolution=0.05)
    back = linemap.decode(linemap.encode(m))
    assert np.array_equal(back.cells, [[F, U], [U, F]])


def test_to_occupancy_grid_uses_ros_int8_convention():
    cells = np.array([[F, O, U], [U, F, O]], dtype=np.uint8)  # row 0 at the origin
    m = linemap.Map(cells, resolution=0.05, origin=(1.0, 2.0, np.pi / 2))
    g = m.to_occupancy_grid()
    assert g["data"].dtype == np.int8
    assert g["data"].tolist() == [0, 100, -1, -1, 0, 100]  # row-major, row 0 first
    assert (g["width"], g["height"]) == (3, 2)
    assert g["resolution"] == float(np.float32(0.05))  # the message's float32
    assert g["origin"] == (1.0, 2.0, np.pi / 2)
    qx, qy, qz, qw = g["orientation"]
    assert (qx, qy) == (0.0, 0.0)
    assert qz == pytest.approx(np.sqrt(0.5)) and qw == pytest.approx(np.sqrt(0.5))
    assert g["frame_id"] == "map"


def test_from_occupancy_grid_reads_like_map_saver():
    # map_saver's defaults: free when v <= 25, occupied when v >= 65, else
    # unknown; -1 and values outside 0..100 unknown.
    data = np.array([0, 25, 26, 64, 65, 100, -1, 101, -128, 127, 50, 10], dtype=np.int8)
    expected = np.array([[F, F, U, U], [O, O, U, U], [U, U, U, F]], dtype=np.uint8)
    m = linemap.Map.from_occupancy_grid(data, 4, 3, 0.05, (1.0, 2.0, 0.5))
    assert m.cells.dtype == np.uint8
    assert np.array_equal(m.cells, expected)
    assert m.resolution == 0.05  # the shortest decimal of the message's float32, as lmap_saver
    assert m.origin[:2] == (1.0, 2.0) and m.origin[2] == pytest.approx(0.5, abs=1e-15)
    # The same as (height, width), as a list (rospy) or an array.array (rclpy).
    for same in (data.reshape(3, 4), data.tolist(), array.array("b", data.tolist())):
        assert np.array_equal(linemap.Map.from_occupancy_grid(same, 4, 3, 0.05).cells, expected)


def test_from_occupancy_grid_thresholds_are_options():
    data = np.array([30, 60], dtype=np.int8)
    m = linemap.Map.from_occupancy_grid(data, 2, 1, 0.05, occupied_thresh=0.6, free_thresh=0.3)
    assert m.cells.tolist() == [[F, O]]


def test_occupancy_grid_round_trip_keeps_cells():
    rng = np.random.default_rng(7)
    cells = rng.integers(0, 3, size=(37, 53), dtype=np.uint8)
    m = linemap.Map(cells, resolution=0.05, origin=(-3.0, 4.5, 0.0))
    g = m.to_occupancy_grid()
    back = linemap.Map.from_occupancy_grid(g["data"], g["width"], g["height"],
                                           g["resolution"], g["origin"])
    assert np.array_equal(back.cells, cells)
    assert back.origin == (-3.0, 4.5, 0.0)


def test_from_occupancy_grid_refuses_bad_data():
    with pytest.raises(TypeError, match="int8"):
        linemap.Map.from_occupancy_grid(np.zeros(4, dtype=np.int16), 2, 2, 0.05)
    with pytest.raises(TypeError, match="int8"):
        linemap.Map.from_occupancy_grid(np.zeros(4, dtype=np.uint8), 2, 2, 0.05)
    with pytest.raises(ValueError, match="shape"):
        linemap.Map.from_occupancy_grid(np.zeros(5, dtype=np.int8), 2, 2, 0.05)
    with pytest.raises(ValueError, match="shape"):
        linemap.Map.from_occupancy_grid(np.zeros((2, 2), dtype=np.int8), 4, 1, 0.05)
    with pytest.raises(ValueError, match="-128..127"):
        linemap.Map.from_occupancy_grid([0, 1, 2, 300], 2, 2, 0.05)
    with pytest.raises(TypeError, match="int8"):
        linemap.Map.from_occupancy_grid([0.0, 0.5, 1.0, 1.5], 2, 2, 0.05)
    with pytest.raises(ValueError, match="resolution"):
        linemap.Map.from_occupancy_grid(np.zeros(4, dtype=np.int8), 2, 2, 0.0)
    with pytest.raises(ValueError, match="width"):
        linemap.Map.from_occupancy_grid(np.zeros(4, dtype=np.int8), -2, -2, 0.05)


def test_from_occupancy_grid_limit_raises_memory_error():
    with pytest.raises(MemoryError, match="limit of 5"):
        linemap.Map.from_occupancy_grid(np.zeros(6, dtype=np.int8), 3, 2, 0.05, max_cells=5)


def test_from_occupancy_grid_default_limit_is_load_s_2_30_cells():
    # 2^30 + 2^15 cells of one value (a broadcast view: no memory), refused
    # before the data are copied, as load() refuses a map over 2^30 cells.
    data = np.broadcast_to(np.int8(-1), (2**15, 2**15 + 1))
    with pytest.raises(MemoryError, match="limit of 1073741824"):
        linemap.Map.from_occupancy_grid(data, 2**15 + 1, 2**15, 0.05)
    with pytest.raises(MemoryError, match="limit of 1073741824"):
        linemap.Map.from_occupancy_grid(np.broadcast_to(np.int8(0), (data.size,)), 2**15 + 1,
                                        2**15, 0.05)
    assert "2^30" in linemap.Map.from_occupancy_grid.__doc__


def test_yaml_fields_are_shown_and_thresholds_settable(tmp_path):
    cells = np.array([[F, O, U], [O, O, F]], dtype=np.uint8)
    m = linemap.Map(cells)
    # map_saver's defaults for a map made from cells.
    assert (m.occupied_thresh, m.free_thresh, m.negate, m.mode) == (0.65, 0.196, False, "trinary")
    # A YAML's own fields come with a map loaded from it.
    (tmp_path / "t.pgm").write_bytes(b"P5\n3 2\n255\n" + bytes([0, 254, 205, 0, 0, 254]))
    (tmp_path / "t.yaml").write_text(
        "image: t.pgm\nmode: scale\nresolution: 0.05\norigin: [0.0, 0.0, 0]\n"
        "negate: 1\noccupied_thresh: 0.7\nfree_thresh: 0.2\n")
    loaded = linemap.load(str(tmp_path / "t.yaml"))
    assert (loaded.occupied_thresh, loaded.free_thresh) == (0.7, 0.2)
    assert (loaded.negate, loaded.mode) == (True, "scale")
    # An .lmap file keeps all four.
    again = linemap.decode(linemap.encode(loaded))
    assert (again.occupied_thresh, again.free_thresh, again.negate, again.mode) == (
        0.7, 0.2, True, "scale")
    # Both at once: from (0.65, 0.196) to (0.15, 0.1) passes through no
    # invalid pair. A .yaml save keeps a pair under which map_saver's grey
    # values read back (205 is unknown under free 0.1).
    m.set_thresholds(0.15, 0.1)
    assert (m.occupied_thresh, m.free_thresh) == (0.15, 0.1)
    m.set_thresholds(0.7, 0.1)
    linemap.save(str(tmp_path / "out.yaml"), m)
    text = (tmp_path / "out.yaml").read_text()
    assert "free_thresh: 0.1" in text and "occupied_thresh: 0.7" in text, text
    # A pair the CLI's options refuse is refused, and the map keeps its pair.
    with pytest.raises(ValueError, match="must be below"):
        m.set_thresholds(0.5, 0.5)
    with pytest.raises(ValueError, match="0..1"):
        m.set_thresholds(1.5, 0.1)
    with pytest.raises(ValueError, match="0..1"):
        m.set_thresholds(0.65, float("nan"))
    assert (m.occupied_thresh, m.free_thresh) == (0.7, 0.1)
    with pytest.raises(AttributeError):
        m.free_thresh = 0.2  # read-only: set_thresholds sets the pair


def scale_map(tmp_path):
    """A map whose every metadata field is off map_saver's defaults."""
    (tmp_path / "t.pgm").write_bytes(b"P5\n3 2\n255\n" + bytes([0, 254, 205, 0, 0, 254]))
    (tmp_path / "t.yaml").write_text(
        "image: t.pgm\nmode: scale\nresolution: 0.1\norigin: [1.5, -2.0, 0.25]\n"
        "negate: 1\noccupied_thresh: 0.7\nfree_thresh: 0.2\n")
    return linemap.load(str(tmp_path / "t.yaml"))


def fields(m):
    return (m.cells.tolist(), m.resolution, m.origin, m.mode, m.negate, m.occupied_thresh,
            m.free_thresh)


def test_map_pickles_with_every_protocol_and_copies(tmp_path):
    import copy
    import pickle
    m = scale_map(tmp_path)
    expected = fields(m)
    assert expected[1:] == (0.1, (1.5, -2.0, 0.25), "scale", True, 0.7, 0.2)  # the YAML's
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        loaded = pickle.loads(pickle.dumps(m, protocol))
        assert type(loaded) is linemap.Map
        assert fields(loaded) == expected, protocol
        assert loaded.cells is not m.cells
    deep = copy.deepcopy(m)
    assert fields(deep) == expected and deep.cells is not m.cells
    # A loaded copy saves the same .lmap file.
    assert linemap.encode(pickle.loads(pickle.dumps(m))) == linemap.encode(m)


def test_unpickling_checks_the_state(tmp_path):
    state = scale_map(tmp_path).__getstate__()

    def loaded(state):
        m = linemap.Map.__new__(linemap.Map)
        m.__setstate__(state)
        return m

    assert fields(loaded(dict(state)))[1:] == (0.1, (1.5, -2.0, 0.25), "scale", True, 0.7, 0.2)
    bad_cells = np.array([[F, 3]], dtype=np.uint8)
    for change, error, match in [
        ({"cells": bad_cells}, ValueError, "cells must be"),
        ({"cells": np.zeros((2, 2), dtype=np.int8)}, TypeError, "uint8"),
        ({"resolution": 0.0}, ValueError, "resolution"),
        ({"origin": (0.0, float("inf"))}, ValueError, "origin"),
        ({"mode": "grey"}, ValueError, "mode 'grey'"),
        ({"free_thresh": float("nan")}, ValueError, "free_thresh is not finite"),
    ]:
        with pytest.raises(error, match=match):
            loaded({**state, **change})
    without = dict(state)
    del without["mode"]
    with pytest.raises(ValueError, match="without 'mode'"):
        loaded(without)


def test_a_map_whose_yaml_thresholds_are_out_of_order_pickles(tmp_path):
    # load() keeps a YAML's pair as map_server reads it, even one
    # set_thresholds() refuses; a pickle gives it back.
    import pickle
    (tmp_path / "t.pgm").write_bytes(b"P5\n2 1\n255\n" + bytes([0, 254]))
    (tmp_path / "t.yaml").write_text(
        "image: t.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.6\nfree_thresh: 0.7\n")
    m = linemap.load(str(tmp_path / "t.yaml"))
    assert (m.occupied_thresh, m.free_thresh) == (0.6, 0.7)
    assert fields(pickle.loads(pickle.dumps(m))) == fields(m)
