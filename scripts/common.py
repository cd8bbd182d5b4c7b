# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""What the measuring scripts share: running the `softshadows` program and
reading the pictures it writes. Run as `python3 scripts/NAME.py`, they find
this module beside them."""

import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def run(program, *args):
    """`program` with `args`; its standard output, or the script stops with
    the program's messages if it fails."""
    result = subprocess.run([program] + list(args), capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("softshadows %s failed:\n%s%s" % (" ".join(args), result.stdout, result.stderr))
    return result.stdout


def read_png(path):
    """An array [rows, columns, components], bottom row first."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return vtk_to_numpy(scalars).reshape(height, width, scalars.GetNumberOfComponents())
