"""Runs the `linemap` program, the reference the module's results are
checked against."""
import csv
import json
import subprocess


def run(cli, *args):
    """stdout of `linemap ARGS`; fails the test on a non-zero exit."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def run_json(cli, *args, expect_exit=0):
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == expect_exit, done.stderr
    return json.loads(done.stdout)


def read_csv_rows(path):
    """{layer: [(x1, y1, x2, y2), ...]} of a layer,x1,y1,x2,y2 CSV."""
    layers = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            layers.setdefault(row["layer"], []).append(
                tuple(float(row[k]) for k in ("x1", "y1", "x2", "y2")))
    return layers
