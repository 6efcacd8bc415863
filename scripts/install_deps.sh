#!/usr/bin/env bash
# Installs every build and test dependency from Debian 12 packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
  build-essential cmake ninja-build pkg-config ca-certificates \
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libfftw3-dev \
  libgtest-dev librapidcheck-dev nlohmann-json3-dev libcli11-dev \
  libsdp-dev coinor-csdp libsdpa-dev sdpa libmumps-seq-dev libopenblas-dev liblapack-dev gfortran \
  python3 python3-jsonschema python3-dev pybind11-dev python3-numpy \
  python3-venv python3-pip python3-setuptools python3-wheel python3-matplotlib python3-pandas python3-scipy \
  gnuplot-nox
