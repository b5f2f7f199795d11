#!/usr/bin/env bash
# Builds the Debian package (apcs_VERSION_ARCH.deb, with its .buildinfo and .changes) from a clean
# clone of the committed tree, so that nothing uncommitted or built before goes into it, and puts
# it in OUTPUT_FOLDER (default build/deb). Installs what is missing first.
# Usage: scripts/package.sh [OUTPUT_FOLDER]      then: sudo apt install ./build/deb/apcs_*.deb
# The tests are not run again (DEB_BUILD_OPTIONS=nocheck) unless DEB_BUILD_OPTIONS says otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --packaging
output=$(realpath -m "${1:-build/deb}")
clone=$(mktemp -d)
trap 'rm -rf "$clone"' EXIT
git clone -q . "$clone/apcs"
(cd "$clone/apcs" &&
  DEB_BUILD_OPTIONS="${DEB_BUILD_OPTIONS:-nocheck} parallel=$(nproc)" dpkg-buildpackage -us -uc -b)
mkdir -p "$output"
mv "$clone"/*.deb "$clone"/*.buildinfo "$clone"/*.changes "$output"/
ls "$output"/apcs_*.deb
