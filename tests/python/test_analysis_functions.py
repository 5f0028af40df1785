"""linemap.lines / segment / plan / eval give the figures the `linemap`
program prints as JSON for the same map."""
import numpy as np
import pytest

import linemap_cli
from conftest import BUNDLED

linemap = pytest.importorskip("linemap")

# Keys whose values are timings, which differ from run to run.
TIMINGS = {"ms", "stages_ms", "timings_ms"}


def without_timings(d):
    return {k: v for k, v in d.items() if k not in TIMINGS}


@pytest.mark.parametrize("name", sorted(BUNDLED))
@pytest.mark.parametrize("method", ["linemap", "rmline"])
def test_lines_equal_the_cli(name, method, tmp_path, cli):
    csv = tmp_path / "lines.csv"
    expected = linemap_cli.run_json(cli, "lines", BUNDLED[name], "--method", method, "-o", csv,
                                    "--json")
    got = linemap.lines(linemap.load(BUNDLED[name]), method=method)
    assert set(got) == set(expected) | {"segments"}
    for key, value in without_timings(expected).items():
        assert got[key] == value, key
    rows = linemap_cli.read_csv_rows(csv).get("segment", [])
    assert got["segments"].shape == (len(rows), 4)
    assert np.allclose(got["segments"], np.array(rows).reshape(-1, 4), atol=5e-7, rtol=0)


def test_straight_walls_and_pose_are_passed_on(cli):
    path = BUNDLED["depot"]
    expected = linemap_cli.run_json(cli, "lines", path, "--straight-walls", "--pose", "1,1",
                                    "--json")
    got = linemap.lines(linemap.load(path), straight_walls=True, pose=(1, 1))
    assert (got["lines"], got["displ_cells"]) == (expected["lines"], expected["displ_cells"])


@pytest.mark.parametrize("name", sorted(BUNDLED))
def test_segment_equals_the_cli(name, tmp_path, cli):
    out = tmp_path / "seg.json"
    linemap_cli.run(cli, "segment", BUNDLED[name], "-o", out)
    import json
    expected = json.loads(out.read_text())
    got = linemap.segment(linemap.load(BUNDLED[name]))
    assert set(got) == set(expected) - {"timings_ms"}
    assert (got["resolution"], got["method"]) == (expected["resolution"], "rooms")
    assert_same_items(got["rooms"], expected["rooms"])
    assert_same_items(got["doors"], expected["doors"])
    assert_same_items(got["blobs"], expected["blobs"], python_only={"cells"})
    for blob in got["blobs"]:
        assert blob["cell_count"] == len(blob["cells"])


def assert_same_items(got, expected, python_only=()):
    """Each dict of `got` has the keys and values of the CLI's JSON object
    (arrays and tuples compared as lists), plus the keys `python_only`."""
    assert len(got) == len(expected)
    for g, e in zip(got, expected):
        assert set(g) == set(e) | set(python_only)
        for key, value in e.items():
            mine = g[key]
            if hasattr(mine, "tolist"):
                mine = mine.tolist()
            elif isinstance(mine, tuple):
                mine = list(mine)
            assert mine == value, key


def test_segment_with_a_pose_equals_the_cli(tmp_path, cli):
    out = tmp_path / "seg.json"
    linemap_cli.run(cli, "segment", BUNDLED["depot"], "--pose", "1,1", "-o", out)
    import json
    expected = json.loads(out.read_text())
    got = linemap.segment(linemap.load(BUNDLED["depot"]), pose=(1, 1))
    assert set(got) == set(expected) - {"timings_ms"}
    assert got["method"] == expected["method"] == "paper"
    assert_same_items(got["rooms"], expected["rooms"])
    assert_same_items(got["blobs"], expected["blobs"], python_only={"cells"})


@pytest.mark.parametrize("flags,kwargs", [
    (["--doors", "0.6,1.0", "--max-room-area", "30"], {"doors": (0.6, 1.0), "max_room_area": 30}),
    (["--method", "paper"], {"method": "paper"}),
    (["--paper-border"], {"paper_border": True}),
])
def test_segment_options_equal_the_cli_flags(flags, kwargs, tmp_path, cli):
    out = tmp_path / "seg.json"
    linemap_cli.run(cli, "segment", BUNDLED["kth"], "-o", out, *flags)
    import json
    expected = json.loads(out.read_text())
    got = linemap.segment(linemap.load(BUNDLED["kth"]), **kwargs)
    assert set(got) == set(expected) - {"timings_ms"}
    assert got["method"] == expected["method"]
    assert_same_items(got["rooms"], expected["rooms"])
    assert_same_items(got["blobs"], expected["blobs"], python_only={"cells"})
    if "doors" in expected:
        assert_same_items(got["doors"], expected["doors"])


