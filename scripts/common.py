# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""What the measuring scripts share: running the `softshadows` program and
reading the pictures it writes (with the tests' reader, Testing/Python/
shadowtest.py). Run as `python3 scripts/NAME.py`, they find this module
beside them."""

import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing",
                                "Python"))
from shadowtest import read_png  # noqa: E402  (bottom row first, as the tests read)

__all__ = ["read_png", "run"]


def run(program, *args):
    """`program` with `args`; its standard output, or the script stops with
    the program's messages if it fails."""
    result = subprocess.run([program] + list(args), capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("softshadows %s failed:\n%s%s" % (" ".join(args), result.stdout, result.stderr))
    return result.stdout
