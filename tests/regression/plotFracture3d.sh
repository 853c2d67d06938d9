#!/usr/bin/env bash
# Regression test for plotFracture.py on 3D fracture tables. The cases are synthetic
# (plotFracture3dCase.py): a flat inclined penny with the analytic penny-crack slip at two
# times, the same nodes on a curved cap ('# frame per node'), a flat rectangle (and locked:
# no slip), the penny's nodes with slip on a patch off the centre, the penny horizontal and
# vertical. Checks:
#  * the maps and the profile are real PNGs (magic bytes, not empty);
#  * the maps' axes (printed: along strike right, up dip up) are README.md's strike and
#    up dip, recomputed from the normal (a horizontal fault: x right, y up); the default
#    profiles (CSV column profile: strike, dip) pass through the node of largest slip (the
#    centroid when nothing slips), along strike (constant z) and up dip (deep end first), end
#    to end across the fault; on the patch they sample its peak;
#  * no axis of any figure uses an offset (plotNoOffset.py, sigma_n near -2.87e7 Pa);
#  * the profile's samples (-profileCsv) lie on the segment and match the analytic values:
#    sigmaN and tauMagnitude (linear in x y z, so reproduced by linear interpolation) to 1e-9
#    relative (round-off); |slip| = K sqrt(A^2 - r^2) to the bound of linear interpolation
#    of that function at r <= 0.8 A (see checkProfile below), r the distance in the map
#    plane from the penny's centre; both for the default segment and for a -line whose
#    points lie off the plane (projected on it);
#  * tables with a fluid pressure (columns pressure, sigmaNEffective): two more maps (p and
#    sigma'_n), two more profile rows and two more CSV columns, p and sigma_n + p exact;
#  * bad input (a table without rows, a missing column, an unknown state, a malformed -line,
#    a -line that misses the fault, -line with several faults, a bad -samples, an unknown
#    image format) exits 1 with a message naming the file or the option, and leaves no PNG,
#    no CSV and no temporary file.
# Usage: plotFracture3d.sh SOURCE_DIR WORK_DIR
set -uo pipefail
src=$1 work=$2
plot=$src/utilities/plotFracture/plotFracture.py
make=$src/tests/regression/plotFracture3dCase.py
python=/usr/bin/python3  # Debian's, which sees python3-matplotlib (etc/debian-packages)
export PYTHONDONTWRITEBYTECODE=1  # the generator is imported from the source tree: write nothing there
fail() { echo "FAIL [plotFracture3d]: $*"; exit 1; }

[[ -x $python ]] || fail "$python missing (install python3-matplotlib)"
"$python" -c "import matplotlib, numpy" 2>/dev/null || fail "matplotlib/numpy missing"
rm -rf "$work" && mkdir -p "$work"

