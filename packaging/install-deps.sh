#!/usr/bin/env bash
# Installs every Debian 12 package Spira needs to build, test and package.
# Used by .ci/run and by the README's set-up commands; safe to run again.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake ninja-build pkg-config git file dpkg-dev \
  qtbase5-dev libqt5opengl5-dev libqt5svg5-dev qttools5-dev-tools \
  libvtk9-dev libvtk9-qt-dev \
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev \
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev \
  libeigen3-dev libassimp-dev liburdfdom-dev liburdfdom-headers-dev libtinyxml-dev \
  libsuitesparse-dev libopenblas0-pthread libtbb-dev nlohmann-json3-dev \
  libpetsc-real-dev openmpi-bin \
  libpcl-dev \
  libgtest-dev libgmock-dev \
  python3-dev pybind11-dev python3-numpy \
  xvfb xauth libgl1-mesa-dri mesa-utils \
  >/dev/null
