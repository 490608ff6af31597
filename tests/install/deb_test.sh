#!/bin/sh
# The Debian packages on this machine (issue 34): apt-get install ./*.deb and the smoke
# test of installed_checks.sh with the source and build trees hidden (hide_trees.sh), then
# apt-get remove, after which no file of the packages is left, then purge.
# Usage: deb_test.sh SOURCE_DIR BUILD_DIR (the packages in BUILD_DIR/packages). Run as root.
# Environment: PYTHON (default /usr/bin/python3), PVBATCH (optional).
set -eu
fail() { echo "deb_test.sh: FAILED: $*" >&2; exit 1; }
source_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-deb-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp "$build_dir"/packages/*.deb "$work/" || fail "no packages in $build_dir/packages (scripts/package.sh)"
cp "$source_dir/examples/meshes/cube.obj" "$work/"
cp -R "$source_dir/plugins/template" "$work/template"
cp "$here/installed_checks.sh" "$here/hide_trees.sh" "$work/"
mkdir "$work/cwd"
packages=$(for deb in "$work"/*.deb; do dpkg-deb -f "$deb" Package; done | tr '\n' ' ')
echo "== apt-get install ./*.deb ($(echo $packages))"

export DEBIAN_FRONTEND=noninteractive
# The install runs with the trees hidden too: the packages carry all they need.
cat > "$work/install_and_check.sh" <<SH
set -e
apt-get install -y -qq --no-install-recommends $(for deb in "$work"/*.deb; do printf '%s ' "$deb"; done) > "$work/apt.log" 2>&1 ||
  { cat "$work/apt.log"; echo "apt-get install failed" >&2; exit 1; }
for p in $packages; do dpkg-query -W -f='\${Package} \${Version} \${Status}\n' "\$p"; done
test -f /usr/share/man/man1/subdiv.1.gz || { echo "no man page /usr/share/man/man1/subdiv.1.gz" >&2; exit 1; }
man -w subdiv > /dev/null 2>&1 || ! command -v man > /dev/null || { echo "man does not find subdiv(1)" >&2; exit 1; }
sh "$work/installed_checks.sh"
SH
# Python writes its byte-code (__pycache__) as it would for a user: removal must clean it.
env -u SUBDIV_SCHEME_PATH -u SUBDIV_PLUGIN_PATH -u SUBDIV_NO_INSTALLED_PLUGINS -u PYTHONPATH -u PYTHONDONTWRITEBYTECODE \
  WORK="$work" PREFIX=/usr CMAKE_COMMAND="${CMAKE_COMMAND:-cmake}" CMAKE_GENERATOR="${CMAKE_GENERATOR:-Unix Makefiles}" \
  PYTHON="${PYTHON:-/usr/bin/python3}" PVBATCH="${PVBATCH:-}" PV_AUTOLOAD=1 \
  sh "$work/hide_trees.sh" "$source_dir" "$build_dir" "$work/cwd" sh "$work/install_and_check.sh" ||
  { apt-get purge -y -qq $packages > /dev/null 2>&1 || true; fail "the installed packages (above)"; }

echo "== apt-get remove: nothing of the packages may stay"
for p in $packages; do dpkg -L "$p"; done | sort -u > "$work/files.txt"
apt-get remove -y -qq $packages > "$work/remove.log" 2>&1 || { cat "$work/remove.log"; fail "apt-get remove"; }
left=""
while IFS= read -r f; do
  # Folders other packages share (/usr/lib, /usr/share/man/man1) stay; files and our own folders may not.
  if [ -e "$f" ] && { [ ! -d "$f" ] || [ -z "$(dpkg -S "$f" 2> /dev/null)" ]; }; then left="$left $f"; fi
done < "$work/files.txt"
apt-get purge -y -qq $packages > /dev/null 2>&1 || true
test -z "$left" || fail "left after apt-get remove:$left"
for p in $packages; do
  if dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "installed"; then fail "$p is still installed"; fi
done
echo "deb_test.sh: ok ($(wc -l < "$work/files.txt") paths installed and removed)"
