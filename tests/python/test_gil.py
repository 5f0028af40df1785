"""Encoding releases the GIL: two threads encoding at once both finish and
give the bytes one thread gives."""
import threading

import pytest

from conftest import BUNDLED

linemap = pytest.importorskip("linemap")


def test_two_threads_encode_the_same_bytes_as_one():
    maps = [linemap.load(BUNDLED["willow"]), linemap.load(BUNDLED["kth"])]
    alone = [linemap.encode(m, vectors=v) for m in maps for v in (True, False)]
    results = {}

    def work(name, m):
        results[name] = [linemap.encode(m, vectors=v) for v in (True, False)]

    threads = [threading.Thread(target=work, args=(i, m)) for i, m in enumerate(maps)]
    threads.append(threading.Thread(target=work, args=(2, maps[0])))  # the same map twice
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert not any(t.is_alive() for t in threads)
    assert results[0] + results[1] == alone
    assert results[2] == alone[:2]


def test_threads_decode_and_plan_at_once():
    m = linemap.load(BUNDLED["depot"])
    data = linemap.encode(m)
    expected_plan = linemap.plan(m, (1, 1), (20, 10))["waypoints"].tolist()
    out = {}

    def decode():
        out["decoded"] = [linemap.decode(data).cells.copy() for _ in range(5)]

    def plan():
        out["plans"] = [linemap.plan(m, (1, 1), (20, 10))["waypoints"].tolist() for _ in range(3)]

    threads = [threading.Thread(target=decode), threading.Thread(target=plan)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert all((c == m.cells).all() for c in out["decoded"])
    assert out["plans"] == [expected_plan] * 3
