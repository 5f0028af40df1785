"""linemap.DecodeLimits and the `limits` argument of the reading functions:
the defaults of the C++ DecodeLimits, checked values, and every reader
holding an .lmap file to them."""
import copy
import pickle

import numpy as np
import pytest

from conftest import REPO

linemap = pytest.importorskip("linemap")

# A 2.2 fixture whose counts `linemap info --json` lists: 437 wall segments,
# 8 rooms and 33 furniture objects, 604 x 307 cells at 0.05 m, origin 0.
DEPOT = REPO / "tests" / "data" / "lmap" / "depot_v2.lmap"
SEGMENTS, OBJECTS, CELLS = 437, 33, 604 * 307

# include/linemap/codec.h and spec/format.md section 7.3.
DEFAULTS = {
    "max_file_bytes": 2**31,
    "max_cells": 2**30,
    "max_chunk_bytes": 2**30,
    "max_inflated_bytes": 2**28,
    "max_segments": 2**24,
    "max_chain_length": 2**26,
    "max_objects": 2**20,
    "max_threads": 0,
}


def test_defaults_are_the_librarys():
    limits = linemap.DecodeLimits()
    assert {name: getattr(limits, name) for name in DEFAULTS} == DEFAULTS


def test_keywords_set_limits_and_repr_rebuilds_them():
    limits = linemap.DecodeLimits(max_segments=1000, max_objects=50)
    assert (limits.max_segments, limits.max_objects) == (1000, 50)
    assert limits.max_cells == DEFAULTS["max_cells"]
    assert limits != linemap.DecodeLimits()
    assert eval(repr(limits), {"linemap": linemap}) == limits
    limits.max_threads = 2
    assert limits.max_threads == 2


@pytest.mark.parametrize("name", sorted(DEFAULTS))
def test_values_are_checked(name):
    lowest = 0 if name == "max_threads" else 1
    highest = 4096 if name == "max_threads" else 2**64 - 1
    for good in (lowest, highest):
        assert getattr(linemap.DecodeLimits(**{name: good}), name) == good
    for bad in (lowest - 1, highest + 1):
        with pytest.raises(ValueError, match=name):
            linemap.DecodeLimits(**{name: bad})
    for wrong in (1.5, True, "5", None):
        with pytest.raises(TypeError, match=name):
            linemap.DecodeLimits(**{name: wrong})
    limits = linemap.DecodeLimits()
    with pytest.raises(ValueError, match=name):
        setattr(limits, name, lowest - 1)
    assert getattr(limits, name) == DEFAULTS[name]


def test_limits_pickle_and_copy_with_every_limit():
    # Every limit off its default, the largest segment limit too.
    limits = linemap.DecodeLimits(
        max_file_bytes=10**6, max_cells=CELLS, max_chunk_bytes=2**20, max_inflated_bytes=2**21,
        max_segments=2**64 - 1, max_chain_length=2**25, max_objects=OBJECTS - 1, max_threads=3)
    assert all(getattr(limits, name) != default for name, default in DEFAULTS.items())
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        loaded = pickle.loads(pickle.dumps(limits, protocol))
        assert type(loaded) is linemap.DecodeLimits
        assert loaded == limits and loaded is not limits
        assert repr(loaded) == repr(limits)
    for copied in (copy.deepcopy(limits), copy.copy(limits)):
        assert copied == limits
        copied.max_threads = 4
        assert limits.max_threads == 3  # a copy, not a view
    # A loaded copy holds a file to its limits as the original does.
    with pytest.raises(MemoryError, match="object limit of 32"):
        linemap.vectors(DEPOT, limits=pickle.loads(pickle.dumps(limits)))


def test_unpickling_checks_the_limits():
    state = linemap.DecodeLimits(max_objects=7).__getstate__()
    assert state == {**DEFAULTS, "max_objects": 7}

    def loaded(state):
        limits = linemap.DecodeLimits.__new__(linemap.DecodeLimits)
        limits.__setstate__(state)
        return limits

    # A state without a limit (pickled before it was added) keeps its default.
    assert loaded({"max_objects": 7}) == linemap.DecodeLimits(max_objects=7)
    with pytest.raises(ValueError, match="max_objects"):
        loaded({**state, "max_objects": 0})
    with pytest.raises(TypeError, match="max_cells"):
        loaded({**state, "max_cells": 1.5})
    with pytest.raises(ValueError, match="max_segment"):
        loaded({**state, "max_segment": 5})  # a misspelt name is not ignored


