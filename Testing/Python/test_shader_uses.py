# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every GLSL file says what it uses: a `// Uses:` paragraph in its opening
comment ("nothing" when it calls no other file's functions) naming each
other file whose functions it calls. Shaders are put together from these
files by the passes, so a missing name is a dependency a reader cannot see.
No rendering; run from ctest as Source.ShaderUses."""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FILES = sorted(glob.glob(os.path.join(ROOT, "Rendering", "glsl", "*.glsl"))
               + glob.glob(os.path.join(ROOT, "Techniques", "glsl", "*", "*.glsl")))
TYPES = r"(?:void|float|int|uint|bool|[iu]?vec[234]|mat[234])"


def code_of(text):
    return re.sub(r"//[^\n]*", "", text)


def uses_paragraph(text):
    """The `// Uses:` line and the comment lines that continue it."""
    found = re.search(r"// Uses:(.*(?:\n//(?! *$).*)*)", text)
    return found.group(1) if found else None


texts = {path: open(path).read() for path in FILES}
defined = {}  # function -> files defining it
for path, text in texts.items():
    for match in re.finditer(r"(?m)^\s*" + TYPES + r"\s+(\w+)\s*\(", code_of(text)):
        defined.setdefault(match.group(1), set()).add(os.path.basename(path))

failures = []
for path, text in texts.items():
    name = os.path.basename(path)
    code = code_of(text)
    needed = set()
    for function, files in defined.items():
        if name not in files and re.search(r"\b" + function + r"\s*\(", code):
            needed |= files
    paragraph = uses_paragraph(text)
    if paragraph is None:
        failures.append("%s: no '// Uses:' line (it uses %s)"
                        % (name, ", ".join(sorted(needed)) or "nothing"))
        continue
    missing = sorted(file for file in needed if file not in paragraph)
    if missing:
        failures.append("%s: calls functions of %s, which its Uses line does not name"
                        % (name, ", ".join(missing)))

if len(FILES) < 30:
    failures.append("found only %d GLSL files under %s" % (len(FILES), ROOT))
for failure in failures:
    print("FAIL: " + failure)
if failures:
    sys.exit(1)
print("ok: %d GLSL files, each naming what it uses" % len(FILES))
