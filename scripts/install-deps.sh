#!/usr/bin/env bash
# Installs every Debian package SubdivKit needs to build, test and benchmark.
# Run as root on Debian 12. Safe to run again: apt skips what is installed.
#
# VTK (for .vtp/.vtk/.pvd files) comes from one of two packages, and this script picks the
# one that does not break what is installed: Debian's VTK (libvtk9-dev) depends on
# python3-vtk9, which conflicts with ParaView's Python (python3-paraview, what pvpython and
# pvbatch need). On a machine with ParaView, SubdivKit builds against the VTK inside
# ParaView's development files (paraview-dev) instead. Force a choice with
# SUBDIV_VTK=debian or SUBDIV_VTK=paraview.
set -euo pipefail

source "$(dirname "$0")/apt-packages.sh"

vtk_package() {
  case "${SUBDIV_VTK:-auto}" in
    debian) echo libvtk9-dev; return ;;
    paraview) echo paraview-dev; return ;;
    auto) ;;
    *) echo "install-deps.sh: SUBDIV_VTK must be debian, paraview or auto (got '${SUBDIV_VTK}')" >&2; exit 2 ;;
  esac
  if installed libvtk9-dev; then echo libvtk9-dev
  elif installed python3-paraview || installed paraview || installed paraview-dev; then echo paraview-dev
  else echo libvtk9-dev
  fi
}

vtk=$(vtk_package)
if [ "$vtk" = libvtk9-dev ] && installed python3-paraview; then
  echo "install-deps.sh: SUBDIV_VTK=debian would remove ParaView's Python (python3-paraview conflicts with" \
       "python3-vtk9, which libvtk9-dev needs); use SUBDIV_VTK=paraview or leave it unset" >&2
  exit 2
fi
echo "VTK: $vtk"
vtk_packages=("$vtk")
# ParaView's VTK config looks for the libraries its IO modules were built with; Debian's
# libvtk9-dev pulls them in itself.
[ "$vtk" = paraview-dev ] && vtk_packages+=(libutfcpp-dev liblzma-dev liblz4-dev libdouble-conversion-dev zlib1g-dev libexpat1-dev)
# The ParaView plugin (plugins/paraview): ParaView's VTK links MPI, whose development files
# find_package(ParaView) needs; xvfb (with xauth, which xvfb-run uses) renders the docs'
# screenshots headless (docs/paraview.md).
[ "$vtk" = paraview-dev ] && vtk_packages+=(libopenmpi-dev xvfb xauth)

# CGAL (subdiv-bench-meshlibs only; optional there): Debian 12's libcgal-dev is CGAL 5.5,
# header-only; it pulls in libgmp-dev, libmpfr-dev and a few Boost -dev packages, and
# neither needs nor removes VTK or ParaView (checked with apt-get -s on a machine with
# python3-paraview).
packages=(
  build-essential cmake ninja-build pkg-config
  libopenmesh-dev nlohmann-json3-dev libfmt-dev doctest-dev
  "${vtk_packages[@]}" libeigen3-dev libmuparser-dev libcli11-dev libtbb-dev
  libosd-dev ccache
  libcgal-dev
  libmetis-dev openmpi-bin libopenmpi-dev
  pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib
  # Python's conversions to other libraries' meshes (python/subdivkit/conversions.py), in the
  # tests only; it needs no VTK.
  python3-open3d
  # Packaging (docs/install.md): Debian packages with CPack (dpkg-shlibdeps, file, the man
  # page; strace where tests/install cannot hide the source tree in a mount namespace), the
  # Python package (PEP 517 offline, a venv) and its types.
  dpkg-dev file help2man strace python3-setuptools python3-wheel python3-build python3-venv python3-pip python3-mypy
)
install_missing "${packages[@]}"
