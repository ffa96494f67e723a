#!/usr/bin/env bash
# Sourced by the ensure-*.sh scripts: install Debian packages the build needs.
#   apt_install WHO PACKAGE...
# As root with apt-get it installs them (status 0, or 1 if apt-get fails); otherwise it says how
# to install them and returns 2, so that the caller decides whether that is fatal.
apt_install() {
  local who=$1
  shift
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "${who}: installing $*"
    DEBIAN_FRONTEND=noninteractive apt-get update -q >/dev/null \
      && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "$@" >/dev/null \
      || { echo "${who}: apt-get install failed" >&2; return 1; }
    return 0
  fi
  echo "${who}: missing. Install with:" >&2
  echo "    sudo apt-get install $*" >&2
  return 2
}