isPng() {  # non-empty, starts with the 8-byte PNG signature
  [[ -s $1 ]] || return 1
  [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]
}
pngHeight() {  # the height in pixels, from the IHDR chunk (bytes 20-23, big-endian)
  echo $((16#$(head -c 24 "$1" | tail -c 4 | od -An -tx1 | tr -d ' \n')))
}

# checkProfile CSV KIND: the samples against the analytic penny (constants of the generator).
checkProfile() {
  "$python" - "$1" "$make" "$2" <<'PY'
import csv, os, sys
import numpy as np
sys.path.insert(0, os.path.dirname(sys.argv[2]))
import plotFracture3dCase as case
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows, "empty profile CSV"
times = sorted({r["time"] for r in rows}, key=float)
expectTimes = ["0.5", "1"] if sys.argv[3] == "disc" else ["1"]
assert times == expectTimes, f"times {times}, expected {expectTimes}"
scale = {"0.5": 0.5, "1": 1.0}
# Each segment (the default pair: column profile, strike then dip; -line: no such column):
# the samples' x y z on one straight line, distance = |p - p0|.
for kind in dict.fromkeys(r.get("profile") for r in rows):
    pts = np.array([[float(r[k]) for k in "xyz"] for r in rows
                    if r["time"] == "1" and r.get("profile") == kind])
    dist = np.array([float(r["distance"]) for r in rows
                     if r["time"] == "1" and r.get("profile") == kind])
    assert len(pts) == 201, f"{kind}: {len(pts)} samples, expected 201"
    assert np.allclose(np.linalg.norm(pts - pts[0], axis=1), dist, rtol=0, atol=1e-9), \
        f"{kind}: distance is not the distance from the first point"
    d = (pts[-1] - pts[0]) / dist[-1]
    off = (pts - pts[0]) - np.outer((pts - pts[0]) @ d, d)
    assert np.abs(off).max() < 1e-9, f"{kind}: samples off the segment"
# Interpolation bound for f = K sqrt(A^2 - r^2) on the disc's nodes: |f - I f| <= h^2/2 *
# max |D^2 f| (h the longest triangle edge, <= 1.1 * A/20 for these rings) and
# |D^2 f| <= K A^2 / (A^2 - r^2)^(3/2); taken at r = 0.8 A + h (the triangles that hold
# the samples with r <= 0.8 A): ~3e-6 m here, against a peak slip of 5.5e-4 m.
A, K = case.A, case.K
h = 1.1 * A / case.RINGS
rb = 0.8 * A + h
tol = h * h / 2 * K * A * A / (A * A - rb * rb) ** 1.5
checked = exact = 0
worst = 0.0
for r in rows:
    p = np.array([float(r[k]) for k in "xyz"])
    q = p - case.C
    u, v = q @ case.T1, q @ case.T2
    rad = np.hypot(u, v)
    slip = float(r["slipMagnitude"])
    expect = scale[r["time"]] * K * np.sqrt(max(A * A - rad * rad, 0.0))
    if rad <= 0.8 * A:
        assert np.isfinite(slip), f"nan slip at r = {rad} inside the penny"
        worst = max(worst, abs(slip - expect))
        assert abs(slip - expect) <= tol, \
            f"slip {slip} at r = {rad:.4f}, analytic {expect}, tolerance {tol:.3g}"
        checked += 1
    sn = float(r["sigmaN"])
    # Tractions cover the non-tip nodes' triangulation: up to the last ring inside the rim.
    assert rad > 0.9 * A or np.isfinite(sn), f"nan sigmaN at r = {rad} inside the penny"
    if np.isfinite(sn):
        s = case.C + u * case.T1 + v * case.T2  # where the generator evaluates them
        assert abs(sn - case.sigmaN(s)) <= 1e-9 * abs(case.sigmaN(s)), \
            f"sigmaN {sn} vs {case.sigmaN(s)}"
        tm = float(r["tauMagnitude"])
        assert abs(tm - case.tauMagnitude(s)) <= 1e-9 * abs(case.tauMagnitude(s)), "tauMagnitude"
        assert abs(float(r["ST"]) - tm / -sn) <= 0.01 * tm / -sn, "ST far from |tau|/-sigmaN"
        exact += 1
assert checked >= 100 and exact >= 100, f"only {checked} slip and {exact} traction samples checked"
print(f"  {sys.argv[3]}: {checked} slip samples within {worst:.2e} m of the analytic penny "
      f"slip (tolerance {tol:.2e} m), {exact} traction samples exact to 1e-9")
PY
}

noOutput() {  # no PNG and no temporary file anywhere in the case folder
  local left
  left=$(find "$1" \( -name '*.png' -o -name '*.tmp' -o -name '*.csv' \) | head -3)
  [[ -z $left ]] || fail "$2: a failed run left: $left"
}

# The flat penny, two times, default profiles: along strike and along dip through the node of
# largest slip (the centre C).
disc=$work/disc
"$python" "$make" "$disc" disc || fail "cannot write the synthetic penny"
out=$("$python" "$plot" -case "$disc" -profileCsv "$disc/profile.csv" 2>&1); rc=$?
printf '%s\n' "$out"
((rc == 0)) || fail "penny: exit $rc"
for png in "$disc"/postProcessing/fracture_fault{,_profile}.png; do
  isPng "$png" || fail "$png missing, empty or not a PNG"
done
grep -qF "maps of slip magnitude, ST and node states at t = 1" <<<"$out" || fail "penny: $out"
checkProfile "$disc/profile.csv" disc || fail "penny: default profile"

# checkDefault CASE SHAPE CENTRE: the default profiles and the maps' axes of a flat fault.
#  * the maps line says: "axes: along strike (s) right, up dip (u) up": s and -u the strike
#    and dip of README.md ("Fluid pressure"), recomputed here from the fault's normal:
#    s horizontal, u in the plane, up (z > 0) unless the fault is horizontal (then s = x,
#    u = y: a map view), -u the steepest way down, and seen from above -u is s turned
#    clockwise by 90 degrees (a vertical fault: u = z, s of azimuth in (-90, 90] from x);
#  * the CSV's first column is profile (strike, then dip), 201 samples each;
#  * both segments pass through CENTRE (the node of largest slip, or the centroid when
#    nothing slips), the strike one along +s (constant z), the dip one along +u (from the
#    deep end up), and both end on the fault's border (BORDER: distance from C in the map
#    plane at the ends, "disc" or "rectangle").
checkDefault() {
  "$python" - "$1" "$make" "$2" "$3" "$4" <<'PY'
import csv, os, re, sys
import numpy as np
case_dir, make, shape, centre, border = sys.argv[1:6]
sys.path.insert(0, os.path.dirname(make))
import plotFracture3dCase as case
n, t1, t2 = case.shapeFrame(shape)
# The README's rule, written out again (not the script's code).
if abs(n[2]) > 1 - 1e-12:
    strike, dip = np.array([1.0, 0, 0]), np.array([0, -1.0, 0])
elif abs(n[2]) < 1e-12:
    dip = np.array([0, 0, -1.0])
    strike = np.array([-n[1], n[0], 0]) / np.hypot(n[0], n[1])
    strike = strike if strike[0] > 0 or (strike[0] == 0 and strike[1] > 0) else -strike
else:
    dip = np.array([0, 0, -1.0]) + n[2] * n  # -z projected on the plane: the steepest way down
    dip /= np.linalg.norm(dip)
    # Seen from above, strike turned clockwise by 90 degrees, (sx, sy) -> (sy, -sx), is dip's
    # horizontal part.
    strike = np.array([-dip[1], dip[0], 0]) / np.hypot(dip[0], dip[1])
    assert dip[2] < 0 and abs(dip @ n) < 1e-12 and abs(strike @ n) < 1e-12
up = -dip
out = open(os.path.join(case_dir, "out.txt")).read()
m = re.search(r"axes: along strike \(([^()]*)\) right, up dip \(([^()]*)\) up", out)
assert m, f"no map axes in: {out}"
s, u = (np.array([float(c) for c in g.split()]) for g in m.groups())
assert np.allclose(s, strike, atol=1e-6), f"map's horizontal axis {s}, strike is {strike}"
assert np.allclose(u, up, atol=1e-6), f"map's vertical axis {u}, up dip is {up}"
assert abs(n[2]) > 1 - 1e-12 or u[2] > 0, f"the map's vertical axis {u} does not go up in z"
rows = list(csv.DictReader(open(os.path.join(case_dir, "profile.csv"))))
assert list(rows[0])[:6] == ["profile", "time", "distance", "x", "y", "z"], list(rows[0])
kinds = list(dict.fromkeys(r["profile"] for r in rows))
assert kinds == ["strike", "dip"], kinds
c = np.array([float(x) for x in centre.split(",")])
for kind, along in (("strike", strike), ("dip", up)):
    seg = [r for r in rows if r["profile"] == kind and r["time"] == "1"]
    assert len(seg) == 201, f"{kind}: {len(seg)} samples"
    pts = np.array([[float(r[k]) for k in "xyz"] for r in seg])
    d = (pts[-1] - pts[0]) / np.linalg.norm(pts[-1] - pts[0])
    assert np.allclose(d, along, atol=1e-9), f"{kind} segment along {d}, expected {along}"
    q = c - pts[0]
    assert np.linalg.norm(q - (q @ d) * d) < 1e-9, f"{kind} segment misses {c}"
    assert 0 <= q @ d <= np.linalg.norm(pts[-1] - pts[0]), f"{c} not between the ends"
    if kind == "strike":
        assert np.ptp(pts[:, 2]) < 1e-9, f"strike segment not horizontal: z {np.ptp(pts[:, 2])}"
    elif abs(n[2]) < 1 - 1e-12:
        assert pts[-1, 2] > pts[0, 2], "the dip segment does not start at its deep end"
    for p in (pts[0], pts[-1]):  # on the border, in the map plane's (t1, t2)
        a, b = (p - case.C) @ t1, (p - case.C) @ t2
        if border == "disc":  # the rim: a polygon of 120 nodes at radius A
            r = np.hypot(a, b)
            assert case.A * np.cos(np.pi / 120) - 1e-9 <= r <= case.A + 1e-9, \
                f"{kind}: end at r = {r}, not on the rim"
        else:
            assert abs(max(abs(a), 2 * abs(b)) - 1) < 1e-9, f"{kind}: end ({a}, {b}) inside"
    slip = np.array([float(r["slipMagnitude"]) for r in seg])
    assert np.all(np.isfinite(slip)), f"{kind}: samples off the fault"
print(f"  {shape}: map axes strike {s}, up dip {u}; the profiles along them through {c}, "
      "end to end")
PY
}
printf '%s\n' "$out" >"$disc/out.txt"
checkDefault "$disc" disc 1,2,3 disc || fail "penny: default profiles or map axes"
# The slip at the profiles' ends (the rim's tips) is 0, the largest at C (K A) is sampled.
"$python" - "$disc/profile.csv" "$make" <<'PY' || fail "penny: slip along the default profiles"
import csv, os, sys
sys.path.insert(0, os.path.dirname(sys.argv[2]))
import plotFracture3dCase as case
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["time"] == "1"]
for kind in ("strike", "dip"):
    slip = [float(r["slipMagnitude"]) for r in rows if r["profile"] == kind]
    assert abs(slip[0]) < 1e-9 and abs(slip[-1]) < 1e-9, f"{kind}: slip at the rim"
    assert max(slip) > 0.999 * case.K * case.A, f"{kind}: the peak {max(slip)} missed"
PY

# Slip on a patch off the centre: the profiles go through its largest slip (a profile
# through the centroid would cross little or none of it), and each samples its peak.
pa=$work/patch
"$python" "$make" "$pa" patch || fail "cannot write the patch case"
out=$("$python" "$plot" -case "$pa" -profileCsv "$pa/profile.csv" 2>&1) || fail "patch: $out"
printf '%s\n' "$out" >"$pa/out.txt"
peak=$("$python" - "$make" <<'PY'
import os, sys
sys.path.insert(0, os.path.dirname(sys.argv[1]))
import plotFracture3dCase as case
print(",".join(f"{c:.17g}" for c in case.C + case.PATCH[0] * case.T1 + case.PATCH[1] * case.T2))
PY
)
checkDefault "$pa" patch "$peak" disc || fail "patch: default profiles"
"$python" - "$pa/profile.csv" "$make" <<'PY' || fail "patch: the profiles miss the slip"
import csv, os, sys
sys.path.insert(0, os.path.dirname(sys.argv[2]))
import plotFracture3dCase as case
rows = list(csv.DictReader(open(sys.argv[1])))
peak = case.K * case.A / 2
for kind in ("strike", "dip"):
    slip = max(float(r["slipMagnitude"]) for r in rows if r["profile"] == kind)
    assert slip > 0.99 * peak, f"{kind}: largest sampled slip {slip}, the patch's {peak}"
PY
isPng "$pa/postProcessing/fracture_fault_profile.png" || fail "patch: no profile PNG"
# A horizontal fault (n pointing down): a map view, x right, y up; a vertical one: z up.
for shape in horizontal vertical; do
  f=$work/$shape
  "$python" "$make" "$f" "$shape" || fail "cannot write the $shape case"
  out=$("$python" "$plot" -case "$f" -profileCsv "$f/profile.csv" 2>&1) || fail "$shape: $out"
  printf '%s\n' "$out" >"$f/out.txt"
  checkDefault "$f" "$shape" 1,2,3 disc || fail "$shape: default profiles or map axes"
  isPng "$f/postProcessing/fracture_fault.png" || fail "$shape: no maps PNG"
done

# A segment given with -line, its points off the plane (projected), chosen outputs.
line=$("$python" - "$make" <<'PY'
import os, sys
sys.path.insert(0, os.path.dirname(sys.argv[1]))
import plotFracture3dCase as case
p0 = case.C - 0.3 * case.T1 + 0.45 * case.T2 + 0.2 * case.N
p1 = case.C + 0.35 * case.T1 - 0.4 * case.T2 - 0.1 * case.N
print(":".join(",".join(f"{c:.17g}" for c in p) for p in (p0, p1)))
PY
)
out=$("$python" "$plot" -case "$disc" -fracture fault -times 0.5,1 -line "$line" \
      -o "$work/maps.png" -profile "$work/profile.png" -profileCsv "$work/line.csv" \
      -noConvergence 2>&1); rc=$?
((rc == 0)) || fail "-line run: exit $rc: $out"
isPng "$work/maps.png" || fail "-o: no PNG"
isPng "$work/profile.png" || fail "-profile: no PNG"
# The CSV's x y z are on the given 3D segment (off the plane), the values at the projection.
"$python" - "$work/line.csv" "$line" <<'PY' || fail "-line: samples not on the given segment"
import csv, sys
import numpy as np
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["time"] == "1"]
p0, p1 = (np.array([float(c) for c in s.split(",")]) for s in sys.argv[2].split(":"))
assert np.allclose([float(rows[0][k]) for k in "xyz"], p0, atol=1e-9)
assert np.allclose([float(rows[-1][k]) for k in "xyz"], p1, atol=1e-9)
# One segment: the columns without 'profile'.
header = open(sys.argv[1]).readline().strip()
assert header == "time,distance,x,y,z,slipMagnitude,sigmaN,tauMagnitude,ST", header
PY
# checkProfile measures r in the plane, so it checks the projection too.
checkProfile "$work/line.csv" disc || fail "-line profile"

