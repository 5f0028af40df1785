"""Shared fixtures of the linemap Python tests.

The module comes from PYTHONPATH (build/python when ctest runs the suite);
every test is skipped when it is not built. Tests that compare with the
`linemap` program find it through LINEMAP_CLI (set by ctest) or at
build/linemap, and are skipped without it.
"""
import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
MAPS = REPO / "tests" / "data" / "maps"

# The bundled maps: (name, YAML path). Every one is small (<= 344 k cells).
BUNDLED = {
    "depot": MAPS / "nav2" / "depot.yaml",
    "lse_arena": MAPS / "navtut" / "lse_arena.yaml",
    "kth": MAPS / "strands" / "kth" / "map.yaml",
    "willow": MAPS / "turtlebot_apps" / "willow-2010-02-18-0.10.yaml",
}


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def cli():
    """Path of the `linemap` program."""
    path = os.environ.get("LINEMAP_CLI") or str(REPO / "build" / "linemap")
    if not os.access(path, os.X_OK):
        pytest.skip("the linemap program is not built (" + path + ")")
    return path
