# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's view across MPI ranks, in pvbatch (scripts/paraview.sh runs
it under mpirun -np 1 and -np 2). The ball is split into pieces across the
ranks (ParaView's sphere source gives each rank a band of latitudes: with
two, rank 0 the upper half, rank 1 the lower); the plane, which its source
does not split, lies on rank 0 only. The spot light shines from the side,
so part of the ball's shadow on the ground is cast by its lower half, on
rank 1, onto rank 0's ground: only combined shadow maps can show it.

    PVBATCH test_parallel.py PLUGIN FOLDER
        one rank: renders each technique into FOLDER
    mpirun -np 2 PVBATCH test_parallel.py PLUGIN FOLDER
        two ranks: renders each technique with the shadow maps combined
        across the ranks and checks it against FOLDER's one-rank image,
        then without and checks that the image differs where the shadow
        of rank 1's piece falls.
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Render

import pvshadows
from pvshadows import check

TECHNIQUES = ("hard", "contact", "contact:multipass", "omni", "reference")

LoadPlugin(sys.argv[1], remote=True, ns=globals())
folder = sys.argv[2]
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
view, light, ball = pvshadows.side_lit_scene()

low, high = pvshadows.process_ids_range(ball)
check((low, high) == (0, ranks - 1),
      "%d rank(s): the ball's pieces lie on ranks %d to %d" % (ranks, low, high))

for name in TECHNIQUES:
    view.ShadowTechnique = name
    view.CombineShadowMaps = 1
    Render(view)
    shaded, _ = pvshadows.screenshot(view, folder, "%s-%dranks" % (name, ranks))
    if ranks == 1:
        continue
    single = pvshadows.grey(pvshadows.image_path(folder, name + "-1ranks"))
    pvshadows.check_alike(shaded, single, "%s: %d ranks as one" % (name, ranks), mean=0.5,
                          share=0.006)

    view.CombineShadowMaps = 0
    Render(view)
    alone, _ = pvshadows.screenshot(view, folder, "%s-%dranks-uncombined" % (name, ranks))
    lighter = (alone - single) > 40
    check(lighter.mean() > 0.015,
          "%s: without combining the maps, %.1f%% of pixels are lighter than the one-rank "
          "image (rank 1's half casts nothing on rank 0's ground)" % (name,
                                                                        100 * lighter.mean()))

pvshadows.finish()
