#!/usr/bin/env bash
# Regenerates the reference table from its generator and requires it to be the checked-in one, so
# that kb_reference.txt, which the C++ tests read, cannot drift from kb_reference.py. Without
# python3 it exits 77, which CTest reports as a skip (scripts/install-deps.sh installs python3).
# Usage: check_reference.sh tests/reference
set -uo pipefail
folder=$1
command -v python3 > /dev/null || { echo "skipped: no python3"; exit 77; }
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
python3 "$folder/kb_reference.py" > "$generated" || { echo "FAILED: kb_reference.py did not run"; exit 1; }
if ! diff -u "$folder/kb_reference.txt" "$generated"; then
  echo "FAILED: kb_reference.txt is not what kb_reference.py writes (run it as its docstring says, read the diff)"
  exit 1
fi
echo "kb_reference.txt is what kb_reference.py writes ($(grep -c '^#' "$generated") sections)"
