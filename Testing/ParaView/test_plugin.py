# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView plugin in pvpython (scripts/paraview.sh runs it): a ball over
a plane under a spot light of radius 0.3 (ParaView's own light Radius),
drawn by ParaView's render view and by the plugin's under every choice of
Shadow Technique. For each, the plugin's view
- puts the shadow where geometry says: dark under the ball's centre and
  inside the tangent cone from the light, lit well outside it,
- softens it with the light's radius (more partly shadowed pixels than with
  Radius 0), but for the hard variants, which stay as they are, and omni,
  which softens point lights only (checked with one),
- draws the rest as ParaView draws it,
- matches its baseline image (Testing/ParaView/Baseline).
The panel has one property per parameter of `softshadows techniques`
(SOFTSHADOWS, the program), named <Technique><Key>, at the listed default;
a parameter set reaches the pass, stays when the technique comes back, and
a value out of range is refused.

The plugin's view is one view whose technique changes, as a user changes it.

    PVPYTHON test_plugin.py PLUGIN SOFTSHADOWS [OUTPUT_FOLDER]
"""
import json
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from paraview.simple import LoadPlugin, Render

import pvshadows
from pvshadows import check

# Hard whatever the radius; omni softens only point lights' shadows.
HARD = ("hard", "hard:sixpass", "silhouette:hard", "aliasfree:hard", "omni", "omni:pcf4",
        "omni:hard")
BASELINES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Baseline")


def techniques_listing(program):
    """What `softshadows techniques` prints. The program is the ordinary
    build's, against the system's VTK: without the library path the pvpython
    wrapper sets for ParaView's VTK and the module built against it."""
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("LD_LIBRARY_PATH", "PYTHONPATH")}
    return subprocess.run([program, "techniques"], check=True, capture_output=True,
                          text=True, env=environment).stdout


def listed_parameters(program):
    """{property name: default} of every technique parameter the program lists."""
    listing = techniques_listing(program)
    parameters = {}
    technique = None
    for line in listing.splitlines():
        if re.match(r"^[a-z]+$", line):
            technique = line
        found = re.match(r"^  ([a-z0-9_]+) +(boolean|integer|number|\[x, y, z\]) +(\S+)", line)
        if found and technique != "vtk":
            name = "".join(word.capitalize() for word in [technique] + found[1].split("_"))
            parameters[name] = json.loads(found[3])
    return parameters


def penumbra_pixels(shaded, plain, umbra):
    """Pixels darkened by between 15% and 85% of the umbra's darkening."""
    darkening = (plain - shaded) / max(umbra, 1.0)
    return int(((darkening > 0.15) & (darkening < 0.85)).sum())


