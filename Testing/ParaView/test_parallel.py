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
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, Render

import pvshadows
from pvshadows import check

TECHNIQUES = ("hard", "contact", "contact:multipass", "omni", "reference")

LoadPlugin(sys.argv[1], remote=True, ns=globals())
folder = sys.argv[2]
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
view, light, ball = pvshadows.scene("ShadowRenderView", ball_resolution=16,
                                    light_position=[3.6, 2.4, 0.0], ball_center=[1.2, 1.2, 0.0])
view.GetProperty("ShadowTechnique")  # the plugin's view, on every rank

low, high = pvshadows.process_ids_range(ball)
check((low, high) == (0, ranks - 1),
      "%d rank(s): the ball's pieces lie on ranks %d to %d" % (ranks, low, high))

for name in TECHNIQUES:
    view.ShadowTechnique = name
    view.CombineShadowMaps = 1
    Render(view)
    shaded, _ = pvshadows.screenshot(view, folder, "%s-%dranks" % (name, ranks))
    one_rank = os.path.join(folder, "%s-1ranks.png" % name.replace(":", "-"))
    if ranks == 1:
        continue
    single = pvshadows.grey(one_rank)
    off = np.abs(shaded - single)
    check((off > 24).mean() < 0.006 and off.mean() < 0.5,
          "%s: %d ranks as one (mean difference %.2f levels, %.2f%% of pixels off by more "
          "than 24)" % (name, ranks, off.mean(), 100 * (off > 24).mean()))

    view.CombineShadowMaps = 0
    Render(view)
    alone, _ = pvshadows.screenshot(view, folder, "%s-%dranks-uncombined" % (name, ranks))
    lighter = (alone - single) > 40
    check(lighter.mean() > 0.015,
          "%s: without combining the maps, %.1f%% of pixels are lighter than the one-rank "
          "image (rank 1's half casts nothing on rank 0's ground)" % (name,
                                                                        100 * lighter.mean()))

pvshadows.finish()
