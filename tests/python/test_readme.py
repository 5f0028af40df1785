"""The README's Python example runs, and prints what its `# ->` comments say."""
import contextlib
import io
import os
import re

import pytest

linemap = pytest.importorskip("linemap")


def python_section_example(readme):
    section = readme.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert len(blocks) == 1
    return blocks[0]


def test_readme_example_runs_and_prints_what_it_says(repo, tmp_path, monkeypatch):
    code = python_section_example((repo / "README.md").read_text())
    expected = [line.split("# -> ", 1)[1].strip() for line in code.splitlines()
                if "# -> " in line]
    assert expected, "the example shows no output"
    # Run where its relative paths work and its output file does no harm.
    os.symlink(repo / "tests", tmp_path / "tests")
    monkeypatch.chdir(tmp_path)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "README.md", "exec"), {})
    assert out.getvalue().splitlines() == expected
    assert (tmp_path / "depot.lmap").exists()