LoadPlugin(sys.argv[1], remote=False, ns=globals())
program = sys.argv[2]
output = sys.argv[3] if len(sys.argv) > 3 else None
with tempfile.TemporaryDirectory() as folder:
    plain_view, _, _ = pvshadows.scene("RenderView")
    plain, _ = pvshadows.screenshot(plain_view, folder, "plain")
    view, light, _ = pvshadows.scene("ShadowRenderView")
    names = view.GetProperty("ShadowTechnique").Available
    specs = techniques_listing(program)
    variants = {}
    for line in specs.splitlines():
        if re.match(r"^[a-z]+$", line) and line != "vtk":
            variants[line] = []
            technique = line
        variant = re.match(r"^  variant (\S+)", line)
        if variant:
            variants[technique].append(variant[1])
    listed = [spec for technique, its in variants.items()
              for spec in [technique] + [technique + ":" + v for v in its[1:]]]
    check(names == listed, "Shadow Technique offers every technique and variant: %s" % names)

    # The panel: a property per parameter, at the class's default.
    parameters = listed_parameters(program)
    check(len(parameters) > 60 and isinstance(parameters.get("AliasfreeLightScale"), list),
          "the program lists %d parameters, vectors too" % len(parameters))
    for name, default in sorted(parameters.items()):
        if name.endswith("MapSize"):
            # One map size for every technique: the view's ShadowMapSize.
            check(view.GetProperty(name) is None and view.ShadowMapSize == default,
                  "%s: the view's ShadowMapSize, %s" % (name, default))
            continue
        value = view.GetPropertyValue(name) if view.GetProperty(name) else None
        if isinstance(default, list):
            matches = value is not None and list(value) == default
        else:
            matches = value is not None and abs(float(value) - float(default)) < 1e-9
        check(matches, "%s: a property at the default %s (%s)" % (name, default, value))

    r = pvshadows.ground_shadow_radius()
    centre = pvshadows.pixel(view, [0.0, 0.0, 0.0])
    umbra = [pvshadows.pixel(view, [s * 0.5 * r, 0.0, 0.0]) for s in (-1, 1)]
    outside = [pvshadows.pixel(view, p) for p in ([1.6, 0, 0], [-1.6, 0, 0], [0, 0, 1.6])]
    for name in names:
        view.ShadowTechnique = name
        light.Radius = 0.0
        Render(view)
        point_light, _ = pvshadows.screenshot(view, folder, name + "-radius0")
        light.Radius = pvshadows.LIGHT_RADIUS
        Render(view)
        shaded, path = pvshadows.screenshot(view, folder, name)
        if output:
            os.makedirs(output, exist_ok=True)
            os.replace(path, os.path.join(output, os.path.basename(path)))
            path = os.path.join(output, os.path.basename(path))

        darkening = plain - shaded
        deepest = darkening[centre]
        dark = all(darkening[p] > 0.6 * deepest for p in umbra) and deepest > 40
        lit = all(abs(darkening[p]) < 8 for p in outside)
        check(dark and lit, "%s: dark under the ball (%.0f levels, %.0f and %.0f at half the "
              "tangent cone's %.2f), lit outside it (%s levels)" % (
                  name, deepest, darkening[umbra[0]], darkening[umbra[1]], r,
                  ", ".join("%.0f" % darkening[p] for p in outside)))

        soft = penumbra_pixels(shaded, plain, deepest)
        hard = penumbra_pixels(point_light, plain, deepest)
        ratio = soft / max(hard, 1)
        if name in HARD:
            check(ratio < 1.3, "%s: hard whatever the radius: %d partly shadowed pixels with "
                  "radius %.1f, %d with 0" % (name, soft, pvshadows.LIGHT_RADIUS, hard))
        else:
            check(ratio > 1.5, "%s: the light's radius widens the penumbra: %d partly shadowed "
                  "pixels with radius %.1f, %d with 0" % (name, soft, pvshadows.LIGHT_RADIUS,
                                                          hard))

        same = (np.abs(plain - shaded) < 8).mean()
        check(same > 0.75, "%s: %.0f%% of pixels as ParaView draws them" % (name, 100 * same))

        baseline_path = os.path.join(BASELINES, os.path.basename(path))
        if not os.path.exists(baseline_path):
            check(False, "%s: no baseline %s" % (name, baseline_path))
            continue
        pvshadows.check_alike(shaded, pvshadows.grey(baseline_path), "%s: as its baseline" % name,
                              mean=1.0, share=0.002)

    # A parameter reaches the pass, stays when its technique comes back, and
    # a value out of range is refused (the pass keeps the last good one).
    view.ShadowTechnique = "hard"
    light.Radius = 0.0
    Render(view)
    one_tap, _ = pvshadows.screenshot(view, folder, "hard-pcf0")
    view.HardPcfRadius = 4
    view.ShadowTechnique = "contact"
    Render(view)
    view.ShadowTechnique = "hard"
    Render(view)
    filtered, _ = pvshadows.screenshot(view, folder, "hard-pcf4")
    umbra_darkening = (plain - one_tap)[centre]
    before = penumbra_pixels(one_tap, plain, umbra_darkening)
    after = penumbra_pixels(filtered, plain, umbra_darkening)
    check(after > 1.5 * before, "HardPcfRadius 4, kept across a change of technique: %d partly "
          "shadowed pixels, %d with 0" % (after, before))
    view.HardPcfRadius = 99
    Render(view)
    refused, _ = pvshadows.screenshot(view, folder, "hard-pcf99")
    check(np.abs(refused - filtered).max() < 2, "HardPcfRadius 99 is refused: the image stays")
    view.HardPcfRadius = 0
    light.Radius = pvshadows.LIGHT_RADIUS

    # omni's own case: a point light (a cone of 90 degrees or more).
    view.ShadowTechnique = "omni"
    light.ConeAngle = 90
    light.Radius = 0.0
    Render(view)
    point_light, _ = pvshadows.screenshot(view, folder, "omni-point-radius0")
    light.Radius = pvshadows.LIGHT_RADIUS
    Render(view)
    shaded, _ = pvshadows.screenshot(view, folder, "omni-point")
    changed = int((np.abs(shaded - point_light) > 16).sum())
    check(changed > 500, "omni, point light: the radius softens the shadow (%d pixels change "
          "by more than 16 levels)" % changed)

pvshadows.finish()
