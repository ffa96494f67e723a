#!/usr/bin/env bash
# Makes sure Debian's Chromium exists for the notebook-page test (tests/test_notebook_pages.py),
# which drives it with Playwright; Playwright's own browser download is not used.
# The emoji font draws the ✅/❌ of the errata tables in the screenshots.
set -u
source "$(dirname "$0")/apt-install.sh"
command -v chromium >/dev/null 2>&1 && [ -e /usr/share/fonts/truetype/noto/NotoColorEmoji.ttf ] && exit 0
apt_install ensure-browser chromium fonts-dejavu-core fonts-noto-color-emoji
status=$?
[ $status = 2 ] && echo "ensure-browser: the notebook-page test will be skipped until then (outside CI)." >&2
[ $status = 1 ] && exit 1
exit 0
