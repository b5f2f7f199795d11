#!/usr/bin/env bash
# Builds the Debian package (apcs_VERSION_ARCH.deb, with its .buildinfo and .changes) from a clean
# clone of the committed tree, so that nothing uncommitted or built before goes into it, and puts
# it in OUTPUT_FOLDER (default build/deb). Installs what is missing first.
# Usage: scripts/package.sh [--with-tests] [OUTPUT_FOLDER]   then: sudo apt install ./build/deb/apcs_*.deb
# The tests are not run (DEB_BUILD_OPTIONS=nocheck) unless --with-tests asks for them, as a Debian
# build daemon runs them, or DEB_BUILD_OPTIONS says otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
build_options=${DEB_BUILD_OPTIONS:-nocheck}
if [ "${1:-}" = --with-tests ]; then
  build_options=${DEB_BUILD_OPTIONS:-}
  shift
fi
bash scripts/install-deps.sh --packaging
output=$(realpath -m "${1:-build/deb}")
clone=$(mktemp -d)
trap 'rm -rf "$clone"' EXIT
git clone -q . "$clone/apcs"
(cd "$clone/apcs" &&
  DEB_BUILD_OPTIONS="$build_options parallel=$(nproc)" dpkg-buildpackage -us -uc -b)
# The build's tests may leave no program running (scripts/programs_left.sh says why).
bash scripts/programs_left.sh "$clone/apcs"
mkdir -p "$output"
mv "$clone"/*.deb "$clone"/*.buildinfo "$clone"/*.changes "$output"/
ls "$output"/apcs_*.deb
