"""linemap.load / save / encode / decode: exact round trips on the bundled
maps, the cells the `linemap` program writes, and errors that name the file."""
import errno
import pickle
import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest

import linemap_cli
from conftest import BUNDLED, MAPS
from pgm_reader import cells_of_map_saver_pgm

linemap = pytest.importorskip("linemap")


@pytest.fixture(params=sorted(BUNDLED))
def bundled(request):
    return BUNDLED[request.param]


def assert_same_map(a, b):
    assert a.cells.dtype == np.uint8 and b.cells.dtype == np.uint8
    assert np.array_equal(a.cells, b.cells)
    assert a.resolution == b.resolution
    assert a.origin == b.origin


def test_lmap_save_load_is_exact(bundled, tmp_path):
    m = linemap.load(bundled)
    out = tmp_path / "map.lmap"
    linemap.save(out, m)
    assert_same_map(linemap.load(out), m)
    assert_same_map(linemap.load(str(out)), m)


def test_straight_walls_match_the_cli_and_stay_exact(tmp_path, cli):
    path = str(BUNDLED["depot"])
    m = linemap.load(path)
    out = tmp_path / "straight.lmap"
    linemap.save(out, m, straight_walls=True)
    assert_same_map(linemap.load(out), m)
    subprocess.run([cli, "encode", path, "-o", str(tmp_path / "cli.lmap"), "--straight-walls"],
                   check=True, capture_output=True)
    assert out.read_bytes() == (tmp_path / "cli.lmap").read_bytes()
    assert linemap.encode(m, straight_walls=True) == out.read_bytes()
    # The default walls follow the pixel steps: more segments than straight ones.
    steps = linemap.vectors(linemap.encode(m))["walls"].shape[0]
    assert linemap.vectors(out)["walls"].shape[0] < steps


def test_compact_matches_the_cli_stays_exact_and_is_no_larger(bundled, tmp_path, cli):
    m = linemap.load(bundled)
    out = tmp_path / "compact.lmap"
    linemap.save(out, m, compact=True)
    assert_same_map(linemap.load(out), m)
    subprocess.run([cli, "encode", str(bundled), "-o", str(tmp_path / "cli.lmap"), "--compact"],
                   check=True, capture_output=True)
    assert out.read_bytes() == (tmp_path / "cli.lmap").read_bytes()
    assert linemap.encode(m, compact=True) == out.read_bytes()
    # Each tile keeps the smallest of more codings than the default's; on
    # maps of 100,000 cells and more the mixed ones win somewhere.
    default = len(linemap.encode(m))
    if m.cells.size >= 100000:
        assert len(out.read_bytes()) < default
    else:
        assert len(out.read_bytes()) <= default


def test_lmap_cells_only_is_exact(bundled, tmp_path):
    m = linemap.load(bundled)
    out = tmp_path / "map.lmap"
    linemap.save(out, m, vectors=False)
    assert_same_map(linemap.load(out), m)
    assert linemap.vectors(out)["walls"].shape == (0, 4)


def test_yaml_save_load_is_exact_and_writes_map_saver_pgm(bundled, tmp_path):
    m = linemap.load(bundled)
    out = tmp_path / "copy.yaml"
    linemap.save(out, m)
    assert_same_map(linemap.load(out), m)
    assert np.array_equal(cells_of_map_saver_pgm(tmp_path / "copy.pgm"), m.cells)


def test_encode_decode_is_exact(bundled):
    m = linemap.load(bundled)
    data = linemap.encode(m)
    assert isinstance(data, bytes) and data[:1] != b""
    assert_same_map(linemap.decode(data), m)
    assert_same_map(linemap.decode(bytearray(data)), m)
    assert_same_map(linemap.decode(memoryview(data)), m)


def test_cells_equal_what_the_cli_decode_writes(bundled, tmp_path, cli):
    """The program encodes (exact, its default) and decodes; the module
    loads the same .lmap: the cells must be those of the program's PGM."""
    lmap = tmp_path / "map.lmap"
    linemap_cli.run(cli, "encode", bundled, "-o", lmap, "--no-sync")
    linemap_cli.run(cli, "decode", lmap, "-o", tmp_path / "decoded.yaml", "--no-sync")
    expected = cells_of_map_saver_pgm(tmp_path / "decoded.pgm")
    loaded = linemap.load(lmap)
    assert np.array_equal(loaded.cells, expected)
    assert np.array_equal(linemap.decode(lmap.read_bytes()).cells, expected)
    info = linemap_cli.run_json(cli, "info", lmap, "--json")
    assert (loaded.width, loaded.height) == (info["width"], info["height"])
    assert loaded.resolution == info["resolution"]
    assert list(loaded.origin) == info["origin"]


def test_yaml_cells_equal_the_cli_decode_of_a_lossless_file(bundled, tmp_path, cli):
    lmap = tmp_path / "map.lmap"
    linemap_cli.run(cli, "encode", bundled, "-o", lmap, "--lossless", "--no-sync")
    linemap_cli.run(cli, "decode", lmap, "-o", tmp_path / "decoded.yaml", "--no-sync")
    assert np.array_equal(linemap.load(bundled).cells,
                          cells_of_map_saver_pgm(tmp_path / "decoded.pgm"))


def test_bare_image_gets_map_server_defaults(tmp_path):
    image = MAPS / "nav2" / "depot.pgm"
    m = linemap.load(image)
    assert m.resolution == 0.05 and m.origin == (0.0, 0.0, 0.0)
    assert m.cells.shape == (307, 604)


