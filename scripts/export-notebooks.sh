#!/usr/bin/env bash
# Executes every notebook and writes it as a self-contained HTML page into build/notebooks/
# (math typeset at export time, nothing loaded from the network; outputs never go into git).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-node-packages.sh
.venv/bin/python scripts/export_notebooks.py build/notebooks notebooks/*.ipynb
echo "HTML pages are in build/notebooks/ (they open offline)"
