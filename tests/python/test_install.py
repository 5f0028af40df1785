"""`cmake --install` puts the module where Debian's python3 looks for the
prefix, and it imports from there."""
import os
import pathlib
import site
import subprocess
import sys

import pytest

linemap = pytest.importorskip("linemap")


def test_installed_module_is_on_debian_pythons_path(tmp_path):
    build = os.environ.get("LINEMAP_BUILD_DIR")
    if not build:
        pytest.skip("LINEMAP_BUILD_DIR (set by ctest) names no build directory")
    prefix = tmp_path / "prefix"
    done = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    found = sorted(prefix.rglob("linemap*.so"))
    assert len(found) == 1, found
    # site.getsitepackages gives the directories python3 searches under a
    # prefix (on Debian: lib/python3/dist-packages, lib/python3.X/dist-packages).
    searched = [pathlib.Path(p) for p in site.getsitepackages([str(prefix)])]
    assert found[0].parent in searched
    # The type stubs beside it (editors, pyright) and as a stub-only
    # package (PEP 561, where mypy looks).
    assert (found[0].parent / "linemap.pyi").is_file()
    assert (found[0].parent / "linemap-stubs" / "__init__.pyi").is_file()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(found[0].parent)
    done = subprocess.run([sys.executable, "-c", "import linemap; print(linemap.__file__)"],
                          env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == str(found[0])