def test_lmap_signature_is_recognised_without_the_suffix(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    renamed = tmp_path / "map.bin"
    renamed.write_bytes(linemap.encode(m))
    assert_same_map(linemap.load(renamed), m)


def test_import_and_load_from_the_repository_root(repo):
    env = dict(os.environ)
    done = subprocess.run(
        [sys.executable, "-c",
         "import linemap; m = linemap.load('tests/data/maps/nav2/depot.yaml'); "
         "print(m.cells.shape)"], cwd=repo, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "(307, 604)\n"


# ---------------------------------------------------------------------------
# Errors: the documented exception, with the library's message naming the file.

def test_missing_files_raise_file_not_found(tmp_path):
    for name in ("none.yaml", "none.lmap", "none.pgm"):
        path = tmp_path / name
        with pytest.raises(FileNotFoundError, match=str(path)):
            linemap.load(path)
    with pytest.raises(FileNotFoundError, match="none.lmap"):
        linemap.vectors(tmp_path / "none.lmap")


def test_missing_files_carry_errno_enoent(tmp_path):
    with pytest.raises(FileNotFoundError) as caught:
        linemap.load(tmp_path / "none.lmap")
    assert caught.value.errno == errno.ENOENT


def unreadable_file():
    """A file this process may not open (chmod 000 when not root; else
    /proc/1/mem where the kernel refuses it), or None."""
    candidates = ["/proc/1/mem"]
    for path in candidates:
        try:
            os.close(os.open(path, os.O_RDONLY))
        except PermissionError:
            return path
        except OSError:
            continue
    return None


def test_unreadable_files_raise_permission_error(tmp_path):
    path = tmp_path / "locked.lmap"
    path.write_bytes(linemap.encode(linemap.Map(np.zeros((4, 4), np.uint8), 0.05, (0, 0, 0))))
    path.chmod(0)
    try:
        target = str(path) if not os.access(path, os.R_OK) else unreadable_file()
        if target is None:
            pytest.skip("every file is readable here (root without a refusing /proc)")
        with pytest.raises(PermissionError, match="Permission denied") as caught:
            linemap.load(target)
        assert caught.value.errno == errno.EACCES
    finally:
        path.chmod(0o600)


def test_yaml_naming_a_missing_image_raises_file_not_found(tmp_path):
    (tmp_path / "map.yaml").write_text("image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                                       "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n")
    with pytest.raises(FileNotFoundError, match="gone.pgm"):
        linemap.load(tmp_path / "map.yaml")


def test_corrupt_lmap_raises_value_error_naming_the_file(tmp_path):
    good = linemap.encode(linemap.load(BUNDLED["depot"]))
    bad = tmp_path / "garbage.lmap"
    bad.write_bytes(b"not an lmap file at all")
    with pytest.raises(ValueError, match="garbage.lmap"):
        linemap.load(bad)
    truncated = tmp_path / "truncated.lmap"
    truncated.write_bytes(good[: len(good) // 2])
    with pytest.raises(ValueError, match="truncated.lmap"):
        linemap.load(truncated)
    flipped = bytearray(good)
    flipped[len(flipped) // 2] ^= 0xFF
    with pytest.raises(ValueError):
        linemap.decode(bytes(flipped))
    with pytest.raises(ValueError):
        linemap.vectors(bytes(flipped))


def test_malformed_yaml_raises_value_error_naming_the_file(tmp_path):
    bad = tmp_path / "broken.yaml"
    bad.write_text("image: [unclosed\n")
    with pytest.raises(ValueError, match="broken.yaml"):
        linemap.load(bad)


def test_limits_raise_memory_error_naming_the_file(tmp_path):
    with pytest.raises(MemoryError, match="depot"):
        linemap.load(BUNDLED["depot"], max_cells=1000)
    lmap = tmp_path / "depot.lmap"
    linemap.save(lmap, linemap.load(BUNDLED["depot"]))
    with pytest.raises(MemoryError, match="depot.lmap"):
        linemap.load(lmap, max_cells=1000)
    with pytest.raises(MemoryError):
        linemap.decode(lmap.read_bytes(), max_cells=1000)
    with pytest.raises(ValueError, match="max_cells"):
        linemap.load(lmap, max_cells=0)


def test_unwritable_destination_raises_os_error_naming_it(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    target = tmp_path / "no" / "such" / "dir" / "map.lmap"
    with pytest.raises(OSError, match=str(target.parent)):
        linemap.save(target, m)
    assert not target.parent.exists()


def test_save_refuses_other_suffixes_and_negative_tolerance(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(ValueError, match="map.png"):
        linemap.save(tmp_path / "map.png", m)
    with pytest.raises(ValueError, match="tolerance"):
        linemap.save(tmp_path / "map.lmap", m, tolerance=-1)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("lmap_name,yaml_name", [
    ("PYX.LMAP", "PYY.YAML"), ("Map.Lmap", "Map.YML"), ("up.lMaP", "up.Yml")])
def test_save_and_convert_take_extensions_in_any_case(tmp_path, lmap_name, yaml_name):
    # As load() and the CLI (`linemap encode D -o UP.LMAP`) take them.
    m = linemap.load(BUNDLED["lse_arena"])
    linemap.save(tmp_path / "lower.lmap", m)
    linemap.save(tmp_path / lmap_name, m)
    assert (tmp_path / lmap_name).read_bytes() == (tmp_path / "lower.lmap").read_bytes()
    assert_same_map(linemap.load(tmp_path / lmap_name), m)
    linemap.save(tmp_path / lmap_name, m, compact=True)  # .lmap options apply
    assert_same_map(linemap.load(tmp_path / lmap_name), m)
    yaml = tmp_path / yaml_name
    linemap.save(yaml, m)
    stem = yaml_name.rsplit(".", 1)[0]
    assert (tmp_path / (stem + ".pgm")).exists()
    assert_same_map(linemap.load(yaml), m)
    with pytest.raises(ValueError, match=r"appl(y|ies) to \.lmap files"):
        linemap.save(yaml, m, compact=True)  # still a YAML path
    linemap.convert(yaml, tmp_path / ("converted." + lmap_name.rsplit(".", 1)[1]))
    assert ((tmp_path / ("converted." + lmap_name.rsplit(".", 1)[1])).read_bytes() ==
            (tmp_path / "lower.lmap").read_bytes())


@pytest.mark.parametrize("name", [".lmap", ".yaml", ".YML"])
def test_save_and_convert_refuse_a_name_that_is_only_an_extension(tmp_path, name):
    # As `linemap decode -o maps/.yaml`: a hidden file was never meant.
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(ValueError, match="no file name before"):
        linemap.save(tmp_path / name, m)
    if name == ".lmap":
        with pytest.raises(ValueError, match="no file name before"):
            linemap.convert(BUNDLED["lse_arena"], tmp_path / name)
    assert list(tmp_path.iterdir()) == []


def test_window_cells_of_a_missing_upper_case_lmap_raise_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError, match="NONE.LMAP"):
        linemap.load(tmp_path / "NONE.LMAP", window_cells=(0, 0, 1, 1))


@pytest.mark.parametrize("name", ["map.lmap", "map.yaml"])
def test_save_into_a_missing_folder_raises_file_not_found_with_errno(tmp_path, name):
    m = linemap.load(BUNDLED["lse_arena"])
    target = tmp_path / "nodir" / name
    with pytest.raises(FileNotFoundError) as caught:
        linemap.save(target, m)
    error = caught.value
    assert error.errno == errno.ENOENT
    # The output that could not be made: the .lmap, or the YAML's image
    # (written first), as the library's message names it.
    written = str(target) if name.endswith(".lmap") else str(target.with_suffix(".pgm"))
    assert error.filename == written
    assert written in error.strerror and "No such file or directory" in error.strerror
    assert not target.parent.exists()


def test_convert_into_a_missing_folder_raises_file_not_found_with_errno(tmp_path):
    target = tmp_path / "nodir" / "map.lmap"
    with pytest.raises(FileNotFoundError) as caught:
        linemap.convert(BUNDLED["lse_arena"], target)
    assert caught.value.errno == errno.ENOENT
    assert caught.value.filename == str(target)
    assert str(target) in caught.value.strerror


def test_save_into_a_file_raises_not_a_directory(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    (tmp_path / "plain").write_bytes(b"")
    with pytest.raises(NotADirectoryError) as caught:
        linemap.save(tmp_path / "plain" / "map.lmap", m)
    assert caught.value.errno == errno.ENOTDIR


def read_only(path):
    """chmod 0444 `path`; skips the test where the file system keeps no
    mode bits."""
    path.chmod(0o444)
    if path.stat().st_mode & 0o222:
        pytest.skip("the file system ignores chmod: no read-only file to save over")


def save_over_read_only(target, save):
    """The PermissionError of save() over the read-only `target`. The
    library refuses a file of mode 0444 even for root (format/file_io.cc);
    were it to write one where root may (open() would), the test skips."""
    try:
        save()
    except PermissionError as error:
        return error
    if os.geteuid() == 0 and os.access(target, os.W_OK):
        pytest.skip("root may write a 0444 file here and the library wrote it")
    pytest.fail("saving over the read-only " + str(target) + " raised nothing")


def test_save_over_a_read_only_file_raises_permission_error_and_leaves_it(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    target = tmp_path / "ro.lmap"
    target.write_bytes(b"old")
    read_only(target)
    try:
        error = save_over_read_only(target, lambda: linemap.save(target, m))
        assert error.errno == errno.EACCES
        assert error.filename == str(target)
        assert str(target) in error.strerror and "read-only" in error.strerror
        assert target.read_bytes() == b"old"
        error = save_over_read_only(
            target, lambda: linemap.convert(BUNDLED["lse_arena"], target))
        assert error.errno == errno.EACCES and error.filename == str(target)
        assert target.read_bytes() == b"old"
    finally:
        target.chmod(0o644)


def test_yaml_save_over_a_read_only_image_names_the_image(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    yaml = tmp_path / "map.yaml"
    linemap.save(yaml, m)
    image = tmp_path / "map.pgm"
    before = (yaml.read_bytes(), image.read_bytes())
    read_only(image)
    try:
        empty = linemap.Map(np.zeros((2, 2), np.uint8))
        error = save_over_read_only(image, lambda: linemap.save(yaml, empty))
        assert error.errno == errno.EACCES
        assert error.filename == str(image)
        assert (yaml.read_bytes(), image.read_bytes()) == before
    finally:
        image.chmod(0o644)


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into a folder of mode 0555")
def test_save_into_a_read_only_folder_raises_permission_error(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o555)
    try:
        with pytest.raises(PermissionError) as caught:
            linemap.save(folder / "map.lmap", m)
        assert caught.value.errno == errno.EACCES
        assert caught.value.filename == str(folder / "map.lmap")
    finally:
        folder.chmod(0o755)


def create_error(path):
    """The OSError of creating `path` as open(path, "w") does, or None where
    that succeeds (the file it made is removed)."""
    try:
        os.close(os.open(path, os.O_WRONLY | os.O_CREAT, 0o644))
    except OSError as error:
        return error
    os.unlink(path)
    return None


def test_save_raises_the_errno_of_the_failed_create(tmp_path):
    # The errno the library's failed call gave, not one guessed by looking
    # at the path afterwards: /proc and /sys take no new file although
    # their folders' permission bits let root make one, which a look at
    # the folder does not show.
    (tmp_path / "plain").write_bytes(b"")
    os.symlink("loop-b.lmap", tmp_path / "loop-a.lmap")
    os.symlink("loop-a.lmap", tmp_path / "loop-b.lmap")
    m = linemap.Map(np.zeros((4, 4), np.uint8))
    (tmp_path / "folder.lmap").mkdir()
    targets = [tmp_path / "nodir" / "map.lmap", tmp_path / "plain" / "map.lmap",
               tmp_path / "loop-a.lmap", pathlib.Path("/proc/linemap-errno-test.lmap"),
               pathlib.Path("/sys/linemap-errno-test.lmap"), tmp_path / "folder.lmap",
               tmp_path / ("n" * 300 + ".lmap")]
    checked = 0
    for target in targets:
        expected = create_error(target)
        if expected is None:
            continue
        for save in (lambda: linemap.save(target, m),
                     lambda: linemap.convert(BUNDLED["lse_arena"], target)):
            with pytest.raises(OSError) as caught:
                save()
            error = caught.value
            assert (type(error), error.errno) == (type(expected), expected.errno), (target, error)
            assert error.filename == str(target)
            assert str(target) in error.strerror
        # A YAML's image is made first, beside it (no symlink loop there).
        image_error = create_error(target.with_suffix(".pgm"))
        if image_error is not None:
            with pytest.raises(OSError) as caught:
                linemap.save(target.with_suffix(".yaml"), m)
            assert caught.value.errno == image_error.errno, (target, caught.value)
        checked += 1
    assert checked >= 3


def test_load_raises_the_errno_of_the_failed_open(tmp_path):
    # NotADirectoryError for a file used as a folder, as open() raises, not
    # ValueError: every failed call raises the OSError of its errno.
    locked = tmp_path / "locked.lmap"
    locked.write_bytes(linemap.encode(linemap.Map(np.zeros((4, 4), np.uint8))))
    locked.chmod(0)
    try:
        plain = tmp_path / "plain"
        plain.write_text("a file, not a folder")
        (tmp_path / "loop.lmap").symlink_to(tmp_path / "loop.lmap")
        targets = [tmp_path / "none.lmap", tmp_path / "nodir" / "none.yaml",
                   plain / "x.lmap", tmp_path / "loop.lmap", tmp_path / ("n" * 300 + ".lmap")]
        unreadable = str(locked) if not os.access(locked, os.R_OK) else unreadable_file()
        if unreadable is not None:
            targets.append(unreadable)
        for target in targets:
            with pytest.raises(OSError) as expected:
                os.close(os.open(target, os.O_RDONLY))
            with pytest.raises(OSError) as caught:
                linemap.load(target)
            error = caught.value
            assert (type(error), error.errno) == (type(expected.value), expected.value.errno)
            assert str(target) in str(error)
    finally:
        locked.chmod(0o600)


@pytest.mark.parametrize("shape", [(0, 3), (3, 0), (0, 0)])
def test_an_empty_map_saves_as_lmap_and_is_refused_as_yaml(tmp_path, shape):
    # The library's Grid and the .lmap format take 0 rows or columns; a map
    # image (PGM, map_server) has at least one pixel.
    m = linemap.Map(np.zeros(shape, np.uint8), 0.05, (1.0, 2.0, 0.0))
    assert (m.height, m.width) == shape
    linemap.save(tmp_path / "e.lmap", m)
    back = linemap.load(tmp_path / "e.lmap")
    assert back.cells.shape == shape and back.origin == (1.0, 2.0, 0.0)
    assert (tmp_path / "e.lmap").read_bytes() == linemap.encode(m)
    assert linemap.decode(linemap.encode(m)).cells.shape == shape
    for name in ("e.yaml", "E.YML"):
        with pytest.raises(ValueError) as caught:
            linemap.save(tmp_path / name, m)
        message = str(caught.value)
        assert name in message
        assert "%d x %d cells" % (shape[1], shape[0]) in message
        assert "at least one row and one column" in message and ".lmap" in message
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.lmap"]


def test_convert_refuses_lmap_sources_naming_load_and_save(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    lmap = tmp_path / "depot.lmap"
    linemap.save(lmap, m)
    renamed = tmp_path / "depot.bin"  # an .lmap file by its signature
    renamed.write_bytes(lmap.read_bytes())
    for source in (lmap, renamed, tmp_path / "UP.LMAP"):
        with pytest.raises(ValueError) as caught:
            linemap.convert(source, tmp_path / "x.lmap")
        message = str(caught.value)
        assert str(source) in message and "not .lmap files" in message
        assert "save(path, load(source)" in message
    assert not (tmp_path / "x.lmap").exists()


@pytest.mark.parametrize("options,named", [
    ({"tolerance": 1}, ["tolerance"]),
    ({"compact": True}, ["compact"]),
    ({"vectors": False}, ["vectors"]),
    ({"straight_walls": True}, ["straight_walls"]),
    ({"max_tolerance_cells": 1000}, ["max_tolerance_cells"]),
    ({"tolerance": 2, "compact": True}, ["tolerance", "compact"]),
])
def test_yaml_save_refuses_the_lmap_options(tmp_path, options, named):
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(ValueError, match=r"appl(y|ies) to \.lmap files") as raised:
        linemap.save(tmp_path / "map.yaml", m, **options)
    for option in named:
        assert option in str(raised.value)
    assert list(tmp_path.iterdir()) == []
    # Their defaults, given explicitly, write the exact YAML + PGM.
    linemap.save(tmp_path / "map.yaml", m, tolerance=0, vectors=True, straight_walls=False,
                 compact=False, max_tolerance_cells=2**26)
    assert_same_map(linemap.load(tmp_path / "map.yaml"), m)


def bench_compact_figures(repo):
    """The compact figures of tools/bench/results/results.csv as the save
    docstring words them: decode ms at the median (compact, default), the
    median and largest per-map decode ratio, the median per-map size saving
    with and without the vector layers (%)."""
    import csv
    import statistics
    with open(repo / "tools" / "bench" / "results" / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))

    def column(name):
        return [float(row[name]) for row in rows]

    compact_ms, default_ms = column("lmap2_compact_decode_ms"), column("lmap2_decode_ms")
    ratios = [c / d for c, d in zip(compact_ms, default_ms)]

    def saving(compact, default):
        return 100 * (1 - statistics.median(
            c / d for c, d in zip(column(compact), column(default))))

    return {
        "decode": "%.1f against %.1f ms" % (statistics.median(compact_ms),
                                            statistics.median(default_ms)),
        "median ratio": "median %.1fx per map" % statistics.median(ratios),
        "largest ratio": "up to %.1fx" % max(ratios),
        "smaller": "%.1f %% smaller" % saving("lmap2_compact_bytes", "lmap2_bytes"),
        "vectors=False": "%.1f %% with vectors=False" % saving("lmap2_raster_compact_bytes",
                                                              "lmap2_raster_bytes"),
    }


def test_save_docstring_gives_the_measured_compact_figures(repo):
    doc = " ".join(linemap.save.__doc__.split())
    for what, words in bench_compact_figures(repo).items():
        assert words in doc, what


def test_convert_writes_the_file_save_writes(tmp_path):
    # 620 x 4300 cells of depot copies: a map of three layer sections, coded
    # as its image is read; the bundled depot itself is loaded whole.
    depot = linemap.load(BUNDLED["depot"])
    tall = np.tile(depot.cells, (3, 8))[:620, :4300].copy()
    big = linemap.Map(tall, resolution=depot.resolution)
    linemap.save(tmp_path / "tall.yaml", big)
    for source in (tmp_path / "tall.yaml", BUNDLED["depot"]):
        linemap.convert(source, tmp_path / "converted.lmap")
        linemap.save(tmp_path / "saved.lmap", linemap.load(source))
        assert (tmp_path / "converted.lmap").read_bytes() == (tmp_path / "saved.lmap").read_bytes()
    assert np.array_equal(linemap.load(tmp_path / "converted.lmap").cells, depot.cells)
    assert np.array_equal(linemap.load(tmp_path / "saved.lmap").cells, depot.cells)
    linemap.convert(tmp_path / "tall.yaml", tmp_path / "tall.lmap")
    assert np.array_equal(linemap.load(tmp_path / "tall.lmap").cells, tall)
    with pytest.raises(ValueError, match="tall.png"):
        linemap.convert(tmp_path / "tall.yaml", tmp_path / "tall.png")
    with pytest.raises(FileNotFoundError, match="none.yaml"):
        linemap.convert(tmp_path / "none.yaml", tmp_path / "none.lmap")
    assert not (tmp_path / "none.lmap").exists()


def test_decode_refuses_text():
    with pytest.raises(TypeError, match="bytes"):
        linemap.decode("LMAP")


# ---------------------------------------------------------------------------
# Vector layers against `linemap export`'s CSV.

# Layer names in the CSV, current and announced (the geometry is compared).
WALL_LAYERS = {"segment", "wall"}
ROOM_LAYERS = {"room_border", "room"}
FURNITURE_LAYERS = {"furniture"}


def rounded(rows):
    """Rows as the CSV prints them (%.6f), sorted, so that the order of the
    layers' pieces does not matter."""
    return sorted(tuple(round(float(v), 6) + 0.0 for v in row) for row in rows)


def ring_edges(points):
    """Edges of a closed chain (the last point joins the first); a one-cell
    chain is one zero-length edge, as `linemap export` writes it."""
    n = len(points)
    return [(*points[i], *points[(i + 1) % n]) for i in range(n)]


def csv_layer(layers, names):
    return [row for name, rows in layers.items() if name in names for row in rows]


@pytest.mark.parametrize("name", sorted(BUNDLED))
def test_vectors_equal_the_cli_export(name, tmp_path, cli):
    lmap = tmp_path / "map.lmap"
    # The default file: walls, rooms and furniture.
    linemap_cli.run(cli, "encode", BUNDLED[name], "-o", lmap, "--no-sync")
    linemap_cli.run(cli, "export", lmap, "-o", tmp_path / "layers.csv")
    layers = linemap_cli.read_csv_rows(tmp_path / "layers.csv")
    assert set(layers) <= WALL_LAYERS | ROOM_LAYERS | FURNITURE_LAYERS

    v = linemap.vectors(lmap)
    assert v["walls"].dtype == np.float64 and v["walls"].shape[1] == 4
    assert rounded(v["walls"]) == rounded(csv_layer(layers, WALL_LAYERS))
    room_edges = [e for room in v["rooms"] for e in ring_edges(room["outline"].tolist())]
    assert rounded(room_edges) == rounded(csv_layer(layers, ROOM_LAYERS))
    furniture_edges = [e for f in v["furniture"] for e in ring_edges(f["outline"].tolist())]
    assert rounded(furniture_edges) == rounded(csv_layer(layers, FURNITURE_LAYERS))
    for room in v["rooms"]:
        assert room["outline"].shape[1] == 2 and isinstance(room["kind"], str)

    # From the bytes, the same.
    from_bytes = linemap.vectors(lmap.read_bytes())
    assert np.array_equal(from_bytes["walls"], v["walls"])
    assert len(from_bytes["rooms"]) == len(v["rooms"])

    m = linemap.load(lmap)
    assert (v["width"], v["height"]) == (m.width, m.height)
    assert v["resolution"] == m.resolution and v["origin"] == m.origin


def test_vectors_have_geometry_on_some_bundled_map(tmp_path, cli):
    """The comparison above is not empty: depot has walls and rooms."""
    lmap = tmp_path / "depot.lmap"
    linemap_cli.run(cli, "encode", BUNDLED["depot"], "-o", lmap, "--no-sync")
    v = linemap.vectors(lmap)
    assert len(v["walls"]) > 10 and len(v["rooms"]) > 0


def test_wall_segments_are_the_polylines_point_pairs(tmp_path, cli):
    lmap = tmp_path / "kth.lmap"
    linemap_cli.run(cli, "encode", BUNDLED["kth"], "-o", lmap, "--no-sync")
    v = linemap.vectors(lmap)
    pairs = [(*p[i], *p[i + 1]) for p in v["wall_polylines"] for i in range(len(p) - 1)]
    assert np.array_equal(v["walls"], np.array(pairs).reshape(-1, 4))


def test_window_cells_load_equals_the_slice_of_the_whole_map(bundled, tmp_path):
    whole = linemap.load(bundled)
    out = tmp_path / "map.lmap"
    linemap.save(out, whole)
    h, w = whole.cells.shape
    for c0, r0, c1, r1 in [(0, 0, w, h), (w // 3, h // 4, w // 3 + 17, h // 4 + 9),
                           (w - 1, h - 1, w, h)]:
        part = linemap.load(out, window_cells=(c0, r0, c1, r1))
        assert np.array_equal(part.cells, whole.cells[r0:r1, c0:c1])
        assert part.resolution == whole.resolution
        # The window's lower-left corner in the map frame (no yaw in the
        # bundled maps): the origin moved by whole cells.
        assert part.origin[0] == pytest.approx(whole.origin[0] + c0 * whole.resolution)
        assert part.origin[1] == pytest.approx(whole.origin[1] + r0 * whole.resolution)


def test_window_cells_are_checked(bundled, tmp_path):
    whole = linemap.load(bundled)
    out = tmp_path / "map.lmap"
    linemap.save(out, whole)
    h, w = whole.cells.shape
    with pytest.raises(ValueError):
        linemap.load(out, window_cells=(0, 0, w + 1, h))
    with pytest.raises(ValueError):
        linemap.load(out, window_cells=(5, 5, 5, 6))
    with pytest.raises(ValueError):
        linemap.load(out, window_cells=(0, 0, 1))
    with pytest.raises(TypeError):
        linemap.load(out, window_cells="0,0,1,1")
    with pytest.raises(ValueError, match="needs an .lmap file"):
        linemap.load(bundled, window_cells=(0, 0, 1, 1))


def test_window_cells_out_of_range_or_of_the_wrong_type(bundled, tmp_path):
    out = tmp_path / "map.lmap"
    linemap.save(out, linemap.load(bundled))
    with pytest.raises(ValueError):
        linemap.load(out, window_cells=(0, 0, 2**70, 1))
    with pytest.raises(TypeError):
        linemap.load(out, window_cells=(0, 0, True, 1))
    with pytest.raises(TypeError):
        linemap.load(out, window_cells=b"\x00\x00\x01\x01")


def test_tolerance_saves_over_max_tolerance_cells_raise_memory_error(tmp_path):
    # depot is 604 x 307 = 185,428 cells.
    m = linemap.load(BUNDLED["depot"])
    out = tmp_path / "depot.lmap"
    with pytest.raises(MemoryError, match="max_tolerance_cells"):
        linemap.save(out, m, tolerance=1, max_tolerance_cells=185_427)
    assert not out.exists()
    with pytest.raises(MemoryError, match="max_tolerance_cells"):
        linemap.encode(m, tolerance=1, max_tolerance_cells=1000)
    with pytest.raises(MemoryError, match="max_tolerance_cells"):
        linemap.convert(BUNDLED["depot"], out, tolerance=2, max_tolerance_cells=1000)
    assert not out.exists()
    # At the map's size, with no limit, and for exact saves it goes ahead.
    at_limit = linemap.encode(m, tolerance=1, max_tolerance_cells=185_428)
    assert linemap.encode(m, tolerance=1, max_tolerance_cells=0) == at_limit
    exact = linemap.encode(m, max_tolerance_cells=1)
    assert np.array_equal(linemap.decode(exact).cells, m.cells)
    with pytest.raises(ValueError, match="max_tolerance_cells"):
        linemap.encode(m, tolerance=1, max_tolerance_cells=-1)
    with pytest.raises(TypeError, match="max_tolerance_cells"):
        linemap.encode(m, tolerance=1, max_tolerance_cells=1.5)


# ---------------------------------------------------------------------------
# Vectors in a window and the room at a point, against the whole file.

@pytest.fixture(scope="module")
def depot_lmap(tmp_path_factory):
    """depot saved by the module (walls, rooms and furniture), its Map and
    the whole file's vectors()."""
    m = linemap.load(BUNDLED["depot"])
    path = tmp_path_factory.mktemp("depot") / "depot.lmap"
    linemap.save(path, m)
    return path, m, linemap.vectors(path)


def cells_of(v, points):
    """Lattice points (col, row) of map-frame metres, for a map without yaw."""
    assert v["origin"][2] == 0
    xy = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    return np.rint((xy - v["origin"][:2]) / v["resolution"] - 0.5).astype(int)


def meets(v, points, window):
    """Whether the box of `points` meets the half-open cell window."""
    c0, r0, c1, r1 = window
    cells = cells_of(v, points)
    (lo_c, lo_r), (hi_c, hi_r) = cells.min(axis=0), cells.max(axis=0)
    return hi_c >= c0 and lo_c < c1 and hi_r >= r0 and lo_r < r1


def test_vectors_in_a_window_are_the_whole_files_items_whose_box_meets_it(depot_lmap):
    path, m, whole = depot_lmap
    h, w = m.cells.shape
    windows = [(0, 0, w, h), (w // 3, h // 4, w // 3 + 40, h // 4 + 30), (0, 0, 1, 1),
               (w - 1, h - 1, w, h), (w // 2, 0, w // 2 + 1, h), (100, 150, 300, 160)]
    nonempty = 0
    for window in windows:
        for source in (path, path.read_bytes()):
            got = linemap.vectors(source, window_cells=window)
            kept = [i for i, p in enumerate(whole["wall_polylines"]) if meets(whole, p, window)]
            polylines = [whole["wall_polylines"][i] for i in kept]
            assert len(got["wall_polylines"]) == len(polylines)
            # Each wall keeps its id in the whole file.
            assert got["wall_ids"].dtype == np.int64
            assert got["wall_ids"].tolist() == kept
            for a, b in zip(got["wall_polylines"], polylines):
                assert np.array_equal(a, b)
            pairs = [(*p[i], *p[i + 1]) for p in polylines for i in range(len(p) - 1)]
            assert np.array_equal(got["walls"], np.array(pairs).reshape(-1, 4))
            for layer in ("rooms", "furniture"):
                items = [item for item in whole[layer] if meets(whole, item["outline"], window)]
                assert len(got[layer]) == len(items), layer
                for a, b in zip(got[layer], items):
                    assert a.keys() == b.keys()
                    assert all(np.array_equal(a[k], b[k]) for k in a)
            for key in ("version", "width", "height", "resolution", "origin"):
                assert got[key] == whole[key]
            nonempty += len(polylines) > 0 and len(got["rooms"]) > 0
    # The whole map and the middle windows hold walls and rooms.
    assert nonempty >= 4
    assert len(linemap.vectors(path, window_cells=(0, 0, w, h))["rooms"]) == len(whole["rooms"])
    assert whole["wall_ids"].tolist() == list(range(len(whole["wall_polylines"])))


def test_vectors_window_is_checked(depot_lmap):
    path, m, _ = depot_lmap
    h, w = m.cells.shape
    for window in [(0, 0, w + 1, h), (5, 5, 5, 6), (-1, 0, 1, 1), (0, 0, 1)]:
        with pytest.raises(ValueError):
            linemap.vectors(path, window_cells=window)
        with pytest.raises(ValueError):
            linemap.vectors(path.read_bytes(), window_cells=window)
    with pytest.raises(TypeError):
        linemap.vectors(path, window_cells="0,0,1,1")


def cell_centre(m, col, row):
    """Map-frame metres of the centre of cell (col, row)."""
    x0, y0, yaw = m.origin
    u, v = (col + 0.5) * m.resolution, (row + 0.5) * m.resolution
    return (x0 + np.cos(yaw) * u - np.sin(yaw) * v, y0 + np.sin(yaw) * u + np.cos(yaw) * v)


def sample_cells(m, step):
    """Cells every `step` columns and rows, row by row from (0, 0)."""
    h, w = m.cells.shape
    return [(c, r) for r in range(0, h, step) for c in range(0, w, step)]


def test_room_at_is_a_room_of_the_file_with_the_cells_of_its_box(depot_lmap):
    path, m, whole = depot_lmap
    by_id = {room["id"]: room for room in whole["rooms"]}
    found, outside = 0, 0
    for col, row in sample_cells(m, 23):
        x, y = cell_centre(m, col, row)
        room = linemap.room_at(path, x, y)
        assert (room is None) == (linemap.room_at(path.read_bytes(), x, y) is None)
        if room is None:
            outside += 1
            continue
        found += 1
        assert set(room) == {"id", "kind", "outline", "window_cells", "map"}
        same = by_id[room["id"]]
        assert room["kind"] == same["kind"]
        assert np.array_equal(room["outline"], same["outline"])
        # The window is the box of the border chain, and holds the point.
        c0, r0, c1, r1 = room["window_cells"]
        cells = cells_of(whole, room["outline"])
        assert (c0, r0) == tuple(cells.min(axis=0)) and (c1 - 1, r1 - 1) == tuple(cells.max(axis=0))
        assert c0 <= col < c1 and r0 <= row < r1
        crop = linemap.load(path, window_cells=room["window_cells"])
        assert_same_map(room["map"], crop)
        assert np.array_equal(room["map"].cells, m.cells[r0:r1, c0:c1])
        from_bytes = linemap.room_at(path.read_bytes(), x, y)
        assert from_bytes["id"] == room["id"] and from_bytes["window_cells"] == (c0, r0, c1, r1)
        assert np.array_equal(from_bytes["map"].cells, room["map"].cells)
    assert found >= 5 and outside >= 1


def test_room_at_is_none_outside_every_room(depot_lmap):
    path, m, _ = depot_lmap
    # depot's corridor encloses most of the map: outside it lie cells near
    # the map's edge (the first, row by row, is cell (8, 4)).
    for col, row in sample_cells(m, 4):
        if linemap.room_at(path, *cell_centre(m, col, row)) is None:
            break
    else:
        pytest.fail("every sampled point of depot lies in a room")
    assert linemap.room_at(path.read_bytes(), *cell_centre(m, col, row)) is None
    # A file without rooms.
    cells_only = linemap.encode(m, vectors=False)
    assert linemap.room_at(cells_only, *cell_centre(m, 300, 150)) is None


def test_room_at_takes_the_cell_whose_square_holds_the_point(depot_lmap, tmp_path):
    """The nearest cell centre, in a map frame turned by the origin's yaw."""
    path, m, _ = depot_lmap
    turned = linemap.Map(m.cells, resolution=m.resolution, origin=(3.0, -2.0, 0.7))
    turned_path = tmp_path / "turned.lmap"
    linemap.save(turned_path, turned)
    turned_rooms = {room["id"]: room for room in linemap.vectors(turned_path)["rooms"]}
    checked = 0
    for col, row in sample_cells(m, 23):
        expected = linemap.room_at(path, *cell_centre(m, col, row))
        if expected is None:
            continue
        checked += 1
        # Points within the cell's square, near its corners.
        for dc, dr in [(0, 0), (0.45, 0.45), (-0.45, 0.45), (-0.45, -0.45), (0.45, -0.45)]:
            got = linemap.room_at(turned_path, *cell_centre(turned, col + dc, row + dr))
            assert got["id"] == expected["id"]
            assert got["window_cells"] == expected["window_cells"]
            assert np.array_equal(got["map"].cells, expected["map"].cells)
            # The outline turns with the frame, as vectors() gives it.
            assert np.array_equal(got["outline"], turned_rooms[got["id"]]["outline"])
    assert checked >= 5


def test_room_at_off_the_map_raises_value_error_naming_the_point(depot_lmap):
    path, m, _ = depot_lmap
    h, w = m.cells.shape
    # Within half a cell of cell (0, 0)'s centre is on the map; beyond is not.
    x, y = cell_centre(m, -0.4, -0.4)
    linemap.room_at(path, x, y)
    for col, row in [(-0.6, 0), (0, -0.6), (w - 0.4, 10), (10, h - 0.4), (1e9, 0)]:
        x, y = cell_centre(m, col, row)
        for source in (path, path.read_bytes()):
            with pytest.raises(ValueError, match="outside the map") as raised:
                linemap.room_at(source, x, y)
            assert "%g" % x in str(raised.value) and "%g" % y in str(raised.value)
    with pytest.raises(ValueError, match="depot.lmap"):
        linemap.room_at(path, -1.0, -1.0)
    with pytest.raises(ValueError):
        linemap.room_at(path, float("nan"), 1.0)
    with pytest.raises(FileNotFoundError):
        linemap.room_at(path.parent / "none.lmap", 1.0, 1.0)


@pytest.mark.parametrize("args", [
    [],
    ["--tolerance", "2"],
    ["--metadata", "--time", "2024-05-01T12:00:00Z", "--pose", "5,5,0.5", "--tolerance", "1"],
])
def test_info_says_what_the_cli_info_json_says(args, tmp_path, cli):
    lmap = tmp_path / "depot.lmap"
    linemap_cli.run(cli, "encode", BUNDLED["depot"], "-o", lmap, "--no-sync", *args)
    want = linemap_cli.run_json(cli, "info", lmap, "--json")
    for source in (lmap, lmap.read_bytes()):
        got = linemap.info(source)
        for key in ("version", "width", "height", "resolution", "lossless", "metadata"):
            assert got[key] == want[key], key
        assert list(got["origin"]) == want["origin"]
        assert got["tolerance"] == want["tolerance_cells"]
    expected_tolerance = int(args[args.index("--tolerance") + 1]) if "--tolerance" in args else None
    assert got["tolerance"] == expected_tolerance
    assert ("robot_pose" in got["metadata"]) == ("--pose" in args)


def test_info_of_a_file_saved_within_a_tolerance_names_it(tmp_path):
    m = linemap.load(BUNDLED["depot"])
    path = tmp_path / "t3.lmap"
    linemap.save(path, m, tolerance=3)
    info = linemap.info(path)
    assert info["lossless"] is False and info["tolerance"] == 3
    assert info["metadata"] == {"tolerance": "3"}
    linemap.save(path, m)
    assert linemap.info(path)["tolerance"] is None and linemap.info(path)["lossless"] is True


def test_info_errors_name_the_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="nope.lmap"):
        linemap.info(tmp_path / "nope.lmap")
    bad = tmp_path / "bad.lmap"
    bad.write_bytes(b"not an lmap file")
    with pytest.raises(ValueError, match="bad.lmap"):
        linemap.info(bad)


def test_paths_are_the_file_systems_bytes(tmp_path):
    # A name that is not UTF-8 (os.fsdecode gives it surrogate escapes) is
    # saved, read and reported under its own bytes, as open() would.
    m = linemap.load(BUNDLED["depot"])
    name = os.fsdecode(os.fsencode(str(tmp_path)) + b"/lat\xff.lmap")
    linemap.save(name, m)
    assert os.listdir(tmp_path) == ["lat\udcff.lmap"]
    assert linemap.info(name)["width"] == m.width
    assert linemap.load(os.fsencode(name)).width == m.width
    missing = os.fsdecode(os.fsencode(str(tmp_path)) + b"/no\xff/x.lmap")
    with pytest.raises(FileNotFoundError) as caught:
        linemap.load(missing)
    assert missing in str(caught.value)


def test_a_path_with_a_nul_byte_is_refused_as_open_refuses_it(tmp_path):
    # The C library would end the name at the NUL and write another file.
    m = linemap.load(BUNDLED["depot"])
    with pytest.raises(ValueError):
        open(tmp_path / "x\0.lmap", "wb")
    for call in (lambda p: linemap.save(p, m), linemap.load, linemap.info):
        with pytest.raises(ValueError, match="null byte"):
            call(str(tmp_path / "new") + "\0x.lmap")
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("bad, error", [(True, TypeError), (2.0, TypeError), ("2", TypeError),
                                        (None, TypeError), (-1, ValueError), (5, ValueError)])
def test_save_tolerance_is_checked_as_eval_checks_it(bad, error, tmp_path):
    # One rule and one message for save, convert, encode and eval: a bool
    # is not a number of cells (True saved a T = 1 file before).
    m = linemap.load(BUNDLED["lse_arena"])
    calls = [lambda: linemap.save(tmp_path / "x.lmap", m, tolerance=bad),
             lambda: linemap.convert(BUNDLED["lse_arena"], tmp_path / "x.lmap", tolerance=bad),
             lambda: linemap.encode(m, tolerance=bad)]
    if bad is not None:
        calls.append(lambda: linemap.eval(m, m, tolerance=bad))
    for call in calls:
        with pytest.raises(error, match=r"tolerance must be .*0\.\.4.*not " + repr(bad)):
            call()
    assert not (tmp_path / "x.lmap").exists()


# metadata= stores the keys info() returns, checked as `linemap encode`
# checks them; the file's cells are the map's either way.
def test_metadata_is_stored_and_read_back_by_info(tmp_path, cli):
    m = linemap.load(BUNDLED["lse_arena"])
    given = {"creator": "robot 7", "time": "2026-11-29T17:45:12.25Z", "frame_id": "floor_2",
             "robot_pose": (1.5, 2.25, 0.5)}
    path = tmp_path / "m.lmap"
    linemap.save(path, m, metadata=given)
    stored = linemap.info(path)["metadata"]
    assert stored == {"creator": "robot 7", "time": "2026-11-29T17:45:12.25Z",
                      "frame_id": "floor_2", "robot_pose": "1.5 2.25 0.5"}
    assert np.array_equal(linemap.load(path).cells, m.cells)
    # What info() gives back saves again the same, through encode() and
    # convert() too.
    assert linemap.info(linemap.encode(m, metadata=stored))["metadata"] == stored
    converted = tmp_path / "c.lmap"
    linemap.convert(BUNDLED["lse_arena"], converted, metadata=stored)
    assert linemap.info(converted)["metadata"] == stored
    # As the CLI stores it.
    linemap_cli.run(cli, "encode", BUNDLED["lse_arena"], "-o", str(tmp_path / "cli.lmap"),
                    "--time", "2026-11-29T17:45:12.25Z", "--pose", "1.5,2.25,0.5")
    cli_meta = linemap.info(tmp_path / "cli.lmap")["metadata"]
    assert cli_meta["time"] == stored["time"] and cli_meta["robot_pose"] == stored["robot_pose"]


@pytest.mark.parametrize("metadata, error, match", [
    ({"time": "yesterday"}, ValueError, "metadata\\['time'\\] 'yesterday' is not an ISO 8601"),
    ({"time": "2026-02-30"}, ValueError, "is not an ISO 8601"),
    ({"time": "2026-01-01\n"}, ValueError, "control character 0x0a"),
    ({"tolerance": "1"}, ValueError, "written by the encoder"),
    ({"owner": "me"}, ValueError, "'owner' is none of creator, time, frame_id, robot_pose"),
    ({"creator": 7}, TypeError, "metadata\\['creator'\\] must be a str"),
    ({"robot_pose": "1 2 3 4"}, ValueError, "robot_pose"),
    ({"robot_pose": (1.0,)}, ValueError, "robot_pose"),
    ({"robot_pose": (1.0, float("nan"))}, ValueError, "robot_pose"),
    ({"robot_pose": (-50.0, 1.0)}, ValueError, "outside the map"),
    ("creator=me", TypeError, "metadata must be a dict"),
])
def test_bad_metadata_is_refused_and_nothing_written(tmp_path, metadata, error, match):
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(error, match=match):
        linemap.save(tmp_path / "m.lmap", m, metadata=metadata)
    assert list(tmp_path.iterdir()) == []


def test_metadata_applies_to_lmap_files_only(tmp_path):
    m = linemap.load(BUNDLED["lse_arena"])
    with pytest.raises(ValueError, match="metadata applies to .lmap files only"):
        linemap.save(tmp_path / "m.yaml", m, metadata={"creator": "me"})
    assert list(tmp_path.iterdir()) == []


# A map loaded from a file saved within T cells keeps T, and a save of it
# says so, as `linemap encode` of that file does: the copy is exact but not
# the robot's map, and its guarantees are checked against the original.
def test_a_map_loaded_from_a_tolerance_file_keeps_its_tolerance(tmp_path, cli):
    from conftest import REPO
    fixture = REPO / "tests" / "data" / "lmap" / "willow_v2_3_tolerance_1.lmap"
    m = linemap.load(fixture)
    assert m.tolerance == 1
    assert linemap.decode(fixture.read_bytes()).tolerance == 1
    assert linemap.load(fixture, window_cells=(10, 10, 60, 40)).tolerance == 1
    # (15, 20) m lies in one of its rooms; the room's cells keep T too.
    assert linemap.room_at(fixture, 15.0, 20.0)["map"].tolerance == 1
    assert linemap.load(BUNDLED["willow"]).tolerance is None
    exact = tmp_path / "exact.lmap"
    linemap.save(exact, linemap.load(BUNDLED["willow"]))
    assert linemap.load(exact).tolerance is None
    copy = tmp_path / "copy.lmap"
    linemap.save(copy, m, compact=True)
    info = linemap.info(copy)
    assert info["tolerance"] == 1 and not info["lossless"]
    assert np.array_equal(linemap.load(copy).cells, m.cells)
    assert linemap.info(linemap.encode(m))["tolerance"] == 1
    # The CLI's check of the copy against the robot's map: its guarantees
    # at the T it names.
    linemap_cli.run(cli, "eval", BUNDLED["willow"], str(copy), "--check")
    # eval() of the Map itself checks it at that T too.
    checked = linemap.eval(linemap.load(BUNDLED["willow"]), m)
    assert checked["tolerance_from_file"] and checked["tolerance_holds"]
    with pytest.raises(ValueError, match="saved within a tolerance of 1 cells"):
        linemap.save(tmp_path / "again.lmap", m, tolerance=2)
    assert not (tmp_path / "again.lmap").exists()
    # Pickles keep it; those made before maps kept it have no key.
    assert pickle.loads(pickle.dumps(m)).tolerance == 1
    state = m.__getstate__()
    del state["tolerance"]
    old = linemap.Map.__new__(linemap.Map)
    old.__setstate__(state)
    assert old.tolerance is None


# A file whose cells are not the robot's map but which names no T (a 2.2
# tolerance file written before files named it, a lossy 1.0 file) cannot
# be copied as if it were exact, as `linemap encode` refuses it; its YAML
# save (what `linemap decode` writes) is allowed.
@pytest.mark.parametrize("name", ["willow_v2_2_tolerance_1.lmap", "depot_lossy.lmap"])
def test_a_map_from_a_lossy_file_without_a_tolerance_is_not_saved_as_exact(tmp_path, name):
    from conftest import REPO
    m = linemap.load(REPO / "tests" / "data" / "lmap" / name)
    assert m.tolerance is None
    for save in (lambda: linemap.save(tmp_path / "copy.lmap", m), lambda: linemap.encode(m)):
        with pytest.raises(ValueError, match="names no tolerance"):
            save()
    assert not (tmp_path / "copy.lmap").exists()
    # The same after a pickle round trip.
    with pytest.raises(ValueError, match="names no tolerance"):
        linemap.encode(pickle.loads(pickle.dumps(m)))
    linemap.save(tmp_path / "copy.yaml", m)
    assert (tmp_path / "copy.pgm").exists()


# A window is never dropped: a file named .LMAP that is no .lmap file is
# refused as one, not read whole as a map image.
def test_a_window_of_a_file_named_lmap_in_capitals_is_read_as_lmap(tmp_path):
    image = tmp_path / "x.LMAP"
    shutil.copy(MAPS / "nav2" / "depot.pgm", image)
    with pytest.raises(ValueError):
        linemap.load(image, window_cells=(0, 0, 10, 10))
