#!/usr/bin/python3
"""Helpers of bench/peers/openfoam.sh (standard library only; /usr/bin/python3).

  stamp                     copy standard input to standard output, each line
                            prefixed with the seconds since the start and a tab
  foam-solve LOG            from a stamped moveMesh log: the seconds from
                            "Time = 1" to the last linear solve line, and the
                            GAMG cycles per component, as JSON
  boundary-error BASE MOVED CSV
                            the largest |moved - base - d| over the nodes of
                            CSV (node,dx,dy,dz: `dgwarp motion-field`), BASE
                            and MOVED OpenFOAM points files (ascii or binary)
  record OUT.jsonl key=value ...
                            append one run's figures to OUT.jsonl, reading the
                            files the keys name (time_file, foam_log,
                            deform_json, deform_err, quality_json,
                            checkmesh_log)
  table OUT.jsonl           the markdown tables and the time ratios
"""
import json
import re
import struct
import sys
import time
from array import array


def stamp():
    start = time.monotonic()
    for line in sys.stdin:
        sys.stdout.write("%.3f\t%s" % (time.monotonic() - start, line))
        sys.stdout.flush()


def foam_solve(log):
    t_start = t_end = None
    cycles = {}
    with open(log) as f:
        for line in f:
            t, _, text = line.partition("\t")
            if text.startswith("Time = ") and t_start is None:
                t_start = float(t)
            m = re.match(r"(\w+):\s+Solving for (\w+), Initial residual = (\S+), Final residual = (\S+), "
                         r"No Iterations (\d+)", text)
            if m:
                t_end = float(t)
                cycles[m.group(2)] = int(m.group(5))
    solve = None if t_start is None or t_end is None else t_end - t_start
    print(json.dumps({"solve_seconds": solve, "cycles": cycles}))


def read_foam_points(path):
    """The coordinates of an OpenFOAM vectorField file, flat (x0 y0 z0 x1 ...)."""
    with open(path, "rb") as f:
        data = f.read()
    head_end = data.index(b"}", data.index(b"FoamFile")) + 1
    binary = re.search(rb"format\s+binary", data[:head_end]) is not None
    m = re.compile(rb"\n\s*(\d+)\s*\(").search(data, head_end)
    n = int(m.group(1))
    start = m.end()
    if binary:
        values = array("d")
        values.frombytes(data[start:start + 24 * n])
        if sys.byteorder != "little":
            values.byteswap()
        return values
    body = data[start:data.index(b"\n)", start)]
    values = array("d", (float(x) for x in body.replace(b"(", b" ").replace(b")", b" ").split()))
    if len(values) != 3 * n:
        raise SystemExit("%s: %d numbers for %d points" % (path, len(values), n))
    return values


def boundary_error(base_file, moved_file, csv_file):
    base, moved = read_foam_points(base_file), read_foam_points(moved_file)
    worst = 0.0
    with open(csv_file) as f:
        next(f)
        for line in f:
            parts = line.split(",")
            n = int(parts[0])
            for d in range(3):
                worst = max(worst, abs(moved[3 * n + d] - base[3 * n + d] - float(parts[1 + d])))
    print("%.3g" % worst)


def time_v(path):
    """Wall seconds, CPU seconds (user + system) and peak memory (MB) of a /usr/bin/time -v report; its
    "Wall seconds" line (openfoam.sh's nanosecond clock), when there is one, rather than GNU time's 10 ms."""
    wall = rss = cpu = None
    wall_ns = None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith(("User time", "System time")):
                cpu = (cpu or 0.0) + float(line.rsplit(" ", 1)[1])
            elif line.startswith("Elapsed (wall clock) time"):
                parts = [float(x) for x in line.rsplit(" ", 1)[1].split(":")]
                wall = 0.0
                for p in parts:
                    wall = wall * 60 + p
            elif line.startswith("Wall seconds:"):
                wall_ns = float(line.rsplit(" ", 1)[1])
            elif line.startswith("Maximum resident set size"):
                rss = int(line.rsplit(" ", 1)[1]) / 1024.0
    return (wall if wall_ns is None else wall_ns), cpu, rss


def checkmesh_status(path):
    with open(path) as f:
        text = f.read()
    if "Mesh OK." in text:
        return "Mesh OK"
    m = re.search(r"Failed (\d+) mesh checks", text)
    return "failed %s checks" % m.group(1) if m else "no verdict"


def record(out, pairs):
    r = dict(p.split("=", 1) for p in pairs)
    row = {k: r[k] for k in ("case", "label", "tool", "setup", "status", "boundary_error", "wall_seconds")
           if k in r}
    if r.get("wall_seconds"):
        row["wall_seconds"] = float(r["wall_seconds"])
    if r.get("time_file"):
        wall, cpu, rss = time_v(r["time_file"])
        row["wall_seconds"], row["cpu_seconds"], row["peak_mb"] = wall, cpu, rss
    if r.get("foam_log"):
        with open(r["foam_log"]) as f:
            row.update(json.load(f))
    if r.get("deform_json"):
        try:
            with open(r["deform_json"]) as f:
                j = json.load(f)
        except (OSError, ValueError):
            j = None
        res = j or {}
        frame = (res.get("frames") or [{}])[0]
        prepare = (res.get("plan") or {}).get("seconds")
        sec = frame.get("seconds") or {}
        if prepare is not None and "deform" in sec:
            row["solve_seconds"] = prepare + sec.get("deform", 0) + (sec.get("untangle") or 0)
            row["prepare_seconds"], row["step_seconds"] = prepare, sec.get("deform", 0) + (sec.get("untangle") or 0)
        q = frame.get("quality")
        if q:
            row["min"], row["mean"], row["inverted"] = q["min"], q["mean"], q["inverted"]
        if res.get("error"):
            row["error"] = res["error"]
        elif not j and r.get("deform_err"):  # no report: the error is on standard error
            with open(r["deform_err"]) as f:
                lines = [line.strip() for line in f if line.strip()]
            if lines:
                row["error"] = lines[-1]
    if r.get("quality_json"):
        with open(r["quality_json"]) as f:
            q = json.load(f)["quality"]
        row["min"], row["mean"], row["inverted"] = q["min"], q["mean"], q["inverted"]
    if r.get("checkmesh_log"):
        row["checkmesh"] = checkmesh_status(r["checkmesh_log"])
    with open(out, "a") as f:
        f.write(json.dumps(row) + "\n")


