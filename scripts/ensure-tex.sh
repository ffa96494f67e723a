#!/usr/bin/env bash
# Makes sure pdflatex (with beamer) and pdftoppm exist for the LaTeX compile tests.
# As root with apt-get it installs Debian's packages; otherwise it says how to.
set -u
missing=()
command -v pdflatex >/dev/null 2>&1 || missing+=(pdflatex)
kpsewhich beamer.cls >/dev/null 2>&1 || missing+=(beamer)
kpsewhich pgfcore.sty >/dev/null 2>&1 || missing+=(pgf)  # beamer needs pgf, in texlive-pictures
command -v pdftoppm >/dev/null 2>&1 || missing+=(pdftoppm)
[ ${#missing[@]} -eq 0 ] && exit 0
packages="texlive-latex-base texlive-latex-recommended texlive-pictures texlive-fonts-recommended lmodern poppler-utils"
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "ensure-tex: installing ${packages} (missing: ${missing[*]})"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null && apt-get install -y -q --no-install-recommends $packages >/dev/null \
    || { echo "ensure-tex: apt-get install failed" >&2; exit 1; }
  exit 0
fi
echo "ensure-tex: missing ${missing[*]}. Install them with:" >&2
echo "    sudo apt-get install ${packages}" >&2
echo "ensure-tex: the LaTeX compile tests will be skipped until then." >&2
exit 0
