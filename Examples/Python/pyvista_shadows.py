# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A PyVista plotter with the module's soft shadows: a ball and a torus over a
floor, lit by a pyvista.Light spot light of radius 0.3, with contact-hardening
shadows. Needs PyVista (python3-pyvista, Debian 13 and later).

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/pyvista_shadows.py [OUTPUT.png] [--plain]

writes OUTPUT.png (default pyvista_shadows.png) and prints its path; --plain
draws the same plotter without the soft shadows.
"""
import os
import sys

import pyvista as pv

from vtksoftshadows.pyvista import disable_soft_shadows, enable_soft_shadows

arguments = [a for a in sys.argv[1:] if a != "--plain"]
output = arguments[0] if arguments else "pyvista_shadows.png"

# lighting="none": PyVista's default light kit is four directional camera
# lights (and a headlight), which would each cast a shadow; here one spot
# light does.
plotter = pv.Plotter(off_screen=True, window_size=(480, 360), lighting="none")
plotter.set_background((0.2, 0.2, 0.25))
plotter.add_mesh(pv.Plane(center=(0, 0, 0), direction=(0, 1, 0), i_size=6, j_size=6),
                 color=(0.8, 0.8, 0.8))
plotter.add_mesh(pv.Sphere(radius=0.5, center=(0, 1, 0), theta_resolution=48, phi_resolution=24),
                 color=(0.9, 0.3, 0.25), smooth_shading=True)
plotter.add_mesh(pv.ParametricTorus(ringradius=0.45, crosssectionradius=0.15)
                 .rotate_x(90, inplace=False).translate((1.4, 0.45, 0.6), inplace=False),
                 color=(0.3, 0.5, 0.9), smooth_shading=True)
plotter.add_light(pv.Light(position=(1.0, 5.0, 0.5), focal_point=(0, 0, 0), positional=True,
                           cone_angle=45, light_type="scene light"))
plotter.camera_position = [(0.0, 5.0, 7.0), (0.0, 0.5, 0.0), (0.0, 1.0, 0.0)]

if "--plain" not in sys.argv:
    # Every light without a size gets light_radius (world units for spot and
    # point lights); the parameters are the scene files' ("contact": {...}).
    enable_soft_shadows(plotter, "contact", light_radius=0.3, map_size=2048)
    # With PyVista 0.48 and later, importing vtksoftshadows.pyvista also
    # gives plotter.enable_soft_shadows(...) and plotter.soft_shadows.

plotter.screenshot(output)
print(os.path.abspath(output))

# Back to what the plotter drew before; the pass's GPU resources are released.
disable_soft_shadows(plotter)
plotter.close()
