#!/usr/bin/env bash
# The session's split of two N-point keys (default 10^5: N files aniK.dat, atomic writes, one disk
# barrier) against a naive script that writes the same N files, the same bytes, plainly (open,
# write, close; no temporary file, no rename, no flush). Both run in fresh folders of the same
# file system, alternately, three times; the medians and their ratio are printed (issue 18 item 2:
# at most 2x). The split's time is the whole headless run, key parsing, start-up and its one
# syncfs included; the naive script flushes nothing.
# Usage: bench/compare_split.sh APCS [POINTS] [FOLDER]   (FOLDER: where to write, default /tmp)
set -euo pipefail
apcs=$(realpath "$1")
points=${2:-100000}
work=$(mktemp -d "${3:-/tmp}/apcs-split-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

for which in 1 2; do
  awk -v n="$points" -v k="$which" \
    'BEGIN { print "PART cloud OPEN"; for (i = 0; i < n; i++) printf "%.3f %.2f %d\n", i * 0.001, (i % 977) * 0.37 + k, k }' \
    > "$work/key$which.dat"
done
printf 'ENTER\nENTER\n' > "$work/split.keys"

# Seconds the split takes in a fresh folder $1.
time_split() {
  mkdir "$1"
  cp "$work/key1.dat" "$work/key2.dat" "$1/"
  python3 - "$apcs" "$work/split.keys" "$1" <<'EOF'
import subprocess, sys, time
apcs, keys, folder = sys.argv[1:]
start = time.perf_counter()
subprocess.run([apcs, "--keys", keys, "--workdir", folder], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(f"{time.perf_counter() - start:.3f}")
EOF
}

# Seconds a plain loop takes to write the files of folder $1 again into a fresh folder $2.
time_naive() {
  python3 - "$1" "$2" "$points" <<'EOF'
import os, sys, time
source, target, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
names = [f"ani{k}.dat" for k in range(1, count + 1)]
contents = []
for name in names:
    with open(os.path.join(source, name), "rb") as file:
        contents.append(file.read())
os.mkdir(target)
start = time.perf_counter()
for name, content in zip(names, contents):
    with open(os.path.join(target, name), "wb") as file:
        file.write(content)
print(f"{time.perf_counter() - start:.3f}")
EOF
}

split_times=()
naive_times=()
# Each run starts from a clean file system (sync), so that the split's own barrier flushes only
# its own files. Nothing is removed before the end: removing 2N files between rounds slowed the
# next run several times over.
for round in 1 2 3; do
  sync
  split_times+=("$(time_split "$work/split$round")")
  sync
  naive_times+=("$(time_naive "$work/split$round" "$work/naive$round")")
done
median() { printf '%s\n' "$@" | sort -n | sed -n 2p; }
split_median=$(median "${split_times[@]}")
naive_median=$(median "${naive_times[@]}")
echo "split of $points points: ${split_times[*]} s (median $split_median s)"
echo "naive script, same files: ${naive_times[*]} s (median $naive_median s)"
awk -v s="$split_median" -v n="$naive_median" 'BEGIN { printf "ratio split / naive: %.2f\n", s / n }'