# The curved cap (per-node frame): the maps in the mean plane, the same analytic profile.
cap=$work/cap
"$python" "$make" "$cap" cap || fail "cannot write the synthetic cap"
grep -q "^# frame per node" "$cap/1/fractures/fault.dat" || fail "cap: no per-node frame line"
out=$("$python" "$plot" -case "$cap" -profileCsv "$cap/profile.csv" 2>&1) || fail "cap: $out"
isPng "$cap/postProcessing/fracture_fault.png" || fail "cap: no maps PNG"
isPng "$cap/postProcessing/fracture_fault_profile.png" || fail "cap: no profile PNG"
checkProfile "$cap/profile.csv" cap || fail "cap: profile"

# The rectangle: the default profiles cross it end to end (their ends on its border), through
# its centre (the largest slip, K A, sampled exactly: the middle sample of a chord through the
# centre of a centrally symmetric fault).
rect=$work/rectangle
"$python" "$make" "$rect" rectangle || fail "cannot write the synthetic rectangle"
out=$("$python" "$plot" -case "$rect" -profileCsv "$rect/profile.csv" 2>&1) || fail "rectangle: $out"
isPng "$rect/postProcessing/fracture_fault.png" || fail "rectangle: no maps PNG"
printf '%s\n' "$out" >"$rect/out.txt"
checkDefault "$rect" rectangle 1,2,3 rectangle || fail "rectangle: default profiles"
"$python" - "$rect/profile.csv" "$make" <<'PY' || fail "rectangle: default profile"
import csv, os, sys
import numpy as np
sys.path.insert(0, os.path.dirname(sys.argv[2]))
import plotFracture3dCase as case
rows = list(csv.DictReader(open(sys.argv[1])))
for kind in ("strike", "dip"):
    slip = np.array([float(r["slipMagnitude"]) for r in rows if r["profile"] == kind])
    mid = slip[len(slip) // 2]  # the centre node, exact: K A
    assert abs(mid - case.K * case.A) < 1e-12, (kind, mid, case.K * case.A)
PY
# Nothing slips (the rectangle locked): the profiles go through the centroid (its centre),
# not through the first node (a corner), which has as much slip as any other: none.
lk=$work/locked
"$python" "$make" "$lk" locked || fail "cannot write the locked rectangle"
out=$("$python" "$plot" -case "$lk" -profileCsv "$lk/profile.csv" 2>&1) || fail "locked: $out"
printf '%s\n' "$out" >"$lk/out.txt"
grep -qF "profiles along strike and dip through the centroid (no slip)" <<<"$out" ||
  fail "locked: $out"
checkDefault "$lk" locked 1,2,3 rectangle || fail "locked: default profiles"

# A fault that folds over itself in its mean plane (here a node row written twice: the
# second copy lands on the first in the map): drawn, with a warning saying so.
f=$work/folded
"$python" "$make" "$f" disc && rm -rf "$f/0.5" || fail "cannot write the folded case"
awk 'NR == 5 { print } { print }' "$f/1/fractures/fault.dat" >"$f/new" &&
  mv "$f/new" "$f/1/fractures/fault.dat"
out=$("$python" "$plot" -case "$f" 2>&1) || fail "folded: $out"
grep -qF "the fault folds over itself in its mean plane (0 node normals at 90 degrees or more \
from it, 1 nodes on top of others)" <<<"$out" || fail "folded: no warning: $out"
isPng "$f/postProcessing/fracture_fault.png" || fail "folded: no maps PNG"

# Bad input: exit 1, a message naming the file or the option, nothing written.
bad() {  # name, expected message, then the plot command's arguments
  local name=$1 want=$2 err rc; shift 2
  err=$("$python" "$plot" "$@" 2>&1 >/dev/null); rc=$?
  ((rc == 1)) || fail "$name: exit $rc, expected 1 ($err)"
  grep -qF -- "$want" <<<"$err" || fail "$name: expected '$want' in: $err"
}
fresh() {  # a fresh penny case with time 1 only, without outputs
  rm -rf "$1" && "$python" "$make" "$1" disc && rm -rf "$1/0.5"
}
b=$work/bad
fresh "$b"
table=$b/1/fractures/fault.dat
head -3 "$table" >"$table.new" && mv "$table.new" "$table"
bad "no rows" "$table: no rows" -case "$b"
noOutput "$b" "no rows"
fresh "$b"
# Drop the ST column (the 19th) from the header and every row.
awk 'NR == 1 { $20 = ""; print; next } /^#/ { print; next } { $19 = ""; print }' "$table" \
  >"$table.new" && mv "$table.new" "$table"
bad "missing column" "$table:1: the header has no column 'ST'" -case "$b" -profileCsv "$b/p.csv"
noOutput "$b" "missing column"
fresh "$b"
sed -i '5s/ slip$/ sliding/' "$table"
bad "unknown state" "$table:5: state 'sliding' is not one of tip, stick, slip, open" \
  -case "$b"
noOutput "$b" "unknown state"
fresh "$b"
bad "bad -line" "-line: expected x0,y0,z0:x1,y1,z1 (two points in m), got '1,2,3:4,5'" \
  -case "$b" -line 1,2,3:4,5
bad "bad -line" "-line: expected x0,y0,z0:x1,y1,z1" -case "$b" -line 1,2,3,4,5,6
bad "bad -line" "-line: expected x0,y0,z0:x1,y1,z1" -case "$b" -line 1,2,nan:4,5,6
bad "-line of one point" "-line: the two points of '1,2,3:1,2,3' coincide" -case "$b" -line 1,2,3:1,2,3
bad "-line off the fault" \
  "-line: the segment (10 10 10) -> (11 10 10) does not cross fracture 'fault'" \
  -case "$b" -line 10,10,10:11,10,10 -profileCsv "$b/p.csv"
# A value with a leading minus is the option's value, not another option.
bad "-line with a leading minus" \
  "-line: the segment (-10 10 10) -> (-11 10 10) does not cross fracture 'fault'" \
  -case "$b" -line -10,10,10:-11,10,10 -profileCsv "$b/p.csv"
bad "-samples" "-samples: expected a whole number >= 2, got '1'" -case "$b" -samples 1
bad "image format" "unknown image format 'xyz'" -case "$b" -o "$b/maps.xyz"
noOutput "$b" "bad options"
[[ ! -e $b/maps.xyz ]] || fail "image format: $b/maps.xyz written"
# -line and the profile outputs need one fault when the case has several.
cp "$table" "$b/1/fractures/other.dat"
bad "-line, two faults" "-line: 2 fractures (fault other); choose one with -fracture" \
  -case "$b" -line 0,0,0:1,1,1
noOutput "$b" "two faults"
# A fault that opens (contact unilateral): its tables have an "opening" column before the
# state; the maps gain its panel and the profile its row.
op=$work/opening
cp -r "$disc" "$op" && rm -rf "$op/postProcessing" "$op/profile.csv"
for f in "$op"/*/fractures/fault.dat; do
  awk 'NR == 1 { sub(/ state$/, " opening state"); print; next }
       /^#/ { print; next }
       { $NF = sprintf("%.6g %s", $12 * 0.5, $NF); print }' "$f" >"$f.new" && mv "$f.new" "$f"
done
out=$("$python" "$plot" -case "$op" -noConvergence 2>&1); rc=$?
((rc == 0)) || fail "opening: exit $rc: $out"
grep -qF "maps of slip magnitude, ST, node states and opening at t = 1" <<<"$out" || fail "opening: $out"
for png in "$op"/postProcessing/fracture_fault{,_profile}.png; do
  isPng "$png" || fail "opening: $png missing, empty or not a PNG"
done
# A fluid pressure (faultPressure, fracturePressure): the tables have "pressure
# sigmaNEffective" before the state (after "opening" where there is one). p is linear in
# x y z (so in the map coordinates, and reproduced by linear interpolation to round-off),
# sigma'_n = sigma_n + p, nan at tips. The maps gain the maps of p and sigma'_n (two rows: the
# figure 11.5 in tall, 1380 px, against 5.8 in, 696 px, without them), the profile its two
# rows (6 of 2.5 in: 1800 px, against 1200 px), the CSV the columns pressure,sigmaNEffective
# after the others; the tables without pressure keep the CSV header they had.
pr=$work/pressure
cp -r "$disc" "$pr" && rm -rf "$pr/postProcessing" "$pr/profile.csv"
for f in "$pr"/*/fractures/fault.dat; do
  "$python" - "$f" "$make" <<'PY' || fail "cannot add the pressure columns"
import math, os, sys
sys.path.insert(0, os.path.dirname(sys.argv[2]))
import plotFracture3dCase as case
path = sys.argv[1]
lines = open(path).read().splitlines()
names = lines[0][1:].split()
out = ["# " + " ".join(names[:-1] + ["pressure", "sigmaNEffective", "state"])]
for line in lines[1:]:
    if line.startswith("#"):
        out.append(line)
        continue
    items = line.split()
    p = case.pressure([float(items[names.index(k)]) for k in "xyz"])
    sn = float(items[names.index("sigmaN")])
    out.append(" ".join(items[:-1] + [repr(p), repr(sn + p) if math.isfinite(sn) else "nan",
                                      items[-1]]))
open(path, "w").write("\n".join(out) + "\n")
PY
done
out=$("$python" "$plot" -case "$pr" -noConvergence -profileCsv "$pr/profile.csv" 2>&1); rc=$?
((rc == 0)) || fail "pressure: exit $rc: $out"
grep -qF "maps of slip magnitude, ST, node states, pressure and effective normal stress at t = 1" \
  <<<"$out" || fail "pressure: $out"
for png in "$pr"/postProcessing/fracture_fault{,_profile}.png; do
  isPng "$png" || fail "pressure: $png missing, empty or not a PNG"
done
h=$(pngHeight "$pr/postProcessing/fracture_fault.png")
((h == 1380)) || fail "pressure: the maps are $h px tall, expected 1380 (two rows of maps)"
h=$(pngHeight "$disc/postProcessing/fracture_fault.png")
((h == 696)) || fail "penny without pressure: the maps are $h px tall, expected 696 (one row)"
h=$(pngHeight "$pr/postProcessing/fracture_fault_profile.png")
((h == 1800)) || fail "pressure: the profile is $h px tall, expected 1800 (six rows)"
"$python" - "$pr/profile.csv" "$disc/profile.csv" "$make" <<'PY' || fail "pressure: profile CSV"
import csv, math, os, sys
import numpy as np
sys.path.insert(0, os.path.dirname(sys.argv[3]))
import plotFracture3dCase as case
plain = open(sys.argv[2]).readline().strip()
assert plain == "profile,time,distance,x,y,z,slipMagnitude,sigmaN,tauMagnitude,ST", plain
header = open(sys.argv[1]).readline().strip()
assert header == plain + ",pressure,sigmaNEffective", header
rows = list(csv.DictReader(open(sys.argv[1])))
assert sorted({r["time"] for r in rows}, key=float) == ["0.5", "1"]
checked = 0
for r in rows:
    q = np.array([float(r[k]) for k in "xyz"]) - case.C
    s = case.C + (q @ case.T1) * case.T1 + (q @ case.T2) * case.T2  # on the plane
    p, sn, eff = float(r["pressure"]), float(r["sigmaN"]), float(r["sigmaNEffective"])
    assert math.isfinite(p), f"nan pressure at {s} (p is given at tips too)"
    assert abs(p - case.pressure(s)) <= 1e-9 * abs(case.pressure(s)), (p, case.pressure(s))
    if math.isfinite(sn):
        assert abs(eff - (sn + p)) <= 1e-9 * abs(sn), (eff, sn + p)
        checked += 1
assert checked >= 300, f"only {checked} samples of sigma'_n"
print(f"  pressure: {len(rows)} samples of p exact to 1e-9, {checked} of sigma'_n = sigma_n + p")
PY
# No axis offsets: sigma_n = -2.87e7 Pa varying by about 1e3 Pa (a deep fault's normal stress
# with the small change slip brings) drawn as -2.87e7 with a 1e7 multiplier, never as ticks of
# +-1000 above an offset (plotNoOffset.py checks every axis of every figure saved).
no=$work/noOffset
cp -r "$disc" "$no" && rm -rf "$no/postProcessing" "$no/profile.csv" "$no/out.txt"
for f in "$no"/*/fractures/fault.dat; do
  awk '/^#/ || $NF == "tip" { print; next }
       { $15 = sprintf("%.17g", -2.8715e7 + 1e-3 * $15); print }' \
    "$f" >"$f.new" && mv "$f.new" "$f"
done
"$python" "$src/tests/regression/plotNoOffset.py" "$plot" -case "$no" -noConvergence ||
  fail "sigma_n near -2.87e7: a figure drawn with an axis offset"
echo "plotFracture3d: ok"
