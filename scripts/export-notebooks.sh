#!/usr/bin/env bash
# Executes every notebook and writes it as HTML into build/notebooks/ (outputs never go into git).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build/notebooks
.venv/bin/jupyter nbconvert --to html --execute --ExecutePreprocessor.timeout=300 \
  --output-dir build/notebooks notebooks/*.ipynb
echo "HTML pages are in build/notebooks/"
