#!/bin/sh
# The package's types (issue 34): the stubs (python/subdivkit/*.pyi) agree with the module
# at run time (mypy's stubtest), `mypy --strict` passes on the examples and on the typed
# test file, and that file's checks hold when it runs.
# Usage: typing_test.sh SOURCE_DIR PACKAGE_PARENT (the folder holding subdivkit/, e.g.
# build/python). Environment: PYTHON (default /usr/bin/python3).
set -eu
fail() { echo "typing_test.sh: FAILED: $*" >&2; exit 1; }
source_dir=$(cd "$1" && pwd)
site=$(cd "$2" && pwd)
python=${PYTHON:-/usr/bin/python3}
"$python" -c "import mypy" 2> /dev/null || fail "mypy is not installed (Debian: python3-mypy; scripts/install-deps.sh)"
test -f "$site/subdivkit/py.typed" || fail "no py.typed in $site/subdivkit"
cache=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-mypy.XXXXXX")
trap 'rm -rf "$cache"' EXIT
cd "$source_dir"  # pyproject.toml's [tool.mypy]

echo "== stubtest: the stubs against the module"
# From the temporary folder: stubtest keeps its .mypy_cache in the working directory.
(cd "$cache" && PYTHONPATH="$site" "$python" -m mypy.stubtest subdivkit --mypy-config-file "$source_dir/pyproject.toml" \
  --allowlist "$source_dir/tests/install/stubtest_allowlist.txt") || fail "stubtest"
echo "== mypy --strict: examples/python and tests/install/typed_usage.py"
MYPYPATH="$site" "$python" -m mypy --strict --cache-dir "$cache" examples/python/*.py tests/install/typed_usage.py ||
  fail "mypy --strict"
echo "== typed_usage.py runs"
PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$python" tests/install/typed_usage.py examples/meshes/cube.obj ||
  fail "typed_usage.py"
echo "typing_test.sh: ok"
