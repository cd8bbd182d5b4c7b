# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How each technique's cost grows with the scene: `softshadows bench` over
generated scenes in three sweeps, each technique in a process of its own
beside `hard` (taking turns in one window: the ratio is of one run):

  triangles  a dense isosurface (the `gyroid` source) of 0.1M, 1M and 10M
             triangles over a floor, 512x512
  actors     10, 100 and 1000 small spheres, each its own actor, 512x512
  windows    the demo scene at 512x512, 1280x720, 1920x1080 and 3840x2160

Per run: the technique's and `hard`'s mean frame time, their ratio, and the
process's peak memory (llvmpipe's textures and buffers are the process's
own); `hard` also runs alone, for the memory the others add to it. A run that fails says
its first error line; one that takes longer than --timeout says so.

Results are kept in docs/benchmarks/scale.json, merged run by run, so a
sweep or a technique can be measured again alone. Unless --no-docs, the
tables in docs/benchmarks.md (between their markers) and the plots
docs/benchmarks/scale-*.png are rewritten from that file. Run by
scripts/scale.sh.

    python3 scripts/scale.py SOFTSHADOWS [--sweeps triangles,actors,windows]
        [--cases 0.1M,1M,...] [--techniques hard,...] [--frames N] [--timeout S]
        [--no-docs]

--cases keeps only the sweeps' cases of those labels (e.g. 0.1M, 1000,
1920x1080).
"""
import argparse
import json
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

TECHNIQUES = ["hard", "vtk", "omni", "contact", "silhouette", "smoothies", "aliasfree:hard",
              "aliasfree"]
RESULTS = "docs/benchmarks/scale.json"
DOC = "docs/benchmarks.md"
BEGIN, END = "<!-- scale tables: scripts/scale.sh -->", "<!-- end of scale tables -->"

# The gyroid's resolution for each triangle count (3 cells: about
# 10 * 3 * resolution^2 triangles, docs/scene-format.md).
TRIANGLES = [(100_000, 58), (1_000_000, 183), (10_000_000, 577)]
ACTORS = [10, 100, 1000]
WINDOWS = [(512, 512), (1280, 720), (1920, 1080), (3840, 2160)]
SPOT = {"type": "spot", "position": [2.5, 5.0, 1.5], "focal_point": [0.0, 0.0, 0.0],
        "cone_angle": 40, "radius": 0.15}


def isosurface_scene(resolution):
    return {"name": "gyroid-%d" % resolution,
            "camera": {"position": [2.4, 2.8, 3.4], "focal_point": [0.0, 0.7, 0.0]},
            "lights": [SPOT],
            "actors": [{"source": "plane", "params": {"size": 5}},
                       {"source": "gyroid", "params": {"radius": 1.0, "resolution": resolution},
                        "position": [0.0, 1.1, 0.0], "color": [0.85, 0.55, 0.3]}]}


def actors_scene(count):
    side = math.ceil(math.sqrt(count))
    spacing = 6.0 / side
    spheres = [{"source": "sphere", "params": {"radius": 0.3 * spacing, "resolution": 12},
                "position": [(i % side - (side - 1) / 2) * spacing, 0.6,
                             (i // side - (side - 1) / 2) * spacing],
                "color": [0.3, 0.5, 0.85]} for i in range(count)]
    return {"name": "actors-%d" % count,
            "camera": {"position": [0.0, 7.0, 9.0], "focal_point": [0.0, 0.0, 0.0]},
            "lights": [SPOT],
            "actors": [{"source": "plane", "params": {"size": 8}}] + spheres}


def bench(program, scene, techniques, size, frames, timeout):
    """(JSON lines, peak MB, error or None) of one bench process."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.monotonic()
        process = subprocess.Popen(
            [program, "bench", scene, "--techniques", ",".join(techniques), "--size",
             "%dx%d" % size, "--frames", str(frames), "--json", "--quiet"],
            stdout=out, stderr=err, start_new_session=True)
        status = None
        while status is None:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid == 0:
                status = None
                if time.monotonic() - start > timeout:
                    os.killpg(process.pid, signal.SIGKILL)
                    os.wait4(process.pid, 0)
                    return [], None, "over %d s" % timeout
                time.sleep(0.2)
        peak = usage.ru_maxrss / 1024.0
        out.seek(0)
        err.seek(0)
        lines = [json.loads(line) for line in out.read().splitlines() if line.startswith("{")]
        if os.waitstatus_to_exitcode(status) != 0 or not lines:
            # The program's own error line, else the first line (VTK's log,
            # coloured), without the prefixes that say nothing.
            problem = [line for line in err.read().splitlines() if line.strip()]
            own = [line for line in problem if line.startswith("softshadows: error:")]
            message = (own or problem or ["exit %d" % status])[0]
            message = re.sub(r"\x1b\[[0-9;]*m", "", message)
            for prefix in ["softshadows: error: ", "VTK reported an error while rendering: "]:
                message = message.replace(prefix, "")
            return [], peak, message[:160]
        return lines, peak, None


