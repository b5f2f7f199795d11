#!/usr/bin/env bash
# Installs the Debian packages APCS needs to build, test and run, skipping those already present.
# Usage: scripts/install-deps.sh [--run | --packaging] [extra-package ...]   (README.md says why)
# Without an option: what building, running and testing need (scripts/test.sh). --run: only what
# building and running need (scripts/run.sh). --packaging: all that, and what building and checking
# the Debian package needs (scripts/package.sh, tests/e2e/debian_package.sh): debhelper and its
# bash-completion add-on, dpkg-dev, fakeroot, lintian, and man-db for `man apcs`.
set -euo pipefail
# CI (.ci/run) installs everything once, before its phases: their own runs of this have nothing to do.
[ -n "${APCS_DEPENDENCIES_CHECKED:-}" ] && exit 0

# libchafa-dev's pkg-config file asks for glib's (libglib2.0-dev), which Debian 12 does not bring with it.
build_and_run=(g++ cmake make ninja-build pkgconf libcli11-dev libeigen3-dev libpng-dev zlib1g-dev libgif-dev libexpat1-dev libchafa-dev libglib2.0-dev
               libncurses-dev console-setup-linux)
# Tests also need: python3 (the reference models in tests/reference), bsdutils (util-linux's
# `script`, a terminal for keys_from_pipe.sh), mount (the full-disk case of batch_faults.sh), and
# librsvg2-bin and imagemagick (svg_renders.sh renders the SVG pictures as viewers do; terminal_pictures.sh
# decodes the sixel files), xvfb, xterm, kitty, x11-apps and xfonts-base (terminal_shows_picture.sh shows
# the sixel file in xterm -ti vt340 -fn 9x15 and the kitty file in kitty on a virtual X server, and takes
# a screenshot with xwd), locales (localedef and its sources: locale_numbers.sh makes a German locale),
# chromium and poppler-utils (handout_print.sh prints a handout's index.html to PDF and counts its pictures),
# synfig (sif_renders.sh renders `apcs export --sif` documents with Synfig's own renderer), and
# openssh-server and openssh-client (ssh_session.py runs the session over a real SSH link: sshd on a port
# of its own, ssh -tt to it).
testing=(catch2 tmux procps groff-base python3 bsdutils mount librsvg2-bin imagemagick xvfb xterm kitty x11-apps
         xfonts-base locales chromium poppler-utils synfig openssh-server openssh-client)
case "${1:-}" in
  --run) testing=(); shift ;;
  --packaging) testing+=(debhelper dpkg-dev fakeroot bash-completion lintian man-db); shift ;;
esac

packages=("${build_and_run[@]}" "${testing[@]}" "$@")

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing packages: ${missing[*]}"
run_as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "Need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  run_as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" apt-get update -qq
"${run_as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