# Options the CLI refuses, refused by lines() and segment() with the
# exception the module's conventions give them (a match of None: any
# message).
REFUSED_OPTIONS = [
    ("lines", {"method": "hough"}, ValueError, "method"),
    ("lines", {"epsilon": 0.2}, ValueError, "epsilon"),
    ("lines", {"pose": (1.0,)}, ValueError, "pose"),
    # The linemap extractor's options with rmline, as the CLI refuses them.
    ("lines", {"method": "rmline", "epsilon": 1.0}, ValueError, "epsilon is an option of"),
    ("lines", {"method": "rmline", "straight_walls": True}, ValueError, "straight_walls"),
    ("segment", {"method": "watershed"}, ValueError, "method"),
    ("segment", {"method": 1}, TypeError, "method"),
    ("segment", {"method": "rooms", "pose": (1, 1)}, ValueError, "paper"),
    ("segment", {"doors": (0.5,)}, ValueError, "doors"),
    ("segment", {"doors": (1.2, 0.5)}, ValueError, None),
    # The rooms method's options with the paper's, as the CLI refuses them.
    ("segment", {"pose": (2, 2), "doors": (0.6, 1.0)}, ValueError, "doors is an option of"),
    ("segment", {"method": "paper", "max_room_area": 10}, ValueError, "max_room_area"),
    ("segment", {"paper_border": True, "doors": (0.5, 1.2)}, ValueError, "method=\"rooms\""),
]


@pytest.mark.parametrize("function, options, error, match", REFUSED_OPTIONS)
def test_options_the_cli_refuses_are_refused(function, options, error, match):
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(error, match=match):
        getattr(linemap, function)(m, **options)


# plan()'s keys, found or not, as the CLI's JSON.
PLAN_KEYS = {"found", "error", "length_m", "commands", "waypoints", "alternatives", "ms",
             "stages_ms", "trajectories"}


def compare_plans(got, expected):
    assert set(got) == PLAN_KEYS and set(expected) == PLAN_KEYS
    for key, value in without_timings(expected).items():
        if key == "waypoints":
            assert got[key].tolist() == value
        elif key == "trajectories":
            assert len(got[key]) == len(value)
            for g, e in zip(got[key], value):
                assert g["waypoints"].tolist() == e["waypoints"]
                assert {k: v for k, v in g.items() if k != "waypoints"} == \
                    {k: v for k, v in e.items() if k != "waypoints"}
        else:
            assert got[key] == value, key


@pytest.mark.parametrize("name,start,goal", [
    ("depot", (1, 1), (20, 10)),
    ("lse_arena", (1, 1, 0.5), (3, 2)),
])
def test_plan_equals_the_cli(name, start, goal, cli):
    expected = linemap_cli.run_json(cli, "plan", BUNDLED[name],
                                    "--from", ",".join(map(str, start)),
                                    "--to", ",".join(map(str, goal)), "--json")
    got = linemap.plan(linemap.load(BUNDLED[name]), start, goal)
    assert got["found"] is True
    compare_plans(got, expected)


def test_plan_not_found_is_a_result_not_an_exception(cli):
    expected = linemap_cli.run_json(cli, "plan", BUNDLED["kth"], "--from", "0,0", "--to", "3,10",
                                    "--json", expect_exit=1)
    got = linemap.plan(linemap.load(BUNDLED["kth"]), start=(0, 0), goal=(3, 10))
    assert got["found"] is False and "safe distance" in got["error"]
    compare_plans(got, expected)


def test_plan_not_found_has_the_keys_of_a_found_plan_empty():
    route = linemap.plan(linemap.load(BUNDLED["kth"]), start=(0, 0), goal=(3, 10))
    assert route["found"] is False and route["alternatives"] == 0
    assert route["length_m"] is None
    assert route["commands"] == [] and route["trajectories"] == []
    assert route["waypoints"].dtype == np.float64 and route["waypoints"].shape == (0, 2)
    assert set(route["stages_ms"]) == {"safe_zone", "wave", "regions", "generation"}
    found = linemap.plan(linemap.load(BUNDLED["depot"]), (1, 1), (20, 10))
    assert found["found"] is True and found["error"] is None
    assert set(found) == set(route) == PLAN_KEYS