def measure(program, sweeps, only, techniques, frames, timeout, results):
    cases = []
    if "triangles" in sweeps:
        cases += [("triangles", "%gM" % (t / 1e6), isosurface_scene(r), (512, 512))
                  for t, r in TRIANGLES]
    if "actors" in sweeps:
        cases += [("actors", str(n), actors_scene(n), (512, 512)) for n in ACTORS]
    if "windows" in sweeps:
        demo = json.load(open("Examples/Scenes/demo.json"))
        cases += [("windows", "%dx%d" % w, demo, w) for w in WINDOWS]
    if only:
        cases = [case for case in cases if case[1] in only]
    with tempfile.TemporaryDirectory() as folder:
        for sweep, label, scene, size in cases:
            path = os.path.join(folder, "%s-%s.json" % (sweep, label))
            with open(path, "w") as f:
                json.dump(scene, f)
            key = "%s/%s" % (sweep, label)
            entry = results.setdefault(key, {})
            # `hard` alone first: its memory is what the others add to.
            for technique in ["hard"] + [t for t in techniques if t != "hard"]:
                alongside = ["hard"] if technique == "hard" else ["hard", technique]
                lines, peak, error = bench(program, path, alongside, size, frames, timeout)
                figures = {"peak_mb": peak, "error": error}
                for line in lines:
                    if line["technique"] == technique:
                        figures.update(ms=line["mean_ms"], ratio=line["ratio_to_hard"])
                    if line["technique"] == "hard":
                        figures["hard_ms"] = line["mean_ms"]
                entry[technique] = figures
                print("%-18s %-12s %s" % (key, technique, describe(figures)), flush=True)
                with open(RESULTS, "w") as f:
                    json.dump(results, f, indent=1, sort_keys=True)


def describe(figures):
    if figures.get("error"):
        return "-- " + figures["error"]
    return "%.0f ms, %.2f x hard, %.0f MB" % (figures["ms"], figures["ratio"],
                                              figures["peak_mb"])


def tables(results):
    text = []
    for sweep, title in [("triangles", "Triangles (a gyroid isosurface), 512x512"),
                         ("actors", "Actors (small spheres), 512x512"),
                         ("windows", "Window size (the demo scene)")]:
        keys = [k for k in results if k.startswith(sweep + "/")]
        if not keys:
            continue
        keys.sort(key=lambda k: sort_key(k))
        labels = [k.split("/", 1)[1] for k in keys]
        text += ["**%s.** Mean ms a frame (ratio to `hard` in the same run), and the "
                 "process's peak memory in MB (`hard`'s row: `hard` alone)." % title, "",
                 "| technique | " + " | ".join(labels) + " |",
                 "|---|" + "---|" * len(labels)]
        for technique in TECHNIQUES:
            cells = []
            for k in keys:
                figures = results[k].get(technique)
                if figures is None:
                    cells.append("")
                elif figures.get("error"):
                    cells.append(figures["error"].replace("|", "/"))
                else:
                    cells.append("%.0f (%.2f), %.0f MB" % (figures["ms"], figures["ratio"],
                                                           figures["peak_mb"]))
            text.append("| `%s` | " % technique + " | ".join(cells) + " |")
        text.append("")
    return "\n".join(text)


def sort_key(key):
    label = key.split("/", 1)[1]
    if "x" in label:
        w, h = label.split("x")
        return int(w) * int(h)
    return float(label.rstrip("M"))


def plots(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for sweep, axis in [("triangles", "triangles (millions)"), ("actors", "actors"),
                        ("windows", "pixels (millions)")]:
        keys = sorted([k for k in results if k.startswith(sweep + "/")], key=sort_key)
        if not keys:
            continue
        x = [sort_key(k) / (1e6 if sweep == "windows" else 1) for k in keys]
        figure, axes = plt.subplots(figsize=(6.4, 4.2))
        for technique in TECHNIQUES:
            points = [(xi, results[k][technique]["ms"]) for xi, k in zip(x, keys)
                      if technique in results[k] and not results[k][technique].get("error")]
            if points:
                axes.plot(*zip(*points), marker="o", label=technique)
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.set_xlabel(axis)
        axes.set_ylabel("ms a frame (llvmpipe, 2 cores)")
        axes.grid(True, which="both", alpha=0.3)
        axes.legend(fontsize=8)
        figure.tight_layout()
        figure.savefig("docs/benchmarks/scale-%s.png" % sweep, dpi=80)
        plt.close(figure)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--sweeps", default="triangles,actors,windows")
    parser.add_argument("--cases", default="")
    parser.add_argument("--techniques", default=",".join(TECHNIQUES))
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--timeout", type=int, default=900)
    parser.add_argument("--no-docs", action="store_true")
    options = parser.parse_args()
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    results = json.load(open(RESULTS)) if os.path.exists(RESULTS) else {}
    measure(options.program, options.sweeps.split(","), [c for c in options.cases.split(",") if c],
            options.techniques.split(","),
            options.frames, options.timeout, results)
    print(tables(results))
    if not options.no_docs:
        doc = open(DOC).read()
        if BEGIN not in doc:
            sys.exit("%s lacks the marker %s" % (DOC, BEGIN))
        head, rest = doc.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        with open(DOC, "w") as f:
            f.write(head + BEGIN + "\n" + tables(results) + END + tail)
        plots(results)


if __name__ == "__main__":
    main()
