#!/usr/bin/env bash
# Makes sure Debian's Chromium exists for the notebook-page test (tests/test_notebook_pages.py),
# which drives it with Playwright; Playwright's own browser download is not used.
# As root with apt-get it installs the package; otherwise it says how to.
set -u
# The emoji font draws the ✅/❌ of the errata tables in the screenshots.
command -v chromium >/dev/null 2>&1 && [ -e /usr/share/fonts/truetype/noto/NotoColorEmoji.ttf ] && exit 0
packages="chromium fonts-dejavu-core fonts-noto-color-emoji"
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "ensure-browser: installing ${packages}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null && apt-get install -y -q --no-install-recommends $packages >/dev/null \
    || { echo "ensure-browser: apt-get install failed" >&2; exit 1; }
  exit 0
fi
echo "ensure-browser: chromium or its fonts are missing. Install them with:" >&2
echo "    sudo apt-get install ${packages}" >&2
echo "ensure-browser: the notebook-page test will be skipped until then (outside CI)." >&2
exit 0