def test_limits_are_keywords_only():
    with pytest.raises(TypeError):
        linemap.DecodeLimits(5)
    with pytest.raises(TypeError):
        linemap.DecodeLimits(max_segment=5)  # a misspelt name is not ignored


# Every function that reads an .lmap file, by path and by bytes.
READERS = {
    "load": lambda limits: linemap.load(DEPOT, limits=limits),
    "load window": lambda limits: linemap.load(DEPOT, window_cells=(0, 0, 50, 50), limits=limits),
    "decode": lambda limits: linemap.decode(DEPOT.read_bytes(), limits=limits),
    "vectors": lambda limits: linemap.vectors(DEPOT, limits=limits),
    "vectors of bytes": lambda limits: linemap.vectors(DEPOT.read_bytes(), limits=limits),
    "room_at": lambda limits: linemap.room_at(DEPOT, 15.1, 7.6, limits=limits),
    "eval": lambda limits: linemap.eval(DEPOT, DEPOT, limits=limits),
}


@pytest.mark.parametrize("reader", sorted(READERS))
@pytest.mark.parametrize(
    "name,count,message",
    [
        ("max_segments", SEGMENTS, "segment limit of 436"),
        ("max_objects", OBJECTS, "object limit of 32"),
        ("max_cells", CELLS, "limit of 185427 cells"),
    ],
)
def test_every_reader_holds_the_file_to_the_limits(reader, name, count, message):
    READERS[reader](linemap.DecodeLimits(**{name: count}))  # at the limit: read
    with pytest.raises(MemoryError, match=message):
        READERS[reader](linemap.DecodeLimits(**{name: count - 1}))


@pytest.mark.parametrize(
    "fixture", ["depot_v2.lmap", "depot_v2_0.lmap", "depot_v2_2_sections_64.lmap"]
)
def test_the_largest_segment_limit_reads_every_layout(fixture):
    # 2^64 - 1 plus one point per wall used to wrap to a handful of points
    # in a 2.0 WALL chunk, which then refused every file with walls.
    path = DEPOT.with_name(fixture)
    limits = linemap.DecodeLimits(max_segments=2**64 - 1)
    assert len(linemap.vectors(path, limits=limits)["walls"]) > 0
    assert np.array_equal(linemap.load(path, limits=limits).cells, linemap.load(path).cells)


def test_max_cells_and_limits_together_are_refused():
    with pytest.raises(ValueError, match="not both"):
        linemap.load(DEPOT, max_cells=CELLS, limits=linemap.DecodeLimits())
    with pytest.raises(TypeError, match="DecodeLimits"):
        linemap.load(DEPOT, limits={"max_cells": CELLS})


def test_threads_do_not_change_the_decode():
    # 64-cell tiles: 50 tiles for the threads to share (depot_v2.lmap is one).
    tiled = REPO / "tests" / "data" / "lmap" / "depot_v2_tiles_64.lmap"
    one = linemap.load(tiled, limits=linemap.DecodeLimits(max_threads=1))
    for threads in (0, 2, 4):
        many = linemap.load(tiled, limits=linemap.DecodeLimits(max_threads=threads))
        assert np.array_equal(one.cells, many.cells), threads
    assert np.array_equal(one.cells, linemap.load(DEPOT).cells)


def test_a_refusal_names_the_limit_that_lifts_it(tmp_path):
    # MemoryError.limit is the keyword to raise, whatever the message says.
    for name, value in [("max_segments", 436), ("max_objects", 32), ("max_cells", 1000),
                        ("max_file_bytes", 100)]:
        with pytest.raises(MemoryError) as refused:
            linemap.load(DEPOT, limits=linemap.DecodeLimits(**{name: value}))
        assert refused.value.limit == name, str(refused.value)
    depot = linemap.load(str(DEPOT))
    with pytest.raises(MemoryError) as refused:
        linemap.save(str(tmp_path / "t.lmap"), depot, tolerance=1, max_tolerance_cells=1000)
    assert refused.value.limit == "max_tolerance_cells"
    assert not (tmp_path / "t.lmap").exists()


def test_a_refusal_no_keyword_lifts_has_limit_none(tmp_path):
    # A map YAML over the loader's own 1 MiB cap: no DecodeLimits field.
    (tmp_path / "big.yaml").write_text("# " + "x" * (1 << 20) + "\nimage: m.pgm\n")
    with pytest.raises(MemoryError) as refused:
        linemap.load(str(tmp_path / "big.yaml"))
    assert refused.value.limit is None, str(refused.value)
