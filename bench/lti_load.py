#!/usr/bin/env python3
"""Load on `raygrade serve` (a benchmark, not a test): N simulated students (200 by default)
launched through the test platform of tests/lti, then all submitting at once (a barrier lets
their threads go together). Prints the median and 99th-percentile time from sending a
submission to its graded answer, the time until the platform has every score, and the server's
peak resident memory (VmHWM of /proc/PID/status). Loopback only; bounded (every request has a
timeout, the whole run a deadline) and stops by itself.

Browsers keep their connections to the tool open between requests; --close makes each student
close them after each answer, to tell the server's handling of idle connections from its grading.

Usage: bench/lti_load.py [--students 200] [--close] [--raygrade build/release/grader/raygrade]"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LTI_DIR = os.path.join(ROOT, "tests", "lti")
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != LTI_DIR] + [LTI_DIR]

import argparse  # noqa: E402
import concurrent.futures  # noqa: E402
import json  # noqa: E402
import shutil  # noqa: E402
import statistics  # noqa: E402
import tempfile  # noqa: E402
import threading  # noqa: E402
import time  # noqa: E402


def proc_status(pid, field):
    """A field of /proc/PID/status in kB (VmHWM, VmRSS), or None."""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def percentile(values, q):
    """The q-th percentile (0..100) by the nearest-rank method."""
    ordered = sorted(values)
    rank = max(1, int(-(-q * len(ordered) // 100)))
    return ordered[rank - 1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--raygrade", default=None)
    ap.add_argument("--deadline", type=float, default=600, help="seconds for the whole run")
    ap.add_argument("--close", action="store_true",
                    help="each student closes its connections once launched and once answered"
                         " (no idle keep-alive connections, unlike a browser)")
    ap.add_argument("--postgresql", action="store_true", help="the tool on PostgreSQL")
    ap.add_argument("--servers", type=int, default=1,
                    help="servers on one PostgreSQL database (with --postgresql)")
    args = ap.parse_args()
    if args.servers > 1 and not args.postgresql:
        ap.error("several servers share a PostgreSQL database: add --postgresql")
    if args.postgresql:
        os.environ["RAYGRADE_TEST_DATABASE"] = "postgresql"
    if args.raygrade:
        os.environ["RAYGRADE"] = os.path.abspath(args.raygrade)
    import requests
    import ltitest
    start_all = time.time()
    tmp = tempfile.mkdtemp(prefix="raygrade-lti-load-")
    pstate, data = os.path.join(tmp, "platform"), os.path.join(tmp, "data")
    os.makedirs(pstate)
    pproc, platform = ltitest.start_platform(pstate)
    tproc, tool = ltitest.start_tool(data)
    procs, tools = [tproc], [tool]
    for i in range(1, args.servers):
        p, t = ltitest.start_tool(os.path.join(tmp, f"data-{i}"), public_url=tool,
                                  database=ltitest.database_url(data))
        procs.append(p)
        tools.append(t)
    try:
        s = ltitest.browser()
        t = s.post(f"{platform}/test/registration-token", timeout=30).json()
        r = s.get(f"{tool}/lti/register", params={"openid_configuration": t["openid_configuration"],
                                                   "registration_token": t["token"]}, timeout=60)
        r.raise_for_status()
        points = ltitest.assignment_points()
        link = s.post(f"{platform}/test/link", json={
            "title": "Homework", "custom": {"assignment": ltitest.ASSIGNMENT},
            "scoreMaximum": points}, timeout=30).json()["id"]

        def launch(i):
            b = ltitest.browser()
            r, launch_data = ltitest.launch(platform, b, user=f"student-{i:03d}", role="Learner",
                                            link=link)
            if r.status_code != 200 or not launch_data:
                raise RuntimeError(f"launch {i}: {r.status_code} {r.text[:200]}")
            if args.close:
                b.close()
            return b, launch_data

        t0 = time.time()
        with concurrent.futures.ThreadPoolExecutor(8) as pool:
            students = list(pool.map(launch, range(args.students)))
        launch_seconds = time.time() - t0
        answers = ltitest.solve(ltitest.student_key(students[0][1]))
        barrier = threading.Barrier(args.students)
        times, failures = [], []
        lock = threading.Lock()

        def hand_in(student, server):
            b, launch_data = student
            submit = launch_data["submit"].replace(tool, tools[server], 1)
            barrier.wait(timeout=120)
            t = time.perf_counter()
            try:
                r = b.post(submit, json={"launch": launch_data["launch"],
                                                        "csrf": launch_data["csrf"],
                                                        "answers": answers}, timeout=120)
                ok = r.status_code == 200 and "score" in r.json()
            except (requests.RequestException, ValueError) as e:
                ok, r = False, e
            elapsed = time.perf_counter() - t
            if args.close:
                b.close()
            with lock:
                (times if ok else failures).append(elapsed if ok else str(r)[:200])

        peak_rss = [0]
        done = threading.Event()

        def sample():
            while not done.is_set():
                peak_rss[0] = max(peak_rss[0],
                                  sum(proc_status(p.pid, "VmRSS") or 0 for p in procs))
                time.sleep(0.02)
        sampler = threading.Thread(target=sample, daemon=True)
        sampler.start()
        threads = [threading.Thread(target=hand_in, args=(x, i % len(tools)), daemon=True)
                   for i, x in enumerate(students)]
        t0 = time.time()
        for th in threads:
            th.start()
        for th in threads:
            th.join(max(1, args.deadline - (time.time() - start_all)))
        wall = time.time() - t0
        # Every score at the platform (the outbox's work), bounded by the deadline.
        scores = []
        while time.time() - start_all < args.deadline:
            scores = requests.get(f"{platform}/test/scores", timeout=30).json()
            if len(scores) >= len(times):
                break
            time.sleep(0.1)
        all_scores = time.time() - t0
        done.set()
        hwm = [proc_status(p.pid, "VmHWM") for p in procs]
        result = {
            "students": args.students, "graded": len(times), "failed": len(failures),
            "database": "postgresql" if args.postgresql else "sqlite", "servers": len(procs),
            "answers_per_s": round(len(times) / wall, 1) if wall else None,
            "launch_s": round(launch_seconds, 2),
            "median_s": round(statistics.median(times), 3) if times else None,
            "p99_s": round(percentile(times, 99), 3) if times else None,
            "max_s": round(max(times), 3) if times else None,
            "all_answers_s": round(wall, 3), "all_scores_at_platform_s": round(all_scores, 3),
            "scores_received": len(scores), "servers_peak_rss_kib": hwm,
            "servers_sampled_rss_kib": peak_rss[0], "cores": os.cpu_count(),
            "connections": "closed after each answer" if args.close else "kept alive, as a browser",
        }
        print(json.dumps(result, indent=1))
        for f in failures[:5]:
            print("failure:", f, file=sys.stderr)
        return 0 if not failures else 1
    finally:
        for p in procs:
            p.stop()
        pproc.stop()
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