def fmt(x, digits=3):
    if x is None:
        return ""
    if isinstance(x, float):
        if x >= 100:
            return "%.0f" % x
        if x == 0 or (x >= 0.01 and x >= 10.0 ** -digits):
            return ("%." + str(digits) + "f") % x
        return "%.2g" % x if x >= 0.01 else "%.1e" % x  # 0.04 s with one digit: 0.04, not 0.0
    return str(x)


def table(path):
    rows = [json.loads(line) for line in open(path)]
    cases = []
    for r in rows:
        if r["case"] not in cases:
            cases.append(r["case"])
    for case in cases:
        rs = [r for r in rows if r["case"] == case and r["label"] != "load"]
        load = [r for r in rows if r["case"] == case and r["label"] == "load"]
        print("\n**%s**%s\n" % (case, " (%s; uptime's 1, 5, 15 min averages)" % load[0]["status"] if load else ""))
        print("| tool | method / set-up | wall s | CPU s | solve s | peak MB | Knupp min | mean | inverted | "
              "boundary error | checkMesh | note |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rs:
            if r["label"] == "original":
                print("| original | | | | | | %s | %s | %s | | %s | |" % (
                    fmt(r.get("min")), fmt(r.get("mean")), r.get("inverted", ""), r.get("checkmesh", "")))
                continue
            note = r.get("status", "")
            if r.get("cycles"):
                note = (note + "; " if note else "") + "GAMG cycles " + "/".join(
                    str(v) for _, v in sorted(r["cycles"].items()))
            if r.get("error"):
                error = r["error"].split(" (worst")[0].replace("dgwarp: invalid result: ", "")
                note = (note + "; " if note else "") + error[:110]
            print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r.get("tool", ""), r.get("setup", r["label"]), fmt(r.get("wall_seconds"), 1),
                fmt(r.get("cpu_seconds"), 1),
                fmt(r.get("solve_seconds"), 2), fmt(r.get("peak_mb"), 0), fmt(r.get("min")), fmt(r.get("mean")),
                r.get("inverted", ""), r.get("boundary_error", ""), r.get("checkmesh", ""), note))
        # The ratios: each OpenFOAM set-up against the fastest dgwarp run at an equal or better minimum.
        foams = [r for r in rs if r.get("tool") == "OpenFOAM" and r.get("min") is not None]
        ours = [r for r in rs if r.get("tool") == "dgwarp" and r.get("min") is not None and r.get("inverted") == 0
                and r.get("wall_seconds")]
        print()
        def ratio(f, ours_row, what):
            solve = ""
            if f.get("solve_seconds") and ours_row.get("solve_seconds"):
                solve = ", solve %.1fx (%s s vs %s s)" % (
                    f["solve_seconds"] / ours_row["solve_seconds"], fmt(f["solve_seconds"], 2),
                    fmt(ours_row["solve_seconds"], 2))
            cpu = ""
            if f.get("cpu_seconds") and ours_row.get("cpu_seconds"):
                cpu = ", CPU %.1fx (%s s vs %s s)" % (f["cpu_seconds"] / ours_row["cpu_seconds"],
                                                      fmt(f["cpu_seconds"], 1), fmt(ours_row["cpu_seconds"], 1))
            return "- %s: OpenFOAM %s (min %s) vs dgwarp %s (%s, min %s): wall %.1fx (%s s vs %s s)%s%s" % (
                case, f["setup"], fmt(f["min"]), ours_row["setup"], what, fmt(ours_row["min"]),
                f["wall_seconds"] / ours_row["wall_seconds"], fmt(f["wall_seconds"], 1),
                fmt(ours_row["wall_seconds"], 1), cpu, solve)

        for f in foams:
            better = [r for r in ours if round(r["min"], 3) >= round(f["min"], 3)]
            best = min(better, key=lambda r: r["wall_seconds"]) if better else None
            default = [r for r in ours if r["label"] == "dg-harmonic"]
            if best and default and best is default[0]:
                print(ratio(f, best, "the default, and the fastest at an equal or better min"))
                continue
            if best:
                print(ratio(f, best, "the fastest at an equal or better min"))
            else:
                print("- %s: OpenFOAM %s (min %s): no dgwarp method reaches its minimum quality" % (
                    case, f["setup"], fmt(f["min"])))
            if default:
                print(ratio(f, default[0], "the default"))


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "stamp":
        stamp()
    elif cmd == "foam-solve":
        foam_solve(*args)
    elif cmd == "boundary-error":
        boundary_error(*args)
    elif cmd == "record":
        record(args[0], args[1:])
    elif cmd == "table":
        table(args[0])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()
