# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `softshadows` program: listing, rendering, sizes, and one clear
message naming the field for every malformed scene."""
import json
import math
import os
import pty
import subprocess
import tempfile

import numpy as np
import shadowtest as st

here = os.path.dirname(os.path.abspath(__file__))
bad = os.path.join(here, "..", "Scenes", "bad")

listing = st.run(["techniques"]).stdout
for name in ("hard", "reference", "vtk", "pcf_radius", "samples"):
    st.check(name in listing, "`techniques` lists %s" % name)

# Each bad scene: exit code 2, one line on stderr naming what is wrong.
expectations = {
    "syntax.json": "syntax.json",
    "unknown_field.json": "lights[0].colour",
    "wrong_type.json": "lights[0].cone_angle",
    "missing_file.json": "actors[0].file",
    "unknown_technique.json": "raytraced",
    "unknown_source.json": "teapot",
    "light_without_position.json": "lights[0]",
}
for name, needle in sorted(expectations.items()):
    result = st.run(["render", os.path.join(bad, name)], check=False)
    message = result.stderr.strip()
    st.check(result.returncode == 2, "%s: exit code 2 (got %d)" % (name, result.returncode))
    st.check(needle in message and "\n" not in message,
             "%s: one line naming %s: %r" % (name, needle, message))

good = st.ball_scene(size=(160, 120), map_size=256)
with tempfile.TemporaryDirectory() as folder:
    scene_file = os.path.join(folder, "ball.json")
    with open(scene_file, "w") as f:
        json.dump(good, f)

    for args, needle in [(["--technique", "nonsense"], "nonsense"),
                         (["--size", "12xfoo"], "--size"),
                         (["--size", "0x10"], "--size"),
                         (["--technique", "hard:fancy"], "fancy"),
                         (["--light", "3", "--shadow-only"], "--light")]:
        result = st.run(["render", scene_file] + args, check=False)
        st.check(result.returncode == 2 and needle in result.stderr,
                 "render %s: rejected naming %s" % (" ".join(args), needle))

    # Default output name, size override, colour image.
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        st.run(["render", scene_file, "--size", "90x70"])
        pixels = st.read_png(os.path.join(folder, "ball-hard.png"))
    finally:
        os.chdir(cwd)
    st.check(pixels.shape[:2] == (70, 90), "--size overrides the scene size")
    st.check(pixels.shape[2] in (3, 4), "colour image written")

    # Shadow-only: grey + alpha, background transparent.
    visibility, geometry = st.shadow_only(good)
    st.check(geometry.any() and not geometry.all(), "shadow-only alpha separates geometry from background")

    # More lights than the receivers have texture units for: rendered, one
    # warning, no shader source, exit code 0.
    many = dict(good, size=[64, 48], lights=[
        {"type": "spot" if i % 2 else "point", "position": [math.cos(i), 4.0, math.sin(i)],
         "intensity": 0.05} for i in range(40)])
    many_file = os.path.join(folder, "many.json")
    with open(many_file, "w") as f:
        json.dump(many, f)
    result = st.run(["render", many_file, "--output", os.path.join(folder, "many.png")])
    st.check(result.stderr.count("lights are drawn without shadows") == 1 and
             len(result.stderr.strip().splitlines()) == 1,
             "40 lights: one warning line and nothing else: %r" % result.stderr[-300:])

    # Glyphs: the ball drawn as 3 x 3 instances casts nine shadows; bad
    # `glyphs` objects are refused naming the field.
    def glyph_scene(glyphs):
        scene = json.loads(json.dumps(good))
        scene["actors"][1]["params"]["radius"] = 0.2
        scene["actors"][1]["glyphs"] = glyphs
        path = os.path.join(folder, "glyphs.json")
        with open(path, "w") as f:
            json.dump(scene, f)
        return scene, path

    scene, _ = glyph_scene({"count": [3, 1, 3], "spacing": 0.8, "turn": True,
                            "sizes": [0.8, 1.2]})
    visibility, geometry = st.shadow_only(scene, "aliasfree:hard")
    single = json.loads(json.dumps(scene))
    del single["actors"][1]["glyphs"]
    one, _ = st.shadow_only(single, "aliasfree:hard")
    shadowed = np.sum(geometry & (visibility < 0.5))
    alone = np.sum(geometry & (one < 0.5))
    st.check(alone > 0 and 6 * alone < shadowed < 12 * alone,
             "3 x 3 glyphs under aliasfree: about nine balls' shadow pixels (%d, one ball %d)"
             % (shadowed, alone))
    for glyphs, needle in [({"spacing": 1}, "actors[1].glyphs"),
                           ({"count": [3, 3]}, "actors[1].glyphs.count"),
                           ({"count": [1000, 1000, 2]}, "at most 1000000"),
                           ({"count": [2, 1, 2], "sizes": [2, 1]}, "actors[1].glyphs.sizes"),
                           ({"count": [2, 1, 2], "spin": 1}, "actors[1].glyphs.spin")]:
        _, path = glyph_scene(glyphs)
        result = st.run(["render", path], check=False)
        message = result.stderr.strip()
        st.check(result.returncode == 2 and needle in message and "\n" not in message,
                 "glyphs %s: one line naming %s: %r" % (glyphs, needle, message))

    # VTK's own pass renders too (the benchmark's baseline).
    st.run(["render", scene_file, "--technique", "vtk", "--output", os.path.join(folder, "vtk.png")])
    st.check(os.path.exists(os.path.join(folder, "vtk.png")), "technique vtk renders")

    # Bench: one JSON object per technique and line, hard included.
    out = st.run(["bench", scene_file, "--techniques", "reference", "--frames", "2",
                  "--size", "64x48", "--json"]).stdout
    rows = [json.loads(line) for line in out.splitlines()]
    names = sorted(row["technique"] for row in rows)
    st.check(names == ["hard", "reference"], "bench adds hard: %s" % names)
    for row in rows:
        st.check(set(row) == {"technique", "frames", "mean_ms", "median_ms", "ratio_to_hard",
                              "map_size", "size", "light_space_median_ms",
                              "screen_space_median_ms", "receivers_median_ms"},
                 "bench JSON keys for %s" % row["technique"])
        # Every technique's steps by timer queries: maps and scene take time,
        # the screen-space step only for a technique that has one.
        st.check(row["light_space_median_ms"] > 0 and row["receivers_median_ms"] > 0
                 and (row["screen_space_median_ms"] > 0) == (row["technique"] == "reference"),
                 "bench: %s's GPU steps %s" % (row["technique"],
                                                [row[k] for k in ("light_space_median_ms",
                                                                  "screen_space_median_ms",
                                                                  "receivers_median_ms")]))
    hard_row = [r for r in rows if r["technique"] == "hard"][0]
    st.check(abs(hard_row["ratio_to_hard"] - 1.0) < 1e-9 and hard_row["size"] == [64, 48],
             "bench: hard's ratio is 1 and the size is the override")

    # A technique's own map_size overrides the scene's; silhouette and
    # smoothies report the work they time themselves; --debug-view is the
    # technique's debug_view parameter.
    own_file = os.path.join(folder, "own_map_size.json")
    with open(own_file, "w") as f:
        scene = st.ball_scene(light_radius=0.3, size=(64, 48), map_size=256)
        scene["shadows"]["smoothies"] = {"map_size": 128}
        json.dump(scene, f)
    out = st.run(["bench", own_file, "--techniques", "silhouette,smoothies", "--frames", "2",
                  "--json"]).stdout
    rows = {row["technique"]: row for row in map(json.loads, out.splitlines())}
    st.check(rows["hard"]["map_size"] == 256 and rows["smoothies"]["map_size"] == 128,
             "bench: smoothies' own map_size 128, hard the scene's 256")
    st.check("pass_median_ms" in rows["silhouette"] and "cpu_median_ms" in rows["smoothies"]
             and "pass_median_ms" not in rows["hard"] and "cpu_median_ms" not in rows["hard"],
             "bench: silhouette's own pass time and smoothies' CPU time, none for hard")
    debug = os.path.join(folder, "debug.png")
    st.run(["render", own_file, "--technique", "silhouette", "--debug-view", "--output", debug])
    st.check(os.path.exists(debug), "--debug-view renders silhouette's distance map")
    result = st.run(["render", own_file, "--technique", "omni", "--debug-view"], check=False)
    st.check(result.returncode == 2 and "no debug view" in result.stderr,
             "--debug-view: omni has none: %r" % result.stderr.strip())

    # Progress: on stderr only when it is a terminal (a pseudo-terminal
    # here), one line rewritten in place and cleared at the end; none with
    # --quiet or into a pipe, where stdout is what it always was.
    soft_file = os.path.join(folder, "soft.json")
    with open(soft_file, "w") as f:
        json.dump(st.ball_scene(light_radius=0.3, size=(64, 48), map_size=256), f)

    def with_terminal(args):
        master, slave = pty.openpty()
        process = subprocess.Popen([st.SOFTSHADOWS] + args, stdout=subprocess.PIPE,
                                   stderr=slave, env=st.PROGRAM_ENV)
        os.close(slave)
        shown = b""
        while True:
            try:
                chunk = os.read(master, 4096)
            except OSError:
                break
            if not chunk:
                break
            shown += chunk
        out = process.stdout.read().decode()
        process.wait()
        os.close(master)
        st.check(process.returncode == 0, "%s under a terminal: exit 0" % args[0])
        return shown.decode(), out

    small = ["--output", os.path.join(folder, "p.png")]
    shown, out = with_terminal(["render", soft_file, "--technique", "reference"] + small)
    st.check("reference: samples" in shown and "100%" in shown and shown.endswith("\r\x1b[K")
             and "\n" not in shown,
             "render reference: samples shown in place and cleared: %r" % shown[-120:])
    st.check(out.startswith("wrote "), "render's stdout as before: %r" % out)
    shown, _ = with_terminal(["render", soft_file, "--technique", "reference", "--quiet"] + small)
    st.check(shown == "", "--quiet: nothing on the terminal: %r" % shown[:120])
    piped = st.run(["render", soft_file, "--technique", "reference"] + small)
    st.check(piped.stderr == "", "into a pipe: no progress: %r" % piped.stderr[:120])
    shown, out = with_terminal(["bench", soft_file, "--techniques", "reference", "--frames",
                                "1", "--size", "64x48"])
    # 3 warm-up frames, one before its block, one timed.
    st.check("bench: frame 5/5, reference" in shown and "x hard" in out,
             "bench: frames and techniques shown: %r" % shown[-120:])
    shown, out = with_terminal(["gallery", soft_file, "--techniques", "hard,reference",
                                "--frames", "1", "--size", "64x48", "--output-dir",
                                os.path.join(folder, "g")])
    st.check("gallery: reference (2/2)" in shown, "gallery: techniques shown: %r" % shown[-120:])
    shown, _ = with_terminal(["truth", soft_file, "--size", "64x48", "--samples", "16",
                              "--output", os.path.join(folder, "t.png")])
    st.check("ray casting" in shown, "truth: ray casting shown: %r" % shown[-120:])
