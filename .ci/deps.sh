#!/usr/bin/env bash
# Installs every Debian 12 package Granota needs to build, run and test.
# Uses sudo when not root. Safe to run again: apt skips what is there.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PKGS=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-svg-dev
  qt6-translations-l10n libqcustomplot-dev libeigen3-dev libgmp-dev
  libbenchmark-dev libgl-dev appstream desktop-file-utils nlohmann-json3-dev
  locales clang clang-format libclang-rt-14-dev
  xvfb xauth x11-utils openbox xdotool
  # test_gui_tikz_latex compiles the TikZ exports with pdflatex, in an article and in beamer:
  # LaTeX, beamer (latex-recommended) and pgf/TikZ (pictures). About 64 MB to download,
  # 235 MB installed, 75 s on a Debian 12 runner.
  texlive-latex-base texlive-latex-recommended texlive-pictures
  # test_bspline_peers compares the B-spline evaluation with scipy's BSpline (python3 and numpy
  # come with it); the test skips where it is missing.
  python3-scipy
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
# The tests also run in a Catalan locale (decimal commas): generate it once.
if ! locale -a 2>/dev/null | grep -qi '^ca_ES\.utf-\?8$'; then
  $SUDO sed -i 's/^# *\(ca_ES\.UTF-8 UTF-8\)/\1/' /etc/locale.gen
  grep -q '^ca_ES.UTF-8 UTF-8' /etc/locale.gen || echo 'ca_ES.UTF-8 UTF-8' | $SUDO tee -a /etc/locale.gen >/dev/null
  $SUDO locale-gen >/dev/null
fi
