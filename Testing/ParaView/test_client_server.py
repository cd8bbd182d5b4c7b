# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's view through a pvserver on two MPI ranks (scripts/paraview.sh
starts the server): the client-server path of the light Radius (the view's
proxy on the client hands it to the view on each server rank) and the shadow
maps combined across the server's ranks. The scene is test_parallel.py's;
its one-rank images in FOLDER are the reference. Then the Light Visibility
filter on the server's ranks, against test_light_visibility.py's one-rank
values in FOLDER.

    PVPYTHON test_client_server.py PLUGIN FOLDER PORT
"""
import os
import sys
import time

import numpy as np
from paraview.simple import Connect, GetSettingsProxy, LoadPlugin, Render

import pvshadows
from pvshadows import check

plugin, folder, port = sys.argv[1], sys.argv[2], int(sys.argv[3])
for attempt in range(60):  # the server takes a few seconds to listen
    if Connect("localhost", port):
        break
    time.sleep(1)
else:
    raise RuntimeError("no pvserver on port %d" % port)
# The client makes the view's proxy class, the server ranks the view.
LoadPlugin(plugin, remote=False, ns=globals())
LoadPlugin(plugin, remote=True, ns=globals())

# Render on the server's ranks and composite there, however small the data
# (else ParaView sends small geometry to the client and renders it there).
GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0

view, light, ball = pvshadows.side_lit_scene()
low, high = pvshadows.process_ids_range(ball)
check((low, high) == (0, 1), "the ball's pieces lie on the server's ranks %d to %d" % (low, high))

for name in ("hard", "contact"):
    view.ShadowTechnique = name
    Render(view)
    shaded, _ = pvshadows.screenshot(view, folder, "%s-server" % name)
    single = pvshadows.grey(pvshadows.image_path(folder, name + "-1ranks"))
    pvshadows.check_alike(shaded, single, "%s: two server ranks as one pvbatch rank" % name,
                          mean=0.5, share=0.006)

# The radius reaches the server's ranks: contact's shadow hardens at 0.
light.Radius = 0.0
Render(view)
hard_edged, _ = pvshadows.screenshot(view, folder, "contact-server-radius0")
changed = int((np.abs(hard_edged - shaded) > 16).sum())
check(changed > 500, "contact: Radius 0 on the client changes %d pixels by more than 16 levels "
      "on the server's image" % changed)

# The Light Visibility filter on the server's ranks (test_light_visibility.py's
# scene and one-rank values), its light as parameters and as a light of the
# view, whose Radius the client hands over.
ground, visibility_ball = pvshadows.visibility_scene()
saved = os.path.join(folder, "light-visibility-1ranks.npz")
given = LightVisibility(Input=ground, Casters=[visibility_ball], LightType="Point",  # noqa: F821
                        LightPosition=pvshadows.VISIBILITY_LIGHT,
                        LightFocalPoint=pvshadows.VISIBILITY_FOCAL_POINT, LightRadius=0.3,
                        Samples=256)
points, values = pvshadows.visibility_values(given)
pvshadows.check_visibility_as_saved(points, values, saved,
                                    "Light Visibility on two server ranks as on one pvbatch rank")
taken = LightVisibility(Input=ground, Casters=[visibility_ball], LightsFrom="Lights",  # noqa: F821
                        Lights=[pvshadows.visibility_light(view)], Samples=256)
points, values = pvshadows.visibility_values(taken)
pvshadows.check_visibility_as_saved(points, values, saved,
                                    "Light Visibility with the view's light on the server")

pvshadows.finish()
