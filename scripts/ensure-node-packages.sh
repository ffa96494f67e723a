#!/usr/bin/env bash
# Makes sure node and the npm packages of package-lock.json are installed into node_modules/, which
# the build owns: MathJax, which typesets the notebook pages at export time and the browser page, and
# Pyodide, the Python runtime of the browser page (make web).
# As root with apt-get it installs Debian's nodejs and npm when node is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/apt-install.sh
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  apt_install ensure-node-packages nodejs npm || exit 1
fi
# npm ci writes node_modules/.package-lock.json; newer than the lock file means up to date.
if [ ! node_modules/.package-lock.json -nt package-lock.json ]; then
  echo "ensure-node-packages: npm ci (MathJax and Pyodide)"
  npm ci --no-audit --no-fund --loglevel=error
  touch node_modules/.package-lock.json
fi
