#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Draws docs/images/architecture.svg from its source, docs/architecture.dot
# (Graphviz), after installing Graphviz when it is missing. Run it after
# editing the source and commit both.
#
#   bash scripts/diagram.sh
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$(softshadows_root)"

softshadows_install_packages graphviz
dot -Tsvg docs/architecture.dot -o docs/images/architecture.svg
echo "docs/images/architecture.svg"
