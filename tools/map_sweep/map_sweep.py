"""The maps an outsider would try: every map YAML of a folder as it is,
transposed, flipped, cropped to odd sizes, with 1 % of its cells set at
random, with free and unknown swapped and (up to 400,000 cells) twice as
fine, plus degenerate grids (1 x 1, one row, one column, all free, all
unknown, all occupied, random, a checkerboard, stripes), through every
encode mode: the exact files (default, --raster-only, --compact) must
decode to the map cell for cell and export, and the files saved within
T = 1..4 (maps up to 1.2 Mcells) must keep every guarantee by
`linemap eval --tolerance T`. Prints the problems found; exit 1 if any.

Run from the repository root with Debian's Python (it has numpy):

  /usr/bin/python3 tools/map_sweep/map_sweep.py [MAPS_DIR] [OUT_DIR]

(defaults ../shared/maps and /tmp/linemap-map-sweep; needs build/linemap
and the module in build/python; about 6 minutes on 2 cores for the 20 map
YAMLs of ../shared/maps.)"""
import glob, json, os, subprocess, sys, time
import numpy as np
sys.path.insert(0, "build/python")
import linemap

CLI = "build/linemap"
MAPS = sys.argv[1] if len(sys.argv) > 1 else "../shared/maps"
OUT = sys.argv[2] if len(sys.argv) > 2 else "/tmp/linemap-map-sweep"
os.makedirs(OUT, exist_ok=True)
maps = sorted(glob.glob(os.path.join(MAPS, "**/*.yaml"), recursive=True))
# nav2's empty_room.yaml names an image that is not there.
maps = [m for m in maps if "empty_room" not in m]

def variants(m):
    c = m.cells
    yield "orig", c
    yield "transpose", c.T.copy()
    yield "flipud", c[::-1].copy()
    yield "crop_odd", c[1:-2, 3:-1].copy() if c.shape[0] > 5 and c.shape[1] > 5 else c
    rng = np.random.default_rng(len(c))
    noisy = c.copy(); mask = rng.random(c.shape) < 0.01
    noisy[mask] = rng.integers(0, 3, mask.sum()).astype(np.uint8)
    yield "noise1pct", noisy
    inv = c.copy(); inv[c == 0] = 2; inv[c == 2] = 0
    yield "free_unknown_swapped", inv
    if c.size < 400_000:
        yield "up2", np.repeat(np.repeat(c, 2, 0), 2, 1)

def degenerate():
    yield "1x1", np.zeros((1, 1), np.uint8)
    yield "1x500", (np.arange(500) % 3).astype(np.uint8).reshape(1, 500)
    yield "500x1", np.ones((500, 1), np.uint8)
    yield "2x2occ", np.ones((2, 2), np.uint8)
    yield "allfree", np.zeros((300, 257), np.uint8)
    yield "allunknown", np.full((300, 257), 2, np.uint8)
    yield "allocc", np.ones((129, 300), np.uint8)
    rng = np.random.default_rng(7)
    yield "random", rng.integers(0, 3, (200, 333)).astype(np.uint8)
    yield "checker", (np.indices((256, 256)).sum(0) % 2).astype(np.uint8)
    stripes = np.zeros((300, 300), np.uint8); stripes[:, ::2] = 1
    yield "stripes", stripes

def run(args, timeout=600):
    t = time.time()
    p = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    return p, time.time() - t

problems = []
def check(name, cells, res=0.05):
    base = f"{OUT}/{name}"
    linemap.save(base + ".yaml", linemap.Map(cells, resolution=res))
    modes = [("exact", []), ("raster", ["--raster-only"]), ("compact", ["--compact"])]
    if cells.size <= 1_200_000:
        modes += [(f"t{t}", ["--tolerance", str(t)]) for t in (1, 2, 3, 4)]
    for mode, extra in modes:
        f = f"{base}.{mode}.lmap"
        p, dt = run([CLI, "encode", base + ".yaml", "-o", f, "--no-png-ratio"] + extra)
        if p.returncode != 0:
            problems.append((name, mode, "encode rc", p.returncode, p.stderr.strip()[:300])); continue
        if mode in ("exact", "raster", "compact"):
            d = linemap.load(f)
            if not np.array_equal(d.cells, cells):
                problems.append((name, mode, "not exact"))
        else:
            p2, _ = run([CLI, "eval", base + ".yaml", f, "--tolerance", mode[1], "--json"])
            if p2.returncode != 0:
                problems.append((name, mode, "eval rc", p2.returncode, p2.stderr.strip()[:300])); continue
            j = json.loads(p2.stdout)
            if j.get("tolerance_holds") is not True:
                problems.append((name, mode, "guarantee", json.dumps(j)[:600]))
        if mode == "exact":
            for ext in ("svg", "geojson", "csv"):
                p3, _ = run([CLI, "export", f, "-o", f"{base}.{ext}"])
                if p3.returncode != 0:
                    problems.append((name, mode, "export " + ext, p3.stderr.strip()[:300]))
        if dt > 20:
            problems.append((name, mode, "slow", round(dt, 1), cells.shape))
    print(name, cells.shape, "done", flush=True)

for n, c in degenerate():
    check("deg_" + n, c)
for path in maps:
    m = linemap.load(path)
    stem = os.path.relpath(path, MAPS).replace("/", "__").replace(".yaml", "")
    for v, c in variants(m):
        check(f"{stem}.{v}", c, m.resolution)
print("PROBLEMS", len(problems))
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