def test_plan_robot_options_are_passed_on(cli):
    expected = linemap_cli.run_json(cli, "plan", BUNDLED["depot"], "--from", "1,1", "--to",
                                    "20,10", "--robot-width", "0.6", "--margin", "0.1",
                                    "--dmax", "3", "--json")
    got = linemap.plan(linemap.load(BUNDLED["depot"]), (1, 1), (20, 10), robot_width=0.6,
                       margin=0.1, d_max=3.0)
    compare_plans(got, expected)


def test_plan_start_or_goal_off_the_map_raises_value_error(cli):
    # Bad input, as the CLI's exit status 2 says; a start in an obstacle or
    # a goal out of reach is the planner's answer (found False).
    m = linemap.load(BUNDLED["depot"])
    with pytest.raises(ValueError, match="start -5.000,1.000 is outside the map"):
        linemap.plan(m, (-5, 1), (20, 10))
    with pytest.raises(ValueError, match="goal 1.000,99.000 is outside the map"):
        linemap.plan(m, (1, 1), (1, 99))
    off = linemap_cli.run_json(cli, "plan", BUNDLED["depot"], "--from", "-5,1", "--to",
                               "20,10", "--json", expect_exit=2)
    assert off["error"] == "start -5.000,1.000 is outside the map"


def test_plan_accepts_numpy_points_as_sequences(cli):
    # A numpy array makes each item as it is read; its points and door
    # widths are numbers like a tuple's (this crashed the interpreter).
    m = linemap.load(BUNDLED["depot"])
    assert compare_plans(linemap.plan(m, np.array([1.0, 1.0]), np.array([20.0, 10.0])),
                         linemap_cli.run_json(cli, "plan", BUNDLED["depot"], "--from", "1,1",
                                              "--to", "20,10", "--json")) is None
    rooms = linemap.segment(m, doors=np.array([0.5, 1.2]))
    assert rooms["rooms"] and len(rooms["rooms"]) == len(linemap.segment(m)["rooms"])
    paper = linemap.segment(m, pose=np.array([2.0, 2.0]))
    assert len(paper["rooms"]) == len(linemap.segment(m, pose=(2.0, 2.0))["rooms"])
    assert linemap.lines(m, pose=np.array([2.0, 2.0]))["segments"].shape == \
        linemap.lines(m, pose=(2.0, 2.0))["segments"].shape
    for bad in (np.array([1.0]), np.array([[1.0, 2.0]]), np.array([np.nan, 1.0])):
        with pytest.raises(ValueError):
            linemap.plan(m, bad, (20, 10))


def test_lines_pose_on_a_cells_lower_edge_is_in_that_cell():
    # One wall on row 3 at 0.1 m/cell, origin (1, 2): 2.4 m is the lower edge
    # of row 4 (free), though (2.4 - 2) / 0.1 - 0.5 is 3.4999999999999991 in
    # doubles, which rounding put on the wall ("not on a free cell").
    cells = np.full((7, 20), linemap.FREE, np.uint8)
    cells[3, 2:18] = linemap.OCCUPIED
    m = linemap.Map(cells, 0.1, (1.0, 2.0, 0.0))
    assert linemap.lines(m, pose=(1.55, 2.4))["lines"] == 1
    with pytest.raises(ValueError, match="not on a free cell"):
        linemap.lines(m, pose=(1.55, 2.399))


def test_plan_options_the_planner_refuses_raise_value_error():
    m = linemap.load(BUNDLED["depot"])
    with pytest.raises(ValueError, match="D_max"):
        linemap.plan(m, (1, 1), (20, 10), d_max=-1)
    with pytest.raises(ValueError, match="goal"):
        linemap.plan(m, (1, 1), (20,))


@pytest.mark.parametrize("name", sorted(BUNDLED))
def test_eval_equals_the_cli(name, tmp_path, cli):
    lmap = tmp_path / "map.lmap"
    linemap_cli.run(cli, "encode", BUNDLED[name], "-o", lmap, "--no-sync")
    expected = linemap_cli.run_json(cli, "eval", BUNDLED[name], lmap, "--json")
    assert linemap.eval(BUNDLED[name], lmap) == expected
    # Maps in memory: the same figures, without the layers' fidelity.
    original, decoded = linemap.load(BUNDLED[name]), linemap.load(lmap)
    layer_keys = ("edge_cells", "displ_ave_cells", "displ_ave_cm", "displ_max_cells",
                  "edge_share_within_1", "edge_share_in_furniture",
                  "edge_share_within_1_or_furniture")
    cells_only = {k: v for k, v in expected.items() if k not in layer_keys}
    assert linemap.eval(original, decoded) == cells_only


