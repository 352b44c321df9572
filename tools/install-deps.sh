#!/bin/sh
# Install the Debian 12 packages C2Blend needs. Idempotent: apt-get runs only when a
# package is missing. Uses sudo when not root.
set -eu
PKGS="build-essential cmake pkg-config libfftw3-dev libcjson-dev libmatheval-dev
liblapacke-dev liblapack-dev python3 python3-numpy python3-matplotlib g++
freecad-python3 libocct-foundation-dev libocct-modeling-data-dev libtbb-dev
libcgal-dev libeigen3-dev python3-dev python3-pytest
clang libclang-rt-14-dev valgrind
xvfb xauth"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO=sudo
  echo "install-deps: installing$missing"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
fi
