# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""`softshadows view`, driven as a user would: keys and a mouse drag sent to
its window with xdotool (X's test extension, under Xvfb), and its
screenshots (key k) checked: the technique cycles, the radius widens the
penumbra and 0 makes it hard, the arrow keys move the shadow with the
light, the trackball turns the camera, q quits."""
import json
import os
import select
import subprocess
import tempfile
import time

import numpy as np

import shadowtest as st

TIMEOUT = 60.0


class Viewer:
    def __init__(self, scene_file, folder):
        self.process = subprocess.Popen(
            [st.SOFTSHADOWS, "view", scene_file, "--size", "240x180"], cwd=folder,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=st.PROGRAM_ENV)
        self.folder = folder
        self.state = self.expect("technique ")
        window = subprocess.run(["xdotool", "search", "--sync", "--name", "softshadows: viewed"],
                                capture_output=True, text=True, timeout=TIMEOUT).stdout.split()
        st.check(len(window) >= 1, "the viewer's window is there, named after the scene")
        self.window = window[0]
        subprocess.run(["xdotool", "windowfocus", "--sync", self.window], check=True,
                       timeout=TIMEOUT)

    def expect(self, prefix):
        """The next stdout line starting with `prefix` (others skipped)."""
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            ready, _, _ = select.select([self.process.stdout], [], [], 1.0)
            if not ready:
                if self.process.poll() is not None:
                    raise AssertionError("the viewer ended (%d): %s"
                                         % (self.process.returncode, self.process.stderr.read()))
                continue
            line = self.process.stdout.readline()
            if line.startswith(prefix):
                return line.strip()
        raise AssertionError("no line %r from the viewer within %g s" % (prefix, TIMEOUT))

    def key(self, *keys):
        """Sends `keys`; returns the state line after the last."""
        for name in keys:
            subprocess.run(["xdotool", "key", "--window", self.window, name], check=True)
            self.state = self.expect("technique ")
        return self.state

    def shot(self):
        subprocess.run(["xdotool", "key", "--window", self.window, "k"], check=True)
        path = self.expect("wrote ").split(" ", 1)[1]
        # Without the corner text (the bottom rows, as images are stored).
        return st.read_png(os.path.join(self.folder, path))[40:, :, :3].astype(float)

    def drag(self, dx, dy):
        x, y = 120, 90
        for command in (["mousemove", "--window", self.window, str(x), str(y)],
                        ["mousedown", "1"],
                        ["mousemove", "--window", self.window, str(x + dx // 2), str(y + dy // 2)],
                        ["mousemove", "--window", self.window, str(x + dx), str(y + dy)],
                        ["mouseup", "1"]):
            subprocess.run(["xdotool"] + command, check=True)
            time.sleep(0.2)


def penumbra(image):
    grey = image.mean(axis=2) / 255.0
    return int(((grey > 0.1) & (grey < 0.9)).sum())


def shadow_centroid(image):
    # The floor only: the black background shows left and right of it.
    grey = image[:, 40:200].mean(axis=2) / 255.0
    rows, columns = np.nonzero(grey < 0.5)
    return np.array([columns.mean(), rows.mean()])


scene = st.ball_scene(light_radius=0.2, technique="contact", size=(240, 180), map_size=512)
scene["name"] = "viewed"
# Straight down at the floor, which fills the view; the light off to +x,
# so that the shadow lies beside the ball.
scene["camera"] = {"position": [0, 8, 0.01], "focal_point": [0, 0, 0], "view_angle": 40}
scene["lights"][0]["position"] = [3.5, 4.5, 0.0]
with tempfile.TemporaryDirectory() as folder:
    folder = os.environ.get("VIEWER_KEEP", folder)
    scene_file = os.path.join(folder, "viewed.json")
    with open(scene_file, "w") as f:
        json.dump(scene, f)
    viewer = Viewer(scene_file, folder)
    st.check(viewer.state.startswith("technique contact,"), "starts with the scene's technique")

    lit = viewer.shot()
    colourful = (lit.max(axis=2) - lit.min(axis=2) > 40).mean()
    st.check(colourful > 0.005, "the red ball is drawn in colour (%.3f)" % colourful)
    following = viewer.key("n")
    st.check(not following.startswith("technique contact,"), "n: the next technique: " + following)
    st.check(viewer.key("b").startswith("technique contact,"), "b: back to contact")

    # The shadow alone (light 0's visibility, grey) for the numbers.
    st.check(viewer.key("o").endswith("shadow only on"), "o: shadow only")
    soft = viewer.shot()
    st.check(np.abs(soft[:, :, 0] - soft[:, :, 1]).max() < 2, "shadow only is grey")
    wider = viewer.key("plus", "plus", "plus")
    st.check("light radius 0.391" in wider, "+ three times: 0.2 x 1.25^3: " + wider)
    softer = viewer.shot()
    hard_state = viewer.key(*["minus"] * 12)
    st.check("light radius 0," in hard_state, "- to radius 0: " + hard_state)
    hard = viewer.shot()
    st.check(penumbra(softer) > 1.3 * penumbra(soft) and penumbra(hard) < 0.5 * penumbra(soft),
             "the radius sizes the penumbra: %d at 0, %d at 0.2, %d at 0.39 pixels"
             % (penumbra(hard), penumbra(soft), penumbra(softer)))

    # The light orbits: 45 degrees around the vertical moves the shadow.
    before = shadow_centroid(hard)
    viewer.key(*["Right"] * 9)
    moved = shadow_centroid(viewer.shot())
    st.check(np.linalg.norm(moved - before) > 8,
             "arrow keys move the shadow with the light (%.1f px)"
             % np.linalg.norm(moved - before))

    # The trackball: a drag turns the camera.
    still = viewer.shot()
    viewer.drag(60, 0)
    turned = viewer.shot()
    st.check(np.abs(turned - still).mean() > 5, "dragging turns the camera (mean change %.1f)"
             % np.abs(turned - still).mean())

    # The viewer may close its window between the key's press and release:
    # xdotool's own error then says nothing about the viewer.
    subprocess.run(["xdotool", "key", "--window", viewer.window, "q"], capture_output=True)
    viewer.process.wait(timeout=TIMEOUT)
    st.check(viewer.process.returncode == 0, "q quits (exit %d)" % viewer.process.returncode)
    errors = viewer.process.stderr.read()
    st.check("ERR" not in errors and "rror" not in errors, "no errors: %r" % errors[-300:])
print("ok")
