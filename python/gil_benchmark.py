"""How much Python work one thread gets done while another runs linemap.

The main thread counts loop turns for as long as a second thread repeats a
call for 0.5 s: beside time.sleep (the baseline), linemap.encode (which
releases the GIL, so the count stays near the baseline on a machine with a
free core) and sorted() of a long list (which holds the GIL: the count
collapses). Run from the repository root after building:

    PYTHONPATH=build/python /usr/bin/python3 python/gil_benchmark.py
"""
import random
import threading
import time

import linemap

MAP = "tests/data/maps/turtlebot_apps/willow-2010-02-18-0.10.yaml"


def main_loop_beside(task, seconds=0.5):
    """Turns of a bare loop in this thread while another repeats `task`."""
    done = threading.Event()

    def work():
        start = time.perf_counter()
        while time.perf_counter() - start < seconds:
            task()
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    turns = 0
    while not done.is_set():
        turns += 1
    worker.join()
    return turns


def main():
    m = linemap.load(MAP)
    numbers = [random.random() for _ in range(300000)]
    for _ in range(3):
        idle = main_loop_beside(lambda: time.sleep(0.01))
        encode = main_loop_beside(lambda: linemap.encode(m, vectors=False))
        sort = main_loop_beside(lambda: sorted(numbers))
        print(f"main-thread loop turns in 0.5 s: beside sleep {idle}, "
              f"beside linemap.encode {encode} ({encode / idle:.0%}), "
              f"beside sorted() {sort} ({sort / idle:.0%})")


if __name__ == "__main__":
    main()
