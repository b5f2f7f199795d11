#!/usr/bin/env bash
# Runs COMMAND... (a Catch2 test that makes a device node), or reports a CTest skip, exit 77 (the
# test's SKIP_RETURN_CODE), when the user is not root and cannot make one: mknod needs CAP_MKNOD.
# Root always runs the command, so CI (root) never skips it, and a node it cannot make fails there.
# Usage: mknod_or_skip.sh COMMAND...
set -uo pipefail
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
if [ "$(id -u)" -ne 0 ] && ! mknod "$probe/null" c 1 3 2> "$probe/err"; then
  echo "skipped: not root, and mknod cannot make a device node here: $(cat "$probe/err")"
  exit 77
fi
"$@"
