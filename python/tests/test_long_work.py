"""Long work: the GIL released (two threads run two cases at once), progress reported,
Ctrl-C (SIGINT) stopping a long run, the engine's threads limited."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import dyncontact

# about a second of marching on one core
CASE = dict(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=20, c1=1870.83, c2=1000)


def test_two_threads_run_two_cases_at_once():
    # Each thread takes the GIL to start its case: were the GIL held while a case computes,
    # the other thread could not start before it ended. So the two runs overlap in time
    # exactly when the GIL is released; no timing threshold (a loaded machine cannot fail
    # it). The speed-up itself is printed, for the record.
    dyncontact.impact.run(**CASE)  # warm
    t0 = time.perf_counter()
    dyncontact.impact.run(**CASE)
    one = time.perf_counter() - t0
    barrier = threading.Barrier(2)
    spans: list[tuple[float, float]] = []
    results = []

    def work() -> None:
        barrier.wait()
        start = time.perf_counter()
        results.append(dyncontact.impact.run(**CASE))
        spans.append((start, time.perf_counter()))

    threads = [threading.Thread(target=work) for _ in range(2)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    two = time.perf_counter() - t0
    print(f"two cases in two threads / one case: {two / one:.2f} (one case {one:.2f} s, {os.cpu_count()} cores)")
    assert len(results) == 2
    assert results[0].to_dict() == results[1].to_dict()
    overlap = min(end for _, end in spans) - max(start for start, _ in spans)
    assert overlap > 0.5 * one, (spans, one)


def test_python_runs_while_a_case_computes():
    # with the GIL held, the loop below could not count while the case runs
    done = threading.Event()
    t = threading.Thread(target=lambda: (dyncontact.impact.run(**CASE), done.set()))
    count = 0
    t.start()
    while not done.is_set():
        count += 1
        time.sleep(0.001)
    t.join()
    assert count > 50, count


def test_progress_reaches_one():
    seen = []
    dyncontact.impact.run(**CASE, progress=seen.append)
    assert seen and seen[-1] == 1.0
    assert all(0.0 <= f <= 1.0 for f in seen)
    assert seen == sorted(seen)
    rows = []
    dyncontact.wedge.curve(theta_deg=86, alpha_range=(100, 900, 40), progress=rows.append)
    assert rows[-1] == 1.0


def test_a_raising_progress_callable_stops_the_run():
    def stop(f):
        if f > 0.0:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        dyncontact.impact.run(**{**CASE, "end": 60}, progress=stop)


def test_thread_limit():
    try:
        dyncontact.set_num_threads(1)
        assert dyncontact.get_num_threads() == 1
        r = dyncontact.wedge.curve(theta_deg=86, alpha_range=(100, 500, 3))
        assert len(r) == 3
    finally:
        dyncontact.set_num_threads(0)
    assert dyncontact.get_num_threads() >= 1


@pytest.mark.parametrize("call", ["impact", "curve"])
def test_sigint_stops_a_long_run(call):
    work = {
        "impact": "dyncontact.impact.run(profile='parabola:R=1', mass_ratio=10, v0_over_c1=0.01, end=80, kappa=1, memory_limit_gib=16, c1=1870.83, c2=1000)",
        "curve": "dyncontact.wedge.curve(theta_deg=86, gamma=0.5, alpha_range=(100, 900, 2000), digits=40)",
    }[call]
    # the child takes Python's own SIGINT handler whatever it inherits (a shell's background
    # job starts with SIGINT ignored, and Python keeps an ignored SIGINT ignored)
    script = textwrap.dedent(f"""
        import signal, sys, time, dyncontact
        signal.signal(signal.SIGINT, signal.default_int_handler)
        print("started", flush=True)
        t = time.perf_counter()
        try:
            {work}
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(7)
        print("finished", flush=True)
    """)
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "started"
    time.sleep(1.5)
    assert p.poll() is None, "the run ended before the signal"
    sent = time.perf_counter()
    p.send_signal(signal.SIGINT)
    p.wait(timeout=30)
    stopped = time.perf_counter() - sent
    out = p.stdout.read()
    assert p.returncode == 7, out
    assert "interrupted" in out
    print(f"{call}: stopped {stopped:.2f} s after SIGINT")
    assert stopped < 1.0, stopped
