#!/bin/sh
# hide_trees.sh SOURCE_DIR BUILD_DIR WORKDIR COMMAND...: runs COMMAND in WORKDIR where the
# source and build trees cannot be used. In a private mount namespace (unshare: as root,
# or as a user where user namespaces are allowed) both are covered by empty folders;
# elsewhere COMMAND runs under strace, and any file operation under them fails the run;
# where neither works (a locked-down container) it runs unhidden, with a warning.
set -eu
source_dir=$1 build_dir=$2 workdir=$3
shift 3
fail() { echo "hide_trees.sh: FAILED: $*" >&2; exit 1; }
case "$workdir" in "$source_dir"/* | "$build_dir"/*) fail "$workdir is inside the source or build tree" ;; esac

if unshare -m true 2> /dev/null; then how="unshare -m"
elif unshare -rm true 2> /dev/null; then how="unshare -rm"
else how=""
fi
if [ -n "$how" ]; then
  echo "hide_trees.sh: $source_dir and $build_dir hidden ($how, empty folders over them)"
  # The build tree first: it may lie inside the source tree.
  exec $how sh -c '
    for d in "$1" "$2"; do mount -t tmpfs -o size=1m hidden "$d" || exit 1; done
    test -z "$(ls -A "$2")" || { echo "hide_trees.sh: $2 is not hidden" >&2; exit 1; }
    cd "$3" && shift 3 && exec "$@"' hide "$build_dir" "$source_dir" "$workdir" "$@"
fi
if ! strace -f -qq -o /dev/null true 2> /dev/null; then
  # Neither a mount namespace nor ptrace here (a locked-down container): the checks still
  # run on a moved prefix, but cannot prove that nothing of the trees is used.
  echo "hide_trees.sh: WARNING: no mount namespace and no strace here; running without hiding $source_dir and $build_dir" >&2
  cd "$workdir" && exec "$@"
fi
echo "hide_trees.sh: no mount namespace here; under strace, nothing in $source_dir or $build_dir may be looked at"
log=$(mktemp "${TMPDIR:-/tmp}/hide_trees.XXXXXX")
trap 'rm -f "$log"' EXIT
(cd "$workdir" && strace -f -qq -e trace=%file -o "$log" "$@")
if grep -F -e "\"$source_dir/" -e "\"$source_dir\"" -e "\"$build_dir/" -e "\"$build_dir\"" "$log" > "$log.touched"; then
  head -20 "$log.touched" >&2
  rm -f "$log.touched"
  fail "the command looked into the source or build tree (above)"
fi
rm -f "$log.touched"