def test_eval_of_a_raster_only_file_has_no_wall_figures(tmp_path, cli):
    # No walls: no distance and no share within 1 cell of one (None, as the
    # CLI's null), rather than a share of 0 that reads as every wall lost.
    lmap = tmp_path / "cells.lmap"
    linemap_cli.run(cli, "encode", BUNDLED["depot"], "-o", lmap, "--raster-only", "--no-sync")
    expected = linemap_cli.run_json(cli, "eval", BUNDLED["depot"], lmap, "--json")
    figures = linemap.eval(BUNDLED["depot"], lmap)
    assert figures == expected
    assert figures["edge_share_within_1"] is None
    assert figures["displ_ave_cells"] is None
    assert figures["edge_share_within_1_or_furniture"] == 0


@pytest.mark.parametrize("t", [1, 3])
def test_eval_with_a_tolerance_equals_the_cli(t, tmp_path, cli):
    path = BUNDLED["depot"]
    lmap = tmp_path / "map.lmap"
    linemap_cli.run(cli, "encode", path, "-o", lmap, "--tolerance", str(t), "--no-sync")
    expected = linemap_cli.run_json(cli, "eval", path, lmap, "--tolerance", str(t), "--json")
    got = linemap.eval(path, lmap, tolerance=t)
    assert got == expected
    assert got["tolerance_holds"] is True and got["local_plans"] > 0
    # A block of obstacles far from every wall breaks the guarantees: both
    # say so, with the same figures.
    broken = linemap.load(lmap)
    free = np.argwhere(broken.cells == linemap.FREE)
    row, col = free[len(free) // 2]
    broken.cells[row - 2:row + 3, col - 2:col + 3] = linemap.OCCUPIED
    linemap.save(tmp_path / "broken.yaml", broken)
    expected = linemap_cli.run_json(cli, "eval", path, tmp_path / "broken.yaml", "--tolerance",
                                    str(t), "--json")
    got = linemap.eval(path, broken, tolerance=t)
    # The Map knows the T of the file it was loaded from; its YAML does not.
    assert got.pop("tolerance_named_cells") == t
    assert "tolerance_named_cells" not in expected
    assert got == expected
    assert got["tolerance_holds"] is False


def test_eval_tolerance_must_be_a_whole_number_of_cells_up_to_4():
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(ValueError, match="0..4"):
        linemap.eval(m, m, tolerance=5)
    with pytest.raises(TypeError, match="tolerance"):
        linemap.eval(m, m, tolerance=1.5)
    assert linemap.eval(m, m, tolerance=0)["tolerance_holds"] is True
    assert "tolerance_holds" not in linemap.eval(m, m)


def test_eval_refuses_maps_of_different_sizes():
    with pytest.raises(ValueError, match="same size"):
        linemap.eval(BUNDLED["depot"], BUNDLED["kth"])


def test_eval_checks_a_tolerance_file_at_the_t_it_names(tmp_path):
    depot = BUNDLED["depot"]
    path = tmp_path / "t2.lmap"
    linemap.save(path, linemap.load(depot), tolerance=2)
    named = linemap.eval(depot, path)
    assert named["tolerance_from_file"] is True and named["tolerance_holds"] is True
    assert named["tolerance_named_cells"] == 2
    given = linemap.eval(depot, path, tolerance=2)
    assert given["tolerance_from_file"] is False and given["tolerance_named_cells"] == 2
    figures = {k: v for k, v in given.items() if k != "tolerance_from_file"}
    assert {k: named[k] for k in figures} == figures
    exact = tmp_path / "exact.lmap"
    linemap.save(exact, linemap.load(depot))
    assert "tolerance_holds" not in linemap.eval(depot, exact)


def test_eval_of_a_tolerance_file_equals_the_cli(tmp_path, cli):
    depot = BUNDLED["depot"]
    path = tmp_path / "t2.lmap"
    linemap.save(path, linemap.load(depot), tolerance=2)
    assert linemap.eval(depot, path) == linemap_cli.run_json(cli, "eval", depot, path, "--json")
