#!/bin/sh
# The Python package the way pip users get it (issue 34): `python3 -m build --wheel
# --no-isolation` reusing the CMake build (SUBDIVKIT_BUILD_DIR), the wheel installed into a
# fresh `python3 -m venv --system-site-packages`, the pytest suite run there against it;
# then `pip install --no-build-isolation .` into the same venv, offline.
# Usage: wheel_test.sh SOURCE_DIR BUILD_DIR. Environment: PYTHON (default /usr/bin/python3).
set -eu
fail() { echo "wheel_test.sh: FAILED: $*" >&2; exit 1; }
source_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-wheel-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1  # offline, nothing kept

echo "== python3 -m build --wheel --no-isolation (SUBDIVKIT_BUILD_DIR=$build_dir)"
(cd "$source_dir" && SUBDIVKIT_BUILD_DIR="$build_dir" "$python" -m build --wheel --no-isolation --outdir "$work/dist" . \
  > "$work/build.log" 2>&1) || { tail -40 "$work/build.log"; fail "python3 -m build"; }
wheel=$(ls "$work"/dist/subdivkit-*.whl)
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build_dir/CMakeCache.txt")
case "$(basename "$wheel")" in "subdivkit-$version-"*) ;; *) fail "$(basename "$wheel") does not carry the CMake version $version (pyproject.toml)" ;; esac
echo "$(basename "$wheel"): $(unzip -l "$wheel" | tail -1 | awk '{print $2}') files"

echo "== a fresh venv (--system-site-packages: Debian's NumPy, SciPy, pytest) with the wheel"
"$python" -m venv --system-site-packages "$work/venv"
venv_python="$work/venv/bin/python"
"$venv_python" -m pip install -q --no-deps "$wheel" || fail "pip install the wheel"
(cd "$work" && env -u PYTHONPATH "$venv_python" - "$work/venv" <<'PY') || fail "the wheel's subdivkit"
import os, sys
import subdivkit as sk
venv = os.path.realpath(sys.argv[1])
here = os.path.realpath(os.path.dirname(sk.__file__))
assert here.startswith(venv), here
loop = [s for s in sk.schemes() if s["name"] == "loop"][0]
assert os.path.realpath(loop["path"]).startswith(here) and loop["origin"] == "built-in", loop
print("subdivkit", sk.__version__, "from", here, "- its schemes from", os.path.dirname(loop["path"]))
PY

if "$venv_python" -c "import mypy" 2> /dev/null; then
  echo "== mypy --strict finds the installed package's types (py.typed, PEP 561)"
  (cd "$source_dir" && env -u PYTHONPATH -u MYPYPATH "$venv_python" -m mypy --strict --cache-dir "$work/mypy-cache" \
    tests/install/typed_usage.py) || fail "mypy --strict against the installed wheel"
fi

echo "== pytest tests/python in the venv"
# The suite compares messages with the build's `subdiv`, which name the scheme files read:
# the build's `subdiv` runs on the wheel's libsubdiv (LD_LIBRARY_PATH comes before its
# RUNPATH), so both read the wheel's scheme files.
wheel_libs=$(cd "$work" && env -u PYTHONPATH "$venv_python" -c \
  "import os, subdivkit; print(os.path.join(os.path.dirname(subdivkit.__file__), 'lib'))")
(cd "$work" && env -u PYTHONPATH LD_LIBRARY_PATH="$wheel_libs" SUBDIV_CLI="$build_dir/tools/subdiv/subdiv" SUBDIV_SOURCE_DIR="$source_dir" MPLBACKEND=Agg \
  SUBDIV_NO_INSTALLED_PLUGINS=1 PYTHONDONTWRITEBYTECODE=1 \
  SUBDIV_PLUGIN_subdiv_sqrt2="$build_dir/plugins/subdiv_sqrt2.so" \
  SUBDIV_PLUGIN_test_plugin_wrong_version="$build_dir/plugins/test_plugin_wrong_version.so" \
  "$venv_python" -m pytest -q -p no:cacheprovider "$source_dir/tests/python") || fail "pytest in the venv"

echo "== pip install --no-build-isolation . (offline, the same build)"
(cd "$source_dir" && SUBDIVKIT_BUILD_DIR="$build_dir" "$venv_python" -m pip install -q --no-build-isolation \
  --force-reinstall --no-deps . > "$work/pip.log" 2>&1) || { tail -40 "$work/pip.log"; fail "pip install ."; }
(cd "$work" && env -u PYTHONPATH "$venv_python" -c "import subdivkit as sk; print('pip install .:', sk.__file__)") ||
  fail "import after pip install ."
echo "wheel_test.sh: ok"
