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
source "$(dirname "$0")/apt-install.sh"
apt_install ensure-tex texlive-latex-base texlive-latex-recommended texlive-pictures texlive-fonts-recommended \
  lmodern poppler-utils
case $? in
  1) exit 1 ;;
  2) echo "ensure-tex: the LaTeX compile tests will be skipped until then (missing: ${missing[*]})." >&2 ;;
esac
exit 0
