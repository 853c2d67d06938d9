#!/usr/bin/env bash
# utilities/vtkPicture/vtkPicture.py, the picture of a case's ParaView files drawn by VTK, on
# solved copies made in WORK_DIR: tests:faultInCube (3D: a fault inside a cube, which the
# body's surface would hide in ParaView) and cases/paperBenchmark (2D). Checks, reading the PNG
# back with VTK: the size asked for; the fault drawn in the colour map's colours (its slip
# ranges over the map: both ends' hues present, blue at zero slip and red at the largest) and
# the body's grey edges; the run under a virtual display when there is none (DISPLAY unset);
# and the user errors (unknown array, unknown time, a folder without VTK files, no display and
# no xvfb-run) exit 1 with the message and write no picture.
# Usage: vtkPicture.sh BIN_DIR SOURCE_DIR WORK_DIR
set -uo pipefail
bin=$1 src=$2 work=$3
pic=$src/utilities/vtkPicture/vtkPicture.py
python=/usr/bin/python3
fail() { echo "FAIL [vtkPicture]: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
unset DISPLAY

solve() {  # solve SOURCE_CASE NAME
  local c=$work/$2
  cp -r "$1" "$c"
  "$c/Allclean" >/dev/null 2>&1 || true
  "$bin/splitFractureNodes" -case "$c" >"$c/log.split" 2>&1 || fail "$2: split"
  "$bin/frictionSolver" -case "$c" >"$c/log.solve" 2>&1 || fail "$2: solve ($(tail -2 "$c/log.solve"))"
}
solve "$src/tests/regression/cases/faultInCube" cube
solve "$src/cases/paperBenchmark" paper

# The picture's size and colours: fractions of pixels that are red-ish (the map's top), blue-ish
# (its bottom) and grey (the body's edges).
colours() {  # colours PNG W H
  "$python" - "$@" <<'PY'
import sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
path, w, h = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
r = vtk.vtkPNGReader()
r.SetFileName(path)
r.Update()
img = r.GetOutput()
dims = img.GetDimensions()
assert (dims[0], dims[1]) == (w, h), f"{path}: {dims[:2]} pixels, asked {w}x{h}"
px = vtk_to_numpy(img.GetPointData().GetScalars()).astype(int)[:, :3]
red = ((px[:, 0] > 180) & (px[:, 1] < 90) & (px[:, 2] < 90)).mean()
blue = ((px[:, 2] > 180) & (px[:, 0] < 90) & (px[:, 1] < 90)).mean()
grey = ((abs(px[:, 0] - px[:, 1]) < 12) & (abs(px[:, 1] - px[:, 2]) < 12) & (px[:, 0] > 60)
        & (px[:, 0] < 200)).mean()
print(f"{red:.5f} {blue:.5f} {grey:.5f}")
PY
}

# 3D, by the fault's normal and from the side: the fault in both of the map's end colours.
for view in normal iso; do
  out=$work/cube_$view.png
  msg=$("$python" "$pic" -case "$work/cube" -view $view -size 640,480 -o "$out" 2>&1) ||
    fail "3D -view $view: exit $?: $msg"
  [[ $msg == "vtkPicture: wrote $out (t = 1, slipMagnitude from 0 to "* ]] || fail "3D: message '$msg'"
  read -r red blue grey < <(colours "$out" 640 480) || fail "3D: the PNG does not read back"
  "$python" -c "import sys; r, b, g = map(float, sys.argv[1:]); sys.exit(0 if r > 1e-4 and b > 1e-4 and g > 1e-4 else 1)" \
    "$red" "$blue" "$grey" || fail "3D -view $view: red $red, blue $blue, grey $grey of the pixels"
  echo "PASS: 3D -view $view: red $red, blue $blue, grey $grey of the pixels"
done
# The default name, another array.
msg=$("$python" "$pic" -case "$work/cube" -array sigmaN 2>&1) || fail "3D -array sigmaN: $msg"
[[ -s $work/cube/postProcessing/vtk_sigmaN_1.png ]] || fail "no postProcessing/vtk_sigmaN_1.png"
# 2D: the fracture's polyline over the square's edges.
out=$work/paper.png
msg=$("$python" "$pic" -case "$work/paper" -size 500,500 -o "$out" 2>&1) || fail "2D: $msg"
read -r red blue grey < <(colours "$out" 500 500) || fail "2D: the PNG does not read back"
"$python" -c "import sys; r, b, g = map(float, sys.argv[1:]); sys.exit(0 if r + b > 1e-4 and g > 1e-4 else 1)" \
  "$red" "$blue" "$grey" || fail "2D: red $red, blue $blue, grey $grey"
echo "PASS: 2D: red $red, blue $blue, grey $grey of the pixels"

# User errors: exit 1, the message, no picture.
bad() {  # bad WHAT EXPECTED ARGS...
  local what=$1 expected=$2
  shift 2
  local out=$work/bad.png msg rc
  rm -f "$out"
  msg=$("$@" -o "$out" 2>&1)
  rc=$?
  ((rc == 1)) || fail "$what: exit $rc, expected 1: $msg"
  [[ $msg == *"$expected"* ]] || fail "$what: message '$msg' lacks '$expected'"
  [[ ! -e $out ]] || fail "$what: a picture was written"
  ls "$work" | grep -q '^\.bad' && fail "$what: a temporary file was left"
  echo "PASS: $what"
}
bad "unknown array" "-array nope: no fracture's .vtp has it at time 1" "$python" "$pic" -case "$work/cube" -array nope
bad "unknown time" "-time 7: not a written time (written: 0.25 0.5 0.75 1)" "$python" "$pic" -case "$work/cube" -time 7
mkdir -p "$work/empty"
bad "no VTK files" "no VTK/<case>.pvd" "$python" "$pic" -case "$work/empty"
bad "no display, no xvfb-run" "install the Debian package xvfb" env PATH=/nonexistent "$python" "$pic" -case "$work/cube"
echo "PASS: vtkPicture"
